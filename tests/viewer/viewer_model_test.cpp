// The viewer's model without a window: replay consistency in both directions, seek versus
// stepping, breakpoints, vertex classes and the camera. Compiles to nothing when the viewer
// is not in the tree, since the model lives in viewer/ (it is built even with FLOOD_VIEWER=OFF).
#if __has_include("model.h")
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "canvas_geometry.h"
#include "edit.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "gorge_focus.h"
#include "key_queue.h"
#include "model.h"
#include "scene.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using flood::testing::RunResult;
using flood::testing::runShell;
using flood::testing::scratch;

namespace {

std::vector<std::string> polygonFiles() {
    auto files = flood::polygonFiles(std::string(FLOOD_SOURCE_DIR) + "/polygons");
    return files;
}

Polygon squareWithHole(bool reverseOuter, bool reverseHole) {
    std::vector<Point> outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    std::vector<Point> hole{{3, 3}, {3, 7}, {7, 7}, {7, 3}};
    if (reverseOuter) std::reverse(outer.begin(), outer.end());
    if (reverseHole) std::reverse(hole.begin(), hole.end());
    Polygon p;
    p.addRing(outer, true);
    p.addRing(hole, false);
    return p;
}

}  // namespace

TEST(ViewerModel, ForwardThenBackwardGivesIdenticalStates) {
    auto files = polygonFiles();
    ASSERT_FALSE(files.empty()) << "polygons/ has no sample polygons";
    for (const auto& f : files) {
        Model m;
        m.open(f);
        std::vector<ReplayState> forward;
        m.first();
        forward.push_back(m.state());
        while (m.step() < m.steps()) {
            m.stepForward();
            forward.push_back(m.state());
        }
        ASSERT_EQ(forward.size(), m.steps() + 1u) << f;
        while (m.step() > 0) {
            m.stepBack();
            EXPECT_TRUE(m.state() == forward[m.step()]) << f << " step " << m.step();
        }
    }
}

TEST(ViewerModel, SeekEqualsStepping) {
    for (const auto& f : polygonFiles()) {
        Model stepping, seeking;
        stepping.open(f);
        seeking.open(f);
        stepping.first();
        // Seek in a scrambled order so keyframes are crossed in both directions.
        for (uint32_t s = 0; s <= stepping.steps(); ++s) {
            uint32_t target = (s * 7919u) % (stepping.steps() + 1);
            seeking.seek(target);
            Model fresh;
            fresh.open(f);
            fresh.first();
            for (uint32_t i = 0; i < target; ++i) fresh.stepForward();
            EXPECT_TRUE(seeking.state() == fresh.state()) << f << " seek " << target;
            if (HasFailure()) return;
        }
    }
}

TEST(ViewerModel, BreakpointsStopAtTheFirstMatchingEvent) {
    for (const auto& f : polygonFiles()) {
        Model m;
        m.open(f);
        const auto& ev = m.trace().events;
        for (int a = 1; a < int(Action::Count); ++a) {
            Breakpoints b;
            b.actions[size_t(a)] = true;
            m.setBreakpoints(b);
            m.first();
            uint32_t expected = 0;
            for (uint32_t i = 0; i < ev.size() && !expected; ++i)
                if (ev[i].action == Action(a)) expected = i + 1;
            bool hit = m.runToBreakpoint(+1);
            EXPECT_EQ(hit, expected != 0) << f << " " << actionName(Action(a));
            EXPECT_EQ(m.step(), expected ? expected : m.steps()) << f;
            // Backward from the end finds the last one.
            m.last();
            uint32_t lastHit = 0;
            for (uint32_t i = 0; i + 1 < ev.size(); ++i)  // events before the final step
                if (ev[i].action == Action(a)) lastHit = i + 1;
            EXPECT_EQ(m.runToBreakpoint(-1), lastHit != 0) << f;
            EXPECT_EQ(m.step(), lastHit) << f;
        }
        // A triangle breakpoint stops where that triangle is cut.
        if (!m.trace().triangles.empty()) {
            uint32_t t = uint32_t(m.trace().triangles.size() / 2);
            Breakpoints b;
            b.triangle = t;
            m.setBreakpoints(b);
            m.first();
            ASSERT_TRUE(m.runToBreakpoint(+1)) << f;
            EXPECT_EQ(m.step(), m.triangleStep(t)) << f;
            const Event* e = m.currentEvent();
            EXPECT_TRUE(t >= e->firstTriangle && t < e->firstTriangle + e->triangleCount);
            EXPECT_GE(m.state().triangleCount, t + 1);
        }
        // A vertex breakpoint stops when it becomes one of the fingers.
        if (m.steps() > 1) {
            Index v = ev.back().before.left;
            if (v != kNone) {
                Breakpoints b;
                b.vertex = v;
                m.setBreakpoints(b);
                m.first();
                ASSERT_TRUE(m.runToBreakpoint(+1)) << f;
                const Fingers& after = m.currentEvent()->after;
                EXPECT_TRUE(after.left == v || after.right == v || after.nextLeft == v ||
                            after.nextRight == v);
            }
        }
    }
}

TEST(ViewerModel, LongRunsReplayAcrossKeyframes) {
    // Hundreds of events, so seeking crosses the replay's keyframes in both directions.
    Model m;
    m.openPolygon(generate("circle-holes", 7, 1500), "circle-holes", {});
    ASSERT_GT(m.steps(), 600u) << m.verdict();
    std::vector<ReplayState> forward;
    for (uint32_t s = 0; s <= m.steps(); ++s) {
        m.seek(s);
        forward.push_back(m.state());
    }
    for (uint32_t s : {m.steps(), 0u, 511u, 257u, 255u, 256u, 1u, m.steps() - 1, 300u}) {
        m.seek(s);
        EXPECT_TRUE(m.state() == forward[s]) << "seek " << s;
    }
    while (m.step() > 0) {
        m.stepBack();
        if (m.step() % 97 == 0) {
            EXPECT_TRUE(m.state() == forward[m.step()]) << "back";
        }
    }
}

TEST(ViewerModel, KeyframesStaySmallAndSeekExactly) {
    // Many dormant gorges at once (circle-sqrt-holes) and a long active chain (comb): the
    // keyframes share dormant chains and are spaced by their size, yet every seek is exact.
    for (const char* family : {"circle-sqrt-holes", "comb", "circle-holes"}) {
        Trace t = record(generate(family, 3, 4000));
        ASSERT_TRUE(t.diagnostic.ok()) << family << ": " << t.diagnostic.message;
        Replay stepper(t, 1u << 30);  // the first keyframe only: pure stepping
        for (uint32_t interval : {4u, 256u}) {
            Replay seeker(t, interval);
            SCOPED_TRACE(std::string(family) + " interval " + std::to_string(interval));
            EXPECT_GT(seeker.keyframeCount(), t.events.size() / (256 * Replay::kMaxWorkFactor));
            // Full copies (every dormant chain, every bridge) would cost ~1 kB per event here.
            EXPECT_LT(seeker.keyframeBytes(), 128 * t.events.size() + 512 * seeker.keyframeCount());
            const uint32_t n = seeker.size();
            for (uint32_t s = 0; s <= n; ++s) {
                uint32_t target = uint32_t((uint64_t(s) * 7919u) % (n + 1));
                ReplayState want = stepper.seek(target);
                EXPECT_TRUE(seeker.seek(target) == want) << "seek " << target;
                if (HasFailure()) return;
            }
        }
    }
}

TEST(ViewerModel, PlaybackStopsAtBreakpointAndEnd) {
    Model m;
    m.openPolygon(generate("comb", 3, 60), "comb", {});
    m.first();
    m.setSpeed(1000);
    m.togglePlay();
    m.advance(10);  // far more than enough steps
    EXPECT_FALSE(m.playing());
    EXPECT_EQ(m.step(), m.steps());

    Breakpoints bridges;
    bridges.actions[size_t(Action::Bridge)] = true;
    m.setBreakpoints(bridges);
    m.first();
    m.togglePlay();
    m.advance(10);
    EXPECT_FALSE(m.playing());
    ASSERT_NE(m.currentEvent(), nullptr);
    EXPECT_EQ(m.currentEvent()->action, Action::Bridge) << "comb has sags: it must bridge";
}

TEST(ViewerModel, VertexClassesIgnoreRingOrientation) {
    for (bool ro : {false, true})
        for (bool rh : {false, true}) {
            auto c = classifyVertices(squareWithHole(ro, rh));
            auto at = [&](Point p) {
                Polygon poly = squareWithHole(ro, rh);
                for (Index i = 0; i < poly.vertices.size(); ++i)
                    if (poly.vertices[i] == p) return c[i];
                return VertexClass::Count;
            };
            EXPECT_EQ(at({0, 0}), VertexClass::Bottom);     // convex minimum of the outer loop
            EXPECT_EQ(at({10, 10}), VertexClass::Ceiling);  // convex maximum
            EXPECT_EQ(at({3, 3}), VertexClass::Sag);        // the hole's lowest point
            EXPECT_EQ(at({7, 7}), VertexClass::Top);        // the hole's highest point
            EXPECT_EQ(at({10, 0}), VertexClass::Regular);
        }
}

