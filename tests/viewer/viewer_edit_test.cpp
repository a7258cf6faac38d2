// Live editing without a window (viewer/edit.h): each edit and its undo/redo to the exact
// coordinate, the flood redone at the same (clamped) step, an invalid edit kept with the
// validator's diagnostic, saving, and drawing from an empty canvas. Compiles to nothing when
// the viewer is not built (FLOOD_VIEWER=OFF).
#if __has_include("edit.h")
#include <gtest/gtest.h>

#include <filesystem>

#include "edit.h"
#include "flood/flood_api.h"
#include "flood/io/io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;

namespace {

// A 10x10 square with a 2x2 hole: vertices 0-3 the outer ring, 4-7 the hole.
Polygon squareWithHole() {
    return makePolygon({{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}}});
}

void openSquare(Model& m) {
    Polygon p = squareWithHole();
    Diagnostic d = validate(p, "square.json");
    ASSERT_TRUE(d.ok()) << d.message;
    m.openPolygon(p, "square.json", d);
    ASSERT_FALSE(m.failed()) << m.verdict();
}

std::vector<Point> ring(const Polygon& p, Index r) {
    return {p.vertices.begin() + p.rings[r].first,
            p.vertices.begin() + p.rings[r].first + p.rings[r].count};
}

// Same rings and parts, every coordinate bit for bit.
void expectSamePolygon(const Polygon& a, const Polygon& b) {
    ASSERT_EQ(a.parts.size(), b.parts.size());
    for (size_t k = 0; k < a.parts.size(); ++k) {
        EXPECT_EQ(a.parts[k].firstRing, b.parts[k].firstRing);
        EXPECT_EQ(a.parts[k].ringCount, b.parts[k].ringCount);
    }
    ASSERT_EQ(a.rings.size(), b.rings.size());
    for (Index r = 0; r < a.rings.size(); ++r) {
        EXPECT_EQ(a.rings[r].first, b.rings[r].first);
        EXPECT_EQ(a.rings[r].count, b.rings[r].count);
    }
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (size_t i = 0; i < a.vertices.size(); ++i)
        EXPECT_TRUE(a.vertices[i] == b.vertices[i]) << "vertex " << i;
}

// The model floods what the editor holds, and the exact checker passed on it.
void expectFloodedValid(const Model& m, size_t triangles) {
    EXPECT_TRUE(m.inputDiagnostic().ok()) << m.inputDiagnostic().message;
    EXPECT_FALSE(m.failed()) << m.verdict();
    EXPECT_TRUE(m.check().ok);
    EXPECT_EQ(m.trace().triangles.size(), triangles);
}

}  // namespace

TEST(ViewerEdit, MoveVertexUndoRedoExact) {
    Model m;
    openSquare(m);
    Editor e(m);
    const Polygon original = m.polygon();
    const uint64_t g = m.generation();
    ASSERT_TRUE(e.moveVertex(2, {11.25, 10.5}));
    EXPECT_NE(m.generation(), g) << "flooded again at once";
    EXPECT_TRUE(m.polygon().vertices[2] == (Point{11.25, 10.5}));
    expectFloodedValid(m, original.expectedTriangles());
    EXPECT_EQ(e.undoLabel(), "move vertex 2 of ring 0");
    ASSERT_TRUE(e.undo());
    expectSamePolygon(m.polygon(), original);
    EXPECT_FALSE(e.canUndo());
    ASSERT_TRUE(e.redo());
    EXPECT_TRUE(m.polygon().vertices[2] == (Point{11.25, 10.5}));
    EXPECT_FALSE(e.redo()) << "nothing left to redo";
}

TEST(ViewerEdit, ADragIsOneCommandAndUndoGoesBackToWhereItBegan) {
    Model m;
    openSquare(m);
    Editor e(m);
    e.beginGesture();
    for (int i = 1; i <= 5; ++i) ASSERT_TRUE(e.moveVertex(5, {4, 6 + 0.25 * i}));
    // The invariant scan waits for the drag to end: no scan to stop at every move.
    EXPECT_FALSE(m.invariantsDone());
    EXPECT_EQ(m.invariantProgress(), 0u);
    e.endGesture();
    m.waitForInvariants();
    EXPECT_TRUE(m.invariantsDone());
    EXPECT_TRUE(m.violations().empty());
    EXPECT_EQ(e.historySize(), 1u);
    EXPECT_TRUE(m.polygon().vertices[5] == (Point{4, 7.25}));
    e.undo();
    EXPECT_TRUE(m.polygon().vertices[5] == (Point{4, 6}));
    // A new gesture is a new command.
    e.beginGesture();
    e.moveVertex(5, {4, 6.5});
    e.endGesture();
    e.beginGesture();
    e.moveVertex(5, {4, 6.75});
    e.endGesture();
    EXPECT_EQ(e.historySize(), 2u) << "the undone drag is forgotten, the two new ones kept";
}

