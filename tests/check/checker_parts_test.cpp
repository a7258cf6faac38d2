// The checker sees all parts together (rule 8): triangulations of MultiPolygons whose parts
// overlap are rejected, however the boundaries meet, and parts that only touch are accepted.
// Each part is valid alone and triangulated alone, so rules 1-7 hold and only rule 8 can tell.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flood/check/checker.h"
#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "flood/machine/flood.h"
#include "flood/tools/generate.h"

using namespace flood;

namespace {

using Ring = std::vector<Point>;

// One part: an outer ring and its holes.
Polygon part(const Ring& outer, const std::vector<Ring>& holes = {}) {
    Polygon p;
    p.addRing(outer, true);
    for (const Ring& h : holes) p.addRing(h, false);
    return p;
}

Ring box(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

struct Together {
    Polygon polygon;
    std::vector<Triangle> triangles;
};

// Each polygon (of one part or more) transformed, validated and triangulated on its own, then
// all concatenated, indices shifted: each part's triangles tile that part.
Together together(const std::vector<Polygon>& pieces, int rotation = 0, bool mirror = false) {
    Together t;
    for (const Polygon& piece : pieces) {
        Polygon p = transform(piece, rotation, mirror, false, 0);
        EXPECT_TRUE(validate(p, "piece").ok());
        FloodResult r = triangulate(p);
        EXPECT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
        EXPECT_TRUE(checkTriangulation(p, r.triangles).ok);
        const Index shift = Index(t.polygon.vertices.size());
        for (Index k = 0; k < p.parts.size(); ++k)
            for (Index r = p.parts[k].firstRing; r < p.parts[k].firstRing + p.parts[k].ringCount;
                 ++r) {
                const flood::Ring& ring = p.rings[r];
                t.polygon.addRing(
                    {p.vertices.begin() + ring.first, p.vertices.begin() + ring.first + ring.count},
                    r == p.parts[k].firstRing);
            }
        for (EdgeSplit s : p.splits) t.polygon.splits.push_back({s.edge + shift, s.vertex + shift});
        for (Triangle tri : r.triangles)
            t.triangles.push_back({tri[0] + shift, tri[1] + shift, tri[2] + shift});
    }
    return t;
}

// The verdict is the same under all eight rotations and mirrors.
::testing::AssertionResult overlapRejected(const std::vector<Polygon>& pieces) {
    for (int rotation = 0; rotation < 4; ++rotation)
        for (bool mirror : {false, true}) {
            Together t = together(pieces, rotation, mirror);
            CheckResult c = checkTriangulation(t.polygon, t.triangles);
            if (c.ok || c.reason.find("parts-overlap") == std::string::npos)
                return ::testing::AssertionFailure()
                       << "rotation " << rotation << (mirror ? " mirrored" : "") << ": "
                       << (c.ok ? "accepted" : c.reason);
        }
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult touchingAccepted(const std::vector<Polygon>& pieces) {
    for (int rotation = 0; rotation < 4; ++rotation)
        for (bool mirror : {false, true}) {
            Together t = together(pieces, rotation, mirror);
            CheckResult c = checkTriangulation(t.polygon, t.triangles);
            if (!c.ok)
                return ::testing::AssertionFailure()
                       << "rotation " << rotation << (mirror ? " mirrored" : "") << ": "
                       << c.reason;
        }
    return ::testing::AssertionSuccess();
}

}  // namespace

// [SECTION] overlapping parts: rejected

TEST(CheckerParts, RejectsIdenticalParts) {
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 4, 4)), part(box(0, 0, 4, 4))}));
    Polygon holed = part(box(0, 0, 6, 6), {box(2, 2, 4, 4)});
    EXPECT_TRUE(overlapRejected({holed, holed}));
}

