// `--no-exact-check`: the exact check of the output is what the flag gives up, and nothing
// else — the same triangles are written, and a result the check would refuse goes out unproven.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

// A file is written while the check runs (cli/main.cpp, checkWhileWriting): a failed check
// must leave no trace of it — an old file as it was, no temporary beside it — and say what the
// check says when the output is written after it (/dev/null is written in place, so after).
TEST(CliExactCheck, AFailedCheckLeavesTheOutputFileAsItWas) {
    auto dir = scratch("exact-check-fails");
    const std::string a = (dir / "a.json").string();
    const std::string in = sourcePath("polygons/invalid/checker-rejects.json");
    std::ofstream(a) << "old";
    RunResult toFile = runCli("triangulate --no-validate " + in + " -o " + a);
    RunResult after = runCli("triangulate --no-validate " + in + " -o /dev/null");
    EXPECT_EQ(toFile.code, 6) << toFile.out;
    EXPECT_EQ(toFile.out, after.out);
    EXPECT_EQ(slurp(a), "old");
    size_t files = 0;
    for (auto it = std::filesystem::directory_iterator(dir); it != decltype(it)(); ++it) ++files;
    EXPECT_EQ(files, 1u) << "a temporary was left beside " << a;
    // A passing check commits the file written beside it.
    ASSERT_EQ(runCli("triangulate " + sourcePath("polygons/holes.json") + " -o " + a).code, 0);
    EXPECT_EQ(slurp(a), runCli("triangulate " + sourcePath("polygons/holes.json")).out);
    std::filesystem::remove_all(dir);
}

}  // namespace
