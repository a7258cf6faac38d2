// The paper's "below" (§3) made a strict total order on the flood machine's nodes, along the
// chosen vertical: on the axes a comparison of coordinates turned so that the vertical is +y,
// off them a comparison of ranks, the vertices sorted once by the exact height test.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/geometry/up.h"
#include "machine/loops.h"
#include "machine/sags/sag_index.h"

namespace flood {

class Heights {
public:
    // The vertices of `poly` as the machine sees them: turned into `rotated` when `up` is an
    // axis other than +y, else as given. Off the axes rank() must run before any comparison;
    // it fills `rank` (per vertex) using `order` as scratch: both lent, so a warm run off the
    // axes allocates nothing either.
    Heights(const Polygon& poly, Up up, const Nodes& nodes, std::vector<Point>& rotated,
            std::vector<uint32_t>& rank, std::vector<Index>& order);
    // Off the axes no coordinate is a height: the vertices are sorted once by the exact
    // comparison along the direction (ties along its perpendicular, then by index, as
    // lower()) and compared by rank from then on. Non-finite vertices go last.
    void rank();

    Up up() const { return up_; }
    bool general() const { return general_; }  // off the axes: heights are ranks
    const Point* points() const { return pts_; }
    const Nodes& nodes() const { return nodes_; }
    Point at(NodeId n) const { return pts_[nodes_[n].v]; }

    // The paper's below: coincident vertices (rings touching at a point, bridge copies) are
    // ordered by vertex index, then node id.
    bool lower(NodeId a, NodeId b) const {
        return lowerIn(&nodes_[NodeId(0)], general_ ? rank_.data() : nullptr, a, b);
    }
    // Appends to `out` the nodes of `ns` lower than both their neighbours, in the order given:
    // the arrays read held in registers across the appends, which might alias them.
    void minima(const std::vector<NodeId>& ns, std::vector<NodeId>& out) const {
        if (ns.empty()) return;
        const Node* node = &nodes_[NodeId(0)];
        const uint32_t* rank = general_ ? rank_.data() : nullptr;
        for (NodeId n : ns) {
            const Node& x = node[uint32_t(n)];
            if (lowerIn(node, rank, n, x.prev) && lowerIn(node, rank, n, x.next)) out.push_back(n);
        }
    }
    // The vertices lower than both their neighbours along their ring: at least the sags of
    // the machine's loops unless rings touch (merged loops have other neighbours there). Of
    // the rings [firstRing, endRing).
    size_t ringMinima(Index firstRing, Index endRing) const;
    // The same order as lower(), as a value (sag_index.h).
    HeightKey key(NodeId n) const {
        if (general_) return {double(rank_[nodes_[n].v]), 0, nodes_[n].v, n};
        return {at(n).y, at(n).x, nodes_[n].v, n};
    }
    // Sorts nodes by lower(), comparing contiguous keys rather than chasing node -> vertex
    // -> point on every comparison; `keys` gets the sorted keys.
    void sort(std::vector<NodeId>& ns, std::vector<HeightKey>& keys) const;

private:
    // lower() over the node array `node` and, off the axes, the ranks `rank` (else null).
    bool lowerIn(const Node* node, const uint32_t* rank, NodeId a, NodeId b) const {
        const Index va = node[uint32_t(a)].v, vb = node[uint32_t(b)].v;
        if (rank) return va != vb ? rank[va] < rank[vb] : a < b;
        const Point pa = pts_[va], pb = pts_[vb];
        if (pa.y != pb.y) return pa.y < pb.y;
        if (pa.x != pb.x) return pa.x < pb.x;
        if (va != vb) return va < vb;
        return a < b;
    }
    bool lowerVertex(Index a, Index b) const;  // lower() on two distinct vertices
    const Polygon& poly_;
    const Nodes& nodes_;
    const Up up_;
    const bool general_;
    const Point* pts_ = nullptr;
    std::vector<uint32_t>& rank_;  // per vertex, off the axes: its rank by height along up_
    std::vector<Index>& order_;    // rank()'s scratch
};

}  // namespace flood
