// The model's run: what an open or an edit adopts, its verdict and its findings, the
// invariant scan, the numbers counted once per run.
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

Model::Model() : trace_(std::make_unique<Trace>()), replay_(std::make_unique<Replay>(*trace_)) {
    verdict_ = computeVerdict();
}

Model::~Model() { cancelInvariants(); }

void Model::adopt(std::unique_ptr<Trace> trace, std::string note) {
    note_ = std::move(note);
    errorView_ = false;
    feature_ = kNoFeature;  // openFeature / openShrunk set these again after adopting
    origin_.clear();
    // The replay points into the trace: replace both together, replay first.
    replay_.reset();
    trace_ = std::move(trace);
    replay_ = std::make_unique<Replay>(*trace_);
    classes_ = classifyVertices(trace_->polygon, trace_->up);
    transcript_ = transcriptItems(trace_->events);
    triangleStep_.assign(trace_->triangles.size(), 0);
    for (const Event& e : trace_->events)
        for (uint32_t t = e.firstTriangle;
             t < e.firstTriangle + e.triangleCount && t < triangleStep_.size(); ++t)
            triangleStep_[t] = e.step + 1;
    computeVerdictLines();  // runs the exact checker: once, not every frame
    computeFindings();
    computeOffenders();
    verdict_ = computeVerdict();
    needsFit_ = true;
    step_ = 0;
    replay_->seek(0);
    timeline = {};
    findBreakpointSteps();
    countTransitions();
    forbiddenStep_ = 0;
    // Land where the trouble is: the forbidden event, so its state is on screen.
    for (const Event& e : trace_->events)
        if (e.action == Action::Forbidden) {
            forbiddenStep_ = e.step + 1;
            seek(forbiddenStep_);
            break;
        }
    landedStep_ = step_;
    landingPending_ = true;
    scanWaiting_ = std::exchange(deferScan_, false);  // live editing: started once the drag ends
    if (scanWaiting_) scan_.reset();                  // no scan yet: nothing done
    else startInvariants();
}

