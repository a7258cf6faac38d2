// The viewer's error view on real faces, without a window (issue 26 §3): every finding of a
// face in the model, the framing of a finding (its culprit edges whole, much smaller than the
// face), Find and Go framing their target, labels placed apart, the findings panel's place in
// the layout. Compiles to nothing when the viewer is not in the tree.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "label_layout.h"
#include "model.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;

namespace {

// A 30 x 10 square with three separate bow-tie holes: three validation findings.
const char* kThreeBowTies = R"({"type": "Polygon", "coordinates": [
 [[0,0],[30,0],[30,10],[0,10],[0,0]],
 [[2,2],[6,6],[6,2],[2,6],[2,2]],
 [[12,2],[16,6],[16,2],[12,6],[12,2]],
 [[22,2],[26,6],[26,2],[22,6],[22,2]]]})";

// A 1000 x 1000 face with a notch, and a 4 x 4 hole in the notch, 20 from its edge: outside
// its outer ring (a finding blaming rings only).
const char* kTinyHole = R"({"type": "Polygon", "coordinates": [
 [[0,0],[1000,0],[1000,400],[500,400],[500,600],[1000,600],[1000,1000],[0,1000],[0,0]],
 [[700,420],[704,420],[704,424],[700,424],[700,420]]]})";

std::string write(const std::string& test, const char* text) {
    std::string path = (flood::testing::scratch(test) / "face.json").string();
    std::ofstream(path) << text << "\n";
    return path;
}

const Rect kCanvas{300, 0, 680, 483};  // the canvas at 1280x800 beside a findings panel

Point edgeEnd(const Polygon& P, Index e) {
    const Ring& r = P.rings[P.ringOf(e)];
    return P.vertices[e + 1 == r.first + r.count ? r.first : e + 1];
}

WorldBox faceBox(const Polygon& P) {
    WorldBox b;
    for (Point p : P.vertices) b.add(p);
    return b;
}

}  // namespace

TEST(ViewerFindings, EveryFindingOfAFaceInTheVerdictsOrder) {
    Model m;
    m.open(write("three-bowties", kThreeBowTies));
    const auto& f = m.findings();
    size_t invalid = 0;
    for (const Finding& x : f) invalid += x.kind == Verdict::Invalid;
    ASSERT_EQ(invalid, 3u) << m.verdict();
    // The first is validate()'s verdict, the others follow; the flood's failures come last.
    EXPECT_EQ(f[0].message, m.inputDiagnostic().message);
    for (size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(f[i].kind, Verdict::Invalid);
        EXPECT_EQ(f[i].where, "ring " + std::to_string(i + 1) + " vertex 0 (" +
                                  std::to_string(2 + 10 * i) + ", 2)");
        EXPECT_NE(f[i].reason.find("crosses"), std::string::npos) << f[i].reason;
        EXPECT_EQ(f[i].reason.find("ring " + std::to_string(i + 1) + " vertex 0 ("),
                  std::string::npos)
            << "the place is apart: " << f[i].reason;
        ASSERT_EQ(f[i].culprits.edges.size(), 2u);
        for (Index e : f[i].culprits.edges) EXPECT_EQ(m.polygon().ringOf(e), i + 1);
        ASSERT_TRUE(f[i].hasPoint);
        EXPECT_NEAR(f[i].point.x, 4 + 10.0 * i, 1e-9);
        EXPECT_NEAR(f[i].point.y, 4, 1e-9);
    }
    for (size_t i = 3; i < f.size(); ++i) EXPECT_NE(f[i].kind, Verdict::Invalid);
    EXPECT_EQ(m.findingsOmitted(), 0u);
    EXPECT_TRUE(m.findingsComplete());
    EXPECT_EQ(m.errorCulprits().edges, f[0].culprits.edges);

    Model ok;
    ok.open(flood::testing::sourcePath("polygons/hole.json"));
    EXPECT_TRUE(ok.findings().empty()) << ok.verdict();
    EXPECT_FALSE(ok.nextFinding(+1));
}

TEST(ViewerFindings, NextAndPreviousGoRoundTheListAndFrameEach) {
    Model m;
    m.open(write("next-finding", kThreeBowTies));
    m.setViewport(kCanvas);
    const size_t n = m.findings().size();
    ASSERT_GE(n, 3u);
    EXPECT_FALSE(m.errorView());
    ASSERT_TRUE(m.nextFinding(+1));  // out of the error view: the current one, the first
    EXPECT_TRUE(m.errorView());
    EXPECT_EQ(m.currentFinding(), 0u);
    ASSERT_TRUE(m.nextFinding(+1));
    EXPECT_EQ(m.currentFinding(), 1u);
    EXPECT_EQ(m.errorCulprits().edges, m.findings()[1].culprits.edges);
    Point p;
    ASSERT_TRUE(m.errorPoint(p));
    EXPECT_NEAR(p.x, 14, 1e-9);
    ASSERT_TRUE(m.nextFinding(-1));
    ASSERT_TRUE(m.nextFinding(-1));
    EXPECT_EQ(m.currentFinding(), n - 1) << "round the list";
    m.hideError();
    ASSERT_TRUE(m.showError());  // E again: the finding chosen last
    EXPECT_EQ(m.currentFinding(), n - 1);
    EXPECT_FALSE(m.showFinding(n));
}

