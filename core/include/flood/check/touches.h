// T-junctions found without validating: for the unvalidated path (--no-validate, the
// complement of `flood verify`), which must not depend on validate() to learn where rings
// touch inside an edge (Polygon::splits), and must stay safe on invalid input.
#pragma once
#include <cstdint>

#include "flood/geometry/polygon.h"

namespace flood {

struct TouchSearch {
    bool complete = true;  // false: the work cap was hit and polygon.splits was left empty
    uint64_t steps = 0;    // cells walked plus point-edge tests (also in work().touchSteps)
};

// Replaces polygon.splits with every vertex lying strictly inside an edge of another ring of
// its part (exact: insideSegment()), one per point and edge, the lowest vertex index at that
// point, sorted by edge and then along the edge: what validate() records for a valid polygon.
// Parts with a non-finite coordinate are skipped (the machine refuses them). Never relies on
// the input being valid: candidates come from a grid whose lines are input coordinates, so
// every cell test is an exact orient() against a corner and no ordering can become
// inconsistent on crossing edges. Work is capped at `maxSteps` (0: a default linear in n,
// see touches.cpp).
TouchSearch findTouches(Polygon& polygon, uint64_t maxSteps = 0);

}  // namespace flood
