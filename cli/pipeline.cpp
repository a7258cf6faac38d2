// The pipeline every command that floods follows (pipeline.h).
#include "pipeline.h"

#include <iostream>

#include "check.h"  // grouped()
#include "flood/check/touches.h"
#include "flood/io/gdal/read_any.h"
#include "task_runner.h"
#include "verbosity.h"

namespace flood::cli {

uint64_t maxInputBytes = kDefaultMaxInputBytes;
Selection selection;
unsigned jobs = 1;

ReadResult readInput(const std::string& path, const TaskRunner& run) {
    return gdal::readAny(path, selection, maxInputBytes, nullptr, run);
}

Status prepare(const std::string& path, Polygon& polygon, bool check, bool floodInvalid) {
    Stopwatch watch;
    ReadResult rr = readInput(path, threadRunner(jobs));
    const std::string name = path == "-" ? "<stdin>" : path;
    detail() << "read: " << name << ": " << rr.polygon.vertices.size() << " vertices, "
             << rr.polygon.rings.size() << (rr.polygon.rings.size() == 1 ? " ring, " : " rings, ")
             << timeText(watch.lap()) << "\n";
    for (const std::string& w : rr.warnings) warning() << w << "\n";
    if (rr.warningsOmitted)
        warning() << name << ": \u2026 and " << grouped(rr.warningsOmitted)
                  << " more warnings like these\n";
    if (!rr.diagnostic.ok()) {
        std::cerr << "error: " << rr.diagnostic.message << "\n";
        return rr.diagnostic.status;
    }
    Diagnostic d = check ? validate(rr.polygon, name, threadRunner(jobs)) : Diagnostic{};
    if (check) detail() << "validate: " << timeText(watch.lap()) << "\n";
    if (!d.ok()) {
        std::cerr << "error: invalid polygon: " << d.message << "\n";
        if (!floodInvalid) return d.status;
        note() << "note: flooding it anyway (as --no-validate), up to where the machine "
                  "stops\n";
        check = false;
    }
    if (!check && !findTouches(rr.polygon).complete)
        warning() << path << ": the search for T-junctions gave up (work cap): "
                  << "the polygon is flooded without them\n";
    polygon = std::move(rr.polygon);
    return d.status;
}

Status judge(const Polygon& polygon, const std::vector<Triangle>& triangles, const Diagnostic& run,
             bool validated, bool exactCheck, const std::function<TriangleCheck()>& triangleCheck) {
    Judgement j = judgeRun(polygon, triangles, run, "", exactCheck, triangleCheck);
    if (j.verdict == Verdict::Forbidden)
        std::cerr << "error: flooding stopped in a forbidden state: " << run.message << "\n";
    else if (j.verdict == Verdict::Checker && validated)
        std::cerr << "internal error: the exact checker rejects our triangulation: "
                  << j.check.reason << "\n";
    else if (j.verdict == Verdict::Checker)
        std::cerr << "error: the exact checker rejects our triangulation: " << j.check.reason
                  << " (validation was skipped; the check of the output caught it: the input "
                     "is probably invalid, run without --no-validate to see why)\n";
    return j.diagnostic.status;
}

Options makeOptions(const std::string& up) {
    Options o;
    std::string why;
    parseUp(up, o.up, why);  // addUp's check has accepted it
    return o;
}

}  // namespace flood::cli
