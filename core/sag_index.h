// The sorted sag list (§4), indexed by x as well, so that a gorge looks only at the sags that
// could lie under it. The paper scans every sag between the water and Next: O(S·G) over a run
// (§7), quadratic on jagged outlines. Here the candidates are also limited to the x-range of
// the quadrangle Left, Right, NextRight, NextLeft, with a merge-sort tree over x whose blocks
// hold height ranks in order: O(log² S) per search plus the candidates tested.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flood {

class SagIndex {
public:
    // xOfRank[r]: the x coordinate of the sag of height rank r (ranks: sags sorted by height).
    void build(const std::vector<double>& xOfRank);
    size_t size() const { return used_.size(); }
    void markUsed(uint32_t rank) { used_[rank] = 1; }

    // The lowest unused rank in (lo, hi) whose x lies in [xmin, xmax] and for which
    // inside(rank) holds; inside is called on candidates in increasing rank. -1 if none.
    template <class Inside>
    int64_t lowest(int64_t lo, int64_t hi, double xmin, double xmax, Inside&& inside);

private:
    struct Cursor {
        uint32_t pos, end;  // into levels_[level]
        uint32_t level;
    };
    void blocks(uint32_t i, uint32_t j);  // fills cursors_ for positions [i, j) of byX_
    std::vector<double> sortedX_;               // x of byX_ order
    std::vector<std::vector<uint32_t>> levels_;  // levels_[l]: ranks sorted in blocks of 2^l
    std::vector<uint8_t> used_;
    std::vector<Cursor> cursors_;  // scratch, reused by every search
};

template <class Inside>
int64_t SagIndex::lowest(int64_t lo, int64_t hi, double xmin, double xmax, Inside&& inside) {
    if (used_.empty() || hi <= lo + 1) return -1;
    uint32_t i = uint32_t(std::lower_bound(sortedX_.begin(), sortedX_.end(), xmin) - sortedX_.begin());
    uint32_t j = uint32_t(std::upper_bound(sortedX_.begin(), sortedX_.end(), xmax) - sortedX_.begin());
    if (i >= j) return -1;
    blocks(i, j);
    for (Cursor& c : cursors_) {
        const std::vector<uint32_t>& a = levels_[c.level];
        if (lo >= 0)
            c.pos = uint32_t(std::upper_bound(a.begin() + c.pos, a.begin() + c.end, uint32_t(lo)) - a.begin());
    }
    // Merge the blocks by rank; there are at most 2 log S of them, so a linear pick is fine.
    for (;;) {
        Cursor* best = nullptr;
        uint32_t bestRank = 0;
        for (Cursor& c : cursors_) {
            if (c.pos >= c.end) continue;
            uint32_t r = levels_[c.level][c.pos];
            if (!best || r < bestRank) best = &c, bestRank = r;
        }
        if (!best || int64_t(bestRank) >= hi) return -1;
        ++best->pos;
        if (!used_[bestRank] && inside(bestRank)) return bestRank;
    }
}

}  // namespace flood
