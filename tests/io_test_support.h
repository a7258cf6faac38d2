// What the tests of reading, validating and trace files share (tests/io/io_test.cpp,
// tests/check/validate_test.cpp, tests/log/trace_io_test.cpp).
#pragma once
#include <string>

#include "flood/geometry/polygon.h"

namespace flood::testing::io {

inline std::string source(const std::string& rel) {
    return std::string(FLOOD_SOURCE_DIR) + "/" + rel;
}

inline bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

inline Polygon square(double s = 10) {
    Polygon p;
    p.addRing({{0, 0}, {s, 0}, {s, s}, {0, s}}, true);
    return p;
}

}  // namespace flood::testing::io

using flood::testing::io::contains;
using flood::testing::io::source;
using flood::testing::io::square;
