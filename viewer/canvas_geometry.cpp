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
    return buildCanvasGeometry(model.trace(), model.classes(), model.outlineOnly(),
                               model.inputDiagnostic().ok());
}

std::shared_ptr<PreparedCanvas> prepareCanvas(CanvasGeometry g, const Trace& trace) {
    auto c = std::make_shared<PreparedCanvas>();
    c->grid.build(trace.polygon, trace.triangles);
    c->vertexGrid.buildVertices(trace.polygon);
    c->vertexMarkers = std::move(g.classes);
    c->vertexMarkers.insert(c->vertexMarkers.end(), g.regular.begin(), g.regular.end());
    g.regular = {};
    c->geometry = std::move(g);
    return c;
}

std::shared_ptr<PreparedCanvas> prepareCanvas(const Model& model) {
    return prepareCanvas(buildCanvasGeometry(model), model.trace());
}

CanvasGeometry buildCanvasGeometry(const Trace& trace, const std::vector<VertexClass>& classes,
                                   bool outline, bool inputOk) {
    CanvasGeometry g;
    const Polygon& poly = trace.polygon;
    const auto& v = poly.vertices;
    const Index n = Index(v.size());
    auto valid = [&](Index i) { return i < n; };

    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (Point p : v)
        if (std::isfinite(p.x) && std::isfinite(p.y))
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x),
            y1 = std::max(y1, p.y);
    if (!(x0 <= x1)) x0 = y0 = x1 = y1 = 0;
    g.origin = {(x0 + x1) / 2, (y0 + y1) / 2};
    const Point o = g.origin;
    g.bbox[0] = float(x0 - o.x), g.bbox[1] = float(y0 - o.y);
    g.bbox[2] = float(x1 - o.x), g.bbox[3] = float(y1 - o.y);

    g.positions.reserve(2 * size_t(n));
    for (Point p : v)
        g.positions.push_back(float(p.x - o.x)), g.positions.push_back(float(p.y - o.y));

    // Triangles keep their flood-order slot even when broken, so a step's triangles stay a
    // prefix; a broken one becomes degenerate (draws nothing).
    const auto& tris = trace.triangles;
    g.triangles.reserve(3 * tris.size());
    g.edges.reserve(6 * tris.size());
    for (const Triangle& t : tris) {
        bool ok = valid(t[0]) && valid(t[1]) && valid(t[2]);
        for (int k = 0; k < 3; ++k) g.triangles.push_back(ok ? t[k] : 0);
        for (int k = 0; k < 3; ++k)
            g.edges.push_back(ok ? t[k] : 0), g.edges.push_back(ok ? t[(k + 1) % 3] : 0);
    }

    // An outline (its open still flooding) is drawn unfilled: the fans' even-odd fill costs a
    // software rasteriser seconds a frame at 10⁵ vertices (each fan triangle spans the face).
    const bool fill = !outline;
    for (const Ring& r : poly.rings) {
        if (r.first + r.count > n || r.count < 3) continue;
        for (Index i = 1; fill && i + 1 < r.count; ++i)
            g.fans.insert(g.fans.end(), {r.first, r.first + i, r.first + i + 1});
        for (Index i = 0; i < r.count; ++i)
            g.boundaryEdges.insert(g.boundaryEdges.end(),
                                   {r.first + i, r.first + (i + 1) % r.count});
        for (Index i = 0; i < r.count; ++i)
            g.boundary.push_back(segment(v[r.first + i], v[r.first + (i + 1) % r.count], o,
                                         palette::kBoundary, 1.5f));
    }

    // The replay appends (sag, bridgeTo) at each Bridge: step s shows a prefix of this list.
    for (const Event& e : trace.events) {
        if (e.action != Action::Bridge) continue;
        bool ok = valid(e.sag) && valid(e.bridgeTo);
        g.bridges.push_back(ok ? segment(v[e.sag], v[e.bridgeTo], o, palette::kBridge, 2)
                               : segment(o, o, o, palette::kBridge, 0));
    }

    for (Index i = 0; i < n && i < classes.size(); ++i) {
        VertexClass c = classes[i];
        bool regular = c == VertexClass::Regular;
        (regular ? g.regular : g.classes)
            .push_back({g.positions[2 * i], g.positions[2 * i + 1], vertexClassColor(c),
                        regular ? 2.5f : 4.5f, float(Scene::Shape::Disc)});
    }
    g.dryIsUncut = inputOk && trace.diagnostic.ok() && !tris.empty() &&
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
    for (const Scene::Marker& m : sc.markers) {
        ov.markers.push_back(
            {float(m.p.x - o.x), float(m.p.y - o.y), m.color, m.radius, float(m.shape)});
        ov.gorgeMarkers += m.thin;  // buildScene lists the gorge rings first
    }
    ov.labels = std::move(sc.labels);
    return ov;
}