TEST(ViewerFraming, AFindingIsFramedWithItsEdgesWholeAndMuchSmallerThanTheFace) {
    Model m;
    m.open(write("framing", kThreeBowTies));
    m.setViewport(kCanvas);
    const Polygon& P = m.polygon();
    const WorldBox face = faceBox(P);
    for (size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        ASSERT_TRUE(m.showFinding(i));
        const WorldBox view = visibleBox(m.camera());
        for (Index e : m.findings()[i].culprits.edges) {
            EXPECT_TRUE(view.contains(P.vertices[e]));
            EXPECT_TRUE(view.contains(edgeEnd(P, e)));
        }
        // Not the whole face, nor the neighbouring holes' crossings.
        EXPECT_LT(view.w(), face.w() / 2);
        EXPECT_LT(view.w() * view.h(), face.w() * face.h() / 4);
        for (size_t j = 0; j < 3; ++j) {
            if (j != i) {
                EXPECT_FALSE(view.contains(m.findings()[j].point)) << j;
            }
        }
        // A margin: the culprit edges do not touch the view's border.
        WorldBox culprit;
        for (Index e : m.findings()[i].culprits.edges) culprit.add(P.vertices[e]);
        EXPECT_GT(culprit.x0 - view.x0, 0.1 * culprit.w());
        EXPECT_GT(view.y1 - culprit.y1, 0.1 * culprit.h());
    }
}

TEST(ViewerFraming, AHoleBlamedWholeIsFramedNotTheOuterRing) {
    Model m;
    m.open(write("tiny-hole", kTinyHole));
    m.setViewport(kCanvas);
    ASSERT_FALSE(m.findings().empty());
    const Finding& f = m.findings()[0];
    ASSERT_EQ(f.kind, Verdict::Invalid);
    ASSERT_EQ(f.culprits.rings.size(), 2u) << f.message;
    EXPECT_EQ(f.culprits.rings[0], 1u);
    ASSERT_TRUE(m.showFinding(0));
    const WorldBox view = visibleBox(m.camera());
    const Polygon& P = m.polygon();
    for (Index i = 0; i < 4; ++i) EXPECT_TRUE(view.contains(P.vertices[P.rings[1].first + i]));
    // The notch's edge 20 below the hole is in view as context, the rest of the face is not.
    EXPECT_TRUE(view.contains({702, 400}));
    EXPECT_LT(view.w(), 1000 / 8.0);
    EXPECT_LT(view.h(), 1000 / 8.0);
    for (Index v = 0; v < P.rings[0].count; ++v) EXPECT_FALSE(view.contains(P.vertices[v])) << v;
}

TEST(ViewerFraming, FindAndGoFrameTheirTarget) {
    Model m;
    m.open(write("find-frames", kThreeBowTies));
    m.fitCamera(kCanvas);
    const double fitted = m.camera().scale();
    const Polygon& P = m.polygon();
    FindTarget t = m.find("v8");  // (12, 2): its neighbours (12, 6) and (16, 6)
    ASSERT_TRUE(t.ok) << t.message;
    const Vec2 mid{kCanvas.x + kCanvas.w / 2, kCanvas.y + kCanvas.h / 2};
    Vec2 at = m.camera().toScreen(P.vertices[8]);
    EXPECT_NEAR(at.x, mid.x, 1e-6);
    EXPECT_NEAR(at.y, mid.y, 1e-6);
    EXPECT_GT(m.camera().scale(), 1.5 * fitted) << "framed, not only centred";
    const WorldBox view = visibleBox(m.camera());
    EXPECT_TRUE(view.contains(P.vertices[11]));  // the nearer neighbour, 4 away
    EXPECT_FALSE(view.contains(P.vertices[0]));

    m.fitCamera(kCanvas);
    t = m.find("t0");
    ASSERT_TRUE(t.ok) << t.message;
    for (Index v : m.trace().triangles[0])
        EXPECT_TRUE(visibleBox(m.camera()).contains(P.vertices[v]));

    // Go: the violation's step, its vertices framed.
    Violation v;
    v.step = 3;
    v.vertices = {12, 13};
    m.fitCamera(kCanvas);
    m.goToViolation(v);
    EXPECT_EQ(m.step(), 3u);
    EXPECT_TRUE(visibleBox(m.camera()).contains(P.vertices[12]));
    EXPECT_TRUE(visibleBox(m.camera()).contains(P.vertices[13]));
    EXPECT_GT(m.camera().scale(), 1.5 * fitted);
}

