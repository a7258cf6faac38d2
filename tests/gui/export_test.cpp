// GUI test of the exports for slides: flood-viewer run headless (Xvfb) writes the canvas alone
// as PNG at the requested size (no panel pixels, water and background where the export's
// camera puts them, the caption band), as SVG (well-formed, one element per triangle), as an
// animated GIF (decoded with giflib: one frame per exported step) and as a numbered PNG
// sequence; a path that cannot be written exits 8 and says why. Skipped without a display,
// except in CI.
#include <gtest/gtest.h>
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef FLOOD_GIF
#include <gif_lib.h>
#endif

#include "export.h"
#include "gui_test_display.h"
#include "model.h"
#include "palette.h"

using namespace flood;
using namespace flood::view;
namespace fs = std::filesystem;

namespace {

#define NEED_DISPLAY()                                                       \
    do {                                                                     \
        if (!hasDisplay()) {                                                 \
            if (inCi()) FAIL() << "no display in CI: run under xvfb-run -a"; \
            GTEST_SKIP() << "no display (run under xvfb-run -a)";            \
        }                                                                    \
    } while (0)

struct ViewerRun {
    int code = -1;
    std::string out;  // stdout and stderr
};

ViewerRun viewer(const std::string& args) {
    ViewerRun r;
    std::string cmd = std::string("'") + FLOOD_VIEWER + "' " + args + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    char buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
    int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

fs::path scratch(const std::string& name) {
    fs::path d =
        fs::path(FLOOD_WORK_DIR) / ("export-test-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// A square with a square hole, as in screenshot_test.cpp: small enough to reason about.
std::string squareWithHole(const fs::path& dir) {
    std::string path = (dir / "square-hole.json").string();
    std::ofstream(path) << R"({"type": "Polygon", "coordinates": [
        [[0, 0], [10, 1], [11, 9], [1, 10], [0, 0]],
        [[4, 4], [4, 6], [6, 6.5], [6.5, 4], [4, 4]]]})"
                           "\n";
    return path;
}

struct Image {
    int w = 0, h = 0;
    std::vector<unsigned char> px;
    bool load(const std::string& path) {
        int channels = 0;
        unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
        if (!data) return false;
        px.assign(data, data + size_t(w) * h * 4);
        stbi_image_free(data);
        return true;
    }
    Rgba at(int x, int y) const {
        const unsigned char* p = px.data() + (size_t(y) * w + x) * 4;
        return {p[0], p[1], p[2], 255};
    }
};

bool close(Rgba a, Rgba b, int tol) {
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

// Pixels of ImGui's dark window background (WindowBg 0.06 grey at alpha 0.94 over the canvas
// background): every panel is mostly this colour, and the canvas never paints it.
size_t panelPixels(const Image& img) {
    Rgba panel{16, 16, 17, 255};
    size_t n = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) n += close(img.at(x, y), panel, 2);
    return n;
}

// The model as the exporting viewer sees it: the hidden 1280x800 window's canvas, fitted clear
// of the find and Edit boxes over it (view_fit.h), where that window prints them.
Camera exportView(Model& m, const Rect& area) {
    Layout layout = computeLayout(1280, 800, 1);
    const fs::path shot =
        fs::path(FLOOD_WORK_DIR) / ("export-view-" + std::to_string(getpid()) + ".png");
    ViewerRun r = viewer("'" + m.path() + "' --step " + std::to_string(m.step()) +
                         " --print-layout --screenshot '" + shot.string() + "' --size 1280x800");
    fs::remove(shot);
    std::vector<Rect> boxes;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        char name[64];
        Rect b;
        if (std::sscanf(line.c_str(), "flood-viewer: layout %63s %lf %lf %lf %lf", name, &b.x, &b.y,
                        &b.w, &b.h) == 5 &&
            (std::string(name) == "find-box" || std::string(name) == "edit-box"))
            boxes.push_back(b);
    }
    EXPECT_EQ(boxes.size(), 2u) << r.out;
    m.fitCamera(layout.canvas, boxes);
    return exportCamera(m.camera(), area);
}

