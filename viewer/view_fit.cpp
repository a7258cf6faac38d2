#include "view_fit.h"

#include <algorithm>
#include <cmath>

namespace flood::view {

namespace {

bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

// The scale at which a box of `aspect` fills `r` (its larger side, for aspect 0: the area).
double fill(const Rect& r, double aspect) {
    if (r.w <= 0 || r.h <= 0) return 0;
    if (!(aspect > 0) || !std::isfinite(aspect)) return r.w * r.h;
    return std::min(r.w / aspect, r.h);  // the box's height at the largest size that fits
}

}  // namespace

Rect freeArea(const Rect& canvas, const std::vector<Rect>& overlays, double aspect) {
    std::vector<Rect> over;
    for (const Rect& o : overlays)
        if (o.w > 0 && o.h > 0 && overlaps(o, canvas)) over.push_back(o);
    if (over.empty()) return canvas;
    // A largest free rectangle has each side on the canvas's edge or an overlay's: try them all
    // (a handful of overlays: a few thousand candidates).
    std::vector<double> xs0{canvas.x}, xs1{canvas.x + canvas.w}, ys0{canvas.y},
        ys1{canvas.y + canvas.h};
    for (const Rect& o : over) {
        xs0.push_back(o.x + o.w), xs1.push_back(o.x);
        ys0.push_back(o.y + o.h), ys1.push_back(o.y);
    }
    Rect best{};
    double bestFill = 0;
    for (double x0 : xs0)
        for (double x1 : xs1)
            for (double y0 : ys0)
                for (double y1 : ys1) {
                    const Rect r{std::max(x0, canvas.x), std::max(y0, canvas.y),
                                 std::min(x1, canvas.x + canvas.w) - std::max(x0, canvas.x),
                                 std::min(y1, canvas.y + canvas.h) - std::max(y0, canvas.y)};
                    if (r.w <= 0 || r.h <= 0) continue;
                    const double f = fill(r, aspect);
                    if (f <= bestFill) continue;
                    if (std::any_of(over.begin(), over.end(),
                                    [&](const Rect& o) { return overlaps(o, r); }))
                        continue;
                    best = r, bestFill = f;
                }
    return best;
}

Camera fitCamera(const WorldBox& bounds, const Rect& canvas, const std::vector<Rect>& overlays) {
    Camera c;
    c.setViewport(canvas);
    if (bounds.empty()) return c;  // nothing to show: the origin at scale 1
    const double w = bounds.w(), h = bounds.h();
    const double aspect = w > 0 && h > 0 ? w / h : 0;
    Rect area = freeArea(canvas, overlays, aspect);
    if (area.w <= 0 || area.h <= 0) area = canvas;
    // Fitted to the free area, then the free area's centre moved onto the polygon's: the
    // viewport stays the canvas so the renderer, picking and labels see one rectangle.
    c.fitBox(bounds.x0, bounds.y0, bounds.x1, bounds.y1, area);
    const double s = c.scale();
    const Point centre = bounds.centre();
    const double dx = area.x + area.w / 2 - (canvas.x + canvas.w / 2);
    const double dy = area.y + area.h / 2 - (canvas.y + canvas.h / 2);
    c.setViewport(canvas);
    c.centerOn({centre.x - dx / s, centre.y + dy / s});
    return c;
}

bool sameRects(const std::vector<Rect>& a, const std::vector<Rect>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::abs(a[i].x - b[i].x) > 0.5 || std::abs(a[i].y - b[i].y) > 0.5 ||
            std::abs(a[i].w - b[i].w) > 0.5 || std::abs(a[i].h - b[i].h) > 0.5)
            return false;
    return true;
}

}  // namespace flood::view
