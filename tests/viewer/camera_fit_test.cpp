// Fit into the free part of the canvas (viewer/view_fit.h), and the model's "the view is the
// last fit's" (issue 27 §4): the windows floating over the canvas never cover the polygon
// after a fit, a fit fills what is left, and a view the user moved is not refitted.
// Compiles to nothing when the viewer is not built.
#if __has_include("view_fit.h")
#include <gtest/gtest.h>

#include "test_support.h"
#include "view_fit.h"

using namespace flood;
using namespace flood::view;
using flood::testing::sourcePath;

namespace {

bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

WorldBox box(double x0, double y0, double x1, double y1) {
    WorldBox b;
    b.add({x0, y0});
    b.add({x1, y1});
    return b;
}

// The polygon's box on screen through `c`.
Rect onScreen(const Camera& c, const WorldBox& b) {
    const Vec2 lo = c.toScreen({b.x0, b.y1}), hi = c.toScreen({b.x1, b.y0});
    return {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
}

}  // namespace

TEST(CameraFit, NothingOverTheCanvasIsTheWholeCanvas) {
    const Rect canvas{300, 0, 680, 672};
    const Rect free = freeArea(canvas, {}, 1.5);
    EXPECT_EQ(free.x, canvas.x);
    EXPECT_EQ(free.w, canvas.w);
    // The same camera as the plain fit of the box.
    Camera plain;
    plain.fitBox(0, 0, 30, 20, canvas);
    const Camera c = fitCamera(box(0, 0, 30, 20), canvas, {});
    EXPECT_DOUBLE_EQ(c.scale(), plain.scale());
    EXPECT_DOUBLE_EQ(c.center().x, plain.center().x);
    EXPECT_DOUBLE_EQ(c.center().y, plain.center().y);
}

TEST(CameraFit, TheFindAndEditBoxesLeaveTheTopEdge) {
    // A wide polygon under a find box at the top-left and an Edit box at the top-right: the
    // polygon goes below them, across the whole width, not beside them.
    const Rect canvas{300, 0, 680, 672};
    const std::vector<Rect> over{{308, 8, 170, 30}, {880, 8, 92, 28}};
    const WorldBox b = box(0, 0, 40, 20);
    const Camera c = fitCamera(b, canvas, over);
    const Rect shown = onScreen(c, b);
    for (const Rect& o : over) EXPECT_FALSE(overlaps(shown, o));
    EXPECT_GE(shown.y, 38);
    EXPECT_GT(shown.w, 0.85 * canvas.w) << "the width is all there is to fill";
    // The viewport stays the canvas: picking and labels see one rectangle.
    EXPECT_EQ(c.viewport().x, canvas.x);
    EXPECT_EQ(c.viewport().w, canvas.w);
}

TEST(CameraFit, ATallPolygonGoesBesideAWindowInTheCorner) {
    // A State table in the bottom-right corner: a tall polygon fits at the left of it, as
    // large as the free column allows, and never under it.
    const Rect canvas{0, 0, 1320, 952};
    const Rect table{752, 524, 560, 420};
    const WorldBox b = box(-5, -10, 5, 10);
    const Camera c = fitCamera(b, canvas, {table});
    const Rect shown = onScreen(c, b);
    EXPECT_FALSE(overlaps(shown, table));
    EXPECT_GT(shown.h, 0.85 * canvas.h);
    EXPECT_LE(shown.x + shown.w, table.x);
}

TEST(CameraFit, OverlaysOutsideTheCanvasChangeNothing) {
    const Rect canvas{300, 0, 680, 672};
    const Camera a = fitCamera(box(0, 0, 1, 1), canvas, {});
    const Camera b = fitCamera(box(0, 0, 1, 1), canvas, {{0, 0, 290, 600}, {990, 10, 50, 50}});
    EXPECT_DOUBLE_EQ(a.scale(), b.scale());
    EXPECT_DOUBLE_EQ(a.center().x, b.center().x);
}

TEST(CameraFit, ACoveredCanvasFitsTheWholeOfIt) {
    const Rect canvas{0, 0, 100, 100};
    EXPECT_LE(freeArea(canvas, {{-10, -10, 200, 200}}, 1).w, 0);
    const Camera c = fitCamera(box(0, 0, 1, 1), canvas, {{-10, -10, 200, 200}});
    EXPECT_GT(c.scale(), 0);
    EXPECT_EQ(c.viewport().w, 100);
}

TEST(CameraFit, SameRectsWithinHalfAPixel) {
    EXPECT_TRUE(sameRects({{0, 0, 10, 10}}, {{0.3, 0, 10, 10.2}}));
    EXPECT_FALSE(sameRects({{0, 0, 10, 10}}, {{2, 0, 10, 10}}));
    EXPECT_FALSE(sameRects({{0, 0, 10, 10}}, {}));
}

TEST(CameraFit, AMovedViewIsNoLongerTheFit) {
    Model m;
    m.open(sourcePath("polygons/paper-figure-7.json"));
    ASSERT_FALSE(m.polygon().vertices.empty());
    const Rect canvas{300, 0, 680, 672};
    EXPECT_TRUE(m.viewIsFit()) << "a fit is pending after an open";
    m.fitCamera(canvas, {{308, 8, 170, 30}});
    EXPECT_TRUE(m.viewIsFit());
    // Every vertex clear of the box over the canvas.
    for (Point p : m.polygon().vertices) {
        const Vec2 s = m.camera().toScreen(p);
        EXPECT_FALSE(s.x >= 308 && s.x <= 478 && s.y >= 8 && s.y <= 38);
    }
    m.zoomAt({600, 300}, 1.15);
    EXPECT_FALSE(m.viewIsFit()) << "zoomed: a layout change keeps this view";
    m.requestFit();
    EXPECT_TRUE(m.viewIsFit());
    m.fitCamera(canvas);
    m.pan(3, 0);
    EXPECT_FALSE(m.viewIsFit()) << "panned";
}

#endif
