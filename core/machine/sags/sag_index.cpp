#include "machine/sags/sag_index.h"

#include <algorithm>
#include <cmath>

#include "machine/heights.h"

namespace flood {

namespace {
constexpr uint32_t kLeafSize = 8;
}  // namespace

// The bucket of y never decreases as y grows (rounding is monotone), so the sags of the
// buckets below y's are all lower than y and those above all higher: a search for y needs only
// its own bucket. Monotone at every scale too: a span that overflows gives scale 0, so every
// height is in bucket 0 except those whose difference is infinite (inf · 0 = NaN: the last
// bucket); one so small that the scale is infinite puts every height above the lowest in the
// last bucket.
size_t SagHeights::bucket(double y) const {
    const size_t last = buckets_.size() - 2;
    if (!(y > y0_)) return 0;
    double b = (y - y0_) * scale_;
    return b < double(last) ? size_t(b) : last;
}

void SagHeights::index(const Heights& heights, const std::vector<NodeId>& sags, const Point* points,
                       const std::vector<uint32_t>& vertices) {
    heights_ = &heights, sags_ = &sags;
    const size_t count = count_ = keys_.size();
    if (count <= kSearchLimit) return;  // below() searches the keys themselves
    points_ = heights.general() ? nullptr : points;
    vertices_ = vertices.data();
    y_.clear();
    if (points_) {
        giveBackIfLarge(y_);
    } else {  // a key's y is its vertex's height rank
        y_.resize(count);
        for (size_t k = 0; k < count; ++k) y_[k] = keys_[k].y;
    }
    giveBackIfLarge(keys_);  // below() then rebuilds a tie's keys from the sags
    const size_t buckets = count / 2 + 1;
    y0_ = count ? y(0) : 0;
    double span = count ? y(count - 1) - y0_ : 0;
    scale_ = span > 0 && std::isfinite(span) ? double(buckets) / span : 0;
    buckets_.assign(buckets + 1, uint32_t(count));
    size_t filled = 0;
    for (size_t k = 0; k < count; ++k)
        for (size_t b = bucket(y(k)); filled <= b;) buckets_[filled++] = uint32_t(k);
}

uint32_t SagHeights::below(const HeightKey& k) const {
    if (count_ <= kSearchLimit)
        return uint32_t(std::lower_bound(keys_.begin(), keys_.end(), k) - keys_.begin());
    size_t b = bucket(k.y);
    size_t a = buckets_[b];
    for (size_t last = buckets_[b + 1]; a < last;) {  // the first y not below k.y
        size_t m = a + (last - a) / 2;
        if (y(m) < k.y) a = m + 1;
        else last = m;
    }
    if (a < count_ && y(a) == k.y) {
        // Among the sags of height k.y (all in this bucket), the first whose key is not below
        // k's: the keys rise with the rank. Given back, a key is rebuilt from its sag's node.
        size_t end = buckets_[b + 1];
        while (a < end) {
            size_t m = a + (end - a) / 2;
            const HeightKey km = keys_.empty() ? heights_->key((*sags_)[m]) : keys_[m];
            if (km < k) a = m + 1;
            else end = m;
        }
    }
    return uint32_t(a);
}

void SagIndex::build(const Point* points) {
    points_ = points;
    const uint32_t n = uint32_t(vertexOfRank_.size());
    used_.assign(n, 0);
    nodes_.clear();
    items_.clear();
    // lowest() scans a bracket of at most kScanLimit sags: so few sags need no tree.
    if (n <= kScanLimit) return;
    build_.resize(n);
    for (uint32_t r = 0; r < n; ++r) build_[r] = {point(r), r};
    depth_ = 0;
    while ((uint64_t(n) >> depth_) > kLeafSize) ++depth_;
    firstLeaf_ = (1u << depth_) - 1;
    nodes_.resize((2u << depth_) - 1);
    leafOfRank_.resize(n);
    buildNode(0, 0, n, 0);
    // The search reads the leaves' ranks alone (4 bytes a sag, not 24), their points by point().
    items_.resize(n);
    for (uint32_t i = 0; i < n; ++i) items_[i] = build_[i].rank;
    giveBackIfLarge(build_);
}

void SagIndex::buildNode(uint32_t id, uint32_t begin, uint32_t end, int depth) {
    Node& n = nodes_[id];
    n.begin = begin;
    n.unused = end - begin;
    double xMin = INFINITY, yMin = INFINITY, xMax = -INFINITY, yMax = -INFINITY;
    uint32_t rankMin = UINT32_MAX, rankMax = 0;
    for (uint32_t i = begin; i < end; ++i) {
        const Item& it = build_[i];
        xMin = std::min(xMin, it.p.x), xMax = std::max(xMax, it.p.x);
        yMin = std::min(yMin, it.p.y), yMax = std::max(yMax, it.p.y);
        rankMin = std::min(rankMin, it.rank), rankMax = std::max(rankMax, it.rank);
    }
    if (begin == end) {  // an empty leaf of the complete tree: never matches
        n.xMin = n.yMin = INFINITY;
        n.xMax = n.yMax = -INFINITY;
        n.rankMin = UINT32_MAX, n.rankMax = 0;
        return;
    }
    n.xMin = xMin, n.yMin = yMin, n.xMax = xMax, n.yMax = yMax;
    n.rankMin = rankMin, n.rankMax = rankMax;
    if (depth == depth_) {
        for (uint32_t i = begin; i < end; ++i) leafOfRank_[build_[i].rank] = id;
        return;
    }
    // Split the wider side of the box at the median.
    bool byX = (xMax - xMin) >= (yMax - yMin);
    uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(
        build_.begin() + begin, build_.begin() + mid, build_.begin() + end,
        [byX](const Item& a, const Item& b) { return byX ? a.p.x < b.p.x : a.p.y < b.p.y; });
    buildNode(2 * id + 1, begin, mid, depth + 1);
    buildNode(2 * id + 2, mid, end, depth + 1);
}

void SagIndex::markUsed(uint32_t rank) {
    if (used_[rank]) return;
    used_[rank] = 1;
    if (nodes_.empty()) return;  // no tree (build())
    for (uint32_t id = leafOfRank_[rank];; id = (id - 1) / 2) {
        --nodes_[id].unused;
        if (id == 0) break;
    }
}

SagIndex::Frame SagIndex::frameOf(const Region& r) {
    double m = std::max({std::abs(r.xMin), std::abs(r.xMax), std::abs(r.yMin), std::abs(r.yMax)});
    for (int k = 0; k < r.lineCount; ++k)
        for (Point p : r.lines[k]) m = std::max({m, std::abs(p.x), std::abs(p.y)});
    Frame f;
    if (m > 0 && std::isfinite(m)) {
        int e;
        std::frexp(m, &e);                   // m in [2^(e-1), 2^e), e in [-1073, 1024]
        f.scale = std::ldexp(1.0, -50 - e);  // 2^-1074 .. 2^1023: a double
    }
    f.lineCount = r.lineCount;
    for (int k = 0; k < r.lineCount; ++k) {
        Point a = r.lines[k][0], b = r.lines[k][1];
        double ax = a.x * f.scale, ay = a.y * f.scale;
        f.lines[k] = {ax, ay, b.x * f.scale - ax, b.y * f.scale - ay};
    }
    return f;
}

// Conservative point test: false only when p is clearly outside the region.
bool SagIndex::mayContain(const Region& r, const Frame& f, Point p) {
    if (p.x < r.xMin || p.x > r.xMax || p.y < r.yMin || p.y > r.yMax) return false;
    for (int k = 0; k < f.lineCount; ++k)
        if (!leftOf(f.lines[k], p.x * f.scale, p.y * f.scale)) return false;
    return true;
}

// True when no point of the node's box can lie in the region. The box tests are exact; the
// line tests need only the corner of the box ∩ region farthest to the left of each line
// (clamping to the region keeps the tested point inside the frame's bounds).
bool SagIndex::outside(const Node& n, const Region& r, const Frame& f) {
    if (n.xMax < r.xMin || n.xMin > r.xMax || n.yMax < r.yMin || n.yMin > r.yMax) return true;
    for (int k = 0; k < f.lineCount; ++k) {
        const Line& l = f.lines[k];
        // cross = dx·(py − ay) − dy·(px − ax) grows with py when dx > 0, with px when dy < 0.
        double px = l.dy < 0 ? std::min(n.xMax, r.xMax) : std::max(n.xMin, r.xMin);
        double py = l.dx > 0 ? std::min(n.yMax, r.yMax) : std::max(n.yMin, r.yMin);
        if (!leftOf(l, px * f.scale, py * f.scale)) return true;
    }
    return false;
}

}  // namespace flood
