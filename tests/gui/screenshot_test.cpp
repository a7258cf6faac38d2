// GUI test: renders a known polygon with `flood-viewer --screenshot` and checks pixels whose
// colours are known from the palette: background outside the polygon, water inside a flooded
// triangle, and the Left marker at the Left vertex. Positions come from the same layout and
// camera fit the viewer uses. A second shot draws the last step first and then steps back:
// the triangles cut after that step must be dry land again (the GPU draws a prefix of the
// flood-order triangles, which must shrink). Exit 77 (skipped) without a display, except in CI.
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <sys/wait.h>

#include "flood/teach/decision_tree.h"
#include "gui_test_display.h"
#include "model.h"
#include "palette.h"
#include "presenter.h"
#include "viewer_run.h"

using namespace flood;
using namespace flood::view;
using flood::view::testing::failWith;
using flood::view::testing::overlaps;
using flood::view::testing::runViewer;
using flood::view::testing::ViewerRun;

namespace {

struct Image {
    int w = 0, h = 0;
    unsigned char* px = nullptr;
    Rgba at(int x, int y) const {
        const unsigned char* p = px + (size_t(y) * w + x) * 4;
        return {p[0], p[1], p[2], p[3]};
    }
};

bool close(Rgba a, Rgba b, int tol) {
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

// True if a pixel within `radius` of (x, y) has `want`: anti-aliasing and rounding of the
// projected position move a colour by a pixel, never more.
bool near(const Image& img, Vec2 p, Rgba want, int radius, Rgba* seen) {
    int cx = int(p.x), cy = int(p.y);
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            int x = cx + dx, y = cy + dy;
            if (x < 0 || y < 0 || x >= img.w || y >= img.h) continue;
            if (close(img.at(x, y), want, 6)) return true;
        }
    if (seen && cx >= 0 && cy >= 0 && cx < img.w && cy < img.h) *seen = img.at(cx, cy);
    return false;
}

int fail(const char* what, Vec2 p, Rgba want, Rgba seen) {
    std::fprintf(stderr, "FAIL: %s at (%.1f, %.1f): want %d,%d,%d, got %d,%d,%d\n", what, p.x, p.y,
                 want.r, want.g, want.b, seen.r, seen.g, seen.b);
    return 1;
}

// Runs flood-viewer headless at `steps` (one or more --step options) into `out`, loads it.
bool shoot(const std::string& input, const std::string& steps, const std::string& out, int W, int H,
           Image& img, int wantExit = 0) {
    std::remove(out.c_str());
    std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + input + "' " + steps +
                      " --screenshot '" + out + "' --size " + std::to_string(W) + "x" +
                      std::to_string(H);
    std::printf("%s\n", cmd.c_str());
    std::fflush(stdout);  // before the child writes to the same stream
    int rc = std::system(cmd.c_str());
    rc = rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    if (rc != wantExit) {
        std::fprintf(stderr, "FAIL: flood-viewer exited with %d, want %d\n", rc, wantExit);
        return false;
    }
    int channels = 0;
    img.px = stbi_load(out.c_str(), &img.w, &img.h, &channels, 4);
    if (!img.px || img.w != W || img.h != H) {
        std::fprintf(stderr, "FAIL: %s is missing or not %dx%d\n", out.c_str(), W, H);
        return false;
    }
    return true;
}

// Probes inside triangle t, away from its centroid label and its edges.
bool probeTriangle(const Model& model, uint32_t t, const Image& img, Rgba want, Vec2& probe,
                   Rgba& seen) {
    const auto& v = model.polygon().vertices;
    const Triangle& tri = model.trace().triangles[t];
    Point a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
    for (auto [wa, wb, wc] : {std::tuple{0.6, 0.2, 0.2}, {0.2, 0.6, 0.2}, {0.2, 0.2, 0.6}}) {
        probe = model.camera().toScreen(
            {wa * a.x + wb * b.x + wc * c.x, wa * a.y + wb * b.y + wc * c.y});
        if (near(img, probe, want, 1, &seen)) return true;
    }
    return false;
}

// The model is at the step shown; `back` shots also check that later triangles are dry.
int checkShot(const Model& model, const Layout& layout, const Image& img, bool back) {
    const Camera& cam = model.camera();
    const char* shot = back ? " (after stepping back)" : "";
    Rgba seen;
    Vec2 probe;
    int failures = 0;
    Vec2 bg{layout.canvas.x + 0.02 * layout.canvas.w, layout.canvas.y + layout.canvas.h / 2};
    if (!near(img, bg, palette::kBackground, 0, &seen))
        failures +=
            fail((std::string("background") + shot).c_str(), bg, palette::kBackground, seen);

    // Water: inside an earlier (not emphasised) flooded triangle.
    const Event* e = model.currentEvent();
    bool water = false;
    for (uint32_t t = 0; t < model.state().triangleCount && !water; ++t)
        if (t < e->firstTriangle || t >= e->firstTriangle + e->triangleCount)
            water = probeTriangle(model, t, img, palette::kWater, probe, seen);
    if (!water)
        failures += fail((std::string("water in a flooded triangle") + shot).c_str(), probe,
                         palette::kWater, seen);

    // Dry land: the largest triangle not cut yet is polygon fill, not water.
    const auto& tris = model.trace().triangles;
    const auto& v = model.polygon().vertices;
    int64_t dry = -1;
    double best = 0;
    for (uint32_t t = model.state().triangleCount; t < tris.size(); ++t) {
        Point a = v[tris[t][0]], b = v[tris[t][1]], c = v[tris[t][2]];
        double area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        if (area > best) best = area, dry = t;
    }
    if (back && dry < 0) {
        std::fprintf(stderr, "FAIL: the test step leaves no triangle to cut\n");
        ++failures;
    }
    if (dry >= 0 && !probeTriangle(model, uint32_t(dry), img, palette::kPolygonFill, probe, seen))
        failures += fail((std::string("dry land in an uncut triangle") + shot).c_str(), probe,
                         palette::kPolygonFill, seen);

    Vec2 left = cam.toScreen(v[model.state().fingers.left]);
    if (!near(img, left, palette::kLeft, 1, &seen))
        failures += fail((std::string("Left marker") + shot).c_str(), left, palette::kLeft, seen);
    return failures;
}

// A 10^5-vertex face (`flood generate circle-jagged 100000`: spikes alternating between radii
// 0.2-0.7 and 0.8-1 around the origin) must read as a shape at the fit: the disc inside radius
// 0.2 is dry land, the plane beyond radius 1 background, and the spiked band mostly not
// vertex-class dots (unthinned, they paved it). Samples on a pixel grid, classified by radius.
bool shootPrinted(const std::string& input, const std::string& args, const std::string& out, int W,
                  int H, Image& img, std::map<std::string, Rect>& layout, bool exact, int wantExit);

int checkDenseFace(const std::string& dir, int W, int H, const Layout& layout) {
    std::string input = dir + "/screenshot-test-dense.json";
    std::string gen =
        std::string("'") + FLOOD_CLI + "' generate circle-jagged 100000 -o '" + input + "'";
    if (std::system(gen.c_str()) != 0) {
        std::fprintf(stderr, "FAIL: %s\n", gen.c_str());
        return 1;
    }
    Model model;
    model.open(input);
    Image img;
    std::map<std::string, Rect> printed;
    if (!shootPrinted(input, "--step 0", dir + "/screenshot-test-dense.png", W, H, img, printed,
                      true, 0))
        return 1;
    // The viewer fits clear of the find and Edit boxes (view_fit.h): the same fit here.
    model.fitCamera(layout.canvas, {printed["find-box"], printed["edit-box"]});
    const Rgba dots[] = {palette::kRegular, palette::kBottom, palette::kSag, palette::kTop,
                         palette::kCeiling};
    int inner = 0, innerLand = 0, band = 0, bandDots = 0, outer = 0, outerBackground = 0;
    const Rect& c = layout.canvas;
    for (double y = c.y + 60; y < c.y + c.h - 4; y += 3)  // below the find box
        for (double x = c.x + 4; x < c.x + c.w - 4; x += 3) {
            Point w = model.camera().toWorld({x, y});
            double r = std::hypot(w.x, w.y);
            Rgba px = img.at(int(x), int(y));
            if (r < 0.15) {
                ++inner, innerLand += close(px, palette::kPolygonFill, 6);
            } else if ((r > 0.25 && r < 0.65) || (r > 0.82 && r < 0.97)) {
                ++band;
                for (Rgba d : dots) bandDots += close(px, d, 6);
            } else if (r > 1.1) {
                ++outer, outerBackground += close(px, palette::kBackground, 6);
            }
        }
    stbi_image_free(img.px);
    std::printf("dense face: land %d/%d inside, dots %d/%d in the band, background %d/%d outside\n",
                innerLand, inner, bandDots, band, outerBackground, outer);
    int failures = 0;
    if (inner < 50 || innerLand < 0.95 * inner) {
        std::fprintf(stderr, "FAIL: dense face: the inner disc is not dry land\n");
        ++failures;
    }
    if (band < 500 || bandDots > 0.4 * band) {
        std::fprintf(stderr, "FAIL: dense face: vertex dots pave the spiked band (a smear)\n");
        ++failures;
    }
    if (outer < 500 || outerBackground < 0.95 * outer) {
        std::fprintf(stderr, "FAIL: dense face: the outside is not background\n");
        ++failures;
    }
    return failures;
}

// ---- presenter mode: --scale, --presenter, --theme and --print-layout ----------------------

// Runs flood-viewer with `args` into `out` at W x H and loads it (a picture of any size when
// `exact` is false); `layout` gets its --print-layout lines ("NAME x y w h").
bool shootPrinted(const std::string& input, const std::string& args, const std::string& out, int W,
                  int H, Image& img, std::map<std::string, Rect>& layout, bool exact = true,
                  int wantExit = 0) {
    std::remove(out.c_str());
    std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + input + "' " + args +
                      " --print-layout --screenshot '" + out + "' --size " + std::to_string(W) +
                      "x" + std::to_string(H);
    const ViewerRun run = runViewer(cmd);
    for (const auto& [name, r] : run.layout) layout[name] = r;
    if (run.exitCode != wantExit) {
        std::fprintf(stderr, "FAIL: flood-viewer %s did not exit %d\n", args.c_str(), wantExit);
        return false;
    }
    int channels = 0;
    img.px = stbi_load(out.c_str(), &img.w, &img.h, &channels, 4);
    if (!img.px || (exact && (img.w != W || img.h != H))) {
        std::fprintf(stderr, "FAIL: %s is missing or not %dx%d\n", out.c_str(), W, H);
        return false;
    }
    return true;
}

bool inside(const Rect& r, int W, int H) {
    return r.w > 0 && r.h > 0 && r.x >= 0 && r.y >= 0 && r.x + r.w <= W && r.y + r.h <= H;
}

// Pixels of `r` (clipped to the image) for which `is` holds.
template <class F>
int count(const Image& img, const Rect& r, F is) {
    int n = 0;
    for (int y = std::max(0, int(r.y)); y < std::min(img.h, int(r.y + r.h)); ++y)
        for (int x = std::max(0, int(r.x)); x < std::min(img.w, int(r.x + r.w)); ++x)
            n += is(img.at(x, y));
    return n;
}

double luminance(Rgba c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Tab at 2x on 1024x768 (the presenter view): no toolbar, the caption whole inside the frame with its
// last line above its bottom padding, the action's name in its colour, and the canvas fitted
// to the space left (the Left marker where the presenter layout puts it).
int checkPresenter(const std::string& dir, const std::string& input, Model& model, uint32_t step) {
    const int W = 1024, H = 768;
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--scale 2 --press tab --step " + std::to_string(step),
                      dir + "/screenshot-test-presenter.png", W, H, img, layout))
        return 1;
    int failures = 0;
    const Rect caption = layout["caption"];
    if (layout.count("toolbar-end")) failures += failWith("presenter view drew the toolbar");
    if (!inside(caption, W, H) || caption.h > H / 2 || caption.y + caption.h != H)
        failures += failWith("the caption is not whole at the bottom of the frame");
    // Text is the style's white; the lowest text row must stay clear of the bottom edge.
    int lowest = -1;
    for (int y = int(caption.y); y < int(caption.y + caption.h) && y < H; ++y)
        if (count(img, {caption.x, double(y), caption.w, 1},
                  [](Rgba c) { return luminance(c) > 200; }) > 0)
            lowest = y;
    if (lowest < 0 || lowest > caption.y + caption.h - 8)
        failures +=
            failWith("the caption's text is missing or runs into its bottom edge (lowest row " +
                     std::to_string(lowest) + ")");
    model.seek(step);
    Rgba actionColour = palette::action(model.currentEvent()->action);
    int named = count(img, caption, [&](Rgba c) { return close(c, actionColour, 8); });
    if (named < 40)
        failures += failWith("the action's name is not drawn in its colour in the caption (" +
                             std::to_string(named) + " pixels)");
    model.fitCamera(presenterLayout(W, H, caption.h).canvas);
    Rgba seen;
    Vec2 left = model.camera().toScreen(model.polygon().vertices[model.state().fingers.left]);
    if (!near(img, left, palette::kLeft, 2, &seen))
        failures += fail("presenter Left marker", left, palette::kLeft, seen);
    Vec2 corner{W - 3.0, 3.0};  // where the Events panel is in the normal view
    if (!near(img, corner, palette::kBackground, 0, &seen))
        failures +=
            fail("canvas background where a panel would be", corner, palette::kBackground, seen);
    stbi_image_free(img.px);
    return failures;
}

