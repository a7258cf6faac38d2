// The core's one search for repeated points (core/geometry/coincident.h): every later copy of a
// point paired with its first position, -0.0 equal to 0.0, also past one hash bucket.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/coincident.h"

namespace {

using flood::Point;

std::vector<std::pair<uint32_t, uint32_t>> sortedRepeats(const std::vector<Point>& pts) {
    auto copies = flood::repeatedPoints(pts.size(), [&](size_t i) { return pts[i]; });
    std::sort(copies.begin(), copies.end());
    return copies;
}

TEST(Coincident, PairsEachLaterCopyWithTheFirst) {
    const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 0}, {2, 5}, {1, 0}, {0, 0}, {-0.0, 0.0}};
    EXPECT_EQ(sortedRepeats(pts),
              (std::vector<std::pair<uint32_t, uint32_t>>{{0, 2}, {0, 5}, {0, 6}, {1, 4}}));
    EXPECT_TRUE(sortedRepeats({{0, 0}, {0, 1}, {1, 0}}).empty());
    EXPECT_TRUE(sortedRepeats({{NAN, 0}, {NAN, 0}}).empty());  // a NaN equals nothing
}

// 10^5 points (many buckets): every third point repeats the one two places before it.
TEST(Coincident, FindsEveryRepeatAcrossBuckets) {
    std::vector<Point> pts;
    std::vector<std::pair<uint32_t, uint32_t>> expected;
    for (uint32_t i = 0; i < 100000; ++i) {
        if (i % 3 == 2) {
            pts.push_back(pts[i - 2]);
            expected.push_back({i - 2, i});
        } else {
            pts.push_back({double(i) * 0.5, -double(i)});
        }
    }
    EXPECT_EQ(sortedRepeats(pts), expected);
}

}  // namespace
