// `--no-exact-check`: the exact check of the output is what the flag gives up, and nothing
// else — the same triangles are written, and a result the check would refuse goes out unproven.
#include <gtest/gtest.h>

#include <string>

#include "test_support.h"

namespace {

using namespace flood::testing;

TEST(CliExactCheck, SkippingTheCheckWritesTheSameTriangles) {
    auto dir = scratch("exact-check");
    const std::string a = (dir / "a.json").string(), b = (dir / "b.json").string();
    const std::string in = sourcePath("polygons/holes.json");
    ASSERT_EQ(runCli("triangulate " + in + " -o " + a).code, 0);
    ASSERT_EQ(runCli("triangulate --no-exact-check " + in + " -o " + b).code, 0);
    EXPECT_EQ(slurp(a), slurp(b));
    std::filesystem::remove_all(dir);
}

TEST(CliExactCheck, WhatTheCheckCatchesGoesUnnoticedWithoutIt) {
    const std::string in = sourcePath("polygons/invalid/checker-rejects.json");
    RunResult checked = runCli("triangulate --no-validate " + in + " -o /dev/null");
    EXPECT_EQ(checked.code, 6) << checked.out;
    RunResult unchecked =
        runCli("triangulate --no-validate --no-exact-check " + in + " -o /dev/null");
    EXPECT_EQ(unchecked.code, 0) << unchecked.out;
    EXPECT_EQ(unchecked.out.find("checker"), std::string::npos) << unchecked.out;
}

}  // namespace
