// The canvas's camera (world to screen), the window's tiled layout, and framing: the camera
// that shows a vertex, a culprit or a ring (the error view, Find, the invariant lane's Go).
#pragma once
#include <vector>

#include "flood/check/checker.h"
#include "flood/geometry/polygon.h"
#include "geometry.h"  // Vec2, Rect

namespace flood::view {

// The tiled window layout: panels on the left and right, timeline at the bottom, canvas in
// the middle, and under the canvas the findings of a failing face. Shared with the
// screenshot test so it can find a vertex on the PNG.
struct Layout {
    Rect canvas, left, right, bottom;
    Rect findings;  // between the canvas and the timeline; empty (h 0) when nothing failed
};
// `bottomWanted`: what the timeline needed last frame (its toolbar wraps at a large scale or
// on a narrow window); it gets that much, up to half the window, when its share is smaller.
// `findingsWanted`: what the findings panel needs (0: none), taken from the canvas's column,
// at most a third of it.
Layout computeLayout(double width, double height, double uiScale, double bottomWanted = 0,
                     double findingsWanted = 0);

// World (polygon coordinates, y up) to screen (y down): screen = origin + (p - center) * scale.
class Camera {
public:
    void fit(const Polygon& polygon, const Rect& viewport);  // whole polygon, 6% margin
    // The box [x0, x1] x [y0, y1] (world), 6% margin; a box of no size (one point) is
    // shown at the scale of a box `minSide` wide.
    void fitBox(double x0, double y0, double x1, double y1, const Rect& viewport,
                double minSide = 1e-300);
    void centerOn(Point p) { cx_ = p.x, cy_ = p.y; }
    // Centres on `p` at `scale` pixels per world unit (clamped as zoomAt clamps).
    void centerOn(Point p, double scale);
    void setViewport(const Rect& viewport) { viewport_ = viewport; }
    Vec2 toScreen(Point p) const;
    Point toWorld(Vec2 s) const;
    void pan(double dx, double dy);              // by screen pixels
    void zoomAt(Vec2 screen, double factor);     // keeps the world point under `screen`
    double scale() const { return scale_; }      // pixels per world unit
    Point center() const { return {cx_, cy_}; }  // world point at the viewport centre
    const Rect& viewport() const { return viewport_; }

private:
    Rect viewport_;
    double cx_ = 0, cy_ = 0, scale_ = 1;
};

// Framing: what E, a click in the findings panel, Find and the invariant lane's Go show.
// A world box, x0 > x1 when empty.
struct WorldBox {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    void add(Point p);  // non-finite points are left out
    bool empty() const { return !(x0 <= x1 && y0 <= y1); }
    double w() const { return x1 - x0; }
    double h() const { return y1 - y0; }
    Point centre() const { return {(x0 + x1) / 2, (y0 + y1) / 2}; }
    bool contains(Point p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};
// The camera showing the neighbourhood of `target` (world) in `viewport`: the target with a
// quarter of its size as margin on each side, never narrower than `minSide` across (a point,
// a short edge: a side the caller chooses so the nearest neighbours show).
Camera frameNeighbourhood(const WorldBox& target, double minSide, const Rect& viewport);
// The box the error view frames for `culprits`: the culprit edges, vertices, triangles and
// point. `ringsAtFault` (a validation finding): when it blames whole rings only (a hole
// outside its outer ring), its first ring (the one at fault) and the nearest vertex of each
// other ring it names, so the hole shows beside what it is judged against but the whole
// outer ring is not framed; the first ring too when nothing else is blamed. Each culprit
// vertex brings its nearer ring neighbour, so its edges show against the rest. `minSide`:
// what frameNeighbourhood is to keep across (a fiftieth of the face for a lone point, else
// 0). False when nothing finite is blamed.
bool culpritBox(const Polygon& polygon, const std::vector<Triangle>& triangles,
                const Culprits& culprits, bool ringsAtFault, WorldBox& box, double& minSide);
// The camera showing `culprits` in `viewport` (culpritBox, frameNeighbourhood). False when
// nothing finite is blamed: `camera` is left as it was.
bool frameCulprits(const Polygon& polygon, const std::vector<Triangle>& triangles,
                   const Culprits& culprits, bool ringsAtFault, const Rect& viewport,
                   Camera& camera);
// The world box a camera shows.
WorldBox visibleBox(const Camera& camera);

}  // namespace flood::view
