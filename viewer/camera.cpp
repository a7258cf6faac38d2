#include "camera.h"

#include <algorithm>
#include <cmath>

#include "flood/check/diagnostic_where.h"

namespace flood::view {

// [SECTION] layout and camera
Layout computeLayout(double width, double height, double uiScale, double bottomWanted,
                     double findingsWanted) {
    // Side columns shrink on small windows so the canvas keeps at least half the width.
    double side = std::min(300.0 * uiScale, width * 0.25);
    double bottom = std::min(128.0 * uiScale, height * 0.3);
    if (bottomWanted > bottom) bottom = std::min(bottomWanted, height * 0.5);
    Layout l;
    l.left = {0, 0, side, height - bottom};
    l.right = {width - side, 0, side, height - bottom};
    l.bottom = {0, height - bottom, width, bottom};
    const double column = std::max(1.0, height - bottom);
    const double findings = findingsWanted > 0 ? std::min(findingsWanted, column / 3) : 0;
    l.canvas = {side, 0, std::max(1.0, width - 2 * side), std::max(1.0, column - findings)};
    if (findings > 0) l.findings = {side, l.canvas.h, l.canvas.w, findings};
    return l;
}

void Camera::fit(const Polygon& polygon, const Rect& viewport) {
    viewport_ = viewport;
    if (polygon.vertices.empty()) {
        cx_ = cy_ = 0;
        scale_ = 1;
        return;
    }
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (Point p : polygon.vertices) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    if (!(x0 <= x1)) x0 = x1 = y0 = y1 = 0;
    fitBox(x0, y0, x1, y1, viewport);
}

void Camera::fitBox(double x0, double y0, double x1, double y1, const Rect& viewport,
                    double minSide) {
    viewport_ = viewport;
    cx_ = (x0 + x1) / 2;
    cy_ = (y0 + y1) / 2;
    double w = std::max(x1 - x0, minSide), h = std::max(y1 - y0, minSide);
    const double usable = 0.88;  // 6% margin on each side
    scale_ = std::min(viewport.w * usable / w, viewport.h * usable / h);
    if (!std::isfinite(scale_) || scale_ <= 0) scale_ = 1;
}

void Camera::centerOn(Point p, double scale) {
    cx_ = p.x, cy_ = p.y;
    scale_ = std::clamp(scale, 1e-12, 1e15);
}

Vec2 Camera::toScreen(Point p) const {
    return {viewport_.x + viewport_.w / 2 + (p.x - cx_) * scale_,
            viewport_.y + viewport_.h / 2 - (p.y - cy_) * scale_};
}

Point Camera::toWorld(Vec2 s) const {
    return {cx_ + (s.x - viewport_.x - viewport_.w / 2) / scale_,
            cy_ - (s.y - viewport_.y - viewport_.h / 2) / scale_};
}

void Camera::pan(double dx, double dy) {
    cx_ -= dx / scale_;
    cy_ += dy / scale_;
}

void Camera::zoomAt(Vec2 screen, double factor) {
    Point before = toWorld(screen);
    scale_ = std::clamp(scale_ * factor, 1e-12, 1e15);
    Point after = toWorld(screen);
    cx_ += before.x - after.x;
    cy_ += before.y - after.y;
}

// ========================================================================================
// [SECTION] framing
void WorldBox::add(Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
}

WorldBox visibleBox(const Camera& camera) {
    const Rect& r = camera.viewport();
    WorldBox b;
    b.add(camera.toWorld({r.x, r.y}));
    b.add(camera.toWorld({r.x + r.w, r.y + r.h}));
    return b;
}

Camera frameNeighbourhood(const WorldBox& target, double minSide, const Rect& viewport) {
    Camera c;
    c.setViewport(viewport);
    if (target.empty()) return c;
    if (!std::isfinite(minSide) || minSide < 0) minSide = 0;
    const Point m = target.centre();
    const double w = std::max(target.w(), minSide) * 1.5, h = std::max(target.h(), minSide) * 1.5;
    // A box of no size at all (one point, nothing beside it): fitBox's fallback scale.
    c.fitBox(m.x - w / 2, m.y - h / 2, m.x + w / 2, m.y + h / 2, viewport);
    return c;
}

bool culpritBox(const Polygon& P, const std::vector<Triangle>& triangles, const Culprits& c,
                bool ringsAtFault, WorldBox& box, double& minSide) {
    const auto& V = P.vertices;
    box = {};
    minSide = 0;
    auto next = [&](Index v) {
        const Ring& r = P.rings[P.ringOf(v)];
        return v + 1 == r.first + r.count ? r.first : v + 1;
    };
    auto prev = [&](Index v) {
        const Ring& r = P.rings[P.ringOf(v)];
        return v == r.first ? r.first + r.count - 1 : v - 1;
    };
    // A culprit vertex and its nearer ring neighbour (not at its point): the neighbourhood
    // that tells its edges from the rest.
    std::vector<Point> neighbours;
    auto vertex = [&](Index v) {
        if (v >= V.size()) return;
        box.add(V[v]);
        double nearest = std::numeric_limits<double>::infinity();
        Point at;
        for (Index u : {prev(v), next(v)}) {
            double d = std::hypot(V[u].x - V[v].x, V[u].y - V[v].y);
            if (d > 0 && d < nearest) nearest = d, at = V[u];
        }
        if (std::isfinite(nearest)) neighbours.push_back(at);
    };
    size_t budget = 256;  // a finding names a few; the error view of a huge ring stays cheap
    for (Index e : c.edges)
        if (e < V.size() && budget) --budget, vertex(e), vertex(next(e));
    for (Index v : c.vertices)
        if (budget) --budget, vertex(v);
    for (uint32_t t : c.triangles)
        if (t < triangles.size() && budget) {
            --budget;
            for (Index v : triangles[t]) vertex(v);
        }
    for (Point q : neighbours) box.add(q);
    Point p;
    if (diagnosticPoint(P, c, p)) box.add(p);
    // Whole rings blamed, nothing finer (a hole outside its outer ring, holes inside each
    // other, a ring of zero area): the ring at fault is the first; the others are context,
    // of which the nearest point is enough.
    const bool ringLevel =
        (ringsAtFault && c.edges.empty() && c.triangles.empty() && !c.hasPoint) || box.empty();
    if (ringLevel && !c.rings.empty() && c.rings[0] < P.rings.size()) {
        const Ring& g = P.rings[c.rings[0]];
        for (Index i = 0; i < g.count; ++i) box.add(V[g.first + i]);
        if (!box.empty()) {
            const Point m = box.centre();
            const double reach = 8 * std::max(box.w(), box.h());
            // The nearest point of each other ring's edges, when it is near enough that the
            // ring at fault stays large in the view.
            for (size_t k = 1; k < c.rings.size() && k < 4; ++k) {
                if (c.rings[k] >= P.rings.size()) continue;
                const Ring& o = P.rings[c.rings[k]];
                double best = std::numeric_limits<double>::infinity();
                Point nearest;
                for (Index i = 0; i < o.count; ++i) {
                    const Point a = V[o.first + i], b = V[o.first + (i + 1) % o.count];
                    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
                    double t = len2 > 0 ? ((m.x - a.x) * dx + (m.y - a.y) * dy) / len2 : 0;
                    t = std::clamp(t, 0.0, 1.0);
                    const Point q{a.x + t * dx, a.y + t * dy};
                    const double d = std::hypot(q.x - m.x, q.y - m.y);
                    if (d < best) best = d, nearest = q;
                }
                if (best <= reach) box.add(nearest);
            }
        }
    }
    if (box.empty()) return false;
    // One point and nothing beside it: a fiftieth of the face around it.
    minSide = 0;
    if (box.w() == 0 && box.h() == 0) {
        WorldBox face;
        for (size_t i = 0; i < V.size(); i += 1 + V.size() / 100000) face.add(V[i]);
        minSide = 0.02 * std::max(face.w(), face.h());
    }
    return true;
}

bool frameCulprits(const Polygon& P, const std::vector<Triangle>& triangles, const Culprits& c,
                   bool ringsAtFault, const Rect& viewport, Camera& camera) {
    WorldBox box;
    double minSide = 0;
    if (!culpritBox(P, triangles, c, ringsAtFault, box, minSide)) return false;
    camera = frameNeighbourhood(box, minSide, viewport);
    return true;
}

}  // namespace flood::view