// The normal view at 2x on 1024x768: the toolbar wraps, so its last button is whole inside
// the frame: a button (mostly the style's blue) with white text, ending where it says.
int checkToolbarAtScale2(const std::string& dir, const std::string& input) {
    const int W = 1024, H = 768;
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--scale 2", dir + "/screenshot-test-scale2.png", W, H, img, layout))
        return 1;
    int failures = 0;
    const Rect b = layout["toolbar-end"];
    if (!inside(b, W, H)) {
        failures += failWith("the toolbar's last button is outside the 1024x768 frame at 2x (" +
                             std::to_string(b.x) + ", " + std::to_string(b.y) + ")");
    } else {
        const int area = int(b.w) * int(b.h);
        int blue = count(img, b, [](Rgba c) { return c.b > c.r + 40; });
        int text = count(img, b, [](Rgba c) { return luminance(c) > 200; });
        if (blue < area / 2 || text < 20)
            failures += failWith("no button drawn at the toolbar's end (" + std::to_string(blue) +
                                 " blue, " + std::to_string(text) + " text pixels of " +
                                 std::to_string(area) + ")");
    }
    stbi_image_free(img.px);
    return failures;
}

// Ctrl+plus three times (150%): the fonts are rebuilt while the viewer runs and the texture
// uploaded again, so the toolbar's last button is taller and still a button with its text.
// F11: the picture is the screen's size, not the window's.
int checkKeys(const std::string& dir, const std::string& input) {
    const int W = 1024, H = 768;
    Image img;
    std::map<std::string, Rect> layout;
    int failures = 0;
    if (!shootPrinted(input, "--press ctrl+plus --press ctrl+plus --press ctrl+plus",
                      dir + "/screenshot-test-zoom.png", W, H, img, layout))
        return 1;
    const Rect b = layout["toolbar-end"];
    const int area = int(b.w) * int(b.h);
    int blue = count(img, b, [](Rgba c) { return c.b > c.r + 40; });
    int text = count(img, b, [](Rgba c) { return luminance(c) > 200; });
    if (!inside(b, W, H) || b.h < 25 || blue < area / 2 || text < 20)
        failures += failWith("after Ctrl+plus x3 the last button is not a 150% button (h " +
                             std::to_string(b.h) + ", " + std::to_string(blue) + " blue, " +
                             std::to_string(text) + " text pixels)");
    stbi_image_free(img.px);
    Image full;
    if (!shootPrinted(input, "--press f11", dir + "/screenshot-test-f11.png", 800, 600, full,
                      layout, false))
        return failures + 1;
    if (full.w == 800 && full.h == 600) failures += failWith("F11 left the window at its size");
    stbi_image_free(full.px);
    return failures;
}

