// Where a diagnostic points, in the words `flood check`'s AT column and the Python module's
// ring/vertex show: read from its culprits (status.h), never cut out of its message.
#pragma once
#include <string>

#include "flood/geometry/polygon.h"
#include "flood/geometry/status.h"

namespace flood {

struct Where {
    Index ring = kNone;    // the first culprit vertex's ring, else the first culprit ring
    Index vertex = kNone;  // the first culprit vertex, numbered within its ring
    std::string text;      // "ring R vertex V (x, y)", "ring R", or "" when nothing is named
};
Where whereOf(const Polygon& polygon, const Culprits& culprits);

// The point a diagnostic is at: its exact point when it has one; where its two culprit edges
// cross (in doubles: a display point, not exact; the middle of a collinear overlap). With
// `anyVertex`, else its first culprit vertex, else its first ring's first vertex. False when
// none of these is known.
bool diagnosticPoint(const Polygon& polygon, const Culprits& culprits, Point& p,
                     bool anyVertex = false);

// The message without its leading "NAME: " and, when it comes next, "WHERE: " (validate()
// puts the location first): what is wrong, the location being shown apart.
std::string reasonOf(const std::string& message, const std::string& name, const Where& where);

}  // namespace flood
