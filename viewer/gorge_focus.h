// "Current gorge only": the canvas outside the active gorge's outline is dimmed. The outline
// is the polygon the gorge's chain and banks bound: NextLeft, Left, the active chain to
// Right, NextRight, and back across the top (the next triangle is cut inside it).
#pragma once
#include <vector>

#include "model.h"

namespace flood::view {

// World points of the outline; empty when no gorge is active (before the start, after the end).
std::vector<Point> activeGorgeOutline(const Model& model);

// The part of `area` outside the closed polygon `outline` (screen points, even-odd, so a
// self-crossing outline of invalid input still dims something sensible), as rectangles in
// rows `rowHeight` high: each row's spans outside the outline at the row's middle. The work
// is the rows each edge spans: a caller redraws it only when the step or the camera changed.
std::vector<Rect> outsideOf(const std::vector<Vec2>& outline, const Rect& area,
                            double rowHeight = 1);

}  // namespace flood::view
