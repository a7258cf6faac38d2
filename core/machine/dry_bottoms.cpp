// The bottoms the water has not reached (dry_bottoms.h).
#include "machine/dry_bottoms.h"

#include "flood/geometry/work.h"

namespace flood {

// Most runs ask a few times (the last time to learn there is none), so the first asks scan the
// list, dropping the bottoms reached since (they stay reached); after kScans the list is sorted
// once and a cursor walks it, as the paper's sorted list would.
NodeId DryBottoms::lowest(const Heights& heights) {
    const Nodes& nodes = heights.nodes();
    if (scans_ < kScans) {
        ++scans_;
        NodeId best = kNil;
        size_t kept = 0;
        work().nodeVisits += bottoms_.size();
        for (NodeId b : bottoms_) {
            if (nodes.wet(b) || !nodes.alive(b)) continue;
            bottoms_[kept++] = b;
            if (best == kNil || heights.lower(b, best)) best = b;
        }
        bottoms_.resize(kept);
        if (scans_ == kScans) {
            heights.sort(bottoms_, keys_);
            giveBackIfLarge(keys_);  // sorted: the keys are not needed again
        }
        return best;
    }
    for (; cursor_ < bottoms_.size(); ++cursor_) {
        ++work().nodeVisits;
        NodeId b = bottoms_[cursor_];
        if (!nodes.wet(b) && nodes.alive(b)) return b;
    }
    return kNil;
}

}  // namespace flood
