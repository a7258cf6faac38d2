// "Current gorge only" dims the canvas outside the active gorge's outline (viewer/gorge_focus.h),
// not outside its bounding box. Compiles to nothing when the viewer is not built.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flood/tools/generate.h"
#include "gorge_focus.h"
#include "model.h"

using namespace flood;
using namespace flood::view;

namespace {
// Even-odd inside test of a closed polygon (the test's own, for sample points).
bool inside(const std::vector<Vec2>& poly, Vec2 p) {
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < poly[j].x + (p.y - poly[j].y) * (poly[i].x - poly[j].x) / (poly[i].y - poly[j].y))
            in = !in;
    return in;
}
bool dimmed(const std::vector<Rect>& dim, Vec2 p) {
    for (const Rect& r : dim)
        if (r.contains(p)) return true;
    return false;
}
}  // namespace

TEST(GorgeFocus, OutsideOfIsTheAreaMinusTheOutline) {
    // A triangle in a 100 x 100 area: its corners' box is half outside it.
    Rect area{0, 0, 100, 100};
    std::vector<Vec2> tri{{10, 90}, {90, 90}, {50, 10}};
    std::vector<Rect> dim = outsideOf(tri, area);
    EXPECT_FALSE(dimmed(dim, {50, 60}));  // inside
    EXPECT_TRUE(dimmed(dim, {15, 20}));   // in the box, outside the triangle
    EXPECT_TRUE(dimmed(dim, {85, 20}));
    EXPECT_TRUE(dimmed(dim, {50, 95}));  // below it
    EXPECT_TRUE(dimmed(dim, {5, 50}));
    // Every sampled pixel centre is dimmed exactly when it is outside.
    for (double y = 0.5; y < 100; y += 3)
        for (double x = 0.5; x < 100; x += 3)
            ASSERT_EQ(dimmed(dim, {x, y}), !inside(tri, {x, y})) << x << ", " << y;
    // No outline: every row dimmed whole.
    EXPECT_EQ(outsideOf({}, area).size(), 100u);
}

TEST(GorgeFocus, TheOutlineRunsNextLeftLeftChainRightNextRight) {
    Model m;
    m.openPolygon(generate("circle-holes", 7, 1500), "circle-holes", {});
    m.fitCamera({0, 0, 800, 600});
    size_t notBoxes = 0, checked = 0;
    for (uint32_t s = 1; s <= m.steps(); s += 7) {
        m.seek(s);
        std::vector<Point> outline = activeGorgeOutline(m);
        const ReplayState& st = m.state();
        if (st.fingers.left == kNone) {
            EXPECT_TRUE(outline.empty() || st.chain.size() > 0) << s;
            continue;
        }
        ASSERT_GE(outline.size(), 2u) << s;
        const auto& v = m.polygon().vertices;
        if (st.fingers.nextLeft != kNone) {
            EXPECT_EQ(outline.front().x, v[st.fingers.nextLeft].x) << s;
            EXPECT_EQ(outline.front().y, v[st.fingers.nextLeft].y) << s;
        }
        if (st.fingers.nextRight != kNone) {
            EXPECT_EQ(outline.back().x, v[st.fingers.nextRight].x) << s;
            EXPECT_EQ(outline.back().y, v[st.fingers.nextRight].y) << s;
        }
        if (outline.size() < 3) continue;
        // Somewhere in the outline's box but outside the outline is dimmed (a box focus would
        // leave it lit), and the outline's inside is not.
        std::vector<Vec2> screen;
        for (Point p : outline) screen.push_back(m.camera().toScreen(p));
        Rect area{0, 0, 800, 600};
        std::vector<Rect> dim = outsideOf(screen, area);
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (Vec2 p : screen)
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x),
            y1 = std::max(y1, p.y);
        bool boxOnly = false;
        for (double y = std::floor(y0) + 0.5; y < y1; y += 2)
            for (double x = std::floor(x0) + 0.5; x < x1; x += 2) {
                if (!area.contains({x, y})) continue;
                ++checked;
                ASSERT_EQ(dimmed(dim, {x, y}), !inside(screen, {x, y}))
                    << "step " << s << " at " << x << ", " << y;
                boxOnly |= !inside(screen, {x, y});
            }
        notBoxes += boxOnly;
    }
    EXPECT_GT(checked, 1000u);
    EXPECT_GT(notBoxes, 10u);
}
#endif
