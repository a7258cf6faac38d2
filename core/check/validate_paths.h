// validate() takes shortcuts: on small polygons a test of every pair of edges instead of
// the sweep (core/check/validate.cpp), on a MultiPolygon a sweep of each group of parts apart
// (validate_groups.cpp). The whole sweep alone, for tests that hold them to one verdict and one
// message. Internal to core/, not a public API.
#pragma once
#include <string>
#include <vector>

#include "flood/io/io.h"

namespace flood {

// validate() without its shortcuts: every polygon sweeps whole, its parts at once (and on a
// valid polygon `enclosing` as validateNesting() below gives it).
Diagnostic validateBySweep(Polygon& polygon, const std::string& name,
                           std::vector<Index>* enclosing = nullptr);

// validate(), and on a valid polygon the innermost ring whose interior holds each ring (kNone:
// none), as its sweep finds it for check 6 in O(n log n): an island's outer ring lies in its
// lake, a hole of another part. Left empty when the polygon is invalid. verify.cpp nests the
// complement's parts with it.
Diagnostic validateNesting(Polygon& polygon, const std::string& name,
                           std::vector<Index>& enclosing);

}  // namespace flood
