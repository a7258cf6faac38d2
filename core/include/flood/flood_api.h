// The front door of libfloodcore for programs that link Flood: rings in, index triples out,
// every polygon validated first (so invalid input gets a diagnostic, never a wrong
// triangulation). Installed as <flood/flood_api.h>; CMake: find_package(Flood) and link
// Flood::core; pkg-config: `flood` (see the README's "C++ package").
#pragma once
#include <string>
#include <vector>

#include "flood/geometry/point_view.h"  // the caller's own points: makePolygonOf, PointAccess, Span
#include "flood/io/io.h"                // validate(): the validity rules alone
#include "flood/log/replay.h"           // Trace, Replay: seek to any step of a recorded flood
#include "flood/machine/flood.h"  // Options, Triangle, Diagnostic, Status, triangulate() without validation

namespace flood {

// One polygon: its outer ring, then its holes. A ring lists its vertices in order, in either
// orientation, open or closed (a last point equal to the first, as OGR, GEOS and WKT store
// rings, is not a vertex); a hole may be a single point.
using Rings = std::vector<std::vector<Point>>;

// A MultiPolygon of `parts` as a Polygon. Vertices are numbered through all rings in order,
// from 0: the numbers the triangles below use. Parts without rings are skipped.
Polygon makePolygon(const std::vector<Rings>& parts);

struct Triangulation {
    Polygon polygon;                  // the input, vertices numbered as in makePolygon
    std::vector<Triangle> triangles;  // counter-clockwise index triples into polygon.vertices
    Diagnostic diagnostic;            // Ok, or why there are no triangles
    bool ok() const { return diagnostic.ok(); }
};

// Validates the parts, then floods them.
Triangulation triangulateParts(const std::vector<Rings>& parts, const Options& options = {});

// Validates a polygon made by makePolygon or makePolygonOf, then floods it.
Triangulation triangulatePolygon(Polygon polygon, const Options& options = {});

// triangulateParts over the caller's own points, read once into the polygon
// (geometry/point_view.h): `rings` is a range of rings (outer, then holes), each a range of
// points of any type with x/y or [0]/[1] members (or a PointAccess); `parts` a range of those.
// The same triangles as triangulateParts given the same coordinates.
template <typename RingsRange>
Triangulation triangulateView(const RingsRange& rings, const Options& options = {}) {
    Polygon polygon;
    bool outer = true;
    for (const auto& ring : rings) {
        addRingOf(polygon, ring, outer);
        outer = false;
    }
    return triangulatePolygon(std::move(polygon), options);
}
template <typename PartsRange>
Triangulation triangulatePartsView(const PartsRange& parts, const Options& options = {}) {
    return triangulatePolygon(makePolygonOf(parts), options);
}

// Validates the parts, then floods them recording every event; on invalid input the trace
// has no events and its diagnostic says why. Replay it with flood::Replay.
Trace traceParts(const std::vector<Rings>& parts, const Options& options = {});

}  // namespace flood
