// The viewer's model without a window: declutter at scale, marker thinning and label culling,
// bridges and the gorge focus.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include <set>

#include "viewer_model_support.h"  // the model, the tests' helpers

// [SECTION] declutter at scale: marker thinning and label culling, without a window
namespace {

// A dense face and a camera fitted on an 800x600 canvas.
struct DenseFace {
    Model m;
    CanvasGeometry g;
    std::vector<MarkerVertex> markers;  // classes first, as the canvas thins them
    Camera fit;
    const Rect view{0, 0, 800, 600};
    explicit DenseFace(size_t n) {
        m.openPolygon(generate("circle-jagged", 1, n), "circle-jagged", {});
        g = buildCanvasGeometry(m);
        markers = g.classes;
        markers.insert(markers.end(), g.regular.begin(), g.regular.end());
        fit.fit(m.polygon(), view);
    }
    Camera zoomedOn(Index v, double factor) const {
        Camera c = fit;
        c.centerOn(m.polygon().vertices[v]);
        c.zoomAt({view.w / 2, view.h / 2}, factor);
        return c;
    }
    Vec2 screen(const Camera& c, const MarkerVertex& k) const {
        return c.toScreen({g.origin.x + k.x, g.origin.y + k.y});
    }
};

}  // namespace

// The boundary decimated to the pixel grid (pixelBoundary): at the fit of 10^5 spikes across a
// disc a fraction of the lines, every line an edge of a ring; every vertex on screen has its
// pixel (or, as rasterisers choose, a neighbour) inked by a line kept, and the pixels the kept
// lines ink are those all edges ink but for at most 1 in 100. Zoomed in on a few vertices the
// lines off screen go; a small face keeps every edge.
TEST(ViewerDeclutter, PixelBoundaryInksThePixelsTheEdgesDo) {
    DenseFace f(100000);
    const Polygon& P = f.m.polygon();
    // The pixels of the viewport (and a pixel round it) segments pass through, sampled a
    // quarter pixel apart.
    struct Ink {
        const Camera& c;
        int W, H;
        std::vector<uint8_t> px;
        Ink(const Camera& cam)
            : c(cam),
              W(int(cam.viewport().w) + 2),
              H(int(cam.viewport().h) + 2),
              px(size_t(W) * H, 0) {}
        uint8_t* at(Vec2 s) {
            const int i = int(std::floor(s.x - c.viewport().x)) + 1,
                      j = int(std::floor(s.y - c.viewport().y)) + 1;
            return i < 0 || j < 0 || i >= W || j >= H ? nullptr : &px[size_t(j) * W + i];
        }
        void line(Vec2 p, Vec2 q) {
            // Only the part within two pixels of the viewport is sampled.
            const Rect& r = c.viewport();
            double t0 = 0, t1 = 1;
            const double d[2] = {q.x - p.x, q.y - p.y}, o[2] = {p.x, p.y};
            const double lo[2] = {r.x - 2, r.y - 2}, hi[2] = {r.x + r.w + 2, r.y + r.h + 2};
            for (int k = 0; k < 2; ++k) {
                if (d[k] == 0) {
                    if (o[k] < lo[k] || o[k] > hi[k]) return;
                    continue;
                }
                double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
                if (a > b) std::swap(a, b);
                t0 = std::max(t0, a), t1 = std::min(t1, b);
            }
            if (t0 > t1) return;
            const double len = (t1 - t0) * std::max(std::abs(d[0]), std::abs(d[1]));
            const int n = int(4 * len) + 1;
            for (int k = 0; k <= n; ++k) {
                const double t = t0 + (t1 - t0) * k / n;
                if (uint8_t* b = at({p.x + d[0] * t, p.y + d[1] * t})) *b = 1;
            }
        }
        bool near(Vec2 s) {
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (uint8_t* b = at({s.x + dx, s.y + dy}); b && *b) return true;
            return false;
        }
    };
    auto check = [&](const Camera& c, const std::vector<uint32_t>& lines) {
        ASSERT_EQ(lines.size() % 2, 0u);
        Ink kept(c), all(c);
        for (size_t k = 0; k + 1 < lines.size(); k += 2) {
            ASSERT_LT(lines[k + 1], P.vertices.size());
            const Ring& g = P.rings[P.ringOf(lines[k])];
            EXPECT_EQ(lines[k + 1], lines[k] + 1 == g.first + g.count ? g.first : lines[k] + 1);
            kept.line(c.toScreen(P.vertices[lines[k]]), c.toScreen(P.vertices[lines[k + 1]]));
        }
        size_t shown = 0, missed = 0;
        for (const Ring& g : P.rings)
            for (Index v = g.first; v < g.first + g.count; ++v) {
                const Index w = v + 1 == g.first + g.count ? g.first : v + 1;
                all.line(c.toScreen(P.vertices[v]), c.toScreen(P.vertices[w]));
                const Vec2 s = c.toScreen(P.vertices[v]);
                if (!c.viewport().contains(s)) continue;
                ++shown;
                missed += !kept.near(s);
            }
        EXPECT_GT(shown, 0u);
        EXPECT_EQ(missed, 0u) << "of " << shown << " vertices on screen";
        size_t inked = 0, lost = 0, extra = 0;
        for (size_t k = 0; k < all.px.size(); ++k)
            inked += all.px[k], lost += all.px[k] && !kept.px[k], extra += kept.px[k] && !all.px[k];
        EXPECT_EQ(extra, 0u);
        EXPECT_LE(lost * 100, inked) << lost << " of " << inked << " pixels";
    };
    const std::vector<uint32_t> fit = pixelBoundary(P, f.fit, 1);
    EXPECT_LT(fit.size() / 2, P.vertices.size() / 3);  // 800x600: a fraction of 10^5 lines
    check(f.fit, fit);
    const Camera in = f.zoomedOn(500, 200);
    const std::vector<uint32_t> zoomed = pixelBoundary(P, in, 1);
    check(in, zoomed);
    EXPECT_LT(zoomed.size() / 2, P.vertices.size() / 3);  // the edges off screen dropped
    Model square;
    square.openPolygon(squareWithHole(false, false), "square", {});
    Camera c;
    c.fit(square.polygon(), f.view);
    EXPECT_EQ(pixelBoundary(square.polygon(), c, 1), buildCanvasGeometry(square).boundaryEdges);
}

