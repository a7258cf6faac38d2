#include "sag_index.h"

#include <algorithm>
#include <cmath>

namespace flood {

namespace {
constexpr uint32_t kLeafSize = 8;
}

void SagIndex::build(const std::vector<Point>& pointOfRank) {
    const uint32_t n = uint32_t(pointOfRank.size());
    used_.assign(n, 0);
    items_.resize(n);
    for (uint32_t r = 0; r < n; ++r) items_[r] = {pointOfRank[r], r};
    nodes_.clear();
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeafSize + 1));
    buildNode(0, n, 0);
}

uint32_t SagIndex::buildNode(uint32_t begin, uint32_t end, int depth) {
    uint32_t id = uint32_t(nodes_.size());
    nodes_.push_back({});
    Node n;
    n.begin = begin;
    n.end = end;
    n.xMin = n.yMin = INFINITY;
    n.xMax = n.yMax = -INFINITY;
    n.rankMin = UINT32_MAX;
    n.rankMax = 0;
    for (uint32_t i = begin; i < end; ++i) {
        const Item& it = items_[i];
        n.xMin = std::min(n.xMin, it.p.x), n.xMax = std::max(n.xMax, it.p.x);
        n.yMin = std::min(n.yMin, it.p.y), n.yMax = std::max(n.yMax, it.p.y);
        n.rankMin = std::min(n.rankMin, it.rank), n.rankMax = std::max(n.rankMax, it.rank);
    }
    if (end - begin > kLeafSize) {
        // Split the wider side of the box at the median.
        bool byX = (n.xMax - n.xMin) >= (n.yMax - n.yMin);
        (void)depth;
        uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                         [byX](const Item& a, const Item& b) { return byX ? a.p.x < b.p.x : a.p.y < b.p.y; });
        n.left = buildNode(begin, mid, depth + 1);
        n.right = buildNode(mid, end, depth + 1);
    }
    nodes_[id] = n;
    return id;
}

// Conservative point test: false only when p is clearly outside the region.
bool SagIndex::mayContain(const Region& r, Point p) {
    if (p.x < r.xMin || p.x > r.xMax || p.y < r.yMin || p.y > r.yMax) return false;
    for (int k = 0; k < r.lineCount; ++k) {
        Point a = r.lines[k][0], b = r.lines[k][1];
        double dx = b.x - a.x, dy = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
        double cross = dx * py - dy * px;
        if (cross < -(1e-9 * (std::fabs(dx * py) + std::fabs(dy * px)) + 1e-300)) return false;
    }
    return true;
}

// True when no point of the node's box can lie in the region. Conservative: the line tests are
// floating-point with a generous error margin, so a box is pruned only when clearly outside.
bool SagIndex::outside(const Node& n, const Region& r) const {
    if (n.xMax < r.xMin || n.xMin > r.xMax || n.yMax < r.yMin || n.yMin > r.yMax) return true;
    for (int k = 0; k < r.lineCount; ++k) {
        Point a = r.lines[k][0], b = r.lines[k][1];
        double dx = b.x - a.x, dy = b.y - a.y;
        bool allRight = true;
        for (int c = 0; c < 4 && allRight; ++c) {
            double px = (c & 1 ? n.xMax : n.xMin) - a.x, py = (c & 2 ? n.yMax : n.yMin) - a.y;
            double cross = dx * py - dy * px;
            double margin = 1e-9 * (std::fabs(dx * py) + std::fabs(dy * px)) + 1e-300;
            allRight = cross < -margin;
        }
        if (allRight) return true;
    }
    return false;
}

}  // namespace flood
