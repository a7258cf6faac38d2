// The front door (flood_api.h): validation first, then the flood machine.
#include "flood/flood_api.h"

#include "flood/io/io.h"

namespace flood {

Polygon makePolygon(const std::vector<Rings>& parts) { return makePolygonOf(parts); }

Triangulation triangulateParts(const std::vector<Rings>& parts, const Options& options) {
    return triangulatePolygon(makePolygon(parts), options);
}

Triangulation triangulatePolygon(Polygon polygon, const Options& options) {
    Triangulation t;
    t.polygon = std::move(polygon);
    t.diagnostic = validate(t.polygon, "polygon");
    if (!t.ok()) return t;
    FloodResult r = triangulate(t.polygon, nullptr, options);
    t.triangles = std::move(r.triangles);
    t.diagnostic = r.diagnostic;
    return t;
}

Trace traceParts(const std::vector<Rings>& parts, const Options& options) {
    Polygon polygon = makePolygon(parts);
    Diagnostic d = validate(polygon, "polygon");
    if (d.ok()) return record(polygon, options);
    Trace t;
    t.polygon = std::move(polygon);
    t.diagnostic = d;
    return t;
}

}  // namespace flood
