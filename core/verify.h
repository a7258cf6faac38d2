// Verification as the paper does it (§6): "we triangulate both the polygon and its
// complement". A valid polygon floods to an exact triangulation, and so does its complement in
// a box around it; an invalid one shows up on one side or the other.
#pragma once
#include <string>

#include "checker.h"
#include "flood.h"

namespace flood {

// The region between a box strictly containing `polygon` and the polygon: the box with every
// outer ring as a hole, plus every hole of the polygon (but point holes) as an island part of
// its own; its T-junctions recorded by validate().
Polygon complementOf(const Polygon& polygon);

struct Verification {
    FloodResult flood, complementFlood;
    CheckResult check, complementCheck;
    bool ok() const {
        return flood.diagnostic.ok() && check.ok && complementFlood.diagnostic.ok() && complementCheck.ok;
    }
    std::string summary() const;  // one line per side: what was checked and the verdict
};

Verification verify(const Polygon& polygon, const Options& options = {});

}  // namespace flood
