// flood-small-bench: what one call costs on a small polygon, without any call overhead.
//
//   flood-small-bench calls FILE N [--validate|--fresh|--earcut]
//                                                 N calls in a loop, for callgrind: the
//                                                 difference of two runs over the difference of
//                                                 their N is the instructions per call
//                                                 (--fresh: flood::triangulate() instead of a kept
//                                                 Triangulator; --earcut: native earcut.hpp's, fresh)
//   flood-small-bench validate FILE N             N calls of validate() alone, for callgrind
//                                                 (the same difference, per call)
//   flood-small-bench vertices FILE               the vertex count the calls see
//   flood-small-bench time FILE...                per file: ns per triangulate() call, and per
//                                                 validate() + triangulate(), warm and fresh,
//                                                 and native earcut.hpp's, fresh and warm, as TSV
//
// Each file is read and validated once. Warm calls reuse one Triangulator (one Earcut object),
// as a program triangulating many small polygons would; fresh calls are the free functions,
// flood::triangulate() and mapbox::earcut(), which allocate anew each time. earcut.hpp is
// compiled in when CMake is given FLOOD_EARCUT_HPP (scripts/small-bench.sh fetches it from
// Debian's source package python-mapbox-earcut); without it its columns are absent. Timings are the least of several batch means (each
// batch ~20 ms), the figure least disturbed by other jobs on a shared machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <array>
#include <vector>

#include "flood/io/io.h"
#include "flood/machine/flood.h"

#ifdef FLOOD_EARCUT_HPP
#include <mapbox/earcut.hpp>
#endif

using namespace flood;

namespace {

bool load(const char* path, Polygon& p) {
    ReadResult rr = readPolygonFile(path);
    if (!rr.diagnostic.ok()) {
        std::fprintf(stderr, "%s\n", rr.diagnostic.message.c_str());
        return false;
    }
    p = std::move(rr.polygon);
    Diagnostic d = validate(p, path);
    if (!d.ok()) {
        std::fprintf(stderr, "%s\n", d.message.c_str());
        return false;
    }
    return true;
}

// One call: the triangulation alone, or validation first (on a copy the loop keeps reusing,
// since validate() records the T-junctions in the polygon it is given).
// `fresh`: flood::triangulate() each time instead of the kept Triangulator.
struct Call {
    const Polygon& polygon;
    bool validating;
    Polygon copy;
    Triangulator triangulator;
    bool fresh = false;
    size_t operator()() {
        const Polygon* p = &polygon;
        if (validating) {
            copy.splits.clear();
            if (!validate(copy, "bench").ok()) std::abort();
            p = &copy;
        }
        return fresh ? triangulate(*p).triangles.size() : triangulator.run(*p).triangles.size();
    }
};

#ifdef FLOOD_EARCUT_HPP
// earcut.hpp's input: each part's rings as arrays of points, the outer ring first.
using EarcutRings = std::vector<std::vector<std::array<double, 2>>>;
std::vector<EarcutRings> earcutParts(const Polygon& p) {
    std::vector<EarcutRings> parts;
    for (const Part& part : p.parts) {
        EarcutRings rings;
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
            std::vector<std::array<double, 2>> ring;
            for (Index v = p.rings[r].first; v < p.rings[r].first + p.rings[r].count; ++v)
                ring.push_back({p.vertices[v].x, p.vertices[v].y});
            rings.push_back(std::move(ring));
        }
        parts.push_back(std::move(rings));
    }
    return parts;
}

// One earcut.hpp call per part: mapbox::earcut() fresh, or one kept Earcut object (warm).
struct EarcutCall {
    std::vector<EarcutRings> parts;
    bool fresh = true;
    mapbox::detail::Earcut<uint32_t> kept;
    size_t operator()() {
        size_t n = 0;
        for (const EarcutRings& rings : parts) {
            if (fresh) {
                n += mapbox::earcut<uint32_t>(rings).size() / 3;
            } else {
                kept(rings);
                n += kept.indices.size() / 3;
            }
        }
        return n;
    }
};
#endif

