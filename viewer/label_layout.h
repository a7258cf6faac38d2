// Placing text labels beside points on the canvas so they never overlap each other, never
// cover a labelled point, and never go under what floats over the canvas (the find box, the
// Edit box, the Shrink window, the locator inset). A label that cannot sit beside its point
// moves away along a ring of candidate places and is tied to the point by a leader line.
// Screen pixels; no ImGui, no GL (tests/viewer_diagnosis_test.cpp drives it).
#pragma once
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "geometry.h"

namespace flood::view {

struct LabelRequest {
    Vec2 anchor;          // the point labelled
    double w = 0, h = 0;  // the text's size
    // Where the label would rather go, its top-left corner from the anchor (the fingers'
    // usual sides: NL above left, R below right); tried before the four usual places.
    bool preferred = false;
    Vec2 offset;
};

struct PlacedLabel {
    Rect box;               // where the text goes (its top-left corner and size)
    bool leader = false;    // drawn away from its point: a line from `from` (the point) to `to`
    Vec2 from, to;          // (`to`: the box's edge point nearest the point)
    bool overlaps = false;  // no free place was found: the least crowded one is used
};

// Places each label in order: first where it prefers, if it does, then just right of and
// above its point (and the three other corners), then further out on
// rings of 16 directions, `step` pixels apart, up to `reach` pixels. A place is free when it
// lies inside `area`, `gap` pixels clear of every label placed and every obstacle, and
// covers no anchor.
std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& labels, const Rect& area,
                                     const std::vector<Rect>& obstacles, double gap = 3,
                                     double step = 14, double reach = 260);

// Labels for points of which some coincide: each group of equal points (exact coordinates)
// is one label, its members in the order given. `members[i]` indexes `points`.
struct PointGroup {
    Point at;
    std::vector<size_t> members;
};
std::vector<PointGroup> groupCoincident(const std::vector<Point>& points);

bool overlap(const Rect& a, const Rect& b, double gap = 0);

}  // namespace flood::view
