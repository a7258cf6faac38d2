#include "sag_index.h"

#include <algorithm>
#include <cmath>

namespace flood {

namespace {
constexpr uint32_t kLeafSize = 8;

float roundDown(double v) {
    float f = float(v);
    return double(f) > v ? std::nextafter(f, -INFINITY) : f;
}
float roundUp(double v) {
    float f = float(v);
    return double(f) < v ? std::nextafter(f, INFINITY) : f;
}
}  // namespace

void SagIndex::build(const std::vector<Point>& pointOfRank) {
    const uint32_t n = uint32_t(pointOfRank.size());
    used_.assign(n, 0);
    items_.resize(n);
    byRank_ = pointOfRank;
    for (uint32_t r = 0; r < n; ++r) items_[r] = {pointOfRank[r], r};
    nodes_.clear();
    if (n == 0) return;
    depth_ = 0;
    while ((uint64_t(n) >> depth_) > kLeafSize) ++depth_;
    firstLeaf_ = (1u << depth_) - 1;
    nodes_.resize((2u << depth_) - 1);
    leafOfRank_.resize(n);
    buildNode(0, 0, n, 0);
}

void SagIndex::buildNode(uint32_t id, uint32_t begin, uint32_t end, int depth) {
    Node& n = nodes_[id];
    n.begin = begin;
    n.unused = end - begin;
    double xMin = INFINITY, yMin = INFINITY, xMax = -INFINITY, yMax = -INFINITY;
    uint32_t rankMin = UINT32_MAX, rankMax = 0;
    for (uint32_t i = begin; i < end; ++i) {
        const Item& it = items_[i];
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
    n.xMin = roundDown(xMin), n.yMin = roundDown(yMin);
    n.xMax = roundUp(xMax), n.yMax = roundUp(yMax);
    n.rankMin = rankMin, n.rankMax = rankMax;
    if (depth == depth_) {
        for (uint32_t i = begin; i < end; ++i) leafOfRank_[items_[i].rank] = id;
        return;
    }
    // Split the wider side of the box at the median.
    bool byX = (xMax - xMin) >= (yMax - yMin);
    uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                     [byX](const Item& a, const Item& b) { return byX ? a.p.x < b.p.x : a.p.y < b.p.y; });
    buildNode(2 * id + 1, begin, mid, depth + 1);
    buildNode(2 * id + 2, mid, end, depth + 1);
}

void SagIndex::markUsed(uint32_t rank) {
    if (used_[rank]) return;
    used_[rank] = 1;
    for (uint32_t id = leafOfRank_[rank];; id = (id - 1) / 2) {
        --nodes_[id].unused;
        if (id == 0) break;
    }
}

// Conservative point test: false only when p is clearly outside the region.
bool SagIndex::mayContain(const Region& r, const Line* lines, Point p) {
    if (p.x < r.xMin || p.x > r.xMax || p.y < r.yMin || p.y > r.yMax) return false;
    for (int k = 0; k < r.lineCount; ++k)
        if (!leftOf(lines[k], p.x, p.y)) return false;
    return true;
}

// True when no point of the node's box can lie in the region. Conservative: the line tests are
// floating-point with a generous error margin, so a box is pruned only when clearly outside.
// Only the box corner farthest to the left of a line needs testing.
bool SagIndex::outside(const Node& n, const Region& r, const Line* lines) const {
    if (n.xMax < r.xMin || n.xMin > r.xMax || n.yMax < r.yMin || n.yMin > r.yMax) return true;
    for (int k = 0; k < r.lineCount; ++k) {
        const Line& l = lines[k];
        // cross = dx·(py − ay) − dy·(px − ax) grows with py when dx > 0, with px when dy < 0.
        double px = l.dy < 0 ? n.xMax : n.xMin, py = l.dx > 0 ? n.yMax : n.yMin;
        if (!leftOf(l, px, py)) return true;
    }
    return false;
}

}  // namespace flood
