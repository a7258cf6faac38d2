// The sorted sag list (§4), indexed in the plane as well, so that a gorge looks only at the
// sags that could lie in it. The paper scans every sag between the water and Next: O(S·G)
// over a run (§7), quadratic on jagged outlines. Here the sags also sit in a k-d tree whose
// boxes are pruned by the gorge's bank lines, the water's height band and the sags already
// used, so a search visits the sags near the gorge rather than every sag at its height. The
// exact `inside` test still decides; the pruning only has to be conservative, at every scale:
// boxes are exact doubles, and the line tests run on coordinates scaled by a power of two so
// that nothing overflows or underflows enough to matter, from 2^-1074 to 2^1023.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/work.h"
#include "machine/node_id.h"

namespace flood {

class Heights;  // heights.h

// The order of heights the flood machine uses (below(), ties by vertex index, then node id),
// as a value: what the sorted sag list is searched with. Off the axes y is the vertex's height
// rank and x is 0.
struct HeightKey {
    double y, x;
    uint32_t v;
    NodeId node;
    bool operator<(const HeightKey& o) const {
        if (y != o.y) return y < o.y;
        if (x != o.x) return x < o.x;
        if (v != o.v) return v < o.v;
        return node < o.node;
    }
};

// The sorted sag list's ranks (§4): how many sags lie strictly below a height, by a binary
// search within one bucket of an equal-height span over the sags' heights, on their y alone
// (the y of their points by rank on the axes, where a key's y is its point's; a copy of the
// keys' y off them) and on the full keys only to break a tie. Large sorted keys (24 bytes a sag) are
// given back once their heights are taken (giveBackIfLarge()): a tie's keys are then rebuilt
// from the sags' nodes (Heights::key()), which give the same order.
class SagHeights {
public:
    std::vector<HeightKey>& keys() { return keys_; }  // the sags' keys, sorted; then index()
    // `sags` and `vertices`: the sags' nodes and vertices by rank (their points in `points`),
    // read by below() as long as it is called.
    void index(const Heights& heights, const std::vector<NodeId>& sags, const Point* points,
               const std::vector<uint32_t>& vertices);
    uint32_t below(const HeightKey& k) const;

private:
    size_t bucket(double y) const;
    double y(size_t rank) const { return points_ ? points_[vertices_[rank]].y : y_[rank]; }
    static constexpr size_t kSearchLimit = 16;  // up to this many sags: no buckets, one search
    std::vector<HeightKey> keys_;               // empty after index() when large
    size_t count_ = 0;                          // sags, from index() on
    const Heights* heights_ = nullptr;
    const std::vector<NodeId>* sags_ = nullptr;
    std::vector<double> y_;          // the sags' keys' y, by rank, off the axes only
    const Point* points_ = nullptr;  // on the axes: the points, read through vertices_
    const uint32_t* vertices_ = nullptr;
    std::vector<uint32_t> buckets_;  // first rank of each height bucket (bucket())
    double y0_ = 0, scale_ = 0;
};

class SagIndex {
public:
    // Where the sag must lie: a box, and strictly left of each directed line a->b given.
    struct Region {
        double xMin, xMax, yMin, yMax;
        Point lines[2][2];
        int lineCount = 0;
    };

    // The sags' vertices by height rank (ranks: sags sorted by height), filled before build();
    // `points`: the vertices' points, read by the searches until the next build().
    std::vector<uint32_t>& vertices() { return vertexOfRank_; }
    void build(const Point* points);
    size_t size() const { return used_.size(); }
    bool used(uint32_t rank) const { return used_[rank]; }
    Point point(uint32_t rank) const { return points_[vertexOfRank_[rank]]; }
    void markUsed(uint32_t rank);

