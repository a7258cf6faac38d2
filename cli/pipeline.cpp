// The pipeline every command that floods follows (pipeline.h).
#include "pipeline.h"

#include <iostream>

#include "check.h"  // grouped()
#include "flood/check/touches.h"
#include "flood/io/gdal/read_any.h"

namespace flood::cli {

uint64_t maxInputBytes = kDefaultMaxInputBytes;
Selection selection;

ReadResult readInput(const std::string& path) {
    return gdal::readAny(path, selection, maxInputBytes);
}

Status prepare(const std::string& path, Polygon& polygon, bool check, bool floodInvalid) {
    ReadResult rr = readInput(path);
    for (const std::string& w : rr.warnings) std::cerr << "warning: " << w << "\n";
    if (rr.warningsOmitted)
        std::cerr << "warning: " << (path == "-" ? "<stdin>" : path) << ": \u2026 and "
                  << grouped(rr.warningsOmitted) << " more warnings like these\n";
    if (!rr.diagnostic.ok()) {
        std::cerr << "error: " << rr.diagnostic.message << "\n";
        return rr.diagnostic.status;
    }
    Diagnostic d = check ? validate(rr.polygon, path == "-" ? "<stdin>" : path) : Diagnostic{};
    if (!d.ok()) {
        std::cerr << "error: invalid polygon: " << d.message << "\n";
        if (!floodInvalid) return d.status;
        std::cerr << "note: flooding it anyway (as --no-validate), up to where the machine "
                     "stops\n";
        check = false;
    }
    if (!check && !findTouches(rr.polygon).complete)
        std::cerr << "warning: " << path << ": the search for T-junctions gave up (work cap): "
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
