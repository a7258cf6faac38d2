// The `flood` command line: exit codes (flood::Status) and messages for every class of bad
// input in polygons/invalid/, and the happy paths of each command.
#include <gtest/gtest.h>

#include "test_support.h"

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

using namespace flood::testing;

namespace {

RunResult run(const std::string& args) { return runCli(args); }

std::string src(const std::string& rel) { return std::string(FLOOD_SOURCE_DIR) + "/" + rel; }

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(Cli, InvalidInputsGiveTheirExitCodeAndMessage) {
    struct Case {
        const char* file;
        int code;
        const char* message;
    } cases[] = {
        {"malformed-json.json", 3, "malformed-json.json:2:3: JSON syntax error"},
        {"bad-structure.json", 3, "bad-structure.json: polygon 0 ring 0 vertex 2: coordinate is not a pair"},
        {"deep-nesting.json", 3, "deep-nesting.json:1:65: JSON nested deeper than 64"},
        {"nan.wkt", 4, "nan.wkt: ring 0 vertex 2 (10, nan): coordinate is not a finite number"},
        {"too-few-points.json", 4, "too-few-points.json: ring 0 vertex 0 (0, 0): ring has 2 distinct points"},
        {"zero-area.json", 4, "zero-area.json: ring 0 vertex 0 (0, 0): ring has zero area"},
        {"self-intersection.json", 4, "self-intersection.json: ring 0 vertex 0 (0, 0): edge ring 0 edge 0-1 (0, 0)-(10, 10) crosses"},
        {"hole-outside.json", 4, "hole-outside.json: ring 1 vertex 0 (20, 20): hole (ring 1) lies outside its outer ring"},
        {"holes-overlapping.json", 4, "holes-overlapping.json: ring 2 vertex 0 (3, 3): hole (ring 2) lies inside another hole (ring 1)"},
        {"hole-crossing-outer.json", 4, "hole-crossing-outer.json: ring 0 vertex 1 (10, 0): edge ring 0 edge 1-2 (10, 0)-(10, 10) crosses edge ring 1 edge 0-1"},
    };
    for (const Case& c : cases) {
        for (const char* cmd : {"triangulate", "trace", "transcript", "verify"}) {
            RunResult r = run(std::string(cmd) + " " + src(std::string("polygons/invalid/") + c.file));
            EXPECT_EQ(r.code, c.code) << cmd << " " << c.file << ": " << r.out;
            EXPECT_TRUE(has(r.out, c.message)) << cmd << " " << c.file << ": " << r.out;
            EXPECT_FALSE(has(r.out, "\"triangles\"")) << "no output for invalid input: " << c.file;
        }
    }
}

TEST(Cli, TriangulateFormatsAndStdin) {
    RunResult j = run("triangulate " + src("polygons/hole.json"));
    EXPECT_EQ(j.code, 0) << j.out;
    EXPECT_TRUE(has(j.out, "\"triangles\": [[")) << j.out;
    RunResult s = run("triangulate --format svg " + src("polygons/hole.json"));
    EXPECT_EQ(s.code, 0);
    EXPECT_TRUE(has(s.out, "<svg"));
    RunResult o = run("triangulate --format obj - < " + src("polygons/hole.json"));
    EXPECT_EQ(o.code, 0) << o.out;
    EXPECT_TRUE(has(o.out, "\nf ")) << o.out;
    std::string cmd = "printf 'POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))' | " +
                      std::string(FLOOD_CLI) + " verify - 2>&1";
    RunResult w;
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    char buf[512];
    for (size_t k; (k = fread(buf, 1, sizeof buf, p)) > 0;) w.out.append(buf, k);
    int st = pclose(p);
    w.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    EXPECT_EQ(w.code, 0) << w.out;
    EXPECT_TRUE(has(w.out, "polygon: 8 triangles, exact triangulation")) << w.out;
    EXPECT_TRUE(has(w.out, "complement: ")) << w.out;
    EXPECT_TRUE(has(w.out, "verify: ok")) << w.out;
}

TEST(Cli, TranscriptTraceBenchAndUsage) {
    RunResult t = run("transcript " + src("polygons/hole.json"));
    EXPECT_EQ(t.code, 0) << t.out;
    EXPECT_TRUE(has(t.out, "Raise")) << t.out;
    EXPECT_TRUE(has(t.out, "; ")) << t.out;
    RunResult n = run("transcript --narrate " + src("polygons/hole.json"));
    EXPECT_EQ(n.code, 0);
    EXPECT_TRUE(has(n.out, "step 0: Start")) << n.out;
    RunResult tr = run("trace " + src("polygons/hole.json"));
    EXPECT_EQ(tr.code, 0);
    EXPECT_TRUE(has(tr.out, "\"format\":\"flood-trace\"")) << tr.out.substr(0, 200);
    RunResult b = run("bench --repeat 3 " + src("polygons/hole.json"));
    EXPECT_EQ(b.code, 0) << b.out;
    EXPECT_TRUE(has(b.out, "ns/vertex")) << b.out;
    RunResult down = run("triangulate --up=-y " + src("polygons/holes.json"));
    EXPECT_EQ(down.code, 0) << down.out;
    EXPECT_EQ(run("").code, 2);
    EXPECT_EQ(run("triangulate").code, 2);
    EXPECT_EQ(run("triangulate --format png x.json").code, 2);
    EXPECT_EQ(run("triangulate --help").code, 0);
    EXPECT_EQ(run("triangulate /nonexistent.json").code, 3);
}
