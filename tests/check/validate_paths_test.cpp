// validate() tests every pair of edges of a small single ring instead of sweeping
// (core/check/validate_edges.cpp, pairsClear), sweeps first with the minimal tests, and
// validates a MultiPolygon group by group (validate_groups.cpp): it must give the full
// sweep's verdict, message, culprits, splits and nesting on every input — the samples, the
// invalid catalogue, generated polygons and mutations of them that repeat points, put vertices
// on edges, cross, overlap and fold back. And its cost, counted: the sweep's hand-over of an
// edge's place, the box test before orient().
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "check/validate_paths.h"
#include "flood/geometry/work.h"
#include "flood/tools/generate.h"
#include "geometry/boxes_apart.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// Both paths on copies of p; everything they report must agree.
// How often validate() gave its groups to a runner (expectSamePaths).
size_t runnerCalls = 0;

void expectSamePaths(const Polygon& p, const std::string& what) {
    Polygon a = p, b = p, c = p;
    std::vector<Index> nestA, nestB;
    Diagnostic da = validate(a, "poly"), db = validateBySweep(b, "poly", &nestB);
    EXPECT_EQ(validateNesting(c, "poly", nestA).message, da.message) << what;
    EXPECT_EQ(nestA, nestB) << what;
    // Groups validated as tasks, in any order and on two threads, give the same.
    Backwards back;
    for (const TaskRunner& run : {back.runner(), TaskRunner(twoThreads)}) {
        Polygon d = p;
        EXPECT_EQ(validate(d, "poly", run).message, da.message) << what;
        EXPECT_EQ(d.pointsDistinct, a.pointsDistinct) << what;
        EXPECT_EQ(d.splits.size(), a.splits.size()) << what;
        for (size_t i = 0; i < std::min(d.splits.size(), a.splits.size()); ++i) {
            EXPECT_EQ(d.splits[i].edge, a.splits[i].edge) << what;
            EXPECT_EQ(d.splits[i].vertex, a.splits[i].vertex) << what;
        }
    }
    runnerCalls += back.calls;
    ASSERT_EQ(da.status, db.status) << what << ": " << da.message << " / " << db.message;
    EXPECT_EQ(da.message, db.message) << what;
    EXPECT_EQ(da.culprits.vertices, db.culprits.vertices) << what;
    EXPECT_EQ(da.culprits.rings, db.culprits.rings) << what;
    EXPECT_EQ(da.culprits.edges, db.culprits.edges) << what;
    EXPECT_EQ(da.culprits.hasPoint, db.culprits.hasPoint) << what;
    EXPECT_EQ(a.pointsDistinct, b.pointsDistinct) << what;
    ASSERT_EQ(a.splits.size(), b.splits.size()) << what;
    for (size_t i = 0; i < a.splits.size(); ++i) {
        EXPECT_EQ(a.splits[i].edge, b.splits[i].edge) << what;
        EXPECT_EQ(a.splits[i].vertex, b.splits[i].vertex) << what;
    }
}

// A small deterministic generator (splitmix64), so the mutations are the same every run.
struct Rng {
    uint64_t s;
    uint64_t next() {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    size_t below(size_t n) { return size_t(next() % n); }
};

// The single ring of p with one vertex moved: onto another vertex, onto the middle of another
// edge, onto the previous vertex (a zero-length edge), or back along its edge (a spike); or two
// vertices swapped (usually a crossing).
Polygon mutate(const Polygon& p, Rng& rng) {
    Polygon q = p;
    std::vector<Point>& V = q.vertices;
    size_t n = V.size(), i = rng.below(n), j = rng.below(n);
    Point& v = V[i];
    switch (rng.below(5)) {
        case 0: v = V[j]; break;
        case 1: {
            Point a = V[j], b = V[(j + 1) % n];
            v = {(a.x + b.x) / 2, (a.y + b.y) / 2};
            break;
        }
        case 2: v = V[(i + n - 1) % n]; break;
        case 3: {
            Point a = V[(i + n - 1) % n];
            v = {a.x + (a.x - v.x) / 2, a.y + (a.y - v.y) / 2};  // past the previous vertex
            break;
        }
        default: std::swap(v, V[j]);
    }
    return q;
}

// An axis-aligned staircase ring of 2k + 2 vertices: many exactly collinear triples.
Polygon staircase(size_t k) {
    std::vector<Point> ring{{0, 0}};
    for (size_t i = 0; i < k; ++i) {
        ring.push_back({double(i + 1), double(i)});
        ring.push_back({double(i + 1), double(i + 1)});
    }
    ring.push_back({0, double(k)});
    Polygon p;
    p.addRing(ring, true);
    return p;
}

}  // namespace

