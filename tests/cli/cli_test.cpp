// The `flood` command line: exit codes (flood::Status) and messages for every class of bad
// input in polygons/invalid/, and the happy paths of each command.
#include <gtest/gtest.h>

#include "test_support.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "flood/log/trace_io.h"
#include "flood/tools/generate.h"
#include "invalid_catalogue.h"

using namespace flood::testing;

namespace {

RunResult run(const std::string& args) { return runCli(args); }

std::string src(const std::string& rel) { return std::string(FLOOD_SOURCE_DIR) + "/" + rel; }

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

}  // namespace

// Every unreadable or invalid example of the catalogue gives the same code and message from
// each command that reads a polygon.
TEST(Cli, InvalidInputsGiveTheirExitCodeAndMessage) {
    size_t rows = 0;
    for (const CatalogueRow& c : kInvalidCatalogue) {
        if (!*c.file || std::string(c.args) != "triangulate" || (c.code != 3 && c.code != 4))
            continue;
        ++rows;
        for (const char* cmd : {"triangulate", "trace", "transcript", "verify"}) {
            RunResult r =
                run(std::string(cmd) + " " + src(std::string("polygons/invalid/") + c.file));
            EXPECT_EQ(r.code, c.code) << cmd << " " << c.file << ": " << r.out;
            EXPECT_TRUE(has(r.out, c.message)) << cmd << " " << c.file << ": " << r.out;
            // No output for invalid input, but for the trace of the flood run anyway (as the
            // viewer runs it) up to where the machine stops.
            if (std::string(cmd) == "trace" && c.code == 4)
                EXPECT_TRUE(has(r.out, "\"format\":\"flood-trace\"")) << c.file << ": " << r.out;
            else
                EXPECT_FALSE(has(r.out, "\"triangles\""))
                    << "no output for invalid input: " << c.file;
        }
    }
    EXPECT_GE(rows, 20u);
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
    // One numbering everywhere: the Nth event is step N, as in the viewer and the messages.
    EXPECT_TRUE(has(n.out, "step 1: Start")) << n.out;
    EXPECT_FALSE(has(n.out, "step 0:")) << n.out;
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

// --- Outputs: complete or untouched; stdout checked (docs/ERRORS.md, exit 8) ---------------

namespace {

namespace fs = std::filesystem;

std::vector<std::string> listing(const fs::path& d) {
    std::vector<std::string> names;
    for (auto& e : fs::directory_iterator(d)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Runs `flood ARGS...` in a child under a file-size limit of `limit` bytes with SIGXFSZ
// ignored (so the write fails with EFBIG instead of killing); stderr is returned in `err`.
int runUnderFileSizeLimit(const std::vector<std::string>& args, rlim_t limit, std::string& err) {
    int pipeFd[2];
    if (pipe(pipeFd) != 0) return -1;
    pid_t pid = fork();
    if (pid == 0) {
        dup2(pipeFd[1], 2);
        close(pipeFd[0]);
        struct rlimit rl = {limit, limit};
        setrlimit(RLIMIT_FSIZE, &rl);
        signal(SIGXFSZ, SIG_IGN);
        std::vector<char*> argv{const_cast<char*>(FLOOD_CLI)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(FLOOD_CLI, argv.data());
        _exit(127);
    }
    close(pipeFd[1]);
    char buf[4096];
    for (ssize_t k; (k = read(pipeFd[0], buf, sizeof buf)) > 0;) err.append(buf, size_t(k));
    close(pipeFd[0]);
    int st = 0;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace

// `flood CMD > /dev/full` used to exit 0 with nothing written.
TEST(Cli, StdoutThatCannotBeWrittenIsAnError) {
    std::string hole = src("polygons/hole.json");
    for (std::string args : {"transcript " + hole, "transcript --narrate " + hole, "verify " + hole,
                             "bench --repeat 1 " + hole, "triangulate " + hole, "trace " + hole,
                             std::string("generate circle-jagged 100"), std::string("--help")}) {
        RunResult r = runShell(std::string(FLOOD_CLI) + " " + args + " 2>&1 >/dev/full");
        EXPECT_EQ(r.code, 8) << args << ": " << r.out;
        EXPECT_TRUE(has(r.out, "error: cannot write standard output: No space left on device"))
            << args << ": " << r.out;
    }
    // A failing command keeps its own exit code and still reports the lost output.
    RunResult bad = runShell(std::string(FLOOD_CLI) + " verify " +
                             src("polygons/invalid/zero-area.json") + " 2>&1 >/dev/full");
    EXPECT_EQ(bad.code, 4) << bad.out;
}

TEST(Cli, OutputFilesThatCannotBeWrittenAreErrors) {
    fs::path d = scratch("unwritable");
    std::string hole = src("polygons/hole.json");
    struct Case {
        std::string out, reason;
    } cases[] = {
        {"/dev/full", "/dev/full: cannot write: No space left on device"},
        {"/dev/full/x.json", "/dev/full/x.json: cannot write: Not a directory"},
        {(d / "missing" / "x.json").string(), "x.json: cannot write: No such file or directory"},
        {d.string(), ": cannot write: Is a directory"},
    };
    for (const Case& c : cases)
        for (const char* cmd : {"triangulate", "trace"}) {
            RunResult r = run(std::string(cmd) + " " + hole + " -o " + c.out);
            EXPECT_EQ(r.code, 8) << cmd << " -o " << c.out << ": " << r.out;
            EXPECT_TRUE(has(r.out, c.reason)) << cmd << " -o " << c.out << ": " << r.out;
        }
    // A directory without write permission (root may write anywhere: then /sys, read-only).
    fs::path ro = d / "read-only";
    fs::create_directories(ro);
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    std::string dir = access(ro.c_str(), W_OK) == 0 ? "/sys" : ro.string();
    if (access(dir.c_str(), W_OK) != 0 && fs::is_directory(dir)) {
        RunResult r = run("generate circle-jagged 100 -o " + dir + "/x.json");
        EXPECT_EQ(r.code, 8) << r.out;
        EXPECT_TRUE(has(r.out, dir + "/x.json: cannot write: ")) << r.out;
        EXPECT_FALSE(fs::exists(dir + "/x.json"));
    }
    fs::permissions(ro, fs::perms::owner_all);
    EXPECT_EQ(listing(d), std::vector<std::string>{"read-only"});  // no temporary left behind
    fs::remove_all(d);
}

// Every writer goes through the same atomic output: past a file-size limit, the old file is
// byte-identical and no temporary remains.
TEST(Cli, FileSizeLimitLeavesTheOldOutputByteIdentical) {
    fs::path d = scratch("fsize");
    fs::path out = d / "out.json";
    const std::string old = "the old content, which must survive\n";
    std::string hole = src("polygons/hole.json");
    std::vector<std::vector<std::string>> commands = {
        {"triangulate", hole, "-o", out.string()},
        {"triangulate", "--format", "svg", hole, "-o", out.string()},
        {"trace", hole, "-o", out.string()},
        {"generate", "circle-jagged", "1000", "-o", out.string()},
        {"shrink", src("polygons/invalid/forbidden-ceiling-as-end.json"), "-o", out.string()},
    };
    for (const auto& args : commands) {
        { std::ofstream(out, std::ios::binary) << old; }
        std::string err;
        int code = runUnderFileSizeLimit(args, old.size() / 2, err);
        EXPECT_EQ(code, 8) << args[0] << ": " << err;
        EXPECT_TRUE(has(err, out.string() + ": cannot write: File too large"))
            << args[0] << ": " << err;
        EXPECT_EQ(slurp(out), old) << args[0];
        EXPECT_EQ(listing(d), std::vector<std::string>{"out.json"}) << args[0];
    }
    // Without a limit the same command replaces the file, with a new file's permissions.
    RunResult r = run("triangulate " + hole + " -o " + out.string());
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(has(slurp(out), "\"triangles\"")) << slurp(out);
    mode_t mask = umask(0);
    umask(mask);
    EXPECT_EQ(unsigned(fs::status(out).permissions()), unsigned(0666 & ~mask));
    EXPECT_EQ(listing(d), std::vector<std::string>{"out.json"});
    fs::remove_all(d);
}

// `flood shrink IN -o IN` used to replace the failing input by its shrunk form.
TEST(Cli, OutputNamingTheInputIsRefused) {
    fs::path d = scratch("same");
    fs::path in = d / "a.json";
    fs::copy_file(src("polygons/invalid/forbidden-ceiling-as-end.json"), in);
    fs::create_symlink("a.json", d / "link.json");
    const std::string original = slurp(in);
    for (const char* cmd : {"shrink", "triangulate --no-validate", "trace --no-validate"})
        for (const std::string& o :
             {in.string(), (d / "." / "a.json").string(), (d / "link.json").string()}) {
            RunResult r = run(std::string(cmd) + " " + in.string() + " -o " + o);
            EXPECT_EQ(r.code, 2) << cmd << " -o " << o << ": " << r.out;
            EXPECT_TRUE(has(r.out, "-o " + o + " is the input file " + in.string() +
                                       ": refusing to overwrite the input"))
                << r.out;
            EXPECT_EQ(slurp(in), original) << cmd << " -o " << o;
        }
    RunResult piped = run("shrink - -o " + in.string() + " < " + in.string());
    EXPECT_EQ(piped.code, 2) << piped.out;
    EXPECT_EQ(slurp(in), original);
    fs::remove_all(d);
}

// A repro is what the user reads back: `flood shrink` on this face once wrote a ring whose
// rounding made two vertices equal; the reader dropped one and the "repro" triangulated.
TEST(Cli, ShrinkWritesAReproThatFailsTheSameWayWhenRun) {
    fs::path d = scratch("repro");
    fs::path out = d / "s.json";
    RunResult r =
        run("shrink " + src("polygons/tutorial/crossing-face.json") + " -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(has(r.out, "reproduce with: flood triangulate --no-validate " + out.string()))
        << r.out;
    RunResult again = run("triangulate --no-validate " + out.string());
    EXPECT_EQ(again.code, 5) << again.out;
    EXPECT_FALSE(has(again.out, "warning")) << again.out;  // nothing repaired on reading
    EXPECT_TRUE(has(slurp(out), "\"source_vertices\":[[")) << slurp(out);
    // -q: errors only.
    RunResult quiet =
        run("shrink -q " + src("polygons/tutorial/crossing-face.json") + " -o " + out.string());
    EXPECT_EQ(quiet.code, 0);
    EXPECT_EQ(quiet.out, "");
    fs::remove_all(d);
}

// --- Input limits and clear messages ---------------------------------------------------------

// --max-input-bytes -5 was read as 2^64 - 5 and accepted (0 was refused): a negative size is
// refused by every command that reads.
TEST(Cli, ANegativeInputLimitIsRefused) {
    std::string hole = src("polygons/hole.json");
    for (const char* cmd :
         {"triangulate", "trace", "transcript", "verify", "bench", "shrink", "check"})
        for (const char* value : {" -5", "=-5", "=-1k"}) {
            RunResult r = run(std::string(cmd) + " --max-input-bytes" + value + " " + hole);
            EXPECT_EQ(r.code, 2) << cmd << value << ": " << r.out;
            EXPECT_TRUE(has(r.out, "--max-input-bytes: '-")) << cmd << value << ": " << r.out;
            EXPECT_TRUE(has(r.out, "' is not a size: give a positive number of bytes"))
                << cmd << value << ": " << r.out;
        }
}

TEST(Cli, InputLimitsAndWhatTheInputIs) {
    fs::path d = scratch("limits");
    { std::ofstream(d / "nul.json", std::ios::binary) << std::string(1000, '\0'); }
    RunResult nul = run("triangulate " + (d / "nul.json").string());
    EXPECT_EQ(nul.code, 3) << nul.out;
    EXPECT_TRUE(has(nul.out, "nul.json: binary data (a NUL byte at byte 0), not GeoJSON or WKT"))
        << nul.out;
    // /dev/zero has no size: reading stops at the first chunk instead of at 4 GB.
    RunResult zero = run("verify /dev/zero");
    EXPECT_EQ(zero.code, 3) << zero.out;
    EXPECT_TRUE(has(zero.out, "/dev/zero: binary data")) << zero.out;
    RunResult dir = run("transcript " + d.string());
    EXPECT_EQ(dir.code, 3) << dir.out;
    EXPECT_TRUE(has(dir.out, d.string() + ": is a directory, not a file")) << dir.out;
    // The cap, on a file (known size) and on a pipe (counted while reading), on every reader.
    std::string holes = src("polygons/holes.json");
    for (const char* cmd : {"triangulate", "trace", "transcript", "verify", "bench", "shrink"}) {
        RunResult f = run(std::string(cmd) + " --max-input-bytes 20 " + holes);
        EXPECT_EQ(f.code, 3) << cmd << ": " << f.out;
        EXPECT_TRUE(has(
            f.out, "holes.json: input is larger than the limit of 20 bytes (--max-input-bytes)"))
            << cmd << ": " << f.out;
    }
    RunResult pipe = runShell("yes '[' | head -c 100000 | " + std::string(FLOOD_CLI) +
                              " verify --max-input-bytes 1k - 2>&1");
    EXPECT_EQ(pipe.code, 3) << pipe.out;
    EXPECT_TRUE(has(pipe.out, "<stdin>: input is larger than the limit of 1024 bytes")) << pipe.out;
    EXPECT_EQ(run("verify --max-input-bytes 1M " + holes).code, 0);
    fs::remove_all(d);
}

// 10^5 repeated points used to print 10^5 warning lines.
TEST(Cli, WarningsAreCappedWithACountOfTheRest) {
    fs::path d = scratch("warn");
    {
        std::ofstream f(d / "rep.wkt");
        f << "POLYGON((0 0";
        for (int i = 0; i < 100000; ++i) f << ", 0 0";
        f << ", 10 0, 10 10, 0 10, 0 0))";
    }
    RunResult r = run("verify " + (d / "rep.wkt").string());
    EXPECT_EQ(r.code, 0) << r.out.substr(0, 2000);
    size_t lines = 0;
    for (size_t at = 0; (at = r.out.find("repeated point dropped", at)) != std::string::npos; ++at)
        ++lines;
    EXPECT_EQ(lines, 10u);
    EXPECT_TRUE(has(r.out, "rep.wkt: \u2026 and 99,990 more warnings like these"))
        << r.out.substr(0, 2000);
    EXPECT_LT(r.out.size(), 2000u);
    fs::remove_all(d);
}

// A 10 MB literal used to be echoed whole into the message.
TEST(Cli, LongLiteralsAreCutInMessages) {
    fs::path d = scratch("literal");
    std::string digits(10000000, '7');
    struct Case {
        const char* file;
        std::string text, message;
    } cases[] = {
        {"n.json", "[[[0,0],[1,0],[1," + digits + "e999]]]", "number out of range: 777"},
        {"s.json", "[[[0,0],[1,0],[1,\"" + digits, "JSON syntax error"},
        {"t.json", "{\"type\":\"" + digits + "\"}", "unsupported GeoJSON type \"777"},
        {"w.wkt", "POLYGON((0 0, 1 0, 1 " + digits + "x))", "expected a number, found \"777"},
        {"k.wkt", "POLYGON((0 0, 1 0, 1 1), Q" + digits + ")",
         "expected '(' or EMPTY, found \"Q777"},
        {"g.wkt", "P" + digits + "((0 0, 1 0, 1 1))", "unsupported WKT geometry \"P777"},
    };
    for (const Case& c : cases) {
        { std::ofstream(d / c.file, std::ios::binary) << c.text; }
        RunResult r = run("triangulate " + (d / c.file).string());
        EXPECT_EQ(r.code, 3) << c.file;
        EXPECT_TRUE(has(r.out, c.message)) << c.file << ": " << r.out.substr(0, 300);
        EXPECT_TRUE(has(r.out, "\u2026")) << c.file << ": " << r.out.substr(0, 300);
        EXPECT_LT(r.out.size(), 400u) << c.file << ": " << r.out.substr(0, 300);
    }
    fs::remove_all(d);
}

TEST(Cli, UnknownSubcommandIsNamed) {
    RunResult r = run("frobnicate x.json");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_TRUE(has(r.out,
                    "unknown subcommand 'frobnicate'; expected one of triangulate, trace, "
                    "transcript, verify, bench, generate, shrink"))
        << r.out;
    EXPECT_FALSE(has(r.out, "A subcommand is required")) << r.out;
}

// `flood trace` on an invalid polygon floods it anyway, as the viewer does, and writes the
// trace up to the forbidden transition; the exit code is still validation's verdict.
TEST(Cli, TraceOfAnInvalidPolygonIsWrittenUpToTheForbiddenTransition) {
    fs::path d = scratch("trace-invalid");
    std::string t = (d / "t.jsonl").string();
    RunResult r =
        run("trace " + src("polygons/invalid/forbidden-ceiling-as-end.json") + " -o " + t);
    EXPECT_EQ(r.code, 4) << r.out;
    EXPECT_TRUE(has(r.out, "error: invalid polygon")) << r.out;
    EXPECT_TRUE(has(r.out, "flooding it anyway")) << r.out;
    flood::Trace back;
    flood::Diagnostic dg = flood::readTraceFile(t, back);
    ASSERT_TRUE(dg.ok()) << dg.message;
    EXPECT_EQ(back.diagnostic.status, flood::Status::Forbidden);
    ASSERT_FALSE(back.events.empty());
    EXPECT_EQ(back.events.back().action, flood::Action::Forbidden);
    // A malformed file is still refused: there is nothing to flood.
    RunResult bad = run("trace " + src("polygons/invalid/malformed-json.json") + " -o " + t);
    EXPECT_EQ(bad.code, 3) << bad.out;
    fs::remove_all(d);
}

TEST(Cli, VersionIsTheProjectsAndExitsZero) {
    RunResult v = run("--version");
    EXPECT_EQ(v.code, 0) << v.out;
    EXPECT_EQ(v.out, std::string("flood ") + FLOOD_PROJECT_VERSION + "\n");
}

// A trace of an unvalidated run holds NaN: written as "NaN" (nlohmann wrote null, which the
// reader refused), it reads back.
TEST(Cli, TraceWithNaNReadsBack) {
    fs::path d = scratch("nan");
    std::string t = (d / "nan.jsonl").string();
    RunResult r = run("trace --no-validate " + src("polygons/invalid/nan.wkt") + " -o " + t);
    EXPECT_EQ(r.code, 5) << r.out;
    flood::Trace back;
    flood::Diagnostic dg = flood::readTraceFile(t, back);
    ASSERT_TRUE(dg.ok()) << dg.message;
    ASSERT_EQ(back.polygon.vertices.size(), 4u);
    EXPECT_TRUE(std::isnan(back.polygon.vertices[2].y));
    EXPECT_EQ(back.polygon.vertices[2].x, 10);
    EXPECT_EQ(back.diagnostic.status, flood::Status::Forbidden);
    fs::remove_all(d);
}

// `generate --help` said "see the error message for the list" (issue 30 §4): it lists every
// family, valid and invalid, and each one it lists generates.
TEST(Cli, GenerateHelpListsEveryFamily) {
    RunResult help = runCli("generate --help");
    ASSERT_EQ(help.code, 0) << help.out;
    std::vector<std::string> want = flood::familyNames(), invalid = flood::invalidFamilyNames();
    want.insert(want.end(), invalid.begin(), invalid.end());
    for (const std::string& family : want) {
        bool listed = false;  // as a whole word of the list: "circle" is no "circle-holes"
        for (size_t at = help.out.find(" " + family); !listed && at != std::string::npos;
             at = help.out.find(" " + family, at + 1))
            listed =
                std::string(",;\n ").find(help.out[at + 1 + family.size()]) != std::string::npos;
        EXPECT_TRUE(listed) << family << "\n" << help.out;
        RunResult r = runCli("generate " + family + " 30 -o /dev/null");
        EXPECT_EQ(r.code, 0) << family << ": " << r.out;
    }
    RunResult unknown = runCli("generate nope 30");
    EXPECT_EQ(unknown.code, 2);
    EXPECT_NE(unknown.out.find("families: " + want.front() + ", "), std::string::npos)
        << unknown.out;
}

// -j lends threads to a MultiPolygon's validation and flood and to the check beside the
// writing: the file written is the one a single thread writes, and -v still times each step.
TEST(Cli, TriangulateWritesTheSameFileOnOneThreadAndOnTwo) {
    fs::path d = scratch("jobs");
    const std::string in = (d / "islands.json").string();
    ASSERT_EQ(run("generate islands 50000 -o " + in).code, 0);
    std::vector<std::string> outs;
    for (const char* j : {"1", "2", "3"}) {
        const std::string out = (d / ("out-j" + std::string(j) + ".json")).string();
        RunResult r = run("triangulate -v -j " + std::string(j) + " " + in + " -o " + out);
        EXPECT_EQ(r.code, 0) << r.out;
        for (const char* step : {"validate: ", "flood: ", "check and write: "})
            EXPECT_TRUE(has(r.out, step)) << j << ": " << r.out;
        outs.push_back(slurp(out));
    }
    EXPECT_TRUE(has(outs[0], "\"triangles\": [["));
    EXPECT_EQ(outs[1], outs[0]);
    EXPECT_EQ(outs[2], outs[0]);
    RunResult zero = run("triangulate -j 0 " + in);
    EXPECT_EQ(zero.code, 2) << zero.out;
    EXPECT_TRUE(has(zero.out, "--jobs")) << zero.out;
    fs::remove_all(d);
}
