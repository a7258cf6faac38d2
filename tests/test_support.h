// Helpers shared by the test files: paths, reading polygons, exact validity assertions.
#pragma once
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "flood/check/checker.h"
#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/machine/flood.h"

namespace flood::testing {

inline std::string sourcePath(const std::string& rel) {
    return std::string(FLOOD_SOURCE_DIR) + "/" + rel;
}
inline std::string sharedPath(const std::string& rel) {
    return std::string(FLOOD_SHARED_DIR) + "/" + rel;
}

// A fresh empty directory for one test (named for it and this process, so parallel runs differ).
inline std::filesystem::path scratch(const std::string& name) {
    std::filesystem::path d = std::filesystem::temp_directory_path() /
                              ("flood-test-" + name + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

// A whole file's bytes.
inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The files of `dir` with extension `ext`, sorted: for a polygon's extension (.json, .wkt),
// its polygons as the core lists them (polygonFiles(): gallery.json is no polygon).
inline std::vector<std::string> filesIn(const std::string& dir, const std::string& ext) {
    std::vector<std::string> out;
    if (polygonFileName("x" + ext)) {
        for (std::string& f : polygonFiles(dir))
            if (std::filesystem::path(f).extension() == ext) out.push_back(std::move(f));
        return out;
    }
    if (!std::filesystem::is_directory(dir)) return out;
    for (auto& e : std::filesystem::directory_iterator(dir))
        if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

// Runs the `flood` command line with `args`; stdout and stderr together, and the exit code.
struct RunResult {
    int code = -1;
    std::string out;
};
// Runs a shell command line as given (its own redirections: stdout is what is read).
inline RunResult runShell(const std::string& command) {
    RunResult r;
    FILE* p = popen(command.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    for (size_t n; (n = fread(buf.data(), 1, buf.size(), p)) > 0;) r.out.append(buf.data(), n);
    int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}
inline RunResult runCli(const std::string& args) {
    return runShell(std::string(FLOOD_CLI) + " " + args + " 2>&1");
}

// Reads a polygon, and validates it as the CLI does, so a valid one carries its T-junctions
// (Polygon::splits); an invalid one is returned as read, for the machine to diagnose.
inline Polygon readOrFail(const std::string& path) {
    ReadResult r = readPolygonFile(path);
    EXPECT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    validate(r.polygon, path);
    return r.polygon;
}

// Islands in lakes, `rings` / 2 deep: concentric squares one unit apart, an outer ring and its
// hole for each part (`flood verify` was quadratic in the depth, issue 25 item 9).
inline Polygon nestedIslands(size_t rings) {
    Polygon p;
    for (size_t i = 0; i < rings; ++i) {
        const double h = double(rings - i);
        if (i % 2 == 0) p.addRing({{-h, -h}, {h, -h}, {h, h}, {-h, h}}, true);
        else p.addRing({{-h, -h}, {-h, h}, {h, h}, {h, -h}}, false);
    }
    return p;
}

// Floods `p` and proves the result exact-valid; returns the run for further checks.
inline FloodResult expectTriangulates(const Polygon& p, const std::string& what,
                                      const Options& options = {}) {
    FloodResult r = triangulate(p, nullptr, options);
    EXPECT_TRUE(r.diagnostic.ok()) << what << ": " << r.diagnostic.message;
    CheckResult c = checkTriangulation(p, r.triangles);
    EXPECT_TRUE(c.ok) << what << ": " << c.reason;
    return r;
}

// `t` written as `flood trace` writes it and read back, for the round-trip tests: the test
// fails if it does not read or loses events; whether each event came back is theirs to say
// (Event's == compares every field).
// `binary`: in the compact form (`flood trace --format bin`) instead of JSON Lines.
inline Trace writtenAndRead(const Trace& t, bool binary = false) {
    std::ostringstream out;
    if (binary) writeBinaryTrace(out, t);
    else writeTrace(out, t);
    Trace back;
    Diagnostic d = parseTrace(out.str(), binary ? "t.bin" : "t.jsonl", back);
    EXPECT_TRUE(d.ok()) << d.message;
    EXPECT_EQ(back.events.size(), t.events.size());
    return back;
}

// The parts of `pieces` placed at `offsets` (each piece's own parts, its holes kept).
inline Polygon layout(const std::vector<Polygon>& pieces, const std::vector<Point>& offsets) {
    Polygon out;
    for (size_t k = 0; k < pieces.size(); ++k) {
        const Polygon& p = pieces[k];
        for (const Part& part : p.parts)
            for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
                std::vector<Point> ring;
                for (Index v = p.rings[r].first; v < p.rings[r].first + p.rings[r].count; ++v)
                    ring.push_back(
                        {p.vertices[v].x + offsets[k].x, p.vertices[v].y + offsets[k].y});
                out.addRing(ring, r == part.firstRing);
            }
    }
    return out;
}

// The tasks one after another, last first: any order must do.
struct Backwards {               // a TaskRunner (flood/geometry/task_runner.h)
    size_t calls = 0, most = 0;  // how often called, the most tasks given at once
    TaskRunner runner() {
        return [this](size_t n, const std::function<void(size_t)>& task) {
            ++calls;
            most = std::max(most, n);
            for (size_t k = n; k-- > 0;) task(k);
        };
    }
};

// Two threads taking the tasks in turn, as `flood check -j2` lends them.
inline void twoThreads(size_t n, const std::function<void(size_t)>& task) {
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t k; (k = next++) < n;) task(k);
    };
    std::thread other(work);
    work();
    other.join();
}

}  // namespace flood::testing