void Model::adoptRun(EditedRun run) {
    input_ = std::move(run.input);
    judged_ = std::move(run.judged);
    if (!input_.ok() && !run.findings.list.empty()) validated_ = std::move(run.findings);
    adopt(std::make_unique<Trace>(std::move(run.trace)));
    judged_.reset();  // used by adopt's verdict, or not needed there: never by a later open
    validated_.reset();
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
    auto replay = std::make_shared<Replay>(*trace_);
    auto checker = std::make_shared<InvariantChecker>(*trace_);
    scan_.startSteps([this, replay, checker, s = uint32_t(0)](Job& job) mutable {
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

const std::vector<Violation>& Model::violations() const {
    static const std::vector<Violation> none;
    return invariantsDone() ? found_ : none;
}

uint32_t Model::firstViolationStep() const {
    const std::vector<Violation>& v = violations();
    return v.empty() ? 0 : v.front().step;
}

void Model::computeOffenders() {
    offenders_.clear();
    auto add = [&](Index v) {
        if (v != kNone && v < trace_->polygon.vertices.size()) offenders_.push_back(v);
    };
    for (const Event& e : trace_->events) {
        if (e.action != Action::Forbidden) continue;
        add(e.culprit), add(e.culprit2);
        add(e.before.left), add(e.before.right), add(e.before.nextLeft), add(e.before.nextRight);
    }
    for (Index v : error_.vertices) add(v);
    std::sort(offenders_.begin(), offenders_.end());
    offenders_.erase(std::unique(offenders_.begin(), offenders_.end()), offenders_.end());
}

std::string Model::computeVerdict() const {
    std::string s;
    for (const VerdictLine& l : verdictLines_) s += (s.empty() ? "" : "\n") + l.text;
    return s;
}

void Model::computeVerdictLines() {
    verdictLines_.clear();
    check_ = {};
    error_ = {};
    firstErrorStep_ = kNone;
    const Polygon& P = trace_->polygon;
    auto line = [&](Verdict k, std::string text, bool note = false) {
        verdictLines_.push_back({k, std::move(text), note});
    };
    if (!note_.empty()) {  // an outline, its open under way or cancelled: nothing to judge yet
        line(Verdict::Ok, note_, true);
        return;
    }
    if (!input_.ok() && P.vertices.empty()) {
        line(input_.status == Status::Malformed ? Verdict::Malformed : Verdict::Invalid,
             input_.message);
        return;
    }
    if (!input_.ok()) {
        line(Verdict::Invalid, "invalid input: " + input_.message);
        error_ = input_.culprits;
    }
    const Event* forbidden = nullptr;
    for (const Event& e : trace_->events)
        if (e.action == Action::Forbidden) {
            forbidden = &e;
            break;
        }
    if (forbidden) {  // the log says where, even when its header lost the machine's diagnostic
        line(Verdict::Forbidden, "forbidden at step " + std::to_string(forbidden->step + 1) + ": " +
                                     describeForbidden(P, *forbidden));
        if (error_.empty()) error_ = forbiddenCulprits(P, *forbidden);
        firstErrorStep_ = forbidden->step + 1;
        return;
    }
    if (P.vertices.empty() && trace_->diagnostic.ok()) return;  // nothing loaded
    // The core's judge on the run (an edit's ran with its flood, off the UI thread): the
    // machine's failure, else the exact checker's word, never the triangle count.
    Judgement j =
        judged_ ? std::move(*judged_) : judgeRun(P, trace_->triangles, trace_->diagnostic, path_);
    judged_.reset();
    check_ = std::move(j.check);
    if (j.verdict == Verdict::Forbidden || j.verdict == Verdict::Internal) {
        line(j.verdict, j.diagnostic.message);
        if (error_.empty()) error_ = j.diagnostic.culprits;
        return;
    }
    if (j.verdict == Verdict::Checker) {
        line(Verdict::Checker, "the exact checker rejects the triangulation: " + check_.reason);
        if (error_.empty()) error_ = check_.culprits;
        for (uint32_t t : check_.culprits.triangles)
            if (t < triangleStep_.size() && triangleStep_[t] &&
                (firstErrorStep_ == kNone || triangleStep_[t] < firstErrorStep_))
                firstErrorStep_ = triangleStep_[t];
    } else if (input_.ok()) {
        line(Verdict::Ok, "ok: " + std::to_string(trace_->triangles.size()) +
                              " triangles, exact checker passed");
    } else {
        line(Verdict::Ok,
             "the exact checker accepts the " + std::to_string(trace_->triangles.size()) +
                 " triangles, but the input is invalid",
             true);
    }
    if (firstErrorStep_ == kNone && !input_.ok()) {
        // Invalid input that floods through: the first step a culprit is a finger.
        for (const Event& e : trace_->events) {
            for (Index v : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
                if (v != kNone && std::find(error_.vertices.begin(), error_.vertices.end(), v) !=
                                      error_.vertices.end())
                    firstErrorStep_ = e.step + 1;
            if (firstErrorStep_ != kNone) break;
        }
    }
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

void Model::computeFindings() {
    findings_.clear();
    findingsOmitted_ = 0;
    findingsComplete_ = true;
    currentFinding_ = 0;
    const Polygon& P = trace_->polygon;
    auto add = [&](Verdict kind, const Diagnostic& d, const std::string& name) {
        Finding f;
        f.kind = kind;
        f.message = d.message;
        f.culprits = d.culprits;
        Where w = whereOf(P, d.culprits);
        f.where = w.text;
        f.reason = reasonOf(d.message, name, w);
        f.hasPoint = diagnosticPoint(P, d.culprits, f.point, true);
        findings_.push_back(std::move(f));
    };
    // One line of the verdict, one finding; the input's line, every validation finding.
    for (const VerdictLine& line : verdictLines_) {
        switch (line.kind) {
            case Verdict::Malformed: add(line.kind, input_, path_); break;
            case Verdict::Invalid: {
                if (P.vertices.empty()) {
                    add(line.kind, input_, path_);
                    break;
                }
                // validate()'s verdict first (an edit's findings came with its flood).
                Findings all = validated_ ? std::move(*validated_) : validateAll(P, path_);
                if (all.list.empty() || all.list.front().message != input_.message)
                    all.list.insert(all.list.begin(), input_);
                for (const Diagnostic& d : all.list) add(line.kind, d, path_);
                findingsOmitted_ = all.omitted;
                findingsComplete_ = all.complete;
                break;
            }
            case Verdict::Forbidden:
                for (const Event& e : trace_->events)
                    if (e.action == Action::Forbidden) {
                        Finding f;
                        f.kind = line.kind;
                        f.step = e.step + 1;
                        f.where = "step " + std::to_string(f.step);
                        f.reason = describeForbidden(P, e);
                        f.message = line.text;
                        f.culprits = forbiddenCulprits(P, e);
                        f.hasPoint = diagnosticPoint(P, f.culprits, f.point, true);
                        findings_.push_back(std::move(f));
                        break;
                    }
                break;
            case Verdict::Internal:
                add(line.kind, trace_->diagnostic, path_);
                findings_.back().message = line.text;
                break;
            case Verdict::Checker: {
                Finding f;
                f.kind = line.kind;
                f.reason = check_.reason;
                f.message = line.text;
                f.culprits = check_.culprits;
                f.where = check_.culprits.triangles.empty()
                              ? whereOf(P, check_.culprits).text
                              : "triangle " + std::to_string(check_.culprits.triangles.front());
                f.hasPoint = diagnosticPoint(P, f.culprits, f.point, true);
                for (uint32_t t : f.culprits.triangles)
                    if (t < triangleStep_.size() && triangleStep_[t] &&
                        (f.step == kNone || triangleStep_[t] < f.step))
                        f.step = triangleStep_[t];
                findings_.push_back(std::move(f));
                break;
            }
            default: break;
        }
    }
    validated_.reset();
    if (!findings_.empty()) error_ = findings_.front().culprits;
}

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

void Model::countTransitions() {
    transitions_ = {};
    const auto& ev = trace_->events;
    for (size_t i = 1; i < ev.size(); ++i)
        ++transitions_[size_t(ev[i - 1].action)][size_t(ev[i].action)];
}

}  // namespace flood::view
