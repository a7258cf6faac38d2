// The pipeline every command that floods follows (pipeline.h).
#include "pipeline.h"

#include <iostream>

#include "check.h"  // grouped()
#include "flood/check/touches.h"
#include "verbosity.h"
#ifdef FLOOD_GDAL
#include "flood/io/gdal/gdal_io.h"
#endif

namespace flood::cli {

uint64_t maxInputBytes = kDefaultMaxInputBytes;
Selection selection;

ReadResult readInput(const std::string& path) {
#ifdef FLOOD_GDAL
    gdal::Selection s{selection.layer, selection.feature, selection.where};
    if (gdal::handles(path, s)) return gdal::readPolygon(path, s);
#endif
    return readPolygonFile(path, maxInputBytes);
}

Status prepare(const std::string& path, Polygon& polygon, bool check, bool floodInvalid) {
    Stopwatch watch;
    ReadResult rr = readInput(path);
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
    Diagnostic d = check ? validate(rr.polygon, name) : Diagnostic{};
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
    if (!run.ok()) {
        std::cerr << "error: flooding stopped in a forbidden state: " << run.message << "\n";
        return run.status;
    }
    if (!exactCheck) return Status::Ok;
    CheckResult c = checkTriangulation(polygon, triangles, triangleCheck);
    if (!c.ok) {
        if (validated)
            std::cerr << "internal error: the exact checker rejects our triangulation: " << c.reason
                      << "\n";
        else
            std::cerr << "error: the exact checker rejects our triangulation: " << c.reason
                      << " (validation was skipped; the check of the output caught it: the input "
                         "is probably invalid, run without --no-validate to see why)\n";
        return Status::Internal;
    }
    return Status::Ok;
}

Options makeOptions(const std::string& up) {
    Options o;
    std::string why;
    parseUp(up, o.up, why);  // addUp's check has accepted it
    return o;
}

}  // namespace flood::cli
