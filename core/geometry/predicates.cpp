// Exact geometric predicates: orient, inside, and the ExactSum accumulator.
//
// Sign conventions (stated once): coordinates are x to the right, y up. orient(a, b, c) is the
// sign of the doubled signed area of triangle (a, b, c) =
//     ax*by - ay*bx + bx*cy - by*cx + cx*ay - cy*ax,
// positive for a counter-clockwise turn (c left of a->b), negative for clockwise, 0 when
// collinear. ExactSum holds an exact sum of products; addCross(a, b) adds a x b = ax*by - ay*bx,
// so summing addCross over a ring's edges gives its doubled signed area (positive when the
// ring is counter-clockwise).
//
// Three stages, each exact where it is used:
//  1. Floating-point filter (Shewchuk's ccwerrboundA on the sum of absolute products). Falls
//     through when anything is non-finite or the magnitudes are so small that underflow could
//     spoil the relative error bound.
//  2. Expansion arithmetic: each of the six products is split exactly into two doubles with fma
//     (two-product) and the twelve doubles are summed with two-sum into a non-overlapping
//     expansion whose sign is the sign of its largest component. Exact when every nonzero
//     |coordinate| lies in [2^-450, 2^450]: products then stay in [2^-900, 2^901], their
//     rounding errors are normal doubles, and no sum can overflow.
//  3. GMP rationals otherwise (mpq_set_d is exact for every finite double).
#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"

#include <gmp.h>

#include <array>
#include <cassert>
#include <cmath>

