// flood-viewer: replays the flooding triangulation of a polygon step by step.
//   flood-viewer [FILE] [--feature N] [--step N] [--screenshot OUT.png] [--size WxH]
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

#include "model.h"
#include "transcript.h"
#include "panels.h"
#include "platform_glfw.h"
#include "renderer.h"

using namespace flood;
using namespace flood::view;

namespace {

struct Args {
    std::string file;
    long step = -1;  // -1: where the model lands by itself
    std::vector<uint32_t> steps;  // every --step in order: one frame at each before the last
    std::string screenshot;
    int width = 1280, height = 800;
    bool bench = false;  // measure open, seek and frame times, print them, exit
    bool showError = false;  // open in the error view (as the E key does)
    long feature = -1;       // --feature N: that feature of a FeatureCollection
    std::string up;          // --up: flood along this direction, with the dial open
};

const char* const kUsage =
    "usage: flood-viewer [FILE] [--feature N] [--step N] [--show-error] [--screenshot OUT.png]\n"
    "                    [--size WxH] [--up DIRECTION]\n"
    "  FILE              polygon (GeoJSON, ring arrays or WKT) or a trace from `flood trace`\n"
    "                    (*.jsonl); default: polygons/paper-figure-7.json\n"
    "  --feature N       open feature N (0-based, as `flood check` numbers them) of a\n"
    "                    FeatureCollection; no such feature: exit 2\n"
    "  --step N          show the state after N events (repeat it to draw each in turn:\n"
    "                    --step 40 --step 5 shows 5 after a frame at 40)\n"
    "  --show-error      start in the error view (zoomed to the culprits), as the E key\n"
    "  --screenshot OUT  render once in a hidden window, write OUT as PNG and exit; the exit\n"
    "                    code is the CLI's: 3 unreadable, 4 invalid, 5 forbidden, 6 checker\n"
    "  --size WxH        window size in pixels (default 1280x800)\n"
    "  --bench           time opening, seeking and drawing (hidden window), print, exit\n"
    "  --up DIRECTION    flood along +y, -y, +x, -x, an angle in degrees (90 is +y) or X,Y,\n"
    "                    with the direction dial open (it compares with the +y run)\n"
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
                if (v) std::fprintf(stderr, "flood-viewer: --step wants a number >= 0, got '%s'\n", v);
                return 2 + 1;
            }
            a.steps.push_back(uint32_t(std::min<long>(a.step, ~0u)));
        } else if (s == "--feature") {
            const char* v = value("--feature");
            char* end = nullptr;
            if (!v || (a.feature = std::strtol(v, &end, 10), *end != 0) || a.feature < 0) {
                if (v) std::fprintf(stderr, "flood-viewer: --feature wants a number >= 0, got '%s'\n", v);
                return 2 + 1;
            }
        } else if (s == "--show-error") {
            a.showError = true;
        } else if (s == "--bench") {
            a.bench = true;
        } else if (s == "--up") {
            const char* v = value("--up");
            Up d;
            std::string why;
            if (v && !parseUp(v, d, why)) std::fprintf(stderr, "flood-viewer: --up: %s\n", why.c_str());
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
                if (v) std::fprintf(stderr, "flood-viewer: --size wants WxH (64..16384), got '%s'\n", v);
                return 2 + 1;
            }
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
    return 0;
}

