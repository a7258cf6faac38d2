// The viewer's model without a window: the flood direction dial, floods again along the new
// direction, in the background, and the summary of what changed.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "viewer_model_support.h"  // the model, the tests' helpers

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
