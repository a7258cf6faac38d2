// The flood machine's invariants (core/machine/flood.cpp's header), checked on the replay state
// after each step: what the viewer's invariant lane shows, and what tells whether invalid input
// broke the machine before it noticed (the Forbidden transition comes later, if at all).
//
// Checked incrementally: each step looks only at what it changed (the chain's ends, the
// joints a Bridge or Jump makes, the triangles it cut, the gorge it pushed or took), so a
// whole trace costs O(events) orient calls, not O(events x chain), plus the vertices a grid
// finds in the cells each triangle cut covers. That part is sampled: a triangle covering more
// than kMaxCells cells (a long sliver across the polygon) is checked in its lowest ones only.
#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "flood/log/replay.h"

namespace flood {

// X(name, what holds between steps on valid input)
#define FLOOD_INVARIANTS(X)                                                                        \
    X(None, "")                                                                                    \
    X(TrianglesCounterClockwise,                                                                   \
      "every triangle cut is counter-clockwise: it lies between the loops")                        \
    X(TriangleEmpty, "no vertex or edge lies inside a triangle cut: the loops bound what is left") \
    X(ReflexChain, "every node strictly inside the active chain is concave or flat")               \
    X(FingersAboveWater, "NextLeft and NextRight are above the water, but beside a top")           \
    X(JumpOnHeldTop, "a top has a jump pointer only while its gorge is held there")                \
    X(LoopsConsistent, "the chain ends are Left and Right; gorges taken are the ones waiting")

enum class Invariant : uint8_t {
#define FLOOD_X(name, text) name,
    FLOOD_INVARIANTS(FLOOD_X)
#undef FLOOD_X
        Count
};
const char* invariantName(Invariant i);
const char* invariantText(Invariant i);

struct Violation {
    Invariant which = Invariant::None;
    uint32_t step = 0;            // the state after this many events breaks it
    std::vector<Index> vertices;  // the vertices that break it, the culprit first
    std::string detail;           // one line naming them
    bool ok() const { return which == Invariant::None; }
};

// Feed it every step of one trace in order: check(replay.seek(s)) for s = 1, 2, ...
// Its events must pass eventProblem() (events.h): the checker reads the vertices they name
// (parseTrace() refuses a trace with one that does not; the machine records none).
class InvariantChecker {
public:
    explicit InvariantChecker(const Trace& trace) : trace_(&trace) {}
    static constexpr int kMaxCells = 48;
    // The first invariant the step that produced `after` broke (None if it kept them all).
    Violation check(const ReplayState& after);

private:
    Point P(Index v) const { return trace_->polygon.vertices[v]; }
    bool reflexAt(const std::vector<Index>& chain, size_t i, Violation& out) const;
    // A vertex strictly inside triangle t (number `number`), or an edge crossing it.
    Violation triangleEmpty(const Triangle& t, uint32_t number);
    void buildGrid();
    const Trace* trace_;
    size_t chainSize_ = 0;  // the active chain's length after the previous step
    struct Waiting {
        bool held = false;
        Index top = kNone;
    };
    std::unordered_map<uint32_t, Waiting> gorges_;  // gorge id -> how it waits
    std::unordered_map<Index, uint32_t> heldTops_;  // top -> gorges held there
    // The vertices bucketed by a uniform grid of about one cell per vertex (built on the
    // first triangle): cell c holds gridVertices_[gridStart_[c] .. gridStart_[c + 1]).
    bool gridBuilt_ = false;
    double gx0_ = 0, gy0_ = 0, gcell_ = 1;
    uint32_t gw_ = 0, gh_ = 0;
    std::vector<uint32_t> gridStart_;
    std::vector<Index> gridVertices_;
    std::vector<Index> ringPrev_, ringNext_;  // a vertex's neighbours on its ring
};

// Every violation of a whole trace, in step order (one per step at most). `progress` gets
// the steps done; a set `cancel` stops early (the result then covers a prefix).
std::vector<Violation> checkInvariants(const Trace& trace,
                                       std::atomic<uint32_t>* progress = nullptr,
                                       const std::atomic<bool>* cancel = nullptr);

}  // namespace flood
