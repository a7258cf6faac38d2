// Replay: rebuild the machine-visible state at any step from the event log alone.
// Keyframes make seeking cheap in both directions; the replay never runs the machine again
// and never mutates the log. Keyframes are spaced by replay work and by their own size, and
// share the chains of dormant gorges (immutable while dormant), so their memory stays a
// small multiple of the log's even when thousands of gorges wait at once.
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
    // `keyframeInterval`: replay work (in events) between keyframes at least. A keyframe
    // bigger than kKeyframeRatio indices per event since the last one waits, but never past
    // kMaxWorkFactor intervals of work (so seeks stay bounded on heavy logs).
    explicit Replay(const Trace& trace, uint32_t keyframeInterval = 256);
    static constexpr uint32_t kKeyframeRatio = 16, kMaxWorkFactor = 128;
    uint32_t size() const { return uint32_t(trace_->events.size()); }
    // State after the first `step` events (0 = before anything happened).
    const ReplayState& seek(uint32_t step);
    const ReplayState& state() const { return state_; }
    const Trace& trace() const { return *trace_; }
    size_t keyframeCount() const { return keyframes_.size(); }
    size_t keyframeBytes() const;  // memory held by keyframes, shared chains counted once

private:
    // A ReplayState without its bridges (always a prefix of bridges_) and with the chains of
    // dormant gorges in chains_, shared between keyframes.
    struct Keyframe {
        ReplayState head;  // chain, jumps and scalars; dormant and bridges left empty
        uint32_t bridgeCount = 0;
        struct Dormant {
            uint32_t id = 0;
            Index top = kNone;
            uint32_t chain = 0;  // in chains_
            bool held = false;
        };
        std::vector<Dormant> dormant;
    };
    void apply(const Event& e);
    void addKeyframe(const std::vector<uint32_t>& pushedSince);
    void restore(const Keyframe& k);
    const Trace* trace_;
    uint32_t interval_;
    std::vector<Keyframe> keyframes_;   // in step order, keyframes_[0] at step 0
    std::vector<uint32_t> keyframeSteps_;
    std::vector<std::pair<Index, Index>> bridges_;  // every Bridge of the run, in order
    std::vector<std::vector<Index>> chains_;        // dormant chains seen by keyframes
    std::vector<int32_t> slots_[2];  // gorge id -> keyframe position, while keyframing
    ReplayState state_;
};

}  // namespace flood
