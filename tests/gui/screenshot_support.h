// The GUI screenshot tests' shared tools (tests/gui/*_screenshot_test.cpp and screenshot_test.cpp,
// each its own program): run flood-viewer --screenshot, read the PNG back, probe pixels whose
// colours the palette knows, and the square-with-a-hole fixture most shots show.
#pragma once
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

#include "gui_test_display.h"
#include "model.h"
#include "palette.h"
#include "presenter.h"
#include "viewer_run.h"

namespace flood::view::testing {

struct Image {
    int w = 0, h = 0;
    unsigned char* px = nullptr;
    Rgba at(int x, int y) const {
        const unsigned char* p = px + (size_t(y) * w + x) * 4;
        return {p[0], p[1], p[2], p[3]};
    }
};

inline bool close(Rgba a, Rgba b, int tol) {
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

// True if a pixel within `radius` of (x, y) has `want`: anti-aliasing and rounding of the
// projected position move a colour by a pixel, never more.
inline bool near(const Image& img, Vec2 p, Rgba want, int radius, Rgba* seen) {
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

inline int fail(const char* what, Vec2 p, Rgba want, Rgba seen) {
    std::fprintf(stderr, "FAIL: %s at (%.1f, %.1f): want %d,%d,%d, got %d,%d,%d\n", what, p.x, p.y,
                 want.r, want.g, want.b, seen.r, seen.g, seen.b);
    return 1;
}

// Runs flood-viewer headless at `steps` (one or more --step options) into `out`, loads it.
inline bool shoot(const std::string& input, const std::string& steps, const std::string& out, int W,
                  int H, Image& img, int wantExit = 0) {
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
inline bool probeTriangle(const Model& model, uint32_t t, const Image& img, Rgba want, Vec2& probe,
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
inline int checkShot(const Model& model, const Layout& layout, const Image& img, bool back) {
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

// Runs flood-viewer with `args` into `out` at W x H and loads it (a picture of any size when
// `exact` is false); `layout` gets its --print-layout lines ("NAME x y w h").
inline bool shootPrinted(const std::string& input, const std::string& args, const std::string& out,
                         int W, int H, Image& img, std::map<std::string, Rect>& layout,
                         bool exact = true, int wantExit = 0) {
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

inline bool inside(const Rect& r, int W, int H) {
    return r.w > 0 && r.h > 0 && r.x >= 0 && r.y >= 0 && r.x + r.w <= W && r.y + r.h <= H;
}

// Pixels of `r` (clipped to the image) for which `is` holds.
template <class F>
inline int count(const Image& img, const Rect& r, F is) {
    int n = 0;
    for (int y = std::max(0, int(r.y)); y < std::min(img.h, int(r.y + r.h)); ++y)
        for (int x = std::max(0, int(r.x)); x < std::min(img.w, int(r.x + r.w)); ++x)
            n += is(img.at(x, y));
    return n;
}

inline double luminance(Rgba c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// WCAG's contrast ratio of two colours (1 to 21; 3 is its floor for graphics such as lines).
inline double contrast(Rgba a, Rgba b) {
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

inline std::string writeFace(const std::string& dir, const std::string& name, const char* json) {
    std::string path = dir + "/" + name + ".json";
    std::ofstream(path) << json << "\n";
    return path;
}

inline bool roughlyWithin(const Rect& r, const Rect& outer) {
    return r.x >= outer.x - 0.5 && r.y >= outer.y - 0.5 && r.x + r.w <= outer.x + outer.w + 0.5 &&
           r.y + r.h <= outer.y + outer.h + 0.5;
}

// The square with a square hole most shots show (bottoms, a sag, a top and ceilings, small
// enough to reason about), opened at a step with an earlier (not emphasised) flooded triangle
// and two distinct chain ends; pictures W x H, laid out as the viewer lays them out.
// `program` names the input file, so the programs may run at once.
struct SquareHole {
    explicit SquareHole(const std::string& program)
        : input(dir + "/" + program + "-square-hole.json") {}
    std::string dir = FLOOD_WORK_DIR;
    std::string input;
    Model model;
    uint32_t step = 0;
    int W = 1000, H = 700;
    Layout layout = computeLayout(1000, 700, 1);  // screenshots are at UI scale 1 (main.cpp)
};

inline bool openSquareHole(SquareHole& f) {
    std::ofstream(f.input) << R"({"type": "Polygon", "coordinates": [
        [[0, 0], [10, 1], [11, 9], [1, 10], [0, 0]],
        [[4, 4], [4, 6], [6, 6.5], [6.5, 4], [4, 4]]]})"
                              "\n";
    Model& model = f.model;
    model.open(f.input);
    if (!model.inputDiagnostic().ok() || model.steps() == 0) {
        std::fprintf(stderr, "FAIL: cannot flood the test polygon: %s\n", model.verdict().c_str());
        return false;
    }
    for (uint32_t s = 1; s <= model.steps() && !f.step; ++s) {
        model.seek(s);
        const ReplayState& st = model.state();
        const Event* e = model.currentEvent();
        if (st.triangleCount > e->triangleCount && st.fingers.left != kNone &&
            st.fingers.left != st.fingers.right && e->action != Action::Forbidden)
            f.step = s;
    }
    if (!f.step) {
        std::fprintf(stderr, "FAIL: no step with a flooded triangle and an open chain\n");
        return false;
    }
    model.seek(f.step);
    model.fitCamera(f.layout.canvas);
    return true;
}

// Fits the fixture's camera as the viewer does at its step: clear of the find and Edit boxes
// (view_fit.h), whose places a --print-layout run of the viewer says.
inline bool fitAsTheViewer(SquareHole& f) {
    Image img;
    std::map<std::string, Rect> printed;
    if (!shootPrinted(f.input, "--step " + std::to_string(f.step),
                      f.dir + "/screenshot-test-fit.png", f.W, f.H, img, printed))
        return false;
    stbi_image_free(img.px);
    f.model.fitCamera(f.layout.canvas, {printed["find-box"], printed["edit-box"]});
    return true;
}

}  // namespace flood::view::testing
