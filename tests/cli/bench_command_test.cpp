// `flood bench`: the figures a user pays are reported beside the core's alone (issue 31 goal 0).
// Only the report's shape is tested: times are measured by benchmarks, never asserted here.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "test_support.h"

using namespace flood::testing;

namespace {

// The ns/vertex figure of the report line starting with `label`, or -1 when there is none.
double perVertex(const std::string& report, const std::string& label) {
    std::smatch m;
    const std::regex line("(^|\n)" + label + " +([0-9]+) ns +([0-9.]+) ns/vertex");
    return std::regex_search(report, m, line) ? std::stod(m[3]) : -1;
}

TEST(BenchCommand, ReportsValidatedCallsOnWarmAndColdMemory) {
    RunResult r = runCli("bench " + sourcePath("polygons/comb.json") + " --repeat 3");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_GT(perVertex(r.out, "no listener:"), 0) << r.out;
    // validate() + a fresh triangulate(): more work than triangulate() alone, never free.
    EXPECT_GT(perVertex(r.out, "validated, warm memory:"), 0) << r.out;
    EXPECT_GT(perVertex(r.out, "validated, cold memory:"), 0) << r.out;
}

TEST(BenchCommand, StdinIsReadOnceSoTheValidatedLinesAreLeftOut) {
    RunResult r = runShell(std::string(FLOOD_CLI) + " bench - --repeat 3 < " +
                           sourcePath("polygons/comb.json") + " 2>&1");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_GT(perVertex(r.out, "no listener:"), 0) << r.out;
    EXPECT_EQ(perVertex(r.out, "validated, warm memory:"), -1) << r.out;
}

}  // namespace
