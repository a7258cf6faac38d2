// The sorted sag list (§4), indexed in the plane as well, so that a gorge looks only at the
// sags that could lie in it. The paper scans every sag between the water and Next: O(S·G)
// over a run (§7), quadratic on jagged outlines. Here the sags also sit in a k-d tree whose
// boxes are pruned by the gorge's bank lines and the water's height band, so a search visits
// the sags near the gorge rather than every sag at its height. The exact `inside` test still
// decides; the pruning only has to be conservative.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "polygon.h"

namespace flood {

class SagIndex {
public:
    // Where the sag must lie: a box, and strictly left of each directed line a->b given.
    struct Region {
        double xMin, xMax, yMin, yMax;
        Point lines[2][2];
        int lineCount = 0;
    };

    // pointOfRank[r]: the sag of height rank r (ranks: sags sorted by height).
    void build(const std::vector<Point>& pointOfRank);
    size_t size() const { return used_.size(); }
    void markUsed(uint32_t rank) { used_[rank] = 1; }

    // The lowest unused rank in (lo, hi) within `region` for which inside(rank) holds;
    // -1 if none. `inside` is only called on candidates in the region.
    template <class Inside>
    int64_t lowest(int64_t lo, int64_t hi, const Region& region, Inside&& inside);

private:
    struct Node {
        double xMin, xMax, yMin, yMax;
        uint32_t rankMin, rankMax;
        uint32_t begin, end;          // range of items_
        uint32_t left = 0, right = 0;  // children (0: leaf)
    };
    struct Item {
        Point p;
        uint32_t rank;
    };
    uint32_t buildNode(uint32_t begin, uint32_t end, int depth);
    bool outside(const Node& n, const Region& r) const;
    static bool mayContain(const Region& r, Point p);
    std::vector<Node> nodes_;
    std::vector<Item> items_;
    std::vector<uint8_t> used_;
    std::vector<uint32_t> stack_;  // scratch, reused by every search
};

template <class Inside>
int64_t SagIndex::lowest(int64_t lo, int64_t hi, const Region& region, Inside&& inside) {
    if (items_.empty() || hi <= lo + 1) return -1;
    int64_t best = hi;  // candidates must beat this
    stack_.assign(1, 0);
    while (!stack_.empty()) {
        const Node& n = nodes_[stack_.back()];
        stack_.pop_back();
        if (int64_t(n.rankMax) <= lo || int64_t(n.rankMin) >= best || outside(n, region)) continue;
        if (n.left == 0) {
            for (uint32_t i = n.begin; i < n.end; ++i) {
                uint32_t r = items_[i].rank;
                if (int64_t(r) <= lo || int64_t(r) >= best || used_[r]) continue;
                if (!mayContain(region, items_[i].p)) continue;
                if (inside(r)) best = r;
            }
            continue;
        }
        // Visit the child with the lower ranks first: it is likelier to hold the answer.
        uint32_t a = n.left, b = n.right;
        if (nodes_[b].rankMin < nodes_[a].rankMin) std::swap(a, b);
        stack_.push_back(b);
        stack_.push_back(a);
    }
    return best < hi ? best : -1;
}

}  // namespace flood
