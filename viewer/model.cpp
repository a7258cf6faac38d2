// The model's run: what an open or an edit adopts (prepared_run.h), its verdict, the
// invariant scan.
#include "model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <utility>

#include "flood/check/diagnostic_where.h"
#include "flood/geometry/predicates.h"
#include "flood/io/gdal/read_any.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "view_fit.h"

namespace flood::view {

Model::Model() : trace_(std::make_unique<Trace>()), replay_(std::make_unique<Replay>(*trace_)) {}

Model::~Model() { cancelInvariants(); }

void Model::adopt(PreparedRun run) {
    note_ = std::move(run.note);
    errorView_ = false;
    feature_ = kNoFeature;  // openFeature / openShrunk set these again after adopting
    origin_.clear();
    // Everything was prepared with the run (prepared_run.h): here it is moved in. The replay
    // points into the trace: replace both together, replay first.
    replay_.reset();
    trace_ = std::move(run.trace);
    replay_ = std::move(run.replay);
    input_ = std::move(run.input);
    classes_ = std::move(run.classes);
    transcript_ = std::move(run.transcript);
    triangleStep_ = std::move(run.triangleStep);
    setVerdict(std::move(run.verdict));
    transitions_ = run.transitions;
    canvas_ = std::move(run.canvas);
    needsFit_ = true;
    step_ = 0;
    replay_->seek(0);
    timeline = {};
    findBreakpointSteps();
    // Land where the trouble is: the forbidden event, so its state is on screen.
    forbiddenStep_ = run.forbiddenStep;
    if (forbiddenStep_) seek(forbiddenStep_);
    landedStep_ = step_;
    landingPending_ = true;
    scanWaiting_ = std::exchange(deferScan_, false);    // live editing: started once the drag ends
    if (scanWaiting_ || !note_.empty()) scan_.reset();  // no scan yet, or no run to scan
    else startInvariants();
}

void Model::setVerdict(RunVerdict v) {
    verdictLines_ = std::move(v.lines);
    verdict_ = std::move(v.text);
    check_ = std::move(v.check);
    error_ = std::move(v.error);
    firstErrorStep_ = v.firstErrorStep;
    findings_ = std::move(v.findings);
    findingsOmitted_ = v.findingsOmitted;
    findingsComplete_ = v.findingsComplete;
    currentFinding_ = 0;
    offenders_ = std::move(v.offenders);
}

bool Model::landOnFirstViolation() {
    if (!landingPending_ || !invariantsDone()) return false;
    landingPending_ = false;
    if (step_ != landedStep_ || firstViolationStep() == 0) return false;
    seek(firstViolationStep());
    return true;
}

void Model::startInvariants() {
    scan_.reset();  // joins the scan before, which writes found_
    found_.clear();
    // In steps of 512 events (checkInvariants' loop, cut): a thread runs them one after
    // another; the web page, a slice of them between frames.
    // Its own replay and checker, built in its first step (off the UI thread): it only steps
    // forward, so one keyframe will do.
    std::shared_ptr<Replay> replay;
    std::shared_ptr<InvariantChecker> checker;
    scan_.startSteps([this, replay, checker, s = uint32_t(0)](Job& job) mutable {
        if (!replay) {
            replay = std::make_shared<Replay>(*trace_, UINT32_MAX);
            checker = std::make_shared<InvariantChecker>(*trace_);
        }
        const uint32_t end = std::min<uint32_t>(s + 512, uint32_t(replay->size()));
        while (s < end) {
            Violation v = checker->check(replay->seek(++s));
            if (!v.ok()) {
                v.step = s;
                found_.push_back(std::move(v));
            }
        }
        job.setProgress(s);
        return s < replay->size();
    });
}

bool Model::invariantsDone() const {
    // Nothing to check before the first open; a deferred scan (a drag) has found nothing yet.
    return !scanWaiting_ && (!scan_.started() || scan_.done());
}

Model::InvariantStatus Model::invariantStatus() const {
    // An outline has no run, nor has a file that could not be read: an empty trace breaks
    // nothing, and "none broken" would claim a check of a flood that never was.
    if (outlineOnly() || steps() == 0) return InvariantStatus::NoRun;
    if (!invariantsDone()) return InvariantStatus::Checking;
    if (!found_.empty()) return InvariantStatus::Broken;
    return invariantProgress() < steps() ? InvariantStatus::Cancelled : InvariantStatus::NoneBroken;
}

const std::vector<Violation>& Model::violations() const {
    static const std::vector<Violation> none;
    return invariantsDone() ? found_ : none;
}

uint32_t Model::firstViolationStep() const {
    const std::vector<Violation>& v = violations();
    return v.empty() ? 0 : v.front().step;
}

bool Model::failed() const {
    return std::any_of(verdictLines_.begin(), verdictLines_.end(),
                       [](const VerdictLine& l) { return l.failure(); });
}

int Model::exitCode() const {
    if (!openDiag_.ok()) return int(openDiag_.status);
    for (const VerdictLine& l : verdictLines_)  // the first failure decides, as in the CLI
        if (l.failure()) return int(verdictStatus(l.kind));
    return 0;
}

bool Model::errorPoint(Point& p) const { return diagnosticPoint(trace_->polygon, error_, p); }

const StateTable& Model::stateTable() const {
    if (stateTableFor_ != generation_) {
        stateTable_ = buildStateTable(polygon(), trace().events, trace().up);
        stateTableFor_ = generation_;
    }
    return stateTable_;
}

uint32_t Model::triangleStep(uint32_t t) const {
    return t < triangleStep_.size() ? triangleStep_[t] : 0;
}

}  // namespace flood::view