TEST(ViewerFraming, FrameNeighbourhoodKeepsAMarginAndAMinimumSide) {
    WorldBox b;
    b.add({0, 0}), b.add({10, 0});
    Camera c = frameNeighbourhood(b, 4, {0, 0, 400, 400});
    WorldBox v = visibleBox(c);
    EXPECT_TRUE(v.contains({-2.4, 0}) && v.contains({12.4, 0}));
    EXPECT_GE(v.h(), 6) << "never thinner than the minimum side, with its margin";
    WorldBox point;
    point.add({5, 5});
    c = frameNeighbourhood(point, 0, {0, 0, 400, 400});
    EXPECT_TRUE(std::isfinite(c.scale()) && c.scale() > 0);
}

TEST(ViewerLabels, PlacedApartOutOfTheBoxesAndBesideTheirPoint) {
    const Rect area{0, 0, 600, 400};
    const std::vector<Rect> boxes{{0, 0, 260, 36}, {500, 0, 100, 36}};
    // Six labels at points a few pixels apart (v205, v206, v207, ...), one under a box.
    std::vector<LabelRequest> labels;
    for (int i = 0; i < 6; ++i)
        labels.push_back({{300.0 + 3 * i, 200.0 + 2 * i}, 110, 17, false, {}});
    labels.push_back({{40, 30}, 110, 17, false, {}});
    std::vector<PlacedLabel> placed = placeLabels(labels, area, boxes);
    ASSERT_EQ(placed.size(), labels.size());
    for (size_t i = 0; i < placed.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_FALSE(placed[i].overlaps);
        const Rect& r = placed[i].box;
        EXPECT_TRUE(r.x >= 0 && r.y >= 0 && r.x + r.w <= 600 && r.y + r.h <= 400);
        for (const Rect& b : boxes) EXPECT_FALSE(overlap(r, b));
        for (size_t j = 0; j < i; ++j) EXPECT_FALSE(overlap(r, placed[j].box)) << j;
        for (const LabelRequest& l : labels)
            EXPECT_FALSE(r.contains(l.anchor)) << "a label covers a labelled point";
        // Beside its point, or tied to it by a leader line.
        const double d =
            std::hypot(placed[i].to.x - labels[i].anchor.x, placed[i].to.y - labels[i].anchor.y);
        EXPECT_TRUE(d < 12 || placed[i].leader) << d;
    }
    EXPECT_FALSE(placed[0].leader) << "the first sits where a label usually does";

    std::vector<PointGroup> g = groupCoincident({{1, 1}, {2, 2}, {1, 1}, {-0.0, 0}, {0, 0}});
    ASSERT_EQ(g.size(), 3u);
    EXPECT_EQ(g[0].members, (std::vector<size_t>{0, 2}));
    EXPECT_EQ(g[2].members, (std::vector<size_t>{3, 4}));
}

TEST(ViewerLayout, TheFindingsPanelSitsUnderTheCanvasAtMostAThirdOfIt) {
    Layout plain = computeLayout(1280, 800, 1);
    EXPECT_EQ(plain.findings.h, 0);
    Layout with = computeLayout(1280, 800, 1, 0, 150);
    EXPECT_EQ(with.findings.h, 150);
    EXPECT_EQ(with.findings.x, with.canvas.x);
    EXPECT_EQ(with.findings.w, with.canvas.w);
    EXPECT_EQ(with.findings.y, with.canvas.y + with.canvas.h);
    EXPECT_EQ(with.findings.y + with.findings.h, with.bottom.y);
    Layout capped = computeLayout(1280, 800, 1, 0, 5000);
    EXPECT_NEAR(capped.findings.h, plain.canvas.h / 3, 1e-9);
}

TEST(ViewerFindings, AnInvalidEditBringsItsFindingsFromItsFlood) {
    Model m;
    m.open(write("edit-findings", kThreeBowTies));
    Model::EditedRun run = Model::floodEdit(m.polygon(), m.path());
    // Prepared with the flood, off the UI thread: its three findings listed already.
    size_t listed = 0;
    for (const Finding& x : run.verdict.findings) listed += x.kind == Verdict::Invalid;
    ASSERT_EQ(listed, 3u);
    m.adoptEdit(std::move(run));
    size_t invalid = 0;
    for (const Finding& x : m.findings()) invalid += x.kind == Verdict::Invalid;
    EXPECT_EQ(invalid, 3u);
}

#endif
