// Verification as the paper does it (§6): "we triangulate both the polygon and its
// complement". A valid polygon floods to an exact triangulation, and so does its complement in
// a box around it; an invalid one shows up on one side or the other — the paper's open
// conjecture, measured in docs/ALGORITHM.md §6 (scripts/conjecture.sh).
#pragma once
#include <string>
#include <vector>

#include "flood/check/checker.h"
#include "flood/machine/flood.h"

namespace flood {

// The region between a box strictly containing `polygon` and the polygon: one part per face.
// The box, its holes the outer rings of the parts that lie in no hole; and each hole of the
// polygon (but point holes: they bound no area) as a part, its holes the outer rings of the
// parts lying in that hole and in no hole nested inside it (an island in a lake), as
// innermostHoles() below nests them. The box's sides are multiples of a power of two about
// the polygon's extent (clamped at +-DBL_MAX, never overflowing), exact and strictly outside;
// when a coordinate is +-DBL_MAX itself no double lies beyond it, so the complement is built
// from the polygon halved (exact unless that loses a subnormal's last bit; then the box
// touches it there).
// Its T-junctions are found by findTouches(), valid input or not.
Polygon complementOf(const Polygon& polygon);

// The nesting complementOf() uses: the innermost hole of another part that each part of
// `polygon` lies in (kNone: none). On a valid polygon, as validation's sweep finds it
// (O(n log n)); otherwise, or with `pointLocation`, by exact point location of each part in
// the holes whose boxes hold its box (quadratic on deep nesting; tests compare the two).
std::vector<Index> innermostHoles(const Polygon& polygon, bool pointLocation = false);

// Which check of the verification caught an input (the first, in this order).
enum class Caught : uint8_t {
    Nothing,     // both sides flooded to exact triangulations
    Polygon,     // the polygon's flood stopped in a forbidden state
    Complement,  // only the complement's flood stopped in a forbidden state
    Checker      // both floods finished; the exact checker rejects one side's triangles
};
const char* caughtName(Caught c);

struct Verification {
    FloodResult flood, complementFlood;
    CheckResult check, complementCheck;
    bool ok() const {
        return flood.diagnostic.ok() && check.ok && complementFlood.diagnostic.ok() &&
               complementCheck.ok;
    }
    Caught caught() const;
    std::string summary() const;  // one line per side: what was checked and the verdict
};

// Floods and checks `polygon` (its splits as given: from validate(), or from findTouches() on
// the unvalidated path) and its complement.
Verification verify(const Polygon& polygon, const Options& options = {});

}  // namespace flood