std::vector<MarkerVertex> thinMarkers(const std::vector<MarkerVertex>& markers, Point o,
                                      const Camera& cam, double cell) {
    const Rect& r = cam.viewport();
    const double x0 = r.x - cell, y0 = r.y - cell;
    const int nx = int(std::ceil(r.w / cell)) + 2, ny = int(std::ceil(r.h / cell)) + 2;
    std::vector<uint8_t> taken(size_t(std::max(nx, 0)) * size_t(std::max(ny, 0)), 0);
    std::vector<MarkerVertex> kept;
    // The camera is affine: its map from (origin-relative) world to cell coordinates, once.
    const Vec2 at = cam.toScreen(o), ex = cam.toScreen({o.x + 1, o.y}),
               ey = cam.toScreen({o.x, o.y + 1});
    const double ix = (ex.x - at.x) / cell, jx = (ex.y - at.y) / cell;
    const double iy = (ey.x - at.x) / cell, jy = (ey.y - at.y) / cell;
    const double i0 = (at.x - x0) / cell, j0 = (at.y - y0) / cell;
    for (const MarkerVertex& m : markers) {
        double i = std::floor(i0 + m.x * ix + m.y * iy), j = std::floor(j0 + m.x * jx + m.y * jy);
        if (!(i >= 0 && j >= 0 && i < nx && j < ny)) continue;  // also drops NaN
        size_t c = size_t(j) * size_t(nx) + size_t(i);
        if (taken[c]) continue;
        taken[c] = 1;
        kept.push_back(m);
    }
    return kept;
}

std::vector<uint32_t> pixelBoundary(const Polygon& polygon, const Camera& cam, double pixel) {
    const auto& v = polygon.vertices;
    const Rect& r = cam.viewport();
    const int W = int(std::ceil(r.w / pixel)) + 2, H = int(std::ceil(r.h / pixel)) + 2;
    if (v.empty() || W <= 2 || H <= 2) return {};
    // The camera is affine: its map from world to pixel coordinates (a pixel's margin round
    // the viewport), once.
    const Point o = v.front();
    const Vec2 at = cam.toScreen(o), ex = cam.toScreen({o.x + 1, o.y}),
               ey = cam.toScreen({o.x, o.y + 1});
    const double ix = (ex.x - at.x) / pixel, jx = (ex.y - at.y) / pixel;
    const double iy = (ey.x - at.x) / pixel, jy = (ey.y - at.y) / pixel;
    const double i0 = (at.x - r.x) / pixel + 1, j0 = (at.y - r.y) / pixel + 1;
    auto map = [&](Point p) {
        const double dx = p.x - o.x, dy = p.y - o.y;
        return Vec2{i0 + dx * ix + dy * iy, j0 + dx * jx + dy * jy};
    };
    std::vector<uint8_t> inked(size_t(W) * size_t(H), 0);
    // Walks the part of a-b on the grid a pixel at a time (8-connected, as a 1-pixel line is
    // drawn), inking it; whether it is to be drawn: it inked an end's pixel or at least
    // kFresh pixels no line before it had. (A line of a million spikes across a disc adds a
    // pixel or two to what the lines before it drew: a hundredth of the picture, in all.)
    constexpr int kFresh = 4;
    auto walk = [&](Vec2 a, Vec2 b) {
        // Clipped to the grid (Liang-Barsky): a line off it draws nothing on screen.
        double t0 = 0, t1 = 1;
        const double d[2] = {b.x - a.x, b.y - a.y}, lo[2] = {a.x, a.y};
        const double hi[2] = {double(W), double(H)};
        for (int k = 0; k < 2; ++k) {
            if (!std::isfinite(lo[k]) || !std::isfinite(d[k])) return false;
            if (d[k] == 0) {
                if (lo[k] < 0 || lo[k] >= hi[k]) return false;
                continue;
            }
            double ta = (0 - lo[k]) / d[k], tb = (hi[k] - lo[k]) / d[k];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        }
        if (t0 > t1) return false;
        const double x0 = a.x + d[0] * t0, y0 = a.y + d[1] * t0;
        const double dx = d[0] * (t1 - t0), dy = d[1] * (t1 - t0);
        const int steps = int(std::ceil(std::max(std::abs(dx), std::abs(dy))));
        int fresh = 0;
        bool end = false;
        for (int k = 0; k <= steps; ++k) {
            const double t = steps ? double(k) / steps : 0;
            const int i = std::clamp(int(x0 + dx * t), 0, W - 1);
            const int j = std::clamp(int(y0 + dy * t), 0, H - 1);
            uint8_t& cell = inked[size_t(j) * size_t(W) + size_t(i)];
            fresh += !cell;
            end |= !cell && ((k == 0 && t0 == 0) || (k == steps && t1 == 1));
            cell = 1;
        }
        return end || fresh >= kFresh;
    };
    std::vector<uint32_t> lines;
    for (const Ring& g : polygon.rings) {
        if (g.count < 2 || g.first + g.count > v.size()) continue;
        Vec2 a = map(v[g.first]);
        for (Index k = 0; k < g.count; ++k) {
            const Index i = g.first + k, j = g.first + (k + 1) % g.count;
            const Vec2 b = map(v[j]);
            if (walk(a, b)) lines.insert(lines.end(), {i, j});
            a = b;
        }
    }
    return lines;
}

