// flood-bench: Flood against the peer triangulators on the same inputs (issue 4).
//
//   flood-bench dump DIR FIXTURES [--seed S] [--max-size N] [--large F,G] [--real R]
//                                                             write inputs + DIR/manifest.tsv
//                                                             (R: real coastlines, family coast)
//   flood-bench run DIR [--timeout S] [--out FILE]            time every triangulator, check it
//   flood-bench memory FILE.poly [--record]                   peak memory of one Flood run
//   flood-bench floor FILE.poly                               the floor's parts, ns (floor.h)
//
// `run` measures each (input, triangulator) in a child process, so a peer that crashes or
// hangs costs one row ("crash", "timeout"), never the run. The out-of-process peers (earcut
// through Python, earcut, libtess and poly2tri under Node.js) run between dump and run; `run`
// checks their triangles and merges their rows.
// scripts/bench.sh chains everything and bench/report.py writes docs/BENCHMARKS.md.
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "flood/check/checker.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/machine/flood.h"
#include "floor.h"
#include "inputs.h"
#include "peers.h"

namespace fs = std::filesystem;
using namespace flood;
using namespace bench;

namespace {

// [SECTION] timing and judging

std::string oneLine(std::string s) {
    for (char& c : s)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return s.size() > 160 ? s.substr(0, 157) + "..." : s;
}

struct Timing {
    double medianNs = 0;
    int runs = 0;
};

// Runs `f` at least 3 times and until ~0.5 s are spent (at most 21 runs); a single run over
// 10 s is not repeated, and over 2 s only 3 times.
Timing timeRuns(const std::function<void()>& f) {
    std::vector<double> t;
    double total = 0;
    while (true) {
        auto t0 = std::chrono::steady_clock::now();
        f();
        double ns =
            std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
        t.push_back(ns);
        total += ns;
        if (t[0] > 10e9) break;
        if (t.size() >= 3 && (total > 0.5e9 || t.size() >= 21)) break;
    }
    std::sort(t.begin(), t.end());
    return {t[t.size() / 2], int(t.size())};
}

// Times `a` and `b` alternately (at least 5 pairs, until ~2 s are spent, at most 21; one pair
// when `b` takes over 10 s), so load from other jobs falls on both alike: their ratio is fairer
// than one of two medians taken minutes apart.
std::pair<Timing, Timing> timePaired(const std::function<void()>& a,
                                     const std::function<void()>& b) {
    std::vector<double> ta, tb;
    double total = 0;
    auto once = [](const std::function<void()>& f) {
        auto t0 = std::chrono::steady_clock::now();
        f();
        return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0)
            .count();
    };
    while (true) {
        ta.push_back(once(a));
        tb.push_back(once(b));
        total += ta.back() + tb.back();
        if (tb[0] > 10e9) break;
        if (ta.size() >= 5 && (total > 2e9 || ta.size() >= 21)) break;
    }
    std::sort(ta.begin(), ta.end());
    std::sort(tb.begin(), tb.end());
    return {{ta[ta.size() / 2], int(ta.size())}, {tb[tb.size() / 2], int(tb.size())}};
}

struct Verdict {
    std::string status;  // valid, invalid, count-differs, adds-vertices, error, refused
    std::string detail;
};

Verdict judge(const Polygon& p, std::vector<Triangle> t, size_t added, const std::string& error) {
    if (!error.empty()) return {"error", oneLine(error)};
    if (added)
        return {"adds-vertices",
                std::to_string(added) + " output vertices/triangles not on input points"};
    size_t expected = p.expectedTriangles();
    if (t.size() != expected)
        return {"count-differs",
                std::to_string(t.size()) + " triangles, n+2h-2-2d = " + std::to_string(expected)};
    orientCounterClockwise(p, t);
    CheckResult c = checkTriangulation(p, t);
    return c.ok ? Verdict{"valid", ""} : Verdict{"invalid", oneLine(c.reason)};
}

struct Recorder : Listener {
    std::vector<Event> events;
    void onEvent(const Event& e) override { events.push_back(e); }
};

// One measurement row, as the child reports it: status, median ns, runs, triangles, detail, extra.
struct Row {
    std::string status, detail, extra;
    double ns = 0;
    int runs = 0;
    size_t triangles = 0;
};

