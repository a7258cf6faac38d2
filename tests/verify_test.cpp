// The paper's verification (§6): a valid polygon and its complement in a box both flood to
// exact triangulations; invalid input fails on at least one side.
#include <gtest/gtest.h>

#include "generate.h"
#include "test_support.h"
#include "verify.h"

using namespace flood;
using namespace flood::testing;

TEST(Verify, ComplementOfValidPolygonsTriangulates) {
    for (const std::string& family : familyNames())
        for (uint64_t seed : {1, 2, 3}) {
            Polygon p = generate(family, seed, 120);
            Verification v = verify(p);
            EXPECT_TRUE(v.ok()) << family << " seed " << seed << "\n" << v.summary();
            Polygon c = complementOf(p);
            size_t pointHoles = 0;
            for (Index r = 0; r < p.rings.size(); ++r) pointHoles += p.rings[r].count == 1;
            EXPECT_EQ(c.parts.size(), 1 + p.holeCount() - pointHoles) << "one island per hole, none per point";
            EXPECT_EQ(c.rings[0].count, 4u);
        }
}

TEST(Verify, SamplePolygonsPass) {
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json")) {
        Verification v = verify(readOrFail(f));
        EXPECT_TRUE(v.ok()) << f << "\n" << v.summary();
    }
}

TEST(Verify, InvalidLoopsFailOnOneSide) {
    Polygon bowtie;  // crosses itself
    bowtie.addRing({{0, 0}, {4, 4}, {4, 0}, {0, 4}}, true);
    EXPECT_FALSE(verify(bowtie).ok());
    Polygon outside;  // hole outside its ring
    outside.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    outside.addRing({{10, 10}, {10, 12}, {12, 12}}, false);
    Verification v = verify(outside);
    EXPECT_FALSE(v.ok());
    EXPECT_NE(v.summary().find("polygon: flooding stopped"), std::string::npos) << v.summary();
}

TEST(Verify, FarFromTheOrigin) {
    Polygon p = generate("grid-holes", 5, 200);  // integer coordinates: the shift is exact
    for (Point& q : p.vertices) q = {q.x + 0x1p40, q.y - 0x1p50};
    ASSERT_TRUE(validate(p, "shifted").ok());
    EXPECT_TRUE(verify(p).ok()) << verify(p).summary();
}
