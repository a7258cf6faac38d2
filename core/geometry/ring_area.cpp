#include "flood/geometry/ring_area.h"

#include "flood/geometry/predicates.h"

namespace flood {

int ringAreaSign(const Point* p, Index count) {
    AreaEstimate estimate;
    for (Index i = 0; i < count; ++i) estimate.addCross(p[i], p[i + 1 == count ? 0 : i + 1]);
    if (int s = estimate.sign()) return s;
    ExactSum exact;  // zero or too close to tell: only exact arithmetic can say
    for (Index i = 0; i < count; ++i) exact.addCross(p[i], p[i + 1 == count ? 0 : i + 1]);
    return exact.sign();
}

namespace {
template <class Below>
int turnAtLowest(const Point* p, Index count, Below lower) {
    Index low = 0;
    Point lowest = p[0];  // held, not read again through `low` on every vertex
    for (Index i = 1; i < count; ++i)
        if (lower(p[i], lowest)) low = i, lowest = p[i];
    int t = orient(p[low == 0 ? count - 1 : low - 1], p[low], p[low + 1 == count ? 0 : low + 1]);
    return t != 0 ? t : ringAreaSign(p, count);
}
}  // namespace

int ringOrientation(const Point* p, Index count) {
    return turnAtLowest(p, count, [](Point a, Point b) { return below(a, b); });
}

int ringOrientation(const Point* p, Index count, Up up) {
    return turnAtLowest(p, count, [up](Point a, Point b) { return belowToward(up, a, b); });
}

}  // namespace flood
