// validate() tests every pair of edges of a small single ring instead of sweeping
// (core/check/validate_edges.cpp, pairsClear), and sweeps first with the minimal tests: it must
// give the full sweep's verdict, message, culprits and splits on every input — the samples, the
// invalid catalogue, generated polygons and mutations of them that repeat points, put vertices
// on edges, cross, overlap and fold back. And its cost, counted: the sweep's hand-over of an
// edge's place, the box test before orient().
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "check/validate_paths.h"
#include "flood/geometry/work.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// Both paths on copies of p; everything they report must agree.
void expectSamePaths(const Polygon& p, const std::string& what) {
    Polygon a = p, b = p;
    Diagnostic da = validate(a, "poly"), db = validateBySweep(b, "poly");
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