// The light theme: the same probes as the dark shot in the light colours (background,
// water, dry land, Left marker), the boundary drawn dark, the panels light.
int checkLightTheme(const std::string& dir, const std::string& input, Model& model, uint32_t step,
                    const Layout& layout) {
    palette::setTheme(Theme::Light);
    Image img;
    std::map<std::string, Rect> printed;
    int failures = 0;
    if (!shootPrinted(input, "--theme light --step " + std::to_string(step),
                      dir + "/screenshot-test-light.png", int(layout.bottom.w),
                      int(layout.bottom.y + layout.bottom.h), img, printed))
        return 1;
    model.seek(step);
    model.fitCamera(layout.canvas, {printed["find-box"], printed["edit-box"]});
    failures += checkShot(model, layout, img, false);
    if (luminance(palette::kBackground) < 200)
        failures += failWith("the light background is not light");
    Rgba seen;
    // The outer ring's first edge, halfway: the boundary line.
    const auto& v = model.polygon().vertices;
    Vec2 mid = model.camera().toScreen({(v[0].x + v[1].x) / 2, (v[0].y + v[1].y) / 2});
    if (!near(img, mid, palette::kBoundary, 1, &seen) || luminance(palette::kBoundary) > 60)
        failures += fail("dark boundary line", mid, palette::kBoundary, seen);
    Rect panel{layout.right.x + 4, layout.right.y + layout.right.h * 0.7, layout.right.w - 8, 20};
    int light = count(img, panel, [](Rgba c) { return luminance(c) > 180; });
    if (light < panel.w * panel.h * 0.6)
        failures += failWith("the panels are not light in the light theme");
    stbi_image_free(img.px);
    palette::setTheme(Theme::Dark);
    return failures;
}
// A bad value of a presenter option is a usage error (exit 2) naming the option and the
// value, before any window.
int checkPresenterUsage() {
    int failures = 0;
    for (const char* bad : {"--scale 9", "--scale x", "--theme sepia", "--press shift"}) {
        std::string cmd = std::string("'") + FLOOD_VIEWER + "' " + bad + " 2>&1";
        FILE* pipe = popen(cmd.c_str(), "r");
        std::string said;
        char line[512];
        while (pipe && std::fgets(line, sizeof line, pipe)) said += line;
        int rc = pipe ? pclose(pipe) : -1;
        std::string option = std::string(bad).substr(0, std::string(bad).find(' '));
        std::string value = std::string(bad).substr(option.size() + 1);
        if (rc == -1 || !WIFEXITED(rc) || WEXITSTATUS(rc) != 2 ||
            said.find(option) == std::string::npos ||
            said.find("'" + value + "'") == std::string::npos)
            failures += failWith(std::string("flood-viewer ") + bad +
                                 ": want exit 2 naming it, got: " + said);
    }
    return failures;
}

