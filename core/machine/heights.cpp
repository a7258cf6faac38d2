// The machine's order of heights (heights.h).
#include "machine/heights.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"

namespace flood {
namespace {

// Exact coordinate permutation making an axis direction +y (a rotation: keeps orientation).
// Only for the axes: off them heights are compared exactly along the direction (rank()).
Point toUp(Point p, Up up) {
    if (up.x == 0) return up.y > 0 ? p : Point{-p.x, -p.y};
    return up.x > 0 ? Point{-p.y, p.x} : Point{p.y, -p.x};
}

}  // namespace

Heights::Heights(const Polygon& poly, Up up, const Nodes& nodes, std::vector<Point>& rotated,
                 std::vector<uint32_t>& rank, std::vector<Index>& order)
    : poly_(poly), nodes_(nodes), up_(up), general_(!up.axis()), rank_(rank), order_(order) {
    if (general_ || (up.x == 0 && up.y > 0)) {  // heights are the input's or ranks: no copy
        pts_ = poly.vertices.data();
        return;
    }
    rotated.clear();
    rotated.reserve(poly.vertices.size());
    for (Point p : poly.vertices) rotated.push_back(toUp(p, up));
    pts_ = rotated.data();
}

void Heights::rank() {
    std::vector<Index>& order = order_;
    order.resize(poly_.vertices.size());
    std::iota(order.begin(), order.end(), Index(0));
    auto finite = [&](Index v) { return std::isfinite(pts_[v].x) && std::isfinite(pts_[v].y); };
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
        const bool fa = finite(a), fb = finite(b);
        if (fa != fb || !fa) return fa != fb ? fa : a < b;
        int h = heightSign(up_, pts_[a], pts_[b]);
        if (h == 0) h = acrossSign(up_, pts_[a], pts_[b]);
        return h != 0 ? h > 0 : a < b;
    });
    rank_.resize(order.size());
    for (size_t k = 0; k < order.size(); ++k) rank_[order[k]] = uint32_t(k);
    work().nodeVisits += order.size();
}

bool Heights::lowerVertex(Index a, Index b) const {
    if (general_) return rank_[a] < rank_[b];
    const Point pa = pts_[a], pb = pts_[b];
    if (pa.y != pb.y) return pa.y < pb.y;
    if (pa.x != pb.x) return pa.x < pb.x;
    return a < b;
}

size_t Heights::ringMinima(Index firstRing, Index endRing) const {
    size_t minima = 0;
    for (Index k = firstRing; k < endRing; ++k) {
        const Ring& r = poly_.rings[k];
        work().nodeVisits += r.count;
        if (r.count < 3) {
            minima += r.count == 1;  // a point hole: a sag
            continue;
        }
        Index before = r.first + r.count - 1;
        for (Index v = r.first, end = r.first + r.count; v < end; before = v++) {
            const Index after = v + 1 == end ? r.first : v + 1;
            minima += lowerVertex(v, before) && lowerVertex(v, after);
        }
    }
    return minima;
}

void Heights::sort(std::vector<NodeId>& ns, std::vector<HeightKey>& keys) const {
    keys.resize(ns.size());
    for (size_t i = 0; i < ns.size(); ++i) keys[i] = key(ns[i]);
    if (ns.size() < 2) return;  // sorted already (a part with one sag is common)
    std::sort(keys.begin(), keys.end());
    for (size_t i = 0; i < ns.size(); ++i) ns[i] = keys[i].node;
}

}  // namespace flood
