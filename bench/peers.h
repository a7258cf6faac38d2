// Adapters to the peer triangulators. Each runs the peer's whole job on a flood::Polygon and
// returns triangles as input vertex indices, so Flood's exact checker can judge them.
#pragma once
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace bench {

struct PeerOutput {
    std::vector<flood::Triangle> triangles;
    size_t added = 0;   // output vertices that are not input points (Steiner / intersections)
    std::string error;  // the peer reported failure
};

// Maps exact coordinates to the first input vertex with them (linear time, hash table).
class CoordIndex {
public:
    explicit CoordIndex(const flood::Polygon& p);
    flood::Index find(flood::Point q) const;  // kNone when q is not an input point
    flood::Index canonical(flood::Index v) const { return canonical_[v]; }

private:
    std::vector<flood::Index> slots_;
    std::vector<flood::Index> canonical_;
    const flood::Polygon* polygon_;
    size_t mask_ = 0;
};

// GLU tessellator, GLU_TESS_WINDING_ODD, triangles only (edge-flag callback installed).
PeerOutput runGlu(const flood::Polygon& p);
// CGAL 5 constrained Delaunay: points bulk-inserted with their index, then every ring edge as a
// constraint, then faces marked inside by nesting level (odd = inside).
PeerOutput runCgal(const flood::Polygon& p, const CoordIndex& index);
// GEOS C API GEOSConstrainedDelaunayTriangulation_r on the (multi)polygon. With `index` null the
// output is only counted, not mapped back (the timed runs).
PeerOutput runGeos(const flood::Polygon& p, const CoordIndex* index);

#ifdef FLOOD_EARCUT_HPP
// Native earcut.hpp (mapbox::earcut, a fresh call per part), compiled into this driver at the
// same optimisation as Flood: the peer a C++ program would pick. Triangles as input indices.
PeerOutput runEarcut(const flood::Polygon& p);
#endif

// Orients every triangle counter-clockwise (peers differ in convention); degenerate ones stay.
void orientCounterClockwise(const flood::Polygon& p, std::vector<flood::Triangle>& t);

}  // namespace bench
