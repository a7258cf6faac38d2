// An open as a background job: read, validate, flood, check (open_job.h).
#include "open_job.h"

#include <utility>

#include "flood/io/gdal/read_any.h"
#include "flood/log/trace_io.h"

namespace flood::view {

const char* openPhaseName(OpenPhase p) {
    switch (p) {
        case OpenPhase::Read: return "reading";
        case OpenPhase::Validate: return "validating";
        case OpenPhase::Flood: return "flooding";
        case OpenPhase::Check: return "checking";
        case OpenPhase::Done: break;
    }
    return "done";
}

static bool go(const EnterPhase& enter, OpenPhase p) { return !enter || enter(p); }

// Every finding of an invalid input, beside validate()'s verdict (off the UI thread, as the
// flood is).
static void validateInto(Polygon& polygon, const std::string& name, FloodedRun& run) {
    run.input = validate(polygon, name);
    if (!run.input.ok()) run.findings = validateAll(polygon, name);
}

bool floodRun(Polygon polygon, const std::string& name, Up up, FloodedRun& run,
              const EnterPhase& enter) {
    polygon.splits.clear();  // validate() finds the polygon's own T-junctions
    run.trace.up = up;       // an empty canvas too: the dial's direction is kept
    if (!polygon.vertices.empty()) {
        if (!go(enter, OpenPhase::Validate)) return false;
        validateInto(polygon, name, run);
        if (!go(enter, OpenPhase::Flood)) return false;
        try {
            run.trace = record(polygon, Options{up});
        } catch (const std::exception& ex) {
            run.trace.diagnostic = {Status::Internal, name + ": " + ex.what()};
        }
        // The exact checker is the costly half of adopting a run: judged here too.
        if (!go(enter, OpenPhase::Check)) return false;
        run.judged = judgeRun(polygon, run.trace.triangles, run.trace.diagnostic, name);
    }
    run.trace.polygon = std::move(polygon);
    run.trace.up = up;
    return true;
}

bool judgeTrace(Trace trace, const std::string& name, FloodedRun& run, const EnterPhase& enter) {
    if (!go(enter, OpenPhase::Validate)) return false;
    if (!trace.polygon.vertices.empty()) {
        Polygon copy = trace.polygon;  // the trace holds the run: its polygon stays as recorded
        validateInto(copy, name, run);
    }
    if (!go(enter, OpenPhase::Check)) return false;
    const Polygon& P = trace.polygon;
    if (!P.vertices.empty() || !trace.diagnostic.ok())
        run.judged = judgeRun(P, trace.triangles, trace.diagnostic, name);
    run.trace = std::move(trace);
    return true;
}

void OpenJob::start(Request request) {
    request_ = std::move(request);
    phase_.store(int(OpenPhase::Read), std::memory_order_release);
    read_ = {};
    outline_ = {};
    warnings_.clear();
    complete_ = false;
    run_ = {};
    job_.start([this](Job& job) { work(job); });
}

bool OpenJob::enter(Job& job, OpenPhase p) {
    job.setProgress(uint64_t(p) * kPerPhase);
    phase_.store(int(p), std::memory_order_release);  // what the phase before wrote is visible
    if (request_.onPhase) request_.onPhase(request_.path, p);
    return !job.cancelRequested();
}

void OpenJob::work(Job& job) {
    job.setTotal(uint64_t(OpenPhase::Done) * kPerPhase);
    const std::string& path = request_.path;
    if (!enter(job, OpenPhase::Read)) return;
    // The bytes read move the bar through the read's share (a 10⁶-vertex face is ~40 MB).
    ReadProgress reading;
    reading.changed = [&] {
        const uint64_t total = reading.bytesTotal, read = reading.bytesRead;
        if (total) job.setProgress(std::min(read, total) * (kPerPhase - 1) / total);
    };
    ReadResult r;
    Trace trace;
    try {
        if (request_.trace) r.diagnostic = readTraceFile(path, trace);
        else
            r = gdal::readAny(path, {request_.gisLayer, -1, request_.gisWhere},
                              kDefaultMaxInputBytes, &reading);
    } catch (const std::exception& ex) {
        r.diagnostic = {Status::Malformed, path + ": " + ex.what()};
    }
    read_ = r.diagnostic;
    if (!read_.ok()) {
        job.setProgress(job.total());
        phase_.store(int(OpenPhase::Done), std::memory_order_release);
        return;
    }
    warnings_ = std::move(r.warnings);
    // The outline to show meanwhile: a copy, since validation records T-junctions in its own.
    outline_ = request_.trace ? trace.polygon : r.polygon;
    auto next = [&](OpenPhase p) { return enter(job, p); };
    complete_ = request_.trace ? judgeTrace(std::move(trace), path, run_, next)
                               : floodRun(std::move(r.polygon), path, request_.up, run_, next);
    if (!complete_) return;
    job.setProgress(job.total());
    phase_.store(int(OpenPhase::Done), std::memory_order_release);
}

}  // namespace flood::view
