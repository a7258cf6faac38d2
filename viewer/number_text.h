// Numbers as the viewer prints them: the shortest text that reads back as the same double
// (-127.71, never -127.70999999999999), as the core's messages and files write them.
#pragma once
#include <charconv>
#include <string>

#include "polygon.h"

namespace flood::view {

inline std::string shortest(double v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

inline std::string pointText(Point p) { return "(" + shortest(p.x) + ", " + shortest(p.y) + ")"; }

}  // namespace flood::view
