// GUI test of the classroom views: Tab's presenter view at 2x with its caption whole, the
// toolbar inside 1024x768 at 2x, Ctrl+plus and F11, the light theme's colours, and bad
// presenter options refused before any window. Exit 77 (skipped) without a display.

#include "screenshot_support.h"

using namespace flood;
using namespace flood::view;
using namespace flood::view::testing;

namespace {

// Tab at 2x on 1024x768 (the presenter view): no toolbar, the caption whole inside the frame with its
// last line above its bottom padding, the action's name in its colour, and the canvas fitted
// to the space left (the Left marker where the presenter layout puts it).
int checkPresenter(const std::string& dir, const std::string& input, Model& model, uint32_t step) {
    const int W = 1024, H = 768;
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--scale 2 --press tab --step " + std::to_string(step),
                      dir + "/screenshot-test-presenter.png", W, H, img, layout))
        return 1;
    int failures = 0;
    const Rect caption = layout["caption"];
    if (layout.count("toolbar-end")) failures += failWith("presenter view drew the toolbar");
    if (!inside(caption, W, H) || caption.h > H / 2 || caption.y + caption.h != H)
        failures += failWith("the caption is not whole at the bottom of the frame");
    // Text is the style's white; the lowest text row must stay clear of the bottom edge.
    int lowest = -1;
    for (int y = int(caption.y); y < int(caption.y + caption.h) && y < H; ++y)
        if (count(img, {caption.x, double(y), caption.w, 1},
                  [](Rgba c) { return luminance(c) > 200; }) > 0)
            lowest = y;
    if (lowest < 0 || lowest > caption.y + caption.h - 8)
        failures +=
            failWith("the caption's text is missing or runs into its bottom edge (lowest row " +
                     std::to_string(lowest) + ")");
    model.seek(step);
    Rgba actionColour = palette::action(model.currentEvent()->action);
    int named = count(img, caption, [&](Rgba c) { return close(c, actionColour, 8); });
    if (named < 40)
        failures += failWith("the action's name is not drawn in its colour in the caption (" +
                             std::to_string(named) + " pixels)");
    model.fitCamera(presenterLayout(W, H, caption.h).canvas);
    Rgba seen;
    Vec2 left = model.camera().toScreen(model.polygon().vertices[model.state().fingers.left]);
    if (!near(img, left, palette::kLeft, 2, &seen))
        failures += fail("presenter Left marker", left, palette::kLeft, seen);
    Vec2 corner{W - 3.0, 3.0};  // where the Events panel is in the normal view
    if (!near(img, corner, palette::kBackground, 0, &seen))
        failures +=
            fail("canvas background where a panel would be", corner, palette::kBackground, seen);
    stbi_image_free(img.px);
    return failures;
}

// The normal view at 2x on 1024x768: the toolbar wraps, so its last button is whole inside
// the frame: a button (mostly the style's blue) with white text, ending where it says.
int checkToolbarAtScale2(const std::string& dir, const std::string& input) {
    const int W = 1024, H = 768;
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--scale 2", dir + "/screenshot-test-scale2.png", W, H, img, layout))
        return 1;
    int failures = 0;
    const Rect b = layout["toolbar-end"];
    if (!inside(b, W, H)) {
        failures += failWith("the toolbar's last button is outside the 1024x768 frame at 2x (" +
                             std::to_string(b.x) + ", " + std::to_string(b.y) + ")");
    } else {
        const int area = int(b.w) * int(b.h);
        int blue = count(img, b, [](Rgba c) { return c.b > c.r + 40; });
        int text = count(img, b, [](Rgba c) { return luminance(c) > 200; });
        if (blue < area / 2 || text < 20)
            failures += failWith("no button drawn at the toolbar's end (" + std::to_string(blue) +
                                 " blue, " + std::to_string(text) + " text pixels of " +
                                 std::to_string(area) + ")");
    }
    stbi_image_free(img.px);
    return failures;
}

