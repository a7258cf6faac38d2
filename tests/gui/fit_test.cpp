// GUI test (issue 27 §4, views that hold): after the first fit, after presenter view on
// (Tab) and off again, with the State table open and with the direction dial and the canvas's
// up arrow shown, no vertex of Fig. 7 lies under a window floating over the canvas (the find
// box, the Edit box, the dial, the State table, the arrow), every vertex is on the canvas, and
// the polygon fills the free part of it; at 1280x800 and 1920x1080. The vertices' places come
// from the camera --print-layout prints, the boxes' from where ImGui drew them; the pictures
// stay in the build directory (fit-*.png) to look at. Exit 77 (skipped) without a display,
// except in CI.
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "gui_test_display.h"
#include "model.h"
#include "view_fit.h"
#include "viewer_run.h"

using namespace flood;
using namespace flood::view;
using namespace flood::view::testing;

namespace {

struct Shot {
    std::map<std::string, Rect> layout;
    Camera camera;
    bool ok = false;
};

// flood-viewer on Fig. 7 at step 23, `args` added, at W x H: the layout and camera it prints.
Shot shoot(const std::string& name, int W, int H, const std::string& args) {
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    const std::string png = std::string(FLOOD_WORK_DIR) + "/fit-" + name + "-" + std::to_string(W) +
                            "x" + std::to_string(H) + ".png";
    std::remove(png.c_str());
    const std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + input +
                            "' --step 23 --theme dark " + args + " --print-layout --screenshot '" +
                            png + "' --size " + std::to_string(W) + "x" + std::to_string(H);
    Shot shot;
    const ViewerRun run = runViewer(cmd);
    shot.layout = run.layout;
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load(png.c_str(), &w, &h, &channels, 4);
    shot.ok = run.exitCode == 0 && px && w == W && h == H && run.cameraScale > 0 &&
              shot.layout.count("canvas");
    stbi_image_free(px);
    shot.camera.setViewport(shot.layout["canvas"]);
    shot.camera.centerOn({run.cameraX, run.cameraY}, run.cameraScale);
    return shot;
}

// The checks: every vertex on the canvas and under none of `boxes` (those the shot drew, each
// grown by a pixel for the printed rounding); the polygon's box on screen fills at least 80%
// of the free area across or down.
int check(const std::string& what, const Shot& shot, const Polygon& P,
          const std::vector<std::string>& boxes) {
    if (!shot.ok) return failWith(what + ": flood-viewer failed or printed no camera");
    int failures = 0;
    const Rect canvas = shot.layout.at("canvas");
    std::vector<Rect> over;
    for (const std::string& b : boxes) {
        if (!shot.layout.count(b)) {
            failures += failWith(what + ": no " + b + " drawn");
            continue;
        }
        const Rect r = shot.layout.at(b);
        over.push_back(r);
        std::printf("%s: %s at %.0f %.0f %.0f x %.0f\n", what.c_str(), b.c_str(), r.x, r.y, r.w,
                    r.h);
    }
    WorldBox box;
    for (Index v = 0; v < P.vertices.size(); ++v) {
        const Vec2 s = shot.camera.toScreen(P.vertices[v]);
        box.add(P.vertices[v]);
        if (!canvas.contains(s))
            failures += failWith(what + ": vertex " + std::to_string(v) + " off the canvas");
        for (size_t i = 0; i < over.size(); ++i) {
            const Rect& r = over[i];
            if (s.x >= r.x - 1 && s.x <= r.x + r.w + 1 && s.y >= r.y - 1 && s.y <= r.y + r.h + 1)
                failures +=
                    failWith(what + ": vertex " + std::to_string(v) + " under " + boxes[i] +
                             " at " + std::to_string(int(s.x)) + "," + std::to_string(int(s.y)));
        }
    }
    const Rect free = freeArea(canvas, over, box.w() / box.h());
    const double w = box.w() * shot.camera.scale(), h = box.h() * shot.camera.scale();
    const double fill = std::max(w / free.w, h / free.h);
    std::printf("%s: the polygon %.0f x %.0f px in a free %.0f x %.0f: %.0f%%\n", what.c_str(), w,
                h, free.w, free.h, fill * 100);
    if (fill < 0.8) failures += failWith(what + ": the polygon does not fill the free canvas");
    return failures;
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    const Polygon& P = m.polygon();
    if (P.vertices.empty()) return failWith("cannot read paper-figure-7.json");
    int failures = 0;
    for (const auto& [W, H] : {std::pair{1280, 800}, std::pair{1920, 1080}}) {
        const std::string at = " at " + std::to_string(W) + "x" + std::to_string(H);
        failures +=
            check("the first fit" + at, shoot("first", W, H, ""), P, {"find-box", "edit-box"});
        failures +=
            check("presenter on (Tab)" + at, shoot("presenter-on", W, H, "--press tab"), P, {});
        failures += check("presenter off (Tab)" + at,
                          shoot("presenter-off", W, H, "--presenter --press tab"), P,
                          {"find-box", "edit-box"});
        failures += check("presenter on and off" + at,
                          shoot("presenter-on-off", W, H, "--press tab --press tab"), P,
                          {"find-box", "edit-box"});
        failures += check("the State table" + at, shoot("state-table", W, H, "--state-table"), P,
                          {"find-box", "edit-box", "state-table-box"});
        failures += check("the direction dial" + at, shoot("dial", W, H, "--up 30"), P,
                          {"find-box", "edit-box", "direction-box", "up-arrow"});
        failures += check("the up arrow in presenter view" + at,
                          shoot("dial-presenter", W, H, "--up 30 --presenter"), P, {"up-arrow"});
    }
    if (failures) return 1;
    std::printf(
        "ok: no vertex under the find box, the Edit box, the State table, the dial or the up "
        "arrow, every vertex on the canvas and the free canvas filled, after the first fit and "
        "presenter on and off, at 1280x800 and 1920x1080\n");
    return 0;
}