TEST(ViewerModel, CameraRoundTripsAndZoomsAtTheCursor) {
    Polygon p = squareWithHole(false, false);
    Camera cam;
    cam.fit(p, Rect{100, 50, 400, 300});
    for (Point q : p.vertices) {
        Vec2 s = cam.toScreen(q);
        EXPECT_TRUE(Rect({100, 50, 400, 300}).contains(s));
        Point back = cam.toWorld(s);
        EXPECT_NEAR(back.x, q.x, 1e-9);
        EXPECT_NEAR(back.y, q.y, 1e-9);
    }
    Vec2 cursor{220, 130};
    Point before = cam.toWorld(cursor);
    cam.zoomAt(cursor, 3.5);
    Point after = cam.toWorld(cursor);
    EXPECT_NEAR(before.x, after.x, 1e-9);
    EXPECT_NEAR(before.y, after.y, 1e-9);
    // y is up in the world and down on screen.
    EXPECT_LT(cam.toScreen({0, 10}).y, cam.toScreen({0, 0}).y);
}

TEST(ViewerModel, TranscriptItemsFollowTheCoreTranscript) {
    for (const auto& f : polygonFiles()) {
        Model m;
        m.open(f);
        std::string text = transcript(m.trace().events);
        size_t at = 0;
        for (const auto& item : m.transcript()) {
            size_t found = text.find(item.text, at);
            ASSERT_NE(found, std::string::npos) << f << ": " << item.text << " in " << text;
            at = found + item.text.size();
        }
    }
}

TEST(ViewerModel, InvalidInputStillOpensAndBlamesVertices) {
    std::string path = ::testing::TempDir() + "viewer-bowtie.json";
    std::ofstream(path)
        << R"({"type":"Polygon","coordinates":[[[0,0],[10,10],[10,0],[0,10],[0,0]]]})";
    Model m;
    m.open(path);
    EXPECT_FALSE(m.inputDiagnostic().ok());
    EXPECT_EQ(m.polygon().vertices.size(), 4u);
    EXPECT_FALSE(m.offenders().empty()) << m.inputDiagnostic().message;
    for (const Event& e : m.trace().events)
        if (e.action == Action::Forbidden) {
            EXPECT_EQ(m.step(), e.step + 1);
            break;
        }
    Scene sc = buildScene(m);  // must not trip on whatever state the machine stopped in
    EXPECT_EQ(sc.rings.size(), 1u);

    Model missing;
    missing.open("/nonexistent/polygon.json");
    EXPECT_FALSE(missing.inputDiagnostic().ok());
    EXPECT_TRUE(missing.polygon().vertices.empty());
    EXPECT_EQ(missing.steps(), 0u);
}

TEST(ViewerModel, SceneShowsTheStateOfTheStep) {
    for (const auto& f : polygonFiles()) {
        Model m;
        m.open(f);
        for (uint32_t s = 0; s <= m.steps(); ++s) {
            m.seek(s);
            Scene sc = buildScene(m);
            EXPECT_EQ(sc.water.size() + sc.current.size(), m.state().triangleCount) << f;
            const Event* e = m.currentEvent();
            EXPECT_EQ(sc.current.size(), e ? e->triangleCount : 0u) << f << " step " << s;
        }
        std::ostringstream svg;
        writeSceneSvg(svg, buildScene(m), m.polygon(), 600);
        std::string text = svg.str(), needle = "<polygon ";
        size_t count = 0;
        for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
            ++count;
        EXPECT_EQ(text.rfind("<svg", 0), 0u) << f;
        EXPECT_EQ(count, m.state().triangleCount) << f << ": one SVG polygon per triangle";
    }
}
TEST(ViewerModel, CanvasBuffersDrawWhatTheSceneDraws) {
    // The GPU path (static buffers + per-step overlay) against buildScene, which the SVG
    // export uses: same primitives at every step, the step's triangles a prefix.
    for (const auto& f : polygonFiles()) {
        Model m;
        m.open(f);
        CanvasGeometry g = buildCanvasGeometry(m);
        ASSERT_EQ(g.positions.size(), 2 * m.polygon().vertices.size()) << f;
        ASSERT_EQ(g.triangles.size(), 3 * m.trace().triangles.size()) << f;
        EXPECT_EQ(g.classes.size() + g.regular.size(), m.polygon().vertices.size()) << f;
        for (uint32_t s = 0; s <= m.steps(); ++s) {
            m.seek(s);
            SCOPED_TRACE(f + " step " + std::to_string(s));
            Scene full = buildScene(m);
            CanvasOverlay ov = buildCanvasOverlay(m, {}, g.origin);
            uint32_t n = m.state().triangleCount;
            ASSERT_EQ(full.water.size() + full.current.size(), n);
            size_t bridges = m.state().bridges.size();
            ASSERT_LE(bridges, g.bridges.size());
            EXPECT_EQ(full.lines.size(), 3 * n + g.boundary.size() + bridges + ov.lines.size());
            EXPECT_EQ(full.markers.size(), g.classes.size() + g.regular.size() + ov.markers.size());
            for (size_t i = 0; i < bridges; ++i) {
                Point sag = m.polygon().vertices[m.state().bridges[i].first];
                EXPECT_FLOAT_EQ(g.bridges[i].ax, float(sag.x - g.origin.x));
                EXPECT_FLOAT_EQ(g.bridges[i].ay, float(sag.y - g.origin.y));
            }
            // The water is the prefix before the current event's triangles.
            const Event* e = m.currentEvent();
            EXPECT_EQ(full.water.size(), e ? e->firstTriangle : n);
            for (uint32_t t = 0; t < n && t < 3; ++t) {
                Point a = m.polygon().vertices[g.triangles[3 * t]];
                const Scene::Tri& st =
                    t < full.water.size() ? full.water[t] : full.current[t - full.water.size()];
                EXPECT_EQ(a, st.a);
            }
            if (HasFailure()) return;
        }
    }
}

TEST(ViewerModel, TriangleGridFindsTheCutTrianglesInAView) {
    Model m;
    m.openPolygon(generate("circle-holes", 5, 3000), "circle-holes", {});
    TriangleGrid grid;
    grid.build(m.polygon(), m.trace().triangles);
    const auto& tris = m.trace().triangles;
    ASSERT_GT(tris.size(), 1000u);
    Point lo{-0.3, -0.2}, hi{0.25, 0.4};
    for (uint32_t count : {0u, 17u, uint32_t(tris.size() / 2), uint32_t(tris.size())}) {
        std::vector<uint32_t> got, want;
        EXPECT_TRUE(
            grid.forEach(lo, hi, count, tris.size(), [&](uint32_t t) { got.push_back(t); }));
        for (uint32_t t = 0; t < count; ++t) {
            Point c = grid.centroid(t);
            if (c.x >= lo.x && c.x <= hi.x && c.y >= lo.y && c.y <= hi.y) want.push_back(t);
        }
        if (count == tris.size()) {
            EXPECT_GT(want.size(), 50u) << "the box must hold triangles";
        }
        std::sort(got.begin(), got.end());
        // Cells cover the box, so the grid may offer a few neighbours: never miss one.
        EXPECT_TRUE(std::includes(got.begin(), got.end(), want.begin(), want.end())) << count;
        for (uint32_t t : got) EXPECT_LT(t, count);
    }
    size_t calls = 0;
    EXPECT_FALSE(
        grid.forEach({-10, -10}, {10, 10}, uint32_t(tris.size()), 50, [&](uint32_t) { ++calls; }));
    EXPECT_EQ(calls, 0u) << "over the cap: nothing drawn";
}

// ---- verdicts, culprits, find, traces (issue 11) ------------------------------------------
namespace {
std::string invalidPath(const std::string& f) {
    return std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid/" + f;
}
size_t countKind(const Model& m, Verdict k) {
    size_t n = 0;
    for (const auto& l : m.verdictLines()) n += l.kind == k;
    return n;
}
bool contains(const std::vector<uint32_t>& v, uint32_t x) {
    return std::find(v.begin(), v.end(), x) != v.end();
}
}  // namespace

TEST(ViewerVerdict, ValidSampleIsOkOnlyBecauseTheCheckerPassed) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    ASSERT_EQ(m.verdictLines().size(), 1u) << m.verdict();
    EXPECT_EQ(m.verdictLines()[0].kind, Verdict::Ok);
    EXPECT_TRUE(m.check().ok);
    EXPECT_FALSE(m.failed());
    EXPECT_EQ(m.exitCode(), 0);
    EXPECT_EQ(m.firstErrorStep(), kNone);
    EXPECT_FALSE(m.showError());
}

