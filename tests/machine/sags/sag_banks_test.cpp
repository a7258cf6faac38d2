// The bank lists' sweep (core/machine/sags/sag_banks.h) against a brute force, and its cost: every
// sag labelled with the edges its rays meet first, along each axis direction, on loops with holes
// and point holes; and a minimum placed among the crossing edges from its own loop's nearby
// edges, at a cost per node that does not grow with the active edges (issue 13).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "flood/tools/generate.h"
#include "machine/sags/sag_banks.h"

using namespace flood;

namespace {

std::vector<uint32_t> loopsOf(const Polygon& p) {
    std::vector<uint32_t> next(p.vertices.size());
    for (const Ring& r : p.rings)
        for (Index k = 0; k < r.count; ++k) next[r.first + k] = r.first + (k + 1) % r.count;
    return next;
}

// The local minima (below() order) and point holes, lowest first: the nodes the sweep labels.
std::vector<uint32_t> minimaOf(const std::vector<Point>& pts, const std::vector<uint32_t>& next) {
    const uint32_t n = uint32_t(next.size());
    std::vector<uint32_t> prev(n), sags;
    for (uint32_t i = 0; i < n; ++i) prev[next[i]] = i;
    for (uint32_t i = 0; i < n; ++i)
        if (next[i] == i || (below(pts[i], pts[prev[i]]) && below(pts[i], pts[next[i]])))
            sags.push_back(i);
    std::sort(sags.begin(), sags.end(),
              [&](uint32_t a, uint32_t b) { return below(pts[a], pts[b]); });
    return sags;
}

// Per side (0: rays to the left), the ranks labelled with each edge: by brute force, along +y.
// An edge crosses the tilted horizontal through p when its ends are either side of p in
// below() order; two crossing edges of a simple polygon keep their order along every such
// line, so the higher of their lower ends, against the other edge, orders them.
using Labels = std::map<uint32_t, std::vector<uint32_t>>;
std::array<Labels, 2> labelsByBruteForce(const std::vector<Point>& pts,
                                         const std::vector<uint32_t>& next,
                                         const std::vector<uint32_t>& sags) {
    struct Edge {
        Point lo, hi;
        uint32_t tail;
    };
    auto leftOf = [](const Edge& a, const Edge& b) {
        if (a.lo == b.lo) return orient(b.lo, b.hi, a.hi) > 0;
        if (below(b.lo, a.lo)) return orient(b.lo, b.hi, a.lo) > 0;
        return orient(a.lo, a.hi, b.lo) < 0;
    };
    std::array<Labels, 2> labels;
    for (uint32_t rank = 0; rank < sags.size(); ++rank) {
        const Point p = pts[sags[rank]];
        const Edge* best[2] = {nullptr, nullptr};
        std::vector<Edge> crossing;
        for (uint32_t t = 0; t < next.size(); ++t) {
            Point a = pts[t], b = pts[next[t]];
            if (below(b, a)) std::swap(a, b);
            if (below(a, p) && below(p, b)) crossing.push_back({a, b, t});
        }
        for (const Edge& c : crossing) {
            const int side = orient(c.lo, c.hi, p);  // +1: p left of the upward edge
            EXPECT_NE(side, 0);                      // validated: no sag on an edge
            const int k = side < 0 ? 0 : 1;          // left of p: a candidate for the left ray
            if (!best[k] || (k == 0 ? leftOf(*best[k], c) : leftOf(c, *best[k]))) best[k] = &c;
        }
        for (int k = 0; k < 2; ++k)
            if (best[k]) labels[k][best[k]->tail].push_back(rank);
    }
    return labels;
}

std::array<Labels, 2> labelsOf(const SagBanks& banks, size_t edges, size_t sags) {
    std::array<Labels, 2> labels;
    auto none = [](uint32_t) { return false; };
    for (int k = 0; k < 2; ++k)
        for (uint32_t t = 0; t < edges; ++t)
            for (int64_t r = -1; (r = banks.lowest(k == 0, t, r, int64_t(sags), none)) >= 0;)
                labels[k][t].push_back(uint32_t(r));
    return labels;
}

// Points turned so that +y along the turned points is `up` along the given ones: a rotation
// by a quarter or half turn, exact, with the same ties (belowToward's four axis cases).
std::vector<Point> turned(const std::vector<Point>& pts, Up up) {
    std::vector<Point> q(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        const Point p = pts[i];
        q[i] = up == Up::MinusY   ? Point{-p.x, -p.y}
               : up == Up::PlusX  ? Point{-p.y, p.x}
               : up == Up::MinusX ? Point{p.y, -p.x}
                                  : p;
    }
    return q;
}

}  // namespace

// Families with holes (circle-holes, grid-holes, rooms), point holes (steiner), several parts
// (islands), sliver gorges (star, circles, comb), collinear runs and equal heights (integer
// grids): the lists equal the brute force's, along each axis, with and without the crossing
// checks. Holes' lowest vertices and point holes have no crossing edge on their loop: their
// search starts from the root.
TEST(SagBanks, LabelsEqualABruteForceAlongEachAxis) {
    const char* families[] = {
        "star",      "circle-jagged", "circle-smooth", "circle-holes", "grid-holes",
        "comb",      "comb-rect",     "steiner",       "collinear",    "ortho-histogram",
        "staircase", "equal-heights", "rooms",         "islands",      "spiral"};
    for (const char* family : families)
        for (size_t size : {200, 1500}) {
            Polygon p = generate(family, 3, size);
            ASSERT_TRUE(validate(p, family).ok()) << family;
            ASSERT_TRUE(p.pointsDistinct) << family;
            const std::vector<uint32_t> next = loopsOf(p);
            for (Up up : {Up::PlusY, Up::MinusY, Up::PlusX, Up::MinusX}) {
                const std::vector<Point> q = turned(p.vertices, up);
                const std::vector<uint32_t> sags = minimaOf(q, next);
                const std::array<Labels, 2> expected = labelsByBruteForce(q, next, sags);
                for (bool simple : {true, false}) {
                    SagBanks banks;
                    ASSERT_TRUE(banks.build(p.vertices, next, sags, up, simple))
                        << family << " " << size;
                    const std::array<Labels, 2> got = labelsOf(banks, next.size(), sags.size());
                    EXPECT_EQ(got[0], expected[0]) << family << " " << size << " up " << up.x << ","
                                                   << up.y << " simple " << simple;
                    EXPECT_EQ(got[1], expected[1]) << family << " " << size << " up " << up.x << ","
                                                   << up.y << " simple " << simple;
                }
            }
        }
}

// A minimum's search starts from an edge of its own loop found crossing the line within a few
// steps, most often its neighbour there: the sweep's work per node (every comparison counted)
// stays near its value at 10^3 instead of growing with the log of the crossing edges. Measured
// at 10^5 (visits + orientations a node): star 6.1, circle-jagged 6.7, comb 4.5; searched from
// the root every time: 10.4, 15.9 and 9.4.
TEST(SagBanks, AMinimumIsPlacedFromItsOwnLoop) {
    for (const char* family : {"star", "circle-jagged", "comb"}) {
        Polygon p = generate(family, 7, 100000);
        const std::vector<uint32_t> next = loopsOf(p);
        const std::vector<uint32_t> sags = minimaOf(p.vertices, next);
        SagBanks banks;
        work() = {};
        ASSERT_TRUE(banks.build(p.vertices, next, sags, Up::PlusY, true)) << family;
        const double perNode =
            double(work().nodeVisits + work().orientCalls) / double(p.vertices.size());
        EXPECT_LE(perNode, 8.0) << family;
    }
}
