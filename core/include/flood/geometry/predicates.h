// The paper's three geometric predicates (§5) — convex, below, inside — and the exact
// orientation test they rest on. Coordinates: x to the right, y up; "up" is +y.
// Every predicate is exact for any finite double input: a fast floating-point filter,
// then exact expansion arithmetic, then GMP rationals for extreme exponents. No epsilon.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>

#include "flood/geometry/polygon.h"
#include "flood/geometry/up.h"
#include "flood/geometry/work.h"

namespace flood {

// Stage 1, the floating-point filter, inline so that the machine's many orient() calls cost a
// few instructions when it decides; the exact stages are in predicates.cpp.
namespace predicates_detail {
constexpr double kEpsilon = 0x1p-53;  // half an ulp of 1: the unit roundoff
constexpr double kCcwErrBoundA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kFilterMin = 0x1p-800;  // below this, underflow could matter: go exact

// A determinant `det` whose error is below kCcwErrBoundA * `sum`: +1 or -1 when it decides, 0
// when it cannot. A NaN or infinite det or sum fails every comparison (an infinite bound
// exceeds everything): 0, so no finiteness test is needed.
inline int filterSign(double det, double sum) {
    if (sum >= kFilterMin) {
        const double bound = kCcwErrBoundA * sum;
        if (det > bound) return 1;
        if (-det > bound) return -1;
    }
    return 0;
}
// Stage 1 for orient: `det` gets the filter's value.
inline int orientFilter(Point a, Point b, Point c, double& det) {
    const double detLeft = (a.x - c.x) * (b.y - c.y);
    const double detRight = (a.y - c.y) * (b.x - c.x);
    det = detLeft - detRight;
    return filterSign(det, std::fabs(detLeft) + std::fabs(detRight));
}
int orientBeyondFilter(Point a, Point b, Point c);  // stages 2 and 3, when stage 1 cannot tell
}  // namespace predicates_detail

// Sign of the doubled signed area of triangle (a, b, c):
// +1 when c lies left of the directed line a->b (counter-clockwise turn),
// -1 when it lies right (clockwise), 0 when the three points are collinear.
inline int orient(Point a, Point b, Point c) {
    ++work().orientCalls;
    double det;
    if (int s = predicates_detail::orientFilter(a, b, c, det)) return s;
    return predicates_detail::orientBeyondFilter(a, b, c);
}

// orient()'s first stage alone: the sign when the floating-point filter decides it, 0 when it
// cannot. For tests that only prune (touches.cpp's box test), where a 0 costs a slower path and
// never a wrong answer. Not counted as orient work.
inline int orientFiltered(Point a, Point b, Point c) {
    double det;
    return predicates_detail::orientFilter(a, b, c, det);
}

// below(a, b): a is lower than b. Heights are y; equal heights are ordered by x, as if
// every horizontal line were tilted slightly (the paper's lexicographic tie-break).
inline bool below(Point a, Point b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }

// Heights along a direction d (up.h): heightSign is the sign of d·(b − a) (+1: b is higher),
// acrossSign the sign of d⊥·(b − a) with d⊥ = (d.y, −d.x), d turned clockwise (+x when d is
// +y). Exact for every finite double, by the same three stages as orient().
int heightSign(Up d, Point a, Point b);
inline int acrossSign(Up d, Point a, Point b) { return heightSign(Up{d.y, -d.x}, a, b); }

// below() along d: a is lower than b; equal heights are ordered along d⊥, as if the level
// lines were tilted slightly (for +y this is below()). Along an axis: coordinate compares.
inline bool belowToward(Up d, Point a, Point b) {
    if (d.x == 0 && d.y > 0) return below(a, b);
    if (d.x == 0 && d.y < 0) return a.y > b.y || (a.y == b.y && a.x > b.x);
    if (d.y == 0 && d.x > 0) return a.x < b.x || (a.x == b.x && a.y > b.y);
    if (d.y == 0 && d.x < 0) return a.x > b.x || (a.x == b.x && a.y < b.y);
    if (int h = heightSign(d, a, b)) return h > 0;
    return acrossSign(d, a, b) > 0;
}

// convex(prev, v, next): the corner at v, walking prev -> v -> next with the interior on the
// left, is strictly convex (turns left). Collinear corners count as not convex.
inline bool convex(Point prev, Point v, Point next) { return orient(prev, v, next) > 0; }

// c lies on the segment a-b strictly between its ends (a T-junction). Exact: one orient and
// coordinate comparisons.
inline bool insideSegment(Point a, Point b, Point c) {
    if (c == a || c == b || orient(a, b, c) != 0) return false;
    if (a.x != b.x) return (a.x < c.x && c.x < b.x) || (b.x < c.x && c.x < a.x);
    return (a.y < c.y && c.y < b.y) || (b.y < c.y && c.y < a.y);
}

// inside(s, left, right, nextRight, nextLeft): s lies strictly inside the quadrangle
// Left, Right, NextRight, NextLeft (counter-clockwise in that order), the region of the
// active gorge between the water level and the next water level (§5, Fig. 4).
bool inside(Point s, Point left, Point right, Point nextRight, Point nextLeft);

// Which stage of the exact predicate decided a sign (the predicate inspector shows it).
enum class Stage : uint8_t { Filter, Expansion, Rationals };
const char* stageName(Stage s);  // "filter", "expansion", "rationals"
struct OrientReport {
    int sign = 0;
    double det = 0;               // the filter's floating-point determinant
    Stage stage = Stage::Filter;  // the stage that decided `sign`
};
// orient() with its working shown: the same stages, code and result.
OrientReport orientExplained(Point a, Point b, Point c);
struct InsideReport {
    bool inside = false;
    Stage stage = Stage::Filter;  // the deepest stage any of its orient tests needed
    int orients = 0;              // orient tests it made
};
InsideReport insideExplained(Point s, Point left, Point right, Point nextRight, Point nextLeft);

// Exact signed doubled area accumulator: add triangles or ring edges, compare sums exactly.
class ExactSum {
public:
    void addProduct(double a, double b);          // += a*b, exactly
    void addCross(Point a, Point b);              // += a.x*b.y - a.y*b.x, exactly
    void addTriangle(Point a, Point b, Point c);  // += doubled signed area, exactly
    void add(const ExactSum& other, int sign = 1);
    int sign() const;                              // exact sign of the sum
    double approx() const;                         // nearest double (for messages)
    bool operator==(const ExactSum& other) const;  // exact equality of the two sums
    size_t size() const { return terms_.size(); }  // expansion length (for tests)
private:
    struct Big;               // GMP rational, used once a term leaves the safe range
    void growTerm(double b);  // += b, exactly (expansion only)
    void maybeCompress();
    void toBig();                // moves the expansion into big_
    Big& ownBig();               // big_, unshared (copy-on-write)
    std::vector<double> terms_;  // non-overlapping expansion, increasing magnitude
    std::shared_ptr<Big> big_;   // value = sum(terms_) + *big_ when set
    size_t compressedSize_ = 0;  // length after the last compression
};

}  // namespace flood
