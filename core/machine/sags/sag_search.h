// The sag search (§4, §5): the lowest unused sag above the water and below Next inside the
// active gorge's quadrangle Left, Right, NextRight, NextLeft. The sorted sag list's ranks
// (SagHeights) bracket the water and Next; the bank lists (sag_banks.h) answer in O(1) when a
// bank is an input edge, else a few ranks are probed and the plane index (sag_index.h) decides.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "flood/machine/events.h"
#include "machine/heights.h"
#include "machine/sags/sag_banks.h"
#include "machine/sags/sag_index.h"

namespace flood {

class SagSearch {
public:
    // The part's sags, filled by the machine before index().
    std::vector<NodeId>& sags() { return sags_; }
    // Sorts the part's sags by height and indexes them. The part's nodes run from
    // `partFirstNode` to the last node, its vertices from `partFirstVertex`; `touching`:
    // some loops share a point (the bank lists are then never built); `simple`: validate()
    // passed and no point is shared (Polygon::pointsDistinct), so no two edges meet.
    void index(const Heights& heights, NodeId partFirstNode, Index partFirstVertex, bool touching,
               bool simple = false);
    // The sag sought, now used; kNil if none.
    // Inline up to the first test: once every sag is bridged, most steps ask.
    NodeId find(NodeId left, NodeId right, NodeId water, NodeId next, Event& e) {
        if (unused_ == 0) return kNil;  // every sag bridged already (or none): nothing to count
        return counted(left, right, water, next, e);
    }

private:
    NodeId counted(NodeId left, NodeId right, NodeId water, NodeId next, Event& e);
    NodeId search(NodeId left, NodeId right, NodeId water, NodeId next, int64_t lo, int64_t hi,
                  Event& e);
    uint32_t sagsBelow(NodeId n);
    void bracket(NodeId water, NodeId next, int64_t& lo, int64_t& hi);
    NodeId use(int64_t rank);
    bool banksPay() const;
    void buildBanks();
    uint32_t inputEdge(NodeId a, NodeId b) const;
    uint32_t initialNext(uint32_t t) const;
    int64_t bankCandidate(NodeId left, NodeId right, int64_t lo, int64_t hi) const;

    static constexpr int64_t kProbes = 4;  // ranks tested before the sag tree
    static constexpr uint64_t kPrice = 3;  // the bank sweep's price, box visits a node (banksPay())
    const Heights* heights_ = nullptr;     // the run's, from index() on
    std::vector<NodeId> sags_;             // by height rank
    SagIndex index_;                       // the sags by height rank, searchable by x
    SagHeights heightsOf_;                 // the sags' heights by rank
    struct Recent {                        // a node and the number of sags below it (sagsBelow())
        NodeId node = kNil;
        uint32_t below = 0;
    };
    static constexpr uint32_t kRecent = 64;
    Recent recent_[kRecent];
    uint64_t recentSet_ = 0;  // bit i: recent_[i] was written since the last clearing
    // Up to this many sags bracket() counts them on their sorted keys, cheaper than the
    // cache's upkeep: recent_ is then left alone.
    static constexpr size_t kCountedSags = 8;
    SagBanks banks_;  // the sags each input edge sees, once the plane index is costly
    bool banksTried_ = false;
    bool buy_ = false;     // banksPay() said so after the last plane index search
    bool simple_ = false;  // index()'s: the bank sweep need not check that edges meet
    uint64_t rent_ = 0;    // box visits of the plane index in this part (banksPay())
    NodeId partFirstNode_ = NodeId(0);
    uint32_t partFirstVertex_ = 0, initialNodes_ = 0;
    // The part's initial links (local ids), for inputEdge() and the bank sweep: most go to the
    // node after or before (a ring as given, or reversed) or to the node itself (a point hole),
    // a byte says which; the others (a ring's closing edge) are listed by tail, ascending. A
    // byte a node rather than 4: the links are held to the end of the run (steiner's peak).
    static constexpr int8_t kListed = 2;  // else the step to the next node: +1, -1 or 0
    std::vector<int8_t> initialStep_;
    std::vector<std::pair<uint32_t, uint32_t>> initialListed_;  // (tail, next)
    std::vector<uint32_t> initialNext_;  // buildBanks()'s, kept: a warm build allocates nothing
    std::vector<uint32_t> sagOfRank_;    // buildBanks()'s, kept: a warm build allocates nothing
    uint32_t unused_ = 0;                // sags of the part not bridged yet
};

}  // namespace flood
