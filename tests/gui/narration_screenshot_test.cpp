// GUI test (issue 27 §1): in presenter view at Fig. 7 step 23 the caption says "Sag vertex 35
// hangs ... below NextRight (vertex 14): a bridge joins it to the water at vertex 51 ...,
// cutting triangle 18", and the canvas labels 35, 14, 51 and triangle 18, in the large font,
// inside the canvas, none over another label; at the default window size and at a
// projector's, and (§4) at 250% the names and the fingers' letters grow with the caption's
// font. `--print-layout` says where each step label went; the picture must show ink there.
// Exit 77 (skipped) without a display, except in CI.
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <sys/wait.h>

#include "gui_test_display.h"
#include "model.h"
#include "palette.h"
#include "viewer_run.h"

using namespace flood;
using namespace flood::view;
using namespace flood::view::testing;

namespace {

// One shot at W x H after `keys` (--press ...): the step labels' rectangles from
// --print-layout, the picture loaded. `font`: the large font's pixels at the shot's scale.
int shootStep23(int W, int H, const std::string& keys = "", double font = 20) {
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    const std::string png = std::string(FLOOD_WORK_DIR) + "/narration-step23-" + std::to_string(W) +
                            "x" + std::to_string(H) + (keys.empty() ? "" : "-zoomed") + ".png";
    std::remove(png.c_str());
    const std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + input +
                            "' --step 23 --presenter --theme dark " + keys +
                            " --print-layout --screenshot '" + png + "' --size " +
                            std::to_string(W) + "x" + std::to_string(H);
    const ViewerRun run = runViewer(cmd);
    if (run.exitCode != 0) return failWith("flood-viewer did not exit 0");
    std::map<std::string, Rect> layout = run.layout;
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load(png.c_str(), &w, &h, &channels, 4);
    if (!px || w != W || h != H) return failWith(png + " is missing or not the size asked");
    const Rect canvas = layout["canvas"];
    int failures = 0;
    // Ink: the names' colour (the theme's strongest contrast) in the label's rectangle.
    auto ink = [&](const Rect& r) {
        int n = 0;
        const Rgba c = palette::kHover;
        for (int y = std::max(0, int(r.y)); y < std::min(h, int(r.y + r.h)); ++y)
            for (int x = std::max(0, int(r.x)); x < std::min(w, int(r.x + r.w)); ++x) {
                const unsigned char* p = px + (size_t(y) * w + x) * 4;
                n += std::abs(p[0] - c.r) <= 30 && std::abs(p[1] - c.g) <= 30 &&
                     std::abs(p[2] - c.b) <= 30;
            }
        return n;
    };
    for (const char* name :
         {"named-vertex-35", "named-vertex-14", "named-vertex-51", "named-triangle-18"}) {
        if (!layout.count(name)) {
            failures += failWith(std::string(name) + ": not labelled at " + std::to_string(W) +
                                 "x" + std::to_string(H));
            continue;
        }
        const Rect& r = layout[name];
        if (!within(r, canvas)) failures += failWith(std::string(name) + " leaves the canvas");
        // The caption's font (20 px at scale 1) and its padding: readable from the back.
        if (r.h < font) failures += failWith(std::string(name) + " is in a small font");
        const int n = ink(r);
        if (n < 40) failures += failWith(std::string(name) + " shows no text");
        std::printf("%s at %.0f %.0f %.0f x %.0f: %d ink pixels\n", name, r.x, r.y, r.w, r.h, n);
    }
    // The fingers' letters in presenter view: the large font too (issue 27 §4), so they grow
    // with Ctrl + as the caption does.
    for (const auto& [name, r] : layout)
        if (name.rfind("finger-", 0) == 0 && r.h < font)
            failures +=
                failWith(name + " is in a small font (" + std::to_string(int(r.h)) + " px tall)");
    // Every step label (names, fingers, ghosts, gorges) apart from every other.
    std::vector<std::pair<std::string, Rect>> labels;
    for (const auto& [name, r] : layout)
        for (const char* kind : {"named-", "finger-", "ghost-", "gorge-"})
            if (name.rfind(kind, 0) == 0) labels.push_back({name, r});
    for (size_t i = 0; i < labels.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (overlaps(labels[i].second, labels[j].second))
                failures += failWith(labels[i].first + " overlaps " + labels[j].first);
    stbi_image_free(px);
    std::printf("%zu step labels at %dx%d\n", labels.size(), W, H);
    return failures;
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    // Ctrl + six times: 250%, the caption's font 50 px.
    std::string zoom;
    for (int i = 0; i < 6; ++i) zoom += " --press ctrl+plus";
    int failures =
        shootStep23(1280, 800) + shootStep23(1920, 1080) + shootStep23(1920, 1080, zoom, 50);
    if (failures) return 1;
    std::printf(
        "ok: step 23's names 35, 14, 51 and triangle 18 labelled large and apart, the fingers'"
        " letters large, at 100%% and 250%%\n");
    return 0;
}
