// GUI test of the error view on real faces (issue 26 §3), at the default 1280x800: every
// finding of a 3-finding face in the findings panel and F8 framing the next, a tiny culprit
// hole thick red and the outer ring not, coincident labels merged and apart, a bad --layer
// said on stderr. Exit 77 (skipped) without a display.

#include "screenshot_support.h"

using namespace flood;
using namespace flood::view;
using namespace flood::view::testing;

namespace {

const int kW = 1280, kH = 800;

// A square with three separate bow-tie holes: the findings panel under the canvas shows every
// finding whole (three invalid-input rows, each inside the panel and the picture, with its red
// tag and its text), not a strip cut after its third line. F8 then frames the second finding:
// its crossing is ringed where the model puts it, its row is the one lit.
int checkFindingsPanel(const std::string& dir) {
    const std::string input = writeFace(dir, "screenshot-test-three-bowties", R"({"type": "Polygon",
        "coordinates": [[[0,0],[30,0],[30,10],[0,10],[0,0]], [[2,2],[6,6],[6,2],[2,6],[2,2]],
        [[12,2],[16,6],[16,2],[12,6],[12,2]], [[22,2],[26,6],[26,2],[22,6],[22,2]]]})");
    Model model;
    model.open(input);
    size_t invalid = 0;
    for (const Finding& f : model.findings()) invalid += f.kind == Verdict::Invalid;
    if (invalid != 3)
        return failWith("three-bowties: want 3 validation findings, the model has " +
                        std::to_string(invalid));
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--show-error --press f8", dir + "/screenshot-test-findings.png", kW,
                      kH, img, layout, true, 4))
        return 1;
    int failures = 0;
    const Rect panel = layout["findings"];
    if (!inside(panel, kW, kH) || panel.h < 60)
        failures += failWith("no findings panel under the canvas");
    const Rect canvas = layout["canvas"];
    if (panel.y < canvas.y + canvas.h - 0.5)
        failures += failWith("the findings panel covers the canvas");
    for (size_t i = 0; i < model.findings().size(); ++i) {
        const std::string name = "finding-" + std::to_string(i);
        if (!layout.count(name)) {
            failures += failWith(name + ": no row in the findings panel");
            continue;
        }
        const Rect row = layout[name];
        if (!roughlyWithin(row, panel) || !inside(row, kW, kH))
            failures += failWith(name + ": its row is not whole inside the panel");
        for (size_t j = 0; j < i; ++j)
            if (overlaps(row, layout["finding-" + std::to_string(j)]))
                failures += failWith(name + " overlaps an earlier row");
        int red = count(img, row, [](Rgba c) { return close(c, palette::kCulprit, 40); });
        int text = count(img, row, [](Rgba c) { return luminance(c) > 180; });
        std::printf("findings panel: row %zu at %.0f,%.0f %.0fx%.0f: %d red, %d text pixels\n", i,
                    row.x, row.y, row.w, row.h, red, text);
        if (red < 15 || text < 60)
            failures += failWith(name + ": its tag or its text is not drawn");
        // F8 lit the second row (the current finding): its background is the header blue.
        int blue = count(img, row, [&](Rgba c) { return c.b > c.r + 40 && c.b > 80; });
        if ((i == 1) != (blue > row.w * row.h / 3))
            failures += failWith(name + (i == 1 ? ": F8's finding is not lit" : ": lit, not F8's"));
    }
    // The second finding framed: its crossing (14, 4) ringed in the error colour.
    model.setViewport(canvas);
    model.showError();
    model.nextFinding(+1);
    Point x;
    Rgba seen;
    if (model.currentFinding() != 1 || !model.errorPoint(x))
        failures += failWith("the model does not go to the second finding");
    else if (Vec2 at = model.camera().toScreen(x); !near(img, at, palette::kCulprit, 2, &seen))
        failures += fail("F8: the second finding's crossing", at, palette::kCulprit, seen);
    stbi_image_free(img.px);
    return failures;
}

