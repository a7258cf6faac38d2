// The paper's open conjecture (§6), as measured by scripts/conjecture.sh: the invalid families
// are invalid, and what the unvalidated verification sees of each kind of defect.
#include <gtest/gtest.h>

#include "flood/check/touches.h"
#include "flood/check/verify.h"
#include "flood/tools/generate.h"
#include "flood/tools/shrink.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

Verification unvalidated(Polygon p) {
    p.splits.clear();
    findTouches(p);
    return verify(p);
}

}  // namespace

TEST(Conjecture, EveryInvalidFamilyIsRefusedByValidate) {
    for (const std::string& family : invalidFamilyNames())
        for (uint64_t seed : {1, 2, 3, 4})
            for (size_t size : {30, 300, 3000}) {
                Polygon p = generateInvalid(family, seed, size);
                EXPECT_FALSE(validate(p, family).ok())
                    << family << " " << size << " --seed " << seed;
                EXPECT_FALSE(invalidFamilyDescription(family).empty());
            }
}

TEST(Conjecture, InvalidFamiliesAreDeterministic) {
    for (const std::string& family : invalidFamilyNames()) {
        Polygon a = generateInvalid(family, 5, 100), b = generateInvalid(family, 5, 100);
        ASSERT_EQ(a.vertices.size(), b.vertices.size()) << family;
        for (size_t i = 0; i < a.vertices.size(); ++i)
            EXPECT_EQ(a.vertices[i], b.vertices[i]) << family;
    }
}

// What catches each kind (docs/ALGORITHM.md §7 explains why).
TEST(Conjecture, WhatCatchesEachKind) {
    EXPECT_EQ(unvalidated(generateInvalid("bowtie-star", 1, 300)).caught(), Caught::Polygon);
    EXPECT_EQ(unvalidated(generateInvalid("hole-outside", 1, 300)).caught(), Caught::Polygon);
    EXPECT_EQ(unvalidated(generateInvalid("part-inside-part", 1, 300)).caught(),
              Caught::Complement);
    EXPECT_EQ(unvalidated(generateInvalid("self-touching", 1, 300)).caught(), Caught::Checker);
    // The touches cut the interior in two: each piece is a region the machine floods and the
    // checker accepts, and so is the complement. It slips through.
    EXPECT_EQ(unvalidated(generateInvalid("touch-cycle", 1, 300)).caught(), Caught::Nothing);
}

// Random invalid rings on a small lattice: every one is caught (docs/ALGORITHM.md §7).
TEST(Conjecture, RandomLatticeInputsAreAllCaught) {
    for (uint64_t seed = 1; seed <= 1000; ++seed) {
        Polygon p = generateInvalid("random-lattice", seed, 20);
        EXPECT_NE(unvalidated(p).caught(), Caught::Nothing) << "seed " << seed;
    }
}

// Every shrunk example of docs/ALGORITHM.md's table (polygons/conjecture/*.json, written by
// scripts/conjecture.sh) is invalid and slips through both floods and the checker.
TEST(Conjecture, TheSlippingExamplesSlip) {
    std::vector<std::string> files = filesIn(sourcePath("polygons/conjecture"), ".json");
    EXPECT_GE(files.size(), 3u);
    for (const std::string& f : files) {
        Polygon p = readPolygonFile(f).polygon;
        EXPECT_FALSE(validate(p, f).ok()) << f;
        EXPECT_EQ(unvalidated(p).caught(), Caught::Nothing)
            << f << ": " << unvalidated(p).summary();
    }
}

// The shrinker's slipping mode keeps candidates invalid and slipping.
TEST(Conjecture, ShrinkKeepsTheSlip) {
    ShrinkOptions o;
    o.slipping = true;
    o.fork = false;
    Polygon p = generateInvalid("touch-cycle", 2, 60);
    ShrinkResult r = shrink(p, o);
    ASSERT_EQ(r.failure.kind, Failure::Kind::Slips) << r.failure.message;
    EXPECT_LT(r.polygon.vertices.size(), p.vertices.size());
    Polygon small = r.polygon;
    EXPECT_FALSE(validate(small, "shrunk").ok());
    EXPECT_EQ(unvalidated(r.polygon).caught(), Caught::Nothing);
    // A valid polygon, or one the verification catches, has nothing to shrink.
    EXPECT_EQ(shrink(generate("star", 1, 50), o).failure.kind, Failure::Kind::None);
    EXPECT_EQ(shrink(generateInvalid("bowtie-star", 1, 50), o).failure.kind, Failure::Kind::None);
}
