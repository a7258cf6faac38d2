// What the canvas uploads to the GPU, as plain arrays (no GL here, so tests can read them).
// Two parts with different lifetimes:
// - CanvasGeometry, built once per opened trace: every vertex, every triangle in flood order
//   (the triangles cut by step s are the prefix [0, triangleCount)), ring fans for the fill,
//   boundary edges, every bridge in event order (again a prefix per step), vertex classes
//   (its layout, which the renderer reads: canvas_vertices.h).
// - CanvasOverlay, rebuilt only when the step (or a display option) changes: what buildScene
//   draws for that step alone (chain, dormant gorges, jumps, water level, fingers, culprits).
// Positions are world coordinates minus `origin`, in float: the camera is a shader uniform,
// so panning and zooming never re-upload anything.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "canvas_vertices.h"
#include "model.h"
#include "palette.h"
#include "scene.h"

namespace flood::view {

// The world geometry of a run (an outline: no fill, see canvas_geometry.cpp); of the model's.
CanvasGeometry buildCanvasGeometry(const Trace& trace, const std::vector<VertexClass>& classes,
                                   bool outline, bool inputOk);
CanvasGeometry buildCanvasGeometry(const Model& model);

struct CanvasOverlay {
    std::vector<SegmentVertex> lines;   // in buildScene's order
    std::vector<MarkerVertex> markers;  // in buildScene's order
    size_t gorgeMarkers = 0;            // markers [0, gorgeMarkers): pending/held rings (thin)
    std::vector<Scene::Line> arrows;    // jump pointers: heads are drawn in screen space
    std::vector<Scene::Label> labels;   // L, R, NL, NR, pending/held gorges
};
// The per-step part of buildScene(model, options), as GPU vertices relative to `origin`.
CanvasOverlay buildCanvasOverlay(const Model& model, const SceneOptions& options, Point origin);

// At most one marker per `cell`-pixel square of a grid over the camera's viewport, so a dense
// polygon reads as a shape, not a smear: in each cell the first marker in list order wins
// (callers list the important ones first), so the choice depends on the camera alone.
// Markers more than a cell outside the viewport are dropped. Positions are relative to `origin`.
std::vector<MarkerVertex> thinMarkers(const std::vector<MarkerVertex>& markers, Point origin,
                                      const Camera& camera, double cell);

// The rings' edges as GL_LINES indices (as CanvasGeometry::boundaryEdges), decimated to the
// pixel grid of `camera`'s viewport (pixels `pixel` logical pixels wide): each edge is walked
// a pixel at a time, as a 1-pixel line is drawn, and kept only when it inks the pixel of one
// of its ends or at least four pixels no edge before it inked; an edge off the viewport is
// dropped. So every vertex on screen still has its pixel inked, and a million spikes across a
// disc at full zoom-out are a fifth of their lines for a software rasteriser, the picture the
// same but for a pixel in several hundred.
std::vector<uint32_t> pixelBoundary(const Polygon& polygon, const Camera& camera, double pixel);

// Triangles bucketed by the grid cell of their centroid, so labels cost what is on screen,
// not what the polygon holds. Vertices too (buildVertices): a vertex is its own "centroid"
// and its "area" is the squared distance to its nearest neighbour, the room its label has.
class TriangleGrid {
public:
    void build(const Polygon& polygon, const std::vector<Triangle>& triangles);
    void buildVertices(const Polygon& polygon);
    // Calls f(t) for every triangle t < count whose centroid lies in the world box, in cell
    // order; returns false (and calls nothing) if more than `cap` would be called.
    template <class F>
    bool forEach(Point lo, Point hi, uint32_t count, size_t cap, F f) const;
    Point centroid(uint32_t t) const { return centroid_[t]; }
    double area(uint32_t t) const { return area_[t]; }

private:
    void bucket(double perCell);  // counting sort of centroid_ into cells of ~perCell items
    bool cells(Point lo, Point hi, int& i0, int& j0, int& i1, int& j1) const;
    double x0_ = 0, y0_ = 0, cell_ = 1;
    int nx_ = 0, ny_ = 0;
    std::vector<uint32_t> start_, ids_;
    std::vector<Point> centroid_;
    std::vector<float> area_;
};

template <class F>
bool TriangleGrid::forEach(Point lo, Point hi, uint32_t count, size_t cap, F f) const {
    int i0, j0, i1, j1;
    if (!cells(lo, hi, i0, j0, i1, j1)) return true;
    auto cut = [&](int i, int j, const uint32_t*& b) {  // ids < count: a prefix of the cell
        size_t c = size_t(j) * nx_ + i;
        b = ids_.data() + start_[c];
        return size_t(std::lower_bound(b, ids_.data() + start_[c + 1], count) - b);
    };
    size_t total = 0;
    const uint32_t* b = nullptr;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            if ((total += cut(i, j, b)) > cap) return false;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            for (size_t k = 0, n = cut(i, j, b); k < n; ++k) f(b[k]);
    return true;
}

// What the canvas builds of a run before its GL upload, prepared with it (prepared_run.h):
// its geometry (uploaded once, then dropped), the label grids and the vertex markers (classes
// first, then regular) that are thinned per camera.
struct PreparedCanvas {
    CanvasGeometry geometry;
    TriangleGrid grid;        // triangle labels by cell
    TriangleGrid vertexGrid;  // vertex labels by cell
    std::vector<MarkerVertex> vertexMarkers;
};
// Takes the run's geometry (buildCanvasGeometry) and adds its label grids.
std::shared_ptr<PreparedCanvas> prepareCanvas(CanvasGeometry geometry, const Trace& trace);
// The same of what the model shows (a canvas that missed the prepared one).
std::shared_ptr<PreparedCanvas> prepareCanvas(const Model& model);

// The labels to draw: the first `count` items of `grid` in the camera's viewport whose screen
// area is at least `minArea` px²; none when more than a screenful of them (4 per minArea of
// viewport) would be candidates, so a zoomed-out million costs a few hundred cell lookups.
std::vector<uint32_t> visibleLabels(const TriangleGrid& grid, const Camera& camera, uint32_t count,
                                    double minArea);

}  // namespace flood::view
