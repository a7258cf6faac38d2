// Replay: rebuild the machine-visible state at any step from the event log alone.
// Keyframes make seeking cheap in both directions; the replay never runs the machine again
// and never mutates the log. Keyframes are spaced by replay work and by their own size, and
// share what did not change since the keyframe before (dormant gorges, their chains, jump
// pointers, bridges), so their memory stays a small multiple of the log's even when
// thousands of gorges wait at once.
#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "flood/log/prefix_tree.h"
#include "flood/machine/events.h"
#include "flood/machine/flood.h"

namespace flood {

// A complete run: input, events and output. What `flood trace` saves and the viewer opens.
struct Trace {
    Polygon polygon;
    std::vector<Event> events;
    std::vector<Triangle> triangles;
    Diagnostic diagnostic;  // outcome of the run
    Up up = Up::PlusY;      // the direction the water rose along (Options::up)
};

// Runs the machine with a recording listener.
Trace record(const Polygon& polygon, const Options& options = {});

// record() in slices (SteppedRun): the web page records a large run between its frames.
class Recording {
public:
    explicit Recording(const Polygon& polygon, const Options& options = {});
    ~Recording();
    Recording(const Recording&) = delete;
    Recording& operator=(const Recording&) = delete;
    bool advance(uint64_t steps);  // at most `steps` more steps; false once the run has ended
    uint32_t steps() const;        // taken so far
    size_t expectedSteps() const;  // about what a run takes (1.5 a vertex): what the log reserves
    Trace take();                  // the trace, once advance() returned false

private:
    struct State;  // core/log/replay.cpp
    std::unique_ptr<State> s_;
};

// A gorge waiting on the to-do list (pending, after a Bridge) or held at a top (after a Spill).
struct Gorge {
    uint32_t id = 0;
    bool held = false;  // held at `top` for a Jump; otherwise pending
    Index top = kNone;
    std::vector<Index> chain;  // its chain, Left to Right
};

struct ReplayState {
    uint32_t step = 0;  // number of events applied
    uint32_t part = 0;
    Fingers fingers;             // Left, Right, NextLeft, NextRight
    Index water = kNone;         // vertex at the water level
    uint32_t triangleCount = 0;  // triangles cut so far (a prefix of Trace::triangles)
    std::vector<Index> chain;    // active chain, Left to Right
    std::vector<Gorge> dormant;  // pending and held gorges
    std::vector<std::pair<Index, Index>> jumps;    // top -> jump pointer, while set
    std::vector<std::pair<Index, Index>> bridges;  // (sag, chain vertex) of every Bridge so far
    bool forbidden = false;                        // the last applied event was Forbidden
};

// Equal in every field, dormant gorges in order: what a seek must reproduce, however it got
// there (stepping, a keyframe, backwards).
bool operator==(const Gorge& a, const Gorge& b);
bool operator==(const ReplayState& a, const ReplayState& b);
inline bool operator!=(const ReplayState& a, const ReplayState& b) { return !(a == b); }

class Replay {
public:
    // `keyframeInterval`: replay work (in events) between keyframes at least. A keyframe
    // costing more than kKeyframeRatio indices per event since the last one waits, but never
    // past kMaxWorkFactor intervals of work (so seeks stay bounded on heavy logs). A keyframe
    // costs its active chain plus what changed since the last one: dormant gorges and jump
    // pointers are stacks in practice, stored as shared prefixes (flood/log/prefix_tree.h).
    explicit Replay(const Trace& trace, uint32_t keyframeInterval = 256);
    static constexpr uint32_t kKeyframeRatio = 16, kMaxWorkFactor = 128;
    uint32_t size() const { return uint32_t(trace_->events.size()); }
    // State after the first `step` events (0 = before anything happened).
    const ReplayState& seek(uint32_t step);
    const ReplayState& state() const { return state_; }
    const Trace& trace() const { return *trace_; }
    size_t keyframeCount() const { return keyframes_.size(); }
    size_t keyframeBytes() const;  // memory held by keyframes, shared parts counted once
    uint32_t lastSeekEvents() const { return lastSeekEvents_; }  // events the last seek re-applied
    uint32_t maxSeekEvents() const { return maxSeekEvents_; }    // the most any seek re-applies
    // Dormant gorges and jump pointers the last seek rewrote from a keyframe (0 if it only
    // stepped forward): only those that differ from the state it started from.
    size_t lastSeekRestored() const { return lastSeekRestored_; }

private:
    // A dormant gorge in a keyframe: its chain is chain number `chain` of chainPool_, copied once while it stays dormant.
    struct Dormant {
        uint32_t id = 0;
        Index top = kNone;
        uint32_t chain = 0;
        bool held = false;
    };
    // A ReplayState's scalars and active chain; its lists are shared with other keyframes.
    struct Keyframe {
        ReplayState head;          // dormant, jumps and bridges left empty
        uint32_t bridgeCount = 0;  // bridges are a prefix of bridges_
        uint32_t dormantHead = 0, dormantCount = 0, jumpsHead = 0, jumpsCount = 0;
    };
    static constexpr uint32_t kNoChain = UINT32_MAX;
    uint64_t apply(const Event& e);  // returns the indices it moved, for keyframe spacing
    void pushGorge(Gorge&& g);
    std::vector<Index> takeGorge(uint32_t id, uint64_t& moved);
    void addKeyframe();
    void restore(size_t keyframe);
    const Trace* trace_;
    uint32_t interval_;
    std::vector<Keyframe> keyframes_;  // in step order, keyframes_[0] at step 0
    std::vector<uint32_t> keyframeSteps_;
    std::vector<std::pair<Index, Index>> bridges_;  // every Bridge of the run, in order
    std::vector<Index> chainPool_;                  // dormant chains seen by keyframes, end to end
    std::vector<size_t> chainEnds_;                 // where each ends in chainPool_
    PrefixTree<Dormant> dormantTree_;
    PrefixTree<std::pair<Index, Index>> jumpsTree_;
    // While keyframing: the chain number of each dormant gorge (kNoChain until a keyframe
    // copies it), the first positions of dormant and jumps changed since the last keyframe,
    // and the indices of the chains the next keyframe would copy.
    // After that, the first positions changed since the last restore() of keyframe restored_.
    bool building_ = false;
    std::vector<uint32_t> dormantChains_;
    size_t dormantLow_ = 0, jumpsLow_ = 0;
    static constexpr size_t kNoKeyframe = SIZE_MAX;
    size_t restored_ = kNoKeyframe;
    uint64_t fresh_ = 0;
    uint32_t lastSeekEvents_ = 0, maxSeekEvents_ = 0;
    size_t lastSeekRestored_ = 0;
    ReplayState state_;
};

}  // namespace flood
