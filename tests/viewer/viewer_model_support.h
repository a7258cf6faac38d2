// Helpers the view model's tests share (tests/viewer/viewer_*_test.cpp).
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/io/io.h"

namespace flood::testing {

// The sample polygons (flood::polygonFiles: all of polygons/ but the gallery's index).
inline std::vector<std::string> polygonFiles() {
    auto files = flood::polygonFiles(std::string(FLOOD_SOURCE_DIR) + "/polygons");
    return files;
}

inline Polygon squareWithHole(bool reverseOuter, bool reverseHole) {
    std::vector<Point> outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    std::vector<Point> hole{{3, 3}, {3, 7}, {7, 7}, {7, 3}};
    if (reverseOuter) std::reverse(outer.begin(), outer.end());
    if (reverseHole) std::reverse(hole.begin(), hole.end());
    Polygon p;
    p.addRing(outer, true);
    p.addRing(hole, false);
    return p;
}

inline bool contains(const std::vector<uint32_t>& v, uint32_t x) {
    return std::find(v.begin(), v.end(), x) != v.end();
}

}  // namespace flood::testing

using flood::testing::contains;
using flood::testing::polygonFiles;
using flood::testing::squareWithHole;
