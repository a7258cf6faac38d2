// flood-viewer: replays the flooding triangulation of a polygon step by step.
//   flood-viewer [FILE] [--feature N] [--layer NAME] [--where SQL] [--step N]
//                [--screenshot OUT.png] [--size WxH] [--scale S] [--presenter] [--theme light|dark]
//   flood-viewer FILE --export-gif OUT.gif [--steps A:B] [--every K] [--fps F] [--caption]
// Without a display it prints a summary of the run instead and says how to get pictures.
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "args.h"
#include "export_job.h"
#include "flood/teach/transcript.h"
#include "model.h"
#include "panels.h"
#include "platform_glfw.h"
#include "renderer.h"
#include "view_fit.h"

using namespace flood;
using namespace flood::view;

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
// What the page shows, for its tests (tests/web/page_test.mjs): Module._flood_web_step() ...
namespace {
const Model* g_shown = nullptr;
const Ui* g_ui = nullptr;
int g_frames = 0, g_scanFrames = 0;
}  // namespace
extern "C" {
EMSCRIPTEN_KEEPALIVE int flood_web_frames() { return g_frames; }
EMSCRIPTEN_KEEPALIVE int flood_web_step() { return g_shown ? int(g_shown->step()) : -1; }
EMSCRIPTEN_KEEPALIVE int flood_web_steps() { return g_shown ? int(g_shown->steps()) : -1; }
EMSCRIPTEN_KEEPALIVE int flood_web_vertices() {
    return g_shown ? int(g_shown->polygon().vertices.size()) : -1;
}
EMSCRIPTEN_KEEPALIVE int flood_web_presenter() { return g_ui ? int(g_ui->presenter) : -1; }
// An open under way (1), in steps between frames (viewer/open_job.h).
EMSCRIPTEN_KEEPALIVE int flood_web_opening() { return g_shown ? int(g_shown->opening()) : -1; }
// The invariant scan still running (1), in slices between frames (viewer/job.h), and the
// frames drawn so far while one ran (counted here: a test's sampling could miss them).
EMSCRIPTEN_KEEPALIVE int flood_web_scanning() {
    return g_shown ? int(!g_shown->invariantsDone()) : -1;
}
EMSCRIPTEN_KEEPALIVE int flood_web_scan_frames() { return g_scanFrames; }
EMSCRIPTEN_KEEPALIVE const char* flood_web_recent(int i) {  // the Open panel's Recent list
    if (!g_shown || i < 0 || size_t(i) >= g_shown->recentFiles().size()) return "";
    return g_shown->recentFiles()[size_t(i)].c_str();
}
// ... and where things were drawn in the last frame, as --print-layout prints them: component
// k (x, y, w, h) of the canvas (what = 0), the caption (1), the Transcript's Copy button (2)
// or the Open panel's gallery row i (3 + i); -1 when it is not shown. (Numbers, not names: Module.ccall answers a Promise under
// ASYNCIFY, a direct call does not.)
EMSCRIPTEN_KEEPALIVE double flood_web_rect(int what, int k) {
    if (!g_ui || what < 0 || k < 0 || k > 3) return -1;
    const std::vector<Rect>& rows = g_ui->openPanel.galleryRows;
    const Rect* r = what == 0                        ? &g_ui->layout.canvas
                    : what == 1                      ? &g_ui->captionRect
                    : what == 2                      ? &g_ui->transcriptCopy
                    : size_t(what - 3) < rows.size() ? &rows[size_t(what - 3)]
                                                     : nullptr;
    if (!r || r->w <= 0) return -1;
    return k == 0 ? r->x : k == 1 ? r->y : k == 2 ? r->w : r->h;
}
}
#endif