// The predicate inspector (--predicates) draws its rows, and hovering its first row
// (--mouse) rings that test's first argument on the canvas. The window's place is its first
// use's (panel_predicates.cpp) and ImGui's default style at scale 1: title bar 19 px, padding
// 8 px, the header row 17 px; the first row's first line is below that.
int checkInspector(const std::string& input, Model& model, const Layout& layout, int W, int H,
                   const std::string& dir) {
    const Rect& c = layout.canvas;
    const Rect win{c.x + 20, c.y + c.h * 0.55, 640, 300};
    const Rgba ring{80, 220, 255, 255};
    // A step whose first row names a vertex the window does not cover.
    uint32_t step = 0;
    Index arg = kNone;
    for (uint32_t s = 1; s <= model.steps() && !step; ++s) {
        model.seek(s);
        const auto& rows = model.inspection();
        if (rows.empty() || rows[0].args.empty() ||
            rows[0].args[0] >= model.polygon().vertices.size())
            continue;
        Vec2 p = model.camera().toScreen(model.polygon().vertices[rows[0].args[0]]);
        if (!win.contains(p) && c.contains(p)) step = s, arg = rows[0].args[0];
    }
    if (!step) {
        std::fprintf(stderr,
                     "FAIL: inspector: no step whose first predicate names a visible vertex\n");
        return 1;
    }
    model.seek(step);
    Vec2 mouse{win.x + 60, win.y + 19 + 8 + 17 + 6};
    char opts[160];
    std::snprintf(opts, sizeof opts, "--step %u --step %u --predicates --mouse %.0f,%.0f", step,
                  step, mouse.x, mouse.y);
    Image img;
    if (!shoot(input, opts, dir + "/screenshot-test-inspector.png", W, H, img)) return 1;
    int failures = 0;
    // Its rows: text in the first row's line, and more in the rows below it.
    int bright = 0;
    for (int y = int(win.y + 19 + 8 + 17); y < int(win.y + 19 + 8 + 17 + 60); ++y)
        for (int x = int(win.x + 8); x < int(win.x + 400); ++x) {
            Rgba px = img.at(x, y);
            bright += px.r + px.g + px.b > 450;
        }
    if (bright < 40) {
        std::fprintf(stderr, "FAIL: inspector: its rows show no text (%d bright pixels)\n", bright);
        ++failures;
    }
    // The hovered row's argument: a ring of radius 9 around the vertex.
    Vec2 v = model.camera().toScreen(model.polygon().vertices[arg]);
    int onRing = 0;
    for (auto [dx, dy] : {std::pair{9.0, 0.0}, {-9.0, 0.0}, {0.0, 9.0}, {0.0, -9.0}})
        onRing += near(img, {v.x + dx, v.y + dy}, ring, 2, nullptr);
    if (onRing < 3) {
        Rgba seen = img.at(int(v.x + 9), int(v.y));
        failures += fail("inspector: the hovered row's argument ringed on the canvas",
                         {v.x + 9, v.y}, ring, seen);
    }
    stbi_image_free(img.px);
    std::printf(
        "inspector: step %u, vertex %u ringed (%d of 4 probes), %d bright pixels in its rows\n",
        step, arg, onRing, bright);
    return failures;
}