// A 1000 x 1000 face whose only trouble is a 4 x 4 hole lying outside it, in a notch, 20 above
// the notch's edge (Greenland's tiny culprit hole): E draws thick red on the hole's four edges
// and nowhere on the outer ring, whose notch edge is in view (thin, as context).
int checkTinyHole(const std::string& dir) {
    const std::string input = writeFace(dir, "screenshot-test-tiny-hole", R"({"type": "Polygon",
        "coordinates": [[[0,0],[1000,0],[1000,400],[500,400],[500,600],[1000,600],[1000,1000],
        [0,1000],[0,0]], [[700,420],[704,420],[704,424],[700,424],[700,420]]]})");
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--show-error", dir + "/screenshot-test-tiny-hole.png", kW, kH, img,
                      layout, true, 4))
        return 1;
    Model model;
    model.open(input);
    model.setViewport(layout["canvas"]);
    if (!model.showError()) return failWith("tiny hole: no error view");
    const Camera& cam = model.camera();
    const Polygon& P = model.polygon();
    std::vector<Rect> labels;
    for (auto& [name, r] : layout)
        if (name.rfind("label-", 0) == 0) labels.push_back(r);
    // Culprit-red pixels across a line at its point `p` (direction d), within 7 px each side.
    auto thickness = [&](Point a, Point b, double t) {
        Vec2 sa = cam.toScreen(a), sb = cam.toScreen(b);
        Vec2 p{sa.x + (sb.x - sa.x) * t, sa.y + (sb.y - sa.y) * t};
        double len = std::hypot(sb.x - sa.x, sb.y - sa.y);
        Vec2 n{-(sb.y - sa.y) / len, (sb.x - sa.x) / len};
        int red = 0;
        for (int k = -7; k <= 7; ++k) {
            int x = int(std::lround(p.x + n.x * k)), y = int(std::lround(p.y + n.y * k));
            if (x >= 0 && y >= 0 && x < img.w && y < img.h)
                red += close(img.at(x, y), palette::kCulprit, 30);
        }
        return std::pair{red, p};
    };
    int failures = 0;
    const Ring& hole = P.rings[1];
    for (Index i = 0; i < hole.count; ++i) {
        Point a = P.vertices[hole.first + i], b = P.vertices[hole.first + (i + 1) % hole.count];
        auto [red, p] = thickness(a, b, 0.5);
        if (red < 3)
            failures +=
                failWith("tiny hole: edge " + std::to_string(i) +
                         " of the hole is not thick red (" + std::to_string(red) + " px at " +
                         std::to_string(int(p.x)) + "," + std::to_string(int(p.y)) + ")");
    }
    // The outer ring where it is in view (away from labels): never thick red.
    const Ring& outer = P.rings[0];
    const Rect canvas = layout["canvas"];
    int probed = 0;
    for (Index i = 0; i < outer.count; ++i) {
        Point a = P.vertices[outer.first + i], b = P.vertices[outer.first + (i + 1) % outer.count];
        Vec2 sa = cam.toScreen(a), sb = cam.toScreen(b);
        const double step = 4 / std::max(4.0, std::hypot(sb.x - sa.x, sb.y - sa.y));  // 4 px
        for (double t = step; t < 1; t += step) {
            auto [red, p] = thickness(a, b, t);
            Rect probe{p.x - 8, p.y - 8, 16, 16};
            if (!roughlyWithin(probe, canvas)) continue;
            bool labelled = false;
            for (const Rect& l : labels) labelled |= overlaps(probe, l);
            if (labelled) continue;
            ++probed;
            if (red >= 2) {
                failures += failWith("tiny hole: the outer ring is thick red at " +
                                     std::to_string(int(p.x)) + "," + std::to_string(int(p.y)));
                break;
            }
        }
    }
    std::printf(
        "tiny hole: 4 hole edges thick red; %d probes on the outer ring in view, none red\n",
        probed);
    if (probed < 40) failures += failWith("tiny hole: the outer ring's nearby edge is not in view");
    stbi_image_free(img.px);
    return failures;
}

