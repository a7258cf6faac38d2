// Rule 8 of the exact checker (core/check/checker.cpp): the parts of a MultiPolygon do not overlap.
#pragma once
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood {

// A boundary edge directed with its part's interior on its left (outer ring counter-clockwise,
// holes clockwise), cut at the part's T-junctions.
struct BoundaryEdge {
    Index a, b, ring;
};

// Given that rules 1-7 hold (each part's triangles tile that part exactly), proves that
// triangles of different parts have disjoint interiors: the parts' boundary winding numbers
// sum to at most 1 everywhere. Parts may touch at points, T-junctions and collinear stretches.
// Returns an empty reason when they do not overlap, else the reason ("parts-overlap: ..."),
// naming the two parts and a vertex or the two crossing edges, with those as data. Exact
// (orient and coordinate comparisons), O(n log n): a sweep over the boundary edges of the
// parts that no line sets apart from the others.
struct PartsOverlap {
    std::string reason;           // "" when the parts do not overlap
    std::vector<Index> vertices;  // the vertex beside the overlap, or the crossing edges' ends
    std::vector<Index> parts;     // the parts that overlap
};
PartsOverlap partsOverlap(const std::vector<Point>& vertices,
                          const std::vector<Index>& partOfVertex,
                          std::vector<BoundaryEdge> boundary);  // freed once read

}  // namespace flood
