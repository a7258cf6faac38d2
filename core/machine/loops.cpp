#include "machine/loops.h"

#include <algorithm>

#include "flood/geometry/predicates.h"
#include "flood/geometry/ring_area.h"
#include "flood/geometry/work.h"

namespace flood {
namespace {

class LoopBuilder {
public:
    LoopBuilder(const Polygon& poly, const Point* pts, Nodes& nodes, LoopScratch& b)
        : poly_(poly), pts_(pts), nodes_(nodes), b_(b) {}

    PartLoops build(const Part& pa, std::vector<NodeId>& partVertices,
                    std::vector<NodeId>& points) {
        // T-junctions of the part (validate() found them): each adds a node on its edge.
        auto split = std::lower_bound(poly_.splits.begin(), poly_.splits.end(),
                                      poly_.rings[pa.firstRing].first,
                                      [](const EdgeSplit& s, Index v) { return s.edge < v; });
        PartLoops out;
        std::vector<Index>& loop = b_.loop;
        for (Index r = pa.firstRing; r < pa.firstRing + pa.ringCount; ++r) {
            const Ring& ring = poly_.rings[r];
            // A ring without T-junctions is its own loop; only the others are copied out.
            const bool plain =
                split == poly_.splits.end() || split->edge >= ring.first + ring.count;
            loop.clear();
            for (Index v = ring.first; !plain && v < ring.first + ring.count; ++v) {
                loop.push_back(v);
                for (; split != poly_.splits.end() && split->edge == v; ++split)
                    loop.push_back(split->vertex);
            }
            // Orient loops so the interior is on the left: outer counter-clockwise, holes
            // clockwise, whatever the file said.
            bool wantCcw = (r == pa.firstRing);
            bool reverse =
                ring.count >= 3 && (ringOrientation(pts_ + ring.first, ring.count) > 0) != wantCcw;
            const NodeId base = nodes_.end();
            const uint32_t count = plain ? ring.count : uint32_t(loop.size());
            Node* nd = nodes_.append(count);
            for (uint32_t i = 0; i < count; ++i) {
                nd[i].v = plain ? ring.first + i : loop[i];
                NodeId p = base + (i == 0 ? count - 1 : i - 1);  // no division: set-up is most of
                NodeId q = base + (i + 1 == count ? 0 : i + 1);  // a small run
                nd[i].prev = reverse ? q : p;
                nd[i].next = reverse ? p : q;
            }
            // The loop's nodes are consecutive ids: listed in one go.
            std::vector<NodeId>& list = count > 1 ? partVertices : points;
            const size_t at = list.size();
            list.resize(at + count);
            for (uint32_t i = 0; i < count; ++i) list[at + i] = base + i;
            work().nodeVisits += count;
            if (r == pa.firstRing) out.outerNodes = count;
        }
        // Validation found no point shared by two vertices, nor a T-junction: nothing to merge.
        out.touching = !poly_.pointsDistinct && mergeTouchingLoops(partVertices);
        return out;
    }

private:
    Point P(NodeId n) const { return pts_[nodes_[n].v]; }
    NodeId prev(NodeId n) const { return nodes_[n].prev; }
    NodeId next(NodeId n) const { return nodes_[n].next; }

    // Rings touching at a point become one loop there: arriving at the point, the next edge
    // is the first one met rotating clockwise from the edge we came along (§1). The k passages
    // through a point are merged in O(k log k): their outgoing edges are sorted once by exact
    // angle, and each arrival takes the outgoing edge just before its own direction.
    // True when some point was shared (the loops may have changed).
    bool mergeTouchingLoops(const std::vector<NodeId>& partVertices) {
        work().touchSearchNodes += partVertices.size();
        repeatedPoints(
            partVertices.size(), [&](size_t i) { return P(partVertices[i]); }, b_.repeats);
        std::vector<std::pair<uint32_t, uint32_t>>& copies = b_.repeats.copies;
        if (copies.empty()) return false;
        for (auto& [first, later] : copies)  // from positions in partVertices to node ids
            first = uint32_t(partVertices[first]), later = uint32_t(partVertices[later]);
        std::sort(copies.begin(), copies.end());
        std::vector<NodeId>&corner = b_.corner, &newNext = b_.newNext;
        std::vector<std::pair<Point, uint32_t>>& outs = b_.outs;
        for (size_t g = 0; g < copies.size();) {
            corner.assign(1, NodeId(copies[g].first));
            size_t e = g;
            for (; e < copies.size() && copies[e].first == copies[g].first; ++e)
                corner.push_back(NodeId(copies[e].second));
            g = e;
            std::sort(corner.begin(), corner.end());
            const Point c = P(corner[0]);
            // Counter-clockwise from +x; among edges of one direction the first passage last,
            // so that the element before any position is the lowest passage of its direction.
            outs.clear();
            for (uint32_t i = 0; i < corner.size(); ++i) outs.emplace_back(P(next(corner[i])), i);
            auto before = [&](const std::pair<Point, uint32_t>& a,
                              const std::pair<Point, uint32_t>& b) {
                if (angleLess(c, a.first, b.first)) return true;
                if (angleLess(c, b.first, a.first)) return false;
                return a.second > b.second;
            };
            std::sort(outs.begin(), outs.end(), before);
            work().nodeVisits += corner.size();
            newNext.resize(corner.size());
            for (size_t i = 0; i < corner.size(); ++i) {
                // Clockwise from the arrival's direction: the last edge strictly before it
                // counter-clockwise, else (wrapping round) the last edge of all.
                Point back = P(prev(corner[i]));
                auto at = std::partition_point(outs.begin(), outs.end(),
                                               [&](const std::pair<Point, uint32_t>& o) {
                                                   return angleLess(c, o.first, back);
                                               });
                const auto& pick = at == outs.begin() ? outs.back() : *(at - 1);
                newNext[i] = next(corner[pick.second]);
            }
            for (size_t i = 0; i < corner.size(); ++i) {
                nodes_[corner[i]].next = newNext[i];
                nodes_[newNext[i]].prev = corner[i];
            }
        }
        return true;
    }

    // Direction c->a comes before c->b counter-clockwise from +x, exactly (half-planes, then
    // orient). A zero-length edge (only in invalid input) comes after every direction, so the
    // order stays a strict weak order.
    static int halfPlane(Point c, Point a) {
        if (a == c) return 2;
        return (a.y > c.y || (a.y == c.y && a.x > c.x)) ? 0 : 1;
    }
    static bool angleLess(Point c, Point a, Point b) {
        int ha = halfPlane(c, a), hb = halfPlane(c, b);
        if (ha != hb) return ha < hb;
        return ha < 2 && orient(c, a, b) > 0;
    }

    const Polygon& poly_;
    const Point* pts_;
    Nodes& nodes_;
    LoopScratch& b_;
};

}  // namespace

PartLoops buildLoops(const Polygon& polygon, const Point* pts, const Part& part, Nodes& nodes,
                     std::vector<NodeId>& vertices, std::vector<NodeId>& points,
                     LoopScratch& scratch) {
    return LoopBuilder(polygon, pts, nodes, scratch).build(part, vertices, points);
}

}  // namespace flood