TEST(ViewerVerdict, InvalidInputNeverSaysOk) {
    Model m;
    m.open(invalidPath("self-intersection.json"));
    EXPECT_EQ(countKind(m, Verdict::Invalid), 1u) << m.verdict();
    EXPECT_EQ(countKind(m, Verdict::Ok), 0u) << m.verdict();
    EXPECT_EQ(m.verdict().find("ok"), std::string::npos) << m.verdict();
    EXPECT_TRUE(m.failed());
    EXPECT_EQ(m.exitCode(), 4);
}

TEST(ViewerVerdict, ForbiddenRunWithoutValidationHasItsOwnLine) {
    // As `--no-validate`: the polygon is flooded as read; some forbidden-*.json stops the machine.
    bool seen = false;
    for (const char* f : {"forbidden-left-behind.json", "forbidden-bad-triangle.json",
                          "forbidden-fill-open.json", "forbidden-spill-no-bottom.json"}) {
        ReadResult r = readPolygonFile(invalidPath(f));
        ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
        Model m;
        m.openPolygon(r.polygon, f, Diagnostic{});
        if (countKind(m, Verdict::Forbidden) == 0) continue;
        seen = true;
        EXPECT_EQ(m.verdictLines().size(), 1u) << m.verdict();
        EXPECT_EQ(m.exitCode(), 5);
        ASSERT_NE(m.firstErrorStep(), kNone);
        EXPECT_EQ(m.trace().events[m.firstErrorStep() - 1].action, Action::Forbidden);
        const Event& e = m.trace().events[m.firstErrorStep() - 1];
        if (e.culprit != kNone) {
            EXPECT_EQ(m.errorCulprits().vertices.front(), e.culprit) << f;
        }
        EXPECT_EQ(m.trace().diagnostic.culprits.vertices, m.errorCulprits().vertices) << f;
    }
    EXPECT_TRUE(seen);
}

TEST(ViewerVerdict, CheckerRejectionIsShownAndBlamesTheTriangle) {
    // A recorded run of a valid polygon with two triangles swapped in orientation: only the
    // exact checker can tell.
    Polygon p = squareWithHole(false, false);
    ASSERT_TRUE(validate(p, "square").ok());
    Trace t = record(p);
    ASSERT_TRUE(t.diagnostic.ok());
    std::swap(t.triangles[3][0], t.triangles[3][1]);
    Model m;
    m.openTrace(t, "tampered.jsonl");
    ASSERT_EQ(m.verdictLines().size(), 1u) << m.verdict();
    EXPECT_EQ(m.verdictLines()[0].kind, Verdict::Checker);
    EXPECT_NE(m.verdict().find("clockwise-triangle: triangle 3"), std::string::npos) << m.verdict();
    EXPECT_EQ(m.errorCulprits().triangles, std::vector<uint32_t>{3});
    EXPECT_EQ(m.firstErrorStep(), m.triangleStep(3));
    EXPECT_EQ(m.exitCode(), 6);

    Model file;  // the committed one: a ring through one point twice
    file.open(invalidPath("checker-rejects.json"));
    EXPECT_EQ(countKind(file, Verdict::Ok), 0u) << file.verdict();
    EXPECT_TRUE(file.failed());

    // As `--no-validate`: only the checker's rejection (triangle-count), blaming the part's ring.
    ReadResult r = readPolygonFile(invalidPath("checker-rejects.json"));
    Model unchecked;
    unchecked.openPolygon(r.polygon, "checker-rejects.json", Diagnostic{});
    ASSERT_EQ(unchecked.verdictLines().size(), 1u) << unchecked.verdict();
    EXPECT_EQ(unchecked.verdictLines()[0].kind, Verdict::Checker) << unchecked.verdict();
    EXPECT_NE(unchecked.verdict().find("triangle-count"), std::string::npos) << unchecked.verdict();
    EXPECT_EQ(unchecked.errorCulprits().rings, std::vector<uint32_t>{0});
    EXPECT_EQ(unchecked.exitCode(), 6);
    unchecked.setViewport({0, 0, 800, 600});
    EXPECT_TRUE(unchecked.showError());
}

TEST(ViewerCulprits, ValidationBlamesWhatItsMessageNames) {
    // Every vertex the culprits list is named in the message as "ring R vertex V" or as an
    // edge "ring R edge A-B"; the first is the message's global vertex.
    for (const char* f :
         {"self-intersection.json", "spike.json", "vertex-on-own-edge.json", "hole-outside.json",
          "holes-overlapping.json", "point-hole-on-edge.json", "crossing-at-shared-vertex.json",
          "collinear-overlap.json", "zero-area.json"}) {
        Model m;
        m.open(invalidPath(f));
        const Diagnostic& d = m.inputDiagnostic();
        ASSERT_FALSE(d.ok()) << f;
        const Culprits& c = d.culprits;
        ASSERT_FALSE(c.vertices.empty()) << f << ": " << d.message;
        EXPECT_NE(d.message.find("(global vertex " + std::to_string(c.vertices[0]) + ")"),
                  std::string::npos)
            << f << ": " << d.message;
        const Polygon& P = m.polygon();
        for (uint32_t r : c.rings)
            EXPECT_NE(d.message.find("ring " + std::to_string(r)), std::string::npos)
                << f << ": " << d.message;
        for (uint32_t e : c.edges) {
            uint32_t r = P.ringOf(e), local = e - P.rings[r].first;
            if (e == c.vertices[0] && d.message.find("the next edge") != std::string::npos)
                continue;
            EXPECT_NE(d.message.find("ring " + std::to_string(r) + " edge " +
                                     std::to_string(local) + "-"),
                      std::string::npos)
                << f << ": " << d.message;
        }
        EXPECT_EQ(m.offenders().empty(), false);
        for (uint32_t v : c.vertices)
            EXPECT_TRUE(std::binary_search(m.offenders().begin(), m.offenders().end(), v));
        m.setViewport({0, 0, 800, 600});
        EXPECT_TRUE(m.showError()) << f;
        EXPECT_TRUE(m.errorView());
        for (uint32_t v : c.vertices)
            EXPECT_TRUE(m.camera().viewport().contains(m.camera().toScreen(P.vertices[v]))) << f;
    }
}

TEST(ViewerCulprits, GeneratedInvalidFamiliesBlameTheNamedVertex) {
    for (const std::string& family : invalidFamilyNames())
        for (uint64_t seed : {1, 2, 3}) {
            Polygon p = generateInvalid(family, seed, 200);
            Diagnostic d = validate(p, family);
            if (d.ok()) continue;  // random-lattice may need another seed; others always fail
            const Culprits& c = d.culprits;
            ASSERT_FALSE(c.vertices.empty()) << family << ": " << d.message;
            EXPECT_NE(d.message.find("(global vertex " + std::to_string(c.vertices[0]) + ")"),
                      std::string::npos)
                << family << ": " << d.message;
            uint32_t r = p.ringOf(c.vertices[0]);
            EXPECT_NE(d.message.find("ring " + std::to_string(r) + " vertex " +
                                     std::to_string(c.vertices[0] - p.rings[r].first)),
                      std::string::npos)
                << family << ": " << d.message;
            for (uint32_t x : c.rings) EXPECT_LT(x, p.rings.size());
            for (uint32_t v : c.vertices) EXPECT_TRUE(contains(c.rings, p.ringOf(v))) << family;
        }
}

TEST(ViewerCulprits, CrossingEdgesGiveTheCrossingPoint) {
    Model m;
    m.open(invalidPath("self-intersection.json"));  // (0,0)-(10,10) crosses (10,0)-(0,12)
    const Culprits& c = m.inputDiagnostic().culprits;
    ASSERT_EQ(c.edges.size(), 2u) << m.inputDiagnostic().message;
    EXPECT_TRUE(contains(c.edges, 0) && contains(c.edges, 2));
    EXPECT_EQ(c.vertices.size(), 4u);
    Point p;
    ASSERT_TRUE(m.errorPoint(p));
    EXPECT_NEAR(p.x, 60.0 / 11, 1e-9);
    EXPECT_NEAR(p.y, 60.0 / 11, 1e-9);

    Model touch;  // a vertex on its own edge: the point is exact, the vertex's coordinates
    touch.open(invalidPath("vertex-on-own-edge.json"));
    const Culprits& t = touch.inputDiagnostic().culprits;
    ASSERT_TRUE(t.hasPoint) << touch.inputDiagnostic().message;
    EXPECT_EQ(Point({t.x, t.y}), touch.polygon().vertices[t.vertices[0]]);
    EXPECT_EQ(t.edges.size(), 1u);
}

