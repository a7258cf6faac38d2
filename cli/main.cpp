// The `flood` command-line tool: triangulate, trace, transcript, verify, bench, generate,
// shrink, check (cli/check.h).
//
// Command-line parsing uses CLI11: a Debian package (libcli11-dev), header-only, with
// subcommands and generated --help, so no hand-written argument parsing.
//
// Every command that floods follows the same pipeline (docs/ERRORS.md):
//   read (warnings to stderr; Malformed -> exit 3) -> validate (Invalid -> exit 4, nothing
//   written) -> flood (Forbidden -> exit 5) -> exact check of our own output (failure -> exit 6)
//   -> write (`triangulate -o FILE`: the check and the writing at once, see checkWhileWriting).
//   Exit codes are flood::Status values. "-" means stdin for input, stdout for output.
// Outputs are written whole or not at all (flood/io/output.h; a failed write exits 8).
#include <malloc.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <exception>
#include <functional>
#include <future>
#include <iostream>
#include <streambuf>
#include <system_error>
#include <thread>

#include "check.h"
#include "flood/check/checker.h"
#include "flood/check/touches.h"
#include "flood/check/verify.h"
#include "flood/io/gdal/read_any.h"
#include "flood/io/io.h"
#include "flood/io/output.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/machine/flood.h"
#include "flood/teach/narrate.h"
#include "flood/teach/quiz.h"
#include "flood/teach/state_table.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "flood/tools/shrink.h"
#include "pipeline.h"
#include "run.h"
#include "task_runner.h"
#include "triangulate_gis.h"
#include "verbosity.h"