// Ctrl+plus three times (150%): the fonts are rebuilt while the viewer runs and the texture
// uploaded again, so the toolbar's last button is taller and still a button with its text.
// F11: the picture is the screen's size, not the window's.
int checkKeys(const std::string& dir, const std::string& input) {
    const int W = 1024, H = 768;
    Image img;
    std::map<std::string, Rect> layout;
    int failures = 0;
    if (!shootPrinted(input, "--press ctrl+plus --press ctrl+plus --press ctrl+plus",
                      dir + "/screenshot-test-zoom.png", W, H, img, layout))
        return 1;
    const Rect b = layout["toolbar-end"];
    const int area = int(b.w) * int(b.h);
    int blue = count(img, b, [](Rgba c) { return c.b > c.r + 40; });
    int text = count(img, b, [](Rgba c) { return luminance(c) > 200; });
    if (!inside(b, W, H) || b.h < 25 || blue < area / 2 || text < 20)
        failures += failWith("after Ctrl+plus x3 the last button is not a 150% button (h " +
                             std::to_string(b.h) + ", " + std::to_string(blue) + " blue, " +
                             std::to_string(text) + " text pixels)");
    stbi_image_free(img.px);
    Image full;
    if (!shootPrinted(input, "--press f11", dir + "/screenshot-test-f11.png", 800, 600, full,
                      layout, false))
        return failures + 1;
    if (full.w == 800 && full.h == 600) failures += failWith("F11 left the window at its size");
    stbi_image_free(full.px);
    return failures;
}

// The light theme: the same probes as the dark shot in the light colours (background,
// water, dry land, Left marker), the boundary drawn dark, the panels light.
int checkLightTheme(const std::string& dir, const std::string& input, Model& model, uint32_t step,
                    const Layout& layout) {
    palette::setTheme(Theme::Light);
    Image img;
    std::map<std::string, Rect> printed;
    int failures = 0;
    if (!shootPrinted(input, "--theme light --step " + std::to_string(step),
                      dir + "/screenshot-test-light.png", int(layout.bottom.w),
                      int(layout.bottom.y + layout.bottom.h), img, printed))
        return 1;
    model.seek(step);
    model.fitCamera(layout.canvas, {printed["find-box"], printed["edit-box"]});
    failures += checkShot(model, layout, img, false);
    if (luminance(palette::kBackground) < 200)
        failures += failWith("the light background is not light");
    Rgba seen;
    // The outer ring's first edge, halfway: the boundary line.
    const auto& v = model.polygon().vertices;
    Vec2 mid = model.camera().toScreen({(v[0].x + v[1].x) / 2, (v[0].y + v[1].y) / 2});
    if (!near(img, mid, palette::kBoundary, 1, &seen) || luminance(palette::kBoundary) > 60)
        failures += fail("dark boundary line", mid, palette::kBoundary, seen);
    Rect panel{layout.right.x + 4, layout.right.y + layout.right.h * 0.7, layout.right.w - 8, 20};
    int light = count(img, panel, [](Rgba c) { return luminance(c) > 180; });
    if (light < panel.w * panel.h * 0.6)
        failures += failWith("the panels are not light in the light theme");
    stbi_image_free(img.px);
    palette::setTheme(Theme::Dark);
    return failures;
}

// A bad value of a presenter option is a usage error (exit 2) naming the option and the
// value, before any window.
int checkPresenterUsage() {
    int failures = 0;
    for (const char* bad : {"--scale 9", "--scale x", "--theme sepia", "--press shift"}) {
        std::string cmd = std::string("'") + FLOOD_VIEWER + "' " + bad + " 2>&1";
        FILE* pipe = popen(cmd.c_str(), "r");
        std::string said;
        char line[512];
        while (pipe && std::fgets(line, sizeof line, pipe)) said += line;
        int rc = pipe ? pclose(pipe) : -1;
        std::string option = std::string(bad).substr(0, std::string(bad).find(' '));
        std::string value = std::string(bad).substr(option.size() + 1);
        if (rc == -1 || !WIFEXITED(rc) || WEXITSTATUS(rc) != 2 ||
            said.find(option) == std::string::npos ||
            said.find("'" + value + "'") == std::string::npos)
            failures += failWith(std::string("flood-viewer ") + bad +
                                 ": want exit 2 naming it, got: " + said);
    }
    return failures;
}

}  // namespace

int main() {
    if (checkPresenterUsage()) return 1;
    if (int skip = displayOrSkip()) return skip;
    SquareHole f("presenter-screenshot-test");
    if (!openSquareHole(f)) return 1;
    int failures = checkPresenter(f.dir, f.input, f.model, f.step);
    failures += checkToolbarAtScale2(f.dir, f.input);
    failures += checkKeys(f.dir, f.input);
    failures += checkLightTheme(f.dir, f.input, f.model, f.step, f.layout);
    if (failures) return 1;
    std::printf(
        "ok: Tab's presenter view at 2x with its caption whole; the toolbar's last "
        "button inside 1024x768 at 2x; Ctrl+plus rebuilds the fonts; F11 fills the "
        "screen; the light theme's ground, lines and panels; bad options refused\n");
    return 0;
}
