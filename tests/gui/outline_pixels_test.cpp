// GUI test (issue 26 §4): a 10^5-vertex outline (`flood generate circle-jagged 100000`, held as
// its flood begins, as a 10^6-vertex face is for seconds) draws its thin boundary decimated to
// the pixel grid (pixelBoundary, canvas_geometry.h): far fewer lines, the same picture. The
// baseline is the same shot with every edge drawn (FLOOD_VIEWER_EXACT_BOUNDARY=1). Stated
// tolerance: every inked canvas pixel of either picture lies within one pixel of an inked pixel
// of the other, and at most 2% of the inked pixels differ at all; at the default window size
// and at projector size (1024x768). The pictures stay in the build directory
// (outline-pixels-*.png).
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gui_test_display.h"
#include "viewer_run.h"

using namespace flood::view;
using namespace flood::view::testing;

namespace {

struct Shot {
    std::vector<unsigned char> rgb;
    int w = 0, h = 0;
    Rect canvas, box;
    size_t lines = 0;  // the decimated boundary's, as printed; 0: every edge
};

bool shoot(const std::string& input, bool exact, const std::string& size, Shot& s) {
    const std::string png = std::string(FLOOD_WORK_DIR) + "/outline-pixels-" + size + "-" +
                            (exact ? "exact" : "decimated") + ".png";
    std::remove(png.c_str());
    const ViewerRun run = runViewer(
        std::string("FLOOD_VIEWER_HOLD_OPEN=flooding ") +
        (exact ? "FLOOD_VIEWER_EXACT_BOUNDARY=1 " : "") + "'" + FLOOD_VIEWER + "' '" + input +
        "' --theme dark --print-layout --screenshot '" + png + "' --size " + size);
    if (run.exitCode != 0 || !run.layout.count("canvas") || !run.layout.count("opening-box"))
        return failWith(png + ": the viewer did not draw the held outline"), false;
    s.canvas = run.layout.at("canvas"), s.box = run.layout.at("opening-box");
    const size_t at = run.output.find("flood-viewer: boundary ");
    if (at != std::string::npos) s.lines = std::strtoul(run.output.c_str() + at + 23, nullptr, 10);
    int n = 0;
    unsigned char* px = stbi_load(png.c_str(), &s.w, &s.h, &n, 3);
    if (!px) return failWith(png + ": no picture"), false;
    s.rgb.assign(px, px + size_t(s.w) * s.h * 3);
    stbi_image_free(px);
    return true;
}

// The decimated outline against every edge drawn, at one window size.
bool samePicture(const std::string& input, const std::string& size) {
    std::printf("at %s:\n", size.c_str());
    Shot dec, all;
    if (!shoot(input, false, size, dec) || !shoot(input, true, size, all)) return false;
    if (dec.w != all.w || dec.h != all.h) return failWith("the two pictures differ in size"), false;
    std::printf("decimated boundary: %zu lines for 100000 edges\n", dec.lines);
    if (dec.lines == 0 || dec.lines > 25000)
        return failWith("the boundary was not decimated"), false;
    if (all.lines != 0) return failWith("FLOOD_VIEWER_EXACT_BOUNDARY=1 still decimated"), false;
    // Inked: not the canvas's background (its top-left corner), on the canvas, out of the box.
    const Rect& c = dec.canvas;
    const int x0 = int(c.x) + 1, y0 = int(c.y) + 1, x1 = int(c.x + c.w) - 1,
              y1 = int(c.y + c.h) - 1;
    auto pixel = [](const Shot& s, int x, int y) { return &s.rgb[(size_t(y) * s.w + x) * 3]; };
    const unsigned char* bg = pixel(all, x0, y0);
    auto inked = [&](const Shot& s, int x, int y) {
        if (x < x0 || y < y0 || x >= x1 || y >= y1) return false;
        const Rect& b = s.box;
        if (x >= b.x - 1 && x < b.x + b.w + 1 && y >= b.y - 1 && y < b.y + b.h + 1) return false;
        const unsigned char* p = pixel(s, x, y);
        return std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 24;
    };
    auto near = [&](const Shot& s, int x, int y) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (inked(s, x + dx, y + dy)) return true;
        return false;
    };
    long ink = 0, differ = 0, stray = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const bool a = inked(dec, x, y), b = inked(all, x, y);
            ink += a || b;
            differ += a != b || (a && std::memcmp(pixel(dec, x, y), pixel(all, x, y), 3) != 0);
            stray += (a && !near(all, x, y)) || (b && !near(dec, x, y));
        }
    std::printf("inked pixels %ld, differing %ld, farther than a pixel from the other's %ld\n", ink,
                differ, stray);
    if (ink < 5000) return failWith("no outline drawn"), false;
    if (stray > 0) return failWith("the decimated outline strays more than a pixel"), false;
    if (differ > ink / 50) return failWith("more than 2% of the outline's pixels differ"), false;
    return true;
}

}  // namespace

int main() {
    if (int rc = displayOrSkip()) return rc;
    const std::string input = std::string(FLOOD_WORK_DIR) + "/outline-pixels.json";
    const std::string gen =
        std::string("'") + FLOOD_CLI + "' generate circle-jagged 100000 -o '" + input + "'";
    if (std::system(gen.c_str()) != 0) return failWith(gen);
    for (const char* size : {"1280x800", "1024x768"})
        if (!samePicture(input, size)) return 1;
    return 0;
}
