// Spill walks remembered (§5; ALGORITHM.md): the dry nodes a walk passed, in its direction
// (prev-wards or next-wards), with the drop count's change along them. Links between dry
// nodes do not change (every edit of the loops touches a wet node), so a later walk reaching
// such a stretch crosses it in one step up to its first node that got wet since. Each
// stretch keeps a tree over its positions that finds that node, or the first bottom or
// ceiling the count would reach at zero, in O(log length).
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <vector>

#include "flood/geometry/polygon.h"
#include "machine/node_id.h"

namespace flood {

class Stretches {
public:
    struct Position {
        NodeId node;
        uint32_t stretch;  // its Stretch in stretches
        int32_t drops;     // the count's change from the stretch's start to just before here
    };  // 12 bytes: a convex bottom or ceiling (where a zero count matters) is the one position
        // whose next position's count is one less, so no flag says it (the last one: record())
    struct Stretch {
        uint32_t start, end;    // its positions in positions
        uint32_t tree, leaves;  // its tree in tree_ (firstAtMost()), leaves a power of two
    };
    std::vector<Position> positions;  // of every stretch recorded, stretch after stretch
    std::vector<Stretch> stretches;

    // For a part whose nodes are numbered from firstNode on, `nodes` of them at most.
    void clear(NodeId firstNode, size_t nodes);
    // The position of node n in the stretches walked in direction dir (0 prev-wards, 1
    // next-wards); kNone if not recorded.
    uint32_t recordedAt(int dir, NodeId n) const {
        const std::vector<uint32_t>& v = at_[dir];
        return n - first_ < v.size() ? v[n - first_] : kNone;
    }
    // Appends p to the stretch being recorded; `sensitive`: p is a convex bottom or ceiling;
    // `end`: the id the next node will get.
    void record(int dir, const Position& p, bool sensitive, NodeId end);
    // Ends the stretch a walk is recording (positions from `run` on) and builds its tree. A
    // stretch of one node is dropped: no walk could cross anything of it (its node is then
    // recorded again by a later walk), and on jagged outlines most stretches are such.
    void close(size_t& run);
    // The first position from `from` on (relative to the stretch's start) whose tree value is
    // at most `limit`; the stretch's length if none.
    uint32_t firstAtMost(const Stretch& s, uint32_t from, int64_t limit) const;
    // Node n got wet: a stretch holding it can no longer be crossed past it. Inline up to
    // the lookup: the machine calls it on every node that gets wet, and most are in no stretch.
    void markWet(NodeId n) {
        const uint32_t i = n - first_;
        for (const std::vector<uint32_t>& at : at_)
            if (i < at.size() && at[i] != kNone) markWetAt(at[i]);
    }

private:
    void markWetAt(uint32_t position);
    std::vector<int32_t> tree_;
    std::vector<uint32_t> at_[2];  // per node of the part, per direction: its position
    NodeId first_{0};
    int dir_ = 0;                 // of the stretch being recorded
    NodeId end_{0};               // record()'s last `end`
    bool lastSensitive_ = false;  // record()'s last `sensitive`
};

}  // namespace flood
