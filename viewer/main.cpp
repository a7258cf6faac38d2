// flood-viewer: replays the flooding triangulation of a polygon step by step.
//   flood-viewer [FILE] [--feature N] [--layer NAME] [--where SQL] [--step N]
//                [--screenshot OUT.png] [--size WxH] [--scale S] [--presenter] [--theme light|dark]
//   flood-viewer FILE --export-gif OUT.gif [--steps A:B] [--every K] [--fps F] [--caption]
// Without a display it prints a summary of the run instead and says how to get pictures.
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "export_job.h"
#include "model.h"
#include "panels.h"
#include "platform_glfw.h"
#include "renderer.h"
#include "transcript.h"

using namespace flood;
using namespace flood::view;

namespace {

struct Args {
    std::string file;
    long step = -1;               // -1: where the model lands by itself
    std::vector<uint32_t> steps;  // every --step in order: one frame at each before the last
    std::string screenshot;
    int width = 1280, height = 800;
    bool bench = false;      // measure open, seek and frame times, print them, exit
    bool showError = false;  // open in the error view (as the E key does)
    long feature = -1;       // --feature N: that feature of a FeatureCollection
    float scale = 0;         // --scale S: the content scale, instead of the monitor's
    bool presenter = false;  // --presenter: start in presenter view (Tab)
    bool themeGiven = false;
    Theme theme = Theme::Dark;  // --theme
    bool printLayout = false;   // --print-layout: where the caption and toolbar end were
    struct Press {
        int key;
        bool ctrl;
    };
    std::vector<Press> presses;  // --press KEY: presenter keys pressed before a screenshot
    bool canvasOnly = false;     // --canvas-only: --screenshot renders the canvas alone
    bool sizeGiven = false;
    ExportSettings exports;  // canvas-only PNG, SVG, GIF, PNG sequence (export.h)
    bool rangeGiven = false, everyGiven = false, fpsGiven = false;
    bool exporting() const {
        return !exports.png.empty() || !exports.svg.empty() || exports.animated();
    }
    std::string layer, where;  // --layer, --where: a GIS dataset's layer and feature filter
    bool predicates = false;   // --predicates: the predicate inspector open
    bool gorgeFocus = false;   // --gorge-focus: "current gorge only"
    bool mouse = false;        // --mouse X,Y (screenshots): the pointer there, for hover pictures
    float mouseX = 0, mouseY = 0;
    std::string up;  // --up: flood along this direction, with the dial open
};

// --press names: the presenter keys, so a screenshot can show what they do.
bool pressNamed(const std::string& name, Args::Press& p) {
    if (name == "tab") return p = {platform::kKeyTab, false}, true;
    if (name == "f11") return p = {platform::kKeyF11, false}, true;
    if (name == "ctrl+plus") return p = {platform::kKeyPlus[0], true}, true;
    if (name == "ctrl+minus") return p = {platform::kKeyMinus[0], true}, true;
    if (name == "ctrl+0") return p = {platform::kKeyZero[0], true}, true;
    return false;
}

const char* const kUsage =
    "usage: flood-viewer [FILE] [--feature N] [--layer NAME] [--where SQL] [--step N]\n"
    "                    [--show-error] [--predicates] [--gorge-focus] [--screenshot OUT.png]\n"
    "                    [--size WxH] [--mouse X,Y] [--scale S] [--presenter] [--theme "
    "light|dark]\n"
    "                    [--up DIRECTION]\n"
    "       flood-viewer FILE --screenshot OUT.png|OUT.svg --canvas-only [--size WxH] [--caption]\n"
    "       flood-viewer FILE --export-gif OUT.gif|--export-png-dir DIR [--steps A:B] [--every K]\n"
    "                    [--fps F] [--caption] [--size WxH]\n"
    "  FILE              polygon (GeoJSON, ring arrays or WKT) or a trace from `flood trace`\n"
    "                    (*.jsonl); default: polygons/paper-figure-7.json\n"
    "  --feature N       open feature N (0-based, as `flood check` numbers them) of a\n"
    "                    FeatureCollection; no such feature: exit 2\n"
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
    "  --print-layout    with --screenshot: print where the caption and the toolbar's last\n"
    "                    button were drawn (x y w h, logical pixels)\n"
    "  --press KEY       with --screenshot: press tab, f11, ctrl+plus, ctrl+minus or ctrl+0\n"
    "                    first (repeat it for more, one frame apart)\n"
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
    "                    (with --feature N: the Nth of those)\n"
    "  --predicates      open the predicate inspector; --gorge-focus: current gorge only\n"
    "  --mouse X,Y       with --screenshot: the pointer at X,Y (what hovering there shows)\n"
    "  --bench           time opening, seeking and drawing (hidden window), print, exit\n"
    "  --up DIRECTION    flood along +y, -y, +x, -x, an angle in degrees (90 is +y) or X,Y,\n"
    "                    with the direction dial open (it compares with the +y run)\n"
    "a file that cannot be written: exit 8, nothing half-written left\n"
    "keys in the viewer: F1 or ?\n";

// Returns 0 to go on, or an exit code + 1 (so 1 means "exit 0", e.g. after --help).
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
        } else if (s == "--step") {
            const char* v = value("--step");
            char* end = nullptr;
            if (!v || (a.step = std::strtol(v, &end, 10), *end != 0) || a.step < 0) {
                if (v)
                    std::fprintf(stderr, "flood-viewer: --step wants a number >= 0, got '%s'\n", v);
                return 2 + 1;
            }
            a.steps.push_back(uint32_t(std::min<long>(a.step, ~0u)));
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
                                 "flood-viewer: --press wants tab, f11, ctrl+plus, ctrl+minus or "
                                 "ctrl+0, got '%s'\n",
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

// No display: say so, then print what can be known without one.
int printSummary(const std::string& why, Model& model, const Args& args) {
    std::printf("flood-viewer: %s.\n", why.c_str());
    if (!args.screenshot.empty() || args.exports.animated()) {
        std::string out = !args.screenshot.empty()    ? args.screenshot
                          : !args.exports.gif.empty() ? args.exports.gif
                                                      : args.exports.pngDir;
        std::fprintf(stderr,
                     "flood-viewer: cannot write %s without a display; try\n"
                     "  xvfb-run -a flood-viewer %s --screenshot %s\n",
                     out.c_str(), args.file.c_str(), out.c_str());
        return 1;
    }
    if (model.polygon().vertices.empty()) {
        std::printf("%s\n", model.inputDiagnostic().message.empty()
                                ? "no polygon to summarise (polygons/ is empty)"
                                : model.inputDiagnostic().message.c_str());
        return model.exitCode();
    }
    const Trace& t = model.trace();
    std::printf("Summary of %s:\n", model.path().c_str());
    std::printf("  %zu vertices in %zu rings, %zu events, %zu triangles\n",
                t.polygon.vertices.size(), t.polygon.rings.size(), t.events.size(),
                t.triangles.size());
    std::printf("  verdict: %s\n", model.verdict().c_str());
    std::printf("  transcript: %s\n", transcript(model.trace().events).c_str());
    std::printf(
        "For more without a display:\n"
        "  flood transcript %s      every event, one per line\n"
        "  flood trace %s           the recorded trace\n"
        "  xvfb-run -a flood-viewer %s --step N --screenshot out.png\n",
        model.path().c_str(), model.path().c_str(), model.path().c_str());
    return 0;
}

double now() {  // seconds; works before the window system is up
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// --bench: what a user waits for on a big polygon, in milliseconds. Frames are timed in three
// parts: build (the viewer's own CPU work: model, overlay, labels, ImGui panels), submit
// (the GL calls; under Mesa llvmpipe this includes the software vertex processing, done in
// the calling thread) and all (after glFinish: the rasteriser threads are done too).
struct BenchStats {
    double openMs = 0, firstFrameMs = 0;
    size_t keyframes = 0, keyframeBytes = 0;
    std::vector<double> seeks;  // seconds
    struct Frames {
        std::vector<double> build, submit, all;  // seconds, from the frame's start
    } step, pan;  // a new random step every frame; the same step while the camera moves
    uint64_t rng = 0x9E3779B97F4A7C15ull;
    uint32_t steps = 0;
    static constexpr int kFrames = 60;
    uint32_t nextStep() {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        return steps ? uint32_t((rng >> 33) % (steps + 1)) : 0;
    }
    static double pct(std::vector<double> v, double q) {
        if (v.empty()) return 0;
        std::sort(v.begin(), v.end());
        return v[std::min(v.size() - 1, size_t(q * double(v.size())))] * 1e3;
    }
    static void frames(const char* what, const Frames& f) {
        std::printf(
            "bench: frame, %s (%zu frames), median / max ms:\n"
            "bench:   build (viewer CPU) %.2f / %.2f; + GL submit %.2f / %.2f; + glFinish %.2f / "
            "%.2f\n",
            what, f.build.size(), pct(f.build, 0.5), pct(f.build, 1.0), pct(f.submit, 0.5),
            pct(f.submit, 1.0), pct(f.all, 0.5), pct(f.all, 1.0));
    }
    void print(const Model& model) const {
        std::printf("bench: %s: %zu vertices, %u events, %zu triangles\n", model.path().c_str(),
                    model.polygon().vertices.size(), steps, model.trace().triangles.size());
        std::printf("bench: open (read, validate, flood with trace, replay keyframes): %.0f ms\n",
                    openMs);
        std::printf("bench: keyframes: %zu, %.1f MB\n", keyframes, keyframeBytes / 1e6);
        std::printf("bench: first frame (canvas buffers built and uploaded): %.0f ms\n",
                    firstFrameMs);
        std::printf(
            "bench: seek to a random step: median %.3f ms, 99%% %.3f ms, max %.3f ms (%zu seeks)\n",
            pct(seeks, 0.5), pct(seeks, 0.99), pct(seeks, 1.0), seeks.size());
        frames("full zoom-out, new random step every frame", step);
        frames("full zoom-out, panning at a fixed step", pan);
    }
};

BenchStats benchOpenAndSeek(Model& model, double openSeconds) {
    BenchStats b;
    b.openMs = openSeconds * 1e3;
    b.steps = model.steps();
    b.keyframes = model.keyframeCount();
    b.keyframeBytes = model.keyframeBytes();
    for (int i = 0; i < 1000; ++i) {
        uint32_t step = b.nextStep();
        double t0 = now();
        model.seek(step);
        b.seeks.push_back(now() - t0);
    }
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    Args args;
    if (int rc = parseArgs(argc, argv, args)) return rc - 1;
    if (args.file.empty()) args.file = defaultPolygonPath();

    Model model;
    // Screenshots stay reproducible: they neither read nor write the recent list or settings.
    std::string recentFile, settingsFile;
    ViewerSettings settings;
    if (args.screenshot.empty()) {
        const char* xdg = std::getenv("XDG_CONFIG_HOME");
        const char* home = std::getenv("HOME");
        std::string dir;
        if (xdg && *xdg) dir = std::string(xdg) + "/flood-viewer/";
        else if (home && *home) dir = std::string(home) + "/.config/flood-viewer/";
        if (!dir.empty()) recentFile = dir + "recent.txt", settingsFile = dir + "settings.txt";
        if (!recentFile.empty()) model.loadRecent(recentFile);
        model.recentPath = recentFile;  // saved on every open
        if (!settingsFile.empty()) settings = loadSettings(settingsFile);
    }
    if (args.themeGiven) settings.theme = args.theme;
    palette::setTheme(settings.theme);
    model.gisLayer = args.layer, model.gisWhere = args.where;
    double openStart = now();
    if (args.feature >= 0) {
        // A feature that cannot be opened is the answer: say so before any window.
        if (!model.openFeature(args.file, size_t(args.feature))) {
            std::fprintf(stderr, "flood-viewer: %s\n", model.openDiagnostic().message.c_str());
            return int(model.openDiagnostic().status);
        }
    } else if (!args.file.empty()) {
        model.open(args.file);
    }
    if (!args.up.empty()) {
        Up d;
        std::string why;
        parseUp(args.up, d, why);  // parseArgs has accepted it
        model.setUp(d);
    }
    double openSeconds = now() - openStart;
    if (!args.steps.empty()) model.seek(args.steps.front());
    if (args.exporting() && args.exports.animated()) {
        // A range past the flood's end is a mistake to say, not to clamp silently.
        const ExportSettings& e = args.exports;
        uint32_t n = model.steps();
        if (e.first > n || (e.last != kNone && e.last > n)) {
            std::fprintf(stderr, "flood-viewer: --steps %u:%u: %s has %u steps (0..%u)\n", e.first,
                         e.last == kNone ? n : e.last, args.file.c_str(), n, n);
            return int(Status::Usage);
        }
    }
    BenchStats bench;
    if (args.bench) bench = benchOpenAndSeek(model, openSeconds);

    std::string error;
    if (!platform::initialize(&error)) return printSummary(error, model, args);

    const bool shot = !args.screenshot.empty() || args.bench || args.exporting();
    platform::WindowOptions wo;
    wo.width = args.width, wo.height = args.height, wo.hidden = shot;
    auto title = [&] {
        return "flood-viewer — " +
               (model.path().empty() ? std::string("no polygon") : model.path());
    };
    wo.title = title();
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is tiled by code; nothing worth saving
    if (!platform::createWindow(wo, &error)) {
        ImGui::DestroyContext();
        platform::terminate();
        return printSummary(error, model, args);
    }
    // Owned by pointer so it is torn down while the GL context still exists.
    auto rendererOwner = std::make_unique<Renderer>();
    Renderer& renderer = *rendererOwner;
    if (!imguiGlInit() || !renderer.init(&error)) {
        std::fprintf(stderr, "flood-viewer: %s\n", error.c_str());
        return int(Status::Internal);
    }
    // Screenshots use scale 1 (or --scale) so the same command gives the same pixels on
    // every machine.
    Ui ui(model, renderer);
    ui.uiScale.setContentScale(args.scale > 0 ? args.scale : shot ? 1.f : platform::contentScale());
    if (!shot) ui.uiScale.setZoomStep(settings.zoomStep);
    ui.theme = settings.theme;
    ui.presenter = args.presenter;
    applyStyle(ui);
    uint64_t styled = ui.uiScale.generation();
    Theme styledTheme = ui.theme;
    ui.showPredicates = args.predicates;
    ui.sceneOptions.gorgeFocus = args.gorgeFocus;
    // A picture shows the invariant lane complete (and the landing on its first violation).
    if (shot) model.waitForInvariants();
    ui.showDirection = !args.up.empty();

    int exitCode = 0;
    uint64_t titled = model.generation();
    double lastTime = platform::time();
    for (int frame = 0; !platform::shouldClose(); ++frame) {
        if (shot || model.playing) platform::pollEvents();
        else platform::waitEvents(0.25);  // idle: wake on input, or 4 times a second
        for (const auto& path : platform::takeDroppedPaths()) {
            model.open(path);
            ui.message =
                model.openDiagnostic().ok() ? "opened " + path : model.openDiagnostic().message;
        }
        // The title names the file loaded (a failed open keeps the previous one).
        if (model.generation() != titled) {
            titled = model.generation();
            platform::setTitle(title());
        }
        // Between frames: a new monitor scale, Ctrl +/-/0 or a theme chosen in the toolbar.
        if (float s; platform::takeContentScaleChange(&s) && args.scale <= 0 && !shot)
            ui.uiScale.setContentScale(s);
        if (ui.theme != palette::theme()) {
            palette::setTheme(ui.theme);
            ui.canvas.generation = ~0ull;  // the canvas buffers hold the old theme's colours
        }
        if (styled != ui.uiScale.generation() || styledTheme != ui.theme) {
            applyStyle(ui);
            ui.canvas.thinKey = {};  // marker thinning cells follow the scale
            styled = ui.uiScale.generation(), styledTheme = ui.theme;
            // Remembered at once, as Recent is on every open.
            if (!settingsFile.empty())
                saveSettings(settingsFile, {ui.theme, ui.uiScale.zoomStep()});
        }
        ui.scale = ui.uiScale.value();
        const float scale = ui.scale;
        // --press: key i goes down at frame 2i and up at 2i + 1, as a hand would press it.
        if (shot && !args.presses.empty() && size_t(frame / 2) < args.presses.size()) {
            const Args::Press& p = args.presses[size_t(frame / 2)];
            io.KeysDown[p.key] = frame % 2 == 0;
            io.KeyCtrl = p.ctrl && frame % 2 == 0;
        }
        imguiGlNewFrame();
        platform::newFrame();
        if (shot && args.mouse) io.MousePos = ImVec2(args.mouseX, args.mouseY);
        ImGui::NewFrame();
        Vec2 size = platform::windowSize();
        const Rect canvasWas = ui.layout.canvas;
        ui.layout = ui.presenter ? presenterLayout(size.x, size.y, ui.captionHeight)
                                 : computeLayout(size.x, size.y, scale, ui.bottomWanted);
        // While the first frames settle the layout (the timeline's and the caption's heights are
        // measured) the camera is fitted to the canvas it ends up with; the error view keeps its
        // own zoom.
        const Rect& c = ui.layout.canvas;
        bool moved =
            c.x != canvasWas.x || c.y != canvasWas.y || c.w != canvasWas.w || c.h != canvasWas.h;
        if (frame > 0 && frame < 3 && moved && !model.errorView) model.needsFit = true;
        if (frame == 0 && args.showError) {
            model.camera.setViewport(ui.layout.canvas);
            model.showError();
            if (!args.steps.empty()) model.seek(args.steps.front());
        }

        double frameStart = now();
        // Bench: frames 3..62 step to a random step, 63..122 pan by a pixel at a fixed one.
        const int benchPhase = frame < 3 ? 0 : (frame - 3) / BenchStats::kFrames + 1;
        if (shot && size_t(frame) < args.steps.size()) model.seek(args.steps[size_t(frame)]);
        if (args.bench && benchPhase == 1) model.seek(bench.nextStep());
        if (args.bench && benchPhase == 2) model.camera.pan(frame % 2 ? 1 : -1, 0);
        if (!shot) handleShortcuts(ui);
        if (!shot || !args.presses.empty()) handlePresenterKeys(ui);
        drawCanvas(ui);
        if (ui.presenter) {
            drawCaption(ui);
        } else {
            drawTimeline(ui);
            drawStateMachine(ui);
            drawDecision(ui);
            drawPredicates(ui);
            drawStateTable(ui);
            drawBreakpoints(ui);
            drawEvents(ui);
            drawTranscript(ui);
            drawOpen(ui);
            drawShrink(ui);
            drawHelp(ui);
            drawExport(ui);
            drawTodo(ui);
            drawDirection(ui);
        }
        ImGui::Render();

        double built = now() - frameStart;
        int fbW = 0, fbH = 0;
        platform::framebufferSize(&fbW, &fbH);
        renderer.render(size, fbW, fbH, ui.layout.canvas, palette::kBackground, ui.canvas.view);
        imguiGlRender();

        if (args.bench) {
            double submitted = now() - frameStart;
            renderer.finish();
            double all = now() - frameStart;
            if (frame == 0) bench.firstFrameMs = all * 1e3;
            for (auto* f : {benchPhase == 1 ? &bench.step : benchPhase == 2 ? &bench.pan : nullptr})
                if (f)
                    f->build.push_back(built), f->submit.push_back(submitted),
                        f->all.push_back(all);
            if (benchPhase == 3) {
                bench.print(model);
                platform::requestClose();
            }
        }
        // ImGui places windows on the 2nd frame; the 3rd is the first settled one.
        // Each extra --step adds a frame.
        // Each --press takes two frames, and the layout two more to settle after the last.
        const int shotFrame = 2 + int(args.steps.empty() ? 0 : args.steps.size() - 1) +
                              (args.presses.empty() ? 0 : 2 * int(args.presses.size()) + 2);
        if (args.exporting() && frame == shotFrame) {
            // The canvas alone, offscreen: run the whole export now.
            ExportJob job(ui, args.exports);
            while (job.advance(0)) {
            }
            bool ok = job.status() == Status::Ok;
            std::fprintf(ok ? stdout : stderr, "flood-viewer: %s\n", job.message().c_str());
            exitCode = ok ? model.exitCode() : int(job.status());
            platform::requestClose();
        }
        std::string png = !args.bench && !args.exporting() && shot && frame == shotFrame
                              ? args.screenshot
                              : ui.pngRequest;
        if (!png.empty()) {
            std::vector<uint8_t> pixels;
            bool ok =
                renderer.readPixels(fbW, fbH, pixels) && writePng(png, fbW, fbH, pixels, &error);
            ui.message = ok ? "wrote " + png : error;
            ui.pngRequest.clear();
            if (shot) {
                std::fprintf(ok ? stdout : stderr, "flood-viewer: %s\n", ui.message.c_str());
                for (auto [name, r] :
                     {std::pair{"caption", ui.captionRect}, {"toolbar-end", ui.toolbarEnd}})
                    if (args.printLayout && r.w > 0)
                        std::printf("flood-viewer: layout %s %.0f %.0f %.0f %.0f\n", name, r.x, r.y,
                                    r.w, r.h);
                // The picture is written; the exit code still says what the input was.
                exitCode = !ok ? int(Status::WriteFailed) : model.exitCode();
                platform::requestClose();
            }
        }
        // The Export panel's export: a slice of it each frame, so the window stays live.
        if (ui.exportJob && !ui.exportJob->advance(1.0 / 30)) {
            ui.exportNote = ui.exportJob->message();
            ui.exportFailed = ui.exportJob->status() != Status::Ok;
            ui.message = ui.exportNote;
            ui.exportJob.reset();
        }
        platform::swapBuffers();

        double now = platform::time();
        if (!shot) model.advance(now - lastTime);
        lastTime = now;
    }

    if (!recentFile.empty()) model.saveRecent(recentFile);
    ui.exportJob.reset();  // its framebuffer goes while the GL context exists
    rendererOwner.reset();
    imguiGlShutdown();
    platform::destroyWindow();
    ImGui::DestroyContext();
    platform::terminate();
    return exitCode;
}
