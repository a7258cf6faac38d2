// Presenter mode without a window (viewer/presenter.h, viewer/palette.h): the UI scale's
// steps and limits, the remembered settings, the two themes, the layouts at a large scale
// and the caption. Compiles to nothing when the viewer is not built.
#if __has_include("presenter.h")
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "flood/teach/narrate.h"
#include "presenter.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using flood::testing::scratch;
using flood::testing::sourcePath;

namespace {

double luminance(Rgba c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// The palette is process-wide: every test leaves it dark, as the rest of the suite expects.
struct ThemeTest : ::testing::Test {
    void TearDown() override { palette::setTheme(Theme::Dark); }
};

}  // namespace

TEST(UiScale, ZoomStepsFrom50To300PercentAndBack) {
    UiScale s;
    EXPECT_EQ(s.value(), 1.f);
    EXPECT_EQ(s.fontPixels(), 13.f);
    EXPECT_FALSE(s.resetZoom());  // already 100%
    EXPECT_TRUE(s.zoomIn());
    EXPECT_FLOAT_EQ(s.zoom(), 1.1f);
    int presses = 0;
    while (s.zoomIn()) ++presses;
    EXPECT_EQ(presses, UiScale::kMaxZoomStep - 1);
    EXPECT_FLOAT_EQ(s.zoom(), 3.f);
    EXPECT_EQ(s.fontPixels(), 39.f);
    EXPECT_TRUE(s.resetZoom());
    EXPECT_EQ(s.zoom(), 1.f);
    while (s.zoomOut()) {
    }
    EXPECT_FLOAT_EQ(s.zoom(), 0.5f);
    EXPECT_EQ(s.zoomStep(), UiScale::kMinZoomStep);
    EXPECT_FALSE(s.setZoomStep(-100));  // clamped to where it is
}

TEST(UiScale, ContentScaleMultipliesTheZoomAndFontsAreWholePixels) {
    UiScale s;
    uint64_t g = s.generation();
    EXPECT_TRUE(s.setContentScale(2));
    EXPECT_NE(s.generation(), g);
    EXPECT_EQ(s.value(), 2.f);
    EXPECT_EQ(s.fontPixels(), 26.f);
    g = s.generation();
    EXPECT_FALSE(s.setContentScale(2));  // no change, nothing to rebuild
    EXPECT_EQ(s.generation(), g);
    s.setZoomStep(2);  // 125%
    EXPECT_FLOAT_EQ(s.value(), 2.5f);
    s.setContentScale(1.5f);
    s.setZoomStep(1);  // 1.5 * 1.1 * 13 = 21.45
    EXPECT_EQ(s.fontPixels(), 21.f);
    EXPECT_EQ(s.fontPixels(20), std::round(20 * 1.5f * 1.1f));
    for (float bad : {0.f, -2.f, NAN, INFINITY}) {
        s.setContentScale(bad);
        EXPECT_EQ(s.contentScale(), 1.f) << bad;
    }
}

TEST(ViewerSettings, RoundTripAndDefaults) {
    auto file = scratch("presenter-settings") / "flood-viewer" / "settings.txt";
    EXPECT_TRUE(saveSettings(file.string(), {Theme::Light, 3}));
    ViewerSettings s = loadSettings(file.string());
    EXPECT_EQ(s.theme, Theme::Light);
    EXPECT_EQ(s.zoomStep, 3);
    ViewerSettings none = loadSettings((file.parent_path() / "missing.txt").string());
    EXPECT_EQ(none.theme, Theme::Dark);
    EXPECT_EQ(none.zoomStep, 0);
}

TEST(ViewerSettings, LinesItDoesNotUnderstandAreSkipped) {
    auto file = scratch("presenter-settings-odd") / "settings.txt";
    std::ofstream(file) << "colour blue\ntheme sepia\n\nzoom 2x\ntheme light\nzoom 99\n";
    ViewerSettings s = loadSettings(file.string());
    EXPECT_EQ(s.theme, Theme::Light);
    EXPECT_EQ(s.zoomStep, UiScale::kMaxZoomStep);  // clamped
}

TEST_F(ThemeTest, LightIsALightGroundWithDarkLinesAndDarkRestoresTheDarkColours) {
    EXPECT_EQ(palette::theme(), Theme::Dark);
    EXPECT_LT(luminance(palette::kBackground), 60);
    Rgba darkWater = palette::kWater, darkRaise = palette::action(Action::Raise);
    palette::setTheme(Theme::Light);
    EXPECT_EQ(palette::theme(), Theme::Light);
    EXPECT_GT(luminance(palette::kBackground), 230);
    EXPECT_LT(luminance(palette::kBoundary), 60);
    EXPECT_LT(luminance(palette::kTriangleEdge), 80);
    EXPECT_NE(luminance(palette::action(Action::Raise)), luminance(darkRaise));
    palette::setTheme(Theme::Dark);
    EXPECT_EQ(luminance(palette::kBackground), luminance(palette::kDark.background));
    EXPECT_EQ(luminance(palette::kWater), luminance(darkWater));
    EXPECT_EQ(luminance(palette::kBoundary), luminance(palette::kDark.boundary));
}

// Every line, marker and label colour must stand out from the ground it is drawn on, in both
// themes (a white dormant chain on the light ground would vanish).
TEST_F(ThemeTest, EveryDrawnColourStandsOutFromTheBackground) {
    for (Theme t : {Theme::Dark, Theme::Light}) {
        palette::setTheme(t);
        const Rgba drawn[] = {palette::kBoundary, palette::kChain,        palette::kLeft,
                              palette::kRight,    palette::kJump,         palette::kDormant,
                              palette::kCulprit,  palette::kVertexNumber, palette::kWaterLevel,
                              palette::kBridge};
        for (const Rgba& c : drawn) {
            double d = std::abs(c.r - palette::kBackground.r) +
                       std::abs(c.g - palette::kBackground.g) +
                       std::abs(c.b - palette::kBackground.b);
            EXPECT_GT(d, 150) << palette::themeName(t) << " " << int(c.r) << "," << int(c.g) << ","
                              << int(c.b);
        }
        for (int a = 0; a < int(Action::Count); ++a) {
            double d =
                std::abs(luminance(palette::action(Action(a))) - luminance(palette::kBackground));
            EXPECT_GT(d, 40) << palette::themeName(t) << " " << actionName(Action(a));
        }
    }
}

TEST(ThemeNames, ParseAndName) {
    Theme t = Theme::Dark;
    EXPECT_TRUE(palette::parseTheme("light", t));
    EXPECT_EQ(t, Theme::Light);
    EXPECT_FALSE(palette::parseTheme("Light ", t));
    EXPECT_EQ(t, Theme::Light);  // untouched
    EXPECT_STREQ(palette::themeName(Theme::Dark), "dark");
}

// At 2x on 1024x768 the wrapped toolbar needs more than the timeline's usual share: it gets
// it (up to half the window); a timeline that needs less keeps the layout as it was.
TEST(PresenterLayout, TimelineGetsTheHeightItsWrappedToolbarNeeds) {
    Layout usual = computeLayout(1024, 768, 2);
    Layout grown = computeLayout(1024, 768, 2, 300);
    EXPECT_DOUBLE_EQ(grown.bottom.h, 300);
    EXPECT_DOUBLE_EQ(grown.bottom.y + grown.bottom.h, 768);
    EXPECT_DOUBLE_EQ(grown.canvas.y + grown.canvas.h, grown.bottom.y);
    EXPECT_LT(usual.bottom.h, 300);
    EXPECT_DOUBLE_EQ(computeLayout(1024, 768, 2, 5000).bottom.h, 384);
    Layout small = computeLayout(1000, 700, 1, 100);
    Layout old = computeLayout(1000, 700, 1);
    EXPECT_DOUBLE_EQ(small.bottom.h, old.bottom.h);
    EXPECT_DOUBLE_EQ(small.canvas.w, old.canvas.w);
}

TEST(PresenterLayout, CanvasOverTheWholeWidthCaptionBelowAtMostHalf) {
    Layout l = presenterLayout(1024, 768, 200);
    EXPECT_DOUBLE_EQ(l.canvas.x, 0);
    EXPECT_DOUBLE_EQ(l.canvas.w, 1024);
    EXPECT_DOUBLE_EQ(l.canvas.h, 568);
    EXPECT_DOUBLE_EQ(l.bottom.y, 568);
    EXPECT_DOUBLE_EQ(l.bottom.h, 200);
    EXPECT_DOUBLE_EQ(l.left.w + l.right.w, 0);
    EXPECT_DOUBLE_EQ(presenterLayout(1024, 768, 1e6).bottom.h, 384);
    EXPECT_DOUBLE_EQ(presenterLayout(1024, 768, 0).canvas.h, 768);  // before it is measured
}

TEST(Caption, StepNumberActionAndTheNarrationSentence) {
    Model m;
    m.open(sourcePath("polygons/paper-figure-7.json"));
    ASSERT_GT(m.steps(), 3u);
    m.seek(0);
    Caption c0 = buildCaption(m);
    EXPECT_EQ(c0.heading, "Step 0 of " + std::to_string(m.steps()));
    EXPECT_FALSE(c0.hasAction);
    EXPECT_FALSE(c0.sentence.empty());
    for (uint32_t s = 1; s <= m.steps(); ++s) {
        m.seek(s);
        Caption c = buildCaption(m);
        const Event& e = m.trace().events[s - 1];
        EXPECT_EQ(c.heading, "Step " + std::to_string(s) + " of " + std::to_string(m.steps()));
        EXPECT_TRUE(c.hasAction);
        EXPECT_EQ(c.action, e.action);
        EXPECT_EQ(c.sentence, narrate(m.polygon(), e));
    }
}

TEST(Caption, NoPolygonSaysWhy) {
    Model m;
    m.open(sourcePath("polygons/no-such-file.json"));
    Caption c = buildCaption(m);
    EXPECT_FALSE(c.hasAction);
    EXPECT_NE(c.sentence.find("no-such-file"), std::string::npos) << c.sentence;
}

#endif