TEST(ViewerFind, EachQueryKindCentresAndSeeks) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    m.fitCamera({0, 0, 800, 600});
    const Polygon& P = m.polygon();
    Vec2 mid{400, 300};
    auto near = [&](Point p) {
        Vec2 s = m.camera().toScreen(p);
        return std::abs(s.x - mid.x) < 1e-6 && std::abs(s.y - mid.y) < 1e-6;
    };
    FindTarget f = m.find("v5");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_TRUE(near(P.vertices[5]));
    ASSERT_NE(f.seekTo, kNone);
    EXPECT_EQ(m.step(), f.seekTo);
    const Event& e = m.trace().events[m.step() - 1];
    bool involved = false;
    for (Index u :
         {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight, e.bottom, e.sag, e.top})
        involved |= u == 5;
    EXPECT_TRUE(involved);

    f = m.find(" T3 ");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_EQ(m.step(), m.triangleStep(3));
    EXPECT_GE(m.state().triangleCount, 4u);

    f = m.find("s7");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_EQ(m.step(), 7u);

    f = m.find("r0");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_EQ(m.step(), 7u) << "a ring does not seek";
    for (Index i = 0; i < P.rings[0].count; ++i)
        EXPECT_TRUE(
            m.camera().viewport().contains(m.camera().toScreen(P.vertices[P.rings[0].first + i])));
}

TEST(ViewerFind, BadQueriesSayWhy) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    m.seek(4);
    for (auto [q, why] : std::vector<std::pair<std::string, std::string>>{
             {"", "type v"},
             {"x12", "start with v"},
             {"v", "a number must follow"},
             {"v1x", "a number must follow"},
             {"v-1", "a number must follow"},
             {"v999999", "no vertex 999999: there are"},
             {"t999999", "no triangle"},
             {"s999999", "no step"},
             {"r99", "no ring 99"},
             {"v99999999999999999999", "a number must follow"}}) {
        FindTarget f = m.find(q);
        EXPECT_FALSE(f.ok) << q;
        EXPECT_NE(f.message.find(why), std::string::npos) << q << ": " << f.message;
        EXPECT_EQ(m.step(), 4u) << "a bad query moves nothing";
    }
}

// The binary form (`flood trace --format bin`) opens by its first bytes, whatever its name; a
// damaged one fails naming the file and keeps what was loaded.
TEST(ViewerTraces, BinaryTraceOpensByItsMagic) {
    std::string dir = ::testing::TempDir();
    Polygon p = squareWithHole(false, true);
    ASSERT_TRUE(validate(p, "square").ok());
    Trace t = record(p);
    std::ostringstream out;
    writeBinaryTrace(out, t);
    const std::string bin = out.str();
    std::ofstream(dir + "saved.trace", std::ios::binary) << bin;
    Model m;
    m.open(dir + "saved.trace");
    ASSERT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.steps(), t.events.size());
    EXPECT_EQ(m.verdictLines().at(0).kind, Verdict::Ok) << m.verdict();
    std::ofstream(dir + "cut.bin", std::ios::binary) << bin.substr(0, bin.size() - 3);
    m.open(dir + "cut.bin");
    EXPECT_EQ(m.exitCode(), 3);
    EXPECT_NE(m.openDiagnostic().message.find("cut.bin: "), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.steps(), t.events.size()) << "a failed open keeps the loaded run";
}

TEST(ViewerTraces, OpenLikeAPolygonAndFailWithTheLine) {
    std::string dir = ::testing::TempDir();
    Polygon p = squareWithHole(false, true);
    ASSERT_TRUE(validate(p, "square").ok());
    Trace t = record(p);
    std::ostringstream out;
    writeTrace(out, t);
    std::string text = out.str();
    std::ofstream(dir + "good.jsonl") << text;
    Model m;
    m.open(dir + "good.jsonl");
    EXPECT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.steps(), t.events.size());
    EXPECT_EQ(m.verdictLines().at(0).kind, Verdict::Ok) << m.verdict();
    EXPECT_EQ(m.recentFiles().front().front(), '/');

    Model byHeader;  // any name: the header line says it is a trace
    std::ofstream(dir + "trace-saved-as.txt") << text;
    byHeader.open(dir + "trace-saved-as.txt");
    EXPECT_EQ(byHeader.steps(), t.events.size()) << byHeader.verdict();

    // Truncated mid-way: a failure naming a line; what was loaded stays.
    std::ofstream(dir + "truncated.jsonl") << text.substr(0, text.size() / 2);
    m.open(dir + "truncated.jsonl");
    EXPECT_EQ(m.openDiagnostic().status, Status::Malformed);
    EXPECT_NE(m.openDiagnostic().message.find("truncated.jsonl:"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.exitCode(), 3);
    EXPECT_EQ(m.steps(), t.events.size()) << "a failed open keeps the loaded run";
    EXPECT_EQ(m.path(), dir + "good.jsonl");

    // A malformed third line: the message names line 3.
    std::istringstream lines(text);
    std::string l1, l2, rest, l;
    std::getline(lines, l1), std::getline(lines, l2);
    while (std::getline(lines, l)) rest += l + "\n";
    std::ofstream(dir + "bad-line.jsonl") << l1 << "\n" << l2 << "\n{\"action\": 12,\n" << rest;
    Model fresh;
    fresh.open(dir + "bad-line.jsonl");
    EXPECT_EQ(fresh.exitCode(), 3);
    EXPECT_NE(fresh.openDiagnostic().message.find("bad-line.jsonl:3:"), std::string::npos)
        << fresh.openDiagnostic().message;
    EXPECT_TRUE(fresh.failed());
    EXPECT_EQ(fresh.verdictLines().at(0).kind, Verdict::Malformed);
}

TEST(ViewerRecent, AbsolutePathsSavedOnEveryOpen) {
    std::string file = ::testing::TempDir() + "viewer-recent/recent.txt";
    std::remove(file.c_str());
    Model m;
    m.recentPath = file;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    std::ifstream in(file);
    std::string first;
    ASSERT_TRUE(std::getline(in, first));
    EXPECT_EQ(first.front(), '/');
    EXPECT_NE(first.find("paper-figure-7.json"), std::string::npos);
    m.open("/nonexistent/polygon.json");
    EXPECT_EQ(m.recentFiles().size(), 1u) << "failed opens are not recent";
    EXPECT_NE(m.path().find("paper-figure-7.json"), std::string::npos);
}

// The timeline click lands on the step the hover names. The strip used to seek to
// lround(x / perEvent): the left half of event i's mark gave step i, one before the
// "step i + 1" its tooltip showed.
TEST(ViewerModel, TimelineClickLandsOnTheHoveredStep) {
    const uint32_t n = 10;
    const double width = 100;
    TimelineView tv;
    for (uint32_t i = 0; i < n; ++i)
        for (double f : {0.0, 0.2, 0.49, 0.51, 0.99}) {
            double x = (i + f) * width / n;
            EXPECT_EQ(tv.eventAt(x, width, n), i) << x;
            EXPECT_EQ(tv.stepAt(x, width, n), i + 1) << x;
        }
    EXPECT_EQ(tv.stepAt(-5, width, n), 1u);    // left of the strip: the first event's step
    EXPECT_EQ(tv.stepAt(width, width, n), n);  // its right edge: the last step
    EXPECT_EQ(tv.stepAt(10, width, 0), 0u);
    // The same on a zoomed and panned strip: the mark under the cursor is the one named.
    tv.zoomAt(50, width, 4, 1000);
    tv.pan(-30, width, 1000);
    for (double x : {0.0, 13.0, 50.0, 99.0}) {
        uint32_t i = tv.eventAt(x, width, 1000);
        double x0 = tv.xOfStep(i, width, 1000), x1 = tv.xOfStep(i + 1, width, 1000);
        EXPECT_LE(x0, x);
        EXPECT_LT(x, x1);
    }
}

TEST(ViewerModel, TimelineZoomsAtTheCursorAndPansWithinTheLog) {
    const uint32_t n = 1000;
    const double width = 200;
    TimelineView tv;
    uint32_t under = tv.eventAt(150, width, n);
    tv.zoomAt(150, width, 10, n);
    EXPECT_NEAR(tv.visible(n), 100, 1e-9);
    EXPECT_EQ(tv.eventAt(150, width, n), under) << "the event under the cursor stays there";
    tv.pan(-1e6, width, n);  // far right: stops at the end of the log
    EXPECT_NEAR(tv.first + tv.visible(n), n, 1e-9);
    tv.pan(1e6, width, n);
    EXPECT_EQ(tv.first, 0);
    tv.zoomAt(0, width, 1e9, n);
    EXPECT_EQ(tv.visible(n), 8) << "never fewer than 8 events across";
    tv.zoomAt(0, width, 1e-9, n);
    EXPECT_EQ(tv.span, 0) << "zoomed out: the whole log again";
    EXPECT_EQ(tv.first, 0);
}

