// An open as a background job: read, validate, flood, check, prepare (open_job.h).
#include "open_job.h"

#include <algorithm>
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
        case OpenPhase::Prepare: return "preparing";
        case OpenPhase::Done: break;
    }
    return "done";
}

std::string openNote(OpenPhase p, size_t vertices) {
    return std::string(openPhaseName(p)) + "... " + std::to_string(vertices) + " vertices";
}

// ---- RunSteps ---------------------------------------------------------------------------
RunSteps::RunSteps(Polygon polygon, std::string name, Up up, std::optional<Diagnostic> given)
    : name_(std::move(name)), up_(up), polygon_(std::move(polygon)) {
    run_.trace.up = up;  // an empty canvas too: the dial's direction is kept
    if (given) {
        run_.input = std::move(*given);
        // Not validated here; its findings are still every finding of an invalid input.
        if (!run_.input.ok() && !polygon_.vertices.empty())
            run_.findings = validateAll(polygon_, name_);
    } else {
        polygon_.splits.clear();  // validate() finds the polygon's own T-junctions
    }
    next_ = polygon_.vertices.empty() ? OpenPhase::Prepare
            : given                   ? OpenPhase::Flood
                                      : OpenPhase::Validate;
}

RunSteps::RunSteps(Trace trace, std::string name)
    : name_(std::move(name)), up_(trace.up), recorded_(true) {
    run_.trace = std::move(trace);
}

OpenPhase RunSteps::after(OpenPhase p) const {
    if (p == OpenPhase::Validate && recorded_) return OpenPhase::Check;
    return OpenPhase(int(p) + 1);
}

// Every finding of an invalid input, beside validate()'s verdict.
static void validateInto(Polygon& polygon, const std::string& name, FloodedRun& run) {
    run.input = validate(polygon, name);
    if (!run.input.ok()) run.findings = validateAll(polygon, name);
}

void RunSteps::step() {
    const Trace& T = run_.trace;
    switch (next_) {
        case OpenPhase::Validate:
            if (!recorded_) {
                validateInto(polygon_, name_, run_);
            } else if (!T.polygon.vertices.empty()) {
                Polygon copy = T.polygon;  // the trace holds the run: its polygon stays as recorded
                validateInto(copy, name_, run_);
            }
            break;
        case OpenPhase::Flood:
            try {
                // Its log reserved, its slices, its log trimmed: each a step of its own.
                if (!recording_) {
                    recording_ = std::make_unique<Recording>(polygon_, Options{up_});
                    floodEnded_ = false;
                    return;
                }
                if (!floodEnded_) {
                    floodEnded_ = !recording_->advance(kFloodSlice);
                    return;
                }
                run_.trace = recording_->take();
            } catch (const std::exception& ex) {
                run_.trace.diagnostic = {Status::Internal, name_ + ": " + ex.what()};
            }
            recording_.reset();
            break;
        case OpenPhase::Check:
            // The exact checker is the costly half of judging a run: here, off the UI thread.
            if (!recorded_ || !T.polygon.vertices.empty() || !T.diagnostic.ok())
                run_.judged =
                    judgeRun(recorded_ ? T.polygon : polygon_, T.triangles, T.diagnostic, name_);
            break;
        case OpenPhase::Prepare:
            if (!recorded_) {
                run_.trace.polygon = std::move(polygon_);
                run_.trace.up = up_;
            }
            if (!preparing_) preparing_.emplace(std::move(run_), name_);
            if (preparing_->step()) return;  // the phase goes on
            prepared_ = preparing_->take();
            preparing_.reset();
            break;
        case OpenPhase::Read:
        case OpenPhase::Done: return;
    }
    next_ = after(next_);
}

double RunSteps::phaseDone() const {
    if (recording_)
        return std::min(0.99, recording_->steps() / double(recording_->expectedSteps()));
    if (preparing_) return preparing_->done() / double(PrepareSteps::kParts);
    return 0;
}

static bool runAll(RunSteps& steps, PreparedRun& run, const EnterPhase& enter) {
    OpenPhase entered = OpenPhase::Done;
    for (OpenPhase p; (p = steps.next()) != OpenPhase::Done; steps.step())
        if (p != entered && enter && !enter(entered = p)) return false;
    run = steps.take();
    return true;
}

bool floodRun(Polygon polygon, const std::string& name, Up up, PreparedRun& run,
              const EnterPhase& enter, std::optional<Diagnostic> given) {
    RunSteps steps(std::move(polygon), name, up, std::move(given));
    return runAll(steps, run, enter);
}

bool judgeTrace(Trace trace, const std::string& name, PreparedRun& run, const EnterPhase& enter) {
    RunSteps steps(std::move(trace), name);
    return runAll(steps, run, enter);
}

// ---- OpenJob ----------------------------------------------------------------------------
void OpenJob::start(Request request) {
    request_ = std::move(request);
    phase_.store(int(OpenPhase::Read), std::memory_order_release);
    read_ = {};
    outlineReady_.store(false, std::memory_order_relaxed);
    outline_ = {};
    warnings_.clear();
    complete_ = false;
    steps_.reset();
    outlining_.reset();
    entered_ = OpenPhase::Read;
    job_.startSteps([this](Job& job) { return step(job); });
}

bool OpenJob::enter(Job& job, OpenPhase p) {
    job.setProgress(uint64_t(p) * kPerPhase);
    phase_.store(int(p), std::memory_order_release);  // what the phase before wrote is visible
    if (request_.onPhase) request_.onPhase(request_.path, p);
    return !job.cancelRequested();
}

void OpenJob::finish(Job& job) {
    job.setProgress(job.total());
    phase_.store(int(OpenPhase::Done), std::memory_order_release);
}

bool OpenJob::step(Job& job) {
    if (!steps_) {
        job.setTotal(kTotal);
        if (!enter(job, OpenPhase::Read)) return false;
        read(job);
        if (!steps_) finish(job);  // the read failed: read_ says why
        return steps_.has_value();
    }
    if (outlining_) {  // still the read's phase: its outline a part a step
        if (!outlining_->step()) {
            outline_ = outlining_->take();
            outlining_.reset();
            outlineReady_.store(true, std::memory_order_release);
        }
        return true;
    }
    const OpenPhase p = steps_->next();
    if (p == OpenPhase::Done) {
        complete_ = true;
        finish(job);
        return false;
    }
    if (p != entered_ && !enter(job, entered_ = p)) return false;
    steps_->step();
    if (steps_->next() == p)  // the phase goes on: how far it is
        job.setProgress(uint64_t(p) * kPerPhase + uint64_t(steps_->phaseDone() * kPerPhase));
    return true;
}

void OpenJob::read(Job& job) {
    const std::string& path = request_.path;
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
    if (!read_.ok()) return;
    warnings_ = std::move(r.warnings);
    // The outline to show meanwhile, prepared in the next steps: a copy of the polygon, since
    // validation records T-junctions in its own.
    FloodedRun outline;
    outline.trace.polygon = request_.trace ? trace.polygon : r.polygon;
    outline.trace.up = request_.trace ? trace.up : request_.up;
    const size_t n = outline.trace.polygon.vertices.size();
    outlining_.emplace(std::move(outline), path, openNote(OpenPhase::Validate, n));
    if (request_.trace) steps_.emplace(std::move(trace), path);
    else steps_.emplace(std::move(r.polygon), path, request_.up);
}

}  // namespace flood::view
