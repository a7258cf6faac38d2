// Exports for slides without a window (viewer/export.h, quantize.h, gif_writer.h): which steps
// become frames, the view an export shows, the caption, the GIF palette (exact when the frames
// hold 256 colours or fewer) and a GIF that giflib reads back. The rendering itself is tested
// under Xvfb (tests/gui/export_test.cpp). Compiles to nothing when the viewer is not built.
#if __has_include("export.h") && __has_include("quantize.h")
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "export.h"
#include "flood/teach/narrate.h"
#include "quantize.h"
#include "scene.h"
#include "test_support.h"
#ifdef FLOOD_GIF
#include <gif_lib.h>

#include "gif_writer.h"
#endif

using namespace flood;
using namespace flood::view;

namespace {

TEST(Export, StepsOfARangeEndOnItsLastStep) {
    EXPECT_EQ(exportSteps(0, 10, 3, 20), (std::vector<uint32_t>{0, 3, 6, 9, 10}));
    EXPECT_EQ(exportSteps(0, 9, 3, 20), (std::vector<uint32_t>{0, 3, 6, 9}));
    EXPECT_EQ(exportSteps(2, 11, 4, 20), (std::vector<uint32_t>{2, 6, 10, 11}));
    EXPECT_EQ(exportSteps(5, kNone, 10, 7), (std::vector<uint32_t>{5, 7}));  // the end: the flood's
    EXPECT_EQ(exportSteps(4, 4, 1, 7), (std::vector<uint32_t>{4}));
    EXPECT_EQ(exportSteps(0, 3, 0, 7), (std::vector<uint32_t>{0, 1, 2, 3}));  // every 0 is every 1
    EXPECT_TRUE(exportSteps(8, kNone, 1, 7).empty());
}

TEST(Export, StepRangesParseOrSayWhy) {
    uint32_t a = 99, b = 99;
    EXPECT_TRUE(parseStepRange("2:5", a, b, nullptr));
    EXPECT_EQ(a, 2u);
    EXPECT_EQ(b, 5u);
    EXPECT_TRUE(parseStepRange("3:", a, b, nullptr));
    EXPECT_EQ(a, 3u);
    EXPECT_EQ(b, kNone);
    EXPECT_TRUE(parseStepRange(":7", a, b, nullptr));
    EXPECT_EQ(a, 0u);
    EXPECT_EQ(b, 7u);
    std::string why;
    for (const char* bad : {"5", "x:3", "1:-2", "1:2:3", "99999999999:", ""}) {
        why.clear();
        EXPECT_FALSE(parseStepRange(bad, a, b, &why)) << bad;
        EXPECT_NE(why.find("--steps"), std::string::npos) << why;
    }
    EXPECT_FALSE(parseStepRange("5:2", a, b, &why));
    EXPECT_NE(why.find("after the last"), std::string::npos) << why;
}

// --step N (viewer/args.cpp), around 2^31 and 2^32, in the fixed-width types the parse uses:
// N itself up to 2^32 - 1, anything larger the end (UINT32_MAX; seek() clamps it). Issue 29:
// std::min<long>(N, ~0u) read ~0u as the long -1 where long is 32 bits (Windows, wasm32), so
// every --step N jumped to the end there.
TEST(Export, StepArgumentAroundTwoToThe32) {
    const struct {
        const char* text;
        uint32_t step;
    } cases[] = {{"0", 0u},
                 {"5", 5u},
                 {"007", 7u},
                 {"2147483647", 2147483647u},  // INT32_MAX, a 32-bit long's largest
                 {"2147483648", 2147483648u},
                 {"4294967294", 4294967294u},
                 {"4294967295", UINT32_MAX},
                 {"4294967296", UINT32_MAX},  // past 2^32 - 1: the end
                 {"9223372036854775808", UINT32_MAX},
                 {"99999999999999999999999999", UINT32_MAX}};
    for (const auto& c : cases) {
        uint32_t step = 12345;
        EXPECT_TRUE(parseStepArg(c.text, step)) << c.text;
        EXPECT_EQ(step, c.step) << c.text;
    }
    for (const char* bad : {"", "-1", "-0", "+5", " 5", "5x", "0x10", "1e3"}) {
        uint32_t step = 12345;
        EXPECT_FALSE(parseStepArg(bad, step)) << bad;
        EXPECT_EQ(step, 12345u) << bad;
    }
}

TEST(Export, CameraShowsWhatTheCanvasShowsAtTheExportSize) {
    Camera canvas;
    canvas.fitBox(0, 0, 10, 5, Rect{300, 40, 800, 500});
    for (Rect area : {Rect{0, 0, 1600, 1000}, Rect{0, 0, 400, 900}, Rect{0, 0, 1920, 1000}}) {
        Camera cam = exportCamera(canvas, area);
        double factor = std::min(area.w / 800, area.h / 500);
        EXPECT_NEAR(cam.scale(), canvas.scale() * factor, 1e-9 * canvas.scale());
        EXPECT_EQ(cam.center().x, canvas.center().x);
        EXPECT_EQ(cam.center().y, canvas.center().y);
        // The canvas's corners land inside the area: nothing visible is cut off.
        for (Vec2 corner : {Vec2{300, 40}, Vec2{1100, 540}}) {
            Vec2 p = cam.toScreen(canvas.toWorld(corner));
            EXPECT_GE(p.x, -1e-6);
            EXPECT_LE(p.x, area.w + 1e-6);
            EXPECT_GE(p.y, -1e-6);
            EXPECT_LE(p.y, area.h + 1e-6);
        }
    }
}

TEST(Export, CaptionIsTheStepTheActionAndTheNarration) {
    Model m;
    m.open(flood::testing::sourcePath("polygons/paper-figure-7.json"));
    ASSERT_GT(m.steps(), 3u);
    CaptionLine c0 = captionOf(m, 0);
    EXPECT_EQ(c0.head, "Step 0");
    const Event& e = m.trace().events[2];
    CaptionLine c = captionOf(m, 3);
    EXPECT_EQ(c.head, std::string("Step 3  ") + actionName(e.action));
    EXPECT_EQ(c.text, narrate(m.polygon(), e));
    EXPECT_EQ(c.headColor.r, palette::action(e.action).r);
}

TEST(Export, SequenceFilesAreNumberedToSortInOrder) {
    EXPECT_EQ(sequenceFile("out", 0, 3), "out/frame-0000.png");
    EXPECT_EQ(sequenceFile("out/", 12, 13), "out/frame-0012.png");
    EXPECT_EQ(sequenceFile("d", 7, 123456), "d/frame-000007.png");
}

// RGBA pixels of the given colours, `each` pixels of colour i repeated (i + 1) * each times.
std::vector<uint8_t> pixelsOf(const std::vector<Rgb>& colours, size_t each) {
    std::vector<uint8_t> px;
    for (size_t i = 0; i < colours.size(); ++i)
        for (size_t k = 0; k < (i + 1) * each; ++k)
            px.insert(px.end(), {colours[i][0], colours[i][1], colours[i][2], 255});
    return px;
}

TEST(Export, PaletteIsExactWhenTheFramesHoldFewColours) {
    std::vector<Rgb> colours;
    for (int i = 0; i < 256; ++i) colours.push_back({uint8_t(i), uint8_t(255 - i), uint8_t(i * 7)});
    std::vector<uint8_t> px = pixelsOf(colours, 1);
    PaletteBuilder b;
    b.add(px.data(), px.size() / 4);
    ASSERT_EQ(b.distinct(), 256u);
    std::vector<Rgb> palette = b.build(256);
    EXPECT_EQ(std::set<Rgb>(palette.begin(), palette.end()),
              std::set<Rgb>(colours.begin(), colours.end()));
    PaletteMap map(palette);
    std::vector<uint8_t> idx(px.size() / 4);
    map.map(px.data(), idx.size(), idx.data());
    for (size_t i = 0; i < idx.size(); ++i)
        for (int k = 0; k < 3; ++k) ASSERT_EQ(palette[idx[i]][k], px[4 * i + k]) << "pixel " << i;
}

TEST(Export, PaletteKeepsTheFrequentColoursExactBeyond256) {
    // 40 flat fills (frequent) and 3000 rare anti-aliasing shades.
    std::vector<Rgb> fills, shades;
    for (int i = 0; i < 40; ++i) fills.push_back({uint8_t(6 * i), 200, uint8_t(250 - 6 * i)});
    for (int i = 0; i < 3000; ++i)
        shades.push_back({uint8_t(i % 251), uint8_t(i % 13 * 19), uint8_t(i / 12)});
    std::vector<uint8_t> px;
    for (const Rgb& s : shades) px.insert(px.end(), {s[0], s[1], s[2], 255});
    std::vector<uint8_t> flat = pixelsOf(fills, 1000);
    px.insert(px.end(), flat.begin(), flat.end());
    PaletteBuilder b;
    b.add(px.data(), px.size() / 4);
    std::vector<Rgb> palette = b.build(256);
    EXPECT_EQ(palette.size(), 256u);
    PaletteMap map(palette);
    for (const Rgb& f : fills) {
        uint8_t rgba[4] = {f[0], f[1], f[2], 255}, i = 0;
        map.map(rgba, 1, &i);
        EXPECT_EQ(palette[i], f) << "a flat fill is kept exactly";
    }
    // Every shade maps to a near colour, not to an arbitrary one.
    uint64_t worst = 0;
    for (const Rgb& s : shades) {
        uint8_t rgba[4] = {s[0], s[1], s[2], 255}, i = 0;
        map.map(rgba, 1, &i);
        uint64_t d = 0;
        for (int k = 0; k < 3; ++k)
            d += uint64_t((int(s[k]) - palette[i][k]) * (int(s[k]) - palette[i][k]));
        worst = std::max(worst, d);
    }
    EXPECT_LT(worst, 3u * 64 * 64);
}

#ifdef FLOOD_GIF
TEST(Export, GifReadsBackFrameByFrameWithItsPalette) {
    const int W = 7, H = 5;
    std::vector<Rgb> palette{{30, 32, 38}, {40, 110, 190}, {250, 200, 60}};
    std::ostringstream out;
    GifWriter gif(out, W, H, palette, 20);
    for (uint8_t f = 0; f < 3; ++f) {
        std::vector<uint8_t> idx(W * H);
        for (int i = 0; i < W * H; ++i) idx[size_t(i)] = uint8_t((i + f) % 3);
        ASSERT_TRUE(gif.addFrame(idx)) << gif.error();
    }
    ASSERT_TRUE(gif.finish()) << gif.error();
    auto dir = flood::testing::scratch("export-gif");
    std::string path = (dir / "t.gif").string();
    std::ofstream(path, std::ios::binary) << out.str();
    int err = 0;
    GifFileType* g = DGifOpenFileName(path.c_str(), &err);
    ASSERT_NE(g, nullptr) << GifErrorString(err);
    ASSERT_EQ(DGifSlurp(g), GIF_OK) << GifErrorString(g->Error);
    EXPECT_EQ(g->ImageCount, 3);
    EXPECT_EQ(g->SWidth, W);
    EXPECT_EQ(g->SHeight, H);
    ASSERT_NE(g->SColorMap, nullptr);
    for (size_t i = 0; i < palette.size(); ++i) {
        GifColorType c = g->SColorMap->Colors[i];
        EXPECT_EQ((Rgb{c.Red, c.Green, c.Blue}), palette[i]);
    }
    EXPECT_EQ(g->SavedImages[2].RasterBits[0], 2);  // (0 + 2) % 3
    GraphicsControlBlock gcb;
    ASSERT_EQ(DGifSavedExtensionToGCB(g, 1, &gcb), GIF_OK);
    EXPECT_EQ(gcb.DelayTime, 20);
    DGifCloseFile(g, &err);
}
#endif

TEST(Export, SvgThroughTheExportCameraHasOneElementPerTriangle) {
    Model m;
    m.open(flood::testing::sourcePath("polygons/paper-figure-7.json"));
    m.seek(m.steps() / 2);
    Camera cam;
    cam.fit(m.polygon(), Rect{0, 0, 640, 420});
    std::ostringstream svg;
    CaptionLine c = captionOf(m, m.step());
    c.text += " <&> \"quoted\"";  // escaped, so the file stays well-formed
    writeSceneSvg(svg, buildScene(m), cam, 640, 480, &c);
    std::string text = svg.str();
    auto count = [&](const std::string& needle) {
        size_t n = 0;
        for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
            ++n;
        return n;
    };
    const Event* e = m.currentEvent();
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(count("<polygon class=\"water\""), m.state().triangleCount - e->triangleCount);
    EXPECT_EQ(count("<polygon class=\"current\""), e->triangleCount);
    EXPECT_NE(text.find("&lt;&amp;&gt; &quot;quoted&quot;"), std::string::npos);
    EXPECT_NE(text.find("width=\"640\" height=\"480\""), std::string::npos);
}

}  // namespace
#endif