// Ten taps in one slow frame are ten presses (ImGui's per-frame key state folded them).
TEST(ViewerModel, KeyQueueKeepsEveryPress) {
    KeyQueue q;
    const int right = 262, left = 263;  // the platform's codes are opaque to the queue
    for (int i = 0; i < 10; ++i) {
        q.push(right, 1, false, false);
        q.push(right, 0, false, false);  // releases are not presses
    }
    q.push(left, 2, true, false);  // an auto-repeat counts, with its modifiers
    std::vector<KeyPress> p = q.take();
    ASSERT_EQ(p.size(), 11u);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(p[size_t(i)].key, right);
    EXPECT_EQ(p[10].key, left);
    EXPECT_TRUE(p[10].shift && p[10].repeat);
    EXPECT_TRUE(q.take().empty()) << "each press is handed out once";
}

// The background scan: none broken on valid input, the lane's ticks on invalid input, and a
// cancel that stops it.
TEST(ViewerModel, InvariantScanRunsInTheBackground) {
    Model m;
    m.openPolygon(generate("circle-holes", 3, 400), "circle-holes", {});
    m.waitForInvariants();
    ASSERT_TRUE(m.invariantsDone());
    EXPECT_EQ(m.invariantProgress(), m.steps());
    EXPECT_TRUE(m.violations().empty());
    EXPECT_EQ(m.firstViolationStep(), 0u);
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid/hole-crossing-outer.json");
    m.waitForInvariants();
    ASSERT_TRUE(m.invariantsDone());
    EXPECT_FALSE(m.violations().empty());
    EXPECT_GT(m.firstViolationStep(), 0u);
    EXPECT_GT(m.forbiddenStep(), 0u);
    EXPECT_LT(m.firstViolationStep(), m.forbiddenStep());
    // The open landed on the forbidden step; the finished scan moves on to the violation once.
    EXPECT_EQ(m.step(), m.forbiddenStep());
    EXPECT_TRUE(m.landOnFirstViolation());
    EXPECT_EQ(m.step(), m.firstViolationStep());
    m.seek(1);
    EXPECT_FALSE(m.landOnFirstViolation());
    EXPECT_EQ(m.step(), 1u);
    // A new open cancels the running scan before the trace it reads goes away.
    m.openPolygon(generate("comb", 1, 200000), "comb", {});
    m.cancelInvariants();
    EXPECT_TRUE(m.invariantsDone());
    EXPECT_LE(m.invariantProgress(), m.steps());
    m.openPolygon(generate("comb", 1, 100), "comb", {});
    m.waitForInvariants();
    EXPECT_EQ(m.invariantProgress(), m.steps());
}