TEST(CheckerParts, RejectsPartStrictlyInsideAnother) {
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 10, 10)), part(box(2, 3, 4, 5))}));
    EXPECT_TRUE(overlapRejected({part(box(2, 3, 4, 5)), part(box(0, 0, 10, 10))}));
    // Inside the outer ring but not inside its hole: no boundary contact either.
    EXPECT_TRUE(
        overlapRejected({part(box(0, 0, 10, 10), {box(5, 5, 9, 9)}), part(box(1, 1, 3, 3))}));
}

TEST(CheckerParts, RejectsProperlyCrossingEdges) {
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 4, 4)), part(box(2, 2, 6, 6))}));
    // A cross: no vertex of either bar lies inside the other, only the edges cross.
    EXPECT_TRUE(overlapRejected({part(box(0, 1, 6, 3)), part(box(2, 0, 4, 4))}));
    // A part larger than the lake it sits in.
    EXPECT_TRUE(
        overlapRejected({part(box(0, 0, 10, 10), {box(2, 2, 8, 8)}), part(box(1, 3, 5, 5))}));
}

// The fuzzer's cases: the parts' boundaries meet only where a vertex of one lies on an edge
// of the other, yet their interiors overlap.
TEST(CheckerParts, RejectsCrossingThroughVerticesOnEdges) {
    // (2,0) lies inside the square's bottom edge and (4,2) inside its right edge; the part
    // leaves the square at one and re-enters at the other.
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 4, 4)), part({{2, 0}, {6, -2}, {4, 2}, {3, 2}})}));
    // A diamond inside the square, its four vertices inside the square's four edges.
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 4, 4)), part({{2, 0}, {4, 2}, {2, 4}, {0, 2}})}));
    // The square inside the diamond, its four corners inside the diamond's four edges.
    EXPECT_TRUE(overlapRejected({part(box(1, 1, 3, 3)), part({{2, 0}, {4, 2}, {2, 4}, {0, 2}})}));
}

TEST(CheckerParts, RejectsCollinearEdgesWithBothPartsOnOneSide) {
    // A smaller rectangle standing on the bottom edge of a larger one.
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 4, 2)), part(box(1, 0, 3, 1))}));
    // Two rectangles shifted along a common line: bottoms and tops collinear, each side edge
    // ends on the other's edges (no proper crossing anywhere).
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 4, 2)), part(box(2, 0, 6, 2))}));
    // The same edge in both parts, interiors on the same side.
    EXPECT_TRUE(overlapRejected({part({{0, 0}, {4, 0}, {2, 3}}), part({{0, 0}, {4, 0}, {2, 1}})}));
}

TEST(CheckerParts, RejectsWedgesInterleavingAtASharedVertex) {
    // At (0,0) the square's wedge spans 0-90 degrees, the triangle's 45-135: they share the
    // vertex, the triangle's top runs along the square's top edge, the square's corner (0,2)
    // lies inside the triangle's top edge.
    EXPECT_TRUE(overlapRejected({part(box(0, 0, 2, 2)), part({{0, 0}, {2, 2}, {-2, 2}})}));
    // Two triangles fanned around one point, the second's wedge inside the first's.
    EXPECT_TRUE(overlapRejected({part({{0, 0}, {4, 1}, {1, 4}}), part({{0, 0}, {2, 1}, {1, 2}})}));
}

TEST(CheckerParts, ReasonNamesTheTwoPartsAndAVertex) {
    Together t =
        together({part(box(0, 0, 10, 10)), part(box(10, 0, 12, 2)), part(box(2, 3, 4, 5))});
    CheckResult c = checkTriangulation(t.polygon, t.triangles);
    ASSERT_FALSE(c.ok);
    EXPECT_NE(c.reason.find("parts-overlap: parts 0 and 2 overlap beside vertex 8 (2, 3)"),
              std::string::npos)
        << c.reason;
    // ... and as data, for the viewer's error view: the vertex and the two parts' outer rings.
    EXPECT_EQ(c.culprits.vertices, std::vector<uint32_t>{8});
    EXPECT_EQ(c.culprits.rings, (std::vector<uint32_t>{0, 2}));
    // The cross: the vertical bar's left edge, directed down, crosses the bar's bottom edge.
    t = together({part(box(0, 1, 6, 3)), part(box(2, 0, 4, 4))});
    c = checkTriangulation(t.polygon, t.triangles);
    ASSERT_FALSE(c.ok);
    EXPECT_NE(c.reason.find("parts-overlap: edge (7, 4) of part 1 crosses edge (0, 1) of part 0"),
              std::string::npos)
        << c.reason;
    EXPECT_EQ(c.culprits.vertices, (std::vector<uint32_t>{7, 4, 0, 1}));
    EXPECT_EQ(c.culprits.rings, (std::vector<uint32_t>{1, 0}));
}

