// The sags a gorge's bank can see (issue 13). A sweep over the part's loops, lowest vertex
// first, labels every sag with the loop edges its horizontal rays meet first, to its left and
// to its right (the rays of the tilted horizontal: below() order). The lowest sag inside a
// gorge sees both of the gorge's banks across open water, so when a bank is an input edge the
// sags labelled with it, in rank order, hold the answer of the sag search (docs/ALGORITHM.md §4).
// A sliver gorge then costs O(1) instead of the O(√S) boxes of the plane index. Heights are
// along a direction `up` (up.h): off the axes the horizontal is the line across it, and every
// test stays exact (belowToward and orient).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/up.h"
#include "flood/geometry/work.h"

namespace flood {

class SagBanks {
public:
    SagBanks();
    ~SagBanks();
    SagBanks(const SagBanks& o);  // the lists, not the scratch
    SagBanks& operator=(const SagBanks& o);
    SagBanks(SagBanks&&) noexcept;
    SagBanks& operator=(SagBanks&&) noexcept;

    // Loops of `next.size()` nodes at `point` (next[i]: the node after i; next[i] == i for a point
    // hole), no two at the same point; sagOfRank: the sags' nodes by height rank. False, and
    // nothing built, when two edges touch or cross, or a sag lies on an edge (unvalidated
    // input): the sweep stops at the first such pair, before its order could be wrong.
    // `simple`: the caller knows that no two edges meet (validate() passed), so the sweep
    // skips those checks, a third of its work.
    bool build(const Point* point, const std::vector<uint32_t>& next,
               const std::vector<uint32_t>& sagOfRank, Up up = Up::PlusY, bool simple = false);
    // The same, the points in a vector of one per node.
    bool build(const std::vector<Point>& point, const std::vector<uint32_t>& next,
               const std::vector<uint32_t>& sagOfRank, Up up = Up::PlusY, bool simple = false) {
        return build(point.data(), next, sagOfRank, up, simple);
    }
    bool built() const { return built_; }
    void clear();

    // The lowest rank in (lo, hi) for which used(rank) is false among the sags whose ray to
    // the left (toLeft) or right meets the edge tail -> next[tail] first; -1 if none.
    template <class Used>
    int64_t lowest(bool toLeft, uint32_t tail, int64_t lo, int64_t hi, Used&& used) const;

private:
    // Per side, the ranks labelled with each edge, ascending. Most edges have none (a bank
    // sees a sag only across open water), so only the edges with some get a list: edge t has
    // one when bit t of `listed` is set, the list(t)-th, ranks[begin[k] .. begin[k+1]), list(t)
    // counted by the bits below it. An array over every edge, 4 bytes an edge a side, was held
    // to the end of the run (steiner's peak).
    struct Side {
        std::vector<uint64_t> listed;  // bit t: edge t has a list
        std::vector<uint32_t> before;  // per word of `listed`: the bits set in the words before
        std::vector<uint32_t> begin, ranks;
        size_t edges = 0;
        void group(const std::vector<uint32_t>& label, size_t edges);
        bool has(uint32_t t) const {
            return t / 64 < listed.size() && (listed[t / 64] >> (t % 64) & 1) != 0;
        }
        uint32_t list(uint32_t t) const {  // for has(t)
            return before[t / 64] + bitsSet(listed[t / 64] & ((uint64_t(1) << (t % 64)) - 1));
        }
        // Inline: without a popcount instruction in the target, the builtin is a library call.
        static uint32_t bitsSet(uint64_t x) {
            x -= (x >> 1) & 0x5555555555555555u;
            x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
            return uint32_t((((x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu) * 0x0101010101010101u) >> 56);
        }
    };
    std::array<Side, 2> side_;  // 0: rays to the left, 1: to the right
    bool built_ = false;
    // The sweep's working memory (its arrays and its slots), kept from build to build so
    // that a warm build on loops no larger than before allocates nothing.
    struct Scratch;
    std::unique_ptr<Scratch> scratch_;
};

template <class Used>
int64_t SagBanks::lowest(bool toLeft, uint32_t tail, int64_t lo, int64_t hi, Used&& used) const {
    const Side& s = side_[toLeft ? 0 : 1];
    if (tail >= s.edges) return -1;
    if (!s.has(tail)) {  // an empty list, counted as before
        ++work().nodeVisits;
        return -1;
    }
    const uint32_t k = s.list(tail);
    auto first = s.ranks.begin() + s.begin[k], last = s.ranks.begin() + s.begin[k + 1];
    // The first rank above lo: a binary search (short: a bank sees few sags).
    while (first != last) {
        auto mid = first + (last - first) / 2;
        if (int64_t(*mid) <= lo) first = mid + 1;
        else last = mid;
    }
    ++work().nodeVisits;
    for (last = s.ranks.begin() + s.begin[k + 1]; first != last && int64_t(*first) < hi; ++first) {
        ++work().nodeVisits;
        if (!used(*first)) return *first;
    }
    return -1;
}

}  // namespace flood