TEST(ViewerDeclutter, ThinningKeepsAtMostOneMarkerPerCellAndAllWhenZoomedIn) {
    DenseFace f(20000);
    const double cell = 12;
    size_t previous = 0;
    int sparseViews = 0;
    for (double zoom : {1.0, 4.0, 64.0, 512.0}) {
        SCOPED_TRACE("zoom " + std::to_string(zoom));
        Camera c = f.zoomedOn(0, zoom);
        std::vector<MarkerVertex> kept = thinMarkers(f.markers, f.g.origin, c, cell);
        // One per cell of the grid anchored a cell outside the viewport's corner.
        std::set<std::pair<long, long>> cells;
        for (const MarkerVertex& k : kept) {
            Vec2 p = f.screen(c, k);
            EXPECT_TRUE(cells
                            .insert({long(std::floor((p.x + cell) / cell)),
                                     long(std::floor((p.y + cell) / cell))})
                            .second);
        }
        // Every marker on screen is in a cell that kept one: thinning never empties a cell.
        std::set<std::pair<long, long>> occupied;
        size_t onScreen = 0;
        for (const MarkerVertex& k : f.markers) {
            Vec2 p = f.screen(c, k);
            if (!f.view.contains(p)) continue;
            ++onScreen;
            occupied.insert(
                {long(std::floor((p.x + cell) / cell)), long(std::floor((p.y + cell) / cell))});
        }
        for (const auto& o : occupied) EXPECT_TRUE(cells.count(o));
        // Deterministic: the same camera keeps the same markers.
        std::vector<MarkerVertex> again = thinMarkers(f.markers, f.g.origin, c, cell);
        ASSERT_EQ(again.size(), kept.size());
        for (size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(again[i].x, kept[i].x);
        if (zoom == 1.0) {
            // The whole face: a few per cell along the annulus, not 20000 dots.
            EXPECT_LT(kept.size(), f.markers.size() / 4);
            EXPECT_LE(kept.size(), size_t((800 / cell + 2) * (600 / cell + 2)));
        }
        // Zoomed in so far that the markers on screen are more than a cell's diagonal apart,
        // no two share a cell: every one is kept.
        std::vector<Vec2> seen;
        for (const MarkerVertex& k : f.markers)
            if (f.view.contains(f.screen(c, k))) seen.push_back(f.screen(c, k));
        double closest = INFINITY;
        for (size_t i = 0; i < seen.size() && seen.size() < 2000; ++i)
            for (size_t j = i + 1; j < seen.size(); ++j)
                closest =
                    std::min(closest, std::hypot(seen[i].x - seen[j].x, seen[i].y - seen[j].y));
        if (seen.size() < 2000 && closest > cell * std::sqrt(2.0)) {
            size_t keptOnScreen = 0;
            for (const MarkerVertex& k : kept) keptOnScreen += f.view.contains(f.screen(c, k));
            EXPECT_EQ(keptOnScreen, onScreen);
            if (onScreen > 3) ++sparseViews;
        }
        std::printf("zoom %g: %zu of %zu markers kept, %zu on screen\n", zoom, kept.size(),
                    f.markers.size(), onScreen);
        previous = kept.size();
    }
    EXPECT_GT(previous, 0u);
    EXPECT_GE(sparseViews, 1) << "no zoom showed several markers a cell apart";
}

TEST(ViewerDeclutter, VertexLabelsOnlyWhereTheyDoNotOverlap) {
    DenseFace f(20000);
    TriangleGrid grid;
    grid.buildVertices(f.m.polygon());
    const double room = 44;  // the canvas's: a six-digit label's width, in pixels
    const uint32_t n = uint32_t(f.m.polygon().vertices.size());
    std::vector<size_t> counts;
    for (double zoom : {1.0, 64.0, 512.0, 4096.0, 65536.0}) {
        SCOPED_TRACE("zoom " + std::to_string(zoom));
        Camera c = f.zoomedOn(0, zoom);
        std::vector<uint32_t> shown = visibleLabels(grid, c, n, room * room);
        counts.push_back(shown.size());
        // No two labelled vertices closer on screen than a label: they cannot overlap.
        for (size_t i = 0; i < shown.size(); ++i)
            for (size_t j = i + 1; j < shown.size(); ++j) {
                Vec2 a = c.toScreen(f.m.polygon().vertices[shown[i]]),
                     b = c.toScreen(f.m.polygon().vertices[shown[j]]);
                ASSERT_GE(std::hypot(a.x - b.x, a.y - b.y), room * 0.999)
                    << shown[i] << " " << shown[j];
            }
        std::printf("zoom %g: %zu vertex labels\n", zoom, shown.size());
    }
    EXPECT_EQ(counts[0], 0u) << "the whole face: 20000 numbers would be a smear";
    EXPECT_GT(counts[1], 0u) << "the loneliest vertices first";
    // Zoomed in far, every vertex in view is numbered (the nearest pair is then ~70 px apart).
    Camera c = f.zoomedOn(0, 4096);
    size_t inView = 0;
    for (Point p : f.m.polygon().vertices) inView += f.view.contains(c.toScreen(p));
    EXPECT_GT(inView, 0u);
    EXPECT_GE(counts[3], inView);
    EXPECT_LE(counts[3], inView + 8) << "only the view and its margin";
    // Triangle labels go through the same culling: few at the fit, many more zoomed in.
    TriangleGrid tris;
    tris.build(f.m.polygon(), f.m.trace().triangles);
    const uint32_t t = uint32_t(f.m.trace().triangles.size());
    std::vector<size_t> triangleCounts;
    for (double zoom : {1.0, 8.0, 64.0}) {
        Camera at = f.fit;
        at.zoomAt({f.view.w / 2, f.view.h / 2}, zoom);  // on the inner disc's big triangles
        triangleCounts.push_back(visibleLabels(tris, at, t, 700).size());
        std::printf("zoom %g: %zu triangle labels\n", zoom, triangleCounts.back());
    }
    EXPECT_EQ(triangleCounts[0], 0u);
    EXPECT_GT(triangleCounts[1], 0u);
}

TEST(ViewerDeclutter, BridgesHaveTheirOwnColourAndGorgeFocusHasAnOutline) {
    // Bridges must not read as the just-cut triangles (both were yellow).
    auto dist = [](Rgba a, Rgba b) {
        return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
    };
    for (Rgba other :
         {palette::kCurrent, palette::kWater, palette::kPolygonFill, palette::kChain,
          palette::kJump, palette::kDormant, palette::kWaterLevel, palette::kTriangleEdge})
        EXPECT_GT(dist(palette::kBridge, other), 120);
    Model m;
    m.openPolygon(generate("circle-holes", 7, 1500), "circle-holes", {});
    bool sawBridge = false;
    for (uint32_t s = 1; s <= m.steps(); ++s) {
        m.seek(s);
        // The focus's outline (gorge_focus.h) runs through every vertex of the active chain.
        std::vector<Point> outline = activeGorgeOutline(m);
        for (Index i : m.state().chain) {
            Point p = m.polygon().vertices[i];
            ASSERT_TRUE(std::any_of(outline.begin(), outline.end(),
                                    [&](Point q) { return q.x == p.x && q.y == p.y; }))
                << "step " << s;
        }
        sawBridge |= !m.state().bridges.empty();
    }
    EXPECT_TRUE(sawBridge);
    // Hidden bridges: buildScene draws no line in the bridge colour.
    SceneOptions o;
    o.bridges = false;
    for (const Scene::Line& l : buildScene(m, o).lines)
        EXPECT_FALSE(l.color.r == palette::kBridge.r && l.color.g == palette::kBridge.g &&
                     l.color.b == palette::kBridge.b);
}

#endif
