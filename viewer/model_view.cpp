// The model's view: fitting and framing the camera, the findings' error view, Find, picking.
#include "model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include "flood/check/diagnostic_where.h"
#include "flood/geometry/predicates.h"
#include "flood/io/gdal/read_any.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "view_fit.h"

namespace flood::view {

// A validation finding shows at the first step one of its vertices is a finger.
uint32_t Model::findingStep(const Finding& f) const {
    if (f.step != kNone || f.kind != Verdict::Invalid) return f.step;
    const auto& blamed = f.culprits.vertices;
    if (blamed.empty()) return kNone;
    for (const Event& e : trace_->events)
        for (Index v : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
            if (v != kNone && std::find(blamed.begin(), blamed.end(), v) != blamed.end())
                return e.step + 1;
    return kNone;
}

bool Model::showFinding(size_t i) {
    if (i >= findings_.size()) return false;
    Finding& f = findings_[i];
    Camera framed = camera_;
    if (!frameCulprits(trace_->polygon, trace_->triangles, f.culprits, f.kind == Verdict::Invalid,
                       camera_.viewport(), framed))
        return false;
    camera_ = framed;
    currentFinding_ = i;
    error_ = f.culprits;
    errorView_ = true;
    needsFit_ = false;
    f.step = findingStep(f);
    if (f.step != kNone) seek(f.step);
    return true;
}

bool Model::nextFinding(int direction) {
    const size_t n = findings_.size();
    if (n == 0) return false;
    if (!errorView_ && showFinding(currentFinding_)) return true;
    // A finding with nothing to frame is skipped.
    for (size_t k = 1; k <= n; ++k) {
        size_t i = direction > 0 ? (currentFinding_ + k) % n : (currentFinding_ + n - k % n) % n;
        if (showFinding(i)) return true;
    }
    return false;
}

bool Model::frameVertices(const std::vector<Index>& vertices) {
    const Polygon& P = trace_->polygon;
    Culprits c;
    for (Index v : vertices)
        if (v < P.vertices.size()) c.vertices.push_back(v);
    if (c.vertices.empty()) return false;
    WorldBox box;
    double minSide = 0;
    if (!culpritBox(P, trace_->triangles, c, false, box, minSide)) return false;
    if (c.vertices.size() == 1) {
        // One vertex stays at the centre: its nearer neighbour's distance on every side.
        const Point v = P.vertices[c.vertices[0]];
        const double r = std::max({v.x - box.x0, box.x1 - v.x, v.y - box.y0, box.y1 - v.y});
        box = {};
        box.add({v.x - r, v.y - r}), box.add({v.x + r, v.y + r});
    }
    camera_ = frameNeighbourhood(box, minSide, camera_.viewport());
    needsFit_ = false;
    return true;
}

void Model::goToViolation(const Violation& v) {
    seek(v.step);
    frameVertices(v.vertices);
}

FindTarget Model::find(const std::string& query) {
    FindTarget f = findTarget(*trace_, query);
    if (!f.ok) return f;
    if (f.seekTo != kNone) seek(f.seekTo);
    if (!f.hasCenter) return f;
    // Framed, never only centred: a vertex with its nearest neighbours, a step's fingers, a
    // triangle or a ring whole with a margin.
    if (!f.vertices.empty() && frameVertices(f.vertices)) return f;
    WorldBox box;
    box.add({f.x0, f.y0}), box.add({f.x1, f.y1});
    if (f.kind == 'r' && (f.x1 > f.x0 || f.y1 > f.y0))
        camera_.fitBox(f.x0, f.y0, f.x1, f.y1, camera_.viewport());
    else if (!box.empty() && (box.w() > 0 || box.h() > 0))
        camera_ = frameNeighbourhood(box, 0, camera_.viewport());
    else camera_.centerOn(f.center);
    needsFit_ = false;
    return f;
}

void Model::fitCamera(const Rect& viewport, const std::vector<Rect>& overlays) {
    WorldBox box;
    for (Point p : trace_->polygon.vertices) box.add(p);
    camera_ = view::fitCamera(box, viewport, overlays);
    fitted_ = camera_;
    needsFit_ = false;
    errorView_ = false;
}

bool Model::viewIsFit() const {
    if (needsFit_) return true;
    const Camera& c = camera_;
    return !errorView_ && c.scale() == fitted_.scale() && c.center().x == fitted_.center().x &&
           c.center().y == fitted_.center().y;
}

Index Model::pickVertex(Vec2 screen, double radiusPx) const {
    Index best = kNone;
    double bestD = radiusPx * radiusPx;
    const auto& v = trace_->polygon.vertices;
    for (Index i = 0; i < v.size(); ++i) {
        Vec2 s = camera_.toScreen(v[i]);
        double d = (s.x - screen.x) * (s.x - screen.x) + (s.y - screen.y) * (s.y - screen.y);
        if (d <= bestD) bestD = d, best = i;
    }
    return best;
}

int64_t Model::pickTriangle(Vec2 screen) const {
    Point p = camera_.toWorld(screen);
    const auto& v = trace_->polygon.vertices;
    uint32_t n = std::min<uint32_t>(state().triangleCount, uint32_t(trace_->triangles.size()));
    // Display-only hit test: plain doubles are fine here, exactness lives in the core.
    auto side = [](Point a, Point b, Point c) {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    };
    for (uint32_t t = 0; t < n; ++t) {
        const Triangle& tri = trace_->triangles[t];
        if (tri[0] >= v.size() || tri[1] >= v.size() || tri[2] >= v.size()) continue;
        double a = side(v[tri[0]], v[tri[1]], p), b = side(v[tri[1]], v[tri[2]], p),
               c = side(v[tri[2]], v[tri[0]], p);
        if ((a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0)) return t;
    }
    return -1;
}

}  // namespace flood::view