TEST(ValidatePaths, SamplesAndInvalidCatalogueAgree) {
    size_t files = 0;
    for (const std::string dir : {"polygons", "polygons/invalid"})
        for (const std::string ext : {".json", ".wkt"})
            for (const std::string& path : filesIn(sourcePath(dir), ext)) {
                ReadResult rr = readPolygonFile(path);
                if (!rr.diagnostic.ok()) continue;  // unreadable: validation never sees it
                expectSamePaths(rr.polygon, path);
                ++files;
            }
    EXPECT_GT(files, 20u);
}

TEST(ValidatePaths, GeneratedAndMutatedRingsAgree) {
    Rng rng{13};
    size_t single = 0, invalid = 0;
    for (const std::string& family : familyNames())
        for (size_t size : {4, 8, 15, 30, 60, 96, 120})
            for (uint64_t seed = 1; seed <= 3; ++seed) {
                Polygon p = generate(family, seed, size);
                expectSamePaths(p, family + " " + std::to_string(size));
                if (p.rings.size() != 1) continue;
                ++single;
                for (int m = 0; m < 12; ++m) {
                    Polygon q = mutate(p, rng);
                    invalid += !validateBySweep(q, "q").ok();
                    expectSamePaths(
                        q, family + " " + std::to_string(size) + " mutation " + std::to_string(m));
                }
            }
    for (size_t k : {2, 5, 20, 40}) {
        Polygon p = staircase(k);
        expectSamePaths(p, "staircase");
        for (int m = 0; m < 20; ++m) expectSamePaths(mutate(p, rng), "staircase mutation");
    }
    EXPECT_GT(single, 30u);  // the shortcut was exercised, on valid rings and on invalid ones
    EXPECT_GT(invalid, 100u);
}

