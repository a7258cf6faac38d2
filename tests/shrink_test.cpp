// The shrinker (core/shrink.h) on planted failures: a crossing buried in a large valid ring,
// a checker failure planted by the test-only corrupt hook, and a polygon that does not fail.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "generate.h"
#include "shrink.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// A 500-vertex valid star with one vertex moved across the ring (a self-intersection).
Polygon buriedCrossing() {
    Polygon star = generate("star", 5, 500);
    EXPECT_TRUE(validate(star, "star").ok());
    Polygon p;
    std::vector<Point> ring(star.vertices.begin(), star.vertices.begin() + star.rings[0].count);
    Point& v = ring[ring.size() / 2];
    v = {-v.x * 3, -v.y * 3};  // through the centre and out the far side
    p.addRing(ring, true);
    return p;
}

}  // namespace

TEST(Shrink, ForbiddenTransitionShrinksToASmallPolygonWithTheSameReason) {
    Polygon p = buriedCrossing();
    ASSERT_GE(p.vertices.size(), 400u);
    EXPECT_FALSE(validate(p, "p").ok());
    ShrinkOptions o;
    Failure original = classify(p, o);
    ASSERT_EQ(original.kind, Failure::Kind::Forbidden) << original.message;
    ShrinkResult r = shrink(p, o);
    EXPECT_FALSE(r.inputValid);
    EXPECT_TRUE(r.failure.sameClass(original)) << r.failure.message;
    EXPECT_LE(r.polygon.vertices.size(), 12u);
    EXPECT_EQ(r.polygon.rings.size(), 1u);
    // The written file reads back to a polygon that fails the same way.
    std::ostringstream os;
    writePolygonJson(os, r.polygon);
    ReadResult back = parsePolygon(os.str(), "shrunk");
    ASSERT_TRUE(back.diagnostic.ok()) << back.diagnostic.message << "\n" << os.str();
    EXPECT_TRUE(classify(back.polygon, o).sameClass(original)) << os.str();
}

TEST(Shrink, PlantedCheckerFailureStaysValidWhileShrinking) {
    Polygon p = generate("circle-holes", 3, 300);
    ASSERT_TRUE(validate(p, "p").ok());
    ShrinkOptions o;
    // Plant: flip the first triangle (the checker then rejects its orientation).
    o.corrupt = [](std::vector<Triangle>& t) {
        if (!t.empty()) std::swap(t[0][1], t[0][2]);
    };
    Failure original = classify(p, o);
    ASSERT_EQ(original.kind, Failure::Kind::CheckerRejects);
    ShrinkResult r = shrink(p, o);
    EXPECT_TRUE(r.inputValid);
    EXPECT_EQ(r.failure.kind, Failure::Kind::CheckerRejects);
    EXPECT_TRUE(validate(r.polygon, "r").ok()) << "a valid input must shrink to a valid polygon";
    EXPECT_LT(r.polygon.vertices.size(), p.vertices.size() / 10);
    EXPECT_EQ(r.polygon.rings.size(), 1u) << "holes are not needed for this failure";
    // Without the plant the shrunk polygon triangulates exactly: the failure was the plant's.
    expectTriangulates(r.polygon, "shrunk");
}

TEST(Shrink, ACrashInTheChildIsAFailureClass) {
    Polygon p = generate("star", 1, 40);
    ShrinkOptions o;
    o.corrupt = [](std::vector<Triangle>&) { std::abort(); };
    Failure f = classify(p, o);
    EXPECT_EQ(f.kind, Failure::Kind::Crash) << f.message;
    ShrinkResult r = shrink(p, o);
    EXPECT_EQ(r.failure.kind, Failure::Kind::Crash);
    EXPECT_EQ(r.polygon.vertices.size(), 3u);  // every polygon "crashes": one triangle is left
}

TEST(Shrink, APassingPolygonIsNotShrunk) {
    Polygon p = generate("comb", 2, 60);
    ShrinkResult r = shrink(p, {});
    EXPECT_EQ(r.failure.kind, Failure::Kind::None);
    EXPECT_EQ(r.polygon.vertices.size(), p.vertices.size());
}

TEST(Shrink, PrecisionIsReduced) {
    // A bow-tie with awkward coordinates: the shrunk one has small-integer coordinates.
    Polygon p;
    p.addRing({{0.1234567, 0.7654321}, {10.987654, 10.123456}, {10.5555, 0.3333}, {0.2222, 12.456}},
              true);
    ShrinkOptions o;
    ASSERT_EQ(classify(p, o).kind, Failure::Kind::Forbidden);
    ShrinkResult r = shrink(p, o);
    for (Point q : r.polygon.vertices) {
        EXPECT_EQ(q.x, std::nearbyint(q.x));
        EXPECT_EQ(q.y, std::nearbyint(q.y));
    }
}