namespace {

// No display: say so, then print what can be known without one.
int printSummary(const std::string& why, Model& model, const Args& args) {
    model.waitOpen();  // the window's open, begun in the background: its run is summarised
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
        "  flood transcript --narrate %s  every event, one per line\n"
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

// The files a session reads and writes in the user's config directory.
struct ConfigFiles {
    std::string recent, settings;
};

ConfigFiles configFiles() {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    std::string dir;
    if (xdg && *xdg) dir = std::string(xdg) + "/flood-viewer/";
    else if (home && *home) dir = std::string(home) + "/.config/flood-viewer/";
    if (dir.empty()) return {};
    return {dir + "recent.txt", dir + "settings.txt"};
}

// Opens what the arguments name, flooded along --up: a FILE in the `background` (the window's
// open: followOpen finishes it), else at once. Returns 0, or the exit code when a feature
// cannot be opened.
int openArgs(Model& model, const Args& args, bool background) {
    model.gisLayer = args.layer, model.gisWhere = args.where;
    if (background && args.feature < 0 && !args.file.empty()) {
        if (!args.up.empty()) {
            Up d;
            std::string why;
            parseUp(args.up, d, why);  // parseArgs has accepted it
            model.setOpenDirection(d);
        }
        model.openInBackground(args.file);
        return 0;
    }
    if (args.feature >= 0) {
        // A feature that cannot be opened is the answer: say so before any window.
        if (!model.openFeature(args.file, size_t(args.feature))) {
            std::fprintf(stderr, "flood-viewer: %s\n", model.openDiagnostic().message.c_str());
            return int(model.openDiagnostic().status);
        }
    } else if (!args.file.empty()) {
        model.open(args.file);
        // A file that cannot be opened as asked (a --layer it does not have, say) is said
        // here too: a screenshot's window shows it, but a script reads stderr.
        if (!model.openDiagnostic().ok())
            std::fprintf(stderr, "flood-viewer: %s\n", model.openDiagnostic().message.c_str());
    }
    if (!args.up.empty()) {
        Up d;
        std::string why;
        parseUp(args.up, d, why);  // parseArgs has accepted it
        model.setUp(d);
    }
    return 0;
}

// Each frame: what the window's open has ready adopted (model.pollOpen), and once it is done,
// what it says.
void followOpen(Ui& ui) {
    const std::string path = ui.model.openingPath();
    if (ui.model.pollOpen()) noteOpened(ui, path);
}

// FLOOD_VIEWER_HOLD_OPEN=PHASE (tests/gui/open_progress_test.cpp): the command line's FILE
// opens in the background even for --screenshot, held as PHASE ("reading", "validating",
// "flooding", "checking") begins, so the picture shows the open under way. Released (and
// the open cancelled) before the viewer exits.
struct OpenHold {
    std::atomic<bool> reached{false}, released{false};
    std::string phase;
};

bool holdOpen(Model& model, OpenHold& hold) {
    const char* phase = std::getenv("FLOOD_VIEWER_HOLD_OPEN");
    if (!phase || !*phase) return false;
    hold.phase = phase;
    model.openHook = [&hold](const std::string&, OpenPhase p) {
        if (hold.phase != openPhaseName(p)) return;
        hold.reached = true;
        while (!hold.released) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    };
    return true;
}

// Until the held open is at its phase, its outline adopted once read.
void waitForHold(Model& model, const OpenHold& hold) {
    while (!hold.reached && model.opening()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        model.pollOpen();
    }
    model.pollOpen();
}

// An export's --steps range past the flood's end is a mistake to say, not to clamp silently.
bool exportRangeFits(const Model& model, const Args& args) {
    if (!args.exporting() || !args.exports.animated()) return true;
    const ExportSettings& e = args.exports;
    uint32_t n = model.steps();
    if (e.first <= n && (e.last == kNone || e.last <= n)) return true;
    std::fprintf(stderr, "flood-viewer: --steps %u:%u: %s has %u steps (0..%u)\n", e.first,
                 e.last == kNone ? n : e.last, args.file.c_str(), n, n);
    return false;
}

std::string windowTitle(const Model& model) {
    return "flood-viewer — " + (model.path().empty() ? std::string("no polygon") : model.path());
}

// What ImGui is styled for, and where the choice is remembered ("": nowhere).
struct Styled {
    uint64_t scale = ~0ull;  // UiScale::generation()
    Theme theme = Theme::Dark;
    std::string settingsFile;
};

// Between frames: a new monitor scale (`followMonitor`), Ctrl +/-/0 or a theme chosen in the
// toolbar restyle ImGui; the choice is remembered at once, as Recent is on every open.
void restyle(Ui& ui, Styled& styled, bool followMonitor) {
    if (float s; platform::takeContentScaleChange(&s) && followMonitor)
        ui.uiScale.setContentScale(s);
    if (ui.theme != palette::theme()) {
        palette::setTheme(ui.theme);
        ui.canvas.generation = ~0ull;  // the canvas buffers hold the old theme's colours
    }
    if (styled.scale != ui.uiScale.generation() || styled.theme != ui.theme) {
        applyStyle(ui);
        ui.canvas.thinKey = {};  // marker thinning cells follow the scale
        styled.scale = ui.uiScale.generation(), styled.theme = ui.theme;
        if (!styled.settingsFile.empty() &&
            saveSettings(styled.settingsFile, {ui.theme, ui.uiScale.zoomStep()}))
            platform::persistConfig();
    }
    ui.scale = ui.uiScale.value();
}

// What a run adds to a frame it draws: its input and the seeks it makes.
struct FrameInput {
    bool keyboard = false;          // the shortcuts (interactive runs)
    bool presenterKeys = false;     // Tab, F11, Ctrl +/-/0: interactive, or --press
    const ImVec2* mouse = nullptr;  // --mouse: the pointer there
    std::function<void()> seeks;    // once the layout is known, before the panels
};

struct DrawnFrame {
    double start = 0, built = 0;  // when the panels began, and the seconds until ImGui rendered
    int framebufferW = 0, framebufferH = 0;
};

// One frame, the same in every run: the layout, the panels, ImGui and the world drawn.
DrawnFrame drawFrame(Ui& ui, const Args& args, int frame, const FrameInput& input) {
    Model& model = ui.model;
    ImGuiIO& io = ImGui::GetIO();
    imguiGlNewFrame();
    platform::newFrame();
    if (input.mouse) io.MousePos = *input.mouse;
    ImGui::NewFrame();
    Vec2 size = platform::windowSize();
    const Rect canvasWas = ui.layout.canvas;
    ui.layout = ui.presenter ? presenterLayout(size.x, size.y, ui.captionHeight)
                             : computeLayout(size.x, size.y, ui.scale, ui.bottomWanted,
                                             findingsHeight(model, ui.scale));
    // The quiz in presenter view takes a column at the canvas's right (panel_quiz.cpp).
    ui.quizColumn = {};
    if (ui.presenter && model.quizOn()) {
        Rect& canvas = ui.layout.canvas;
        const double w = std::min(canvas.w * 0.4, 460.0 * ui.scale);
        canvas.w -= w;
        ui.quizColumn = {canvas.x + canvas.w, canvas.y, w, canvas.h};
    }
    // Every layout change (the first frames settling, presenter view on or off, F11, a resize,
    // a window over the canvas shown, moved or closed) refits a view that is still the last
    // fit's, into the canvas's free part; a view the user zoomed or panned stays.
    const Rect& c = ui.layout.canvas;
    const std::vector<Rect> overlays = canvasOverlays(ui);
    const bool moved = c.x != canvasWas.x || c.y != canvasWas.y || c.w != canvasWas.w ||
                       c.h != canvasWas.h || !sameRects(overlays, ui.fitOverlays);
    ui.fitOverlays = overlays;
    if (moved && model.viewIsFit()) model.requestFit();
    if (frame == 0 && args.showError) {
        model.setViewport(ui.layout.canvas);
        model.showError();
        if (!args.steps.empty()) model.seek(args.steps.front());
    }

    DrawnFrame drawn;
    drawn.start = now();
    if (input.seeks) input.seeks();
    if (input.keyboard) handleShortcuts(ui);
    if (input.presenterKeys) handlePresenterKeys(ui);
    drawCanvas(ui);
    drawOpening(ui);  // an open under way, in either view
    drawQuiz(ui);     // in either view
    if (ui.presenter) {
        drawCaption(ui);
    } else {
        drawTimeline(ui);
        drawFindings(ui);
        drawStateMachine(ui);
        drawDecision(ui);
        drawPredicates(ui);
        drawStateTable(ui);
        drawBreakpoints(ui);
        if (!model.quizOn()) {  // they list the steps to come: the quiz takes their place
            drawEvents(ui);
            drawTranscript(ui);
        }
        drawOpen(ui);
        drawShrink(ui);
        drawHelp(ui);
        drawExport(ui);
        drawTodo(ui);
        drawDirection(ui);
    }
    ImGui::Render();

    drawn.built = now() - drawn.start;
    platform::framebufferSize(&drawn.framebufferW, &drawn.framebufferH);
    ui.renderer.render(size, drawn.framebufferW, drawn.framebufferH, ui.layout.canvas,
                       palette::kBackground, ui.canvas.view);
    imguiGlRender();
    return drawn;
}

// Writes the back buffer as `png`; the outcome goes to ui.message. True when written.
bool writeFrame(Ui& ui, const DrawnFrame& f, const std::string& png) {
    std::vector<uint8_t> pixels;
    std::string error;
    bool ok = ui.renderer.readPixels(f.framebufferW, f.framebufferH, pixels) &&
              writePng(png, f.framebufferW, f.framebufferH, pixels, &error);
    ui.message = ok ? "wrote " + png : error;
    return ok;
}

// Save PNG (ui.pngRequest): the canvas alone, offscreen at the canvas's size, as it shows it
// (no panel or box over it), written atomically through the export's path; the toast over the
// canvas gives the full path, or why not. True when written.
bool saveCanvasPng(Ui& ui) {
    ExportSettings s;
    s.png = ui.pngRequest;
    ui.pngRequest.clear();
    s.width = std::max(1, int(std::lround(ui.layout.canvas.w)));
    s.height = std::max(1, int(std::lround(ui.layout.canvas.h)));
    ExportJob job(ui, s);
    while (job.advance(0)) {
    }
    const bool ok = job.status() == Status::Ok;
    if (ok) ui.lastExportDir = folderOf(s.png);
    showToast(ui, job.message(), !ok);
    ui.message = job.message();
    return ok;
}

// The interactive run: until the window closes, idle unless something plays or moves.
void runInteractive(Ui& ui, const Args& args, Styled& styled) {
    Model& model = ui.model;
    uint64_t titled = model.generation();
    double lastTime = platform::time();
    FrameInput input;
    input.keyboard = input.presenterKeys = true;
    std::vector<std::string> recentPersisted;  // the model saves the list on every open
    for (int frame = 0; !platform::shouldClose(); ++frame) {
        // Idle (wake on input, or 4 times a second) unless the flood plays or, in the web page,
        // background work runs in slices between frames (viewer/job.h); 30 times a second while
        // an open runs, so its progress moves.
        if (model.playing() || Job::slicesPending()) platform::pollEvents();
        else platform::waitEvents(model.opening() ? 1.0 / 30 : 0.25);
        for (const auto& path : platform::takeDroppedPaths()) {
            model.openInBackground(path);
            ui.message = "opening " + path;
        }
        if (model.recentFiles() != recentPersisted && !model.recentPath.empty()) {
            recentPersisted = model.recentFiles();
            platform::persistConfig();
        }
        followOpen(ui);
        // The title names the file loaded (a failed open keeps the previous one).
        if (model.generation() != titled) {
            titled = model.generation();
            platform::setTitle(windowTitle(model));
        }
        restyle(ui, styled, args.scale <= 0);
        drawFrame(ui, args, frame, input);
        if (!ui.pngRequest.empty()) saveCanvasPng(ui);
        // The Export panel's export: a slice of it each frame, so the window stays live.
        if (ui.exportJob && !ui.exportJob->advance(1.0 / 30)) {
            ui.exportNote = ui.exportJob->message();
            ui.exportFailed = ui.exportJob->status() != Status::Ok;
            if (!ui.exportFailed) ui.lastExportDir = folderOf(ui.exportPath);
            ui.message = ui.exportNote;
            ui.exportJob.reset();
        }
        Job::runSlices(1.0 / 60);  // the web page's background work; nothing on the desktop
        platform::swapBuffers();
#ifdef __EMSCRIPTEN__
        g_shown = &model, g_ui = &ui, ++g_frames, g_scanFrames += !model.invariantsDone();
#endif

        double now = platform::time();
        model.advance(now - lastTime);
        lastTime = now;
    }
}

// A scripted run's input for `frame`: each --step in turn, and --press key i down at frame
// 2i and up at 2i + 1, as a hand would press it.
FrameInput scriptedInput(Ui& ui, const Args& args, int frame, const ImVec2& mouse) {
    ImGuiIO& io = ImGui::GetIO();
    if (!args.presses.empty() && size_t(frame / 2) < args.presses.size()) {
        const Args::Press& p = args.presses[size_t(frame / 2)];
        io.KeysDown[p.key] = frame % 2 == 0;
        io.KeyCtrl = p.ctrl && frame % 2 == 0;
        io.KeyShift = p.shift && frame % 2 == 0;
    }
    FrameInput input;
    input.presenterKeys = !args.presses.empty();
    input.mouse = args.mouse ? &mouse : nullptr;
    if (size_t(frame) < args.steps.size())
        input.seeks = [&ui, step = args.steps[size_t(frame)]] { ui.model.seek(step); };
    // --answer: the quiz question pending at the last --step answered, as its key would.
    if (args.answer != Action::Count && frame + 1 == int(std::max<size_t>(args.steps.size(), 1)))
        input.seeks = [&ui, seek = input.seeks, a = args.answer] {
            if (seek) seek();
            ui.model.answerQuiz(a);
        };
    return input;
}

// --screenshot and the exports: a few frames for the layout to settle, then the picture (the
// window's, or the canvas alone offscreen) and the exit code: the input's, or the write's.
int runScreenshot(Ui& ui, const Args& args, Styled& styled) {
    Model& model = ui.model;
    // ImGui places windows on the 2nd frame; the 3rd is the first settled one.
    // Each extra --step adds a frame.
    // Each --press takes two frames, and the layout two more to settle after the last.
    const int shotFrame = 2 + int(args.steps.empty() ? 0 : args.steps.size() - 1) +
                          (args.presses.empty() ? 0 : 2 * int(args.presses.size()) + 2);
    const ImVec2 mouse(args.mouseX, args.mouseY);
    int exitCode = 0;
    for (int frame = 0; !platform::shouldClose(); ++frame) {
        platform::pollEvents();
        restyle(ui, styled, false);
        followOpen(ui);  // a held open (FLOOD_VIEWER_HOLD_OPEN) stays where it is held
        DrawnFrame f = drawFrame(ui, args, frame, scriptedInput(ui, args, frame, mouse));
        if (!ui.pngRequest.empty()) {  // --press p: Save PNG, as the toolbar's button
            const bool ok = saveCanvasPng(ui);
            std::fprintf(ok ? stdout : stderr, "flood-viewer: %s\n", ui.message.c_str());
            if (!ok) exitCode = int(Status::WriteFailed);
        }
        if (frame == shotFrame && args.exporting()) {
            // The canvas alone, offscreen: run the whole export now.
            ExportJob job(ui, args.exports);
            while (job.advance(0)) {
            }
            bool ok = job.status() == Status::Ok;
            std::fprintf(ok ? stdout : stderr, "flood-viewer: %s\n", job.message().c_str());
            exitCode = ok ? model.exitCode() : int(job.status());
            platform::requestClose();
        } else if (frame == shotFrame) {
            bool ok = writeFrame(ui, f, args.screenshot);
            std::fprintf(ok ? stdout : stderr, "flood-viewer: %s\n", ui.message.c_str());
            std::vector<std::pair<std::string, Rect>> printed = {
                {"caption", ui.captionRect},
                {"toolbar-end", ui.toolbarEnd},
                {"canvas", ui.layout.canvas},
                {"findings", ui.layout.findings},
                {"find-box", ui.findBox},
                {"edit-box", ui.editBox},
                {"shrink-box", ui.shrinkBox},
                {"opening-box", ui.openingBox},
                {"inset", ui.inset},
                {"transcript-copy", ui.transcriptCopy},
                {"quiz-box", ui.quizBox},
                {"direction-box", ui.directionBox},
                {"state-table-box", ui.stateTableBox},
                {"up-arrow", upArrowRect(ui)}};
            for (size_t i = 0; i < ui.findingRows.size(); ++i)
                printed.push_back({"finding-" + std::to_string(i), ui.findingRows[i]});
            for (size_t i = 0; i < ui.labels.size(); ++i)
                printed.push_back({"label-" + std::to_string(i), ui.labels[i]});
            for (const auto& l : ui.stepLabels) printed.push_back(l);
            for (const auto& [name, r] : printed)
                if (args.printLayout && r.w > 0)
                    std::printf("flood-viewer: layout %s %.0f %.0f %.0f %.0f\n", name.c_str(), r.x,
                                r.y, r.w, r.h);
            // The camera: a vertex's place is x + w/2 + (px - cx) * scale, y + h/2 - (py - cy)
            // * scale in the canvas above.
            const Camera& cam = model.camera();
            if (args.printLayout)
                std::printf("flood-viewer: camera %.17g %.17g %.17g\n", cam.center().x,
                            cam.center().y, cam.scale());
            if (args.printLayout && ui.canvas.pixelBoundaryLines)  // decimated (pixelBoundary)
                std::printf("flood-viewer: boundary %zu lines for %zu vertices\n",
                            ui.canvas.pixelBoundaryLines, model.polygon().vertices.size());
            // The picture is written; the exit code still says what the input was.
            exitCode = !ok || exitCode == int(Status::WriteFailed) ? int(Status::WriteFailed)
                                                                   : model.exitCode();
            platform::requestClose();
        }
        platform::swapBuffers();
    }
    return exitCode;
}

// --bench: frames 3..62 step to a random step, 63..122 pan by a pixel at a fixed one; then
// the figures are printed.
void runBench(Ui& ui, const Args& args, Styled& styled, BenchStats& bench) {
    Model& model = ui.model;
    const ImVec2 mouse(args.mouseX, args.mouseY);
    for (int frame = 0; !platform::shouldClose(); ++frame) {
        platform::pollEvents();
        restyle(ui, styled, false);
        const int phase = frame < 3 ? 0 : (frame - 3) / BenchStats::kFrames + 1;
        FrameInput input = scriptedInput(ui, args, frame, mouse);
        input.seeks = [&, scripted = input.seeks] {
            if (scripted) scripted();
            if (phase == 1) model.seek(bench.nextStep());
            if (phase == 2) model.pan(frame % 2 ? 1 : -1, 0);
        };
        DrawnFrame f = drawFrame(ui, args, frame, input);
        double submitted = now() - f.start;
        ui.renderer.finish();
        double all = now() - f.start;
        if (frame == 0) bench.firstFrameMs = all * 1e3;
        if (BenchStats::Frames* times = phase == 1   ? &bench.step
                                        : phase == 2 ? &bench.pan
                                                     : nullptr)
            times->build.push_back(f.built), times->submit.push_back(submitted),
                times->all.push_back(all);
        if (phase == 3) {
            bench.print(model);
            platform::requestClose();
        }
        platform::swapBuffers();
    }
}

// --time-open: the window's open of FILE timed as a user waits for it, CPU side (each frame
// after glFinish; under Xvfb the GL is Mesa's software one): from the request to the first
// frame showing the outline and to the first showing the flooded run, and the longest frame
// meanwhile (the window's stall). Then the same file opened whole before a frame, as the
// window did before the background open (Model::open, still the scripts' path).
void runTimeOpen(Ui& ui, const Args& args, Styled& styled) {
    Model& model = ui.model;
    auto frameDrawn = [&](int frame) {
        restyle(ui, styled, false);
        drawFrame(ui, args, frame, {});
        ui.renderer.finish();
        platform::swapBuffers();
    };
    const double start = now();
    model.openInBackground(args.file);
    double read = 0, outline = 0, flooded = 0, longest = 0;
    int frame = 0;
    for (; !platform::shouldClose(); ++frame) {
        const double f0 = now();
        platform::waitEvents(1.0 / 30);  // as the window idles while an open runs
        followOpen(ui);
        const bool shown = !model.polygon().vertices.empty(), done = !model.opening();
        if (shown && read == 0) read = now() - start;  // adopted: its frame still to draw
        frameDrawn(frame);
        const double t = now();
        longest = std::max(longest, t - f0);
        if (shown && outline == 0) outline = t - start;
        if (done) {
            flooded = t - start;
            break;
        }
    }
    std::printf(
        "time-open: %s: %zu vertices, %u events%s\n", args.file.c_str(),
        model.polygon().vertices.size(), model.steps(),
        model.openDiagnostic().ok() ? "" : (" (" + model.openDiagnostic().message + ")").c_str());
    std::printf(
        "time-open: in the background: outline adopted %.0f ms, its first frame %.0f ms, first "
        "flooded frame %.0f ms, longest frame meanwhile %.0f ms (%d frames)\n",
        read * 1e3, outline * 1e3, flooded * 1e3, longest * 1e3, frame + 1);
    const double whole = now();
    model.open(args.file);
    frameDrawn(frame + 1);
    std::printf(
        "time-open: opened whole (Model::open, as before): first frame %.0f ms, the "
        "window still throughout\n",
        (now() - whole) * 1e3);
}

}  // namespace

int main(int argc, char** argv) {
    Args args;
    if (int rc = parseArgs(argc, argv, args)) return rc - 1;
    if (args.file.empty()) args.file = defaultPolygonPath();
    const bool shot = !args.screenshot.empty() || args.bench || args.exporting() || args.timeOpen;

    OpenHold hold;  // before the model: its open's hook may wait on it until the model joins it
    Model model;
    struct Release {  // on every way out, before ~Model joins the held open
        OpenHold& hold;
        ~Release() { hold.released = true; }
    } release{hold};
    // Screenshots neither read nor write the recent list, nor write the settings; they read the
    // saved theme (a picture looks as the viewer does), not the zoom (scale 1 or --scale).
    const ConfigFiles saved = configFiles();
    const ConfigFiles config = args.screenshot.empty() ? saved : ConfigFiles{};
    ViewerSettings settings;
    if (!config.recent.empty()) model.loadRecent(config.recent);
    model.recentPath = config.recent;  // saved on every open
    if (!saved.settings.empty()) settings = loadSettings(saved.settings);
    if (args.themeGiven) settings.theme = args.theme;
    palette::setTheme(settings.theme);
    const bool held = holdOpen(model, hold);
    double openStart = now();
    // The window opens its FILE in the background; a picture, a --step or a benchmark wait
    // for the whole open, as before.
    if (args.timeOpen) {  // opened by runTimeOpen, once the window is up
    } else if (int rc = openArgs(model, args, (!shot && args.steps.empty()) || held)) {
        return rc;
    }
    if (held) waitForHold(model, hold);
    double openSeconds = now() - openStart;
    if (args.quiz) model.startQuiz(args.quizAsked);
    if (!args.steps.empty()) model.seek(args.steps.front());
    if (!exportRangeFits(model, args)) return int(Status::Usage);
    BenchStats bench;
    if (args.bench) bench = benchOpenAndSeek(model, openSeconds);

    std::string error;
    if (!platform::initialize(&error)) return printSummary(error, model, args);
    platform::WindowOptions wo;
    wo.width = args.width, wo.height = args.height, wo.hidden = shot;
    wo.title = windowTitle(model);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is tiled by code; nothing worth saving
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
    Styled styled{ui.uiScale.generation(), ui.theme, config.settings};
    ui.showPredicates = args.predicates;
    ui.showStateTable = args.stateTable;
    if (args.quiz) ui.quizAsked = args.quizAsked;
    ui.sceneOptions.gorgeFocus = args.gorgeFocus;
    // A picture shows the invariant lane complete (and the landing on its first violation).
    if (shot) model.waitForInvariants();
    ui.showDirection = !args.up.empty();

    int exitCode = 0;
    if (args.timeOpen) runTimeOpen(ui, args, styled);
    else if (args.bench) runBench(ui, args, styled, bench);
    else if (shot) exitCode = runScreenshot(ui, args, styled);
    else runInteractive(ui, args, styled);

    hold.released = true;
    model.cancelOpen();  // an open still under way ends its phase; ~Model joins it
    if (!config.recent.empty()) model.saveRecent(config.recent);
    ui.exportJob.reset();  // its framebuffer goes while the GL context exists
    rendererOwner.reset();
    imguiGlShutdown();
    platform::destroyWindow();
    ImGui::DestroyContext();
    platform::terminate();
    return exitCode;
}