std::string serialize(const Row& r) {
    std::ostringstream s;
    s.precision(15);
    s << r.status << '\t' << r.ns << '\t' << r.runs << '\t' << r.triangles << '\t' << r.detail
      << '\t' << r.extra;
    return s.str();
}

Row measure(const std::string& who, const Polygon& p, const CoordIndex& index) {
    Row row;
    Verdict v;
    if (who == "flood") {
        FloodResult result;
        Timing t = timeRuns([&] { result = triangulate(p); });
        row.ns = t.medianNs;
        row.runs = t.runs;
        row.triangles = result.triangles.size();
        if (!result.diagnostic.ok()) v = {"refused", oneLine(result.diagnostic.message)};
        else v = judge(p, result.triangles, 0, "");
        Polygon copy = p;  // validate() records the T-junctions it finds into its polygon
        Timing tv = timeRuns([&] { (void)validate(copy, "input"); });
        // One more run counted (flood/geometry/work.h): the sag search's share of the
        // machine's work.
        work() = {};
        (void)triangulate(p);
        const WorkCounters w = work();
        row.extra = "validate_ns=" + std::to_string(tv.medianNs) +
                    ";machine_work=" + std::to_string(w.nodeVisits + w.sagTests + w.orientCalls) +
                    ";sag_work=" + std::to_string(w.sagSearch);
    } else if (who == "flood-rec") {
        // Full trace recording as `flood trace` and the viewer get it: record(), a fresh Trace
        // (polygon copy and event log) each run, timed in turn with a plain run.
        FloodResult plain;
        Trace trace;
        auto [tp, t] = timePaired([&] { plain = triangulate(p); }, [&] { trace = record(p); });
        row.ns = t.medianNs;
        row.runs = t.runs;
        row.triangles = trace.triangles.size();
        if (!trace.diagnostic.ok()) v = {"refused", oneLine(trace.diagnostic.message)};
        else v = judge(p, trace.triangles, 0, "");
        // The same with one listener log whose capacity is kept between runs (clear()): the
        // difference is the first-touch cost of fresh memory.
        Recorder kept;
        Timing tk = timeRuns([&] {
            kept.events.clear();
            (void)triangulate(p, &kept);
        });
        row.extra = "events=" + std::to_string(trace.events.size()) +
                    ";reused_ns=" + std::to_string(tk.medianNs) +
                    ";paired_plain_ns=" + std::to_string(tp.medianNs);
    } else if (who == "floor") {
        FloorNs f = measureFloor(p);
        row.ns = f.total();
        row.runs = 1;
        v = {"ok", ""};
        row.extra = "io_ns=" + std::to_string(f.io) + ";orient_ns=" + std::to_string(f.orient) +
                    ";sags_ns=" + std::to_string(f.sags);
    } else if (who == "glu") {
        PeerOutput out;
        Timing t = timeRuns([&] { out = runGlu(p); });
        row.ns = t.medianNs, row.runs = t.runs, row.triangles = out.triangles.size();
        v = judge(p, out.triangles, out.added, out.error);
    } else if (who == "cgal") {
        PeerOutput out;
        Timing t = timeRuns([&] { out = runCgal(p, index); });
        row.ns = t.medianNs, row.runs = t.runs, row.triangles = out.triangles.size();
        v = judge(p, out.triangles, out.added, out.error);
#ifdef FLOOD_EARCUT_HPP
    } else if (who == "earcut-hpp") {
        PeerOutput out;
        Timing t = timeRuns([&] { out = runEarcut(p); });
        row.ns = t.medianNs, row.runs = t.runs, row.triangles = out.triangles.size();
        v = judge(p, out.triangles, out.added, out.error);
#endif
    } else if (who == "geos") {
        PeerOutput out;
        Timing t = timeRuns([&] { out = runGeos(p, nullptr); });
        row.ns = t.medianNs, row.runs = t.runs;
        out = runGeos(p, &index);  // once more, mapped back to input indices (not timed)
        row.triangles = out.triangles.size() + out.added;
        v = judge(p, out.triangles, out.added, out.error);
    }
    row.status = v.status;
    row.detail = v.detail;
    return row;
}

