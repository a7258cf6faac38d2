// The floor (see floor.h).
#include "floor.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "flood/geometry/predicates.h"

namespace bench {

using flood::Index;
using flood::Point;
using flood::Polygon;
using flood::Triangle;

namespace {

// The parts are cheap (a few ns per vertex): the median of 7..101 runs, until ~0.3 s are spent.
double medianNs(const std::function<uint64_t()>& f) {
    std::vector<double> t;
    double total = 0;
    volatile uint64_t sink = 0;  // the result is used, so no part is optimised away
    while (t.size() < 7 || (total < 0.3e9 && t.size() < 101)) {
        auto t0 = std::chrono::steady_clock::now();
        sink = sink + f();
        double ns =
            std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
        t.push_back(ns);
        total += ns;
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// Calls f(prev, v, next) for every vertex with its ring neighbours.
template <class F>
void forEachCorner(const Polygon& p, F&& f) {
    for (const flood::Ring& r : p.rings)
        for (Index k = 0; k < r.count; ++k) {
            Index v = r.first + k;
            Index prev = k == 0 ? r.first + r.count - 1 : v - 1;
            Index next = k + 1 == r.count ? r.first : v + 1;
            f(prev, v, next);
        }
}

}  // namespace

FloorNs measureFloor(const Polygon& p) {
    const size_t n = p.vertices.size(), triangles = p.expectedTriangles();
    FloorNs f;
    f.io = medianNs([&] {
        // Fresh memory each run, as a triangulator's result is (new pages are part of the cost).
        std::unique_ptr<Point[]> in(new Point[n]);
        std::memcpy(in.get(), p.vertices.data(), n * sizeof(Point));
        std::unique_ptr<Triangle[]> out(new Triangle[triangles]);
        for (size_t i = 0; i < triangles; ++i) out[i] = {Index(i), Index(i + 1), Index(i + 2)};
        return uint64_t(in[n / 2].x != 0) + (triangles ? out[triangles / 2][0] : 0);
    });
    f.orient = medianNs([&] {
        uint64_t convex = 0;
        forEachCorner(p, [&](Index a, Index b, Index c) {
            convex += flood::orient(p.vertices[a], p.vertices[b], p.vertices[c]) > 0;
        });
        return convex;
    });
    f.sags = medianNs([&] {
        std::vector<Index> sags;
        forEachCorner(p, [&](Index a, Index b, Index c) {
            const auto& v = p.vertices;
            if (flood::below(v[b], v[a]) && flood::below(v[b], v[c])) sags.push_back(b);
        });
        std::sort(sags.begin(), sags.end(),
                  [&](Index a, Index b) { return flood::below(p.vertices[a], p.vertices[b]); });
        return uint64_t(sags.size());
    });
    return f;
}

}  // namespace bench