// The invariant lane of an invalid input flooded anyway: a tick at each violation the model
// finds, where the timeline puts that step, and none elsewhere. The strip's place is found on
// the picture (the lane's own colour), so a scrollbar in the timeline does not matter.
int checkInvariantLane(const std::string& dir, int W, int H, const Layout& layout) {
    std::string input =
        std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid/hole-crossing-outer.json";
    Model model;
    model.open(input);
    model.waitForInvariants();
    const std::vector<Violation>& found = model.violations();
    if (found.empty() || model.forbiddenStep() == 0 ||
        found.front().step >= model.forbiddenStep()) {
        std::fprintf(stderr, "FAIL: lane: %s should break an invariant before its forbidden step\n",
                     input.c_str());
        return 1;
    }
    Image img;
    std::string step = "--step " + std::to_string(model.forbiddenStep());
    if (!shoot(input, step, dir + "/screenshot-test-lane.png", W, H, img, model.exitCode()))
        return 1;
    // The tick's orange (255, 120, 40), also where anti-aliasing blends it half into the lane;
    // not the first error's red (its green stays low).
    const Rgba laneColour{34, 30, 40, 255};
    auto orange = [](Rgba p) { return p.r - p.b > 80 && p.g > 55 && p.g < 140; };
    // The lane: the middle of the timeline's rows with the most pixels of its colour (its top
    // row meets the current step's tick).
    std::vector<int> perRow(size_t(H), 0);
    int best = 0;
    for (int y = int(layout.bottom.y); y < H; ++y) {
        for (int x = 0; x < W; ++x) perRow[size_t(y)] += close(img.at(x, y), laneColour, 2);
        best = std::max(best, perRow[size_t(y)]);
    }
    int top = -1, bottom = -1;
    for (int y = int(layout.bottom.y); y < H; ++y)
        if (perRow[size_t(y)] >= best * 9 / 10) bottom = y, top = top < 0 ? y : top;
    int laneY = (top + bottom) / 2;
    int x0 = W, x1 = -1;
    std::vector<int> ticks;
    for (int x = 0; x < W && laneY >= 0; ++x) {
        Rgba px = img.at(x, laneY);
        bool lane = close(px, laneColour, 2), tick = orange(px),
             error = close(px, palette::kCulprit, 6);
        if (lane || tick || error) x0 = std::min(x0, x), x1 = std::max(x1, x);
        if (tick) ticks.push_back(x);
    }
    int failures = 0;
    if (best < W / 2) {
        std::fprintf(stderr, "FAIL: lane: no invariant lane in the timeline\n");
        stbi_image_free(img.px);
        return 1;
    }
    // A step sits at the right edge of its event's mark: x0 + step * width / events.
    const double width = x1 - x0 + 1;
    auto xOf = [&](uint32_t s) { return x0 + s * width / model.steps(); };
    for (const Violation& v : found) {
        bool seen = false;
        for (int t : ticks) seen |= std::abs(t - xOf(v.step)) <= 2;
        if (!seen) {
            std::fprintf(stderr, "FAIL: lane: no tick for the violation at step %u (x %.1f)\n",
                         v.step, xOf(v.step));
            ++failures;
        }
    }
    for (int t : ticks) {
        bool expected = false;
        for (const Violation& v : found) expected |= std::abs(t - xOf(v.step)) <= 3;
        if (!expected) {
            std::fprintf(stderr, "FAIL: lane: a tick at x %d where no invariant breaks\n", t);
            ++failures;
            break;
        }
    }
    std::printf(
        "lane: row %d, x %d..%d, %zu violations (first at step %u, forbidden at %u), %zu tick "
        "pixels\n",
        laneY, x0, x1, found.size(), found.front().step, model.forbiddenStep(), ticks.size());
    stbi_image_free(img.px);
    return failures;
}

// WCAG's contrast ratio of two colours (1 to 21; 3 is its floor for graphics such as lines).
double contrast(Rgba a, Rgba b) {
    auto lum = [](Rgba c) {
        auto lin = [](uint8_t v) {
            double s = v / 255.0;
            return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
        };
        return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
    };
    double x = lum(a) + 0.05, y = lum(b) + 0.05;
    return std::max(x, y) / std::min(x, y);
}

// The Decision panel's yes/no answers in each theme: at a step whose path answers both yes
// and no, both colours are drawn in the panel and stand out from its background (read from
// the picture: its most common colour) at 3:1 or more; "no" is never the forbidden red.
int checkDecisionAnswers(const std::string& dir) {
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    Model model;
    model.open(input);
    const DecisionTree& tree = decisionTree();
    // The step whose lit path has the most answered tests, at least one of each answer.
    uint32_t step = 0;
    size_t best = 0;
    for (uint32_t s = 1; s <= model.steps(); ++s) {
        model.seek(s);
        size_t yes = 0, no = 0;
        for (const PathStep& p : decisionPath(*model.currentEvent()).steps) {
            const DecisionNode& n = tree.nodes[size_t(p.node)];
            if (n.kind != DecisionNode::Kind::Action && n.yes != n.no && n.yes >= 0 && n.no >= 0)
                (p.answer ? yes : no) += 1;
        }
        if (yes && no && yes + no > best) best = yes + no, step = s;
    }
    if (!step) return failWith("decision answers: no step answers both yes and no");
    const int W = 1000, H = 700;
    const Rect col = computeLayout(W, H, 1).left;
    const Rect panel{col.x, col.y + col.h * 0.38, col.w, col.h * 0.27};
    int failures = 0;
    for (Theme theme : {Theme::Light, Theme::Dark}) {
        palette::setTheme(theme);
        const std::string name = palette::themeName(theme);
        Image img;
        if (!shoot(input, "--theme " + name + " --step " + std::to_string(step),
                   dir + "/screenshot-test-decision-" + name + ".png", W, H, img))
            return failures + 1;
        std::map<uint32_t, int> seen;
        for (int y = int(panel.y); y < int(panel.y + panel.h); ++y)
            for (int x = int(panel.x); x < int(panel.x + panel.w); ++x) {
                Rgba c = img.at(x, y);
                ++seen[uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b];
            }
        uint32_t mode = 0;
        int most = 0;
        for (auto [c, n] : seen)
            if (n > most) most = n, mode = c;
        const Rgba background{uint8_t(mode >> 16), uint8_t(mode >> 8), uint8_t(mode), 255};
        const palette::TreeColours& colours = palette::tree();
        for (auto [what, c] : {std::pair{"yes", colours.yes}, {"no", colours.no}}) {
            int drawn = count(img, panel, [&](Rgba p) { return close(p, c, 8); });
            double ratio = contrast(c, background);
            std::printf("decision %s theme, step %u: '%s' %d pixels, contrast %.2f with %d,%d,%d\n",
                        name.c_str(), step, what, drawn, ratio, background.r, background.g,
                        background.b);
            if (drawn < 8 || ratio < 3)
                failures += failWith("the " + name + " theme's '" + what +
                                     "' answers are missing or too close to the panel");
        }
        if (close(colours.no, palette::kCulprit, 100) ||
            close(colours.no, palette::action(Action::Forbidden), 100) ||
            colours.no.r >= colours.no.b)
            failures += failWith("the " + name + " theme's 'no' is the forbidden red");
        stbi_image_free(img.px);
    }
    palette::setTheme(Theme::Dark);
    return failures;
}
// ---- the error view on real faces (issue 26 §3), at the default 1280x800 --------------------