// No display: say so, then print what can be known without one.
int printSummary(const std::string& why, Model& model, const Args& args) {
    std::printf("flood-viewer: %s.\n", why.c_str());
    if (!args.screenshot.empty()) {
        std::fprintf(stderr, "flood-viewer: cannot write %s without a display; try\n"
                             "  xvfb-run -a flood-viewer %s --screenshot %s\n",
                     args.screenshot.c_str(), args.file.c_str(), args.screenshot.c_str());
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
    std::printf("For more without a display:\n"
                "  flood transcript %s      every event, one per line\n"
                "  flood trace %s           the recorded trace\n"
                "  xvfb-run -a flood-viewer %s --step N --screenshot out.png\n",
                model.path().c_str(), model.path().c_str(), model.path().c_str());
    return 0;
}

double now() {  // seconds; works before the window system is up
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// --bench: what a user waits for on a big polygon, in milliseconds. Frames are timed in three
// parts: build (the viewer's own CPU work: model, overlay, labels, ImGui panels), submit
// (the GL calls; under Mesa llvmpipe this includes the software vertex processing, done in
// the calling thread) and all (after glFinish: the rasteriser threads are done too).
struct BenchStats {
    double openMs = 0, firstFrameMs = 0;
    size_t keyframes = 0, keyframeBytes = 0;
    std::vector<double> seeks;                    // seconds
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
        std::printf("bench: frame, %s (%zu frames), median / max ms:\n"
                    "bench:   build (viewer CPU) %.2f / %.2f; + GL submit %.2f / %.2f; + glFinish %.2f / %.2f\n",
                    what, f.build.size(), pct(f.build, 0.5), pct(f.build, 1.0), pct(f.submit, 0.5),
                    pct(f.submit, 1.0), pct(f.all, 0.5), pct(f.all, 1.0));
    }
    void print(const Model& model) const {
        std::printf("bench: %s: %zu vertices, %u events, %zu triangles\n", model.path().c_str(),
                    model.polygon().vertices.size(), steps, model.trace().triangles.size());
        std::printf("bench: open (read, validate, flood with trace, replay keyframes): %.0f ms\n", openMs);
        std::printf("bench: keyframes: %zu, %.1f MB\n", keyframes, keyframeBytes / 1e6);
        std::printf("bench: first frame (canvas buffers built and uploaded): %.0f ms\n", firstFrameMs);
        std::printf("bench: seek to a random step: median %.3f ms, 99%% %.3f ms, max %.3f ms (%zu seeks)\n",
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
    // Screenshots stay reproducible: they neither read nor write the recent list.
    std::string recentFile;
    if (args.screenshot.empty()) {
        const char* xdg = std::getenv("XDG_CONFIG_HOME");
        const char* home = std::getenv("HOME");
        if (xdg && *xdg) recentFile = std::string(xdg) + "/flood-viewer/recent.txt";
        else if (home && *home) recentFile = std::string(home) + "/.config/flood-viewer/recent.txt";
        if (!recentFile.empty()) model.loadRecent(recentFile);
        model.recentPath = recentFile;  // saved on every open
    }
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
    BenchStats bench;
    if (args.bench) bench = benchOpenAndSeek(model, openSeconds);

    std::string error;
    if (!platform::initialize(&error)) return printSummary(error, model, args);

    const bool shot = !args.screenshot.empty() || args.bench;
    platform::WindowOptions wo;
    wo.width = args.width, wo.height = args.height, wo.hidden = shot;
    auto title = [&] {
        return "flood-viewer — " + (model.path().empty() ? std::string("no polygon") : model.path());
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
    // Screenshots use scale 1 so the same command gives the same pixels on every machine.
    float scale = shot ? 1.f : platform::contentScale();
    ImFontConfig font;
    font.SizePixels = 13.f * scale;
    io.Fonts->AddFontDefault(&font);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().ScaleAllSizes(scale);

    Ui ui(model, renderer);
    ui.scale = scale;
    ui.showDirection = !args.up.empty();

    int exitCode = 0;
    uint64_t titled = model.generation();
    double lastTime = platform::time();
    for (int frame = 0; !platform::shouldClose(); ++frame) {
        if (shot || model.playing) platform::pollEvents();
        else platform::waitEvents(0.25);  // idle: wake on input, or 4 times a second
        for (const auto& path : platform::takeDroppedPaths()) {
            model.open(path);
            ui.message = model.openDiagnostic().ok() ? "opened " + path : model.openDiagnostic().message;
        }
        // The title names the file loaded (a failed open keeps the previous one).
        if (model.generation() != titled) {
            titled = model.generation();
            platform::setTitle(title());
        }
        imguiGlNewFrame();
        platform::newFrame();
        ImGui::NewFrame();
        Vec2 size = platform::windowSize();
        ui.layout = computeLayout(size.x, size.y, scale);
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
        drawCanvas(ui);
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
        drawDirection(ui);
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
                if (f) f->build.push_back(built), f->submit.push_back(submitted), f->all.push_back(all);
            if (benchPhase == 3) {
                bench.print(model);
                platform::requestClose();
            }
        }
        // ImGui places windows on the 2nd frame; the 3rd is the first settled one.
        // Each extra --step adds a frame.
        const int shotFrame = 2 + int(args.steps.empty() ? 0 : args.steps.size() - 1);
        std::string png = !args.bench && shot && frame == shotFrame ? args.screenshot : ui.pngRequest;
        if (!png.empty()) {
            std::vector<uint8_t> pixels;
            bool ok = renderer.readPixels(fbW, fbH, pixels) && writePng(png, fbW, fbH, pixels, &error);
            ui.message = ok ? "wrote " + png : "cannot write " + png + ": " + error;
            ui.pngRequest.clear();
            if (shot) {
                std::fprintf(ok ? stdout : stderr, "flood-viewer: %s\n", ui.message.c_str());
                // The picture is written; the exit code still says what the input was.
                exitCode = !ok ? 1 : model.exitCode();
                platform::requestClose();
            }
        }
        platform::swapBuffers();

        double now = platform::time();
        if (!shot) model.advance(now - lastTime);
        lastTime = now;
    }

    if (!recentFile.empty()) model.saveRecent(recentFile);
    rendererOwner.reset();
    imguiGlShutdown();
    platform::destroyWindow();
    ImGui::DestroyContext();
    platform::terminate();
    return exitCode;
}
