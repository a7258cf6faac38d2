#include "ring_area.h"

#include "predicates.h"

namespace flood {

int ringAreaSign(const Polygon& polygon, Index first, Index count) {
    const Point* p = polygon.vertices.data() + first;
    AreaEstimate estimate;
    for (Index i = 0; i < count; ++i) estimate.addCross(p[i], p[i + 1 == count ? 0 : i + 1]);
    if (int s = estimate.sign()) return s;
    ExactSum exact;  // zero or too close to tell: only exact arithmetic can say
    for (Index i = 0; i < count; ++i) exact.addCross(p[i], p[i + 1 == count ? 0 : i + 1]);
    return exact.sign();
}

}  // namespace flood