const int kW = 1280, kH = 800;

std::string writeFace(const std::string& dir, const std::string& name, const char* json) {
    std::string path = dir + "/" + name + ".json";
    std::ofstream(path) << json << "\n";
    return path;
}

bool within(const Rect& r, const Rect& outer) {
    return r.x >= outer.x - 0.5 && r.y >= outer.y - 0.5 && r.x + r.w <= outer.x + outer.w + 0.5 &&
           r.y + r.h <= outer.y + outer.h + 0.5;
}

// A square with three separate bow-tie holes: the findings panel under the canvas shows every
// finding whole (three invalid-input rows, each inside the panel and the picture, with its red
// tag and its text), not a strip cut after its third line. F8 then frames the second finding:
// its crossing is ringed where the model puts it, its row is the one lit.
int checkFindingsPanel(const std::string& dir) {
    const std::string input = writeFace(dir, "screenshot-test-three-bowties", R"({"type": "Polygon",
        "coordinates": [[[0,0],[30,0],[30,10],[0,10],[0,0]], [[2,2],[6,6],[6,2],[2,6],[2,2]],
        [[12,2],[16,6],[16,2],[12,6],[12,2]], [[22,2],[26,6],[26,2],[22,6],[22,2]]]})");
    Model model;
    model.open(input);
    size_t invalid = 0;
    for (const Finding& f : model.findings()) invalid += f.kind == Verdict::Invalid;
    if (invalid != 3)
        return failWith("three-bowties: want 3 validation findings, the model has " +
                        std::to_string(invalid));
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--show-error --press f8", dir + "/screenshot-test-findings.png", kW,
                      kH, img, layout, true, 4))
        return 1;
    int failures = 0;
    const Rect panel = layout["findings"];
    if (!inside(panel, kW, kH) || panel.h < 60)
        failures += failWith("no findings panel under the canvas");
    const Rect canvas = layout["canvas"];
    if (panel.y < canvas.y + canvas.h - 0.5)
        failures += failWith("the findings panel covers the canvas");
    for (size_t i = 0; i < model.findings().size(); ++i) {
        const std::string name = "finding-" + std::to_string(i);
        if (!layout.count(name)) {
            failures += failWith(name + ": no row in the findings panel");
            continue;
        }
        const Rect row = layout[name];
        if (!within(row, panel) || !inside(row, kW, kH))
            failures += failWith(name + ": its row is not whole inside the panel");
        for (size_t j = 0; j < i; ++j)
            if (overlaps(row, layout["finding-" + std::to_string(j)]))
                failures += failWith(name + " overlaps an earlier row");
        int red = count(img, row, [](Rgba c) { return close(c, palette::kCulprit, 40); });
        int text = count(img, row, [](Rgba c) { return luminance(c) > 180; });
        std::printf("findings panel: row %zu at %.0f,%.0f %.0fx%.0f: %d red, %d text pixels\n", i,
                    row.x, row.y, row.w, row.h, red, text);
        if (red < 15 || text < 60)
            failures += failWith(name + ": its tag or its text is not drawn");
        // F8 lit the second row (the current finding): its background is the header blue.
        int blue = count(img, row, [&](Rgba c) { return c.b > c.r + 40 && c.b > 80; });
        if ((i == 1) != (blue > row.w * row.h / 3))
            failures += failWith(name + (i == 1 ? ": F8's finding is not lit" : ": lit, not F8's"));
    }
    // The second finding framed: its crossing (14, 4) ringed in the error colour.
    model.setViewport(canvas);
    model.showError();
    model.nextFinding(+1);
    Point x;
    Rgba seen;
    if (model.currentFinding() != 1 || !model.errorPoint(x))
        failures += failWith("the model does not go to the second finding");
    else if (Vec2 at = model.camera().toScreen(x); !near(img, at, palette::kCulprit, 2, &seen))
        failures += fail("F8: the second finding's crossing", at, palette::kCulprit, seen);
    stbi_image_free(img.px);
    return failures;
}