namespace {

using namespace flood;
using namespace flood::cli;

void addUp(CLI::App* cmd, std::string& up) {
    cmd->add_option("--up", up,
                    "The direction the water rises along: +y (default), -y, +x, -x, an angle in "
                    "degrees counter-clockwise from +x (90 is +y), or X,Y. Write --up=-y (with "
                    "'=') for values starting with '-'.")
        ->check(CLI::Validator(
            [](std::string& v) {
                Up d;
                std::string why;
                return parseUp(v, d, why) ? std::string() : why;
            },
            "DIRECTION"));
}

int cmdTriangulate(const std::string& in, const std::string& out, std::string format,
                   bool multipolygon, const std::string& up, bool check, bool exactCheck) {
    std::string driver;
    if (int c = cli::outputFormat(out, format, driver)) return c;
    if (!driver.empty())
        return cli::triangulateGis({in, out, format, driver, multipolygon, selection, maxInputBytes,
                                    makeOptions(up), check, exactCheck});
    Polygon polygon;
    Status s = prepare(in, polygon, check);
    if (s != Status::Ok) return code(s);
    Stopwatch watch;
    FloodResult r = triangulate(polygon, nullptr, makeOptions(up), threadRunner(jobs));
    detail() << "flood: " << r.triangles.size() << " triangles, " << timeText(watch.lap()) << "\n";
    struct Timed {  // -v: the time of the rest, whichever way it ends
        Stopwatch& watch;
        ~Timed() { detail() << "check and write: " << timeText(watch.lap()) << "\n"; }
    } timed{watch};
    auto write = [&](Output& o) {
        if (format == "svg") writeSvg(o.stream(), polygon, r.triangles);
        else if (format == "obj") writeObj(o.stream(), polygon, r.triangles);
        else writeJson(o.stream(), polygon, r.triangles);
    };
    auto judged = [&] { return judge(polygon, r.triangles, r.diagnostic, check, exactCheck); };
    // A file is written through a temporary, so it can be written while the check runs (with
    // a second thread: -j).
    // Anything else (stdout, a pipe) is written only once the check has passed.
    if (exactCheck && r.diagnostic.ok() && jobs > 1 && Output::discardable(out)) {
        Output o(out);
        if (o.discardable()) {
            s = checkWhileWriting(polygon, r.triangles, check, [&] { write(o); });
            return code(s != Status::Ok ? s : o.commit());  // uncommitted: the file is removed
        }
        s = judged();
        if (s != Status::Ok) return code(s);
        write(o);
        return code(o.commit());
    }
    s = judged();
    if (s != Status::Ok) return code(s);
    Output o(out);
    write(o);
    return code(o.commit());
}

// An invalid polygon is flooded anyway, as the viewer floods it: its trace, up to the
// forbidden transition that proves it wrong, is what one wants to look at. The exit code is
// still the verdict's (4 for invalid input).
int cmdTrace(const std::string& in, const std::string& out, const std::string& up, bool check,
             bool exactCheck, bool binary) {
    Polygon polygon;
    Status s = prepare(in, polygon, check, true);
    const Status verdict = s;
    if (s != Status::Ok && s != Status::Invalid) return code(s);
    const bool validated = check && verdict == Status::Ok;
    Stopwatch watch;
    Trace t = record(polygon, makeOptions(up));
    detail() << "flood: " << t.events.size() << " events recorded, " << timeText(watch.lap())
             << "\n";
    s = judge(polygon, t.triangles, t.diagnostic, validated, exactCheck);
    if (verdict != Status::Ok) s = verdict;
    // A trace of a forbidden run is exactly what one wants to look at: write it anyway,
    // but still exit with the failure status.
    if (s == Status::Internal)
        t.diagnostic = {Status::Internal, "the exact checker rejects the result"};
    Output o(out);
    if (binary) writeBinaryTrace(o.stream(), t);
    else writeTrace(o.stream(), t);
    Status w = o.commit();
    return code(s != Status::Ok ? s : w);
}

// What `flood transcript` prints besides the paper's line: --narrate, --quiz, --table.
struct TranscriptWants {
    bool narrate = false, quiz = false, table = false;
    std::string quizActions = "all", answers;  // answers: a file for them, "" after the questions
};

int cmdTranscript(const std::string& in, const TranscriptWants& want, const std::string& up,
                  bool check) {
    QuizActions asked;
    std::string why;
    if (!parseQuizActions(want.quizActions, asked, why)) {
        std::cerr << "error: --quiz-actions: " << why << "\n";
        return code(Status::Usage);
    }
    Polygon polygon;
    Status s = prepare(in, polygon, check);
    if (s != Status::Ok) return code(s);
    Trace t = record(polygon, makeOptions(up));
    Status j = judge(polygon, t.triangles, t.diagnostic, check);
    if (j == Status::Internal) return code(j);  // never narrate a wrong triangulation
    if (want.quiz) {
        // A handout: the questions, then the answers on a page of their own (a form feed)
        // or in their own file.
        std::cout << quizQuestionsText(polygon, t.events, asked, t.up);
        const std::string answers = quizAnswersText(polygon, t.events, asked);
        if (want.answers.empty()) {
            std::cout << "\f\n" << answers;
        } else {
            Output o(want.answers);
            o.stream() << answers;
            if (Status w = o.commit(); w != Status::Ok) return code(w);
        }
    } else if (!want.narrate) {
        std::cout << transcript(t.events) << "\n";
    } else {
        // One numbered sentence per event in the flood metaphor (flood/teach/narrate.h),
        // numbered as the viewer's timeline and describeForbidden() number them: step N is the
        // Nth event.
        for (const Event& e : t.events)
            std::cout << "step " << e.step + 1 << ": " << actionName(e.action) << ": "
                      << flood::narrate(polygon, e) << "\n";
    }
    if (want.table) std::cout << "\n" << formatStateTable(buildStateTable(polygon, t.events, t.up));
    return code(j);
}

int cmdVerify(const std::string& in, const std::string& up, bool check) {
    Polygon polygon;
    Status s = prepare(in, polygon, check);
    if (s != Status::Ok) return code(s);
    // The paper's verification (§6): flood the polygon and its complement in a box, and check
    // both exactly. Unvalidated, it is the paper's open conjecture at work: say what caught it.
    Stopwatch watch;
    Verification v = verify(polygon, makeOptions(up));
    detail() << "verify: " << timeText(watch.lap()) << "\n";
    std::cout << v.summary() << "\n";
    if (!v.ok()) {
        std::cout << "verify: FAILED (caught by: " << caughtName(v.caught()) << ")\n";
        return code(Status::VerifyFailed);
    }
    if (!check) std::cout << "verify: validation skipped: caught by nothing\n";
    std::cout << "verify: ok: " << polygon.vertices.size() << " vertices in "
              << polygon.rings.size() << " rings\n";
    return code(Status::Ok);
}

// Median wall time of `repeat` runs, in nanoseconds.
template <typename F>
double medianNs(int repeat, F&& run) {
    std::vector<double> t;
    for (int i = 0; i < repeat; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        run();
        auto t1 = std::chrono::steady_clock::now();
        t.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// The generator's families, as --help and an unknown family's message list them.
std::string familyList() {
    std::string list;
    for (const std::string& n : familyNames()) list += (list.empty() ? "" : ", ") + n;
    list += "; invalid families (validation refuses them): ";
    const std::vector<std::string> invalid = invalidFamilyNames();
    for (size_t k = 0; k < invalid.size(); ++k) list += (k ? ", " : "") + invalid[k];
    return list;
}

// Writes a generated polygon: ring array (one part) or GeoJSON MultiPolygon, streamed so a
// 10^7-vertex file needs no second copy in memory.
int cmdGenerate(const std::string& family, size_t size, uint64_t seed, const std::string& out) {
    auto names = familyNames(), invalid = invalidFamilyNames();
    bool isInvalid = std::find(invalid.begin(), invalid.end(), family) != invalid.end();
    if (!isInvalid && std::find(names.begin(), names.end(), family) == names.end()) {
        std::cerr << "error: unknown family \"" << family << "\"; families: " << familyList()
                  << "\n";
        return code(Status::Usage);
    }
    Polygon p = isInvalid ? generateInvalid(family, seed, size) : generate(family, seed, size);
    Output o(out);
    writePolygonJson(o.stream(), p);
    return code(o.commit());
}

// Shrinks a failing polygon (validation skipped; see flood/tools/shrink.h) and writes the repro: a
// GeoJSON Feature that says where it came from. It is written only once its bytes, read back
// as the user will read them, fail the same way; a file is read back from disk after writing.
int cmdShrink(const std::string& in, const std::string& out, const std::string& up,
              unsigned timeout, bool slipping, bool quiet) {
    Polygon polygon;
    Status s = prepare(in, polygon, false);
    if (s != Status::Ok) return code(s);
    ShrinkOptions o;
    o.flood = makeOptions(up);
    o.timeoutSeconds = timeout;
    o.slipping = slipping;
    // Progress on a terminal, a line rewritten at most five times a second.
    const bool progress = !quiet && isatty(STDERR_FILENO);
    const auto t0 = std::chrono::steady_clock::now();
    auto shown = t0;
    if (progress)
        o.onTry = [&](size_t tries, size_t vertices) {
            auto now = std::chrono::steady_clock::now();
            if (now - shown < std::chrono::milliseconds(200)) return true;
            shown = now;
            std::fprintf(stderr, "\rshrink: %zu tries, %zu vertices, %.1f s\033[K", tries, vertices,
                         std::chrono::duration<double>(now - t0).count());
            return true;
        };
    ShrinkResult r = shrink(polygon, o);
    if (progress) std::fprintf(stderr, "\r\033[K");
    if (r.failure.kind == Failure::Kind::None && slipping) {
        std::cerr << "error: nothing to shrink: " << in
                  << " is valid, or the unvalidated verification catches it\n";
        return code(Status::Usage);
    }
    if (r.failure.kind == Failure::Kind::None) {
        std::cerr << "error: nothing to shrink: " << in
                  << " triangulates (validation skipped) and the exact checker accepts it\n";
        return code(Status::Usage);
    }
    std::string kind = failureKindName(r.failure.kind);
    if (r.failure.kind == Failure::Kind::Forbidden)
        kind += std::string(" ") + forbiddenName(r.failure.reason);
    if (!r.reproduces) {
        std::cerr << "error: " << in << " fails (" << kind
                  << "), but not once written and read back: no repro written\n";
        return code(Status::Internal);
    }
    // The direction only when it is not the default, so the command shown stays short.
    ReproSource source{in, selection.feature >= 0 ? std::to_string(selection.feature) : "",
                       o.flood.up == Up::PlusY ? "" : upName(o.flood.up), out};
    const std::string text = reproJson(polygon, r, source);
    if (!quiet) {
        std::cerr << "shrink: " << kind << (r.inputValid ? " (input valid, kept valid)" : "")
                  << ": " << polygon.vertices.size() << " vertices in " << polygon.rings.size()
                  << " rings -> " << r.polygon.vertices.size() << " vertices in "
                  << r.polygon.rings.size() << " rings (" << r.tries << " runs)\n";
        if (!r.failure.message.empty()) std::cerr << "shrink: " << r.failure.message << "\n";
    }
    Output file(out);
    file.stream() << text;
    Status written = file.commit();
    if (written != Status::Ok) return code(written);
    // Checked the way its user reads it: the file itself when there is one (a FIFO or a
    // device cannot be read back: what went there is the text).
    std::string back = text;
    if (out != "-" && Output::discardable(out) &&
        !readInputFile(out, back, kDefaultMaxInputBytes, "a polygon").ok())
        back.clear();
    if (!classifyText(back, o, r.inputValid).sameClass(r.failure)) {
        std::cerr << "error: " << out << ": the repro written does not fail as " << kind
                  << " when read back\n";
        return code(Status::Internal);
    }
    if (!quiet) std::cerr << "shrink: reproduce with: " << reproduceCommand(r, source) << "\n";
    return code(Status::Ok);
}

// CPU time of this thread, in nanoseconds: steadier than wall time on a loaded machine.
double cpuNs() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e9 + double(t.tv_nsec);
}

// A stream that keeps nothing: the writer's own cost, without the system's.
struct NullBuf : std::streambuf {
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
    int_type overflow(int_type c) override { return traits_type::not_eof(c); }
};

// `flood triangulate IN -o OUT`'s steps one by one, each the median CPU time of `repeat` runs:
// what the command costs beside triangulate() alone.
void benchPipeline(const std::string& in, int repeat, const Options& o, double n) {
    const char* names[] = {"read", "validate", "flood", "check", "write"};
    std::vector<double> t[7];  // the five steps, then the check and writing at once
    for (int k = 0; k < repeat; ++k) {
        double t0 = cpuNs();
        ReadResult rr = readInput(in);
        double t1 = cpuNs();
        if (!rr.diagnostic.ok() || !validate(rr.polygon, in).ok()) return;
        double t2 = cpuNs();
        FloodResult r = triangulate(rr.polygon, nullptr, o);
        double t3 = cpuNs();
        CheckResult c = checkTriangulation(rr.polygon, r.triangles);
        double t4 = cpuNs();
        NullBuf null;
        std::ostream sink(&null);
        writeJson(sink, rr.polygon, r.triangles);
        double t5 = cpuNs();
        if (!c.ok) return;
        // The check and the writing as the command runs them, at once (checkWhileWriting):
        // this thread's CPU time, and the other's (its clock starts with it).
        double other = 0;
        Status s = checkWhileWriting(rr.polygon, r.triangles, true, [&] {
            writeJson(sink, rr.polygon, r.triangles);
            other = cpuNs();
        });
        double t6 = cpuNs();
        if (s != Status::Ok) return;
        double step[] = {t1 - t0, t2 - t1, t3 - t2, t4 - t3, t5 - t4, t6 - t5, other};
        for (int i = 0; i < 7; ++i) t[i].push_back(step[i]);
    }
    double m[7];
    for (int i = 0; i < 7; ++i) {
        std::sort(t[i].begin(), t[i].end());
        m[i] = t[i][t[i].size() / 2];
    }
    double total = 0;
    std::string text = "end to end, CPU time per step (median of " + std::to_string(repeat) + "):";
    for (int i = 0; i < 5; ++i) {
        total += m[i];
        char part[64];
        std::snprintf(part, sizeof part, " %s %.1f", names[i], m[i] / n);
        text += part;
    }
    char tail[96];
    std::snprintf(tail, sizeof tail, " ns/vertex; all %.1f ns/vertex = x%.2f flood\n", total / n,
                  total / m[2]);
    std::cout << text << tail;
    // The command's longest path: read, validate, flood, then the longer of the two threads.
    const double path = m[0] + m[1] + m[2] + std::max(m[5], m[6]);
    char both[192];
    std::snprintf(both, sizeof both,
                  "check and write at once: this thread %.1f, the other %.1f ns/vertex; longest "
                  "path %.1f ns/vertex = x%.2f flood\n",
                  m[5] / n, m[6] / n, path / n, path / m[2]);
    std::cout << both;
}

// The allocator as the command runs it (cold: large blocks mapped afresh, see run()), or as a
// long-running caller's process has it after its first calls (warm: freed memory kept for the
// next call, glibc's dynamic thresholds at their ceiling).
void keepMemory(bool keep) {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, keep ? 32 << 20 : 1 << 20);
    mallopt(M_TRIM_THRESHOLD, keep ? 64 << 20 : 128 << 10);
#else
    (void)keep;
#endif
}
// Gives freed memory back to the system, so the next run faults its pages in anew.
void trimMemory() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

struct Recording : Listener {
    std::vector<Event> events;
    void onEvent(const Event& e) override { events.push_back(e); }
};

int cmdBench(const std::string& in, int repeat, const std::string& up) {
    Polygon polygon;
    Status s = prepare(in, polygon);
    if (s != Status::Ok) return code(s);
    Options o = makeOptions(up);
    FloodResult first = triangulate(polygon, nullptr, o);
    s = judge(polygon, first.triangles, first.diagnostic);
    if (s != Status::Ok) return code(s);
    size_t sink = 0;
    double plain =
        medianNs(repeat, [&] { sink += triangulate(polygon, nullptr, o).triangles.size(); });
    // Full trace recording as `flood trace` and the viewer do it (record(): a fresh log each
    // run), then into one log whose capacity is kept (clear()): the difference is fresh memory.
    size_t events = 0;
    double recorded = medianNs(repeat, [&] {
        Trace t = record(polygon, o);
        sink += t.triangles.size();
        events = t.events.size();
    });
    Recording rec;
    double reused = medianNs(repeat, [&] {
        rec.events.clear();
        sink += triangulate(polygon, &rec, o).triangles.size();
    });
    // What a caller pays: validate() and a fresh triangulate() on the polygon as read.
    double validatedCold = 0, validatedWarm = 0;
    if (in != "-") {  // stdin cannot be read again
        ReadResult raw = readInput(in);
        auto validated = [&](bool cold) {
            std::vector<double> t;
            for (int k = 0; k < repeat; ++k) {
                Polygon p = raw.polygon;
                if (cold) trimMemory();
                auto t0 = std::chrono::steady_clock::now();
                if (validate(p, in).ok()) sink += triangulate(p, nullptr, o).triangles.size();
                t.push_back(
                    std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0)
                        .count());
            }
            std::sort(t.begin(), t.end());
            return t[t.size() / 2];
        };
        validatedCold = validated(true);
        keepMemory(true);
        validated(false);  // the allocator warmed up, as by a caller's earlier calls
        validatedWarm = validated(false);
        keepMemory(false);
    }
    double n = double(std::max<size_t>(1, polygon.vertices.size()));
    // Formatted into std::cout, which keeps the reason of a failed write (flood/io/output.h).
    auto line = [](const char* format, auto... values) {
        char text[256];
        std::snprintf(text, sizeof text, format, values...);
        std::cout << text;
    };
    line("vertices %zu, triangles %zu, events %zu, repeat %d (median time, reading excluded)\n",
         polygon.vertices.size(), first.triangles.size(), events, repeat);
    line("no listener:                    %12.0f ns  %8.1f ns/vertex\n", plain, plain / n);
    line("recording listener, fresh log:  %12.0f ns  %8.1f ns/vertex  (x%.2f)\n", recorded,
         recorded / n, recorded / plain);
    line("recording listener, reused log: %12.0f ns  %8.1f ns/vertex  (x%.2f)\n", reused,
         reused / n, reused / plain);
    if (validatedWarm > 0) {
        line("validated, warm memory:         %12.0f ns  %8.1f ns/vertex  (x%.2f)\n", validatedWarm,
             validatedWarm / n, validatedWarm / plain);
        line("validated, cold memory:         %12.0f ns  %8.1f ns/vertex  (x%.2f)\n", validatedCold,
             validatedCold / n, validatedCold / plain);
    }
    if (in != "-") benchPipeline(in, repeat, o, n);  // stdin cannot be read again
    return sink == 0 && !first.triangles.empty() ? code(Status::Internal) : 0;
}

}  // namespace

