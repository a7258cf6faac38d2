// Find: a vertex, triangle, step or ring named by the user, looked up against a trace.
#pragma once
#include <cstdint>
#include <string>

#include "flood/log/replay.h"

namespace flood::view {

// Find: "v2999" (vertex), "t77022" (triangle), "s12051" (step), "r3" (ring), parsed and
// looked up against a trace. A bad query says why in `message`.
struct FindTarget {
    bool ok = false;
    std::string message;
    char kind = 0;  // 'v', 't', 's' or 'r'
    uint64_t index = 0;
    bool hasCenter = false;
    Point center;                           // where to centre the view
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // what to show (a ring's box; a point otherwise)
    uint32_t seekTo = kNone;                // step to seek to, kNone: stay
    std::vector<Index> vertices;            // what to frame: a vertex, a step's fingers
};
FindTarget findTarget(const Trace& trace, const std::string& query);

}  // namespace flood::view