// A step with earlier (not emphasised) flooded triangles.
uint32_t middleStep(const std::string& input) {
    Model m;
    m.open(input);
    for (uint32_t s = 1; s <= m.steps(); ++s) {
        m.seek(s);
        if (m.state().triangleCount > m.currentEvent()->triangleCount + 1) return s;
    }
    return 0;
}

TEST(ExportGui, CanvasOnlyPngHasTheSizeAndNoPanels) {
    NEED_DISPLAY();
    fs::path dir = scratch("png");
    std::string input = squareWithHole(dir);
    Model m;
    m.open(input);
    uint32_t step = middleStep(input);
    ASSERT_GT(step, 0u);
    m.seek(step);
    const int W = 640, H = 480;
    std::string whole = (dir / "window.png").string(), canvas = (dir / "canvas.png").string();
    ViewerRun w = viewer("'" + input + "' --step " + std::to_string(step) + " --screenshot '" +
                         whole + "' --size 640x480");
    ASSERT_EQ(w.code, 0) << w.out;
    ViewerRun c = viewer("'" + input + "' --step " + std::to_string(step) + " --screenshot '" +
                         canvas + "' --canvas-only --size 640x480");
    ASSERT_EQ(c.code, 0) << c.out;
    Image win, img;
    ASSERT_TRUE(win.load(whole));
    ASSERT_TRUE(img.load(canvas));
    EXPECT_EQ(img.w, W);
    EXPECT_EQ(img.h, H);
    // The detector sees the panels of the window shot; the canvas alone has none.
    EXPECT_GT(panelPixels(win), size_t(W * H / 10));
    EXPECT_EQ(panelPixels(img), 0u);
    // The corners are background (no panel, no find box), the water where the camera says.
    for (auto [x, y] : {std::pair{1, 1}, {W - 2, 1}, {1, H - 2}, {W - 2, H - 2}})
        EXPECT_TRUE(close(img.at(x, y), palette::kBackground, 2)) << "corner " << x << "," << y;
    Camera cam = exportView(m, Rect{0, 0, double(W), double(H)});
    const auto& v = m.polygon().vertices;
    const Triangle& t = m.trace().triangles[0];  // flooded first, not by the current event
    bool water = false;                          // away from the centroid's label and the edges
    for (auto [a, b, c] : {std::tuple{0.6, 0.2, 0.2}, {0.2, 0.6, 0.2}, {0.2, 0.2, 0.6}}) {
        Vec2 s = cam.toScreen({a * v[t[0]].x + b * v[t[1]].x + c * v[t[2]].x,
                               a * v[t[0]].y + b * v[t[1]].y + c * v[t[2]].y});
        water |= close(img.at(int(s.x), int(s.y)), palette::kWater, 6);
    }
    EXPECT_TRUE(water) << "water inside triangle 0";
    Vec2 left = cam.toScreen(v[m.state().fingers.left]);
    bool found = false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            found |= close(img.at(int(left.x) + dx, int(left.y) + dy), palette::kLeft, 6);
    EXPECT_TRUE(found) << "Left marker at " << left.x << "," << left.y;
}

