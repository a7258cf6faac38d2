// Fit into the free part of the canvas: the windows that float over the canvas (the find box,
// the Edit box, the direction dial, the State table, ...) cover part of it, and a fit that
// ignores them puts the polygon's top vertices and the fingers' letters under them. Pure
// geometry, no ImGui: tests/viewer/camera_fit_test.cpp drives it.
#pragma once
#include <vector>

#include "model.h"

namespace flood::view {

// The rectangle inside `canvas` that no overlay touches and in which a box of aspect
// `aspect` (width / height; 0: any) shows largest: the candidates are bounded by the canvas's
// and the overlays' edges (an overlay outside the canvas changes nothing). The canvas itself
// when nothing floats over it; an empty rectangle when the overlays cover it all.
Rect freeArea(const Rect& canvas, const std::vector<Rect>& overlays, double aspect);

// The camera showing `bounds` (world) whole in the free area of `canvas` (freeArea), 6% margin
// there, with the canvas as its viewport (screen coordinates stay the canvas's). When the
// overlays leave no room, the whole canvas.
Camera fitCamera(const WorldBox& bounds, const Rect& canvas, const std::vector<Rect>& overlays);

// The same rectangles, in the same order, within 0.5 px: whether a layout changed.
bool sameRects(const std::vector<Rect>& a, const std::vector<Rect>& b);

}  // namespace flood::view
