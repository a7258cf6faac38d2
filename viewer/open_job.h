// Opening a file in the window (issue 26 §4): read, validate, flood and check run as one Job
// (job.h), so a face of 10⁶ vertices shows its outline as soon as it is read and the window
// stays live while it floods. Model::openInBackground starts it and Model::pollOpen adopts
// what it has ready; Model::open stays the synchronous path (tests, scripts, screenshots).
#pragma once
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "flood/check/verdict.h"
#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "job.h"

namespace flood::view {

// The phases of an open, in order. A trace read from a file has no Flood phase.
enum class OpenPhase : int { Read, Validate, Flood, Check, Done };
const char* openPhaseName(OpenPhase p);  // "reading", "validating", "flooding", "checking", "done"

// A run computed off the UI thread, for the model to adopt (Model::adoptEdit, an open's
// Model::pollOpen): the trace, the input's verdict, the judge's and every finding.
struct FloodedRun {
    Trace trace;       // trace.polygon: the polygon flooded, its T-junctions recorded
    Diagnostic input;  // the validator's verdict on it
    std::optional<Judgement> judged;  // judgeRun on the run, unless nothing was flooded
    Findings findings;                // validateAll's, when `input` is invalid
};

// Called before each phase with it; false stops the run there (a cancelled open).
using EnterPhase = std::function<bool(OpenPhase)>;

// Validates, floods (invalid polygons too: the viewer shows where the machine stops) and
// judges `polygon`; an empty polygon is an empty canvas, not an invalid one. False when
// `enter` stopped it (the run is then incomplete and not to be adopted).
bool floodRun(Polygon polygon, const std::string& name, Up up, FloodedRun& run,
              const EnterPhase& enter = {});
// The same for a recorded trace: its polygon validated (a copy: the trace is the run) and
// its triangles judged.
bool judgeTrace(Trace trace, const std::string& name, FloodedRun& run,
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

    // Once phase() is past Read: the read's verdict and, when it read, the polygon as read
    // (the outline to show while the rest runs), its warnings and size.
    const Diagnostic& readDiagnostic() const { return read_; }
    Polygon takeOutline() { return std::move(outline_); }
    const std::vector<std::string>& warnings() const { return warnings_; }
    // Once done(): whether every phase ran (not cancelled, the read succeeded), and the run.
    bool complete() const { return complete_; }
    FloodedRun& run() { return run_; }

private:
    void work(Job& job);
    bool enter(Job& job, OpenPhase p);
    Request request_;
    std::atomic<int> phase_{int(OpenPhase::Read)};
    Diagnostic read_;
    Polygon outline_;
    std::vector<std::string> warnings_;
    bool complete_ = false;
    FloodedRun run_;
    Job job_;  // declared last, so it is joined before what its work writes is destroyed
};

}  // namespace flood::view
