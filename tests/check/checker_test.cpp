// The exact checker accepts correct triangulations and rejects each kind of wrong one with the
// rule it breaks named in the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <future>
#include <set>

#include "flood/check/checker.h"
#include "flood/io/io.h"
#include "flood/machine/flood.h"
#include "flood/tools/generate.h"

using flood::checkTriangulation;
using flood::Point;
using flood::Polygon;
using flood::Triangle;

namespace {

Polygon square() {
    Polygon p;
    p.addRing({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    return p;
}

Polygon square4() {
    Polygon p;
    p.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    return p;
}

// Regular-ish convex hexagon on integer coordinates, counter-clockwise.
Polygon hexagon() {
    Polygon p;
    p.addRing({{2, 0}, {4, 0}, {6, 2}, {4, 4}, {2, 4}, {0, 2}}, true);
    return p;
}
const std::vector<Triangle> kHexagonFan = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};

// Square (0..6) with a square hole (2..4), both rings counter-clockwise in the input.
Polygon squareWithHole() {
    Polygon p;
    p.addRing({{0, 0}, {6, 0}, {6, 6}, {0, 6}}, true);
    p.addRing({{2, 2}, {4, 2}, {4, 4}, {2, 4}}, false);
    return p;
}
const std::vector<Triangle> kSquareWithHole = {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                               {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};

::testing::AssertionResult rejected(const Polygon& p, const std::vector<Triangle>& t,
                                    const std::string& rule) {
    auto r = checkTriangulation(p, t);
    if (r.ok) return ::testing::AssertionFailure() << "accepted, expected " << rule;
    if (r.reason.find(rule) == std::string::npos)
        return ::testing::AssertionFailure() << "reason '" << r.reason << "', expected " << rule;
    return ::testing::AssertionSuccess() << r.reason;
}

::testing::AssertionResult accepted(const Polygon& p, const std::vector<Triangle>& t) {
    auto r = checkTriangulation(p, t);
    if (!r.ok) return ::testing::AssertionFailure() << r.reason;
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(Checker, AcceptsSquare) {
    EXPECT_TRUE(accepted(square(), {{0, 1, 2}, {0, 2, 3}}));
    EXPECT_TRUE(accepted(square(), {{1, 2, 3}, {1, 3, 0}}));
    EXPECT_TRUE(accepted(square(), {{2, 0, 1}, {3, 0, 2}}));  // rotated vertex order
}

TEST(Checker, AcceptsClockwiseInputRing) {
    Polygon p;
    p.addRing({{0, 0}, {0, 2}, {2, 2}, {2, 0}}, true);
    EXPECT_TRUE(accepted(p, {{0, 3, 2}, {0, 2, 1}}));
    EXPECT_TRUE(rejected(p, {{0, 2, 3}, {0, 1, 2}}, "clockwise-triangle"));
}

TEST(Checker, AcceptsSquareWithHoleBothOrientations) {
    EXPECT_TRUE(accepted(squareWithHole(), kSquareWithHole));
    // Same shape, both rings reversed: old index -> new index.
    Polygon q;
    q.addRing({{0, 0}, {0, 6}, {6, 6}, {6, 0}}, true);
    q.addRing({{2, 2}, {2, 4}, {4, 4}, {4, 2}}, false);
    const flood::Index map[8] = {0, 3, 2, 1, 4, 7, 6, 5};
    std::vector<Triangle> t;
    for (const Triangle& tri : kSquareWithHole)
        t.push_back({map[tri[0]], map[tri[1]], map[tri[2]]});
    EXPECT_TRUE(accepted(q, t));
    // Outer clockwise, hole counter-clockwise mixed.
    Polygon r;
    r.addRing({{0, 0}, {0, 6}, {6, 6}, {6, 0}}, true);
    r.addRing({{2, 2}, {4, 2}, {4, 4}, {2, 4}}, false);
    const flood::Index map2[8] = {0, 3, 2, 1, 4, 5, 6, 7};
    t.clear();
    for (const Triangle& tri : kSquareWithHole)
        t.push_back({map2[tri[0]], map2[tri[1]], map2[tri[2]]});
    EXPECT_TRUE(accepted(r, t));
}

TEST(Checker, AcceptsHoleTouchingOuterAtSharedVertex) {
    // Outer: 0(0,0) 1(2,0) 2(4,0) 3(4,4) 4(0,4); hole: 5(2,0) 6(3,2) 7(1,2), apex on vertex 1.
    // Each wedge of interior at (2,0) is bounded by one edge of each ring; the left wedge's
    // triangle uses copy 1, the right wedge's uses copy 5. The touching point makes the region
    // simply connected: n + 2h - 2 - 2d = 8 + 2 - 2 - 2 = 6 triangles.
    Polygon p;
    p.addRing({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    p.addRing({{2, 0}, {3, 2}, {1, 2}}, false);
    std::vector<Triangle> t = {{0, 1, 7}, {0, 7, 4}, {4, 7, 6}, {4, 6, 3}, {3, 6, 2}, {2, 6, 5}};
    EXPECT_TRUE(accepted(p, t));
    t[5] = {2, 6, 1};  // the other copy works too
    EXPECT_TRUE(accepted(p, t));
    t.push_back({0, 1, 7});
    EXPECT_TRUE(rejected(p, t, "triangle-count"));
}

TEST(Checker, AcceptsQuadHoleTouchingOuter) {
    // Outer 0(0,0) 1(3,0) 2(6,0) 3(6,6) 4(0,6); hole 5(3,0) 6(4,2) 7(3,4) 8(2,2) touching the
    // outer ring at (3,0): 9 + 2 - 2 - 2 = 7 triangles.
    Polygon p;
    p.addRing({{0, 0}, {3, 0}, {6, 0}, {6, 6}, {0, 6}}, true);
    p.addRing({{3, 0}, {4, 2}, {3, 4}, {2, 2}}, false);
    std::vector<Triangle> t = {{0, 1, 8}, {0, 8, 4}, {8, 7, 4}, {4, 7, 3},
                               {7, 6, 3}, {6, 2, 3}, {5, 2, 6}};
    EXPECT_TRUE(accepted(p, t));
    t[6] = {5, 6, 2};
    EXPECT_TRUE(rejected(p, t, "clockwise-triangle"));
}

TEST(Checker, AcceptsTwoParts) {
    Polygon p;
    p.addRing({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    p.addRing({{2, 2}, {4, 2}, {4, 4}, {2, 4}}, true);  // touches the first part at (2,2)
    EXPECT_TRUE(accepted(p, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}));
    EXPECT_TRUE(rejected(p, {{0, 1, 6}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}, "mixed-parts"));
}

TEST(Checker, RejectsMissingTriangle) {
    EXPECT_TRUE(rejected(square(), {{0, 1, 2}}, "triangle-count"));
    EXPECT_TRUE(rejected(squareWithHole(), {kSquareWithHole.begin(), kSquareWithHole.end() - 1},
                         "triangle-count"));
}

TEST(Checker, RejectsFlippedTriangle) {
    EXPECT_TRUE(rejected(square(), {{0, 2, 1}, {0, 2, 3}}, "clockwise-triangle"));
}

TEST(Checker, RejectsDegenerateTriangle) {
    Polygon p;  // collinear vertex 1 on the bottom edge
    p.addRing({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    EXPECT_TRUE(accepted(p, {{1, 2, 3}, {1, 3, 4}, {0, 1, 4}}));
    EXPECT_TRUE(rejected(p, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}, "degenerate-triangle"));
}

TEST(Checker, RejectsOverlappingTrianglesWithCorrectCount) {
    EXPECT_TRUE(accepted(hexagon(), kHexagonFan));
    // (1, 4, 5) overlaps (0, 3, 4); count is right but boundary edge (5, 0) is never covered.
    EXPECT_TRUE(
        rejected(hexagon(), {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {1, 4, 5}}, "boundary-edge-missing"));
    // Same triangle twice: every edge used twice the same way.
    EXPECT_TRUE(rejected(square(), {{0, 1, 2}, {0, 1, 2}}, "edge-used-twice"));
}

TEST(Checker, RejectsBoundaryEdgeMissing) {
    EXPECT_TRUE(
        rejected(hexagon(), {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {2, 4, 5}}, "boundary-edge-missing"));
}

TEST(Checker, RejectsBoundaryEdgeFromOutside) {
    // Triangles covering the hole of the square-with-hole use hole edges from the wrong side.
    std::vector<Triangle> t = kSquareWithHole;
    t[7] = {4, 5, 6};
    EXPECT_TRUE(rejected(squareWithHole(), t, "boundary-edge-reversed"));
}

TEST(Checker, RejectsEdgeUsedTwiceSameWay) {
    EXPECT_TRUE(
        rejected(hexagon(), {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 3, 5}}, "edge-used-twice"));
}

TEST(Checker, RejectsUnmatchedInteriorEdge) {
    // Three ears plus the overlapping middle triangle (1, 3, 5): every boundary edge once, no
    // directed edge twice, count right, but diagonal (2, 0) has no twin.
    EXPECT_TRUE(accepted(hexagon(), {{0, 1, 2}, {2, 3, 4}, {4, 5, 0}, {0, 2, 4}}));
    EXPECT_TRUE(
        rejected(hexagon(), {{0, 1, 2}, {2, 3, 4}, {4, 5, 0}, {1, 3, 5}}, "unmatched-edge"));
}

TEST(Checker, RejectsCrossingDiagonals) {
    // Diagonals 1-3 and 5-1 cross 2-4, 4-0 and 0-2: all boundary edges covered once.
    EXPECT_TRUE(
        rejected(hexagon(), {{0, 1, 2}, {2, 3, 4}, {4, 5, 0}, {1, 3, 5}}, "unmatched-edge"));
    // Diagonals 0-3 and 1-4 (and 2-4) cross; the count is right, edge (4, 5) is lost.
    EXPECT_TRUE(
        rejected(hexagon(), {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {0, 3, 5}}, "boundary-edge-missing"));
    // A square split along both diagonals at once.
    EXPECT_TRUE(rejected(square(), {{0, 1, 2}, {1, 2, 3}}, "edge-used-twice"));
    EXPECT_TRUE(rejected(square(), {{0, 1, 2}, {1, 3, 0}}, "edge-used-twice"));
}

TEST(Checker, RejectsIndexOutOfRange) {
    EXPECT_TRUE(rejected(square(), {{0, 1, 2}, {0, 2, 7}}, "index-out-of-range"));
    EXPECT_TRUE(rejected(square(), {{0, 1, 2}, {0, 2, flood::kNone}}, "index-out-of-range"));
}

TEST(Checker, ReasonNamesTriangleAndVertices) {
    auto r = checkTriangulation(square(), {{0, 1, 2}, {0, 3, 2}});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(r.reason.find("triangle 1 (0, 3, 2)"), std::string::npos) << r.reason;
}

TEST(Checker, RejectsBadRings) {
    Polygon p;
    p.addRing({{0, 0}, {1, 1}, {2, 2}}, true);
    EXPECT_TRUE(rejected(p, {{0, 1, 2}}, "degenerate-triangle"));
    EXPECT_TRUE(rejected(p, {}, "triangle-count"));
}

TEST(Checker, AreaRuleAgreesWithTopology) {
    // When rules 1-6 hold, the triangles form a 2-chain whose boundary is the polygon's, so the
    // area rule cannot fail on its own: it is a second, independent proof. Check it holds on a
    // polygon with large and tiny coordinates, where a float area sum would be inexact.
    Polygon p;
    p.addRing({{0, 0}, {1e-300, 0}, {1e300, 1e-300}, {1e300, 1e300}, {0, 1e-10}}, true);
    EXPECT_TRUE(accepted(p, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

// Correct at scale (speed is measured in bench/, not here).
TEST(Checker, MillionTrianglesAtScale) {
    // Convex polygon on the parabola y = x^2 (exact integers), fan-triangulated.
    const int n = 1000002;
    std::vector<Point> pts;
    pts.reserve(n);
    for (int i = 0; i < n; ++i) pts.push_back({double(i), double(i) * double(i)});
    Polygon p;
    p.addRing(pts, true);
    std::vector<Triangle> t;
    t.reserve(n - 2);
    for (flood::Index i = 1; i + 1 < flood::Index(n); ++i) t.push_back({0, i, i + 1});
    auto r = checkTriangulation(p, t);
    EXPECT_TRUE(r.ok) << r.reason;
    std::swap(t[1000][1], t[1000][2]);
    EXPECT_FALSE(checkTriangulation(p, t).ok);
}

// A hole touching the square's bottom edge inside it (a T-junction at vertex 4): the edge
// counts as two boundary edges, 0-4 and 4-1, and the triangle count is one less.
TEST(Checker, SplitsBoundaryEdgesAtTJunctions) {
    Polygon p = square4();
    p.addRing({{2, 0}, {3, 1}, {1, 1}}, false);
    const std::vector<Triangle> t = {{0, 4, 6}, {4, 1, 5}, {1, 2, 5},
                                     {5, 2, 3}, {5, 3, 6}, {6, 3, 0}};
    EXPECT_TRUE(rejected(p, t, "triangle-count"));  // without the split: n + 2h - 2 = 7 expected
    p.splits = {{0, 4}};
    EXPECT_TRUE(accepted(p, t));
    p.splits = {{1, 5}};  // (3, 1) is not on the edge (4, 0)-(4, 4)
    EXPECT_TRUE(rejected(p, t, "bad-split"));
    p.splits = {{0, 9}};
    EXPECT_TRUE(rejected(p, t, "bad-split"));
}

// A single-point hole (a Steiner point) must be a vertex of the triangulation.
TEST(Checker, PointHolesMustBeUsed) {
    Polygon p = square4();
    p.addRing({{1, 1}}, false);
    EXPECT_TRUE(accepted(p, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}));
    EXPECT_TRUE(rejected(p, {{0, 1, 2}, {0, 2, 3}}, "triangle-count"));
    EXPECT_TRUE(rejected(p, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 4, 0}}, "clockwise"));
    Polygon outerPoint;  // an outer ring of one point is no polygon
    outerPoint.addRing({{1, 1}}, true);
    EXPECT_TRUE(rejected(outerPoint, {}, "ring-too-short"));
}

// The failed rule comes as data (CheckResult::rule), the number checker.cpp gives it: each
// rejection above, by rule. Rule 7 (area) is implied by rules 3-6, so no input reaches it.
TEST(Checker, ReportsTheFailedRule) {
    using flood::CheckRule;
    auto ruleOf = [](const Polygon& p, const std::vector<Triangle>& t) {
        return checkTriangulation(p, t).rule;
    };
    Polygon outerPoint;
    outerPoint.addRing({{1, 1}}, true);
    EXPECT_EQ(ruleOf(outerPoint, {}), CheckRule::Rings);
    Polygon bowTie;  // a ring of zero area whose two triangles pass rules 1-4
    bowTie.addRing({{0, 0}, {2, 0}, {0, 2}, {2, 2}}, true);
    EXPECT_EQ(ruleOf(bowTie, {{0, 1, 2}, {1, 3, 2}}), CheckRule::Rings);
    EXPECT_EQ(ruleOf(square(), {{0, 1, 2}, {0, 2, 7}}), CheckRule::Indices);
    EXPECT_EQ(ruleOf(square(), {{0, 1, 2}}), CheckRule::PartsAndCount);
    Polygon two;
    two.addRing({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    two.addRing({{2, 2}, {4, 2}, {4, 4}, {2, 4}}, true);
    EXPECT_EQ(ruleOf(two, {{0, 1, 6}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}), CheckRule::PartsAndCount);
    EXPECT_EQ(ruleOf(square(), {{0, 2, 1}, {0, 2, 3}}), CheckRule::CounterClockwise);
    EXPECT_EQ(ruleOf(square(), {{0, 1, 2}, {0, 1, 2}}), CheckRule::DistinctEdges);
    EXPECT_EQ(ruleOf(hexagon(), {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {2, 4, 5}}),
              CheckRule::BoundaryEdges);
    std::vector<Triangle> fromOutside = kSquareWithHole;
    fromOutside[7] = {4, 5, 6};
    EXPECT_EQ(ruleOf(squareWithHole(), fromOutside), CheckRule::BoundaryEdges);
    EXPECT_EQ(ruleOf(hexagon(), {{0, 1, 2}, {2, 3, 4}, {4, 5, 0}, {1, 3, 5}}),
              CheckRule::InteriorTwins);
    Polygon twice;  // two identical parts, each triangulated alone: only rule 8 can tell
    twice.addRing({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    twice.addRing({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    EXPECT_EQ(ruleOf(twice, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}),
              CheckRule::PartsDisjoint);
    EXPECT_EQ(ruleOf(square(), {{0, 1, 2}, {0, 2, 3}}), CheckRule::None);
}

// checkTriangles() on another thread, handed to checkTriangulation (as `flood triangulate -o`
// does while writing), gives the verdict of the check alone: the same rule, reason and
// culprits, rule 3 reported before any later rule even when the others finish first. Over
// every generated family, triangulated, then broken in each way the rules catch.
TEST(Checker, TriangleCheckOnAnotherThreadGivesTheSameVerdict) {
    auto elsewhere = [](const Polygon& p, const std::vector<Triangle>& t) {
        std::future<flood::TriangleCheck> each =
            std::async(std::launch::async, [&] { return flood::checkTriangles(p, t); });
        return checkTriangulation(p, t, [&] { return each.get(); });
    };
    size_t cases = 0, rejectedCases = 0;
    std::set<flood::CheckRule> rules;
    auto same = [&](const Polygon& p, const std::vector<Triangle>& t, const std::string& what) {
        flood::CheckResult alone = checkTriangulation(p, t), split = elsewhere(p, t);
        EXPECT_EQ(alone.ok, split.ok) << what;
        EXPECT_EQ(alone.rule, split.rule) << what;
        EXPECT_EQ(alone.reason, split.reason) << what;
        EXPECT_EQ(alone.culprits.triangles, split.culprits.triangles) << what;
        EXPECT_EQ(alone.culprits.vertices, split.culprits.vertices) << what;
        EXPECT_EQ(alone.culprits.rings, split.culprits.rings) << what;
        ++cases, rejectedCases += !alone.ok;
        rules.insert(alone.rule);
    };
    for (const std::string& family : flood::familyNames()) {
        Polygon p = flood::generate(family, 7, 400);
        ASSERT_TRUE(flood::validate(p, family).ok()) << family;
        const std::vector<Triangle> t = flood::triangulate(p, nullptr, {}).triangles;
        ASSERT_FALSE(t.empty()) << family;
        same(p, t, family);
        const size_t k = t.size() / 2;
        auto broken = [&](const char* how, auto&& change) {
            std::vector<Triangle> b = t;
            change(b);
            same(p, b, family + ": " + how);
        };
        broken("flipped", [&](auto& b) { std::swap(b[k][1], b[k][2]); });  // rules 3 and 5/6
        broken("flipped last", [&](auto& b) { std::swap(b.back()[1], b.back()[2]); });
        broken("dropped", [&](auto& b) { b.erase(b.begin() + long(k)); });
        broken("twice", [&](auto& b) { b[k] = b[k == 0 ? 1 : k - 1]; });
        broken("degenerate", [&](auto& b) { b[k][2] = b[k][1]; });
        broken("out of range", [&](auto& b) { b[k][0] = flood::Index(p.vertices.size()); });
        broken("rotated ends", [&](auto& b) {  // two triangles trade a corner: twins break
            std::swap(b[k][0], b[(k + 1) % b.size()][0]);
        });
    }
    EXPECT_GT(rejectedCases, cases / 2);
    for (flood::CheckRule r : {flood::CheckRule::None, flood::CheckRule::Indices,
                               flood::CheckRule::PartsAndCount, flood::CheckRule::CounterClockwise})
        EXPECT_TRUE(rules.count(r)) << "no case broke rule " << int(r);
}

// A fan: one vertex with an edge to every other (the checker sorts a long edge list
// differently from the short ones), accepted, and refused with one triangle turned over.
TEST(Checker, FanAroundOneVertex) {
    const int n = 1000;
    std::vector<Point> ring;
    for (int i = 0; i < n; ++i)  // along the parabola y = x^2: convex, counter-clockwise
        ring.push_back({double(i), double(i) * i});
    Polygon p;
    p.addRing(ring, true);
    std::vector<Triangle> fan;
    for (flood::Index i = 1; i + 1 < n; ++i) fan.push_back({0, i, i + 1});
    EXPECT_TRUE(accepted(p, fan));
    std::swap(fan[n / 2][1], fan[n / 2][2]);
    EXPECT_TRUE(rejected(p, fan, "clockwise-triangle"));
}