// Runs measure() in a child process with a time limit.
Row guarded(const std::string& who, const Polygon& p, const CoordIndex& index, double timeoutS) {
    int fd[2];
    if (pipe(fd) != 0) return {"error", "pipe failed", "", 0, 0, 0};
    std::fflush(nullptr);
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        std::string line;
        try {
            line = serialize(measure(who, p, index));
        } catch (const std::exception& e) {
            line =
                serialize({"error", oneLine(std::string("exception: ") + e.what()), "", 0, 0, 0});
        } catch (...) {
            line = serialize({"error", "unknown exception", "", 0, 0, 0});
        }
        line += "\n";
        ssize_t w = write(fd[1], line.data(), line.size());
        (void)w;
        _exit(0);
    }
    close(fd[1]);
    std::string text;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
    bool timedOut = false;
    while (true) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                        deadline - std::chrono::steady_clock::now())
                        .count();
        if (left <= 0) {
            timedOut = true;
            break;
        }
        pollfd pf{fd[0], POLLIN, 0};
        int r = poll(&pf, 1, int(std::min<long long>(left, 1000)));
        if (r > 0) {
            char buf[4096];
            ssize_t n = read(fd[0], buf, sizeof buf);
            if (n <= 0) break;
            text.append(buf, size_t(n));
        }
    }
    close(fd[0]);
    if (timedOut) kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    if (timedOut) return {"timeout", "over " + std::to_string(int(timeoutS)) + " s", "", 0, 0, 0};
    if (WIFSIGNALED(status))
        return {"crash", std::string("signal ") + strsignal(WTERMSIG(status)), "", 0, 0, 0};
    std::istringstream s(text);
    Row row;
    std::string ns, runs, tris;
    std::getline(s, row.status, '\t');
    std::getline(s, ns, '\t');
    std::getline(s, runs, '\t');
    std::getline(s, tris, '\t');
    std::getline(s, row.detail, '\t');
    std::getline(s, row.extra, '\n');
    if (row.status.empty() || ns.empty()) return {"crash", "no result", "", 0, 0, 0};
    row.ns = std::stod(ns);
    row.runs = std::stoi(runs);
    row.triangles = std::stoull(tris);
    return row;
}

// [SECTION] commands

std::string safeName(const std::string& name) {
    std::string s = name;
    std::replace(s.begin(), s.end(), '/', '_');
    return s;
}

int cmdDump(const std::string& dir, const std::string& fixtures, uint64_t seed, size_t maxSize,
            const std::vector<std::string>& large, const std::string& real) {
    fs::create_directories(dir);
    std::vector<InputInfo> rows;
    auto add = [&](const std::string& name, const std::string& family, size_t size,
                   const Polygon& p) {
        InputInfo r;
        r.name = name;
        r.family = family;
        r.size = size;
        r.vertices = p.vertices.size();
        r.holes = p.holeCount();
        Polygon checked = p;  // with the T-junctions validate() finds, for the flood and checker
        Diagnostic d = validate(checked, name);
        r.valid = d.ok();
        r.verdict = d.ok() ? "" : oneLine(d.message);
        r.path = (fs::absolute(dir) / (safeName(name) + ".poly")).string();
        writePoly(r.path, checked);
        rows.push_back(r);
        std::fprintf(stderr, "dump %-32s %9zu vertices %5zu holes %s\n", name.c_str(), r.vertices,
                     r.holes, r.valid ? "" : "INVALID");
    };
    // Each .json file of a folder, in name order, as FAMILY/STEM.
    auto addFolder = [&](const std::string& folder, const std::string& family) {
        std::vector<fs::path> files;
        if (fs::is_directory(folder))
            for (const auto& e : fs::directory_iterator(folder))
                if (e.path().extension() == ".json") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) {
            ReadResult rr = readPolygonFile(f.string());
            if (!rr.diagnostic.ok()) {
                std::fprintf(stderr, "dump: skipping unreadable %s: %s\n", f.c_str(),
                             rr.diagnostic.message.c_str());
                continue;
            }
            add(family + "/" + f.stem().string(), family, rr.polygon.vertices.size(), rr.polygon);
        }
    };
    addFolder(fixtures, "fixture");
    if (!real.empty()) addFolder(real, "coast");
    for (const auto& family : benchFamilies())
        for (size_t size : benchSizes(family, large))
            if (size <= maxSize)
                add(family + "/" + std::to_string(size), family, size,
                    benchGenerate(family, seed, size));
    writeManifest((fs::path(dir) / "manifest.tsv").string(), rows);
    return 0;
}

