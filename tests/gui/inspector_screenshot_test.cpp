// GUI test of what explains a step: the predicate inspector's rows and the hovered row's
// argument ringed, the invariant lane's ticks where the violations are, and the Decision
// panel's yes/no answers readable in both themes. Exit 77 (skipped) without a display.

#include "flood/teach/decision_tree.h"
#include "screenshot_support.h"

using namespace flood;
using namespace flood::view;
using namespace flood::view::testing;

namespace {

// The predicate inspector (--predicates) draws its rows, and hovering its first row
// (--mouse) rings that test's first argument on the canvas. The window's place is its first
// use's (panel_predicates.cpp) and ImGui's default style at scale 1: title bar 19 px, padding
// 8 px, the header row 17 px; the first row's first line is below that.
int checkInspector(const std::string& input, Model& model, const Layout& layout, int W, int H,
                   const std::string& dir) {
    const Rect& c = layout.canvas;
    const Rect win{c.x + 20, c.y + c.h * 0.55, 640, 300};
    const Rgba ring{80, 220, 255, 255};
    // A step whose first row names a vertex the window does not cover.
    uint32_t step = 0;
    Index arg = kNone;
    for (uint32_t s = 1; s <= model.steps() && !step; ++s) {
        model.seek(s);
        const auto& rows = model.inspection();
        if (rows.empty() || rows[0].args.empty() ||
            rows[0].args[0] >= model.polygon().vertices.size())
            continue;
        Vec2 p = model.camera().toScreen(model.polygon().vertices[rows[0].args[0]]);
        if (!win.contains(p) && c.contains(p)) step = s, arg = rows[0].args[0];
    }
    if (!step) {
        std::fprintf(stderr,
                     "FAIL: inspector: no step whose first predicate names a visible vertex\n");
        return 1;
    }
    model.seek(step);
    Vec2 mouse{win.x + 60, win.y + 19 + 8 + 17 + 6};
    char opts[160];
    std::snprintf(opts, sizeof opts, "--step %u --step %u --predicates --mouse %.0f,%.0f", step,
                  step, mouse.x, mouse.y);
    Image img;
    if (!shoot(input, opts, dir + "/screenshot-test-inspector.png", W, H, img)) return 1;
    int failures = 0;
    // Its rows: text in the first row's line, and more in the rows below it.
    int bright = 0;
    for (int y = int(win.y + 19 + 8 + 17); y < int(win.y + 19 + 8 + 17 + 60); ++y)
        for (int x = int(win.x + 8); x < int(win.x + 400); ++x) {
            Rgba px = img.at(x, y);
            bright += px.r + px.g + px.b > 450;
        }
    if (bright < 40) {
        std::fprintf(stderr, "FAIL: inspector: its rows show no text (%d bright pixels)\n", bright);
        ++failures;
    }
    // The hovered row's argument: a ring of radius 9 around the vertex.
    Vec2 v = model.camera().toScreen(model.polygon().vertices[arg]);
    int onRing = 0;
    for (auto [dx, dy] : {std::pair{9.0, 0.0}, {-9.0, 0.0}, {0.0, 9.0}, {0.0, -9.0}})
        onRing += near(img, {v.x + dx, v.y + dy}, ring, 2, nullptr);
    if (onRing < 3) {
        Rgba seen = img.at(int(v.x + 9), int(v.y));
        failures += fail("inspector: the hovered row's argument ringed on the canvas",
                         {v.x + 9, v.y}, ring, seen);
    }
    stbi_image_free(img.px);
    std::printf(
        "inspector: step %u, vertex %u ringed (%d of 4 probes), %d bright pixels in its rows\n",
        step, arg, onRing, bright);
    return failures;
}

// The invariant lane of an invalid input flooded anyway: a tick at each violation the model
// finds, where the timeline puts that step, and none elsewhere. The strip's place is found on
// the picture (the lane's own colour), so a scrollbar in the timeline does not matter.
int checkInvariantLane(const std::string& dir, int W, int H, const Layout& layout) {
    std::string input =
        std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid/hole-crossing-outer.json";
    Model model;
    model.open(input);
    model.waitForInvariants();
    const std::vector<Violation>& found = model.violations();
    if (found.empty() || model.forbiddenStep() == 0 ||
        found.front().step >= model.forbiddenStep()) {
        std::fprintf(stderr, "FAIL: lane: %s should break an invariant before its forbidden step\n",
                     input.c_str());
        return 1;
    }
    Image img;
    std::string step = "--step " + std::to_string(model.forbiddenStep());
    if (!shoot(input, step, dir + "/screenshot-test-lane.png", W, H, img, model.exitCode()))
        return 1;
    // The tick's orange (255, 120, 40), also where anti-aliasing blends it half into the lane;
    // not the first error's red (its green stays low).
    const Rgba laneColour{34, 30, 40, 255};
    auto orange = [](Rgba p) { return p.r - p.b > 80 && p.g > 55 && p.g < 140; };
    // The lane: the middle of the timeline's rows with the most pixels of its colour (its top
    // row meets the current step's tick).
    std::vector<int> perRow(size_t(H), 0);
    int best = 0;
    for (int y = int(layout.bottom.y); y < H; ++y) {
        for (int x = 0; x < W; ++x) perRow[size_t(y)] += close(img.at(x, y), laneColour, 2);
        best = std::max(best, perRow[size_t(y)]);
    }
    int top = -1, bottom = -1;
    for (int y = int(layout.bottom.y); y < H; ++y)
        if (perRow[size_t(y)] >= best * 9 / 10) bottom = y, top = top < 0 ? y : top;
    int laneY = (top + bottom) / 2;
    int x0 = W, x1 = -1;
    std::vector<int> ticks;
    for (int x = 0; x < W && laneY >= 0; ++x) {
        Rgba px = img.at(x, laneY);
        bool lane = close(px, laneColour, 2), tick = orange(px),
             error = close(px, palette::kCulprit, 6);
        if (lane || tick || error) x0 = std::min(x0, x), x1 = std::max(x1, x);
        if (tick) ticks.push_back(x);
    }
    int failures = 0;
    if (best < W / 2) {
        std::fprintf(stderr, "FAIL: lane: no invariant lane in the timeline\n");
        stbi_image_free(img.px);
        return 1;
    }
    // A step sits at the right edge of its event's mark: x0 + step * width / events.
    const double width = x1 - x0 + 1;
    auto xOf = [&](uint32_t s) { return x0 + s * width / model.steps(); };
    for (const Violation& v : found) {
        bool seen = false;
        for (int t : ticks) seen |= std::abs(t - xOf(v.step)) <= 2;
        if (!seen) {
            std::fprintf(stderr, "FAIL: lane: no tick for the violation at step %u (x %.1f)\n",
                         v.step, xOf(v.step));
            ++failures;
        }
    }
    for (int t : ticks) {
        bool expected = false;
        for (const Violation& v : found) expected |= std::abs(t - xOf(v.step)) <= 3;
        if (!expected) {
            std::fprintf(stderr, "FAIL: lane: a tick at x %d where no invariant breaks\n", t);
            ++failures;
            break;
        }
    }
    std::printf(
        "lane: row %d, x %d..%d, %zu violations (first at step %u, forbidden at %u), %zu tick "
        "pixels\n",
        laneY, x0, x1, found.size(), found.front().step, model.forbiddenStep(), ticks.size());
    stbi_image_free(img.px);
    return failures;
}

// The Decision panel's yes/no answers in each theme: at a step whose path answers both yes
// and no, both colours are drawn in the panel and stand out from its background (read from
// the picture: its most common colour) at 3:1 or more; "no" is never the forbidden red.
int checkDecisionAnswers(const std::string& dir) {
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    Model model;
    model.open(input);
    const DecisionTree& tree = decisionTree();
    // The step whose lit path has the most answered tests, at least one of each answer.
    uint32_t step = 0;
    size_t best = 0;
    for (uint32_t s = 1; s <= model.steps(); ++s) {
        model.seek(s);
        size_t yes = 0, no = 0;
        for (const PathStep& p : decisionPath(*model.currentEvent()).steps) {
            const DecisionNode& n = tree.nodes[size_t(p.node)];
            if (n.kind != DecisionNode::Kind::Action && n.yes != n.no && n.yes >= 0 && n.no >= 0)
                (p.answer ? yes : no) += 1;
        }
        if (yes && no && yes + no > best) best = yes + no, step = s;
    }
    if (!step) return failWith("decision answers: no step answers both yes and no");
    const int W = 1000, H = 700;
    const Rect col = computeLayout(W, H, 1).left;
    const Rect panel{col.x, col.y + col.h * 0.38, col.w, col.h * 0.27};
    int failures = 0;
    for (Theme theme : {Theme::Light, Theme::Dark}) {
        palette::setTheme(theme);
        const std::string name = palette::themeName(theme);
        Image img;
        if (!shoot(input, "--theme " + name + " --step " + std::to_string(step),
                   dir + "/screenshot-test-decision-" + name + ".png", W, H, img))
            return failures + 1;
        std::map<uint32_t, int> seen;
        for (int y = int(panel.y); y < int(panel.y + panel.h); ++y)
            for (int x = int(panel.x); x < int(panel.x + panel.w); ++x) {
                Rgba c = img.at(x, y);
                ++seen[uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b];
            }
        uint32_t mode = 0;
        int most = 0;
        for (auto [c, n] : seen)
            if (n > most) most = n, mode = c;
        const Rgba background{uint8_t(mode >> 16), uint8_t(mode >> 8), uint8_t(mode), 255};
        const palette::TreeColours& colours = palette::tree();
        for (auto [what, c] : {std::pair{"yes", colours.yes}, {"no", colours.no}}) {
            int drawn = count(img, panel, [&](Rgba p) { return close(p, c, 8); });
            double ratio = contrast(c, background);
            std::printf("decision %s theme, step %u: '%s' %d pixels, contrast %.2f with %d,%d,%d\n",
                        name.c_str(), step, what, drawn, ratio, background.r, background.g,
                        background.b);
            if (drawn < 8 || ratio < 3)
                failures += failWith("the " + name + " theme's '" + what +
                                     "' answers are missing or too close to the panel");
        }
        if (close(colours.no, palette::kCulprit, 100) ||
            close(colours.no, palette::action(Action::Forbidden), 100) ||
            colours.no.r >= colours.no.b)
            failures += failWith("the " + name + " theme's 'no' is the forbidden red");
        stbi_image_free(img.px);
    }
    palette::setTheme(Theme::Dark);
    return failures;
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    SquareHole f("inspector-screenshot-test");
    if (!openSquareHole(f) || !fitAsTheViewer(f)) return 1;
    int failures = checkInspector(f.input, f.model, f.layout, f.W, f.H, f.dir);
    failures += checkInvariantLane(f.dir, f.W, f.H, f.layout);
    failures += checkDecisionAnswers(f.dir);
    if (failures) return 1;
    std::printf(
        "ok: the predicate inspector's rows and hover; the invariant lane's ticks; the "
        "decision tree's yes/no answers readable in both themes\n");
    return 0;
}
