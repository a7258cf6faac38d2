// GUI test: the Decision panel draws the Fig. 9 tree with the current event's path lit. At a
// step with an event the path colour is in the panel; at step 0 (nothing decided) it is not,
// so what is lit is the path and nothing else. Exit 77 (skipped) without a display, except in CI.
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/wait.h>

#include "gui_test_display.h"
#include "model.h"
#include "palette.h"

using namespace flood;
using namespace flood::view;

namespace {

// Pixels of `want` (within a small tolerance) in the rectangle `r` of the picture `png`
// that `flood-viewer INPUT ARGS` writes; -1 if it could not be made.
long countColour(const std::string& input, const std::string& args, const std::string& png, int W,
                 int H, const Rect& r, Rgba want) {
    std::remove(png.c_str());
    std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + input + "' " + args +
                      " --screenshot '" + png + "' --size " + std::to_string(W) + "x" +
                      std::to_string(H);
    std::printf("%s\n", cmd.c_str());
    std::fflush(stdout);
    int rc = std::system(cmd.c_str());
    if (rc == -1 || !WIFEXITED(rc) || WEXITSTATUS(rc) != 0) {
        std::fprintf(stderr, "FAIL: flood-viewer did not exit 0\n");
        return -1;
    }
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load(png.c_str(), &w, &h, &channels, 4);
    if (!px || w != W || h != H) {
        std::fprintf(stderr, "FAIL: %s is missing or not %dx%d\n", png.c_str(), W, H);
        return -1;
    }
    long n = 0;
    for (int y = int(r.y); y < int(r.y + r.h); ++y)
        for (int x = int(r.x); x < int(r.x + r.w); ++x) {
            const unsigned char* p = px + (size_t(y) * w + x) * 4;
            n += std::abs(p[0] - want.r) <= 6 && std::abs(p[1] - want.g) <= 6 &&
                 std::abs(p[2] - want.b) <= 6;
        }
    stbi_image_free(px);
    return n;
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    const std::string dir = FLOOD_WORK_DIR;
    const int W = 1000, H = 700;
    // The Decision panel's rectangle, as panel_decision.cpp places it (UI scale 1 in shots).
    const Rect col = computeLayout(W, H, 1).left;
    const Rect panel{col.x, col.y + col.h * 0.38, col.w, col.h * 0.27};
    long lit = countColour(input, "--step 5", dir + "/tree-screenshot-step5.png", W, H, panel,
                           palette::kTreePath);
    long none = countColour(input, "--step 0", dir + "/tree-screenshot-step0.png", W, H, panel,
                            palette::kTreePath);
    if (lit < 0 || none < 0) return 1;
    std::printf("path colour in the Decision panel: %ld pixels at step 5, %ld at step 0\n", lit,
                none);
    if (lit < 40) {
        std::fprintf(stderr, "FAIL: the current path is not lit in the decision tree\n");
        return 1;
    }
    if (none != 0) {
        std::fprintf(stderr, "FAIL: something is lit in the decision tree before any event\n");
        return 1;
    }
    std::printf(
        "ok: the decision tree is drawn with the path of step 5 lit, nothing lit at step 0\n");
    return 0;
}
