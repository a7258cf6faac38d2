// GUI test (issue 26 §4, big faces open at once): while an open runs in the background, the
// outline is on the canvas and a box over the canvas shows the progress bar (ImGui's
// PlotHistogram colour, two fifths full as the flood begins: two of five phases done) and the
// Cancel button; at 1280x800 and, in presenter view, at a projector's 1024x768. The open is
// held as its flood begins by FLOOD_VIEWER_HOLD_OPEN (viewer/main.cpp), as a 10⁶-vertex face
// would be for seconds. The pictures stay in the build directory (open-progress-*.png).
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <cstdio>
#include <cstdlib>
#include <string>

#include "gui_test_display.h"
#include "viewer_run.h"

using namespace flood::view;
using namespace flood::view::testing;

namespace {

int check(int W, int H, const std::string& extra) {
    const std::string what = std::to_string(W) + "x" + std::to_string(H) + extra;
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/comb.json";
    const std::string png = std::string(FLOOD_WORK_DIR) + "/open-progress-" + std::to_string(W) +
                            "x" + std::to_string(H) + ".png";
    std::remove(png.c_str());
    const ViewerRun run =
        runViewer("FLOOD_VIEWER_HOLD_OPEN=flooding '" + std::string(FLOOD_VIEWER) + "' '" + input +
                  "' --theme dark --print-layout --screenshot '" + png + "' --size " +
                  std::to_string(W) + "x" + std::to_string(H) + extra);
    if (run.exitCode != 0)
        return failWith(what + ": flood-viewer exited " + std::to_string(run.exitCode));
    if (!run.layout.count("opening-box") || !run.layout.count("canvas"))
        return failWith(what + ": no progress box drawn");
    const Rect box = run.layout.at("opening-box"), canvas = run.layout.at("canvas");
    if (!within(box, canvas)) return failWith(what + ": the progress box is not over the canvas");
    for (const char* other : {"find-box", "edit-box"})
        if (run.layout.count(other) && overlaps(box, run.layout.at(other)))
            return failWith(what + ": the progress box covers the " + other);
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(png.c_str(), &w, &h, &n, 3);
    if (!px || w != W || h != H) return failWith(what + ": no picture");
    // In the box: the bar's fill (230, 179, 0), and the Cancel button's blue at its right end.
    long fill = 0, button = 0, polygon = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const unsigned char* p = px + 3 * (size_t(y) * size_t(W) + size_t(x));
            const bool inBox = x >= box.x && x < box.x + box.w && y >= box.y && y < box.y + box.h;
            if (inBox && std::abs(p[0] - 230) < 12 && std::abs(p[1] - 179) < 12 && p[2] < 20)
                ++fill;
            if (inBox && x > box.x + box.w * 0.75 && p[2] > p[0] + 40) ++button;
            // Out of the box on the canvas: the outline, anything not the background's grey.
            const bool onCanvas = x >= canvas.x && x < canvas.x + canvas.w && y >= canvas.y &&
                                  y < canvas.y + canvas.h;
            if (onCanvas && !inBox && (std::abs(p[0] - p[2]) > 30 || std::abs(p[1] - p[2]) > 30))
                ++polygon;
        }
    stbi_image_free(px);
    std::printf("%s: box %.0f %.0f %.0f x %.0f, %ld fill, %ld button, %ld outline pixels\n",
                what.c_str(), box.x, box.y, box.w, box.h, fill, button, polygon);
    // Two fifths of the bar (less the Cancel button) is filled: two of the five phases.
    const double barArea = (box.w * 0.5) * 12;
    if (fill < barArea * 0.5) return failWith(what + ": the progress bar is not drawn half full");
    if (button < 100) return failWith(what + ": no Cancel button");
    if (polygon < 200) return failWith(what + ": no outline on the canvas");
    return 0;
}

}  // namespace

int main() {
    if (int rc = displayOrSkip()) return rc;
    int failures = check(1280, 800, "");
    failures += check(1024, 768, " --presenter");
    return failures ? 1 : 0;
}