TEST(ExportGui, CaptionIsABandUnderTheCanvas) {
    NEED_DISPLAY();
    fs::path dir = scratch("caption");
    std::string input = squareWithHole(dir);
    Model m;
    m.open(input);
    uint32_t step = middleStep(input);
    std::string out = (dir / "captioned.png").string();
    ViewerRun c = viewer("'" + input + "' --step " + std::to_string(step) + " --screenshot '" +
                         out + "' --canvas-only --caption --size 800x500");
    ASSERT_EQ(c.code, 0) << c.out;
    Image img;
    ASSERT_TRUE(img.load(out));
    // The head "Step N  Action" in the action's colour, in the bottom rows only.
    Rgba head = palette::action(m.trace().events[step - 1].action);
    int lowest = img.h, headPixels = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < 200; ++x)
            if (close(img.at(x, y), head, 1)) lowest = std::min(lowest, y), ++headPixels;
    EXPECT_GT(headPixels, 20);
    EXPECT_GT(lowest, img.h * 3 / 4) << "the caption is under the canvas";
    // The narration's text colour to the right of the head.
    int text = 0;
    for (int y = img.h * 3 / 4; y < img.h; ++y)
        for (int x = 200; x < img.w; ++x) text += close(img.at(x, y), palette::kBoundary, 1);
    EXPECT_GT(text, 50);
}

TEST(ExportGui, SvgIsWellFormedWithATriangleElementPerTriangle) {
    NEED_DISPLAY();
    fs::path dir = scratch("svg");
    std::string input = squareWithHole(dir);
    Model m;
    m.open(input);
    uint32_t step = middleStep(input);
    m.seek(step);
    std::string out = (dir / "canvas.svg").string();
    ViewerRun c = viewer("'" + input + "' --step " + std::to_string(step) + " --screenshot '" +
                         out + "' --canvas-only --caption --size 800x600");
    ASSERT_EQ(c.code, 0) << c.out;
    // Debian's Python parses it: well-formed XML, and counts the triangle elements.
    std::string py =
        "/usr/bin/python3 -c \"import sys, xml.etree.ElementTree as E; r = "
        "E.parse(sys.argv[1]).getroot(); "
        "p = [e for e in r.iter('{http://www.w3.org/2000/svg}polygon')]; "
        "print(r.get('width'), r.get('height'), len(p), sum(e.get('class') == 'current' for e in "
        "p))\" '" +
        out + "' 2>&1";
    FILE* pipe = popen(py.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char buf[512] = "";
    size_t n = fread(buf, 1, sizeof buf - 1, pipe);
    buf[n] = 0;
    int rc = pclose(pipe);
    ASSERT_EQ(WEXITSTATUS(rc), 0) << "not well-formed XML: " << buf;
    std::string want = "800 600 " + std::to_string(m.state().triangleCount) + " " +
                       std::to_string(m.currentEvent()->triangleCount) + "\n";
    EXPECT_EQ(std::string(buf), want);
}

#ifdef FLOOD_GIF
TEST(ExportGui, GifHasAFramePerExportedStep) {
    NEED_DISPLAY();
    fs::path dir = scratch("gif");
    std::string input = squareWithHole(dir);
    Model m;
    m.open(input);
    ASSERT_GE(m.steps(), 7u);
    std::string out = (dir / "flood.gif").string();
    // Steps 1, 4 and the range's end 6: three frames.
    ViewerRun c = viewer("'" + input + "' --export-gif '" + out +
                         "' --steps 1:6 --every 3 --fps 4 --caption --size 320x240");
    ASSERT_EQ(c.code, 0) << c.out;
    int err = 0;
    GifFileType* g = DGifOpenFileName(out.c_str(), &err);
    ASSERT_NE(g, nullptr) << GifErrorString(err);
    ASSERT_EQ(DGifSlurp(g), GIF_OK) << GifErrorString(g->Error);
    EXPECT_EQ(g->ImageCount, 3);
    EXPECT_EQ(size_t(g->ImageCount), exportSteps(1, 6, 3, m.steps()).size());
    EXPECT_EQ(g->SWidth, 320);
    EXPECT_EQ(g->SHeight, 240);
    GraphicsControlBlock gcb;
    ASSERT_EQ(DGifSavedExtensionToGCB(g, 0, &gcb), GIF_OK);
    EXPECT_EQ(gcb.DelayTime, 25);  // 4 frames a second
    // The flat fills are in the palette exactly: the background and the water.
    bool background = false, water = false;
    for (int i = 0; i < g->SColorMap->ColorCount; ++i) {
        GifColorType c = g->SColorMap->Colors[i];
        Rgba colour{c.Red, c.Green, c.Blue, 255};
        background |= close(colour, palette::kBackground, 0);
        water |= close(colour, palette::kWater, 0);
    }
    EXPECT_TRUE(background);
    EXPECT_TRUE(water);
    DGifCloseFile(g, &err);
    EXPECT_NE(c.out.find("3 frames"), std::string::npos) << c.out;
}
#endif

TEST(ExportGui, PngSequenceHasAFilePerExportedStep) {
    NEED_DISPLAY();
    fs::path dir = scratch("seq");
    std::string input = squareWithHole(dir);
    fs::path frames = dir / "frames";
    ViewerRun c = viewer("'" + input + "' --export-png-dir '" + frames.string() +
                         "' --steps 0:5 --every 2 --size 200x150");
    ASSERT_EQ(c.code, 0) << c.out;
    // Steps 0, 2, 4 and 5.
    std::vector<std::string> names;
    for (auto& e : fs::directory_iterator(frames)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"frame-0000.png", "frame-0001.png", "frame-0002.png",
                                               "frame-0003.png"}));
    Image a, b;
    ASSERT_TRUE(a.load((frames / "frame-0000.png").string()));
    ASSERT_TRUE(b.load((frames / "frame-0003.png").string()));
    EXPECT_EQ(a.w, 200);
    EXPECT_EQ(a.h, 150);
    EXPECT_NE(a.px, b.px) << "step 0 and step 5 look different";
}

