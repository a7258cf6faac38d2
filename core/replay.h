// Replay: rebuild the machine-visible state at any step from the event log alone.
// Keyframes every few hundred events make seeking cheap in both directions; the replay
// never runs the machine again and never mutates the log.
#pragma once
#include <utility>
#include <vector>

#include "events.h"
#include "flood.h"

namespace flood {

// A complete run: input, events and output. What `flood trace` saves and the viewer opens.
struct Trace {
    Polygon polygon;
    std::vector<Event> events;
    std::vector<Triangle> triangles;
    Diagnostic diagnostic;  // outcome of the run
};

// Runs the machine with a recording listener.
Trace record(const Polygon& polygon, const Options& options = {});

// A gorge waiting on the to-do list (pending, after a Bridge) or held at a top (after a Spill).
struct Gorge {
    uint32_t id = 0;
    bool held = false;          // held at `top` for a Jump; otherwise pending
    Index top = kNone;
    std::vector<Index> chain;   // its chain, Left to Right
};

struct ReplayState {
    uint32_t step = 0;            // number of events applied
    uint32_t part = 0;
    Fingers fingers;              // Left, Right, NextLeft, NextRight
    Index water = kNone;          // vertex at the water level
    uint32_t triangleCount = 0;   // triangles cut so far (a prefix of Trace::triangles)
    std::vector<Index> chain;     // active chain, Left to Right
    std::vector<Gorge> dormant;   // pending and held gorges
    std::vector<std::pair<Index, Index>> jumps;    // top -> jump pointer, while set
    std::vector<std::pair<Index, Index>> bridges;  // (sag, chain vertex) of every Bridge so far
    bool forbidden = false;       // the last applied event was Forbidden
};

class Replay {
public:
    explicit Replay(const Trace& trace, uint32_t keyframeInterval = 256);
    uint32_t size() const { return uint32_t(trace_->events.size()); }
    // State after the first `step` events (0 = before anything happened).
    const ReplayState& seek(uint32_t step);
    const ReplayState& state() const { return state_; }
    const Trace& trace() const { return *trace_; }

private:
    void apply(const Event& e);
    const Trace* trace_;
    uint32_t interval_;
    std::vector<ReplayState> keyframes_;  // keyframes_[k] = state after k * interval_ events
    ReplayState state_;
};

}  // namespace flood
