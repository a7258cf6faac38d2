// The viewer's model without a window: replay consistency in both directions, seek versus
// stepping, breakpoints, vertex classes, the camera, the scene and the canvas buffers. Compiles
// to nothing when the viewer is not in the tree, since the model lives in viewer/ (it is built
// even with FLOOD_VIEWER=OFF). Its other concerns: viewer_verdict_test.cpp (verdicts,
// culprits, find, traces), viewer_timeline_test.cpp, viewer_features_test.cpp (shrink,
// features, GIS, gallery), viewer_declutter_test.cpp, viewer_direction_test.cpp.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "viewer_model_support.h"  // the model, the tests' helpers

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

#endif