// Labels of coincident and near culprit vertices (v0 = v4 at one point, v1 and v5 a few pixels
// apart): one label per point, the coincident ones merged, no two labels overlapping, each with
// its text drawn, none under the find box, the Edit box, the Shrink window or the inset.
int checkLabels(const std::string& dir) {
    const std::string input = writeFace(dir, "screenshot-test-labels", R"({"type": "Polygon",
        "coordinates": [[[0,0],[128,1],[128,-5],[-10,-5],[0,0],[124,0.96875],[-10,10],[0,0]]]})");
    Image img;
    std::map<std::string, Rect> layout;
    if (!shootPrinted(input, "--show-error", dir + "/screenshot-test-labels.png", kW, kH, img,
                      layout, true, 4))
        return 1;
    Model model;
    model.open(input);
    model.setViewport(layout["canvas"]);
    model.showError();
    std::vector<Point> points;
    for (Index v : model.errorCulprits().vertices) points.push_back(model.polygon().vertices[v]);
    std::vector<Point> distinct;
    for (Point p : points)
        if (std::find(distinct.begin(), distinct.end(), p) == distinct.end()) distinct.push_back(p);
    std::vector<Rect> labels;
    for (size_t i = 0; layout.count("label-" + std::to_string(i)); ++i)
        labels.push_back(layout["label-" + std::to_string(i)]);
    int failures = 0;
    if (points.size() < 4 || distinct.size() >= points.size())
        failures += failWith("labels: the face's finding has no coincident culprit vertices");
    if (labels.size() != distinct.size())
        failures += failWith("labels: " + std::to_string(labels.size()) + " labels for " +
                             std::to_string(distinct.size()) + " distinct points (" +
                             std::to_string(points.size()) + " vertices)");
    const Rect canvas = layout["canvas"];
    for (size_t i = 0; i < labels.size(); ++i) {
        const Rect& l = labels[i];
        if (!roughlyWithin(l, canvas))
            failures += failWith("label " + std::to_string(i) + " leaves the canvas");
        for (size_t j = 0; j < i; ++j)
            if (overlaps(l, labels[j]))
                failures += failWith("labels " + std::to_string(j) + " and " + std::to_string(i) +
                                     " overlap");
        for (const char* box : {"find-box", "edit-box", "shrink-box", "inset"})
            if (layout.count(box) && overlaps(l, layout[box]))
                failures += failWith("label " + std::to_string(i) + " is under the " + box);
        int text = count(img, l, [](Rgba c) { return close(c, palette::kCulprit, 40); });
        if (text < 20) failures += failWith("label " + std::to_string(i) + " shows no text");
    }
    std::printf("labels: %zu culprit vertices at %zu points, %zu labels apart\n", points.size(),
                distinct.size(), labels.size());
    stbi_image_free(img.px);
    return failures;
}

// A --layer the dataset does not have, with --screenshot: the reason on stderr, exit 3 (or 2
// without GDAL, which --layer needs).
int checkBadLayer(const std::string& dir) {
    const std::string cmd = std::string("'") + FLOOD_VIEWER + "' '" + FLOOD_SOURCE_DIR +
                            "/polygons/datasets/mixed.geojson' --layer nope --screenshot '" + dir +
                            "/screenshot-test-layer.png' 2>&1 >/dev/null";
    FILE* pipe = popen(cmd.c_str(), "r");
    std::string said;
    char line[512];
    while (pipe && std::fgets(line, sizeof line, pipe)) said += line;
    int rc = pipe ? pclose(pipe) : -1;
    rc = rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
#ifdef FLOOD_GDAL
    const bool ok = rc == 3 && said.find("no layer \"nope\"") != std::string::npos;
#else
    const bool ok = rc == 2 && said.find("GDAL") != std::string::npos;
#endif
    return ok ? 0
              : failWith("--layer nope --screenshot: exit " + std::to_string(rc) +
                         ", stderr: " + said);
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    const std::string dir = FLOOD_WORK_DIR;
    int failures = checkFindingsPanel(dir);
    failures += checkTinyHole(dir);
    failures += checkLabels(dir);
    failures += checkBadLayer(dir);
    if (failures) return 1;
    std::printf(
        "ok: every finding of a 3-finding face in the findings panel and F8 framing the "
        "next; a tiny culprit hole thick red, the outer ring not; coincident labels "
        "merged and apart; a bad --layer said on stderr\n");
    return 0;
}
