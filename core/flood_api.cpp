// The front door (flood_api.h): validation first, then the flood machine.
#include "flood/flood_api.h"

#include "flood/io/io.h"

namespace flood {

Polygon makePolygon(const std::vector<Rings>& parts) {
    Polygon p;
    std::vector<Point> open;
    for (const Rings& rings : parts)
        for (size_t r = 0; r < rings.size(); ++r) {
            const std::vector<Point>& ring = rings[r];
            // Closed as OGR, GEOS and WKT store it: the repeated first point is not a vertex.
            if (ring.size() > 3 && ring.back() == ring.front()) {
                open.assign(ring.begin(), ring.end() - 1);
                p.addRing(open, r == 0);
            } else {
                p.addRing(ring, r == 0);
            }
        }
    return p;
}

Triangulation triangulateParts(const std::vector<Rings>& parts, const Options& options) {
    Triangulation t;
    t.polygon = makePolygon(parts);
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
