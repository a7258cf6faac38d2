// The floor (issue 13): what any triangulator of a polygon must at least do, timed on the same
// input, so Flood's time can be read as a multiple of it. Three parts, each over all vertices:
//   io      read the coordinates and write the triangles: a copy of the n points into fresh
//           memory and n + 2h - 2 index triples written out (memory bandwidth);
//   orient  one exact orientation test per vertex, with its two ring neighbours;
//   sags    find the sags (vertices below both ring neighbours, below() order) and sort them.
#pragma once
#include <cstdint>

#include "flood/geometry/polygon.h"

namespace bench {

struct FloorNs {
    double io = 0, orient = 0, sags = 0;  // median ns of each part alone
    double total() const { return io + orient + sags; }
};

FloorNs measureFloor(const flood::Polygon& p);

}  // namespace bench
