// The shrinker (flood/tools/shrink.h) on planted failures: a crossing buried in a large valid ring,
// a checker failure planted by the test-only corrupt hook, and a polygon that does not fail.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "flood/check/touches.h"
#include "flood/tools/generate.h"
#include "flood/tools/shrink.h"
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

// [SECTION] the repro read back (issue 26): a repro is what the user reads, not what we hold

namespace {

// Reads `path` and prepares it as `flood shrink` does (the T-junction search, no validation).
bool readForShrink(const std::string& path, Polygon& p) {
    ReadResult r = readPolygonFile(path);
    if (!r.diagnostic.ok()) return false;  // malformed samples: nothing to shrink
    p = std::move(r.polygon);
    findTouches(p);
    return true;
}

// Shrinks `p`, then reads the written repro back as the user will and expects the same failure.
// Returns the repro's text.
std::string expectReproReadsBack(const Polygon& p, const std::string& what, size_t maxTries) {
    ShrinkOptions o;
    o.fork = false;  // the tests' failures are forbidden transitions and checker rejections
    o.maxTries = maxTries;
    ShrinkResult r = shrink(p, o);
    if (r.failure.kind == Failure::Kind::None) return "";
    EXPECT_TRUE(r.reproduces) << what;
    std::string text = reproJson(p, r, {what, "", "", "s.json"});
    Failure back = classifyText(text, o, r.inputValid);
    EXPECT_TRUE(back.sameClass(r.failure))
        << what << ": shrunk to " << failureKindName(r.failure.kind) << ", read back as "
        << failureKindName(back.kind) << " (" << back.message << ")\n"
        << text;
    // The reader keeps every vertex: nothing was repaired on the way back.
    ReadResult read = parsePolygon(text, "repro");
    EXPECT_TRUE(read.warnings.empty()) << what << ": " << read.warnings.front();
    EXPECT_EQ(read.polygon.vertices.size(), r.polygon.vertices.size()) << what;
    return text;
}

}  // namespace

TEST(ShrinkRepro, CrossingFaceReadsBackFailingTheSameWay) {
    // Rounding made two vertices of this face's repro equal; the reader dropped one and the
    // repro triangulated.
    Polygon p;
    ASSERT_TRUE(readForShrink(sourcePath("polygons/tutorial/crossing-face.json"), p));
    std::string text = expectReproReadsBack(p, "crossing-face", 20000);
    EXPECT_NE(text.find("\"reproduce\":\"flood triangulate --no-validate s.json\""),
              std::string::npos)
        << text;
}

TEST(ShrinkRepro, EveryInvalidSampleReadsBackFailingTheSameWay) {
    size_t shrunk = 0;
    for (const std::string& path : filesIn(sourcePath("polygons/invalid"), ".json")) {
        Polygon p;
        if (!readForShrink(path, p)) continue;
        if (!expectReproReadsBack(p, path, 3000).empty()) ++shrunk;
    }
    EXPECT_GE(shrunk, 15u) << "most invalid samples fail unvalidated";
}

TEST(ShrinkRepro, EveryInvalidFamilyReadsBackFailingTheSameWayAtSeveralSizes) {
    for (const std::string& family : invalidFamilyNames())
        for (size_t size : {20, 200, 2000}) {
            Polygon p = generateInvalid(family, 7, size);
            findTouches(p);
            expectReproReadsBack(p, family + " " + std::to_string(size), 600);
        }
}

TEST(ShrinkRepro, RealSizeFaceWithTwoVerticesSwappedReadsBack) {
    // A 20,000-vertex face with two neighbours swapped: a bow-tie buried in a large ring. The
    // shrink is cut short; what it hands back must still reproduce.
    Polygon star = generate("circle-jagged", 3, 20000);
    std::vector<Point> ring(star.vertices.begin(), star.vertices.begin() + star.rings[0].count);
    std::swap(ring[ring.size() / 3], ring[ring.size() / 3 + 1]);
    Polygon p;
    p.addRing(ring, true);
    findTouches(p);
    expectReproReadsBack(p, "swapped", 200);
}

TEST(ShrinkRepro, SaysWhereItCameFrom) {
    Polygon p = buriedCrossing();
    findTouches(p);
    ShrinkOptions o;
    o.fork = false;
    ShrinkResult r = shrink(p, o);
    ASSERT_EQ(r.failure.kind, Failure::Kind::Forbidden);
    ASSERT_EQ(r.origin.size(), r.polygon.vertices.size());
    std::string text = reproJson(p, r, {"star.json", "12", "", "s.json"});
    for (const char* key : {"\"source\":\"star.json\"", "\"feature\":\"12\"", "\"failure\":",
                            "\"reason\":", "\"source_vertices\":[[", "\"source_bbox\":["})
        EXPECT_NE(text.find(key), std::string::npos) << key << "\n" << text;
    // Each remaining vertex names a distinct input vertex, in the input's ring order, and the
    // box is theirs, in the input's coordinates (precision reduction moved the repro's own).
    ASSERT_FALSE(r.origin.empty());
    double box[4] = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < r.origin.size(); ++i) {
        ASSERT_LT(r.origin[i], p.vertices.size());
        if (i) {
            EXPECT_LT(r.origin[i - 1], r.origin[i]);
        }
        const Point q = p.vertices[r.origin[i]];
        box[0] = std::min(box[0], q.x), box[1] = std::min(box[1], q.y);
        box[2] = std::max(box[2], q.x), box[3] = std::max(box[3], q.y);
    }
    nlohmann::json props = nlohmann::json::parse(text)["properties"];
    EXPECT_EQ(props["source_vertices"][0].get<std::vector<Index>>(), r.origin);
    EXPECT_EQ(props["source_bbox"].get<std::vector<double>>(), std::vector<double>(box, box + 4));
}