// A 1000 x 1000 face whose only trouble is a 4 x 4 hole lying outside it, in a notch, 20 above
// the notch's edge (Greenland's tiny culprit hole): E draws thick red on the hole's four edges
// and nowhere on the outer ring, whose notch edge is in view (thin, as context).
int checkTinyHole(const std::string& dir) {
    const std::string input = writeFace(dir, "screenshot-test-tiny-hole", R"({"type": "Polygon",
        "coordinates": [[[0,0],[1000,0],[1000,400],[500,400],[500,600],[1000,600],[1000,1000],
        [0,1000],[0,0]], [[700,420],[704,420],[704,424],[700,424],[700,420]]]})");
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--show-error", dir + "/screenshot-test-tiny-hole.png", kW, kH, img,
                      layout, true, 4))
        return 1;
    Model model;
    model.open(input);
    model.setViewport(layout["canvas"]);
    if (!model.showError()) return failWith("tiny hole: no error view");
    const Camera& cam = model.camera();
    const Polygon& P = model.polygon();
    std::vector<Rect> labels;
    for (auto& [name, r] : layout)
        if (name.rfind("label-", 0) == 0) labels.push_back(r);
    // Culprit-red pixels across a line at its point `p` (direction d), within 7 px each side.
    auto thickness = [&](Point a, Point b, double t) {
        Vec2 sa = cam.toScreen(a), sb = cam.toScreen(b);
        Vec2 p{sa.x + (sb.x - sa.x) * t, sa.y + (sb.y - sa.y) * t};
        double len = std::hypot(sb.x - sa.x, sb.y - sa.y);
        Vec2 n{-(sb.y - sa.y) / len, (sb.x - sa.x) / len};
        int red = 0;
        for (int k = -7; k <= 7; ++k) {
            int x = int(std::lround(p.x + n.x * k)), y = int(std::lround(p.y + n.y * k));
            if (x >= 0 && y >= 0 && x < img.w && y < img.h)
                red += close(img.at(x, y), palette::kCulprit, 30);
        }
        return std::pair{red, p};
    };
    int failures = 0;
    const Ring& hole = P.rings[1];
    for (Index i = 0; i < hole.count; ++i) {
        Point a = P.vertices[hole.first + i], b = P.vertices[hole.first + (i + 1) % hole.count];
        auto [red, p] = thickness(a, b, 0.5);
        if (red < 3)
            failures +=
                failWith("tiny hole: edge " + std::to_string(i) +
                         " of the hole is not thick red (" + std::to_string(red) + " px at " +
                         std::to_string(int(p.x)) + "," + std::to_string(int(p.y)) + ")");
    }
    // The outer ring where it is in view (away from labels): never thick red.
    const Ring& outer = P.rings[0];
    const Rect canvas = layout["canvas"];
    int probed = 0;
    for (Index i = 0; i < outer.count; ++i) {
        Point a = P.vertices[outer.first + i], b = P.vertices[outer.first + (i + 1) % outer.count];
        Vec2 sa = cam.toScreen(a), sb = cam.toScreen(b);
        const double step = 4 / std::max(4.0, std::hypot(sb.x - sa.x, sb.y - sa.y));  // 4 px
        for (double t = step; t < 1; t += step) {
            auto [red, p] = thickness(a, b, t);
            Rect probe{p.x - 8, p.y - 8, 16, 16};
            if (!within(probe, canvas)) continue;
            bool labelled = false;
            for (const Rect& l : labels) labelled |= overlaps(probe, l);
            if (labelled) continue;
            ++probed;
            if (red >= 2) {
                failures += failWith("tiny hole: the outer ring is thick red at " +
                                     std::to_string(int(p.x)) + "," + std::to_string(int(p.y)));
                break;
            }
        }
    }
    std::printf(
        "tiny hole: 4 hole edges thick red; %d probes on the outer ring in view, none red\n",
        probed);
    if (probed < 40) failures += failWith("tiny hole: the outer ring's nearby edge is not in view");
    stbi_image_free(img.px);
    return failures;
}

// Labels of coincident and near culprit vertices (v0 = v4 at one point, v1 and v5 a few pixels
// apart): one label per point, the coincident ones merged, no two labels overlapping, each with
// its text drawn, none under the find box, the Edit box, the Shrink window or the inset.
int checkLabels(const std::string& dir) {
    const std::string input = writeFace(dir, "screenshot-test-labels", R"({"type": "Polygon",
        "coordinates": [[[0,0],[128,1],[128,-5],[-10,-5],[0,0],[124,0.96875],[-10,10],[0,0]]]})");
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--show-error", dir + "/screenshot-test-labels.png", kW, kH, img,
                      layout, true, 4))
        return 1;
    Model model;
    model.open(input);
    model.setViewport(layout["canvas"]);
    model.showError();
    std::vector<Point> points;
    for (Index v : model.errorCulprits().vertices) points.push_back(model.polygon().vertices[v]);
    std::vector<Point> distinct;
    for (Point p : points)
        if (std::find(distinct.begin(), distinct.end(), p) == distinct.end()) distinct.push_back(p);
    std::vector<Rect> labels;
    for (size_t i = 0; layout.count("label-" + std::to_string(i)); ++i)
        labels.push_back(layout["label-" + std::to_string(i)]);
    int failures = 0;
    if (points.size() < 4 || distinct.size() >= points.size())
        failures += failWith("labels: the face's finding has no coincident culprit vertices");
    if (labels.size() != distinct.size())
        failures += failWith("labels: " + std::to_string(labels.size()) + " labels for " +
                             std::to_string(distinct.size()) + " distinct points (" +
                             std::to_string(points.size()) + " vertices)");
    const Rect canvas = layout["canvas"];
    for (size_t i = 0; i < labels.size(); ++i) {
        const Rect& l = labels[i];
        if (!within(l, canvas))
            failures += failWith("label " + std::to_string(i) + " leaves the canvas");
        for (size_t j = 0; j < i; ++j)
            if (overlaps(l, labels[j]))
                failures += failWith("labels " + std::to_string(j) + " and " + std::to_string(i) +
                                     " overlap");
        for (const char* box : {"find-box", "edit-box", "shrink-box", "inset"})
            if (layout.count(box) && overlaps(l, layout[box]))
                failures += failWith("label " + std::to_string(i) + " is under the " + box);
        int text = count(img, l, [](Rgba c) { return close(c, palette::kCulprit, 40); });
        if (text < 20) failures += failWith("label " + std::to_string(i) + " shows no text");
    }
    std::printf("labels: %zu culprit vertices at %zu points, %zu labels apart\n", points.size(),
                distinct.size(), labels.size());
    stbi_image_free(img.px);
    return failures;
}

// A --layer the dataset does not have, with --screenshot: the reason on stderr, exit 3 (or 2
// without GDAL, which --layer needs).
int checkBadLayer(const std::string& dir) {
    const std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + FLOOD_SOURCE_DIR +
                            "/polygons/datasets/mixed.geojson' --layer nope --screenshot '" + dir +
                            "/screenshot-test-layer.png' 2>&1 >/dev/null";
    FILE* pipe = popen(cmd.c_str(), "r");
    std::string said;
    char line[512];
    while (pipe && std::fgets(line, sizeof line, pipe)) said += line;
    int rc = pipe ? pclose(pipe) : -1;
    rc = rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
#ifdef FLOOD_GDAL
    const bool ok = rc == 3 && said.find("no layer \"nope\"") != std::string::npos;
#else
    const bool ok = rc == 2 && said.find("GDAL") != std::string::npos;
#endif
    return ok ? 0
              : failWith("--layer nope --screenshot: exit " + std::to_string(rc) +
                         ", stderr: " + said);
}

}  // namespace

