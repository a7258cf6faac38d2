// The plane-indexed sag list finds exactly what a scan of the sorted list would find, at every
// scale of the coordinates, and its pruning does not depend on the scale. The bank lists
// (core/machine/sags/sag_banks.h) label each sag with the edges its horizontal rays meet first,
// refuse loops whose edges meet, and keep the sag search's work below the rest of the machine's.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "flood/machine/flood.h"
#include "flood/tools/generate.h"
#include "machine/sags/sag_banks.h"
#include "machine/sags/sag_index.h"

using namespace flood;

namespace {

// Random sag sets, regions and queries (coordinates: `coord` of small integers, so there are
// many ties), each answer compared with a scan using the exact orient. Returns how many
// candidates the index handed to `inside`: the work its pruning left.
uint64_t agreesWithAScan(const std::function<double(double)>& coord, uint32_t seed = 7) {
    std::mt19937 rng(seed);
    uint64_t insideCalls = 0;
    for (int trial = 0; trial < 300; ++trial) {
        size_t n = 1 + rng() % 300;
        std::vector<Point> pts(n);
        for (Point& p : pts) p = {coord(double(rng() % 50)), coord(double(rng() % 50))};
        SagIndex index;
        index.vertices().resize(n);
        for (uint32_t k = 0; k < n; ++k) index.vertices()[k] = k;
        index.build(pts.data());
        std::vector<uint8_t> used(n, 0);
        for (int q = 0; q < 50; ++q) {
            int64_t lo = int64_t(rng() % (n + 1)) - 1, hi = int64_t(rng() % (n + 2));
            SagIndex::Region region;
            double a = coord(double(rng() % 55) - 2), b = coord(double(rng() % 55) - 2);
            region.xMin = std::min(a, b), region.xMax = std::max(a, b);
            a = coord(double(rng() % 55) - 2), b = coord(double(rng() % 55) - 2);
            region.yMin = std::min(a, b), region.yMax = std::max(a, b);
            region.lineCount = int(rng() % 3);
            for (int k = 0; k < region.lineCount; ++k)
                for (int e = 0; e < 2; ++e)
                    region.lines[k][e] = {coord(double(rng() % 50)), coord(double(rng() % 50))};
            auto inRegion = [&](Point p) {
                if (p.x < region.xMin || p.x > region.xMax || p.y < region.yMin ||
                    p.y > region.yMax)
                    return false;
                for (int k = 0; k < region.lineCount; ++k)
                    if (orient(region.lines[k][0], region.lines[k][1], p) <= 0) return false;
                return true;
            };
            uint32_t mod = 1 + rng() % 3;
            auto inside = [&](uint32_t r) { return r % mod == 0 && inRegion(pts[r]); };
            int64_t expect = -1;
            for (int64_t r = std::max<int64_t>(lo + 1, 0); r < hi && r < int64_t(n); ++r)
                if (!used[r] && inside(uint32_t(r))) {
                    expect = r;
                    break;
                }
            int64_t got = index.lowest(lo, hi, region, [&](uint32_t r) {
                ++insideCalls;
                return inside(r);
            });
            EXPECT_EQ(got, expect) << "trial " << trial << " query " << q;
            if (got != expect) return insideCalls;
            if (got >= 0 && rng() % 2) {
                index.markUsed(uint32_t(got));
                used[got] = 1;
            }
        }
    }
    return insideCalls;
}

}  // namespace

TEST(SagIndex, AgreesWithAScanOfTheSortedList) {
    agreesWithAScan([](double v) { return v; });
}

// Scaling by 2^k is exact here (integers below 2^6, times 2^k for |k| <= 1060), and the
// index works in coordinates scaled to the region, so it must make the same pruning
// decisions: the same answers after the same number of `inside` calls. The unscaled
// products overflowed (inf - inf = NaN dropped candidates) from 2^510 on, and floats
// overflowed at 2^128 and underflowed below 2^-126 (no pruning at all).
TEST(SagIndex, PrunesTheSameAtEveryScale) {
    const uint64_t unscaled = agreesWithAScan([](double v) { return v; });
    for (int k : {-1060, -1000, -500, -130, 130, 500, 600, 1000, 1017}) {
        SCOPED_TRACE("scale 2^" + std::to_string(k));
        EXPECT_EQ(agreesWithAScan([k](double v) { return std::ldexp(v, k); }), unscaled);
    }
}

// Coordinates of every magnitude in one search, ±(1 .. 2^1023) and ±(2^-1074 .. 1): the
// differences overflow and the products underflow unless the tests are scale-aware.
TEST(SagIndex, AgreesAcrossAllMagnitudes) {
    auto spread = [](double v) {
        // v in [-2, 52]: 0 stays 0, others map monotonically onto widely spaced magnitudes.
        if (v == 0) return 0.0;
        double m = std::ldexp(1.0 + std::fabs(v) / 64, int(std::fabs(v)) * 38 - 1074);
        return v < 0 ? -m : m;
    };
    for (uint32_t seed : {7u, 8u, 9u}) agreesWithAScan(spread, seed);
    auto signedSpread = [&](double v) { return int(v) % 2 ? -spread(v) : spread(v); };
    for (uint32_t seed : {7u, 8u, 9u}) agreesWithAScan(signedSpread, seed);
}