// Rows written by an out-of-process peer (earcut_bench.py, node/peers_time.mjs):
// name -> (name, status, ns, runs, triangles, detail[, added]).
std::map<std::string, std::vector<std::string>> readExternal(const std::string& path) {
    std::map<std::string, std::vector<std::string>> m;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::istringstream s(line);
        std::string x;
        while (std::getline(s, x, '\t')) f.push_back(x);
        if (f.size() >= 5 && f[0] != "name") m[f[0]] = f;
    }
    return m;
}

// The peers run outside this driver: their name in the results, the file stem of their rows
// (DIR/STEM.tsv) and triangles (DIR/<input>.STEM.tri).
const std::vector<std::pair<std::string, std::string>> kExternal{{"earcut", "earcut"},
                                                                 {"earcut-js", "earcut-node"},
                                                                 {"libtess", "libtess-node"},
                                                                 {"poly2tri", "poly2tri-node"}};

Row externalRow(const std::string& dir, const std::string& stem, const InputInfo& info,
                const Polygon& p, const std::map<std::string, std::vector<std::string>>& rows) {
    auto it = rows.find(info.name);
    if (it == rows.end()) return {"missing", "no " + stem + " result", "", 0, 0, 0};
    const auto& f = it->second;
    Row row;
    row.status = f[1];
    row.ns = std::stod(f[2]);
    row.runs = std::stoi(f[3]);
    row.triangles = std::stoull(f[4]);
    row.detail = f.size() > 5 ? f[5] : "";
    if (row.status != "ok") return row;
    std::ifstream in((fs::path(dir) / (safeName(info.name) + "." + stem + ".tri")).string(),
                     std::ios::binary);
    std::vector<uint32_t> idx(row.triangles * 3);
    in.read(reinterpret_cast<char*>(idx.data()), std::streamsize(idx.size() * 4));
    if (!in)
        return {"error", stem + " triangle file unreadable", "", row.ns, row.runs, row.triangles};
    std::vector<Triangle> t(row.triangles);
    for (size_t i = 0; i < t.size(); ++i) {
        t[i] = {idx[3 * i], idx[3 * i + 1], idx[3 * i + 2]};
        for (uint32_t v : t[i])
            if (v >= p.vertices.size())
                return {"error",      stem + ": vertex index out of range", "", row.ns, row.runs,
                        row.triangles};
    }
    size_t added = f.size() > 6 && !f[6].empty() ? std::stoull(f[6]) : 0;
    Verdict v = judge(p, t, added, "");
    row.status = v.status;
    row.detail = v.detail;
    return row;
}

// Above this size (10^7, for a few cheap families) only Flood and the floor are timed: the peers
// take minutes there, and their growth is already clear from 10^3..10^6.
constexpr size_t kLargestPeerSize = 1000000;

