// The `flood` command-line tool: triangulate, trace, transcript, verify, bench.
//
// Command-line parsing uses CLI11: a Debian package (libcli11-dev), header-only, with
// subcommands and generated --help, so no hand-written argument parsing.
//
// Every command that floods follows the same pipeline (docs/ERRORS.md):
//   read (warnings to stderr; Malformed -> exit 3) -> validate (Invalid -> exit 4, nothing
//   written) -> flood (Forbidden -> exit 5) -> exact check of our own output (failure -> exit 6)
//   -> write. Exit codes are flood::Status values. "-" means stdin for input, stdout for output.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "checker.h"
#include "flood.h"
#include "io.h"
#include "replay.h"
#include "trace_io.h"
#include "transcript.h"
#include "verify.h"

namespace {

using namespace flood;

int code(Status s) { return int(s); }

// Reads and validates; on failure prints the diagnostic and returns its status.
Status prepare(const std::string& path, Polygon& polygon) {
    ReadResult rr = readPolygonFile(path);
    for (const std::string& w : rr.warnings) std::cerr << "warning: " << w << "\n";
    if (!rr.diagnostic.ok()) {
        std::cerr << "error: " << rr.diagnostic.message << "\n";
        return rr.diagnostic.status;
    }
    Diagnostic d = validate(rr.polygon, path == "-" ? "<stdin>" : path);
    if (!d.ok()) {
        std::cerr << "error: invalid polygon: " << d.message << "\n";
        return d.status;
    }
    polygon = std::move(rr.polygon);
    return Status::Ok;
}

// Checks a finished run. Forbidden -> 5 (its explanation), checker rejects -> 6.
Status judge(const Polygon& polygon, const std::vector<Triangle>& triangles,
             const Diagnostic& run) {
    if (!run.ok()) {
        std::cerr << "error: flooding stopped in a forbidden state: " << run.message << "\n";
        return run.status;
    }
    CheckResult c = checkTriangulation(polygon, triangles);
    if (!c.ok) {
        std::cerr << "internal error: the exact checker rejects our triangulation: " << c.reason
                  << "\n";
        return Status::Internal;
    }
    return Status::Ok;
}

// Writes `text` to `path` ("-" is stdout) in one go, so failures leave no partial file.
Status writeOut(const std::string& path, const std::string& text) {
    if (path == "-") {
        std::cout << text << std::flush;
        return std::cout ? Status::Ok : Status::Malformed;
    }
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        std::cerr << "error: " << path << ": cannot write output file\n";
        return Status::Malformed;
    }
    return Status::Ok;
}

Options makeOptions(const std::string& up) {
    Options o;
    if (up == "-y") o.up = Up::MinusY;
    else if (up == "+x" || up == "x") o.up = Up::PlusX;
    else if (up == "-x") o.up = Up::MinusX;
    else o.up = Up::PlusY;
    return o;
}

void addUp(CLI::App* cmd, std::string& up) {
    cmd->add_option("--up", up,
                    "The vertical that the water rises along: +y (default), -y, +x, -x. "
                    "Write --up=-y (with '=') for the negative ones.")
        ->check(CLI::IsMember({"+y", "y", "-y", "+x", "x", "-x"}));
}

int cmdTriangulate(const std::string& in, const std::string& out, std::string format,
                   const std::string& up) {
    Polygon polygon;
    Status s = prepare(in, polygon);
    if (s != Status::Ok) return code(s);
    FloodResult r = triangulate(polygon, nullptr, makeOptions(up));
    s = judge(polygon, r.triangles, r.diagnostic);
    if (s != Status::Ok) return code(s);
    if (format.empty()) {
        auto ends = [&](const char* ext) {
            std::string e = ext;
            return out.size() >= e.size() && out.compare(out.size() - e.size(), e.size(), e) == 0;
        };
        format = ends(".svg") ? "svg" : ends(".obj") ? "obj" : "json";
    }
    std::ostringstream ss;
    if (format == "svg") writeSvg(ss, polygon, r.triangles);
    else if (format == "obj") writeObj(ss, polygon, r.triangles);
    else writeJson(ss, polygon, r.triangles);
    return code(writeOut(out, ss.str()));
}

int cmdTrace(const std::string& in, const std::string& out, const std::string& up) {
    Polygon polygon;
    Status s = prepare(in, polygon);
    if (s != Status::Ok) return code(s);
    Trace t = record(polygon, makeOptions(up));
    s = judge(polygon, t.triangles, t.diagnostic);
    // A trace of a forbidden run is exactly what one wants to look at: write it anyway,
    // but still exit with the failure status.
    if (s == Status::Internal) t.diagnostic = {Status::Internal, "the exact checker rejects the result"};
    std::ostringstream ss;
    writeTrace(ss, t);
    Status w = writeOut(out, ss.str());
    return code(s != Status::Ok ? s : w);
}

