// Groups of parts that lie apart: a MultiPolygon's parts whose bounding boxes a vertical or
// horizontal line separates cannot cross, touch or lie inside each other, so what is checked
// between parts (validation's checks 4-6, the checker's rule 8) can be checked group by group.
// On 125,000 islands side by side, the sweeps that took every part at once keep 250,000 edges
// in one tree, where each group needs four. Internal to core/, not a public API.
#pragma once
#include <cstddef>
#include <limits>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood {

// A closed axis-parallel box; empty (x0 > x1) until a point is added.
struct Box {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    void add(Point p) {
        if (p.x < x0) x0 = p.x;
        if (p.x > x1) x1 = p.x;
        if (p.y < y0) y0 = p.y;
        if (p.y > y1) y1 = p.y;
    }
    bool empty() const { return !(x0 <= x1); }
};

// The group of each box, numbered from 0 in the order of each group's first box, such that
// two boxes of different groups lie strictly on either side of a vertical or horizontal line.
// Found by cutting along x where no box spans the gap, then each piece along y, and so on
// (a guillotine cut); pieces that no line cuts are groups. Not the finest grouping in general
// (boxes in a pinwheel are one group) but exact for rows and grids. Empty boxes are groups of
// their own. Every coordinate must be finite. The work is capped at O(n log n) comparisons:
// past the cap, what is left uncut stays one group each piece, still a valid grouping.
std::vector<Index> groupsApart(const std::vector<Box>& boxes, size_t& groupCount);

}  // namespace flood
