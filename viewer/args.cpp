#include "args.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "flood/geometry/up.h"
#include "platform_glfw.h"  // the --press keys

#ifndef FLOOD_VERSION  // set by viewer/CMakeLists.txt, as the CLI's
#define FLOOD_VERSION "unknown"
#endif

namespace flood::view {

namespace {

// --press names: the presenter keys and the findings' F8, so a screenshot can show what they
// do.
bool pressNamed(const std::string& name, Args::Press& p) {
    if (name == "tab") return p = {platform::kKeyTab, false}, true;
    if (name == "f8") return p = {platform::kKeyF8, false}, true;
    if (name == "shift+f8") return p = {platform::kKeyF8, false, true}, true;
    if (name == "f11") return p = {platform::kKeyF11, false}, true;
    if (name == "ctrl+plus") return p = {platform::kKeyPlus[0], true}, true;
    if (name == "ctrl+minus") return p = {platform::kKeyMinus[0], true}, true;
    if (name == "ctrl+0") return p = {platform::kKeyZero[0], true}, true;
    if (name == "p") return p = {'P', false}, true;  // Save PNG
    return false;
}

const char* const kUsage =
    "usage: flood-viewer [FILE] [--feature N] [--layer NAME] [--where SQL] [--step N]\n"
    "                    [--show-error] [--predicates] [--gorge-focus] [--screenshot OUT.png]\n"
    "                    [--size WxH] [--mouse X,Y] [--scale S] [--presenter] [--theme "
    "light|dark]\n"
    "                    [--up DIRECTION] [--quiz ACTIONS [--answer ACTION]] [--state-table]\n"
    "       flood-viewer FILE --screenshot OUT.png|OUT.svg --canvas-only [--size WxH] [--caption]\n"
    "       flood-viewer FILE --export-gif OUT.gif|--export-png-dir DIR [--steps A:B] [--every K]\n"
    "                    [--fps F] [--caption] [--size WxH]\n"
    "       flood-viewer --help | --version\n"
    "  FILE              polygon (GeoJSON, ring arrays or WKT) or a trace from `flood trace`\n"
    "                    (*.jsonl); default: polygons/paper-figure-7.json\n"
    "  --feature N       open the feature of FID N (as `flood check` and `flood\n"
    "                    --feature` number them) of a FeatureCollection or GIS layer;\n"
    "                    no such feature: exit 2\n"
    "  --step N          show the state after N events (repeat it to draw each in turn:\n"
    "                    --step 40 --step 5 shows 5 after a frame at 40)\n"
    "  --show-error      start in the error view (zoomed to the culprits), as the E key\n"
    "  --screenshot OUT  render once in a hidden window, write OUT as PNG and exit; the exit\n"
    "                    code is the CLI's: 3 unreadable, 4 invalid, 5 forbidden, 6 checker\n"
    "  --size WxH        window size in pixels (default 1280x800); with --canvas-only, an\n"
    "                    SVG or an export below: the picture's size (the window keeps 1280x800)\n"
    "  --scale S         UI scale 0.5..4 instead of the monitor's (screenshots: 1)\n"
    "  --presenter       start in presenter view: the canvas and a large caption (Tab)\n"
    "  --theme T         light or dark (default: the last one chosen, else dark)\n"
    "  --print-layout    with --screenshot: print where the caption, the toolbar's last\n"
    "                    button, the canvas, the findings and their rows, the boxes over the\n"
    "                    canvas, the error view's labels and the step's labels\n"
    "                    (named-vertex-35, ...) were drawn (x y w h, logical px), and the\n"
    "                    camera (centre x y, pixels per unit)\n"
    "  --press KEY       with --screenshot: press tab, f11, ctrl+plus, ctrl+minus, ctrl+0,\n"
    "                    f8, shift+f8 or p (Save PNG) first (repeat it for more, one frame\n"
    "                    apart)\n"
    "  --canvas-only     --screenshot renders the canvas alone (no panels), offscreen at --size;\n"
    "                    OUT ending in .svg is always the canvas alone, as SVG\n"
    "  --export-gif OUT  the flood (or --steps) as an animated GIF of the canvas, then exit\n"
    "  --export-png-dir DIR  the same as numbered PNGs DIR/frame-0000.png, ... (DIR is made)\n"
    "  --steps A:B       the steps exported (A: or :B for an open end; default the whole flood)\n"
    "  --every K         a frame every K steps; the last step B always ends the animation\n"
    "  --fps F           GIF frames per second, 0.1 to 50 (default 10)\n"
    "  --caption         a line under the canvas: step, action and the step's narration\n"
    "  --layer NAME      a GIS dataset's layer (GDAL; default: its only layer)\n"
    "  --where 'SQL'     only the GIS features an OGR SQL attribute filter keeps\n"
    "                    (with --feature N: FID N, if the filter keeps it)\n"
    "  --predicates      open the predicate inspector; --gorge-focus: current gorge only\n"
    "  --quiz ACTIONS    start in the quiz (key Q), asking about ACTIONS: raise, bridge, spill,\n"
    "                    jump, fill, comma separated, or all\n"
    "  --answer ACTION   with --quiz: answer the question before the last --step's next event\n"
    "  --state-table     open the State table (Fig. 10)\n"
    "  --mouse X,Y       with --screenshot: the pointer at X,Y (what hovering there shows)\n"
    "  --bench           time opening, seeking and drawing (hidden window), print, exit\n"
    "  --up DIRECTION    flood along +y, -y, +x, -x, an angle in degrees (90 is +y) or X,Y,\n"
    "                    with the direction dial open (it compares with the +y run)\n"
    "a file that cannot be written: exit 8, nothing half-written left\n"
    "keys in the viewer: F1 or ?\n";

}  // namespace

int parseArgs(int argc, char** argv, Args& a) {
    for (int i = 1; i < argc; ++i) {
        std::string s = argv[i];
        auto value = [&](const char* name) -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "flood-viewer: %s needs a value\n%s", name, kUsage);
                return nullptr;
            }
            return argv[++i];
        };
        if (s == "-h" || s == "--help") {
            std::fputs(kUsage, stdout);
            return 1;
        } else if (s == "--version") {
            std::puts("flood-viewer " FLOOD_VERSION);
            return 1;
        } else if (s == "--step") {
            const char* v = value("--step");
            uint32_t step = 0;
            if (!v || !parseStepArg(v, step)) {
                if (v)
                    std::fprintf(stderr, "flood-viewer: --step wants a number >= 0, got '%s'\n", v);
                return 2 + 1;
            }
            a.steps.push_back(step);
        } else if (s == "--feature") {
            const char* v = value("--feature");
            char* end = nullptr;
            if (!v || (a.feature = std::strtol(v, &end, 10), *end != 0) || a.feature < 0) {
                if (v)
                    std::fprintf(stderr, "flood-viewer: --feature wants a number >= 0, got '%s'\n",
                                 v);
                return 2 + 1;
            }
        } else if (s == "--scale") {
            const char* v = value("--scale");
            char* end = nullptr;
            if (!v || (a.scale = std::strtof(v, &end), *end != 0) ||
                !(a.scale >= 0.5f && a.scale <= 4)) {
                if (v)
                    std::fprintf(stderr,
                                 "flood-viewer: --scale wants a number in 0.5..4, got '%s'\n", v);
                return 2 + 1;
            }
        } else if (s == "--theme") {
            const char* v = value("--theme");
            if (!v || !palette::parseTheme(v, a.theme)) {
                if (v)
                    std::fprintf(stderr, "flood-viewer: --theme wants light or dark, got '%s'\n",
                                 v);
                return 2 + 1;
            }
            a.themeGiven = true;
        } else if (s == "--presenter") {
            a.presenter = true;
        } else if (s == "--press") {
            const char* v = value("--press");
            Args::Press p{};
            if (!v || !pressNamed(v, p)) {
                if (v)
                    std::fprintf(stderr,
                                 "flood-viewer: --press wants tab, f11, ctrl+plus, ctrl+minus, "
                                 "ctrl+0, f8 or shift+f8, got '%s'\n",
                                 v);
                return 2 + 1;
            }
            a.presses.push_back(p);
        } else if (s == "--print-layout") {
            a.printLayout = true;
        } else if (s == "--layer" || s == "--where") {
            const char* v = value(s.c_str());
            if (!v) return 2 + 1;
            (s == "--layer" ? a.layer : a.where) = v;
        } else if (s == "--quiz") {
            const char* v = value("--quiz");
            std::string why;
            if (!v || !parseQuizActions(v, a.quizAsked, why)) {
                if (v) std::fprintf(stderr, "flood-viewer: --quiz: %s\n", why.c_str());
                return 2 + 1;
            }
            a.quiz = true;
        } else if (s == "--answer") {
            const char* v = value("--answer");
            QuizActions one;
            std::string why;
            if (v && parseQuizActions(v, one, why))
                for (Action c : kQuizChoices)  // exactly one of them
                    if (one.bits == uint8_t(1u << int(c))) a.answer = c;
            if (a.answer == Action::Count) {
                if (v)
                    std::fprintf(stderr,
                                 "flood-viewer: --answer wants raise, bridge, spill, jump or "
                                 "fill, got '%s'\n",
                                 v);
                return 2 + 1;
            }
        } else if (s == "--state-table") {
            a.stateTable = true;
        } else if (s == "--predicates") {
            a.predicates = true;
        } else if (s == "--gorge-focus") {
            a.gorgeFocus = true;
        } else if (s == "--mouse") {
            const char* v = value("--mouse");
            if (!v || std::sscanf(v, "%f,%f", &a.mouseX, &a.mouseY) != 2) {
                if (v) std::fprintf(stderr, "flood-viewer: --mouse wants X,Y, got '%s'\n", v);
                return 2 + 1;
            }
            a.mouse = true;
        } else if (s == "--show-error") {
            a.showError = true;
        } else if (s == "--bench") {
            a.bench = true;
        } else if (s == "--up") {
            const char* v = value("--up");
            Up d;
            std::string why;
            if (v && !parseUp(v, d, why))
                std::fprintf(stderr, "flood-viewer: --up: %s\n", why.c_str());
            if (!v || !why.empty()) return 2 + 1;
            a.up = v;
        } else if (s == "--screenshot") {
            const char* v = value("--screenshot");
            if (!v) return 2 + 1;
            a.screenshot = v;
        } else if (s == "--size") {
            const char* v = value("--size");
            if (!v || std::sscanf(v, "%dx%d", &a.width, &a.height) != 2 || a.width < 64 ||
                a.height < 64 || a.width > 16384 || a.height > 16384) {
                if (v)
                    std::fprintf(stderr, "flood-viewer: --size wants WxH (64..16384), got '%s'\n",
                                 v);
                return 2 + 1;
            }
            a.sizeGiven = true;
        } else if (s == "--canvas-only") {
            a.canvasOnly = true;
        } else if (s == "--caption") {
            a.exports.caption = true;
        } else if (s == "--export-gif" || s == "--export-png-dir") {
            const char* v = value(s.c_str());
            if (!v) return 2 + 1;
            (s == "--export-gif" ? a.exports.gif : a.exports.pngDir) = v;
        } else if (s == "--steps") {
            const char* v = value("--steps");
            std::string error;
            if (!v) return 2 + 1;
            if (!parseStepRange(v, a.exports.first, a.exports.last, &error)) {
                std::fprintf(stderr, "flood-viewer: %s\n", error.c_str());
                return 2 + 1;
            }
            a.rangeGiven = true;
        } else if (s == "--every") {
            const char* v = value("--every");
            char* end = nullptr;
            long k = v ? std::strtol(v, &end, 10) : 0;
            if (!v || *end != 0 || k < 1 || k > 1000000000L) {
                if (v)
                    std::fprintf(stderr,
                                 "flood-viewer: --every wants a number of steps >= 1, got '%s'\n",
                                 v);
                return 2 + 1;
            }
            a.exports.every = uint32_t(k);
            a.everyGiven = true;
        } else if (s == "--fps") {
            const char* v = value("--fps");
            char* end = nullptr;
            double f = v ? std::strtod(v, &end) : 0;
            if (!v || *end != 0 || !(f >= kMinFps && f <= kMaxFps)) {
                if (v)
                    std::fprintf(
                        stderr,
                        "flood-viewer: --fps wants frames per second from 0.1 to 50, got '%s'\n",
                        v);
                return 2 + 1;
            }
            a.exports.fps = f;
            a.fpsGiven = true;
        } else if (!s.empty() && s[0] == '-' && s != "-") {
            std::fprintf(stderr, "flood-viewer: unknown option %s\n%s", s.c_str(), kUsage);
            return 2 + 1;
        } else if (a.file.empty()) {
            a.file = s;
        } else {
            std::fprintf(stderr, "flood-viewer: one FILE only\n%s", kUsage);
            return 2 + 1;
        }
    }
    // The screenshot is an export when it is the canvas alone (or an SVG, which only can be).
    const std::string& shot = a.screenshot;
    bool svg = shot.size() >= 4 && shot.compare(shot.size() - 4, 4, ".svg") == 0;
    if (svg) a.exports.svg = shot;
    else if (a.canvasOnly && !shot.empty()) a.exports.png = shot;
    const char* needs = nullptr;
    if (a.canvasOnly && shot.empty()) needs = "--canvas-only needs --screenshot OUT";
    else if ((a.rangeGiven || a.everyGiven) && !a.exports.animated())
        needs = "--steps and --every need --export-gif or --export-png-dir";
    else if (a.fpsGiven && a.exports.gif.empty()) needs = "--fps needs --export-gif";
    else if (a.exports.caption && !a.exporting())
        needs = "--caption needs --canvas-only, an SVG or an export";
    else if (a.exporting() && a.bench) needs = "--bench cannot be combined with exports";
    else if (a.answer != Action::Count && !a.quiz) needs = "--answer needs --quiz";
#ifndef FLOOD_GIF
    if (!a.exports.gif.empty())
        needs = "--export-gif: this flood-viewer was built without giflib (FLOOD_GIF)";
#endif
    if (needs) {
        std::fprintf(stderr, "flood-viewer: %s\n%s", needs, kUsage);
        return 2 + 1;
    }
    if (a.exporting()) {
        a.exports.width = a.width, a.exports.height = a.height;
        if (!a.sizeGiven) a.exports.width = 1280, a.exports.height = 800;
        a.width = 1280, a.height = 800;  // the hidden window's; the pictures have their own size
    }
    return 0;
}

}  // namespace flood::view
