// Vertex classes of §3 (Fig. 1), from each vertex's ring neighbours: the viewer colours them,
// the Fig. 10 state table (state_table.h) indexes its rows by them.
#pragma once
#include <cstdint>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/up.h"

namespace flood {

enum class VertexClass : uint8_t { Regular, Bottom, Sag, Top, Ceiling, Count };
const char* vertexClassName(VertexClass c);  // "regular", "bottom", ...
// Rings are walked with the interior on the left (outer rings counter-clockwise, holes
// clockwise), whatever their orientation in the file. Heights are along `up` (up.h).
std::vector<VertexClass> classifyVertices(const Polygon& polygon, Up up = Up::PlusY);

}  // namespace flood
