// An event in one line, for lists and tooltips: "Bridge sag 12 to 7, gorge 3 pending;
// triangles 8-9". Terser than narration (flood/teach/narrate.h), which says why in sentences.
#pragma once
#include <string>

#include "flood/geometry/polygon.h"
#include "flood/machine/events.h"

namespace flood {

// The action, the vertices it moved (by index, "-" for none) and the triangles it cut; a
// Forbidden event is described by describeForbidden(), which names its vertices in `polygon`.
std::string describeEvent(const Polygon& polygon, const Event& e);

}  // namespace flood
