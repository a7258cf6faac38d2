// -q and -v on every command of `flood` (cli/verbosity.h), through the binary: -q leaves
// errors alone on stderr, -v adds each stage's time and check's line per feature, and stdout is
// the same at every level.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "test_support.h"

using namespace flood::testing;
namespace fs = std::filesystem;

namespace {

struct Outcome {
    int code = -1;
    std::string out, err;
};

Outcome runFlood(const std::string& args) {
    fs::path err = fs::temp_directory_path() / ("flood-verbosity-" + std::to_string(getpid()));
    RunResult r = runShell(std::string(FLOOD_CLI) + " " + args + " 2>" + err.string());
    Outcome run{r.code, r.out, slurp(err)};
    fs::remove(err);
    return run;
}

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// A square with a repeated point (a warning) and a bow-tie (an error), as a dataset and alone.
struct Inputs {
    fs::path dir = scratch("verbosity");
    std::string repeated = (dir / "repeated.json").string();
    std::string bowtie = (dir / "bowtie.json").string();
    std::string dataset = (dir / "two.geojson").string();
    Inputs() {
        std::ofstream(repeated) << "[[[0,0],[4,0],[4,0],[4,4],[0,4]]]";
        std::ofstream(bowtie) << "[[[0,0],[4,2],[4,0],[0,3]]]";
        std::ofstream(dataset) << R"({"type": "FeatureCollection", "features": [
{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,0],[4,4],[0,4],[0,0]]]}},
{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[4,2],[4,0],[0,3],[0,0]]]}}]})";
    }
    ~Inputs() { fs::remove_all(dir); }
};

}  // namespace

TEST(Verbosity, QuietKeepsErrorsOnlyVerboseAddsTheStages) {
    Inputs in;
    Outcome normal = runFlood("triangulate " + in.repeated);
    ASSERT_EQ(normal.code, 0) << normal.err;
    EXPECT_TRUE(has(normal.err, "warning: ")) << normal.err;
    EXPECT_TRUE(has(normal.err, "repeated")) << normal.err;

    Outcome quiet = runFlood("triangulate -q " + in.repeated);
    EXPECT_EQ(quiet.code, 0);
    EXPECT_EQ(quiet.err, "") << "-q: no warning";
    EXPECT_EQ(quiet.out, normal.out) << "stdout is the same";

    Outcome verbose = runFlood("triangulate --verbose " + in.repeated);
    EXPECT_EQ(verbose.code, 0);
    EXPECT_EQ(verbose.out, normal.out);
    EXPECT_TRUE(has(verbose.err, "warning: ")) << verbose.err;
    for (const char* stage : {"read: ", "validate: ", "flood: 2 triangles, ", "check and write: "})
        EXPECT_TRUE(std::regex_search(
            verbose.err, std::regex(std::string("(^|\n)") + stage + ".*[0-9]\\.[0-9]{3} s\n")))
            << stage << " in:\n"
            << verbose.err;
    EXPECT_FALSE(has(normal.err, "read: ")) << "no detail without -v";

    // Errors stay: -q silences what is not one.
    Outcome refused = runFlood("triangulate -q " + in.bowtie);
    EXPECT_EQ(refused.code, 4);
    EXPECT_TRUE(has(refused.err, "error: invalid polygon: ")) << refused.err;
    Outcome traced = runFlood("trace -q " + in.bowtie);
    EXPECT_EQ(traced.code, 4);
    EXPECT_TRUE(has(traced.err, "error: ")) << traced.err;
    EXPECT_FALSE(has(traced.err, "note: ")) << "the note flooding it anyway is not an error";
    EXPECT_TRUE(has(runFlood("trace " + in.bowtie).err, "note: "));
}

TEST(Verbosity, CheckQuietAndAFeatureALineWithV) {
    Inputs in;
    Outcome normal = runFlood("check " + in.dataset);
    EXPECT_EQ(normal.code, 4);
    EXPECT_TRUE(has(normal.err, "warning: ")) << normal.err;
    Outcome quiet = runFlood("check -q " + in.dataset);
    EXPECT_EQ(quiet.code, 4);
    EXPECT_EQ(quiet.err, "");
    // Its outputs' summaries are notes too: said without -q, silent under it.
    const std::string layer = (in.dir / "findings.geojson").string();
    Outcome written = runFlood("check " + in.dataset + " --findings " + layer);
    EXPECT_EQ(written.code, 4);
    EXPECT_TRUE(has(written.err, "check: wrote 1 finding to " + layer)) << written.err;
    Outcome writtenQuietly = runFlood("check -q " + in.dataset + " --findings " + layer);
    EXPECT_EQ(writtenQuietly.code, 4);
    EXPECT_EQ(writtenQuietly.err, "");
    EXPECT_TRUE(fs::exists(layer));
    Outcome verbose = runFlood("check -v " + in.dataset);
    EXPECT_EQ(verbose.code, 4);
    EXPECT_TRUE(has(verbose.err, "check: " + in.dataset + ": feature 0: ok, 4 vertices\n"))
        << verbose.err;
    EXPECT_TRUE(has(verbose.err, "check: " + in.dataset + ": feature 1: invalid, 4 vertices\n"))
        << verbose.err;
    // The table on stdout is the same (but for the time in its summary).
    const std::regex time("; [0-9.]+ s\n");
    EXPECT_EQ(std::regex_replace(verbose.out, time, ""), std::regex_replace(normal.out, time, ""));
    EXPECT_EQ(std::regex_replace(quiet.out, time, ""), std::regex_replace(normal.out, time, ""));
}

TEST(Verbosity, EveryCommandTakesBothAndSaysSo) {
    for (const std::string cmd : {"triangulate x", "trace x", "transcript x", "verify x", "bench x",
                                  "generate star 10", "shrink x", "check x"}) {
        Outcome help = runFlood(cmd.substr(0, cmd.find(' ')) + " --help");
        EXPECT_EQ(help.code, 0) << cmd;
        EXPECT_TRUE(has(help.out, "-q,--quiet")) << cmd << ":\n" << help.out;
        EXPECT_TRUE(has(help.out, "-v,--verbose")) << cmd << ":\n" << help.out;
        Outcome both = runFlood(cmd + " -q -v");
        EXPECT_EQ(both.code, 2) << cmd << ": " << both.err;
        EXPECT_TRUE(has(both.err, "excludes")) << cmd << ": " << both.err;
    }
    Outcome top = runFlood("--help");
    EXPECT_TRUE(has(top.out, "Every command takes -q")) << top.out;
    EXPECT_TRUE(has(top.out, "never coloured")) << top.out;
    Outcome gen = runFlood("generate -q star 20");
    EXPECT_EQ(gen.code, 0);
    EXPECT_EQ(gen.err, "");
    EXPECT_TRUE(has(gen.out, "[[[")) << gen.out;
}
