#include "verify.h"

#include <algorithm>
#include <cmath>

#include "io.h"

namespace flood {

Polygon complementOf(const Polygon& polygon) {
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (Point p : polygon.vertices) {
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
    }
    // A margin as large as the polygon keeps the box strictly outside it, also when the
    // coordinates are far from the origin (the margin never vanishes in rounding).
    double scale = std::max({maxX - minX, maxY - minY, std::fabs(minX), std::fabs(maxX),
                             std::fabs(minY), std::fabs(maxY), 1.0});
    double x0 = minX - scale, y0 = minY - scale, x1 = maxX + scale, y1 = maxY + scale;
    auto ring = [&](Index r) {
        const Ring& g = polygon.rings[r];
        return std::vector<Point>(polygon.vertices.begin() + g.first,
                                  polygon.vertices.begin() + g.first + g.count);
    };
    Polygon c;
    c.addRing({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, true);
    for (const Part& part : polygon.parts) c.addRing(ring(part.firstRing), false);
    // Holes become parts; a point hole bounds no area, so it has no complement.
    for (const Part& part : polygon.parts)
        for (Index r = part.firstRing + 1; r < part.firstRing + part.ringCount; ++r)
            if (polygon.rings[r].count > 1) c.addRing(ring(r), true);
    // Parts that touched at a T-junction are now holes of the box touching there: validation
    // records the splits the flood needs (an invalid input leaves none; its flood will fail).
    validate(c, "complement");
    return c;
}

Verification verify(const Polygon& polygon, const Options& options) {
    Verification v;
    v.flood = triangulate(polygon, nullptr, options);
    if (v.flood.diagnostic.ok()) v.check = checkTriangulation(polygon, v.flood.triangles);
    Polygon complement = complementOf(polygon);
    v.complementFlood = triangulate(complement, nullptr, options);
    if (v.complementFlood.diagnostic.ok()) v.complementCheck = checkTriangulation(complement, v.complementFlood.triangles);
    return v;
}

std::string Verification::summary() const {
    auto side = [](const char* what, const FloodResult& f, const CheckResult& c) {
        std::string s = what;
        if (!f.diagnostic.ok()) return s + ": flooding stopped: " + f.diagnostic.message;
        if (!c.ok) return s + ": " + std::to_string(f.triangles.size()) + " triangles, NOT a triangulation: " + c.reason;
        return s + ": " + std::to_string(f.triangles.size()) + " triangles, exact triangulation";
    };
    return side("polygon", flood, check) + "\n" + side("complement", complementFlood, complementCheck);
}

}  // namespace flood