TEST(ViewerEdit, InsertOnAnEdgeShiftsTheRingsAfterItAndUndoes) {
    Model m;
    openSquare(m);
    Editor e(m);
    const Polygon original = m.polygon();
    ASSERT_TRUE(e.insertVertex(1, {10.5, 5}));  // on the edge 1 -> 2, bulging out
    const Polygon& p = m.polygon();
    ASSERT_EQ(p.rings.size(), 2u);
    EXPECT_EQ(p.rings[0].count, 5u);
    EXPECT_EQ(p.rings[1].first, 5u);
    EXPECT_EQ(ring(p, 0), (std::vector<Point>{{0, 0}, {10, 0}, {10.5, 5}, {10, 10}, {0, 10}}));
    EXPECT_EQ(ring(p, 1), ring(original, 1));
    expectFloodedValid(m, original.expectedTriangles() + 1);
    // The closing edge: after the ring's last vertex.
    ASSERT_TRUE(
        e.insertVertex(8, {5, 4}));  // the hole's closing edge (6,4) -> (4,4), now from vertex 8
    EXPECT_EQ(ring(m.polygon(), 1), (std::vector<Point>{{4, 4}, {4, 6}, {6, 6}, {6, 4}, {5, 4}}));
    e.undo();
    e.undo();
    expectSamePolygon(m.polygon(), original);
    e.redo();
    EXPECT_EQ(m.polygon().vertices[2], (Point{10.5, 5}));
}

