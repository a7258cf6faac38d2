// The exact triangulation checker: proves a triangle list is a triangulation of a polygon.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/ring_area.h"  // AreaEstimate
#include "flood/geometry/status.h"

namespace flood {

// The rules checker.cpp numbers, in the order they are checked. Rings (0) is what must hold
// of the polygon before a triangle can be judged: rings long enough, indices that fit, and
// (checked where rule 5 orients the rings) no ring of zero area.
enum class CheckRule : int {
    Rings = 0,
    Indices = 1,           // every index in range
    PartsAndCount = 2,     // one part per triangle, the count per part, splits inside their edge
    CounterClockwise = 3,  // every triangle counter-clockwise and non-degenerate
    DistinctEdges = 4,     // no directed edge twice
    BoundaryEdges = 5,     // every boundary edge once, from the inside
    InteriorTwins = 6,     // every other edge has its reverse
    Area = 7,              // the areas add up
    PartsDisjoint = 8,     // parts do not overlap
    None = -1              // every rule holds
};

struct CheckResult {
    bool ok = false;
    std::string reason;                // first rule broken, naming the triangle / edge / vertices
    Culprits culprits;                 // the same triangle / vertices / ring as data
    CheckRule rule = CheckRule::None;  // the rule `reason` says is broken (None when ok)
};

// Checks, exactly (no epsilon): triangle count n + 2h - 2 - 2d per part (d = vertices repeating
// an earlier point of the part, where rings touch; see checker.cpp); every triangle
// counter-clockwise and non-degenerate with indices in range; every boundary edge covered
// exactly once on the interior side (outer loop counter-clockwise, holes clockwise, whatever
// orientation the input rings had); every other edge used by exactly two triangles in
// opposite directions; the triangle areas sum exactly to the polygon's area; triangles of
// different parts have disjoint interiors (parts may touch at points, at a vertex inside
// another part's edge, along collinear stretches; a part may lie in another's hole).
CheckResult checkTriangulation(const Polygon& polygon, const std::vector<Triangle>& triangles);

// Rule 3 and the triangles' half of rule 7 look at each triangle alone, so a caller with a
// core to spare may compute them there (checkTriangles) while checkTriangulation does the
// rest, handed a function that waits for them (`triangleCheck`): cli/main.cpp does it beside
// writing the output. The result, message included, is the one checkTriangulation gives alone.
struct TriangleCheck {
    CheckResult rule3;  // the first clockwise or degenerate triangle, or a pass
    AreaEstimate area;  // the doubled triangle areas, summed in triangle order
};
// Safe on any input: a triangle with an index out of range is left to rule 1.
TriangleCheck checkTriangles(const Polygon& polygon, const std::vector<Triangle>& triangles);
CheckResult checkTriangulation(const Polygon& polygon, const std::vector<Triangle>& triangles,
                               const std::function<TriangleCheck()>& triangleCheck);

}  // namespace flood
