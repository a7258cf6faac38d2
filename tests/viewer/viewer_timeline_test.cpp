// The viewer's model without a window: the timeline (clicks, zoom), the key queue, the invariant
// scan in the background and the predicate inspector.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "viewer_model_support.h"  // the model, the tests' helpers

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

#endif
