// What the view model's tests share (tests/viewer/viewer_*_test.cpp, one file per concern):
// the viewer's and core's headers they use, and their helpers. Included only where the viewer
// is in the tree (each test file is guarded by __has_include("model.h")).
#pragma once
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "canvas_geometry.h"
#include "edit.h"
#include "flood/geometry/polygon.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "gorge_focus.h"
#include "key_queue.h"
#include "model.h"
#include "scene.h"
#include "test_support.h"

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
using flood::testing::RunResult;
using flood::testing::runShell;
using flood::testing::scratch;
using flood::testing::squareWithHole;
using namespace flood;
using namespace flood::view;