// Parts that a line sets apart from all others are not swept (geometry/boxes_apart.h): an
// overlap among the rest is still found, in a row or a column of parts apart, and reported as
// the sweep of every part reports it.
TEST(CheckerParts, OverlapAmongPartsApartIsFound) {
    std::vector<Polygon> apart, touching;
    for (int k = 0; k < 40; ++k) {
        if (k == 20) {  // the overlapping pair, at the same place in both layouts
            for (auto* pieces : {&apart, &touching}) {
                pieces->push_back(part(box(200, 0, 203, 3)));
                pieces->push_back(part(box(201, 1, 205, 2)));
            }
        }
        apart.push_back(part(box(4 * k, 0, 4 * k + 3, 3)));
        touching.push_back(part(box(3 * k - 300, 0, 3 * k - 297, 3)));  // along whole edges
    }
    EXPECT_TRUE(overlapRejected(apart));
    EXPECT_TRUE(overlapRejected(touching));
    Together a = together(apart), t = together(touching);
    EXPECT_EQ(checkTriangulation(a.polygon, a.triangles).reason,
              checkTriangulation(t.polygon, t.triangles).reason);
    apart.erase(apart.begin() + 21);  // the pair's second square
    EXPECT_TRUE(touchingAccepted(apart));
}

// [SECTION] touching parts: accepted

TEST(CheckerParts, AcceptsPartsTouchingAtVertices) {
    // A 2x2 checkerboard: four squares meeting at (1,1), two of them through corners only.
    EXPECT_TRUE(touchingAccepted({part(box(0, 0, 1, 1)), part(box(1, 1, 2, 2)),
                                  part(box(1, 0, 2, 1)), part(box(0, 1, 1, 2))}));
    // Triangles fanned around one point, wedges in turn, one point shared by six parts.
    std::vector<Polygon> fan;
    const Point spokes[6] = {{4, 0}, {2, 4}, {-2, 4}, {-4, 0}, {-2, -4}, {2, -4}};
    for (int k = 0; k < 6; ++k) fan.push_back(part({{0, 0}, spokes[k], spokes[(k + 1) % 6]}));
    EXPECT_TRUE(touchingAccepted(fan));
}

TEST(CheckerParts, AcceptsTJunctionsBetweenParts) {
    // (2,2) lies inside the first part's top edge, (4,2) inside the second's bottom edge; the
    // parts touch along the stretch between.
    EXPECT_TRUE(touchingAccepted({part(box(0, 0, 4, 2)), part(box(2, 2, 6, 4))}));
    // Triangles standing on their apex inside the square's top edge, upright and leaning.
    EXPECT_TRUE(touchingAccepted({part(box(0, 0, 4, 4)), part({{1, 6}, {2, 4}, {3, 6}})}));
    EXPECT_TRUE(touchingAccepted({part(box(0, 0, 4, 4)), part({{1, 8}, {2, 4}, {2, 6}})}));
    // The square's corner (4,4) inside the triangle's edge (2,6)-(6,2).
    EXPECT_TRUE(touchingAccepted({part(box(0, 0, 4, 4)), part({{2, 6}, {6, 2}, {6, 6}})}));
}

