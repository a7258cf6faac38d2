// The machine's own words for where it stopped (flood.h): defined here, beside the machine, so
// that the machine depends on no layer above it (they were in teach/narrate.cpp).
#include <algorithm>
#include <sstream>

#include "flood/machine/flood.h"
#include "geometry/number_text.h"

namespace flood {

// Declared in flood.h (the public API): a forbidden state's diagnostic, in words and as data.
Culprits forbiddenCulprits(const Polygon& polygon, const Event& e) {
    Culprits c;
    const Fingers& f = e.before;
    for (Index v : {e.culprit, e.culprit2, f.left, f.right, f.nextLeft, f.nextRight})
        if (v < polygon.vertices.size() &&
            std::find(c.vertices.begin(), c.vertices.end(), v) == c.vertices.end()) {
            c.vertices.push_back(v);
            Index r = polygon.ringOf(v);
            if (std::find(c.rings.begin(), c.rings.end(), r) == c.rings.end()) c.rings.push_back(r);
        }
    return c;
}

std::string describeForbidden(const Polygon& polygon, const Event& e) {
    std::ostringstream os;
    auto vertex = [&](const char* label, Index v) {
        if (v == kNone || v >= polygon.vertices.size()) return;
        Index r = polygon.ringOf(v);
        Point p = polygon.vertices[v];
        // Coordinates as the shortest text that reads back the same (-127.71, not
        // -127.70999999999999), as every message and file writes them.
        os << "; " << label << " = vertex " << v << " (ring " << r << " vertex "
           << v - polygon.rings[r].first << ", " << formatDouble(p.x) << ", " << formatDouble(p.y)
           << ")";
    };
    os << "forbidden transition " << forbiddenName(e.reason) << " at step " << e.step + 1;
    vertex("at", e.culprit);
    vertex("and", e.culprit2);
    vertex("Left", e.after.left);
    vertex("Right", e.after.right);
    os << ": " << forbiddenText(e.reason);
    return os.str();
}

}  // namespace flood
