// A run made ready to show (prepared_run.h): its verdict and findings, the numbers counted
// once per run, the replay's keyframes and the canvas's arrays.
#include "prepared_run.h"

#include <algorithm>
#include <utility>

#include "canvas_geometry.h"
#include "flood/check/diagnostic_where.h"
#include "flood/teach/describe.h"

namespace flood::view {

namespace {

const Event* firstForbidden(const Trace& t) {
    for (const Event& e : t.events)
        if (e.action == Action::Forbidden) return &e;
    return nullptr;
}

// The verdict's lines, the checker's result, the first failure's culprits and step.
void judgeLines(RunVerdict& v, const Trace& trace, const Diagnostic& input,
                std::optional<Judgement> judged, const std::vector<uint32_t>& triangleStep) {
    const Polygon& P = trace.polygon;
    auto line = [&](Verdict k, std::string text, bool note = false) {
        v.lines.push_back({k, std::move(text), note});
    };
    if (!input.ok() && P.vertices.empty()) {
        line(input.status == Status::Malformed ? Verdict::Malformed : Verdict::Invalid,
             input.message);
        return;
    }
    if (!input.ok()) {
        line(Verdict::Invalid, "invalid input: " + input.message);
        v.error = input.culprits;
    }
    if (const Event* forbidden = firstForbidden(trace)) {
        // The log says where, even when its header lost the machine's diagnostic.
        line(Verdict::Forbidden, "forbidden at step " + std::to_string(forbidden->step + 1) + ": " +
                                     describeForbidden(P, *forbidden));
        if (v.error.empty()) v.error = forbiddenCulprits(P, *forbidden);
        v.firstErrorStep = forbidden->step + 1;
        return;
    }
    // Nothing loaded; else floodRun and judgeTrace judged the run (the core's judge: the
    // machine's failure, else the exact checker's word, never the triangle count).
    if ((P.vertices.empty() && trace.diagnostic.ok()) || !judged) return;
    Judgement& j = *judged;
    v.check = std::move(j.check);
    if (j.verdict == Verdict::Forbidden || j.verdict == Verdict::Internal) {
        line(j.verdict, j.diagnostic.message);
        if (v.error.empty()) v.error = j.diagnostic.culprits;
        return;
    }
    if (j.verdict == Verdict::Checker) {
        line(Verdict::Checker, "the exact checker rejects the triangulation: " + v.check.reason);
        if (v.error.empty()) v.error = v.check.culprits;
        for (uint32_t t : v.check.culprits.triangles)
            if (t < triangleStep.size() && triangleStep[t] &&
                (v.firstErrorStep == kNone || triangleStep[t] < v.firstErrorStep))
                v.firstErrorStep = triangleStep[t];
    } else if (input.ok()) {
        line(Verdict::Ok,
             "ok: " + std::to_string(trace.triangles.size()) + " triangles, exact checker passed");
    } else {
        line(Verdict::Ok,
             "the exact checker accepts the " + std::to_string(trace.triangles.size()) +
                 " triangles, but the input is invalid",
             true);
    }
    if (v.firstErrorStep == kNone && !input.ok()) {
        // Invalid input that floods through: the first step a culprit is a finger.
        const auto& blamed = v.error.vertices;
        for (const Event& e : trace.events) {
            for (Index x : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
                if (x != kNone && std::find(blamed.begin(), blamed.end(), x) != blamed.end())
                    v.firstErrorStep = e.step + 1;
            if (v.firstErrorStep != kNone) break;
        }
    }
}

// One line of the verdict, one finding; the input's line, every validation finding.
void listFindings(RunVerdict& v, const Trace& trace, const Diagnostic& input, Findings all,
                  const std::string& name, const std::vector<uint32_t>& triangleStep) {
    const Polygon& P = trace.polygon;
    auto add = [&](Verdict kind, const Diagnostic& d) {
        Finding f;
        f.kind = kind;
        f.message = d.message;
        f.culprits = d.culprits;
        Where w = whereOf(P, d.culprits);
        f.where = w.text;
        f.reason = reasonOf(d.message, name, w);
        f.hasPoint = diagnosticPoint(P, d.culprits, f.point, true);
        v.findings.push_back(std::move(f));
    };
    for (const VerdictLine& line : v.lines) {
        switch (line.kind) {
            case Verdict::Malformed: add(line.kind, input); break;
            case Verdict::Invalid: {
                if (P.vertices.empty()) {
                    add(line.kind, input);
                    break;
                }
                // validate()'s verdict first (floodRun and judgeTrace found the rest).
                if (all.list.empty() || all.list.front().message != input.message)
                    all.list.insert(all.list.begin(), input);
                for (const Diagnostic& d : all.list) add(line.kind, d);
                v.findingsOmitted = all.omitted;
                v.findingsComplete = all.complete;
                break;
            }
            case Verdict::Forbidden:
                if (const Event* e = firstForbidden(trace)) {
                    Finding f;
                    f.kind = line.kind;
                    f.step = e->step + 1;
                    f.where = "step " + std::to_string(f.step);
                    f.reason = describeForbidden(P, *e);
                    f.message = line.text;
                    f.culprits = forbiddenCulprits(P, *e);
                    f.hasPoint = diagnosticPoint(P, f.culprits, f.point, true);
                    v.findings.push_back(std::move(f));
                }
                break;
            case Verdict::Internal:
                add(line.kind, trace.diagnostic);
                v.findings.back().message = line.text;
                break;
            case Verdict::Checker: {
                Finding f;
                f.kind = line.kind;
                f.reason = v.check.reason;
                f.message = line.text;
                f.culprits = v.check.culprits;
                f.where = v.check.culprits.triangles.empty()
                              ? whereOf(P, v.check.culprits).text
                              : "triangle " + std::to_string(v.check.culprits.triangles.front());
                f.hasPoint = diagnosticPoint(P, f.culprits, f.point, true);
                for (uint32_t t : f.culprits.triangles)
                    if (t < triangleStep.size() && triangleStep[t] &&
                        (f.step == kNone || triangleStep[t] < f.step))
                        f.step = triangleStep[t];
                v.findings.push_back(std::move(f));
                break;
            }
            default: break;
        }
    }
    if (!v.findings.empty()) v.error = v.findings.front().culprits;
}

// The vertices to blame: the forbidden events' fingers and culprits, the first finding's.
void listOffenders(RunVerdict& v, const Trace& trace) {
    const size_t n = trace.polygon.vertices.size();
    auto add = [&](Index x) {
        if (x != kNone && x < n) v.offenders.push_back(x);
    };
    for (const Event& e : trace.events) {
        if (e.action != Action::Forbidden) continue;
        add(e.culprit), add(e.culprit2);
        add(e.before.left), add(e.before.right), add(e.before.nextLeft), add(e.before.nextRight);
    }
    for (Index x : v.error.vertices) add(x);
    std::sort(v.offenders.begin(), v.offenders.end());
    v.offenders.erase(std::unique(v.offenders.begin(), v.offenders.end()), v.offenders.end());
}

void joinLines(RunVerdict& v) {
    for (const VerdictLine& l : v.lines) v.text += (v.text.empty() ? "" : "\n") + l.text;
}

}  // namespace

RunVerdict noteVerdict(const std::string& note) {
    RunVerdict v;
    v.lines.push_back({Verdict::Ok, note, true});
    joinLines(v);
    return v;
}

PrepareSteps::PrepareSteps(FloodedRun run, std::string name, std::string note)
    : run_(std::move(run)), name_(std::move(name)) {
    p_.note = std::move(note);
}

PrepareSteps::~PrepareSteps() = default;

bool PrepareSteps::step() {
    switch (next_++) {
        case 0:  // the replay's keyframes: a pass over the events
            p_.trace = std::make_unique<Trace>(std::move(run_.trace));
            p_.replay = std::make_unique<Replay>(*p_.trace);
            p_.input = std::move(run_.input);
            return true;
        case 1: p_.classes = classifyVertices(p_.trace->polygon, p_.trace->up); return true;
        case 2: p_.transcript = transcriptItems(p_.trace->events); return true;
        case 3: verdict(); return true;
        case 4:
            geometry_ = std::make_unique<CanvasGeometry>(
                buildCanvasGeometry(*p_.trace, p_.classes, !p_.note.empty(), p_.input.ok()));
            return true;
        case 5: p_.canvas = prepareCanvas(std::move(*geometry_), *p_.trace); return false;
        default: return false;
    }
}

void PrepareSteps::verdict() {
    PreparedRun& p = p_;
    const Trace& t = *p.trace;
    p.triangleStep.assign(t.triangles.size(), 0);
    for (const Event& e : t.events)
        for (uint32_t k = e.firstTriangle;
             k < e.firstTriangle + e.triangleCount && k < p.triangleStep.size(); ++k)
            p.triangleStep[k] = e.step + 1;
    if (!p.note.empty()) {
        p.verdict = noteVerdict(p.note);
    } else {
        judgeLines(p.verdict, t, p.input, std::move(run_.judged), p.triangleStep);
        listFindings(p.verdict, t, p.input, std::move(run_.findings), name_, p.triangleStep);
        listOffenders(p.verdict, t);
        joinLines(p.verdict);
    }
    for (size_t i = 1; i < t.events.size(); ++i)
        ++p.transitions[size_t(t.events[i - 1].action)][size_t(t.events[i].action)];
    if (const Event* e = firstForbidden(t)) p.forbiddenStep = e->step + 1;
}

PreparedRun prepareRun(FloodedRun run, const std::string& name, std::string note) {
    PrepareSteps steps(std::move(run), name, std::move(note));
    while (steps.step()) {
    }
    return steps.take();
}

}  // namespace flood::view
