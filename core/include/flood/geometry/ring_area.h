// Sums of doubled signed areas (cross products of coordinates) in doubles, with a proven bound
// on their error: what decides a ring's orientation, or proves two sums differ, without exact
// arithmetic whenever the bound allows — and ExactSum (predicates.h) when it does not. At 10^6
// vertices the exact expansions were an eighth of `flood triangulate`'s time.
// With ringOrientation below, the core's one place for a ring's orientation: the flood
// machine orients its loops with ringOrientation, and classifyVertices (the viewer's colours,
// the state table's rows) with the same rule, so that its classes are the machine's on every
// ring; validation takes ringAreaSign, since its check 3 asks whether the area is zero, and
// the two agree on the simple rings it accepts. The exact checker uses AreaEstimate alone,
// deliberately (checker.cpp says why).
// Internal to core/, not a public API.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "flood/geometry/polygon.h"
#include "flood/geometry/up.h"

namespace flood {

class AreaEstimate {
public:
    void addCross(Point a, Point b) {  // += a.x*b.y - a.y*b.x
        double l = a.x * b.y, r = a.y * b.x;
        sum_ += l - r;
        magnitude_ += std::fabs(l) + std::fabs(r);
        ++terms_;
    }
    void addTriangle(Point a, Point b, Point c) {  // += the doubled signed area of abc
        addCross(a, b), addCross(b, c), addCross(c, a);
    }
    double value() const { return sum_; }
    // Terms counted in 64 bits on every platform (size_t is 32 bits on wasm32 and 32-bit
    // Windows, where `size_t(1) << 50` was undefined).
    static constexpr uint64_t kMaxTerms = uint64_t(1) << 50;
    uint64_t terms() const { return terms_; }
    // |value() - exact| <= bound(), when finite() (not for kMaxTerms terms or more). Each product
    // and difference errs by at most u (2^-53) relatively, plus 2^-1074 absolutely where it
    // underflows, and a recursive sum of m terms by (m - 1)u of their magnitudes: at most
    // (m + 3)u·M + 3m·2^-1074 with M the exact sum of |products|; twice that covers the
    // rounding of M and of this formula.
    double bound() const {
        return 2 * (double(terms_) + 3) * 0x1p-53 * magnitude_ + 6 * double(terms_) * 0x1p-1074;
    }
    bool finite() const {
        return std::isfinite(sum_) && std::isfinite(magnitude_) && terms_ < kMaxTerms;
    }
    // The sign when the bound decides it, else 0 (undecided, not zero).
    int sign() const {
        if (!finite()) return 0;
        const double b = bound();
        return sum_ > b ? 1 : -sum_ > b ? -1 : 0;
    }

private:
    double sum_ = 0, magnitude_ = 0;
    uint64_t terms_ = 0;
};

// The exact sign of the doubled signed area of the ring of `count` vertices at `first`.
// +1 counter-clockwise, -1 clockwise, 0 zero area (as for any ring that is not simple).
int ringAreaSign(const Point* ring, Index count);
inline int ringAreaSign(const Polygon& polygon, Index first, Index count) {
    return ringAreaSign(polygon.vertices.data() + first, count);
}

// The orientation of a ring as the flood machine takes it: the turn at its lowest vertex
// (below()), strictly convex on a simple ring, so the same as ringAreaSign there and cheaper;
// where that corner is flat (only on a ring that is not simple), ringAreaSign. On rings that
// are not simple the two can differ, and the machine's choice decides which forbidden state
// unvalidated input reaches (docs/ERRORS.md's forbidden-bad-triangle.json): kept as it is.
int ringOrientation(const Point* ring, Index count);
// The same with the lowest vertex taken along `up` (belowToward()): the machine's rule for a
// ring of the input's coordinates when the machine turns them so that `up`, an axis, is +y.
int ringOrientation(const Point* ring, Index count, Up up);

}  // namespace flood