TEST(CheckerParts, AcceptsGridsOfSquares) {
    for (int n : {3, 7}) {
        std::vector<Polygon> grid, board, bricks;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                grid.push_back(part(box(i, j, i + 1, j + 1)));  // along whole edges
                if ((i + j) % 2 == 0) board.push_back(part(box(i, j, i + 1, j + 1)));  // at corners
                bricks.push_back(
                    part(box(2 * i + j % 2, j, 2 * i + j % 2 + 2, j + 1)));  // T-junctions
            }
        EXPECT_TRUE(touchingAccepted(grid)) << n;
        EXPECT_TRUE(touchingAccepted(board)) << n;
        EXPECT_TRUE(touchingAccepted(bricks)) << n;
    }
}

TEST(CheckerParts, AcceptsIslandsInLakes) {
    Polygon lake = part(box(0, 0, 10, 10), {box(2, 2, 8, 8)});
    EXPECT_TRUE(touchingAccepted({lake, part(box(3, 3, 7, 7))}));
    EXPECT_TRUE(touchingAccepted({lake, part(box(2, 2, 8, 8))}));  // the island fills the lake
    EXPECT_TRUE(
        touchingAccepted({lake, part(box(2, 2, 5, 5))}));  // touching the shore along two edges
    EXPECT_TRUE(
        touchingAccepted({lake, part({{5, 2}, {8, 5}, {5, 8}, {2, 5}})}));  // at T-junctions
    // An island with a lake with an island, as one polygon of three parts.
    Polygon nested = lake;
    nested.addRing(box(3, 3, 7, 7), true);
    nested.addRing(box(4, 4, 6, 6), false);
    nested.addRing(box(4.5, 4.5, 5.5, 5.5), true);
    EXPECT_TRUE(touchingAccepted({nested}));
}

TEST(CheckerParts, AcceptsTheGeneratedIslands) {
    for (size_t size : {8, 30, 120, 1000})
        for (uint64_t seed = 0; seed < 10; ++seed)
            EXPECT_TRUE(touchingAccepted({generate("islands", seed, size)}));
}

// [SECTION] random parts on a small grid, against pairwise triangle tests

namespace {

// Interiors of two counter-clockwise triangles are disjoint exactly when one triangle lies
// on the closed outer side of an edge line of the other.
bool interiorsMeet(const Polygon& p, const Triangle& s, const Triangle& t) {
    auto separated = [&](const Triangle& u, const Triangle& w) {
        for (int k = 0; k < 3; ++k) {
            Point a = p.vertices[u[k]], b = p.vertices[u[(k + 1) % 3]];
            if (orient(a, b, p.vertices[w[0]]) <= 0 && orient(a, b, p.vertices[w[1]]) <= 0 &&
                orient(a, b, p.vertices[w[2]]) <= 0)
                return true;
        }
        return false;
    };
    return !separated(s, t) && !separated(t, s);
}

// A valid one-part polygon with small integer coordinates, so that parts share vertices,
// touch inside edges, run along each other and overlap in every degenerate way.
Polygon randomPart(std::mt19937_64& rng) {
    auto coord = [&](int hi) { return double(rng() % uint64_t(hi + 1)); };
    for (;;) {
        Polygon p;
        switch (rng() % 4) {
            case 0:
            case 1: {  // a triangle, a quadrangle or a pentagon
                Ring ring;
                for (size_t k = 3 + rng() % 3; k > 0; --k) ring.push_back({coord(6), coord(6)});
                p = part(ring);
                break;
            }
            case 2: {
                double x = coord(5), y = coord(5);
                p = part(box(x, y, x + 1 + coord(5 - int(x)), y + 1 + coord(5 - int(y))));
                break;
            }
            default: {  // a box with a hole touching it or not
                double x = coord(2), y = coord(2), w = 3 + coord(1), h = 3 + coord(1);
                double hx = x + 1 + coord(int(w) - 3), hy = y + coord(int(h) - 2);
                p = part(box(x, y, x + w, y + h), {box(hx, hy, hx + 1, hy + 1)});
            }
        }
        Polygon q = p;
        if (validate(q, "random part").ok()) return p;
    }
}

}  // namespace