namespace flood {

namespace {

constexpr double kSafeMin = 0x1p-450;  // expansion arithmetic is exact for |coordinates|
constexpr double kSafeMax = 0x1p450;   //   in [kSafeMin, kSafeMax] (or zero)
constexpr double kTermMax = 0x1p1000;  // ExactSum terms stay below this (no overflow)

// x + y = s + e exactly (Knuth's two-sum; needs round-to-nearest and no fp contraction).
inline void twoSum(double a, double b, double& s, double& e) {
    s = a + b;
    double bv = s - a;
    double av = s - bv;
    e = (a - av) + (b - bv);
}

// a * b = p + e exactly, when no underflow/overflow happens.
inline void twoProduct(double a, double b, double& p, double& e) {
    p = a * b;
    e = std::fma(a, b, -p);
}

inline bool safe(double v) {
    double m = std::fabs(v);
    return m == 0 || (m >= kSafeMin && m <= kSafeMax);
}

// Adds b to the non-overlapping expansion h[0..len) (increasing magnitude) in place,
// dropping zero components. Returns the new length (at most len + 1).
inline int growExpansion(double* h, int len, double b) {
    double q = b;
    int j = 0;
    for (int i = 0; i < len; ++i) {
        double s, e;
        twoSum(q, h[i], s, e);
        if (e != 0) h[j++] = e;
        q = s;
    }
    if (q != 0) h[j++] = q;
    return j;
}

// A predicate's value written as a sum of N products f[i][0] * f[i][1] of its (negated)
// coordinates: the exact stages read only these terms, so each predicate states them once.
template <size_t N>
using Products = std::array<std::array<double, 2>, N>;

// Stage 2 applies when every factor is in the safe exponent range, stage 3 otherwise.
template <size_t N>
Stage exactStage(const Products<N>& f) {
    for (const auto& pr : f)
        if (!safe(pr[0]) || !safe(pr[1])) return Stage::Rationals;
    return Stage::Expansion;
}

// Stage 2: each product is split into two doubles (twoProduct) and summed as an expansion,
// whose largest component has the sign.
template <size_t N>
int expansionSign(const Products<N>& f) {
    double h[2 * N + 1];
    int len = 0;
    for (const auto& pr : f) {
        double p, e;
        twoProduct(pr[0], pr[1], p, e);
        len = growExpansion(h, len, p);
        len = growExpansion(h, len, e);
    }
    if (len == 0) return 0;
    return h[len - 1] > 0 ? 1 : -1;
}

struct Mpq {
    mpq_t q;
    Mpq() { mpq_init(q); }
    explicit Mpq(double d) {
        mpq_init(q);
        // GMP aborts on inf/NaN. Non-finite input is outside the predicates' contract (callers
        // validate first); it gets an unspecified sign here, never a crash.
        if (std::isfinite(d)) mpq_set_d(q, d);
    }
    Mpq(const Mpq&) = delete;
    Mpq& operator=(const Mpq&) = delete;
    ~Mpq() { mpq_clear(q); }
};

// q += a * b exactly.
void mpqAddProduct(mpq_t q, double a, double b) {
    Mpq x(a), y(b);
    mpq_mul(x.q, x.q, y.q);
    mpq_add(q, q, x.q);
}

// Stage 3: the sum in GMP rationals.
template <size_t N>
int rationalSign(const Products<N>& f) {
    Mpq sum;
    for (const auto& pr : f) mpqAddProduct(sum.q, pr[0], pr[1]);
    return mpq_sgn(sum.q);
}

// Stages 2 and 3: the exact sign of the sum, and the stage that decided it.
template <size_t N>
int exactSign(const Products<N>& f, Stage& stage) {
    stage = exactStage(f);
    return stage == Stage::Expansion ? expansionSign(f) : rationalSign(f);
}

// orient's doubled area, ax*by - ay*bx + bx*cy - by*cx + cx*ay - cy*ax, as its six products.
Products<6> orientProducts(Point a, Point b, Point c) {
    return {{{a.x, b.y}, {-a.y, b.x}, {b.x, c.y}, {-b.y, c.x}, {c.x, a.y}, {-c.y, a.x}}};
}

using predicates_detail::filterSign;  // stage 1 (predicates.h)
using predicates_detail::orientFilter;

}  // namespace

int predicates_detail::orientBeyondFilter(Point a, Point b, Point c) {
    assert(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(b.x) && std::isfinite(b.y) &&
           std::isfinite(c.x) && std::isfinite(c.y) &&
           "orient() needs finite coordinates; validate the input first");
    // Both products have a factor that is exactly zero (points on one vertical or horizontal
    // line, or a repeated point: common in rectilinear input): the area is exactly zero, no
    // expansion needed. A difference of two finite doubles is zero only when they are equal.
    if ((a.x == c.x || b.y == c.y) && (a.y == c.y || b.x == c.x)) return 0;
    Stage stage;
    return exactSign(orientProducts(a, b, c), stage);
}

namespace {
// d·(b − a) by the filter. Each term is a product of an exact component and one rounded
// difference, so orient's error bound covers it.
inline int heightFilter(Up d, Point a, Point b) {
    double p = d.x * (b.x - a.x), q = d.y * (b.y - a.y);
    return filterSign(p + q, std::fabs(p) + std::fabs(q));
}
}  // namespace

int heightSign(Up d, Point a, Point b) {
    ++work().heightCalls;
    if (int s = heightFilter(d, a, b)) return s;
    Stage stage;  // d·(b − a) = dx*bx - dx*ax + dy*by - dy*ay
    return exactSign(Products<4>{{{d.x, b.x}, {-d.x, a.x}, {d.y, b.y}, {-d.y, a.y}}}, stage);
}

// The same stages as orient(), saying which decided; not counted as the machine's work. (orient()
// answers the exactly-zero products of axis-collinear points without stage 2; this reports the
// stage that would decide them.)
OrientReport orientExplained(Point a, Point b, Point c) {
    OrientReport r;
    if ((r.sign = orientFilter(a, b, c, r.det))) return r;
    r.sign = exactSign(orientProducts(a, b, c), r.stage);
    return r;
}

const char* stageName(Stage s) {
    switch (s) {
        case Stage::Filter: return "filter";
        case Stage::Expansion: return "expansion";
        case Stage::Rationals: return "rationals";
    }
    return "?";
}

namespace {
// s lies on the closed segment p-q (p == q allowed).
template <class Orient>
bool onSegment(Orient&& turn, Point s, Point p, Point q) {
    if (turn(p, q, s) != 0) return false;
    return std::fmin(p.x, q.x) <= s.x && s.x <= std::fmax(p.x, q.x) && std::fmin(p.y, q.y) <= s.y &&
           s.y <= std::fmax(p.y, q.y);
}

// Rule: s is inside when it lies on none of the four closed edges L-R, R-NR, NR-NL, NL-L and
// the closed path L -> R -> NR -> NL -> L winds around it a nonzero number of times. For a
// simple quadrangle (convex or not, either orientation) this is exactly its open interior; a
// degenerate quadrangle (repeated or collinear vertices) has no interior points beyond those of
// its non-degenerate part; a self-crossing one counts both lobes. All tests are exact orient
// calls (`turn`) and exact coordinate comparisons.
template <class Orient>
bool insideWith(Orient&& turn, Point s, Point left, Point right, Point nextRight, Point nextLeft) {
    const Point q[4] = {left, right, nextRight, nextLeft};
    int winding = 0;
    for (int i = 0; i < 4; ++i) {
        Point p = q[i], r = q[(i + 1) % 4];
        if (onSegment(turn, s, p, r)) return false;
        if (p.y <= s.y) {
            if (r.y > s.y && turn(p, r, s) > 0) ++winding;  // upward edge, s on its left
        } else {
            if (r.y <= s.y && turn(p, r, s) < 0) --winding;  // downward edge, s on its right
        }
    }
    return winding != 0;
}
}  // namespace

bool inside(Point s, Point left, Point right, Point nextRight, Point nextLeft) {
    return insideWith(orient, s, left, right, nextRight, nextLeft);
}

InsideReport insideExplained(Point s, Point left, Point right, Point nextRight, Point nextLeft) {
    InsideReport r;
    auto turn = [&r](Point a, Point b, Point c) {
        OrientReport o = orientExplained(a, b, c);
        ++r.orients;
        if (o.stage > r.stage) r.stage = o.stage;
        return o.sign;
    };
    r.inside = insideWith(turn, s, left, right, nextRight, nextLeft);
    return r;
}

// [SECTION] ExactSum

struct ExactSum::Big {
    mpq_t q;
    Big() { mpq_init(q); }
    Big(const Big& o) {
        mpq_init(q);
        mpq_set(q, o.q);
    }
    Big& operator=(const Big&) = delete;
    ~Big() { mpq_clear(q); }
};

ExactSum::Big& ExactSum::ownBig() {
    if (!big_) big_ = std::make_shared<Big>();
    else if (big_.use_count() > 1) big_ = std::make_shared<Big>(*big_);
    return *big_;
}

namespace {
// q += the expansion's terms, exactly.
void mpqAddTerms(mpq_t q, const std::vector<double>& terms) {
    for (double t : terms) mpqAddProduct(q, t, 1);
}
}  // namespace

void ExactSum::toBig() {
    mpqAddTerms(ownBig().q, terms_);
    terms_.clear();
    compressedSize_ = 0;
}

void ExactSum::growTerm(double b) {
    if (b == 0) return;
    if (!(std::fabs(b) <= kTermMax)) {
        mpqAddProduct(ownBig().q, b, 1);
        return;
    }
    double q = b;
    size_t j = 0;
    for (size_t i = 0; i < terms_.size(); ++i) {
        double s, e;
        twoSum(q, terms_[i], s, e);
        if (e != 0) terms_[j++] = e;
        q = s;
    }
    terms_.resize(j);
    if (q != 0) terms_.push_back(q);
    if (!terms_.empty() && std::fabs(terms_.back()) > kTermMax) toBig();
}

// Shewchuk's Compress: same value, non-overlapping, usually far fewer components.
void ExactSum::maybeCompress() {
    if (terms_.size() <= 2 * compressedSize_ + 8) return;
    size_t m = terms_.size();
    std::vector<double> g(m);
    double q = terms_[m - 1];
    size_t bottom = m - 1;
    for (size_t i = m - 1; i-- > 0;) {
        double s, e;
        twoSum(q, terms_[i], s, e);
        if (e != 0) {
            g[bottom--] = s;
            q = e;
        } else {
            q = s;
        }
    }
    g[bottom] = q;
    size_t top = 0;
    for (size_t i = bottom + 1; i < m; ++i) {
        double s, e;
        twoSum(g[i], q, s, e);
        if (e != 0) terms_[top++] = e;
        q = s;
    }
    terms_[top++] = q;
    terms_.resize(top);
    if (top == 1 && terms_[0] == 0) terms_.clear();
    compressedSize_ = terms_.size();
}

void ExactSum::addProduct(double a, double b) {
    if (a == 0 || b == 0) return;
    double ma = std::fabs(a), mb = std::fabs(b);
    if (ma >= kSafeMin && ma <= kSafeMax && mb >= kSafeMin && mb <= kSafeMax) {
        double p, e;
        twoProduct(a, b, p, e);
        growTerm(p);
        growTerm(e);
        maybeCompress();
    } else {
        mpqAddProduct(ownBig().q, a, b);
    }
}

void ExactSum::addCross(Point a, Point b) {
    addProduct(a.x, b.y);
    addProduct(-a.y, b.x);
}

void ExactSum::addTriangle(Point a, Point b, Point c) {
    addCross(a, b);
    addCross(b, c);
    addCross(c, a);
}

void ExactSum::add(const ExactSum& other, int sign) {
    assert((sign == 1 || sign == -1) && "ExactSum::add takes sign +1 or -1");
    if (&other == this) {
        // NOLINTNEXTLINE(performance-unnecessary-copy-initialization): other is *this, changing
        ExactSum copy = other;
        add(copy, sign);
        return;
    }
    for (double t : other.terms_) growTerm(sign * t);
    maybeCompress();
    if (other.big_) {
        Big& b = ownBig();
        if (sign > 0) mpq_add(b.q, b.q, other.big_->q);
        else mpq_sub(b.q, b.q, other.big_->q);
    }
}

int ExactSum::sign() const {
    if (!big_) return terms_.empty() ? 0 : (terms_.back() > 0 ? 1 : -1);
    Big total(*big_);
    mpqAddTerms(total.q, terms_);
    return mpq_sgn(total.q);
}

double ExactSum::approx() const {
    if (big_) {
        Big total(*big_);
        mpqAddTerms(total.q, terms_);
        return mpq_get_d(total.q);
    }
    double s = 0;
    for (double t : terms_) s += t;  // increasing magnitude: the error is tiny
    return s;
}

bool ExactSum::operator==(const ExactSum& other) const {
    ExactSum d = *this;
    d.add(other, -1);
    return d.sign() == 0;
}

}  // namespace flood
