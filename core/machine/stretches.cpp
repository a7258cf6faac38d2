#include "machine/stretches.h"

#include <algorithm>

#include "flood/geometry/work.h"

namespace flood {

void Stretches::clear(NodeId firstNode, size_t nodes) {
    positions.clear();
    // A node is in one stretch a direction at most: room made at once, never moved (a move
    // holds the old and the new array together). Pages never written cost no memory.
    if (positions.capacity() < 2 * nodes) positions.reserve(2 * nodes);
    stretches.clear();
    tree_.clear();
    for (auto& at : at_) at.clear();  // grown by the first spill walk (record())
    first_ = firstNode;
}

void Stretches::record(int dir, const Position& p, bool sensitive, NodeId end) {
    dir_ = dir, end_ = end, lastSensitive_ = sensitive;
    positions.push_back(p);
}

// The tree is a complete binary tree over the positions holding, for bottoms and ceilings, the
// count's change before them (INT32_MAX elsewhere), each inner node the least of its two.
void Stretches::close(size_t& run) {
    const uint32_t start = uint32_t(run);
    if (start + 1 == positions.size()) positions.pop_back();  // crosses nothing
    const uint32_t end = uint32_t(positions.size());
    run = end;
    if (start == end) return;
    // The walk that recorded the stretch did not meet its nodes again (it ends where it
    // started at the latest), so they are looked up from here on only.
    std::vector<uint32_t>& v = at_[dir_];
    if (end_ - first_ > v.size()) v.resize(end_ - first_, kNone);
    for (uint32_t k = start; k < end; ++k) v[positions[k].node - first_] = k;
    uint32_t leaves = 1;
    while (leaves < end - start) leaves <<= 1;
    const uint32_t tree = uint32_t(tree_.size());
    tree_.resize(tree + 2 * size_t(leaves), INT32_MAX);
    int32_t* t = tree_.data() + tree;
    for (uint32_t k = start; k < end; ++k) {  // a bottom or ceiling takes one off the count
        const bool sensitive =
            k + 1 < end ? positions[k + 1].drops == positions[k].drops - 1 : lastSensitive_;
        if (sensitive) t[leaves + k - start] = positions[k].drops;
    }
    for (uint32_t i = leaves; i-- > 1;) t[i] = std::min(t[2 * i], t[2 * i + 1]);
    work().nodeVisits += 2 * size_t(leaves);
    stretches.push_back({start, end, tree, leaves});
}

uint32_t Stretches::firstAtMost(const Stretch& s, uint32_t from, int64_t limit) const {
    const int32_t* t = tree_.data() + s.tree;
    for (size_t i = s.leaves + from;;) {
        ++work().nodeVisits;
        if (t[i] <= limit) {
            while (i < s.leaves) i = t[2 * i] <= limit ? 2 * i : 2 * i + 1;
            return uint32_t(i - s.leaves);
        }
        for (; i & 1; i >>= 1)
            if (i == 1) return s.end - s.start;  // right edge of the tree: none
        ++i;
    }
}

// Its leaf and their ancestors in the stretch's tree get INT32_MIN, below any count.
void Stretches::markWetAt(uint32_t at) {
    const Stretch& s = stretches[positions[at].stretch];
    int32_t* t = tree_.data() + s.tree;
    for (size_t i = s.leaves + at - s.start; i >= 1 && t[i] != INT32_MIN; i >>= 1) {
        t[i] = INT32_MIN;
        ++work().nodeVisits;
    }
}

}  // namespace flood