template <typename C>
double nsPerCall(C& call) {
    using clock = std::chrono::steady_clock;
    size_t sink = 0, batch = 1;
    for (;; batch *= 2) {  // a batch long enough for the clock: 20 ms
        auto t0 = clock::now();
        for (size_t i = 0; i < batch; ++i) sink += call();
        if (clock::now() - t0 > std::chrono::milliseconds(20)) break;
    }
    double best = 1e300;
    for (int round = 0; round < 15; ++round) {
        auto t0 = clock::now();
        for (size_t i = 0; i < batch; ++i) sink += call();
        best = std::min(best, std::chrono::duration<double, std::nano>(clock::now() - t0).count() /
                                  double(batch));
    }
    if (sink == 0) std::fprintf(stderr, "no triangles\n");
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 4 && std::strcmp(argv[1], "calls") == 0) {
        Polygon p;
        if (!load(argv[2], p)) return 3;
        const char* flag = argc > 4 ? argv[4] : "";
        long n = std::atol(argv[3]);
        size_t sink = 0;
        if (std::strcmp(flag, "--earcut") == 0) {
#ifdef FLOOD_EARCUT_HPP
            EarcutCall call{earcutParts(p), true, {}};
            for (long i = 0; i < n; ++i) sink += call();
#else
            std::fprintf(stderr,
                         "flood-small-bench: built without earcut.hpp (FLOOD_EARCUT_HPP)\n");
            return 2;
#endif
        } else {
            Call call{
                p, std::strcmp(flag, "--validate") == 0, p, {}, std::strcmp(flag, "--fresh") == 0};
            for (long i = 0; i < n; ++i) sink += call();
        }
        std::printf("%zu triangles in %ld calls\n", sink, n);
        return 0;
    }
    if (argc >= 4 && std::strcmp(argv[1], "validate") == 0) {
        Polygon p;
        if (!load(argv[2], p)) return 3;
        long n = std::atol(argv[3]);
        size_t sink = 0;
        for (long i = 0; i < n; ++i) sink += validate(p, "bench").ok();
        std::printf("%zu valid in %ld calls\n", sink, n);
        return 0;
    }
    if (argc == 3 && std::strcmp(argv[1], "vertices") == 0) {
        Polygon p;
        if (!load(argv[2], p)) return 3;
        std::printf("%zu\n", p.vertices.size());
        return 0;
    }
    if (argc >= 3 && std::strcmp(argv[1], "time") == 0) {
        std::printf(
            "file\tvertices\ttriangulate_ns\tvalidate_triangulate_ns\tfresh_triangulate_ns"
            "\tfresh_validate_triangulate_ns");
#ifdef FLOOD_EARCUT_HPP
        std::printf("\tearcut_hpp_fresh_ns\tearcut_hpp_warm_ns");
#endif
        std::printf("\n");
        for (int i = 2; i < argc; ++i) {
            Polygon p;
            if (!load(argv[i], p)) return 3;
            Call flood{p, false, p, {}}, both{p, true, p, {}};
            Call freshFlood{p, false, p, {}, true}, freshBoth{p, true, p, {}, true};
            std::printf("%s\t%zu\t%.1f\t%.1f\t%.1f\t%.1f", argv[i], p.vertices.size(),
                        nsPerCall(flood), nsPerCall(both), nsPerCall(freshFlood),
                        nsPerCall(freshBoth));
#ifdef FLOOD_EARCUT_HPP
            EarcutCall fresh{earcutParts(p), true, {}}, warm{earcutParts(p), false, {}};
            std::printf("\t%.1f\t%.1f", nsPerCall(fresh), nsPerCall(warm));
#endif
            std::printf("\n");
        }
        return 0;
    }
    std::fprintf(
        stderr,
        "usage: flood-small-bench calls FILE N [--validate|--fresh|--earcut] | validate FILE N | "
        "vertices "
        "FILE | time FILE...\n");
    return 2;
}
