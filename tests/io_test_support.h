// What the tests of reading, validating and trace files share (tests/io/io_test.cpp,
// tests/check/validate_test.cpp, tests/log/trace_io_test.cpp).
#pragma once
#include <cstdio>
#include <string>

#include "flood/geometry/polygon.h"
#include "flood/io/io.h"

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

// Everything a polygon read holds, as text: its diagnostic and warnings, every vertex bit for
// bit, its rings and parts. Equal texts, equal reads.
inline std::string describe(const ReadResult& r) {
    std::string s = "  status " + std::to_string(int(r.diagnostic.status)) + " " +
                    r.diagnostic.message + " omitted " + std::to_string(r.warningsOmitted) + "\n";
    for (const std::string& w : r.warnings) s += "  warning " + w + "\n";
    char buf[64];
    for (const Point& p : r.polygon.vertices) {
        std::snprintf(buf, sizeof buf, " %a,%a", p.x, p.y);
        s += buf;
    }
    for (const Ring& g : r.polygon.rings)
        s += " ring " + std::to_string(g.first) + "+" + std::to_string(g.count);
    for (const Part& p : r.polygon.parts)
        s += " part " + std::to_string(p.firstRing) + "+" + std::to_string(p.ringCount);
    return s;
}

}  // namespace flood::testing::io

using flood::testing::io::contains;
using flood::testing::io::source;
using flood::testing::io::square;