namespace {

// Loops given as rings of local node ids (each ring's nodes consecutive, in loop order).
std::vector<uint32_t> loopsOf(const std::vector<size_t>& ringSizes) {
    std::vector<uint32_t> next;
    for (size_t count : ringSizes) {
        const uint32_t base = uint32_t(next.size());
        for (uint32_t i = 0; i < count; ++i) next.push_back(base + (i + 1) % uint32_t(count));
    }
    return next;
}

const auto kNoneUsed = [](uint32_t) { return false; };

}  // namespace

// An outer square (edges 0..3, counter-clockwise) and two triangular holes (clockwise): B
// (nodes 7-9, sag 7 at (2,1), rank 0) left of A (nodes 4-6, sag 4 at (5,2), rank 1). A's ray
// to the left meets B's edge 9 -> 7 before the square's left side; B's ray to the right passes
// under A and meets the square's right side, as does A's.
TEST(SagBanks, LabelsEachSagWithTheEdgesItsRaysMeetFirst) {
    std::vector<Point> pts = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 2},
                              {4, 6}, {6, 6},  {2, 1},   {1, 8},  {3, 8}};
    SagBanks banks;
    ASSERT_TRUE(banks.build(pts, loopsOf({4, 3, 3}), {7, 4}));
    EXPECT_EQ(banks.lowest(true, 3, -1, 2, kNoneUsed), 0);   // the square's left side sees B only
    EXPECT_EQ(banks.lowest(true, 9, -1, 2, kNoneUsed), 1);   // B's right bank sees A
    EXPECT_EQ(banks.lowest(false, 1, -1, 2, kNoneUsed), 0);  // the right side sees both, B first
    EXPECT_EQ(banks.lowest(false, 1, 0, 2, kNoneUsed), 1);   // above B's rank: A
    EXPECT_EQ(banks.lowest(false, 1, -1, 1, kNoneUsed), 0);  // below A's rank: B
    EXPECT_EQ(banks.lowest(false, 1, -1, 2, [](uint32_t r) { return r == 0; }), 1);  // B used
    EXPECT_EQ(banks.lowest(false, 1, 1, 2, kNoneUsed), -1);  // an empty bracket
    EXPECT_EQ(banks.lowest(true, 1, -1, 2, kNoneUsed),
              -1);  // nothing left of it sees the right side
    EXPECT_EQ(banks.lowest(false, 5, -1, 2, kNoneUsed), -1);  // A's top edge: no sag
}

// A point hole is labelled like any sag; it has no edges of its own.
TEST(SagBanks, LabelsAPointHole) {
    std::vector<Point> pts = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 5}};
    SagBanks banks;
    ASSERT_TRUE(banks.build(pts, loopsOf({4, 1}), {4}));
    EXPECT_EQ(banks.lowest(true, 3, -1, 1, kNoneUsed), 0);
    EXPECT_EQ(banks.lowest(false, 1, -1, 1, kNoneUsed), 0);
}

// Unvalidated input: the sweep stops at the first pair of edges that meet, and nothing is
// built, so the machine keeps the plane index alone.
TEST(SagBanks, RefusesLoopsWhoseEdgesMeet) {
    SagBanks banks;
    // A bow tie: edges 0 -> 1 and 2 -> 3 cross.
    EXPECT_FALSE(banks.build({{0, 0}, {10, 10}, {10, 0}, {0, 10}}, loopsOf({4}), {}));
    EXPECT_FALSE(banks.built());
    // A hole whose sag lies on the square's bottom edge.
    EXPECT_FALSE(banks.build({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 0}, {4, 6}, {6, 6}},
                             loopsOf({4, 3}), {4}));
    // A hole crossing the square's right side.
    EXPECT_FALSE(banks.build({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {9, 2}, {8, 6}, {12, 6}},
                             loopsOf({4, 3}), {4}));
    // Two holes overlapping along an edge.
    EXPECT_FALSE(banks.build(
        {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {2, 6}, {4, 6}, {2, 3}, {2, 5}, {1, 5}},
        loopsOf({4, 3, 3}), {}));
    // The same square is fine.
    EXPECT_TRUE(banks.build({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, loopsOf({4}), {}));
}

// Issue 13: on sliver gorges (star, jagged and smooth circles, collinear runs) the plane index
// visited O(sqrt S) boxes per search, ~4x the rest of the machine at 10^5 on star and ~6x on
// circle-jagged. With the bank lists the sag search costs no more than the rest there.
TEST(SagBanks, SagSearchCostsNoMoreThanTheRestOfTheMachine) {
    for (const std::string family : {"star", "circle-smooth", "circle-jagged", "collinear"}) {
        Polygon p = generate(family, 7, 100000);
        ASSERT_TRUE(validate(p, family).ok()) << family;
        work() = {};
        FloodResult r = triangulate(p);
        ASSERT_TRUE(r.diagnostic.ok()) << family << ": " << r.diagnostic.message;
        const WorkCounters& w = work();
        const uint64_t total = w.nodeVisits + w.sagTests + w.orientCalls;
        EXPECT_LE(w.sagSearch, total - w.sagSearch)
            << family << ": sag search " << w.sagSearch << " of " << total;
    }
}
