// The unvalidated path through the `flood` command (--no-validate): T-junctions found without
// validation (flood/check/touches.h), the exact self-check still run, and `flood verify
// --no-validate` telling which check caught an invalid input (docs/ALGORITHM.md §7).
#include <gtest/gtest.h>

#include "test_support.h"

using namespace flood::testing;

// These exited 5 or 2 before: the machine only learnt of T-junctions from validation, and
// verify had no --no-validate.
TEST(NoValidate, TJunctionPolygonsTriangulate) {
    const std::string f = sourcePath("polygons/t-junction.json");
    for (const char* cmd : {"triangulate --no-validate", "trace --no-validate -o /dev/null",
                            "transcript --no-validate", "verify --no-validate"}) {
        RunResult r = runCli(std::string(cmd) + " " + f);
        EXPECT_EQ(r.code, 0) << cmd << "\n" << r.out;
    }
    RunResult v = runCli("verify --no-validate " + f);
    EXPECT_NE(v.out.find("caught by nothing"), std::string::npos) << v.out;
}

TEST(NoValidate, VerifySaysWhatCaughtIt) {
    RunResult r =
        runCli("verify --no-validate " + sourcePath("polygons/invalid/self-intersection.json"));
    EXPECT_EQ(r.code, 7) << r.out;
    EXPECT_NE(r.out.find("verify: FAILED (caught by: polygon)"), std::string::npos) << r.out;
    RunResult o =
        runCli("verify --no-validate " + sourcePath("polygons/invalid/parts-overlapping.json"));
    EXPECT_EQ(o.code, 7) << o.out;
    EXPECT_NE(o.out.find("verify: FAILED (caught by: complement)"), std::string::npos) << o.out;
}

// The self-check after flooding runs on the unvalidated path and says validation was skipped.
TEST(NoValidate, TheSelfCheckRunsAndSaysSo) {
    RunResult r =
        runCli("triangulate --no-validate " + sourcePath("polygons/invalid/checker-rejects.json"));
    EXPECT_EQ(r.code, 6) << r.out;
    EXPECT_NE(r.out.find("validation was skipped; the check of the output caught it"),
              std::string::npos)
        << r.out;
}

// Overlapping parts are flooded apart, so only the exact checker can see them.
TEST(NoValidate, OverlappingPartsAreRefused) {
    for (const char* cmd : {"triangulate --no-validate", "trace --no-validate -o /dev/null",
                            "transcript --no-validate"}) {
        RunResult r =
            runCli(std::string(cmd) + " " + sourcePath("polygons/invalid/parts-overlapping.json"));
        EXPECT_NE(r.code, 0) << cmd << "\n" << r.out;
    }
}

// The conjecture's tools through the command line: an invalid family, and shrinking a slip.
TEST(NoValidate, GenerateInvalidAndShrinkASlip) {
    const std::string g = ::testing::TempDir() + "touch-cycle.json",
                      s = ::testing::TempDir() + "slip.json";
    RunResult r = runCli("generate touch-cycle 40 --seed 2 -o " + g);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(runCli("verify " + g).code, 4);
    EXPECT_EQ(runCli("verify --no-validate " + g).code, 0);
    RunResult k = runCli("shrink --slipping " + g + " -o " + s);
    EXPECT_EQ(k.code, 0) << k.out;
    EXPECT_NE(k.out.find("invalid, yet the unvalidated verification passes it"), std::string::npos)
        << k.out;
    EXPECT_EQ(runCli("verify --no-validate " + s).code, 0);
    RunResult n = runCli("shrink --slipping " +
                         sourcePath("polygons/invalid/self-intersection.json") + " -o " + s);
    EXPECT_EQ(n.code, 2) << n.out;
    EXPECT_NE(n.out.find("the unvalidated verification catches it"), std::string::npos) << n.out;
}
