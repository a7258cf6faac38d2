// Seeded generator of valid polygons for tests, benchmarks and the viewer's open list.
// Every family takes (seed, size), size being roughly the total vertex count, and returns a
// valid flood::Polygon: rings simple, holes inside their outer ring, rings touching only at
// single points (shared vertices or T-junctions, recorded in Polygon::splits). Output is
// identical on every platform (own PRNG and own sin/cos, no std distributions). Where a new
// family goes: a function in generate.cpp (an invalid one in generate_invalid.cpp) and one row
// in its family table.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood {

// Names of all families, in a fixed order.
std::vector<std::string> familyNames();

// One-line description of a family (empty for unknown names).
std::string familyDescription(const std::string& family);

// Generates a polygon of the family; asserts the family name exists (see familyNames()).
Polygon generate(const std::string& family, uint64_t seed, size_t size);

// Exact transforms: rotate by rotation90 quarter turns counter-clockwise, then mirror x -> -x,
// then reverse every ring's orientation, then start every ring `shift` vertices later.
Polygon transform(const Polygon& polygon, int rotation90, bool mirror, bool reverse, size_t shift);

// Invalid families, for measuring what the verification catches (docs/ALGORITHM.md §6): each
// a valid family with one seeded defect — crossing edges, a ring touching itself, a spike, a
// vertex on its own edge, holes crossing, overlapping, nested or outside, collinear overlap,
// parts crossing or nested, touches cutting the interior in two, random lattice rings — that
// validate() refuses. Same (seed, size) contract as generate().
std::vector<std::string> invalidFamilyNames();
std::string invalidFamilyDescription(const std::string& family);
Polygon generateInvalid(const std::string& family, uint64_t seed, size_t size);

}  // namespace flood