std::vector<uint32_t> visibleLabels(const TriangleGrid& grid, const Camera& cam, uint32_t count,
                                    double minArea) {
    constexpr double kLabelMargin = 32;  // pixels
    const Rect& r = cam.viewport();
    Point a = cam.toWorld({r.x, r.y + r.h}), b = cam.toWorld({r.x + r.w, r.y});
    size_t cap = size_t(4 * r.w * r.h / minArea) + 16;
    double px2 = cam.scale() * cam.scale();
    std::vector<uint32_t> shown;
    // The grid's cells overhang the view: keep what is on screen, or near enough to show
    // part of its text.
    const Rect near{r.x - kLabelMargin, r.y - kLabelMargin, r.w + 2 * kLabelMargin,
                    r.h + 2 * kLabelMargin};
    grid.forEach(a, b, count, cap, [&](uint32_t t) {
        if (grid.area(t) * px2 >= minArea && near.contains(cam.toScreen(grid.centroid(t))))
            shown.push_back(t);
    });
    return shown;
}

// ----------------------------------------------------------------------------------------
void TriangleGrid::buildVertices(const Polygon& polygon) {
    centroid_ = polygon.vertices;
    area_.assign(centroid_.size(), 0.f);
    bucket(8);  // finer than for triangles: the neighbour search below scans 3x3 cells
    // A vertex's room: the distance to its nearest neighbour, searched in the 3x3 cells around
    // it; anything farther is at least a cell away, so min(found, cell) never overstates it.
    // A crowded block (a cluster far denser than the grid) is given no room rather than a
    // quadratic search: its labels would need an extreme zoom anyway.
    constexpr size_t kMaxScan = 512;
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
            int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, nx_ - 1);
            int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, ny_ - 1);
            size_t block = 0;
            for (int jj = j0; jj <= j1; ++jj)
                block += start_[size_t(jj) * nx_ + i1 + 1] - start_[size_t(jj) * nx_ + i0];
            const size_t c = size_t(j) * nx_ + i;
            for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                const uint32_t a = ids_[k];
                const Point p = centroid_[a];
                double best = cell_ * cell_;
                if (block > kMaxScan) best = 0;
                for (int jj = j0; jj <= j1 && best > 0; ++jj)
                    for (uint32_t q = start_[size_t(jj) * nx_ + i0];
                         q < start_[size_t(jj) * nx_ + i1 + 1]; ++q) {
                        if (ids_[q] == a) continue;
                        Point o = centroid_[ids_[q]];
                        best =
                            std::min(best, (o.x - p.x) * (o.x - p.x) + (o.y - p.y) * (o.y - p.y));
                    }
                area_[a] = float(best);
            }
        }
}

void TriangleGrid::build(const Polygon& polygon, const std::vector<Triangle>& triangles) {
    const auto& v = polygon.vertices;
    const size_t n = triangles.size();
    centroid_.assign(n, Point{0, 0});
    area_.assign(n, 0.f);
    for (size_t t = 0; t < n; ++t) {
        const Triangle& tri = triangles[t];
        if (tri[0] >= v.size() || tri[1] >= v.size() || tri[2] >= v.size()) continue;
        Point a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
        centroid_[t] = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
        area_[t] = float(std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2);
    }
    bucket(32);
}

void TriangleGrid::bucket(double perCell) {
    const size_t n = centroid_.size();
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (Point c : centroid_) {
        if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
        x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y),
        y1 = std::max(y1, c.y);
    }
    if (!(x0 <= x1)) x0 = x1 = y0 = y1 = 0;
    // About perCell items a cell: cheap to count, and a zoomed-in view visits few cells.
    int side = std::clamp(int(std::sqrt(double(n) / perCell)), 1, 512);
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
    i0 = clampCell(std::floor((lo.x - x0_) / cell_), nx_),
    i1 = clampCell(std::floor((hi.x - x0_) / cell_), nx_);
    j0 = clampCell(std::floor((lo.y - y0_) / cell_), ny_),
    j1 = clampCell(std::floor((hi.y - y0_) / cell_), ny_);
    i0 = std::max(i0, 0), j0 = std::max(j0, 0), i1 = std::min(i1, nx_ - 1),
    j1 = std::min(j1, ny_ - 1);
    return i0 <= i1 && j0 <= j1;
}

}  // namespace flood::view
