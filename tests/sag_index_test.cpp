// The x-indexed sag list finds exactly what a scan of the sorted list would find.
#include <gtest/gtest.h>

#include <random>

#include "sag_index.h"

using namespace flood;

TEST(SagIndex, AgreesWithAScanOfTheSortedList) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 300; ++trial) {
        size_t n = 1 + rng() % 200;
        std::vector<double> x(n);
        for (double& v : x) v = double(rng() % 50);  // many equal x
        SagIndex index;
        index.build(x);
        std::vector<uint8_t> used(n, 0);
        for (int q = 0; q < 50; ++q) {
            int64_t lo = int64_t(rng() % (n + 1)) - 1, hi = int64_t(rng() % (n + 2));
            double a = double(rng() % 55) - 2, b = double(rng() % 55) - 2;
            double xmin = std::min(a, b), xmax = std::max(a, b);
            uint32_t mod = 1 + rng() % 4;  // "inside" accepts ranks divisible by mod
            auto inside = [&](uint32_t r) { return r % mod == 0; };
            int64_t expect = -1;
            for (int64_t r = lo + 1; r < hi && r < int64_t(n); ++r)
                if (r >= 0 && !used[r] && x[r] >= xmin && x[r] <= xmax && inside(uint32_t(r))) {
                    expect = r;
                    break;
                }
            int64_t got = index.lowest(lo, hi, xmin, xmax, inside);
            ASSERT_EQ(got, expect) << "n " << n << " lo " << lo << " hi " << hi << " x " << xmin << ".." << xmax;
            if (got >= 0 && rng() % 2) {
                index.markUsed(uint32_t(got));
                used[got] = 1;
            }
        }
    }
}