int cmdTranscript(const std::string& in, bool narrate, const std::string& up) {
    Polygon polygon;
    Status s = prepare(in, polygon);
    if (s != Status::Ok) return code(s);
    Trace t = record(polygon, makeOptions(up));
    Status j = judge(polygon, t.triangles, t.diagnostic);
    if (j == Status::Internal) return code(j);  // never narrate a wrong triangulation
    if (!narrate) {
        std::cout << transcript(t.events) << "\n";
    } else {
        auto f = [](Index i) { return i == kNone ? std::string("-") : std::to_string(i); };
        for (const Event& e : t.events) {
            std::cout << "step " << e.step << ": " << actionName(e.action) << " (part " << e.part
                      << ", " << (e.side == Side::Left ? "Left" : "Right") << ")  fingers L "
                      << f(e.after.left) << " R " << f(e.after.right) << " NL "
                      << f(e.after.nextLeft) << " NR " << f(e.after.nextRight);
            if (e.triangleCount)
                std::cout << "  triangles " << triangleRange(e.firstTriangle, e.triangleCount);
            if (e.action == Action::Forbidden) std::cout << "  " << forbiddenText(e.reason);
            std::cout << "  -- " << actionMeaning(e.action) << "\n";
        }
    }
    return code(j);
}

int cmdVerify(const std::string& in, const std::string& up) {
    Polygon polygon;
    Status s = prepare(in, polygon);
    if (s != Status::Ok) return code(s);
    // The paper's verification (§6): flood the polygon and its complement in a box, and check
    // both exactly.
    Verification v = verify(polygon, makeOptions(up));
    std::cout << v.summary() << "\n";
    if (!v.ok()) {
        std::cout << "verify: FAILED\n";
        return code(Status::VerifyFailed);
    }
    std::cout << "verify: ok: " << polygon.vertices.size() << " vertices in " << polygon.rings.size()
              << " rings\n";
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
    double plain = medianNs(repeat, [&] { sink += triangulate(polygon, nullptr, o).triangles.size(); });
    Recording rec;
    double recorded = medianNs(repeat, [&] {
        rec.events.clear();
        sink += triangulate(polygon, &rec, o).triangles.size();
    });
    double n = double(std::max<size_t>(1, polygon.vertices.size()));
    std::printf("vertices %zu, triangles %zu, events %zu, repeat %d\n", polygon.vertices.size(),
                first.triangles.size(), rec.events.size(), repeat);
    std::printf("no listener:        %12.0f ns  %8.1f ns/vertex\n", plain, plain / n);
    std::printf("recording listener: %12.0f ns  %8.1f ns/vertex\n", recorded, recorded / n);
    return sink == 0 && !first.triangles.empty() ? code(Status::Internal) : 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"flood: triangulate polygons with holes by flooding (Ronfard & Rossignac 1994)"};
    app.require_subcommand(1);
    std::string in, out = "-", format, up = "+y";
    bool narrate = false;
    int repeat = 5;

    auto* tri = app.add_subcommand("triangulate", "Triangulate a polygon and write the result");
    tri->add_option("IN", in, "Input polygon (GeoJSON, ring array or WKT; - for stdin)")->required();
    tri->add_option("-o,--output", out, "Output file (- for stdout, the default)");
    tri->add_option("--format", format, "json, svg or obj (default: from the output extension, else json)")
        ->check(CLI::IsMember({"json", "svg", "obj"}));
    addUp(tri, up);

    auto* trace = app.add_subcommand("trace", "Flood and write the event trace (JSON Lines)");
    trace->add_option("IN", in, "Input polygon (- for stdin)")->required();
    trace->add_option("-o,--output", out, "Output trace file (- for stdout, the default)");
    addUp(trace, up);

    auto* tr = app.add_subcommand("transcript", "Print the paper-style transcript (Fig. 7)");
    tr->add_option("IN", in, "Input polygon (- for stdin)")->required();
    tr->add_flag("--narrate", narrate, "One line per event: step, action, fingers, triangles");
    addUp(tr, up);

    auto* ver = app.add_subcommand("verify", "Triangulate and check the result exactly");
    ver->add_option("IN", in, "Input polygon (- for stdin)")->required();
    addUp(ver, up);

    auto* bench = app.add_subcommand("bench", "Median in-process triangulation time");
    bench->add_option("IN", in, "Input polygon (- for stdin)")->required();
    bench->add_option("--repeat", repeat, "Number of timed runs (default 5)")
        ->check(CLI::Range(1, 1000000));
    addUp(bench, up);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return code(Status::Usage);
    }
    try {
        if (tri->parsed()) return cmdTriangulate(in, out, format, up);
        if (trace->parsed()) return cmdTrace(in, out, up);
        if (tr->parsed()) return cmdTranscript(in, narrate, up);
        if (ver->parsed()) return cmdVerify(in, up);
        if (bench->parsed()) return cmdBench(in, repeat, up);
    } catch (const std::exception& e) {
        std::cerr << "internal error: " << e.what() << "\n";
        return code(Status::Internal);
    }
    return code(Status::Usage);
}
