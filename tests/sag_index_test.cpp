// The plane-indexed sag list finds exactly what a scan of the sorted list would find.
#include <gtest/gtest.h>

#include <random>

#include "predicates.h"
#include "sag_index.h"

using namespace flood;

TEST(SagIndex, AgreesWithAScanOfTheSortedList) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 300; ++trial) {
        size_t n = 1 + rng() % 300;
        std::vector<Point> pts(n);
        for (Point& p : pts) p = {double(rng() % 50), double(rng() % 50)};  // many ties
        SagIndex index;
        index.build(pts);
        std::vector<uint8_t> used(n, 0);
        for (int q = 0; q < 50; ++q) {
            int64_t lo = int64_t(rng() % (n + 1)) - 1, hi = int64_t(rng() % (n + 2));
            SagIndex::Region region;
            double a = double(rng() % 55) - 2, b = double(rng() % 55) - 2;
            region.xMin = std::min(a, b), region.xMax = std::max(a, b);
            a = double(rng() % 55) - 2, b = double(rng() % 55) - 2;
            region.yMin = std::min(a, b), region.yMax = std::max(a, b);
            region.lineCount = int(rng() % 3);
            for (int k = 0; k < region.lineCount; ++k)
                for (int e = 0; e < 2; ++e) region.lines[k][e] = {double(rng() % 50), double(rng() % 50)};
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
            int64_t got = index.lowest(lo, hi, region, inside);
            ASSERT_EQ(got, expect) << "trial " << trial << " query " << q;
            if (got >= 0 && rng() % 2) {
                index.markUsed(uint32_t(got));
                used[got] = 1;
            }
        }
    }
}