// The predicate inspector's recomputation from the state before each step gives what the
// machine recorded, for every test of every step, on the gallery and the generated families.
TEST(ViewerModel, InspectorRecomputesTheRecordedTests) {
    std::vector<Trace> traces;
    for (const auto& f : polygonFiles()) {
        Model m;
        m.open(f);
        traces.push_back(m.trace());
    }
    for (const std::string& family : familyNames())
        for (size_t size : {30, 300}) traces.push_back(record(generate(family, 5, size)));
    // Invalid input too, up to and including the Forbidden step (the tests that led there).
    for (const auto& f : flood::polygonFiles(std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid")) {
        Model m;
        m.open(f);
        traces.push_back(m.trace());
    }
    for (const std::string& family : invalidFamilyNames())
        traces.push_back(record(generateInvalid(family, 3, 200)));
    size_t rows = 0, sagRows = 0, forbidden = 0;
    std::array<size_t, 3> stages{};
    for (const Trace& t : traces) {
        Replay before(t);
        std::vector<VertexClass> classes = classifyVertices(t.polygon);
        for (const Event& e : t.events) {
            forbidden += e.action == Action::Forbidden && e.tested != 0;
            const std::vector<PredicateRow> rs =
                inspectDecision(t, before.seek(e.step), e, classes);
            for (const PredicateRow& r : rs) {
                if (r.hasRecorded) {
                    ++rows;
                    ASSERT_EQ(r.result, r.recorded) << "step " << e.step + 1 << ": " << r.predicate;
                } else {
                    ++sagRows;
                }
                if (r.stage.rfind("filter", 0) == 0) ++stages[0];
                if (r.stage.rfind("expansion", 0) == 0) ++stages[1];
            }
            // Every test the event ran has its row.
            for (int i = 0; i < int(flood::Test::WalkLanded); ++i) {
                const flood::Test test = flood::Test(i);
                if (!e.didTest(test)) continue;
                EXPECT_TRUE(std::any_of(rs.begin(), rs.end(),
                                        [&](const PredicateRow& r) { return r.test == test; }))
                    << "step " << e.step + 1 << " test " << testText(test);
            }
        }
    }
    EXPECT_GT(rows, 1000u);
    EXPECT_GT(sagRows, 10u);
    EXPECT_GT(stages[0], 10u);
    EXPECT_GT(stages[1], 0u) << "collinear corners need the exact stage";
    EXPECT_GT(forbidden, 3u);
}

// ----------------------------------------------------------------------------------------
// Shrink from the viewer, and the features of a collection.
namespace {

// A 300-vertex valid star with one vertex moved through the centre: the ring crosses itself.
Polygon buriedCrossing() {
    Polygon star = generate("star", 5, 300);
    std::vector<Point> ring(star.vertices.begin(), star.vertices.begin() + star.rings[0].count);
    Point& v = ring[ring.size() / 2];
    v = {-v.x * 3, -v.y * 3};
    Polygon p;
    p.addRing(ring, true);
    return p;
}

std::string scratchDir(const std::string& name) {
    std::string dir = std::string(::testing::TempDir()) + "flood-viewer-" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string mixedPath() {
    return std::string(FLOOD_SOURCE_DIR) + "/polygons/datasets/mixed.geojson";
}

}  // namespace

TEST(ViewerShrink, BackgroundShrinkFinishesSmallerFailingTheSameWayAndOpensBesideTheOriginal) {
    const std::string dir = scratchDir("shrink");
    const std::string file = dir + "/crossing.json";
    ASSERT_TRUE(saveGeoJson(buriedCrossing(), file).ok());
    Model m;
    m.open(file);
    ASSERT_TRUE(m.failed());
    const size_t before = m.polygon().vertices.size();
    ASSERT_GE(before, 250u);
    ShrinkOptions o;
    o.fork = false;  // no crash or hang to survive here; keeps the test light
    const Failure original = classify(m.polygon(), o);
    ASSERT_EQ(original.kind, Failure::Kind::Forbidden) << original.message;

    ShrinkJob job;
    job.start(m.polygon(), o);
    job.wait();
    ASSERT_TRUE(job.done());
    const ShrinkResult& r = job.result();
    EXPECT_FALSE(r.cancelled);
    EXPECT_LE(r.polygon.vertices.size(), 12u);
    EXPECT_TRUE(r.failure.sameClass(original)) << r.failure.message;
    EXPECT_TRUE(classify(r.polygon, o).sameClass(original));
    EXPECT_EQ(job.tries(), r.tries - 1) << "progress is the tries made before the last";

    m.openShrunk(r);
    EXPECT_TRUE(m.shrunk());
    EXPECT_EQ(m.polygon().vertices.size(), r.polygon.vertices.size());
    EXPECT_NE(m.path().find("(shrunk)"), std::string::npos) << m.path();
    EXPECT_TRUE(m.failed());
    ASSERT_FALSE(m.recentFiles().empty());
    EXPECT_EQ(m.recentFiles().front(), std::filesystem::absolute(file).lexically_normal().string());

    // Saved as GeoJSON, atomically: the file reads back, nothing else is left in the folder.
    const std::string repro = dir + "/crossing-shrunk.geojson";
    ASSERT_TRUE(saveGeoJson(m.polygon(), repro).ok());
    ReadResult back = readPolygonFile(repro);
    ASSERT_TRUE(back.diagnostic.ok()) << back.diagnostic.message;
    EXPECT_EQ(back.polygon.vertices.size(), r.polygon.vertices.size());
    EXPECT_TRUE(classify(back.polygon, o).sameClass(original));
    size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u);

    m.openOrigin();  // one click back
    EXPECT_FALSE(m.shrunk());
    EXPECT_EQ(m.polygon().vertices.size(), before);
}

TEST(ViewerShrink, CancelStopsAtTheNextTry) {
    ShrinkOptions o;
    o.fork = false;
    ShrinkJob job;
    size_t calls = 0;
    // The test's hook asks for the cancel at try 5, from the shrinking thread itself.
    o.onTry = [&](size_t tries, size_t) {
        ++calls;
        if (tries == 5) job.requestCancel();
        return true;
    };
    Polygon p = buriedCrossing();
    job.start(p, o);
    job.wait();
    ASSERT_TRUE(job.done());
    EXPECT_TRUE(job.result().cancelled);
    EXPECT_EQ(calls, 5u) << "not one classification after the cancel";
    EXPECT_EQ(job.result().tries, 5u);
    // What it found until then still fails the same way.
    EXPECT_TRUE(job.result().failure.sameClass(classify(p, o)));
    EXPECT_LT(job.result().polygon.vertices.size(), p.vertices.size());
}

TEST(ViewerShrink, SavingToAnUnwritablePlaceFailsAndLeavesNothing) {
    const std::string dir = scratchDir("unwritable");
    Diagnostic d = saveGeoJson(buriedCrossing(), dir + "/no-such-folder/x.geojson");
    EXPECT_EQ(d.status, Status::WriteFailed);
    EXPECT_NE(d.message.find("no-such-folder/x.geojson"), std::string::npos) << d.message;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(ViewerFeatures, OpenFeatureNOpensThatFeature) {
    Model m;
    ASSERT_TRUE(m.openFeature(mixedPath(), 7));  // "two holes": 4 + 4 + 4 vertices
    EXPECT_EQ(m.feature(), 7u);
    EXPECT_EQ(m.polygon().vertices.size(), 12u);
    EXPECT_EQ(m.polygon().rings.size(), 3u);
    EXPECT_FALSE(m.failed());
    EXPECT_EQ(m.path(), mixedPath() + "#7");
    ASSERT_TRUE(m.openFeature(mixedPath(), 1));  // the bow-tie crosses itself
    EXPECT_EQ(m.polygon().vertices.size(), 4u);
    EXPECT_TRUE(m.failed());
    EXPECT_EQ(m.exitCode(), 4);
}

TEST(ViewerFeatures, OutOfRangeOrNotACollectionIsAClearFailureKeepingWhatWasLoaded) {
    Model m;
    ASSERT_TRUE(m.openFeature(mixedPath(), 8));
    const size_t loaded = m.polygon().vertices.size();
    EXPECT_FALSE(m.openFeature(mixedPath(), 99));
    EXPECT_EQ(m.openDiagnostic().status, Status::Usage);
    EXPECT_NE(m.openDiagnostic().message.find("mixed.geojson"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_NE(m.openDiagnostic().message.find("99"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_NE(m.openDiagnostic().message.find("0..9"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), loaded);
    EXPECT_EQ(m.feature(), 8u);

    EXPECT_FALSE(m.openFeature(mixedPath(), 6));  // a LineString: no polygon to open
    EXPECT_EQ(m.openDiagnostic().status, Status::Usage);
    EXPECT_FALSE(m.openFeature(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json", 0));
    EXPECT_NE(m.openDiagnostic().message.find("not a FeatureCollection"), std::string::npos);
    EXPECT_EQ(m.polygon().vertices.size(), loaded);
}

TEST(ViewerFeatures, ListShowsVerdictsFailingFirst) {
    FeatureScan scan;
    scan.start(mixedPath());
    scan.wait();
    ASSERT_TRUE(scan.done());
    EXPECT_TRUE(scan.diagnostic().ok()) << scan.diagnostic().message;
    std::vector<std::pair<size_t, Verdict>> got;
    for (const auto& f : scan.features()) got.push_back({f.index, f.kind});
    const std::vector<std::pair<size_t, Verdict>> want = {
        {1, Verdict::Invalid},   {3, Verdict::Invalid},   {4, Verdict::Invalid},
        {5, Verdict::Malformed}, {9, Verdict::Malformed}, {0, Verdict::Ok},
        {2, Verdict::Ok},        {7, Verdict::Ok},        {8, Verdict::Ok}};
    EXPECT_EQ(got, want);
    EXPECT_EQ(scan.total(), want.size());
    EXPECT_EQ(scan.progress(), want.size());
    ASSERT_FALSE(scan.features().empty());
    EXPECT_EQ(scan.features()[0].name, "bow-tie");
    EXPECT_NE(scan.features()[0].reason.find("ring 0"), std::string::npos)
        << scan.features()[0].reason;
    EXPECT_EQ(scan.features().back().id, "triangle");
    EXPECT_EQ(scan.features().back().vertices, 3u);

    FeatureScan single;  // not a collection: nothing to list
    single.start(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    single.wait();
    EXPECT_TRUE(single.features().empty());
}

// [SECTION] declutter at scale: marker thinning and label culling, without a window
namespace {

// A dense face and a camera fitted on an 800x600 canvas.
struct DenseFace {
    Model m;
    CanvasGeometry g;
    std::vector<MarkerVertex> markers;  // classes first, as the canvas thins them
    Camera fit;
    const Rect view{0, 0, 800, 600};
    explicit DenseFace(size_t n) {
        m.openPolygon(generate("circle-jagged", 1, n), "circle-jagged", {});
        g = buildCanvasGeometry(m);
        markers = g.classes;
        markers.insert(markers.end(), g.regular.begin(), g.regular.end());
        fit.fit(m.polygon(), view);
    }
    Camera zoomedOn(Index v, double factor) const {
        Camera c = fit;
        c.centerOn(m.polygon().vertices[v]);
        c.zoomAt({view.w / 2, view.h / 2}, factor);
        return c;
    }
    Vec2 screen(const Camera& c, const MarkerVertex& k) const {
        return c.toScreen({g.origin.x + k.x, g.origin.y + k.y});
    }
};

}  // namespace

TEST(ViewerDeclutter, ThinningKeepsAtMostOneMarkerPerCellAndAllWhenZoomedIn) {
    DenseFace f(20000);
    const double cell = 12;
    size_t previous = 0;
    int sparseViews = 0;
    for (double zoom : {1.0, 4.0, 64.0, 512.0}) {
        SCOPED_TRACE("zoom " + std::to_string(zoom));
        Camera c = f.zoomedOn(0, zoom);
        std::vector<MarkerVertex> kept = thinMarkers(f.markers, f.g.origin, c, cell);
        // One per cell of the grid anchored a cell outside the viewport's corner.
        std::set<std::pair<long, long>> cells;
        for (const MarkerVertex& k : kept) {
            Vec2 p = f.screen(c, k);
            EXPECT_TRUE(cells
                            .insert({long(std::floor((p.x + cell) / cell)),
                                     long(std::floor((p.y + cell) / cell))})
                            .second);
        }
        // Every marker on screen is in a cell that kept one: thinning never empties a cell.
        std::set<std::pair<long, long>> occupied;
        size_t onScreen = 0;
        for (const MarkerVertex& k : f.markers) {
            Vec2 p = f.screen(c, k);
            if (!f.view.contains(p)) continue;
            ++onScreen;
            occupied.insert(
                {long(std::floor((p.x + cell) / cell)), long(std::floor((p.y + cell) / cell))});
        }
        for (const auto& o : occupied) EXPECT_TRUE(cells.count(o));
        // Deterministic: the same camera keeps the same markers.
        std::vector<MarkerVertex> again = thinMarkers(f.markers, f.g.origin, c, cell);
        ASSERT_EQ(again.size(), kept.size());
        for (size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(again[i].x, kept[i].x);
        if (zoom == 1.0) {
            // The whole face: a few per cell along the annulus, not 20000 dots.
            EXPECT_LT(kept.size(), f.markers.size() / 4);
            EXPECT_LE(kept.size(), size_t((800 / cell + 2) * (600 / cell + 2)));
        }
        // Zoomed in so far that the markers on screen are more than a cell's diagonal apart,
        // no two share a cell: every one is kept.
        std::vector<Vec2> seen;
        for (const MarkerVertex& k : f.markers)
            if (f.view.contains(f.screen(c, k))) seen.push_back(f.screen(c, k));
        double closest = INFINITY;
        for (size_t i = 0; i < seen.size() && seen.size() < 2000; ++i)
            for (size_t j = i + 1; j < seen.size(); ++j)
                closest =
                    std::min(closest, std::hypot(seen[i].x - seen[j].x, seen[i].y - seen[j].y));
        if (seen.size() < 2000 && closest > cell * std::sqrt(2.0)) {
            size_t keptOnScreen = 0;
            for (const MarkerVertex& k : kept) keptOnScreen += f.view.contains(f.screen(c, k));
            EXPECT_EQ(keptOnScreen, onScreen);
            if (onScreen > 3) ++sparseViews;
        }
        std::printf("zoom %g: %zu of %zu markers kept, %zu on screen\n", zoom, kept.size(),
                    f.markers.size(), onScreen);
        previous = kept.size();
    }
    EXPECT_GT(previous, 0u);
    EXPECT_GE(sparseViews, 1) << "no zoom showed several markers a cell apart";
}

TEST(ViewerDeclutter, VertexLabelsOnlyWhereTheyDoNotOverlap) {
    DenseFace f(20000);
    TriangleGrid grid;
    grid.buildVertices(f.m.polygon());
    const double room = 44;  // the canvas's: a six-digit label's width, in pixels
    const uint32_t n = uint32_t(f.m.polygon().vertices.size());
    std::vector<size_t> counts;
    for (double zoom : {1.0, 64.0, 512.0, 4096.0, 65536.0}) {
        SCOPED_TRACE("zoom " + std::to_string(zoom));
        Camera c = f.zoomedOn(0, zoom);
        std::vector<uint32_t> shown = visibleLabels(grid, c, n, room * room);
        counts.push_back(shown.size());
        // No two labelled vertices closer on screen than a label: they cannot overlap.
        for (size_t i = 0; i < shown.size(); ++i)
            for (size_t j = i + 1; j < shown.size(); ++j) {
                Vec2 a = c.toScreen(f.m.polygon().vertices[shown[i]]),
                     b = c.toScreen(f.m.polygon().vertices[shown[j]]);
                ASSERT_GE(std::hypot(a.x - b.x, a.y - b.y), room * 0.999)
                    << shown[i] << " " << shown[j];
            }
        std::printf("zoom %g: %zu vertex labels\n", zoom, shown.size());
    }
    EXPECT_EQ(counts[0], 0u) << "the whole face: 20000 numbers would be a smear";
    EXPECT_GT(counts[1], 0u) << "the loneliest vertices first";
    // Zoomed in far, every vertex in view is numbered (the nearest pair is then ~70 px apart).
    Camera c = f.zoomedOn(0, 4096);
    size_t inView = 0;
    for (Point p : f.m.polygon().vertices) inView += f.view.contains(c.toScreen(p));
    EXPECT_GT(inView, 0u);
    EXPECT_GE(counts[3], inView);
    EXPECT_LE(counts[3], inView + 8) << "only the view and its margin";
    // Triangle labels go through the same culling: few at the fit, many more zoomed in.
    TriangleGrid tris;
    tris.build(f.m.polygon(), f.m.trace().triangles);
    const uint32_t t = uint32_t(f.m.trace().triangles.size());
    std::vector<size_t> triangleCounts;
    for (double zoom : {1.0, 8.0, 64.0}) {
        Camera at = f.fit;
        at.zoomAt({f.view.w / 2, f.view.h / 2}, zoom);  // on the inner disc's big triangles
        triangleCounts.push_back(visibleLabels(tris, at, t, 700).size());
        std::printf("zoom %g: %zu triangle labels\n", zoom, triangleCounts.back());
    }
    EXPECT_EQ(triangleCounts[0], 0u);
    EXPECT_GT(triangleCounts[1], 0u);
}

TEST(ViewerDeclutter, BridgesHaveTheirOwnColourAndGorgeFocusHasAnOutline) {
    // Bridges must not read as the just-cut triangles (both were yellow).
    auto dist = [](Rgba a, Rgba b) {
        return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
    };
    for (Rgba other :
         {palette::kCurrent, palette::kWater, palette::kPolygonFill, palette::kChain,
          palette::kJump, palette::kDormant, palette::kWaterLevel, palette::kTriangleEdge})
        EXPECT_GT(dist(palette::kBridge, other), 120);
    Model m;
    m.openPolygon(generate("circle-holes", 7, 1500), "circle-holes", {});
    bool sawBridge = false;
    for (uint32_t s = 1; s <= m.steps(); ++s) {
        m.seek(s);
        // The focus's outline (gorge_focus.h) runs through every vertex of the active chain.
        std::vector<Point> outline = activeGorgeOutline(m);
        for (Index i : m.state().chain) {
            Point p = m.polygon().vertices[i];
            ASSERT_TRUE(std::any_of(outline.begin(), outline.end(),
                                    [&](Point q) { return q.x == p.x && q.y == p.y; }))
                << "step " << s;
        }
        sawBridge |= !m.state().bridges.empty();
    }
    EXPECT_TRUE(sawBridge);
    // Hidden bridges: buildScene draws no line in the bridge colour.
    SceneOptions o;
    o.bridges = false;
    for (const Scene::Line& l : buildScene(m, o).lines)
        EXPECT_FALSE(l.color.r == palette::kBridge.r && l.color.g == palette::kBridge.g &&
                     l.color.b == palette::kBridge.b);
}
#ifdef FLOOD_GDAL
// The viewer opens a GIS dataset like a polygon file (core/io/gdal/): a GeoPackage made here
// with ogr2ogr from a GeoJSON square with a hole.
TEST(ViewerGdal, OpensAGeoPackage) {
    std::filesystem::path d = scratch("viewer-gdal");
    std::ofstream(d / "square.geojson")
        << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"name": "sq"},
             "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10],[0,0]],
                                                           [[3,3],[3,7],[7,7],[7,3],[3,3]]]}}]})";
    RunResult made = runShell("ogr2ogr -f GPKG " + (d / "square.gpkg").string() + " " +
                              (d / "square.geojson").string() + " 2>&1");
    ASSERT_EQ(made.code, 0) << made.out;
    Model m;
    m.open((d / "square.gpkg").string());
    EXPECT_EQ(m.exitCode(), 0) << m.verdict();
    EXPECT_EQ(m.polygon().vertices.size(), 8u);
    EXPECT_EQ(m.polygon().rings.size(), 2u);
    EXPECT_FALSE(m.failed()) << m.verdict();
    std::filesystem::remove_all(d);
}
#endif

// The flood direction dial (issue 12): turning it floods again along the new direction, at
// the same step, and the summary says what changed against the run before.
TEST(ViewerDirection, TurningFloodsAgainAndSaysWhatChanged) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/two-gorges.json");
    ASSERT_FALSE(m.failed()) << m.verdict();
    EXPECT_EQ(m.up(), Up::PlusY);
    EXPECT_FALSE(m.hasPreviousSummary());
    const FloodSummary along90 = m.summary();
    m.seek(3);
    ASSERT_TRUE(m.setUp(Up::PlusX));
    EXPECT_EQ(m.up(), Up::PlusX);
    EXPECT_EQ(m.trace().up, Up::PlusX);
    EXPECT_FALSE(m.failed()) << m.verdict();
    EXPECT_EQ(m.step(), std::min<uint32_t>(3, m.steps()));
    EXPECT_EQ(m.path(), std::string(FLOOD_SOURCE_DIR) + "/polygons/two-gorges.json");
    // The summary is the run's own: the same as flooding and classifying along +x directly.
    Trace direct = record(m.polygon(), Options{Up::PlusX});
    for (const SummaryChange& c : compareSummaries(
             summarizeFlood(direct, classifyVertices(m.polygon(), Up::PlusX)), m.summary()))
        EXPECT_FALSE(c.changed()) << c.what;
    // Before is the +y run; the decomposition is not the same along +x.
    ASSERT_TRUE(m.hasPreviousSummary());
    bool changed = false;
    for (const SummaryChange& c : compareSummaries(along90, m.summary())) {
        changed |= c.changed();
        if (c.what == "triangles") {
            EXPECT_FALSE(c.changed()) << "a triangulation has n - 2 + 2h triangles";
        }
    }
    EXPECT_TRUE(changed);
    for (const SummaryChange& c : compareSummaries(m.previousSummary(), along90))
        EXPECT_FALSE(c.changed()) << c.what;
    // Not a direction, or the same one: nothing happens.
    EXPECT_FALSE(m.setUp(Up::PlusX));
    EXPECT_FALSE(m.setUp(Up{0, 0}));
    // Any angle floods exactly; opening another file keeps the dial's direction.
    ASSERT_TRUE(m.setUp(upFromDegrees(17)));
    EXPECT_FALSE(m.failed()) << m.verdict();
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/holes.json");
    EXPECT_EQ(m.up(), upFromDegrees(17));
    EXPECT_FALSE(m.failed()) << m.verdict();
}

// The summary counts what the trace holds: gorges from bottoms, classes, actions.
TEST(ViewerDirection, SummaryCountsTheRun) {
    Trace t = record(squareWithHole(false, false));
    FloodSummary s = summarizeFlood(t, classifyVertices(t.polygon));
    EXPECT_EQ(s.classes[size_t(VertexClass::Bottom)], 1u);
    EXPECT_EQ(s.classes[size_t(VertexClass::Sag)], 1u);
    EXPECT_EQ(s.gorges, 1u);
    EXPECT_EQ(s.actions[size_t(Action::Bridge)], 1u);
    EXPECT_EQ(s.actions[size_t(Action::Start)], 1u);
    EXPECT_EQ(s.triangles, 8u);
}

// The timeline's breakpoint ticks are the model's: found again when the breakpoints change
// and when another trace is opened, never left over from the previous one.
TEST(ViewerModel, BreakpointStepsFollowTheBreakpointsAndTheTrace) {
    auto stepsOf = [](const Model& m, Action a) {
        std::vector<uint32_t> steps;
        for (const Event& e : m.trace().events)
            if (e.action == a) steps.push_back(e.step + 1);
        return steps;
    };
    Model m;
    m.openPolygon(generate("comb", 3, 60), "comb", {});
    EXPECT_TRUE(m.breakpointSteps().empty()) << "no breakpoint enabled";
    Breakpoints b;
    b.actions[size_t(Action::Bridge)] = true;
    m.setBreakpoints(b);
    ASSERT_FALSE(stepsOf(m, Action::Bridge).empty()) << "comb has sags: it must bridge";
    EXPECT_EQ(m.breakpointSteps(), stepsOf(m, Action::Bridge));
    m.openPolygon(generate("circle-holes", 3, 40), "circle-holes", {});
    EXPECT_TRUE(m.breakpoints().actions[size_t(Action::Bridge)]) << "breakpoints outlive an open";
    EXPECT_EQ(m.breakpointSteps(), stepsOf(m, Action::Bridge)) << "the new trace's steps";
    m.setBreakpoints({});
    EXPECT_TRUE(m.breakpointSteps().empty());
}

// The state machine's edges: how often each action follows each other, counted per open.
TEST(ViewerModel, TransitionsCountConsecutiveEvents) {
    Model m;
    m.openPolygon(generate("comb", 3, 60), "comb", {});
    const auto& ev = m.trace().events;
    ASSERT_GT(ev.size(), 2u);
    uint64_t total = 0;
    for (const auto& row : m.transitions())
        for (uint32_t n : row) total += n;
    EXPECT_EQ(total, ev.size() - 1);
    uint32_t raiseThenBridge = 0;
    for (size_t i = 1; i < ev.size(); ++i)
        raiseThenBridge += ev[i - 1].action == Action::Raise && ev[i].action == Action::Bridge;
    EXPECT_EQ(m.transitions()[size_t(Action::Raise)][size_t(Action::Bridge)], raiseThenBridge);

    m.openPolygon(squareWithHole(false, false), "square", {});
    total = 0;
    for (const auto& row : m.transitions())
        for (uint32_t n : row) total += n;
    EXPECT_EQ(total, m.trace().events.size() - 1) << "counted again for the new trace";
}

// The camera moves only through the model's commands: an open leaves a fit pending, the fit
// clears it and ends the error view, the Fit button asks again.
TEST(ViewerModel, CameraFitIsACommand) {
    Model m;
    m.openPolygon(generate("comb", 3, 60), "comb", {});
    EXPECT_TRUE(m.fitPending());
    const Rect canvas{0, 0, 800, 600};
    m.fitCamera(canvas);
    EXPECT_FALSE(m.fitPending());
    for (Point p : m.polygon().vertices) EXPECT_TRUE(canvas.contains(m.camera().toScreen(p)));
    const Point c = m.camera().center();
    m.pan(10, 0);
    EXPECT_LT(m.camera().center().x, c.x) << "dragging right shows what is left of the centre";
    m.requestFit();
    EXPECT_TRUE(m.fitPending());
}

// Playing from the end starts again from step 0; pausing keeps the step.
TEST(ViewerModel, SetPlayingRewindsAtTheEnd) {
    Model m;
    m.openPolygon(generate("comb", 3, 60), "comb", {});
    m.last();
    m.setPlaying(true);
    EXPECT_TRUE(m.playing());
    EXPECT_EQ(m.step(), 0u);
    m.setSpeed(2);
    m.advance(1.0);
    EXPECT_EQ(m.step(), 2u);
    m.setPlaying(false);
    m.advance(1.0);
    EXPECT_EQ(m.step(), 2u);
    EXPECT_FALSE(m.playing());
}

// The dial floods through the editor's background flood: dragging it through a hundred
// angles in one go on a large polygon starts one flood, then one of the last angle when that
// is adopted; the UI thread (this one) validates, floods and checks nothing.
TEST(ViewerDirection, DraggingTheDialFloodsInTheBackgroundOnceAtATime) {
    Model m;
    Polygon p = generate("circle-holes", 3, 5000);
    m.openPolygon(p, "circle-holes", validate(p, "circle-holes"));
    ASSERT_FALSE(m.failed()) << m.verdict();
    m.seek(m.steps() / 2);
    const uint32_t at = m.step();
    Editor e(m);
    e.background = true;
    work() = {};
    for (int i = 1; i <= 100; ++i) ASSERT_TRUE(e.setUp(upFromDegrees(90 + 2.5 * i)));
    EXPECT_EQ(e.floods(), 1u) << "the angles passed while a flood runs wait for the next";
    EXPECT_EQ(m.up(), Up::PlusY) << "the old run stays on screen until the new one is ready";
    EXPECT_EQ(e.up(), upFromDegrees(340)) << "the dial shows the angle asked for";
    e.wait();
    EXPECT_EQ(e.floods(), 2u);
    EXPECT_EQ(m.up(), upFromDegrees(340));
    EXPECT_EQ(m.trace().up, upFromDegrees(340));
    EXPECT_FALSE(m.failed()) << m.verdict();
    EXPECT_EQ(m.step(), std::min(at, m.steps()));
    EXPECT_TRUE(m.hasPreviousSummary());
    EXPECT_EQ(work().nodeVisits, 0u) << "a flood ran on the UI thread";
    EXPECT_EQ(work().validatorSteps, 0u);
    EXPECT_EQ(work().checkerSteps, 0u);
    // The run adopted is the one of that direction.
    Trace direct = record(m.polygon(), Options{upFromDegrees(340)});
    EXPECT_EQ(direct.events.size(), m.trace().events.size());
    work() = {};  // that flood was this test's own

    // Frame by frame (a turn, then the frame's poll): never two floods at once, and every
    // flood started but the last one running has been adopted.
    const uint64_t floods = e.floods(), generation = m.generation();
    for (int i = 1; i <= 40; ++i) {
        e.setUp(upFromDegrees(10 + 7.5 * i));
        e.poll();
        EXPECT_LE(e.floods() - floods, m.generation() - generation + 1);
    }
    e.wait();
    EXPECT_EQ(e.floods() - floods, m.generation() - generation);
    EXPECT_EQ(m.up(), upFromDegrees(310));
    EXPECT_EQ(work().nodeVisits, 0u) << "a flood ran on the UI thread";
}

// Turning the dial is not an edit and forgets none: the edits' undo history stays, and an
// edit floods along the dial's direction, not back along +y.
TEST(ViewerDirection, EditsFloodAlongTheDialsDirection) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/hole.json");
    ASSERT_FALSE(m.failed()) << m.verdict();
    Editor e(m);
    const Point v = m.polygon().vertices[0];
    ASSERT_TRUE(e.moveVertex(0, {v.x - 0.25, v.y - 0.25}));
    const Up turned = upFromDegrees(17);
    ASSERT_TRUE(e.setUp(turned));
    EXPECT_EQ(m.up(), turned);
    EXPECT_TRUE(m.hasPreviousSummary());
    EXPECT_TRUE(e.canUndo()) << "the dial dropped the edit history";
    EXPECT_TRUE(m.polygon().vertices[0] == (Point{v.x - 0.25, v.y - 0.25}));
    ASSERT_TRUE(e.undo());
    EXPECT_TRUE(m.polygon().vertices[0] == v);
    EXPECT_EQ(m.up(), turned) << "the edit flooded along another direction than the dial's";
    EXPECT_EQ(m.trace().up, turned);
    EXPECT_FALSE(e.setUp(turned)) << "the same direction again does nothing";
    EXPECT_FALSE(e.setUp(Up{0, 0}));
    EXPECT_EQ(e.floods(), 3u);  // the move, the turn and the undo
}

#endif

// Opening the gallery file opens the gallery (issue 27 §4): its first polygon, its folder's
// list for the Open panel, and a count the UI shows the panel on; a gallery.json that lists
// nothing is read as a polygon file and fails as one.
TEST(ViewerGallery, OpeningTheGalleryFileOpensItsFirstPolygon) {
    const std::string dir = flood::testing::sourcePath("polygons");
    const std::vector<GalleryEntry> gallery = readGallery(dir);
    ASSERT_FALSE(gallery.empty());
    Model m;
    m.open(dir + "/gallery.json");
    EXPECT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.path(), gallery.front().file);
    EXPECT_GT(m.steps(), 0u);
    EXPECT_EQ(m.galleryOpens(), 1u);
    EXPECT_EQ(m.galleryDir(), dir);

    const auto empty = flood::testing::scratch("empty-gallery");
    std::ofstream((empty / "gallery.json").string()) << "[]";
    Model none;
    none.open((empty / "gallery.json").string());
    EXPECT_EQ(none.openDiagnostic().status, Status::Malformed);
    EXPECT_EQ(none.galleryOpens(), 0u);
}
