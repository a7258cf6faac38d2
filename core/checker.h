// The exact triangulation checker: proves a triangle list is a triangulation of a polygon.
#pragma once
#include <string>
#include <vector>

#include "polygon.h"
#include "status.h"

namespace flood {

struct CheckResult {
    bool ok = false;
    std::string reason;  // first rule broken, naming the triangle / edge / vertices
    Culprits culprits;   // the same triangle / vertices / ring as data
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

}  // namespace flood
