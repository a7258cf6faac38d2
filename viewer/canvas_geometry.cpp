#include "canvas_geometry.h"

#include <algorithm>
#include <cmath>

namespace flood::view {

namespace {

SegmentVertex segment(Point a, Point b, Point o, Rgba c, float width) {
    return {float(a.x - o.x), float(a.y - o.y), float(b.x - o.x), float(b.y - o.y), c, width};
}

}  // namespace

CanvasGeometry buildCanvasGeometry(const Model& model) {
    CanvasGeometry g;
    const Polygon& poly = model.polygon();
    const auto& v = poly.vertices;
    const Index n = Index(v.size());
    auto valid = [&](Index i) { return i < n; };

    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (Point p : v)
        if (std::isfinite(p.x) && std::isfinite(p.y))
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    if (!(x0 <= x1)) x0 = y0 = x1 = y1 = 0;
    g.origin = {(x0 + x1) / 2, (y0 + y1) / 2};
    const Point o = g.origin;
    g.bbox[0] = float(x0 - o.x), g.bbox[1] = float(y0 - o.y);
    g.bbox[2] = float(x1 - o.x), g.bbox[3] = float(y1 - o.y);

    g.positions.reserve(2 * size_t(n));
    for (Point p : v) g.positions.push_back(float(p.x - o.x)), g.positions.push_back(float(p.y - o.y));

    // Triangles keep their flood-order slot even when broken, so a step's triangles stay a
    // prefix; a broken one becomes degenerate (draws nothing).
    const auto& tris = model.trace().triangles;
    g.triangles.reserve(3 * tris.size());
    g.edges.reserve(6 * tris.size());
    for (const Triangle& t : tris) {
        bool ok = valid(t[0]) && valid(t[1]) && valid(t[2]);
        for (int k = 0; k < 3; ++k) g.triangles.push_back(ok ? t[k] : 0);
        for (int k = 0; k < 3; ++k)
            g.edges.push_back(ok ? t[k] : 0), g.edges.push_back(ok ? t[(k + 1) % 3] : 0);
    }

    for (const Ring& r : poly.rings) {
        if (r.first + r.count > n || r.count < 3) continue;
        for (Index i = 1; i + 1 < r.count; ++i)
            g.fans.insert(g.fans.end(), {r.first, r.first + i, r.first + i + 1});
        for (Index i = 0; i < r.count; ++i)
            g.boundaryEdges.insert(g.boundaryEdges.end(), {r.first + i, r.first + (i + 1) % r.count});
        for (Index i = 0; i < r.count; ++i)
            g.boundary.push_back(segment(v[r.first + i], v[r.first + (i + 1) % r.count], o,
                                         palette::kBoundary, 1.5f));
    }

    // The replay appends (sag, bridgeTo) at each Bridge: step s shows a prefix of this list.
    for (const Event& e : model.trace().events) {
        if (e.action != Action::Bridge) continue;
        bool ok = valid(e.sag) && valid(e.bridgeTo);
        g.bridges.push_back(ok ? segment(v[e.sag], v[e.bridgeTo], o, palette::kBridge, 2)
                               : segment(o, o, o, palette::kBridge, 0));
    }

    const auto& classes = model.classes();
    for (Index i = 0; i < n && i < classes.size(); ++i) {
        VertexClass c = classes[i];
        bool regular = c == VertexClass::Regular;
        (regular ? g.regular : g.classes)
            .push_back({g.positions[2 * i], g.positions[2 * i + 1], vertexClassColor(c),
                        regular ? 2.5f : 4.5f, float(Scene::Shape::Disc)});
    }
    const Trace& trace = model.trace();
    g.dryIsUncut = model.inputDiagnostic().ok() && trace.diagnostic.ok() && !tris.empty() &&
                   tris.size() == poly.expectedTriangles();
    return g;
}

CanvasOverlay buildCanvasOverlay(const Model& model, const SceneOptions& options, Point o) {
    SceneOptions only = options;
    only.perStepOnly = true;
    Scene sc = buildScene(model, only);
    CanvasOverlay ov;
    ov.lines.reserve(sc.lines.size());
    for (const Scene::Line& l : sc.lines) {
        ov.lines.push_back(segment(l.a, l.b, o, l.color, l.width));
        if (l.arrow) ov.arrows.push_back(l);
    }
    ov.markers.reserve(sc.markers.size());
    for (const Scene::Marker& m : sc.markers)
        ov.markers.push_back({float(m.p.x - o.x), float(m.p.y - o.y), m.color, m.radius, float(m.shape)});
    ov.labels = std::move(sc.labels);
    return ov;
}

// ----------------------------------------------------------------------------------------
void TriangleGrid::build(const Polygon& polygon, const std::vector<Triangle>& triangles) {
    const auto& v = polygon.vertices;
    const size_t n = triangles.size();
    centroid_.assign(n, Point{0, 0});
    area_.assign(n, 0.f);
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (size_t t = 0; t < n; ++t) {
        const Triangle& tri = triangles[t];
        if (tri[0] >= v.size() || tri[1] >= v.size() || tri[2] >= v.size()) continue;
        Point a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
        centroid_[t] = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
        area_[t] = float(std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2);
        if (!std::isfinite(centroid_[t].x) || !std::isfinite(centroid_[t].y)) continue;
        x0 = std::min(x0, centroid_[t].x), x1 = std::max(x1, centroid_[t].x);
        y0 = std::min(y0, centroid_[t].y), y1 = std::max(y1, centroid_[t].y);
    }
    if (!(x0 <= x1)) x0 = x1 = y0 = y1 = 0;
    // About 32 triangles a cell: cheap to count, and a zoomed-in view visits few cells.
    int side = std::clamp(int(std::sqrt(double(n) / 32)), 1, 512);
    x0_ = x0, y0_ = y0;
    cell_ = std::max({(x1 - x0) / side, (y1 - y0) / side, 1e-300});
    nx_ = std::max(1, int(std::ceil((x1 - x0) / cell_)));
    ny_ = std::max(1, int(std::ceil((y1 - y0) / cell_)));
    auto cellOf = [&](Point p) {
        int i = std::clamp(int((p.x - x0_) / cell_), 0, nx_ - 1);
        int j = std::clamp(int((p.y - y0_) / cell_), 0, ny_ - 1);
        return size_t(j) * nx_ + i;
    };
    // Counting sort by cell; within a cell ids stay increasing (flood order).
    start_.assign(size_t(nx_) * ny_ + 1, 0);
    for (size_t t = 0; t < n; ++t) ++start_[cellOf(centroid_[t]) + 1];
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    ids_.resize(n);
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (size_t t = 0; t < n; ++t) ids_[fill[cellOf(centroid_[t])]++] = uint32_t(t);
}

bool TriangleGrid::cells(Point lo, Point hi, int& i0, int& j0, int& i1, int& j1) const {
    if (ids_.empty()) return false;
    auto clampCell = [](double x, int n) { return int(std::clamp(x, -1.0, double(n))); };
    i0 = clampCell(std::floor((lo.x - x0_) / cell_), nx_), i1 = clampCell(std::floor((hi.x - x0_) / cell_), nx_);
    j0 = clampCell(std::floor((lo.y - y0_) / cell_), ny_), j1 = clampCell(std::floor((hi.y - y0_) / cell_), ny_);
    i0 = std::max(i0, 0), j0 = std::max(j0, 0), i1 = std::min(i1, nx_ - 1), j1 = std::min(j1, ny_ - 1);
    return i0 <= i1 && j0 <= j1;
}

}  // namespace flood::view
