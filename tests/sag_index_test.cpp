// The plane-indexed sag list finds exactly what a scan of the sorted list would find, at every
// scale of the coordinates, and its pruning does not depend on the scale.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "predicates.h"
#include "sag_index.h"

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
        index.build(pts);
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
                if (p.x < region.xMin || p.x > region.xMax || p.y < region.yMin || p.y > region.yMax) return false;
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
