#include "flood/machine/vertex_class.h"

#include <cmath>

#include <utility>

#include "flood/geometry/predicates.h"
#include "flood/geometry/ring_area.h"

namespace flood {

const char* vertexClassName(VertexClass c) {
    switch (c) {
        case VertexClass::Regular: return "regular";
        case VertexClass::Bottom: return "bottom";
        case VertexClass::Sag: return "sag";
        case VertexClass::Top: return "top";
        case VertexClass::Ceiling: return "ceiling";
        default: return "?";
    }
}

std::vector<VertexClass> classifyVertices(const Polygon& polygon, Up up) {
    std::vector<VertexClass> out(polygon.vertices.size(), VertexClass::Regular);
    const auto& v = polygon.vertices;
    for (size_t r = 0; r < polygon.rings.size(); ++r) {
        const Ring& ring = polygon.rings[r];
        if (ring.count == 1)
            out[ring.first] = VertexClass::Sag;  // a Steiner point: a hole's bottom
        if (ring.count < 3) continue;
        // A ring with a non-finite coordinate has no classes (the machine refuses it: NotFinite),
        // and the exact predicates are for finite doubles only.
        bool finite = true;
        for (Index i = 0; i < ring.count; ++i)
            finite &= std::isfinite(v[ring.first + i].x) && std::isfinite(v[ring.first + i].y);
        if (!finite) continue;
        // The file may list a ring either way; the predicates want the interior on the left.
        // Outer rings of a part come first: holes must turn the other way.
        bool isOuter = false;
        for (const Part& p : polygon.parts) isOuter |= (p.firstRing == r);
        // The machine's orientation (ring_area.h): it compares coordinates turned so that an
        // axis `up` is +y, and off the axes the input's own, lowest by y.
        const int sign =
            ringOrientation(v.data() + ring.first, ring.count, up.axis() ? up : Up::PlusY);
        bool reversed = isOuter ? sign < 0 : sign > 0;
        for (Index i = 0; i < ring.count; ++i) {
            Point prev = v[ring.first + (i + ring.count - 1) % ring.count];
            Point cur = v[ring.first + i];
            Point next = v[ring.first + (i + 1) % ring.count];
            if (reversed) std::swap(prev, next);
            bool isMin = belowToward(up, cur, prev) && belowToward(up, cur, next);
            bool isMax = belowToward(up, prev, cur) && belowToward(up, next, cur);
            bool isConvex = convex(prev, cur, next);
            VertexClass c = VertexClass::Regular;
            if (isMin) c = isConvex ? VertexClass::Bottom : VertexClass::Sag;
            if (isMax) c = isConvex ? VertexClass::Ceiling : VertexClass::Top;
            out[ring.first + i] = c;
        }
    }
    return out;
}

}  // namespace flood