    // The lowest unused rank in (lo, hi) within `region` for which inside(rank) holds;
    // -1 if none. `inside` is only called on candidates in the region.
    template <class Inside>
    int64_t lowest(int64_t lo, int64_t hi, const Region& region, Inside&& inside);

private:
    // Implicit complete tree: node i has children 2i+1, 2i+2; every leaf is at depth depth_.
    // Boxes are the exact extremes of their sags (floats would overflow past 3.4e38 and
    // flush below 1e-38, losing all pruning there).
    struct Node {
        double xMin, xMax, yMin, yMax;
        uint32_t rankMin, rankMax;
        uint32_t begin, unused;  // first item; sags of the subtree not used yet
    };
    // A search's bank lines, prepared once, in coordinates multiplied by `scale`: a power of
    // two (exact, bar underflow) that brings the region's largest |coordinate| into
    // [2^-51, 2^-50). Every point tested lies in the region's box, so differences stay below
    // 2^-49 and products below 2^-97: no overflow at any input scale, and underflow only in
    // components below 2^-1022, whose absolute errors (< 2^-1074 each) the margin covers.
    struct Line {
        double ax, ay, dx, dy;
    };
    struct Frame {
        double scale = 1;
        Line lines[2];
        int lineCount = 0;
    };
    static Frame frameOf(const Region& r);
    struct Item {  // build()'s: a sag's point beside its rank, for the splits
        Point p;
        uint32_t rank;
    };
    void buildNode(uint32_t id, uint32_t begin, uint32_t end, int depth);
    static bool leftOf(const Line& l, double px, double py);
    static bool outside(const Node& n, const Region& r, const Frame& f);
    static bool mayContain(const Region& r, const Frame& f, Point p);
    std::vector<Node> nodes_;                   // empty when there are kScanLimit sags or fewer
    static constexpr uint32_t kScanLimit = 48;  // brackets up to this many sags are scanned
    std::vector<Item> build_;                   // build()'s scratch
    std::vector<uint32_t> items_;               // ranks, leaf after leaf; their points by point()
    std::vector<uint32_t> vertexOfRank_;        // not their points: 12 bytes a sag less
    const Point* points_ = nullptr;
    std::vector<uint32_t> leafOfRank_;  // rank -> leaf node id
    std::vector<uint8_t> used_;
    std::vector<uint32_t> stack_;  // scratch, reused by every search
    int depth_ = 0;
    uint32_t firstLeaf_ = 0;
};

// Might the scaled point (px, py) be strictly left of the line? False only when it is clearly
// right: the cross product's rounding error is below 4·2^-53·(|a| + |b|) plus the underflow
// errors, both far inside the margin. Written so that a NaN would keep the point.
inline bool SagIndex::leftOf(const Line& l, double px, double py) {
    px -= l.ax, py -= l.ay;
    double a = l.dx * py, b = l.dy * px;
    return !(a - b < -(1e-9 * (std::abs(a) + std::abs(b)) + 0x1p-1000));
}

template <class Inside>
int64_t SagIndex::lowest(int64_t lo, int64_t hi, const Region& region, Inside&& inside) {
    if (used_.empty() || hi <= lo + 1) return -1;
    const Frame frame = frameOf(region);
    int64_t best = hi;  // candidates must beat this
    if (nodes_.empty() || hi - lo - 1 <= int64_t(kScanLimit)) {
        // A thin band (or a list too short for a tree) holds few sags: scan them in rank order,
        // as the paper does (§4).
        for (int64_t r = std::max<int64_t>(lo + 1, 0); r < hi && r < int64_t(used_.size()); ++r) {
            ++work().nodeVisits;
            if (!used_[size_t(r)] && mayContain(region, frame, point(uint32_t(r))) &&
                inside(uint32_t(r)))
                return r;
        }
        return -1;
    }
    stack_.clear();
    stack_.push_back(0);
    while (!stack_.empty()) {
        uint32_t id = stack_.back();
        stack_.pop_back();
        ++work().nodeVisits;  // a box of the tree
        const Node& n = nodes_[id];
        if (n.unused == 0 || int64_t(n.rankMax) <= lo || int64_t(n.rankMin) >= best ||
            outside(n, region, frame))
            continue;
        if (id >= firstLeaf_) {
            uint32_t end = id + 1 < nodes_.size() ? nodes_[id + 1].begin : uint32_t(items_.size());
            for (uint32_t i = n.begin; i < end; ++i) {
                uint32_t r = items_[i];
                ++work().nodeVisits;
                if (int64_t(r) <= lo || int64_t(r) >= best || used_[r]) continue;
                if (!mayContain(region, frame, point(r))) continue;
                if (inside(r)) best = r;
            }
            continue;
        }
        // Visit the child with the lower ranks first: it is likelier to hold the answer.
        uint32_t a = 2 * id + 1, b = a + 1;
        if (nodes_[b].rankMin < nodes_[a].rankMin) std::swap(a, b);
        stack_.push_back(b);
        stack_.push_back(a);
    }
    return best < hi ? best : -1;
}

}  // namespace flood