TEST(ViewerEdit, DeleteVertexAndUndoPutsItBackInPlace) {
    Model m;
    Polygon p = makePolygon({{{{0, 0}, {10, 0}, {12, 5}, {10, 10}, {0, 10}}}});
    m.openPolygon(p, "pentagon.json", validate(p, "pentagon.json"));
    Editor e(m);
    ASSERT_TRUE(e.deleteVertex(2));
    EXPECT_EQ(ring(m.polygon(), 0), (std::vector<Point>{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
    expectFloodedValid(m, 2);
    ASSERT_TRUE(e.undo());
    expectSamePolygon(m.polygon(), p);
    expectFloodedValid(m, 3);
}

TEST(ViewerEdit, DeletingAHolesLastVertexRemovesTheHoleButAnOuterRingKeepsItsHoles) {
    Model m;
    Polygon p = makePolygon({{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 5}}}});  // a Steiner point
    m.openPolygon(p, "steiner.json", validate(p, "steiner.json"));
    ASSERT_FALSE(m.failed()) << m.verdict();
    Editor e(m);
    ASSERT_TRUE(e.deleteVertex(4));
    EXPECT_EQ(m.polygon().rings.size(), 1u);
    EXPECT_EQ(m.polygon().parts[0].ringCount, 1u);
    expectFloodedValid(m, 2);
    e.undo();
    expectSamePolygon(m.polygon(), p);

    Polygon tiny = makePolygon({{{{0, 0}}, {{5, 5}}}});
    m.openPolygon(tiny, "tiny.json", validate(tiny, "tiny.json"));
    EXPECT_FALSE(e.deleteVertex(0));
    EXPECT_NE(e.message().find("holes first"), std::string::npos) << e.message();
    expectSamePolygon(e.polygon(), tiny);
}

TEST(ViewerEdit, AddRingMakesAHoleInsideAndAPartOutside) {
    Model m;
    openSquare(m);
    Editor e(m);
    const Polygon original = m.polygon();
    const std::vector<Point> hole{{1, 1}, {1, 2}, {2, 2}, {2, 1}};
    ASSERT_TRUE(e.addRing(hole));
    const Polygon& p = m.polygon();
    ASSERT_EQ(p.parts.size(), 1u);
    EXPECT_EQ(p.parts[0].ringCount, 3u);
    EXPECT_EQ(ring(p, 2), hole);
    expectFloodedValid(m, original.expectedTriangles() + 6);  // 4 vertices, 1 hole more

    const std::vector<Point> island{{20, 0}, {30, 0}, {25, 8}};
    ASSERT_TRUE(e.addRing(island));
    ASSERT_EQ(m.polygon().parts.size(), 2u);
    EXPECT_EQ(m.polygon().parts[1].firstRing, 3u);
    EXPECT_EQ(ring(m.polygon(), 3), island);
    EXPECT_FALSE(m.failed()) << m.verdict();
    // Undone in turn, then both again.
    e.undo();
    e.undo();
    expectSamePolygon(m.polygon(), original);
    e.redo();
    e.redo();
    EXPECT_EQ(ring(m.polygon(), 3), island);
    EXPECT_FALSE(e.addRing({{40, 40}, {41, 40}})) << "an outer ring needs three corners";
}

TEST(ViewerEdit, MoveRingByTheGesturesTotalOffset) {
    Model m;
    openSquare(m);
    Editor e(m);
    const Polygon original = m.polygon();
    e.beginGesture();
    e.moveRing(1, {0.1, 0});
    e.moveRing(1, {0.2, 0});
    e.moveRing(1, {0.3, -1});
    e.endGesture();
    EXPECT_EQ(e.historySize(), 1u);
    std::vector<Point> want = ring(original, 1);
    for (Point& q : want) q = {q.x + 0.3, q.y - 1};  // from where it began, not 0.1 + 0.2 + 0.3
    EXPECT_EQ(ring(m.polygon(), 1), want);
    EXPECT_EQ(ring(m.polygon(), 0), ring(original, 0));
    expectFloodedValid(m, original.expectedTriangles());
    e.undo();
    expectSamePolygon(m.polygon(), original);
}

TEST(ViewerEdit, FloodedAgainAtTheSameStepClampedToTheNewTrace) {
    Model m;
    Polygon p = generate("comb", 3, 60);
    m.openPolygon(p, "comb", validate(p, "comb"));
    ASSERT_FALSE(m.failed()) << m.verdict();
    Editor e(m);
    const uint32_t mid = m.steps() / 2;
    m.seek(mid);
    m.centerOn({123, 456});
    const Point v0 = m.polygon().vertices[0];
    ASSERT_TRUE(e.moveVertex(0, {v0.x, v0.y}));  // the same polygon, flooded again
    EXPECT_EQ(m.step(), mid);
    EXPECT_EQ(m.state().step, mid);
    EXPECT_FALSE(m.fitPending()) << "the camera stays";
    EXPECT_EQ(m.camera().center().x, 123);

    // A shorter trace: the step is clamped to its end.
    m.last();
    const uint32_t longSteps = m.steps();
    ASSERT_TRUE(e.deleteVertex(5));
    ASSERT_LT(m.steps(), longSteps);
    EXPECT_EQ(m.step(), m.steps());
    EXPECT_EQ(m.state().step, m.steps());
    EXPECT_FALSE(m.failed()) << m.verdict();
}

TEST(ViewerEdit, ABowTieIsKeptWithTheValidatorsDiagnosticAndUndoRestoresValidity) {
    Model m;
    openSquare(m);
    Editor e(m);
    m.seek(2);
    // (10, 10) dragged to (-5, 10): edge 1 -> 2 now crosses edge 3 -> 0.
    e.beginGesture();
    ASSERT_TRUE(e.moveVertex(2, {5, 10}));
    ASSERT_TRUE(e.moveVertex(2, {-5, 10}));
    e.endGesture();
    Polygon bowTie = e.polygon();
    EXPECT_TRUE(bowTie.vertices[2] == (Point{-5, 10})) << "the edit is kept";
    Diagnostic expected = validate(bowTie, "square.json");
    ASSERT_EQ(expected.status, Status::Invalid);
    EXPECT_EQ(m.inputDiagnostic().status, Status::Invalid);
    EXPECT_EQ(m.inputDiagnostic().message, expected.message);
    EXPECT_NE(m.inputDiagnostic().message.find("ring 0"), std::string::npos)
        << m.inputDiagnostic().message;
    EXPECT_TRUE(m.failed());
    EXPECT_EQ(m.exitCode(), int(Status::Invalid));
    ASSERT_FALSE(m.verdictLines().empty());
    EXPECT_EQ(m.verdictLines()[0].kind, Verdict::Invalid);
    EXPECT_TRUE(m.polygon().vertices[2] == (Point{-5, 10}));

    ASSERT_TRUE(e.undo());
    expectSamePolygon(m.polygon(), squareWithHole());
    expectFloodedValid(m, squareWithHole().expectedTriangles());
    EXPECT_EQ(m.step(), 2u);
}

TEST(ViewerEdit, SaveWritesGeoJsonThatReloadsEqualAndNeverTheInputSilently) {
    namespace fs = std::filesystem;
    const fs::path dir = flood::testing::scratch("viewer-edit-save");
    const std::string input = (dir / "square.json").string();
    ASSERT_TRUE(saveGeoJson(squareWithHole(), input).ok());
    Model m;
    m.open(input);
    ASSERT_FALSE(m.failed()) << m.verdict();
    Editor e(m);
    e.insertVertex(0, {5, -0.125});
    e.addRing({{20, 0}, {30, 0}, {25, 8.000000000000002}});  // a second part, an inexact decimal
    EXPECT_EQ(e.defaultSavePath(), (dir / "square-edited.json").string());
    const std::string before = flood::testing::slurp(input);
    Diagnostic refused = e.save(input);
    EXPECT_EQ(refused.status, Status::Usage);
    EXPECT_EQ(flood::testing::slurp(input), before) << "the input is untouched";

    const std::string out = e.defaultSavePath();
    ASSERT_TRUE(e.save(out).ok());
    EXPECT_EQ(e.defaultSavePath(), (dir / "square-edited-2.json").string())
        << "never the saved one either";
    ReadResult back = readPolygonFile(out);
    ASSERT_TRUE(back.diagnostic.ok()) << back.diagnostic.message;
    expectSamePolygon(back.polygon, e.polygon());
    EXPECT_NE(flood::testing::slurp(out).find("MultiPolygon"), std::string::npos);
    // Only the two files: no temporary left behind.
    size_t files = 0;
    for (const auto& f : fs::directory_iterator(dir)) files += f.is_regular_file();
    EXPECT_EQ(files, 2u);
    ASSERT_TRUE(e.save(input, true).ok()) << "overwriting the input when asked to";

    e.newEmpty();
    EXPECT_EQ(e.save(out).status, Status::Usage) << "an empty canvas has nothing to save";
}

TEST(ViewerEdit, AnEmptyCanvasAndThreeCornersGiveAValidTriangle) {
    Model m;
    openSquare(m);
    Editor e(m);
    const Polygon original = m.polygon();
    e.newEmpty();
    EXPECT_TRUE(m.polygon().vertices.empty());
    EXPECT_EQ(m.steps(), 0u);
    EXPECT_FALSE(m.failed()) << m.verdict();
    e.corners = {{0, 0}, {4, 0}, {1, 3}};
    ASSERT_TRUE(e.closeRing());
    EXPECT_TRUE(e.corners.empty());
    ASSERT_EQ(m.polygon().rings.size(), 1u);
    EXPECT_EQ(ring(m.polygon(), 0), (std::vector<Point>{{0, 0}, {4, 0}, {1, 3}}));
    expectFloodedValid(m, 1);
    EXPECT_EQ(m.path(), "square.json") << "an edit keeps the name";
    e.undo();
    e.undo();
    expectSamePolygon(m.polygon(), original);
}

TEST(ViewerEdit, OpeningAnotherFileStartsAFreshHistory) {
    Model m;
    openSquare(m);
    Editor e(m);
    e.moveVertex(0, {-1, -1});
    ASSERT_TRUE(e.canUndo());
    Polygon tri = makePolygon({{{{0, 0}, {1, 0}, {0, 1}}}});
    m.openPolygon(tri, "tri.json", validate(tri, "tri.json"));
    EXPECT_FALSE(e.canUndo());
    expectSamePolygon(e.polygon(), tri);
}

TEST(ViewerEdit, BackgroundFloodShowsTheOldTraceUntilTheNewOneIsAdopted) {
    Model m;
    Polygon p = generate("circle-holes", 2, 2000);
    m.openPolygon(p, "circle-holes", validate(p, "circle-holes"));
    ASSERT_FALSE(m.failed()) << m.verdict();
    Editor e(m);
    e.background = true;
    const Point v = m.polygon().vertices[0];
    // Many moves in one drag: edits made while a flood runs wait for the next one.
    e.beginGesture();
    for (int i = 1; i <= 20; ++i) e.moveVertex(0, {v.x, v.y});
    e.moveVertex(0, {v.x * 1.0001, v.y});
    e.endGesture();
    EXPECT_TRUE(e.polygon().vertices[0] == (Point{v.x * 1.0001, v.y}));
    e.wait();
    EXPECT_FALSE(e.pending());
    EXPECT_TRUE(m.polygon().vertices[0] == (Point{v.x * 1.0001, v.y}))
        << "the latest edit is what is shown";
    EXPECT_FALSE(m.failed()) << m.verdict();

    // A flood overtaken by an open is dropped, never adopted over the new file.
    e.moveVertex(0, v);
    Polygon tri = makePolygon({{{{0, 0}, {1, 0}, {0, 1}}}});
    m.openPolygon(tri, "tri.json", validate(tri, "tri.json"));
    e.wait();
    e.poll();
    EXPECT_EQ(m.path(), "tri.json");
    expectSamePolygon(m.polygon(), tri);
}

#endif