TEST(CheckerParts, AgreesWithPairwiseTriangleTestsOnRandomParts) {
    std::mt19937_64 rng(20261201);
    size_t overlapping = 0, touching = 0;
    for (int run = 0; run < 3000; ++run) {
        std::vector<Polygon> pieces;
        for (size_t k = 2 + rng() % 3; k > 0; --k) pieces.push_back(randomPart(rng));
        Together t = together(pieces, int(rng() % 4), rng() % 2 == 1);
        std::vector<Index> partOf(t.polygon.vertices.size());
        for (Index k = 0; k < t.polygon.parts.size(); ++k) {
            const flood::Part& pt = t.polygon.parts[k];
            for (Index r = pt.firstRing; r < pt.firstRing + pt.ringCount; ++r)
                for (Index i = 0; i < t.polygon.rings[r].count; ++i)
                    partOf[t.polygon.rings[r].first + i] = k;
        }
        bool overlap = false;
        for (size_t i = 0; i < t.triangles.size() && !overlap; ++i)
            for (size_t j = i + 1; j < t.triangles.size() && !overlap; ++j)
                overlap = partOf[t.triangles[i][0]] != partOf[t.triangles[j][0]] &&
                          interiorsMeet(t.polygon, t.triangles[i], t.triangles[j]);
        CheckResult c = checkTriangulation(t.polygon, t.triangles);
        ASSERT_EQ(c.ok, !overlap) << "run " << run << ": " << c.reason;
        if (overlap) {
            ASSERT_NE(c.reason.find("parts-overlap"), std::string::npos) << c.reason;
        }
        (overlap ? overlapping : touching)++;
    }
    EXPECT_GT(touching, 300u);  // both verdicts are well represented
    EXPECT_GT(overlapping, 300u);
}

// [SECTION] work: O(n log n), also with many parts side by side and on top of each other

namespace {

struct SweepWork {
    double steps, orients;  // per vertex, for the checker alone
};

SweepWork checkerWork(const Together& t) {
    work() = {};
    CheckResult c = checkTriangulation(t.polygon, t.triangles);
    EXPECT_TRUE(c.ok) << c.reason;
    const double n = double(t.polygon.vertices.size());
    return {double(work().checkerSteps) / n, double(work().orientCalls) / n};
}

}  // namespace

TEST(CheckerParts, WorkPerVertexStaysFlat) {
    for (const char* shape : {"row", "stack"}) {
        SweepWork base{};
        for (size_t n : {1000, 10000, 100000}) {
            std::vector<Polygon> pieces;
            for (size_t k = 0; k < n / 8; ++k)
                if (std::string(shape) == "row") {  // squares with a hole, along whole edges
                    pieces.push_back(part(box(3.0 * k, k % 3, 3.0 * k + 3, k % 3 + 3),
                                          {box(3.0 * k + 1, k % 3 + 1, 3.0 * k + 2, k % 3 + 2)}));
                } else {  // long rectangles on top of each other: the sweep holds them all at once
                    pieces.push_back(part(box(k % 7, 2.0 * k, 1000, 2.0 * k + 2)));
                }
            SweepWork w = checkerWork(together(pieces));
            EXPECT_GT(w.steps, 0) << shape;
            if (n == 1000) base = w;
            EXPECT_LE(w.steps, 1.5 * base.steps) << shape << " at " << n;
            EXPECT_LE(w.orients, 2.5 * base.orients) << shape << " at " << n;  // log n comparisons
        }
    }
}

// Islands apart (a line between each and the next): no sweep at all.
TEST(CheckerParts, IslandsApartAreNotSwept) {
    SweepWork w = checkerWork(together({generate("islands", 1, 10000)}));
    EXPECT_EQ(w.steps, 0);
}
