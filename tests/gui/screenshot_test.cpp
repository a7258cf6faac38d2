// GUI test: renders a known polygon with `flood-viewer --screenshot` and checks pixels whose
// colours are known from the palette: background outside the polygon, water inside a flooded
// triangle, and the Left marker at the Left vertex. Positions come from the same layout and
// camera fit the viewer uses. A second shot draws the last step first and then steps back:
// the triangles cut after that step must be dry land again (the GPU draws a prefix of the
// flood-order triangles, which must shrink). Then the error view of a self-crossing ring, an
// unreadable file, and a 10^5-vertex face. Exit 77 (skipped) without a display, except in CI.

#include "screenshot_support.h"

using namespace flood;
using namespace flood::view;
using namespace flood::view::testing;

namespace {

// A 10^5-vertex face (`flood generate circle-jagged 100000`: spikes alternating between radii
// 0.2-0.7 and 0.8-1 around the origin) must read as a shape at the fit: the disc inside radius
// 0.2 is dry land, the plane beyond radius 1 background, and the spiked band mostly not
// vertex-class dots (unthinned, they paved it). Samples on a pixel grid, classified by radius.
int checkDenseFace(const std::string& dir, int W, int H, const Layout& layout) {
    std::string input = dir + "/screenshot-test-dense.json";
    std::string gen =
        std::string("'") + FLOOD_CLI + "' generate circle-jagged 100000 -o '" + input + "'";
    if (std::system(gen.c_str()) != 0) {
        std::fprintf(stderr, "FAIL: %s\n", gen.c_str());
        return 1;
    }
    Model model;
    model.open(input);
    Image img;
    std::map<std::string, Rect> printed;
    if (!shootPrinted(input, "--step 0", dir + "/screenshot-test-dense.png", W, H, img, printed,
                      true, 0))
        return 1;
    // The viewer fits clear of the find and Edit boxes (view_fit.h): the same fit here.
    model.fitCamera(layout.canvas, {printed["find-box"], printed["edit-box"]});
    const Rgba dots[] = {palette::kRegular, palette::kBottom, palette::kSag, palette::kTop,
                         palette::kCeiling};
    int inner = 0, innerLand = 0, band = 0, bandDots = 0, outer = 0, outerBackground = 0;
    const Rect& c = layout.canvas;
    for (double y = c.y + 60; y < c.y + c.h - 4; y += 3)  // below the find box
        for (double x = c.x + 4; x < c.x + c.w - 4; x += 3) {
            Point w = model.camera().toWorld({x, y});
            double r = std::hypot(w.x, w.y);
            Rgba px = img.at(int(x), int(y));
            if (r < 0.15) {
                ++inner, innerLand += close(px, palette::kPolygonFill, 6);
            } else if ((r > 0.25 && r < 0.65) || (r > 0.82 && r < 0.97)) {
                ++band;
                for (Rgba d : dots) bandDots += close(px, d, 6);
            } else if (r > 1.1) {
                ++outer, outerBackground += close(px, palette::kBackground, 6);
            }
        }
    stbi_image_free(img.px);
    std::printf("dense face: land %d/%d inside, dots %d/%d in the band, background %d/%d outside\n",
                innerLand, inner, bandDots, band, outerBackground, outer);
    int failures = 0;
    if (inner < 50 || innerLand < 0.95 * inner) {
        std::fprintf(stderr, "FAIL: dense face: the inner disc is not dry land\n");
        ++failures;
    }
    if (band < 500 || bandDots > 0.4 * band) {
        std::fprintf(stderr, "FAIL: dense face: vertex dots pave the spiked band (a smear)\n");
        ++failures;
    }
    if (outer < 500 || outerBackground < 0.95 * outer) {
        std::fprintf(stderr, "FAIL: dense face: the outside is not background\n");
        ++failures;
    }
    return failures;
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;

    SquareHole f("screenshot-test");
    if (!openSquareHole(f)) return 1;
    Model& model = f.model;
    const uint32_t step = f.step;
    const std::string& dir = f.dir;
    const std::string& input = f.input;
    const int W = f.W, H = f.H;
    const Layout& layout = f.layout;
    int failures = 0;
    for (bool back : {false, true}) {
        std::string out = dir + (back ? "/screenshot-test-back.png" : "/screenshot-test.png");
        std::string steps = (back ? "--step " + std::to_string(model.steps()) + " " : "") +
                            "--step " + std::to_string(step);
        Image img;
        std::map<std::string, Rect> printed;
        if (!shootPrinted(input, steps, out, W, H, img, printed)) return 1;
        // The viewer fits clear of the find and Edit boxes (view_fit.h): the same fit here.
        model.fitCamera(layout.canvas, {printed["find-box"], printed["edit-box"]});
        failures += checkShot(model, layout, img, back);
        stbi_image_free(img.px);
    }
    if (failures) return 1;

    // The error view of a self-crossing ring: exit code 4 (invalid), the picture still
    // written, the two crossing edges thick in the error colour at the crossing point and along
    // them, the rest dimmed.
    std::string bad = dir + "/screenshot-test-crossing.json";
    std::ofstream(bad) << R"({"type": "Polygon", "coordinates": [
        [[0, 0], [10, 0], [0, 10], [10, 10], [0, 0]]]})"
                          "\n";
    // The canvas is what the findings panel under it leaves: read from the viewer.
    Image img;
    std::map<std::string, Rect> printed;
    if (!shootPrinted(bad, "--show-error", dir + "/screenshot-test-error.png", W, H, img, printed,
                      true, 4))
        return 1;
    Model crossing;
    crossing.open(bad);
    crossing.setViewport(printed["canvas"]);
    Point x;
    if (!crossing.showError() || !crossing.errorPoint(x)) {
        std::fprintf(stderr, "FAIL: no error view for %s: %s\n", bad.c_str(),
                     crossing.verdict().c_str());
        return 1;
    }
    Rgba seen;
    Vec2 at = crossing.camera().toScreen(x);
    if (!near(img, at, palette::kCulprit, 1, &seen))
        failures += fail("crossing point", at, palette::kCulprit, seen);
    Vec2 along = crossing.camera().toScreen({7.5, 2.5});  // on edge (10,0)-(0,10)
    if (!near(img, along, palette::kCulprit, 1, &seen))
        failures += fail("culprit edge", along, palette::kCulprit, seen);
    Vec2 inside = crossing.camera().toScreen({5, 8.5});  // inside the upper lobe, dimmed
    if (near(img, inside, palette::kCulprit, 2, &seen) ||
        near(img, inside, palette::kPolygonFill, 0, &seen))
        failures +=
            fail("dimmed interior (not fill, not culprit)", inside, palette::kBackground, seen);
    stbi_image_free(img.px);
    // Unreadable input: the window (with the reason) is still pictured, the exit code is 3.
    Image none;
    if (!shoot(dir + "/no-such-polygon.json", "", dir + "/screenshot-test-unreadable.png", W, H,
               none, 3))
        return 1;
    stbi_image_free(none.px);
    if (failures) return 1;
    if (int dense = checkDenseFace(dir, W, H, layout); dense != 0) return dense;
    if (failures) return 1;
    std::printf(
        "ok: step %u, background, water, dry land and Left marker where expected, also "
        "after stepping back from the end; error view: crossing and culprit edge in the error "
        "colour; a 10^5-vertex face reads as a shape\n",
        step);
    return 0;
}
