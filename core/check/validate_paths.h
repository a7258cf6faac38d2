// validate() takes a shortcut on small single rings (a test of every pair of edges instead of
// the sweep, core/check/validate.cpp): the sweep alone, for tests that hold the two to one verdict
// and one message. Internal to core/, not a public API.
#pragma once
#include <string>

#include "io/io.h"

namespace flood {

// validate() without the shortcut: every polygon sweeps.
Diagnostic validateBySweep(Polygon& polygon, const std::string& name);

}  // namespace flood
