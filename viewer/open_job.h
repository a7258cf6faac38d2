// Opening a file in the window (issue 26 §4): read, validate, flood, check and prepare run as
// one Job (job.h), a phase a step, so a face of 10⁶ vertices shows its outline as soon as it
// is read and the window (the page too, between phases) stays live while it floods. Model::openInBackground starts it and Model::pollOpen adopts
// what it has ready; Model::open stays the synchronous path (tests, scripts, screenshots).
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flood/check/verdict.h"
#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "job.h"
#include "prepared_run.h"

namespace flood::view {

// The phases of an open, in order. A trace read from a file has no Flood phase.
enum class OpenPhase : int { Read, Validate, Flood, Check, Prepare, Done };
// "reading", "validating", "flooding", "checking", "preparing", "done"
const char* openPhaseName(OpenPhase p);
// An outline's verdict while its open goes on: "flooding... N vertices".
std::string openNote(OpenPhase p, size_t vertices);

// Called before each phase with it; false stops the run there (a cancelled open).
using EnterPhase = std::function<bool(OpenPhase)>;

// floodRun and judgeTrace cut in steps (a Job's steps: its thread on the desktop, between
// frames in the page): a phase a step, but the flood a slice of kFloodSlice machine steps a
// step and the preparation (prepared_run.h) a part a step, so that no step of a large run
// holds the page long.
class RunSteps {
public:
    // A polygon to validate, flood (invalid polygons too: the viewer shows where the machine
    // stops) and judge; an empty polygon is an empty canvas, not an invalid one. `given`: the
    // input's verdict already known (validated, or not at all as --no-validate): the polygon
    // is flooded as it is, its T-junctions as recorded.
    RunSteps(Polygon polygon, std::string name, Up up, std::optional<Diagnostic> given = {});
    // A recorded trace: its polygon validated (a copy: the trace is the run), its triangles
    // judged.
    RunSteps(Trace trace, std::string name);
    OpenPhase next() const { return next_; }  // the phase step() runs; Done: none is left
    void step();
    double phaseDone() const;                            // how much of next() is done, in [0, 1)
    static constexpr uint64_t kFloodSlice = 16384;       // ~15 ms of a flood, natively
    PreparedRun take() { return std::move(prepared_); }  // once next() is Done

private:
    OpenPhase after(OpenPhase p) const;
    std::string name_;
    Up up_;
    bool recorded_ = false;  // a trace: no Flood phase
    Polygon polygon_;        // to flood
    FloodedRun run_;
    PreparedRun prepared_;
    std::unique_ptr<Recording> recording_;   // the Flood phase under way
    bool floodEnded_ = false;                // its last slice taken
    std::optional<PrepareSteps> preparing_;  // the Prepare phase under way
    OpenPhase next_ = OpenPhase::Validate;
};

// RunSteps run whole: false when `enter` stopped them (the run is then incomplete and not
// to be adopted).
bool floodRun(Polygon polygon, const std::string& name, Up up, PreparedRun& run,
              const EnterPhase& enter = {}, std::optional<Diagnostic> given = {});
bool judgeTrace(Trace trace, const std::string& name, PreparedRun& run,
                const EnterPhase& enter = {});

class OpenJob {
public:
    struct Request {
        std::string path;
        std::string gisLayer, gisWhere;  // Model::gisLayer, gisWhere
        Up up = Up::PlusY;
        bool trace = false;  // a trace file (Model's isTracePath), not a polygon
        // Called on the job's thread as each phase begins, before the cancel is looked at:
        // a test (or FLOOD_VIEWER_HOLD_OPEN) holds the open there.
        std::function<void(const std::string& path, OpenPhase)> onPhase;
    };
    static constexpr uint32_t kPerPhase = 1000;  // progress units a phase is worth
    static constexpr uint32_t kTotal = uint32_t(OpenPhase::Done) * kPerPhase;

    void start(Request request);
    const Request& request() const { return request_; }
    bool done() const { return job_.done(); }
    void requestCancel() { job_.requestCancel(); }  // no join: the phase under way ends first
    bool cancelRequested() const { return job_.cancelRequested(); }
    void wait() { job_.wait(); }
    OpenPhase phase() const { return OpenPhase(phase_.load(std::memory_order_acquire)); }
    // Over all phases (kPerPhase each): the bytes read, then a phase at a time; monotone,
    // total() once done.
    uint32_t progress() const { return job_.progress(); }
    uint32_t total() const { return job_.total(); }

    // True once the read succeeded and its outline is prepared (a failed read never sets it).
    bool outlineReady() const { return outlineReady_.load(std::memory_order_acquire); }
    // Once outlineReady() or done(): the read's verdict and, when it read, the polygon as read
    // prepared as an outline (to show while the rest runs), its warnings.
    const Diagnostic& readDiagnostic() const { return read_; }
    PreparedRun takeOutline() { return std::move(outline_); }
    const std::vector<std::string>& warnings() const { return warnings_; }
    // Once done(): whether every phase ran (not cancelled, the read succeeded), and the run.
    bool complete() const { return complete_; }
    PreparedRun takeRun() { return steps_->take(); }

private:
    bool step(Job& job);  // the read, its outline's parts, then steps_ a step a call
    void read(Job& job);
    bool enter(Job& job, OpenPhase p);
    void finish(Job& job);
    Request request_;
    std::atomic<int> phase_{int(OpenPhase::Read)};
    std::atomic<bool> outlineReady_{false};  // what read() wrote is visible
    Diagnostic read_;
    PreparedRun outline_;
    std::vector<std::string> warnings_;
    bool complete_ = false;
    std::optional<PrepareSteps> outlining_;  // the outline, once read, until prepared
    std::optional<RunSteps> steps_;          // once read
    OpenPhase entered_ = OpenPhase::Read;    // the phase enter() last began
    Job job_;  // declared last, so it is joined before what its work writes is destroyed
};

}  // namespace flood::view
