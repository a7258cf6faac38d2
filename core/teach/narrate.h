// Narration: one sentence per event in the flood metaphor of the paper (§3–§6), saying what
// happened and why, built from the event's decision bits (Event::tested/passed), fingers,
// triangle range and sag/top/jump fields. Shown by the viewer's Decision panel and by
// `flood transcript --narrate`; docs/TUTORIAL.md quotes it. A forbidden state's diagnostic
// (describeForbidden, forbiddenCulprits: declared in flood.h) is the machine's own, made in
// machine/forbidden.cpp.
#pragma once
#include <string>

#include "geometry/polygon.h"
#include "machine/events.h"

namespace flood {

// "NextLeft (vertex 7) is lower than NextRight (vertex 9) and no sag lies between the water
// and NextLeft: the water rises on the left bank to vertex 7, cutting triangles 8-12."
// Plain ASCII (the viewer's default font has no dashes). `polygon` names the rings of
// vertices (holes are called so); events from another polygon still narrate, by index.
std::string narrate(const Polygon& polygon, const Event& e);

}  // namespace flood
