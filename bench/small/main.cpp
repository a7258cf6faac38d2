// flood-small-bench: what one call costs on a small polygon, without any call overhead.
//
//   flood-small-bench calls FILE N [--validate]   N calls in a loop, for callgrind: the
//                                                 difference of two runs over the difference of
//                                                 their N is the instructions per call
//   flood-small-bench validate FILE N             N calls of validate() alone, for callgrind
//                                                 (the same difference, per call)
//   flood-small-bench time FILE...                per file: ns per triangulate() call, and per
//                                                 validate() + triangulate(), as TSV
//
// Each file is read and validated once; the calls then reuse one Triangulator, as a program
// triangulating many small polygons would. Timings are the least of several batch means (each
// batch ~20 ms), the figure least disturbed by other jobs on a shared machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "flood/io/io.h"
#include "flood/machine/flood.h"

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
struct Call {
    const Polygon& polygon;
    bool validating;
    Polygon copy;
    Triangulator triangulator;
    size_t operator()() {
        if (!validating) return triangulator.run(polygon).triangles.size();
        copy.splits.clear();
        if (!validate(copy, "bench").ok()) std::abort();
        return triangulator.run(copy).triangles.size();
    }
};

double nsPerCall(Call& call) {
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
        Call call{p, argc > 4 && std::strcmp(argv[4], "--validate") == 0, p, {}};
        long n = std::atol(argv[3]);
        size_t sink = 0;
        for (long i = 0; i < n; ++i) sink += call();
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
    if (argc >= 3 && std::strcmp(argv[1], "time") == 0) {
        std::printf("file\tvertices\ttriangulate_ns\tvalidate_triangulate_ns\n");
        for (int i = 2; i < argc; ++i) {
            Polygon p;
            if (!load(argv[i], p)) return 3;
            Call flood{p, false, p, {}}, both{p, true, p, {}};
            std::printf("%s\t%zu\t%.1f\t%.1f\n", argv[i], p.vertices.size(), nsPerCall(flood),
                        nsPerCall(both));
        }
        return 0;
    }
    std::fprintf(
        stderr,
        "usage: flood-small-bench calls FILE N [--validate] | validate FILE N | time FILE...\n");
    return 2;
}
