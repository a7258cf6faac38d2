// Rule 8 of the exact checker (core/checker.cpp): the parts of a MultiPolygon do not overlap.
#pragma once
#include <string>
#include <vector>

#include "polygon.h"

namespace flood {

// A boundary edge directed with its part's interior on its left (outer ring counter-clockwise,
// holes clockwise), cut at the part's T-junctions.
struct BoundaryEdge {
    Index a, b, ring;
};

// Given that rules 1-7 hold (each part's triangles tile that part exactly), proves that
// triangles of different parts have disjoint interiors: the parts' boundary winding numbers
// sum to at most 1 everywhere. Parts may touch at points, T-junctions and collinear stretches.
// Returns "" when they do not overlap, else the reason ("parts-overlap: ..."), naming the two
// parts and a vertex or the two crossing edges. Exact (orient and coordinate comparisons),
// O(n log n): a sweep over the boundary edges.
std::string partsOverlap(const std::vector<Point>& vertices, const std::vector<Index>& partOfVertex,
                         const std::vector<BoundaryEdge>& boundary);

}  // namespace flood