int cmdRun(const std::string& dir, double timeoutS, const std::string& outPath) {
    std::vector<InputInfo> inputs = readManifest((fs::path(dir) / "manifest.tsv").string());
    std::vector<std::map<std::string, std::vector<std::string>>> external;
    for (const auto& e : kExternal)
        external.push_back(readExternal((fs::path(dir) / (e.second + ".tsv")).string()));
    std::ofstream(fs::path(dir) / "event_bytes.txt") << sizeof(Event) << "\n";  // for the report
    std::ofstream out(outPath);
    out << "name\tfamily\tsize\tvertices\tholes\tinput_"
           "valid\texpected\ttriangulator\tstatus\tns\truns\ttriangles\tdetail\textra\n";
    const std::vector<std::string> who{"flood",     "floor", "flood-rec", "glu", "cgal", "geos",
#ifdef FLOOD_EARCUT_HPP
                                       "earcut-hpp"
#endif
    };
    std::map<std::string, std::vector<double>> history;  // triangulator|family -> single-run ns
    std::map<std::string, bool> givenUp;
    for (const auto& info : inputs) {
        Polygon p = readPoly(info.path);
        CoordIndex index(p);
        auto emit = [&](const std::string& name, const Row& r) {
            out << info.name << '\t' << info.family << '\t' << info.size << '\t' << info.vertices
                << '\t' << info.holes << '\t' << (info.valid ? 1 : 0) << '\t'
                << p.expectedTriangles() << '\t' << name << '\t' << r.status << '\t' << r.ns << '\t'
                << r.runs << '\t' << r.triangles << '\t' << r.detail << '\t' << r.extra << '\n';
            out.flush();
            std::fprintf(stderr, "%-30s %-10s %-14s %12.1f ns/vertex  %s\n", info.name.c_str(),
                         name.c_str(), r.status.c_str(),
                         r.ns / double(std::max<size_t>(1, info.vertices)), r.detail.c_str());
        };
        for (const auto& w : who) {
            std::string key = w + "|" + info.family;
            if (info.size > kLargestPeerSize && w != "flood" && w != "floor") {
                emit(w, {"skipped", "above 10^6 only Flood and the floor run", "", 0, 0, 0});
                continue;
            }
            if (info.family != "fixture" && givenUp[key]) {
                emit(w, {"skipped", "timed out or predicted over the limit at a smaller size", "",
                         0, 0, 0});
                continue;
            }
            // Flood and the floor get 4x the limit: their figures are the point of the goals, and
            // Flood's child also times validate() and makes one counted run.
            const double limit = w == "flood" || w == "floor" ? 4 * timeoutS : timeoutS;
            auto& h = history[key];
            if (info.family != "fixture" && h.size() >= 2) {
                double growth = std::max(10.0, h[h.size() - 1] / h[h.size() - 2]);  // per decade
                double predicted = h.back() * growth * 1e-9;
                if (predicted > 0.75 * limit) {
                    givenUp[key] = true;
                    std::ostringstream d;
                    d << "predicted " << int(predicted) << " s per run from the smaller sizes";
                    emit(w, {"skipped", d.str(), "", 0, 0, 0});
                    continue;
                }
            }
            Row r = guarded(w, p, index, limit);
            if (r.status == "timeout" || r.status == "crash") givenUp[key] = true;
            else h.push_back(r.ns);
            emit(w, r);
        }
        for (size_t e = 0; e < kExternal.size(); ++e)
            emit(kExternal[e].first, externalRow(dir, kExternal[e].second, info, p, external[e]));
    }
    return 0;
}

long maxRssKb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

int cmdMemory(const std::string& path, bool rec) {
    Polygon p = readPoly(path);
    long before = maxRssKb();
    Recorder r;
    FloodResult result = triangulate(p, rec ? &r : nullptr);
    long after = maxRssKb();
    std::printf("%zu\t%ld\t%ld\t%zu\t%zu\n", p.vertices.size(), before, after,
                result.triangles.size(), r.events.size());
    return result.diagnostic.ok() ? 0 : 1;
}

int cmdFloor(const std::string& path) {
    Polygon p = readPoly(path);
    FloorNs f = measureFloor(p);
    std::printf("vertices %zu\tio %.0f ns\torient %.0f ns\tsags %.0f ns\ttotal %.1f ns/vertex\n",
                p.vertices.size(), f.io, f.orient, f.sags,
                f.total() / double(std::max<size_t>(1, p.vertices.size())));
    return 0;
}

int usage() {
    std::fprintf(stderr,
                 "usage: flood-bench dump DIR FIXTURES [--seed S] [--max-size N] [--large F,G] "
                 "[--real R]\n"
                 "       flood-bench run DIR [--timeout S] [--out FILE]\n"
                 "       flood-bench memory FILE.poly [--record]\n"
                 "       flood-bench floor FILE.poly\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> a(argv + 1, argv + argc);
    if (a.empty()) return usage();
    auto option = [&](const std::string& name, const std::string& fallback) {
        for (size_t i = 0; i + 1 < a.size(); ++i)
            if (a[i] == name) return a[i + 1];
        return fallback;
    };
    bool flag = std::find(a.begin(), a.end(), "--record") != a.end();
    try {
        if (a[0] == "dump" && a.size() >= 3) {
            std::vector<std::string> large;  // families also run at 10^7
            std::istringstream list(option("--large", ""));
            for (std::string f; std::getline(list, f, ',');)
                if (!f.empty()) large.push_back(f);
            return cmdDump(a[1], a[2], std::stoull(option("--seed", "1")),
                           std::stoull(option("--max-size", "1000000")), large,
                           option("--real", ""));
        }
        if (a[0] == "run" && a.size() >= 2)
            return cmdRun(a[1], std::stod(option("--timeout", "60")),
                          option("--out", a[1] + "/results.tsv"));
        if (a[0] == "memory" && a.size() >= 2) return cmdMemory(a[1], flag);
        if (a[0] == "floor" && a.size() >= 2) return cmdFloor(a[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "flood-bench: %s\n", e.what());
        return 6;
    }
    return usage();
}
