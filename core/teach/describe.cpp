#include "flood/teach/describe.h"

#include <sstream>

#include "flood/machine/flood.h"
#include "flood/teach/narrate.h"
#include "flood/teach/transcript.h"

namespace flood {

static std::string vertexName(Index v) { return v == kNone ? "-" : std::to_string(v); }

std::string describeEvent(const Polygon& polygon, const Event& e) {
    std::ostringstream s;
    s << actionName(e.action);
    const char* c = e.side == Side::Left ? "Left" : "Right";
    switch (e.action) {
        case Action::Start:
            s << " at bottom " << vertexName(e.bottom) << " (part " << e.part << ")";
            break;
        case Action::Raise:
            s << " " << c << ": Next" << c << " "
              << vertexName(e.side == Side::Left ? e.before.nextLeft : e.before.nextRight)
              << " joins the chain";
            break;
        case Action::Bridge:
            s << " sag " << vertexName(e.sag) << " to " << vertexName(e.bridgeTo);
            if (e.gorgePushed != kNone) s << ", gorge " << e.gorgePushed << " pending";
            break;
        case Action::Spill:
            s << " over top " << vertexName(e.top) << " (jump -> " << vertexName(e.jumpTarget)
              << ")";
            // Where the water goes on: a new gorge at a bottom, or a pending gorge resumed
            // (its chain then starts at the vertex Left is after the event).
            if (e.bottom != kNone) s << ", new gorge at " << vertexName(e.bottom);
            else if (e.gorgePopped != kNone)
                s << ", into pending gorge " << e.gorgePopped << " at " << vertexName(e.after.left);
            break;
        case Action::Jump:
            s << " from top " << vertexName(e.top) << " to " << vertexName(e.jumpTarget);
            break;
        case Action::Fill:
            s << " at " << vertexName(e.before.nextLeft);
            if (e.gorgePopped != kNone) s << ", resume gorge " << e.gorgePopped;
            break;
        case Action::Forbidden: s << ": " << describeForbidden(polygon, e); break;
        default: break;
    }
    if (e.triangleCount > 0)
        s << (e.triangleCount == 1 ? "; triangle " : "; triangles ")
          << triangleRange(e.firstTriangle, e.triangleCount);
    return s.str();
}

}  // namespace flood
