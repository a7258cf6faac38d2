// The paper's "below" (§3) made a strict total order on the flood machine's nodes, along the
// chosen vertical: on the axes a comparison of coordinates turned so that the vertical is +y,
// off them a comparison of ranks, the vertices sorted once by the exact height test.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <vector>

#include "loops.h"
#include "polygon.h"
#include "sag_index.h"
#include "up.h"

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
        if (general_) {
            const Index va = nodes_[a].v, vb = nodes_[b].v;
            return va != vb ? rank_[va] < rank_[vb] : a < b;
        }
        Point pa = at(a), pb = at(b);
        if (pa.y != pb.y) return pa.y < pb.y;
        if (pa.x != pb.x) return pa.x < pb.x;
        if (nodes_[a].v != nodes_[b].v) return nodes_[a].v < nodes_[b].v;
        return a < b;
    }
    // The vertices lower than both their neighbours along their ring: at least the sags of
    // the machine's loops unless rings touch (merged loops have other neighbours there).
    size_t ringMinima() const;
    // The same order as lower(), as a value (sag_index.h).
    HeightKey key(NodeId n) const {
        if (general_) return {double(rank_[nodes_[n].v]), 0, nodes_[n].v, n};
        return {at(n).y, at(n).x, nodes_[n].v, n};
    }
    // Sorts nodes by lower(), comparing contiguous keys rather than chasing node -> vertex
    // -> point on every comparison; `keys` gets the sorted keys.
    void sort(std::vector<NodeId>& ns, std::vector<HeightKey>& keys) const;

private:
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
