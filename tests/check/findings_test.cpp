// validateAll() (core/io.h): every finding of a face, not only the first — k separate problems
// give k findings, the first is validate()'s verdict, and a valid polygon has none.
#include <gtest/gtest.h>

#include <set>

#include "flood/io/io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;

namespace {

// A 100 x 100 square with `k` holes, each a bow-tie (one self-crossing), apart from each other.
Polygon bowTieHoles(int k) {
    Polygon p;
    p.addRing({{0, 0}, {100, 0}, {100, 100}, {0, 100}}, true);
    for (int i = 0; i < k; ++i) {
        double x = 2 + 3 * (i % 30), y = 2 + 3 * (i / 30);
        p.addRing({{x, y}, {x + 1, y + 1}, {x + 1, y}, {x, y + 1}}, false);
    }
    return p;
}

// The same square with `k` triangular holes outside it (check 6), to the right.
Polygon holesOutside(int k) {
    Polygon p;
    p.addRing({{0, 0}, {100, 0}, {100, 100}, {0, 100}}, true);
    for (int i = 0; i < k; ++i) {
        double y = 3 * i;
        p.addRing({{200, y}, {201, y}, {200, y + 1}}, false);
    }
    return p;
}

}  // namespace

TEST(Findings, KSeparateCrossingsGiveKFindings) {
    for (int k : {1, 2, 5, 40}) {
        Polygon p = bowTieHoles(k);
        Findings f = validateAll(p, "p");
        ASSERT_EQ(f.list.size(), size_t(k)) << k;
        EXPECT_EQ(f.omitted, 0u);
        EXPECT_TRUE(f.complete);
        for (const Diagnostic& d : f.list) {
            EXPECT_EQ(d.status, Status::Invalid);
            EXPECT_NE(d.message.find("crosses edge"), std::string::npos) << d.message;
            EXPECT_EQ(d.culprits.edges.size(), 2u) << d.message;
        }
        // Each finding names a different hole.
        std::set<uint32_t> rings;
        for (const Diagnostic& d : f.list) rings.insert(d.culprits.rings.at(0));
        EXPECT_EQ(rings.size(), size_t(k));
    }
}

TEST(Findings, TheFirstIsValidatesVerdict) {
    Polygon p = bowTieHoles(7);
    Polygon q = p;
    Diagnostic d = validate(q, "p");
    Findings f = validateAll(p, "p");
    ASSERT_FALSE(f.list.empty());
    EXPECT_EQ(f.list[0].message, d.message);
}

TEST(Findings, MaxFindingsBoundsTheListAndCountsTheRest) {
    Findings f = validateAll(bowTieHoles(40), "p", 10);
    EXPECT_EQ(f.list.size(), 10u);
    EXPECT_EQ(f.omitted, 30u);
}

TEST(Findings, LaterChecksGoOnPastEachFinding) {
    Findings outside = validateAll(holesOutside(6), "p");
    ASSERT_EQ(outside.list.size(), 6u);
    for (const Diagnostic& d : outside.list)
        EXPECT_NE(d.message.find("lies outside its outer ring"), std::string::npos) << d.message;
    // Repeated points: each one a finding (check 2).
    Polygon rep;
    rep.addRing({{0, 0}, {1, 0}, {1, 0}, {2, 0}, {2, 2}, {2, 2}, {0, 2}, {0, 2}}, true);
    EXPECT_EQ(validateAll(rep, "rep").list.size(), 3u);
}

// On many generated polygons, valid and invalid: no findings exactly when validate() accepts,
// and the first finding is its diagnostic.
TEST(Findings, AgreeWithValidateOnGeneratedPolygons) {
    size_t invalid = 0, valid = 0;
    for (uint64_t seed = 1; seed <= 6; ++seed) {
        for (const std::string& family : familyNames())
            for (size_t size : {30, 300}) {
                Polygon p = generate(family, seed, size);
                Polygon q = p;
                ASSERT_TRUE(validate(q, family).ok());
                EXPECT_TRUE(validateAll(p, family).list.empty()) << family;
                ++valid;
            }
        for (const std::string& family : invalidFamilyNames())
            for (size_t size : {30, 300}) {
                Polygon p = generateInvalid(family, seed, size);
                Polygon q = p;
                Diagnostic d = validate(q, family);
                Findings f = validateAll(p, family);
                ASSERT_EQ(f.list.empty(), d.ok()) << family;
                if (!d.ok()) {
                    EXPECT_EQ(f.list[0].message, d.message) << family;
                    ++invalid;
                }
            }
    }
    EXPECT_GT(invalid, 50u);
    EXPECT_GT(valid, 100u);
}

// Every sample, valid or not (an empty ring once crashed the collection).
TEST(Findings, AgreeWithValidateOnEverySample) {
    size_t samples = 0;
    for (const char* dir :
         {"polygons", "polygons/invalid", "polygons/tutorial", "polygons/regress"})
        for (const std::string& path :
             flood::testing::filesIn(flood::testing::sourcePath(dir), ".json")) {
            ReadResult r = readPolygonFile(path);
            if (!r.diagnostic.ok()) continue;
            Polygon q = r.polygon;
            Diagnostic d = validate(q, path);
            Findings f = validateAll(r.polygon, path);
            ASSERT_EQ(f.list.empty(), d.ok()) << path;
            if (!d.ok()) {
                EXPECT_EQ(f.list[0].message, d.message) << path;
            }
            ++samples;
        }
    EXPECT_GT(samples, 40u);
}