TEST(ExportGui, UnwritablePathExits8AndSaysWhy) {
    NEED_DISPLAY();
    fs::path dir = scratch("unwritable");
    std::string input = squareWithHole(dir);
    std::string missing = (dir / "no-such-dir").string();
    struct Case {
        std::string args, path;
    } cases[] = {
        {"--screenshot '" + missing + "/a.png' --canvas-only", missing + "/a.png"},
        {"--screenshot '" + missing + "/a.png'", missing + "/a.png"},  // the window shot too
        {"--screenshot '" + missing + "/a.svg'", missing + "/a.svg"},
        {"--export-png-dir '" + missing + "/deeper/frames'", missing + "/deeper/frames"},
#ifdef FLOOD_GIF
        {"--export-gif '" + missing + "/a.gif' --steps 0:2", missing + "/a.gif"},
#endif
    };
    for (const Case& k : cases) {
        ViewerRun r = viewer("'" + input + "' " + k.args + " --size 160x120");
        EXPECT_EQ(r.code, 8) << k.args << "\n" << r.out;
        EXPECT_NE(r.out.find(k.path), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("cannot write"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("No such file or directory"), std::string::npos) << r.out;
    }
    EXPECT_FALSE(fs::exists(missing));
}

// Every writer of the viewer against the files an output can hurt (issue 25; the command
// line's are in tests/cli/special_files_test.cpp): through a symbolic link the target is
// written and keeps its mode, the link stays; a FIFO and a device are written in place; a
// folder that cannot be written is exit 8 naming OUT, nothing left in it.
TEST(ExportGui, EveryWriterAgainstSpecialFiles) {
    NEED_DISPLAY();
    fs::path dir = scratch("special");
    std::string input = squareWithHole(dir);
    struct Writer {
        std::string option, ext;
    };
    std::vector<Writer> writers = {
        {"--screenshot", ".png"}, {"--screenshot", ".svg"}, {"--canvas-only --screenshot", ".png"}};
#ifdef FLOOD_GIF
    writers.push_back({"--steps 0:2 --export-gif", ".gif"});
#endif
    const fs::path fifo = dir / "fifo", got = dir / "got";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
    fs::path ro = dir / "ro";
    fs::create_directories(ro);
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    const fs::path unwritable = access(ro.c_str(), W_OK) == 0 ? fs::path("/proc") : ro;
    for (const Writer& w : writers) {
        SCOPED_TRACE(w.option + " OUT" + w.ext);
        const std::string run = "'" + input + "' --size 160x120 " + w.option + " ";
        const fs::path real = dir / ("real-" + std::to_string(&w - writers.data()));
        fs::create_directories(real);
        const fs::path target = real / ("target" + w.ext), link = dir / ("link" + w.ext);
        { std::ofstream(target) << "old"; }
        ASSERT_EQ(chmod(target.c_str(), 0600), 0);
        fs::remove(link);
        fs::create_symlink(real.filename() / target.filename(), link);
        ViewerRun r = viewer(run + "'" + link.string() + "'");
        EXPECT_EQ(r.code, 0) << r.out;
        EXPECT_TRUE(fs::is_symlink(link));
        EXPECT_GT(fs::file_size(target), 10u);
        struct stat st;
        ASSERT_EQ(stat(target.c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 07777, 0600u);
        EXPECT_EQ(fs::directory_iterator(real)->path(), target) << "a temporary left";
        r = viewer(run + "/dev/null");
        EXPECT_EQ(r.code, 0) << r.out;
        // A FIFO: its reader gets the file (the format is chosen by OUT's name: a link to it).
        const fs::path toFifo = dir / ("to-fifo" + w.ext);
        fs::remove(toFifo);
        fs::create_symlink(fifo, toFifo);
        fs::remove(got);
        std::string cmd = "cat '" + fifo.string() + "' > '" + got.string() + "' & '" +
                          FLOOD_VIEWER + "' " + run + "'" + toFifo.string() + "' 2>&1; wait";
        FILE* p = popen(cmd.c_str(), "r");
        ASSERT_NE(p, nullptr);
        char buf[256];
        while (fgets(buf, sizeof buf, p)) {
        }
        int status = pclose(p);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
        EXPECT_GT(fs::file_size(got), 10u);
        EXPECT_TRUE(fs::is_fifo(fifo));
        const std::string out = (unwritable / ("new" + w.ext)).string();
        r = viewer(run + "'" + out + "'");
        EXPECT_EQ(r.code, 8) << r.out;
        EXPECT_NE(r.out.find(out + ": cannot write"), std::string::npos) << r.out;
    }
    fs::permissions(ro, fs::perms::owner_all);
    EXPECT_TRUE(fs::is_empty(ro));
}

TEST(ExportGui, BadExportOptionsAreUsageErrors) {
    fs::path dir = scratch("usage");
    std::string input = squareWithHole(dir);
    for (const char* bad :
         {"--steps 0:3", "--export-gif x.gif --steps 3:1", "--export-gif x.gif --every 0",
          "--export-gif x.gif --fps 100", "--canvas-only", "--caption --screenshot x.png"}) {
        ViewerRun r = viewer("'" + input + "' " + bad);
        EXPECT_EQ(r.code, 2) << bad << "\n" << r.out;
    }
    if (hasDisplay()) {  // past the flood's end: known once the file is open
        ViewerRun r = viewer("'" + input + "' --export-png-dir '" + (dir / "f").string() +
                             "' --steps 0:9999");
        EXPECT_EQ(r.code, 2) << r.out;
        EXPECT_NE(r.out.find("steps (0.."), std::string::npos) << r.out;
    }
}

// Exports follow the theme: with --theme light the canvas-only PNG's ground and water, the
// SVG's background and dry land, and the GIF's palette are the light palette's; with --theme
// dark the dark one's (named explicitly: without it the viewer takes the last theme chosen).
TEST(ExportGui, ExportsUseTheTheme) {
    NEED_DISPLAY();
    fs::path dir = scratch("theme");
    std::string input = squareWithHole(dir);
    Model m;
    m.open(input);
    const uint32_t step = middleStep(input);
    ASSERT_GT(step, 0u);
    m.seek(step);
    const int W = 480, H = 360;
    Camera cam = exportView(m, Rect{0, 0, double(W), double(H)});
    const auto& v = m.polygon().vertices;
    const Triangle& t = m.trace().triangles[0];  // flooded, not by the current event
    const Vec2 inWater = cam.toScreen({0.6 * v[t[0]].x + 0.2 * v[t[1]].x + 0.2 * v[t[2]].x,
                                       0.6 * v[t[0]].y + 0.2 * v[t[1]].y + 0.2 * v[t[2]].y});
    // The fill of the first element whose tag starts with `element` and holds `attribute`,
    // in whatever order the writer puts the attributes.
    auto svgFill = [](const std::string& svg, const std::string& element,
                      const std::string& attribute = "") {
        for (size_t at = svg.find(element); at != std::string::npos;
             at = svg.find(element, at + 1)) {
            const std::string tag = svg.substr(at, svg.find('>', at) - at);
            if (tag.find(attribute) == std::string::npos) continue;
            size_t fill = tag.find("fill=\"#");
            return fill == std::string::npos ? std::string("(no fill)") : tag.substr(fill + 6, 7);
        }
        return std::string("(no ") + element + " " + attribute + ")";
    };
    auto hex = [](Rgba c) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
        return std::string(buf);
    };
    for (Theme theme : {Theme::Light, Theme::Dark}) {
        const std::string name = palette::themeName(theme);
        SCOPED_TRACE(name);
        const palette::Colours& want = theme == Theme::Light ? palette::kLight : palette::kDark;
        const std::string args = "'" + input + "' --theme " + name + " --step " +
                                 std::to_string(step) + " --size " + std::to_string(W) + "x" +
                                 std::to_string(H);
        const std::string png = (dir / (name + ".png")).string(),
                          svg = (dir / (name + ".svg")).string();
        ViewerRun r = viewer(args + " --canvas-only --screenshot '" + png + "'");
        ASSERT_EQ(r.code, 0) << r.out;
        Image img;
        ASSERT_TRUE(img.load(png));
        for (auto [x, y] : {std::pair{1, 1}, {W - 2, H - 2}})
            EXPECT_TRUE(close(img.at(x, y), want.background, 2)) << "corner " << x << "," << y;
        bool water = false;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                water |= close(img.at(int(inWater.x) + dx, int(inWater.y) + dy), want.water, 6);
        EXPECT_TRUE(water) << "the theme's water inside triangle 0";
        r = viewer(args + " --screenshot '" + svg + "'");
        ASSERT_EQ(r.code, 0) << r.out;
        std::ifstream in(svg);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        EXPECT_EQ(svgFill(text, "<rect width=\"100%\" height=\"100%\""), hex(want.background));
        EXPECT_EQ(svgFill(text, "<path", "fill-rule=\"evenodd\""), hex(want.polygonFill));
#ifdef FLOOD_GIF
        const std::string gifPath = (dir / (name + ".gif")).string();
        r = viewer("'" + input + "' --theme " + name + " --export-gif '" + gifPath +
                   "' --steps 0:2 --size 160x120");
        ASSERT_EQ(r.code, 0) << r.out;
        int err = 0;
        GifFileType* g = DGifOpenFileName(gifPath.c_str(), &err);
        ASSERT_NE(g, nullptr) << GifErrorString(err);
        ASSERT_EQ(DGifSlurp(g), GIF_OK) << GifErrorString(g->Error);
        bool background = false;
        for (int i = 0; i < g->SColorMap->ColorCount; ++i) {
            GifColorType c = g->SColorMap->Colors[i];
            background |= close(Rgba{c.Red, c.Green, c.Blue, 255}, want.background, 0);
        }
        EXPECT_TRUE(background) << "the theme's background in the GIF's palette";
        DGifCloseFile(g, &err);
#endif
    }
}

}  // namespace
