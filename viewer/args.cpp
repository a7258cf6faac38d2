// flood-viewer's command line through CLI11, as the `flood` command's (cli/main.cpp): each
// option with its help, its value checked as it is parsed (an error names the option and the
// value), then the checks between options.
#include "args.h"

#include <CLI/CLI.hpp>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <functional>

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

// A CLI11 check from a test of the value: "" when it is fine, else why not.
CLI::Validator wants(const char* name, std::function<bool(const std::string&)> ok,
                     const std::string& what) {
    return CLI::Validator(
        [ok = std::move(ok), what](std::string& v) {
            return ok(v) ? std::string() : "wants " + what + ", got '" + v + "'";
        },
        "", name);
}

bool wholeNumber(const std::string& v, long low, long high, long& out) {
    char* end = nullptr;
    out = std::strtol(v.c_str(), &end, 10);
    return !v.empty() && *end == 0 && out >= low && out <= high;
}

bool realNumber(const std::string& v, double low, double high, double& out) {
    char* end = nullptr;
    out = std::strtod(v.c_str(), &end);
    return !v.empty() && *end == 0 && out >= low && out <= high;
}

}  // namespace

int parseArgs(int argc, char** argv, Args& a) {
    CLI::App app{
        "flood-viewer: watch Flood triangulate a polygon, step by step (F1 or ? in the "
        "viewer lists the keys)"};
    app.set_version_flag("--version", std::string("flood-viewer ") + FLOOD_VERSION);
    app.footer(
        "  flood-viewer FILE --screenshot OUT.png|OUT.svg --canvas-only [--size WxH] [--caption]\n"
        "  flood-viewer FILE --export-gif OUT.gif|--export-png-dir DIR [--steps A:B] [--every K]"
        " [--fps F] [--caption] [--size WxH]\n"
        "Exit codes are the flood command's: 2 usage, 3 unreadable, 4 invalid, 5 forbidden, 6 "
        "checker, 8 a file that cannot be written (nothing half-written left).\n");
    app.add_option("FILE", a.file,
                   "A polygon (GeoJSON, ring arrays, WKT or a GIS dataset) or a trace from "
                   "`flood trace` (*.jsonl, *.bin); default: polygons/paper-figure-7.json");
    std::vector<std::string> steps;
    app.add_option("--step", steps,
                   "Show the state after N events; repeat it to draw each in turn (--step 40 "
                   "--step 5 shows 5 after a frame at 40)")
        ->type_name("N")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(wants(
            "N",
            [](const std::string& v) {
                uint32_t s;
                return parseStepArg(v, s);
            },
            "a number >= 0"));
    app.add_option("--feature", a.feature,
                   "Open the feature of FID N (as `flood check` and `flood --feature` number "
                   "them) of a FeatureCollection or GIS layer; no such feature: exit 2")
        ->type_name("N")
        ->check(wants(
            "N",
            [](const std::string& v) {
                long n;
                return wholeNumber(v, 0, LONG_MAX, n);
            },
            "a number >= 0"));
    app.add_option("--layer", a.layer, "A GIS dataset's layer (GDAL; default: its only layer)")
        ->type_name("NAME");
    app.add_option("--where", a.where,
                   "Only the GIS features an OGR SQL attribute filter keeps (with --feature N: "
                   "FID N, if the filter keeps it)")
        ->type_name("SQL");
    app.add_flag("--show-error", a.showError,
                 "Start in the error view (zoomed to the culprits), as the E key");
    app.add_flag("--predicates", a.predicates, "Open the predicate inspector");
    app.add_flag("--gorge-focus", a.gorgeFocus, "The canvas shows the current gorge only");
    app.add_option("--screenshot", a.screenshot,
                   "Render once in a hidden window, write OUT as PNG (or, ending in .svg, the "
                   "canvas as SVG) and exit; the exit code is the flood command's")
        ->type_name("OUT");
    std::string size;
    app.add_option("--size", size,
                   "Window size in pixels (default 1280x800); with --canvas-only, an SVG or an "
                   "export: the picture's size (the window keeps 1280x800)")
        ->type_name("WxH")
        ->check(wants(
            "WxH",
            [&](const std::string& v) {
                char tail = 0;
                return std::sscanf(v.c_str(), "%dx%d%c", &a.width, &a.height, &tail) == 2 &&
                       a.width >= 64 && a.height >= 64 && a.width <= 16384 && a.height <= 16384;
            },
            "WxH (64..16384)"));
    std::string mouse;
    app.add_option("--mouse", mouse,
                   "With --screenshot: the pointer at X,Y (what hovering there shows)")
        ->type_name("X,Y")
        ->check(wants(
            "X,Y",
            [&](const std::string& v) {
                char tail = 0;
                return std::sscanf(v.c_str(), "%f,%f%c", &a.mouseX, &a.mouseY, &tail) == 2;
            },
            "X,Y"));
    app.add_option("--scale", a.scale, "UI scale 0.5..4 instead of the monitor's (screenshots: 1)")
        ->type_name("S")
        ->check(wants(
            "S",
            [](const std::string& v) {
                double s;
                return realNumber(v, 0.5, 4, s);
            },
            "a number in 0.5..4"));
    app.add_flag("--presenter", a.presenter,
                 "Start in presenter view: the canvas and a large caption (Tab)");
    std::string theme;
    app.add_option("--theme", theme, "light or dark (default: the last one chosen, else dark)")
        ->type_name("T")
        ->check(wants(
            "T",
            [](const std::string& v) {
                Theme t;
                return palette::parseTheme(v.c_str(), t);
            },
            "light or dark"));
    app.add_flag("--print-layout", a.printLayout,
                 "With --screenshot: print where the caption, the toolbar's last button, the "
                 "canvas, the findings and their rows, the boxes over the canvas, the error "
                 "view's labels and the step's labels (named-vertex-35, ...) were drawn (x y w "
                 "h, logical px), and the camera (centre x y, pixels per unit)");
    std::vector<std::string> presses;
    app.add_option("--press", presses,
                   "With --screenshot: press tab, f11, ctrl+plus, ctrl+minus, ctrl+0, f8, "
                   "shift+f8 or p (Save PNG) first (repeat it for more, one frame apart)")
        ->type_name("KEY")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(wants(
            "KEY",
            [](const std::string& v) {
                Args::Press p{};
                return pressNamed(v, p);
            },
            "tab, f11, ctrl+plus, ctrl+minus, ctrl+0, f8, shift+f8 or p"));
    app.add_flag("--canvas-only", a.canvasOnly,
                 "--screenshot renders the canvas alone (no panels), offscreen at --size; OUT "
                 "ending in .svg is always the canvas alone");
    app.add_option("--export-gif", a.exports.gif,
                   "The flood (or --steps) as an animated GIF of the canvas, then exit")
        ->type_name("OUT");
    app.add_option("--export-png-dir", a.exports.pngDir,
                   "The same as numbered PNGs DIR/frame-0000.png, ... (DIR is made)")
        ->type_name("DIR");
    std::string range;
    app.add_option("--steps", range,
                   "The steps exported (A: or :B for an open end; default the whole flood)")
        ->type_name("A:B")
        ->check(CLI::Validator(
            [&](std::string& v) {
                std::string error;
                return parseStepRange(v, a.exports.first, a.exports.last, &error) ? std::string()
                                                                                  : error;
            },
            "", "A:B"));
    long every = 0;
    app.add_option("--every", every, "A frame every K steps; the last step B always ends it")
        ->type_name("K")
        ->check(wants(
            "K",
            [](const std::string& v) {
                long k;
                return wholeNumber(v, 1, 1000000000L, k);
            },
            "a number of steps >= 1"));
    double fps = 0;
    app.add_option("--fps", fps, "GIF frames per second, 0.1 to 50 (default 10)")
        ->type_name("F")
        ->check(wants(
            "F",
            [](const std::string& v) {
                double f;
                return realNumber(v, kMinFps, kMaxFps, f);
            },
            "frames per second from 0.1 to 50"));
    app.add_flag("--caption", a.exports.caption,
                 "A line under the canvas: step, action and the step's narration");
    std::string quiz, answer;
    app.add_option("--quiz", quiz,
                   "Start in the quiz (key Q), asking about ACTIONS: raise, bridge, spill, jump, "
                   "fill, comma separated, or all")
        ->type_name("ACTIONS")
        ->check(CLI::Validator(
            [&](std::string& v) {
                std::string why;
                return parseQuizActions(v, a.quizAsked, why) ? std::string() : why;
            },
            "", "ACTIONS"));
    app.add_option("--answer", answer,
                   "With --quiz: answer the question before the last --step's next event")
        ->type_name("ACTION")
        ->check(CLI::Validator(
            [&](std::string& v) {
                QuizActions one;
                std::string why;
                if (parseQuizActions(v, one, why))
                    for (Action c : kQuizChoices)  // exactly one of them
                        if (one.bits == uint8_t(1u << int(c))) return a.answer = c, std::string();
                return "wants raise, bridge, spill, jump or fill, got '" + v + "'";
            },
            "", "ACTION"));
    app.add_flag("--state-table", a.stateTable, "Open the State table (Fig. 10)");
    app.add_flag("--bench", a.bench,
                 "Time opening, seeking and drawing (hidden window), print, exit");
    app.add_flag("--time-open", a.timeOpen,
                 "Time the window's open of FILE (hidden window): to the outline's first frame "
                 "and to the first flooded frame, then the same file opened whole; print, exit");
    app.add_option("--up", a.up,
                   "Flood along +y, -y, +x, -x, an angle in degrees (90 is +y) or X,Y, with the "
                   "direction dial open (it compares with the +y run); --up=-y for a value "
                   "starting with '-'")
        ->type_name("DIRECTION")
        ->check(CLI::Validator(
            [](std::string& v) {
                Up d;
                std::string why;
                return parseUp(v, d, why) ? std::string() : why;
            },
            "", "DIRECTION"));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        app.exit(e);
        return 1;
    } catch (const CLI::CallForVersion& e) {
        app.exit(e);
        return 1;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "flood-viewer: %s\nRun with --help for more information.\n", e.what());
        return 2 + 1;
    }
    for (const std::string& v : steps) {
        uint32_t step = 0;
        parseStepArg(v, step);  // checked above
        a.steps.push_back(step);
    }
    for (const std::string& v : presses) {
        Args::Press p{};
        pressNamed(v, p);
        a.presses.push_back(p);
    }
    a.sizeGiven = !size.empty();
    a.mouse = !mouse.empty();
    a.themeGiven = !theme.empty();
    if (a.themeGiven) palette::parseTheme(theme.c_str(), a.theme);
    a.quiz = !quiz.empty();
    a.rangeGiven = !range.empty();
    a.everyGiven = every > 0;
    if (a.everyGiven) a.exports.every = uint32_t(every);
    a.fpsGiven = fps > 0;
    if (a.fpsGiven) a.exports.fps = fps;
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
    else if (a.timeOpen && (a.bench || a.exporting() || !shot.empty()))
        needs = "--time-open cannot be combined with --bench, --screenshot or exports";
    else if (a.answer != Action::Count && !a.quiz) needs = "--answer needs --quiz";
#ifndef FLOOD_GIF
    if (!a.exports.gif.empty())
        needs = "--export-gif: this flood-viewer was built without giflib (FLOOD_GIF)";
#endif
    if (needs) {
        std::fprintf(stderr, "flood-viewer: %s\nRun with --help for more information.\n", needs);
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