int main() {
    if (checkPresenterUsage()) return 1;
    if (int skip = displayOrSkip()) return skip;

    // A square with a square hole: bottoms, a sag, a top and ceilings, small enough to reason about.
    std::string dir = FLOOD_WORK_DIR;
    std::string input = dir + "/screenshot-test-square-hole.json";
    std::ofstream(input) << R"({"type": "Polygon", "coordinates": [
        [[0, 0], [10, 1], [11, 9], [1, 10], [0, 0]],
        [[4, 4], [4, 6], [6, 6.5], [6.5, 4], [4, 4]]]})"
                            "\n";

    Model model;
    model.open(input);
    if (!model.inputDiagnostic().ok() || model.steps() == 0) {
        std::fprintf(stderr, "FAIL: cannot flood the test polygon: %s\n", model.verdict().c_str());
        return 1;
    }
    // A step with an earlier (not emphasised) flooded triangle and two distinct chain ends.
    uint32_t step = 0;
    for (uint32_t s = 1; s <= model.steps() && !step; ++s) {
        model.seek(s);
        const ReplayState& st = model.state();
        const Event* e = model.currentEvent();
        if (st.triangleCount > e->triangleCount && st.fingers.left != kNone &&
            st.fingers.left != st.fingers.right && e->action != Action::Forbidden)
            step = s;
    }
    if (!step) {
        std::fprintf(stderr, "FAIL: no step with a flooded triangle and an open chain\n");
        return 1;
    }
    model.seek(step);

    const int W = 1000, H = 700;
    // Screenshots are rendered at UI scale 1 (see main.cpp), so logical pixels are pixels.
    Layout layout = computeLayout(W, H, 1);
    model.fitCamera(layout.canvas);
    int failures = 0;
    for (bool back : {false, true}) {
        std::string out = dir + (back ? "/screenshot-test-back.png" : "/screenshot-test.png");
        std::string steps = (back ? "--step " + std::to_string(model.steps()) + " " : "") +
                            "--step " + std::to_string(step);
        Image img;
        std::map<std::string, Rect> printed;
        if (!shootPrinted(input, steps, out, W, H, img, printed)) return 1;
        // The viewer fits clear of the find and Edit boxes (view_fit.h): the same fit here.
        model.fitCamera(layout.canvas, {printed["find-box"], printed["edit-box"]});
        failures += checkShot(model, layout, img, back);
        stbi_image_free(img.px);
    }
    if (failures) return 1;

    // The error view of a self-crossing ring: exit code 4 (invalid), the picture still
    // written, the two crossing edges thick in the error colour at the crossing point and along
    // them, the rest dimmed.
    std::string bad = dir + "/screenshot-test-crossing.json";
    std::ofstream(bad) << R"({"type": "Polygon", "coordinates": [
        [[0, 0], [10, 0], [0, 10], [10, 10], [0, 0]]]})"
                          "\n";
    // The canvas is what the findings panel under it leaves: read from the viewer.
    Image img;
    std::map<std::string, Rect> printed;
    if (!shootPrinted(bad, "--show-error", dir + "/screenshot-test-error.png", W, H, img, printed,
                      true, 4))
        return 1;
    Model crossing;
    crossing.open(bad);
    crossing.setViewport(printed["canvas"]);
    Point x;
    if (!crossing.showError() || !crossing.errorPoint(x)) {
        std::fprintf(stderr, "FAIL: no error view for %s: %s\n", bad.c_str(),
                     crossing.verdict().c_str());
        return 1;
    }
    Rgba seen;
    Vec2 at = crossing.camera().toScreen(x);
    if (!near(img, at, palette::kCulprit, 1, &seen))
        failures += fail("crossing point", at, palette::kCulprit, seen);
    Vec2 along = crossing.camera().toScreen({7.5, 2.5});  // on edge (10,0)-(0,10)
    if (!near(img, along, palette::kCulprit, 1, &seen))
        failures += fail("culprit edge", along, palette::kCulprit, seen);
    Vec2 inside = crossing.camera().toScreen({5, 8.5});  // inside the upper lobe, dimmed
    if (near(img, inside, palette::kCulprit, 2, &seen) ||
        near(img, inside, palette::kPolygonFill, 0, &seen))
        failures +=
            fail("dimmed interior (not fill, not culprit)", inside, palette::kBackground, seen);
    stbi_image_free(img.px);
    // Unreadable input: the window (with the reason) is still pictured, the exit code is 3.
    Image none;
    if (!shoot(dir + "/no-such-polygon.json", "", dir + "/screenshot-test-unreadable.png", W, H,
               none, 3))
        return 1;
    stbi_image_free(none.px);
    if (failures) return 1;
    if (int dense = checkDenseFace(dir, W, H, layout); dense != 0) return dense;
    failures += checkPresenter(dir, input, model, step);
    failures += checkToolbarAtScale2(dir, input);
    failures += checkKeys(dir, input);
    failures += checkLightTheme(dir, input, model, step, layout);
    failures += checkInspector(input, model, layout, W, H, dir);
    failures += checkInvariantLane(dir, W, H, layout);
    failures += checkDecisionAnswers(dir);
    failures += checkFindingsPanel(dir);
    failures += checkTinyHole(dir);
    failures += checkLabels(dir);
    failures += checkBadLayer(dir);
    if (failures) return 1;
    std::printf(
        "ok: step %u, background, water, dry land and Left marker where expected, also "
        "after stepping back from the end; error view: crossing and culprit edge in the error "
        "colour; "
        "a 10^5-vertex face reads as a shape; Tab's presenter view at 2x with its caption whole; "
        "the toolbar's "
        "last button inside 1024x768 at 2x; Ctrl+plus rebuilds the fonts; F11 fills the screen; "
        "the light theme's ground, lines and panels; the predicate inspector's rows and hover; the "
        "invariant lane's ticks; the decision tree's yes/no answers readable in both themes; "
        "every finding of a 3-finding face in the findings panel and F8 framing the next; a tiny "
        "culprit hole thick red, the outer ring not; coincident labels merged and apart; a bad "
        "--layer said on stderr\n",
        step);
    return 0;
}