// Scratch is reused between calls on a thread: a polygon with touches, an invalid one, then a
// plain one must each get their own answer.
TEST(ValidatePaths, ReusedScratchForgetsTheLastPolygon) {
    Polygon touching;  // a hole touching its outer ring at a vertex and inside an edge
    touching.addRing({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, true);
    touching.addRing({{5, 0}, {7, 3}, {3, 3}}, false);
    Polygon crossing;
    crossing.addRing({{0, 0}, {4, 4}, {4, 0}, {0, 4}}, true);
    Polygon plain = generate("star", 1, 40);
    for (int round = 0; round < 2; ++round) {
        Polygon t = touching, c = crossing, s = plain;
        ASSERT_TRUE(validate(t, "t").ok());
        EXPECT_EQ(t.splits.size(), 1u);
        EXPECT_FALSE(t.pointsDistinct);
        EXPECT_NE(validate(c, "c").message.find("crosses"), std::string::npos);
        ASSERT_TRUE(validate(s, "s").ok());
        EXPECT_TRUE(s.splits.empty());
        EXPECT_TRUE(s.pointsDistinct);
    }
}

// Work, counted: a sweep of a staircase (axis-parallel edges, where orient()'s filter cannot
// decide collinear triples) and of a polygon with many holes (a wide sweep line, where each
// passing vertex used to search the tree for its next edge). Before the box test, the axis
// shortcut and the hand-over: 9.0 and 18.4 exact orientation tests per vertex (now 1.0, 2.1).
TEST(ValidatePaths, SweepMakesFewOrientTestsPerVertex) {
    for (const char* family : {"staircase", "circle-holes"}) {
        Polygon p = std::string(family) == "staircase" ? staircase(5000)
                                                       : generate("circle-holes", 1, 20000);
        work() = {};
        ASSERT_TRUE(validateBySweep(p, family).ok());
        double perVertex = double(work().orientCalls) / double(p.vertices.size());
        EXPECT_LT(perVertex, 6.0) << family;
    }
}

// Every family of the generator: validation's work (orientation tests plus validatorSteps) per
// vertex at most 1.5 log2 n (at 3·10^4). Before the changes above it was up to 2.7 log2 n
// (t-junctions; ortho-spiral, collinear and touching-holes above 2 too); before the minimal
// sweep at most 1.8 (circle-jagged), now at most 0.87 on every family but touching-holes (1.07).
TEST(ValidatePaths, EveryFamilyWorkPerVertexWithinOneAndAHalfLogN) {
    for (const std::string& family : familyNames()) {
        Polygon p = generate(family, 7, 30000);
        work() = {};
        ASSERT_TRUE(validate(p, family).ok()) << family;
        double n = double(p.vertices.size());
        double perVertex = double(work().orientCalls + work().validatorSteps) / n;
        EXPECT_LE(perVertex, 1.5 * std::log2(n)) << family;
    }
}

// validate() sweeps first with the minimal tests (new neighbours only), and runs the full sweep
// when that finds a problem or a T-junction: the full sweep's answer on large polygons of many
// rings too — valid ones, each invalid family, and mutations.
TEST(ValidatePaths, MinimalSweepGivesTheFullSweepsAnswer) {
    Rng rng{29};
    size_t invalid = 0;
    for (size_t size : {300, 3000})
        for (uint64_t seed = 1; seed <= 2; ++seed) {
            for (const std::string& family : familyNames()) {
                Polygon p = generate(family, seed, size);
                expectSamePaths(p, family + " " + std::to_string(size));
                for (int m = 0; m < 3; ++m) {
                    Polygon q = mutate(p, rng);
                    invalid += !validateBySweep(q, "q").ok();
                    expectSamePaths(
                        q, family + " " + std::to_string(size) + " mutation " + std::to_string(m));
                }
            }
            for (const std::string& family : invalidFamilyNames()) {
                Polygon p = generateInvalid(family, seed, size);
                ASSERT_FALSE(validateBySweep(p, "p").ok()) << family;
                expectSamePaths(p, family + " " + std::to_string(size));
            }
        }
    EXPECT_GT(invalid, 100u);
}

// The minimal sweep's work, counted: no hand-over comparisons, two pair tests where the
// boundary passes on (the full sweep makes five), and beside each other the two edges that
// start at a vertex. Where no problem is found, validate() does less than half the full
// sweep's work on these families.
TEST(ValidatePaths, MinimalSweepHalvesTheWork) {
    for (const char* family : {"circle-holes", "spiral", "circle-smooth", "comb", "star"}) {
        Polygon p = generate(family, 3, 20000);
        work() = {};
        ASSERT_TRUE(validateBySweep(p, family).ok());
        uint64_t full = work().orientCalls + work().validatorSteps;
        work() = {};
        ASSERT_TRUE(validate(p, family).ok());
        uint64_t minimal = work().orientCalls + work().validatorSteps;
        const double n = double(p.vertices.size());
        std::cout << "[ WORK ] " << family << ": minimal " << double(minimal) / n << ", full "
                  << double(full) / n << " per vertex\n";
        EXPECT_LT(2 * minimal, full) << family;
    }
}

// MultiPolygons whose parts lie apart, side by side, in grids, overlapping, touching along a
// line, one inside another: validate() takes each group of parts apart alone
// (validate_groups.cpp) and must still give the whole sweep's answer — on valid layouts, on
// overlapping ones, and on mutations that move a vertex of one part onto another part or
// swap vertices within a part.
namespace {

Box boxOf(const Polygon& p) {
    Box b;
    for (Point v : p.vertices) b.add(v);
    return b;
}

size_t groupsOf(const Polygon& p) {
    std::vector<Box> boxes(p.parts.size());
    for (Index k = 0; k < p.parts.size(); ++k)
        for (Index r = p.parts[k].firstRing; r < p.parts[k].firstRing + p.parts[k].ringCount; ++r)
            for (Index v = p.rings[r].first; v < p.rings[r].first + p.rings[r].count; ++v)
                boxes[k].add(p.vertices[v]);
    size_t count = 0;
    groupsApart(boxes, count);
    return count;
}

}  // namespace

TEST(ValidatePaths, PartsApartGiveTheWholeSweepsAnswer) {
    Rng rng{41};
    const std::vector<std::string> families{"star",      "comb-rect",      "circle-holes",
                                            "staircase", "touching-holes", "t-junctions",
                                            "steiner",   "islands"};
    size_t grouped = 0, invalid = 0, valid = 0;
    for (int round = 0; round < 60; ++round) {
        const size_t count = 2 + rng.below(7);
        std::vector<Polygon> pieces;
        double width = 0, height = 0;
        for (size_t k = 0; k < count; ++k) {
            pieces.push_back(generate(families[rng.below(families.size())], rng.next() % 100 + 1,
                                      12 + rng.below(40)));
            Box b = boxOf(pieces.back());
            for (Point& v : pieces.back().vertices) v = {v.x - b.x0, v.y - b.y0};
            width = std::max(width, b.x1 - b.x0), height = std::max(height, b.y1 - b.y0);
        }
        // A step of a whole box keeps the pieces apart; exactly the box makes them touch along
        // a line; less makes them overlap; 0.25 puts a piece over the first one's corner.
        const double steps[] = {width + 1, width, width * 0.5, width * 0.25};
        const double step = steps[rng.below(4)];
        const int style = int(rng.below(3));  // a row, a grid, or scattered over the first piece
        std::vector<Point> offsets;
        for (size_t k = 0; k < count; ++k) {
            if (style == 0) offsets.push_back({double(k) * step, 0});
            else if (style == 1)
                offsets.push_back({double(k % 3) * step, double(k / 3) * (height + 1)});
            else offsets.push_back({double(rng.below(4)) * step, double(rng.below(4)) * step});
        }
        Polygon p = layout(pieces, offsets);
        grouped += groupsOf(p) >= 2 && p.vertices.size() >= 64;
        const std::string what = "layout " + std::to_string(round);
        (validateBySweep(p, "p").ok() ? valid : invalid)++;
        expectSamePaths(p, what);
        for (int m = 0; m < 6; ++m) {
            Polygon q = p;
            std::vector<Point>& V = q.vertices;
            const size_t i = rng.below(V.size()), j = rng.below(V.size());
            if (m % 3 == 0) V[i] = V[j];  // onto a vertex, usually of another part
            else if (m % 3 == 1) {        // onto the middle of an edge
                const Index r = q.ringOf(Index(j)),
                            next = j + 1 == q.rings[r].first + q.rings[r].count ? q.rings[r].first
                                                                                : Index(j + 1);
                V[i] = {(V[j].x + V[next].x) / 2, (V[j].y + V[next].y) / 2};
            } else std::swap(V[i], V[j]);
            invalid += !validateBySweep(q, "q").ok();
            expectSamePaths(q, what + " mutation " + std::to_string(m));
        }
    }
    // Groups interleaved in part order, each with T-junctions: parts 0 and 2 meet at a corner,
    // part 1 lies apart. The splits are still in edge order.
    Polygon t = generate("t-junctions", 1, 40);
    const Box b = boxOf(t);
    const double w = b.x1 - b.x0, h = b.y1 - b.y0;
    Polygon corners = layout({t, t, t}, {{0, 0}, {10 * w, 0}, {w, h}});
    ASSERT_EQ(groupsOf(corners), 2u);
    ASSERT_TRUE(validateBySweep(corners, "p").ok());
    EXPECT_GT(corners.splits.size(), 3u);
    expectSamePaths(corners, "interleaved groups");
    EXPECT_GT(grouped, 20u);      // the group path was taken, on valid and on invalid layouts
    EXPECT_GT(runnerCalls, 20u);  // and its groups given to the runner
    EXPECT_GT(valid, 10u);
    EXPECT_GT(invalid, 100u);
}

// Work, counted: validating many islands side by side grows like n, group by group, where the
// whole sweep keeps every island's edges in one tree (log n per step).
TEST(ValidatePaths, IslandsApartCostTheSamePerVertexAtEverySize) {
    std::vector<double> perVertex;
    for (size_t size : {1000, 100000}) {
        Polygon p = generate("islands", 1, size);
        work() = {};
        ASSERT_TRUE(validate(p, "islands").ok());
        perVertex.push_back(double(work().orientCalls + work().validatorSteps) /
                            double(p.vertices.size()));
        work() = {};
        Polygon q = p;
        ASSERT_TRUE(validateBySweep(q, "islands").ok());
        std::cout << "[ WORK ] islands/" << size << ": " << perVertex.back()
                  << " per vertex by groups, "
                  << double(work().orientCalls + work().validatorSteps) / double(p.vertices.size())
                  << " whole\n";
    }
    EXPECT_LE(perVertex[1], perVertex[0] * 1.02);
}
