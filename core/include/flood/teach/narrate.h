// Narration: one sentence per event in the flood metaphor of the paper (§3–§6), saying what
// happened and why, built from the event's decision bits (Event::tested/passed), fingers,
// triangle range and sag/top/jump fields. Shown by the viewer's Decision panel and caption
// and by `flood transcript --narrate`; docs/TUTORIAL.md quotes it. With the sentence come the
// vertices and triangles it names, as data, so the viewer's canvas labels exactly those.
// A forbidden state's diagnostic (describeForbidden, forbiddenCulprits: declared in flood.h)
// is the machine's own, made in machine/forbidden.cpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/machine/events.h"

namespace flood {

// A vertex the sentence names and the role it gives it: {35, "sag"}, {14, "NextRight
// before"}. A finger is named as it was before the step ("before"); Left and Right after
// it. Roles are short, in the paper's words, for a label beside the vertex.
struct NamedVertex {
    Index vertex = kNone;
    const char* role = "";
};

struct Narration {
    // "NextLeft (vertex 7) is lower than NextRight (vertex 9) and no sag lies between the
    // water and NextLeft: the water rises on the left bank to vertex 7, cutting triangles
    // 8-12." Plain ASCII (the viewer's default font has no dashes).
    std::string text;
    std::vector<NamedVertex> vertices;              // every "vertex N" of the text, in its order
    uint32_t firstTriangle = 0, triangleCount = 0;  // "triangles 8-12": 8, 5; none: count 0
};

// `polygon` names the rings of vertices (holes are called so); events from another polygon
// still narrate, by index.
Narration narration(const Polygon& polygon, const Event& e);
std::string narrate(const Polygon& polygon, const Event& e);  // narration(...).text

}  // namespace flood
