#include "flood/geometry/polygon.h"

#include <algorithm>

#include "geometry/coincident.h"

namespace flood {

Index Polygon::ringOf(Index v) const {
    auto it = std::upper_bound(rings.begin(), rings.end(), v,
                               [](Index x, const Ring& r) { return x < r.first; });
    return Index(it - rings.begin()) - 1;
}

bool sameGeometry(const Polygon& a, const Polygon& b) {
    if (a.vertices != b.vertices || a.rings.size() != b.rings.size() ||
        a.parts.size() != b.parts.size())
        return false;
    for (size_t i = 0; i < a.rings.size(); ++i)
        if (a.rings[i].first != b.rings[i].first || a.rings[i].count != b.rings[i].count)
            return false;
    for (size_t i = 0; i < a.parts.size(); ++i)
        if (a.parts[i].firstRing != b.parts[i].firstRing ||
            a.parts[i].ringCount != b.parts[i].ringCount)
            return false;
    return true;
}

bool Polygon::tiled() const {
    size_t ringsSeen = 0, verticesSeen = 0;
    for (const Part& part : parts) {
        if (part.firstRing != ringsSeen) return false;
        ringsSeen += part.ringCount;
    }
    for (const Ring& ring : rings) {
        if (ring.first != verticesSeen) return false;
        verticesSeen += ring.count;
    }
    return ringsSeen == rings.size() && verticesSeen == vertices.size();
}

size_t Polygon::expectedTriangles() const {
    size_t t = 0;
    for (Index k = 0; k < parts.size(); ++k) {
        const Part& p = parts[k];
        const Index first = rings[p.firstRing].first;
        const size_t n = partVertices(k);
        // Each extra copy of a point (rings touching there) takes 2pi from the angle sum,
        // so two triangles fewer.
        const size_t copies =
            repeatedPoints(n, [&](size_t i) { return vertices[first + i]; }).size();
        // A T-junction adds a boundary node at a point that is already a vertex: one node
        // more, one copy more. A single-point hole has one vertex but turns by 0, not 2pi.
        size_t junctions = 0, points = 0;
        for (const EdgeSplit& s : splits) junctions += s.edge >= first && s.edge < first + n;
        for (Index r = p.firstRing + 1; r < p.firstRing + p.ringCount; ++r)
            points += rings[r].count == 1;
        t += n + 2 * (p.ringCount - 1) - 2 - 2 * copies - junctions - points;
    }
    return t;
}

void Polygon::addRing(const std::vector<Point>& pts, bool outer) {
    pointsDistinct = false;  // the new ring may touch the others
    if (outer) parts.push_back({Index(rings.size()), 0});
    rings.push_back({Index(vertices.size()), Index(pts.size())});
    parts.back().ringCount++;
    vertices.insert(vertices.end(), pts.begin(), pts.end());
}

}  // namespace flood
