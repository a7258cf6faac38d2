// A run made ready to show (issue 26 §4): what the model shows of a flooded or recorded run
// that needs no GL, computed once — the replay's keyframes, the vertex classes, the
// transcript, the step that cut each triangle, the verdict with every finding, the
// transitions, and the canvas's arrays and label grids. One function makes it, prepareRun:
// in an open's or an edit's job (its Prepare phase, off the UI thread) and in the synchronous
// open (tests, --screenshot), so the window and the scripts show the same run. The model moves
// it in (Model::adopt); the canvas uploads its arrays.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flood/check/checker.h"
#include "flood/check/verdict.h"
#include "flood/geometry/status.h"
#include "flood/log/replay.h"
#include "flood/machine/events.h"
#include "flood/machine/vertex_class.h"
#include "flood/teach/transcript.h"

namespace flood::view {

// The verdict, one line per finding, of the core's kinds (flood/check/verdict.h). Ok only
// when the exact checker passed on valid input; every failure (malformed, invalid input,
// forbidden state, checker rejection, internal) has its own line, drawn red. A note (the
// checker accepting the triangles of invalid input) is an Ok line drawn grey.
struct VerdictLine {
    Verdict kind = Verdict::Ok;
    std::string text;
    bool note = false;
    bool failure() const { return kind != Verdict::Ok; }
};

// One finding of the open face, as the findings panel lists it: a validation finding
// (validateAll, the first being validate()'s verdict), the forbidden transition, the exact
// checker's rejection, an internal failure or an unreadable file.
struct Finding {
    Verdict kind = Verdict::Invalid;
    std::string message;    // the diagnostic's whole line
    std::string where;      // "ring R vertex V (x, y)", "step N", "triangle T", or ""
    std::string reason;     // what is wrong, the location apart
    Culprits culprits;      // what it blames (drawn thick in the error view)
    bool hasPoint = false;  // `point` is where it is (diagnosticPoint, any vertex)
    Point point;
    uint32_t step = kNone;  // the step it shows at; kNone: none (or not known yet)
};

// What a flood computed off the UI thread, before it is prepared: the trace, the input's
// verdict, the judge's and every finding.
struct FloodedRun {
    Trace trace;       // trace.polygon: the polygon flooded, its T-junctions recorded
    Diagnostic input;  // the validator's verdict on it
    std::optional<Judgement> judged;  // judgeRun on the run, unless nothing was flooded
    Findings findings;                // validateAll's, when `input` is invalid
};

// A run's verdict: its lines (and their text, one a line), the exact checker's result, the
// first failure's culprits and step, every finding (at most 100 of validation's, the count
// of the rest), and the vertices to blame.
struct RunVerdict {
    std::vector<VerdictLine> lines;
    std::string text;
    CheckResult check;
    Culprits error;
    uint32_t firstErrorStep = kNone;
    std::vector<Finding> findings;
    size_t findingsOmitted = 0;
    bool findingsComplete = true;
    std::vector<Index> offenders;
};
// An outline's: its note alone (its open under way or cancelled: nothing to judge yet).
RunVerdict noteVerdict(const std::string& note);

struct PreparedCanvas;  // canvas_geometry.h: the canvas's arrays and label grids
struct CanvasGeometry;  // canvas_vertices.h: its arrays

using Transitions = std::array<std::array<uint32_t, size_t(Action::Count)>, size_t(Action::Count)>;

struct PreparedRun {
    std::unique_ptr<Trace> trace;    // at a stable address: the replay points into it
    std::unique_ptr<Replay> replay;  // its keyframes built
    std::string note;                // an outline's verdict (its open under way), else ""
    Diagnostic input;
    std::vector<VertexClass> classes;
    std::vector<TranscriptItem> transcript;
    std::vector<uint32_t> triangleStep;  // per triangle, the step that cut it (0: none)
    RunVerdict verdict;
    Transitions transitions{};   // how often event `to` follows event `from`
    uint32_t forbiddenStep = 0;  // the first Forbidden event's step, 0 if none
    std::shared_ptr<PreparedCanvas> canvas;
};

// `run` made ready to show under `name`; with a `note`, it is an outline (no events) whose
// verdict is the note.
PreparedRun prepareRun(FloodedRun run, const std::string& name, std::string note = {});

// prepareRun() a part at a time, each a pass over the run (the page prepares a large run
// between its frames): the keyframes, the classes, the transcript, the verdict, the canvas's
// arrays, its label grids.
class PrepareSteps {
public:
    PrepareSteps(FloodedRun run, std::string name, std::string note = {});
    ~PrepareSteps();
    bool step();  // the next part; false once the last is done
    static constexpr int kParts = 6;
    int done() const { return next_; }            // parts done so far
    PreparedRun take() { return std::move(p_); }  // once step() returned false

private:
    void verdict();
    FloodedRun run_;
    std::string name_;
    PreparedRun p_;
    std::unique_ptr<CanvasGeometry> geometry_;  // between the canvas's two parts
    int next_ = 0;
};

}  // namespace flood::view