int flood::cli::run(int argc, char** argv) {
    takeOverStdout();
    // Large blocks always come from (and go back to) the system: glibc otherwise raises this
    // threshold after the first large free, and what each step of the pipeline (read,
    // validate, flood, check) frees stays resident under the next one's peak.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    // Past a file-size limit, a write fails with EFBIG instead of killing the process, so the
    // temporary output is removed and the reason printed.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"flood: triangulate polygons with holes by flooding (Ronfard & Rossignac 1994)"};
    app.set_version_flag("--version", std::string("flood ") + FLOOD_VERSION);
    app.require_subcommand(1);
    app.footer(
        "Every command takes -q (--quiet: errors only on stderr, no progress line, warnings or "
        "notes) and -v (--verbose: also the time of each stage; check: a line per feature). "
        "Output is plain text, never coloured (docs/CLI.md, \"Quiet, verbose, no colour\").\n");
    std::string in, out = "-", format, up = "+y";
    bool noValidate = false, slipping = false, noExactCheck = false;
    std::string family;
    size_t size = 0;
    uint64_t seed = 1;
    unsigned timeout = 10;
    auto addNoValidate = [&](CLI::App* cmd) {
        cmd->add_flag("--no-validate", noValidate,
                      "Skip validation: feed the polygon to the flood machine as is, so invalid "
                      "input is diagnosed by the machine's forbidden transitions (docs/ERRORS.md); "
                      "the exact check of the output still runs");
    };
    auto addNoExactCheck = [&](CLI::App* cmd) {
        cmd->add_flag("--no-exact-check", noExactCheck,
                      "Skip the exact check of the output: the triangles written are unproven, "
                      "and with --no-validate invalid input may pass unnoticed (the check is about "
                      "a tenth of the time of a large polygon)");
    };
    int repeat = 5;

    // The options every flooding command shares: IN, --up and --no-validate, and the exact
    // check where the command writes triangles or events.
    auto flooding = [&](CLI::App* cmd, const char* inHelp, bool exactCheck) {
        cmd->add_option("IN", in, inHelp)->required();
        addUp(cmd, up);
        addNoValidate(cmd);
        if (exactCheck) addNoExactCheck(cmd);
    };
    const char* const polygonIn = "Input polygon (- for stdin)";

    auto* tri = app.add_subcommand("triangulate", "Triangulate a polygon and write the result");
    flooding(tri, "Input polygon (GeoJSON, ring array or WKT; - for stdin)", true);
    tri->add_option("-o,--output", out, "Output file (- for stdout, the default)");
    tri->add_option("-j,--jobs", jobs,
                    "Threads for one input: a large GeoJSON parsed in pieces, a MultiPolygon's "
                    "parts validated and flooded in parallel, the exact check beside the writing "
                    "(default: every core it may use)")
        ->type_name("N")
        ->check(CLI::Range(1u, 1024u));
    tri->add_option("--format", format,
                    "json, svg, obj, or with GDAL any vector driver or its extension (gpkg, fgb, "
                    "GeoJSON, shp, KML, CSV, ...): a layer of the triangles of each feature "
                    "(default: from the output extension; none or stdout: json)");
    std::string perFeature = "triangles";
    tri->add_option("--per-feature", perFeature,
                    "GIS outputs: one polygon per triangle (triangles, the default) or one "
                    "MultiPolygon per feature (multipolygon)")
        ->check(CLI::IsMember({"triangles", "multipolygon"}));

    auto* trace = app.add_subcommand("trace", "Flood and write the event trace (JSON Lines)");
    flooding(trace, polygonIn, true);
    trace->add_option("-o,--output", out, "Output trace file (- for stdout, the default)");
    std::string traceFormat;
    trace
        ->add_option("--format", traceFormat,
                     "jsonl (JSON Lines, for people and scripts) or bin (compact binary, for "
                     "large traces; the viewer opens both) (default: bin for a .bin output, "
                     "else jsonl)")
        ->check(CLI::IsMember({"jsonl", "bin"}));

    auto* tr = app.add_subcommand("transcript", "Print the paper-style transcript (Fig. 7)");
    flooding(tr, polygonIn, false);
    TranscriptWants want;
    tr->add_flag("--narrate", want.narrate,
                 "One numbered sentence per event: what happened and why");
    auto* quiz = tr->add_flag("--quiz", want.quiz,
                              "A handout: predict the next action. Numbered questions (the state "
                              "before each asked step), then the answers after a form feed");
    quiz->excludes("--narrate");
    tr->add_option("--quiz-actions", want.quizActions,
                   "The actions --quiz asks about, comma separated: raise, bridge, spill, jump, "
                   "fill or all (default all)")
        ->needs(quiz);
    tr->add_option("--answers", want.answers,
                   "Write --quiz's answers to this file instead of after the questions")
        ->needs(quiz);
    tr->add_flag("--table", want.table,
                 "Also print the complete Fig. 10 table: every vertex combination, its states "
                 "or X, this run's counts");

    auto* ver = app.add_subcommand("verify", "Triangulate and check the result exactly");
    flooding(ver, polygonIn, false);

    auto* bench = app.add_subcommand(
        "bench",
        "Median in-process triangulation time: the core alone, with a recording listener, "
        "validated as a caller pays it (validate() + a fresh triangulate(), on warm memory as "
        "a long-running program has it and on cold memory as one command has it), then the "
        "command's steps");
    bench->add_option("IN", in, polygonIn)->required();
    bench->add_option("--repeat", repeat, "Number of timed runs (default 5)")
        ->check(CLI::Range(1, 1000000));
    addUp(bench, up);

    auto* gen = app.add_subcommand(
        "generate",
        "Write a generated polygon (flood/tools/generate.h): a valid family, or an invalid one");
    gen->add_option("FAMILY", family, "Polygon family: " + familyList())->required();
    gen->add_option("SIZE", size, "Approximate vertex count")
        ->required()
        ->check(CLI::Range(size_t(3), size_t(1) << 31));
    gen->add_option("-o,--output", out, "Output file (- for stdout, the default)");
    gen->add_option("--seed", seed, "Random seed (default 1)");

    auto* shr = app.add_subcommand(
        "shrink", "Shrink a failing polygon to a small one that fails the same way");
    shr->add_option("IN", in, polygonIn)->required();
    shr->add_option("-o,--output", out,
                    "Output file for the minimal polygon (- for stdout, the default)");
    shr->add_option("--timeout", timeout, "Seconds before a run counts as a hang (default 10)")
        ->check(CLI::Range(1u, 3600u));
    shr->add_flag("--slipping", slipping,
                  "Shrink an invalid polygon that the unvalidated verification (verify "
                  "--no-validate) passes, keeping it so (docs/ALGORITHM.md §7)");
    addUp(shr, up);

    cli::CheckOptions checkOptions;
    checkOptions.jobs = jobs = availableCores();
    auto* chk = app.add_subcommand("check",
                                   "Check every polygon of a dataset: each feature of "
                                   "each file, folders recursively; a table or --json");
    chk->add_option(
           "FILE", checkOptions.inputs,
           "Files and folders (in folders, recursively: " + cli::folderFormats() + "; - for stdin)")
        ->required();
    chk->add_flag("--json", checkOptions.json,
                  "One JSON document: a record per feature and the summary");
    chk->add_option("--extract", checkOptions.extractDir,
                    "Write each failing feature to DIR/STEM_featureN.json, or, from a GIS dataset, "
                    "as the feature it was (fields, FID, CRS) in its format: "
                    "DIR/STEM_featureFID.gpkg, .shp, ...")
        ->type_name("DIR");
    chk->add_option("--findings", checkOptions.findingsOut,
                    "Write every finding as a GIS layer OUT (.gpkg, .geojson, .fgb, .shp, ...: by "
                    "its extension): a point per finding with its file, layer, fid, name, status, "
                    "reason, ring, vertex and message, and the culprit edges as lines (layer "
                    "finding_edges of a .gpkg, else OUT_edges.EXT beside it)")
        ->type_name("OUT");
    chk->add_option("-j,--jobs", checkOptions.jobs,
                    "Features checked in parallel (default: every core it may use)")
        ->type_name("N")
        ->check(CLI::Range(1u, 1024u));
    chk->add_option("--max-findings", checkOptions.maxFindings,
                    "An invalid feature's findings listed (default 100); the rest are counted")
        ->type_name("N")
        ->check(CLI::Range(size_t(1), size_t(1) << 30));
    addNoValidate(chk);

    for (CLI::App* cmd : {tri, trace, tr, ver, bench, shr, chk})
        cmd->add_option("--max-input-bytes", maxInputBytes,
                        "Refuse inputs larger than this (default 4 GiB; suffixes k, M, G: "
                        "1024-based)")
            ->transform(CLI::AsSizeValue(false))
            // Runs before the size transform (each transform goes in front), which would
            // read -5 as 2^64 - 5 and so accept it.
            ->transform(CLI::Validator(
                [](std::string& v) {
                    size_t first = v.find_first_not_of(" \t");
                    return first != std::string::npos && v[first] == '-'
                               ? "'" + v + "' is not a size: give a positive number of bytes " +
                                     "(suffixes k, M, G)"
                               : std::string();
                },
                ""))
            ->check(CLI::Range(uint64_t(1), UINT64_MAX));
    for (CLI::App* cmd : {tri, trace, tr, ver, bench, shr, chk}) {
        cmd->add_option("--layer", selection.layer,
                        "GIS dataset (through GDAL): the layer to read "
                        "(needed when there are several)")
            ->type_name("NAME");
        cmd->add_option("--feature", selection.feature,
                        "GIS dataset: only the feature with this FID")
            ->type_name("FID")
            ->check(CLI::NonNegativeNumber);
        cmd->add_option(
               "--where", selection.where,
               "GIS dataset: only the features this OGR SQL filter keeps, e.g. \"name = 'x'\"")
            ->type_name("FILTER");
    }

    // -q and -v on every command (verbosity.h); shrink's -q was first, so it keeps its words.
    bool quiet = false, verbose = false;
    for (CLI::App* cmd : {tri, trace, tr, ver, bench, gen, shr, chk}) {
        auto* q = cmd->add_flag(
            "-q,--quiet", quiet,
            "Errors only on stderr: no progress line, warnings, notes or summary there");
        cmd->add_flag("-v,--verbose", verbose,
                      "More on stderr: the time of each stage (read, validate, flood, check and "
                      "write); check: a line per feature")
            ->excludes(q);
    }

    // CLI11 would say "A subcommand is required" for a misspelt one: name it and the choices.
    if (argc > 1 && argv[1][0] != '-') {
        auto cmds = app.get_subcommands([](CLI::App*) { return true; });
        bool known = false;
        std::string names;
        for (CLI::App* c : cmds) {
            known |= c->get_name() == argv[1];
            names += (names.empty() ? "" : ", ") + c->get_name();
        }
        if (!known) {
            std::string name = argv[1];
            if (name.size() > 60) name.replace(60, std::string::npos, "\u2026");
            std::cerr << "error: unknown subcommand '" << name << "'; expected one of " << names
                      << "\n";
            return code(Status::Usage);
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return code(Status::Usage);
    }
    verbosity = quiet ? Verbosity::Quiet : verbose ? Verbosity::Verbose : Verbosity::Normal;
    if (selection.any() && !gdal::built()) {
        std::cerr << "error: --layer, --feature and --where read GIS datasets through GDAL: this "
                     "flood was built without it (install libgdal-dev, reconfigure)\n";
        return code(Status::Usage);
    }
    // -o naming the input (shrink IN -o IN) would replace the very file being read.
    if ((tri->parsed() || trace->parsed() || shr->parsed()) && out != "-" && sameFile(in, out)) {
        std::cerr << "error: -o " << out << " is the input file " << (in == "-" ? "<stdin>" : in)
                  << ": refusing to overwrite the input; write the output elsewhere\n";
        return code(Status::Usage);
    }
    try {
        if (tri->parsed())
            return cmdTriangulate(in, out, format, perFeature == "multipolygon", up, !noValidate,
                                  !noExactCheck);
        if (trace->parsed()) {
            bool binary = traceFormat == "bin" || (traceFormat.empty() && out.size() > 4 &&
                                                   out.compare(out.size() - 4, 4, ".bin") == 0);
            return cmdTrace(in, out, up, !noValidate, !noExactCheck, binary);
        }
        if (tr->parsed()) return cmdTranscript(in, want, up, !noValidate);
        if (gen->parsed()) return cmdGenerate(family, size, seed, out);
        if (shr->parsed()) return cmdShrink(in, out, up, timeout, slipping, quiet);
        if (ver->parsed()) return cmdVerify(in, up, !noValidate);
        if (bench->parsed()) return cmdBench(in, repeat, up);
        if (chk->parsed()) {
            checkOptions.maxInputBytes = maxInputBytes;
            checkOptions.validate = !noValidate;
            checkOptions.selection = selection;
            if (!checkOptions.findingsOut.empty())
                if (int c = cli::findingsFormat(checkOptions.findingsOut)) return c;
            return cli::runCheck(checkOptions);
        }
    } catch (const std::exception& e) {
        std::cerr << "internal error: " << e.what() << "\n";
        return code(Status::Internal);
    }
    return code(Status::Usage);
}
