// Loop building (§1), the flood machine's set-up: a part's rings become circular doubly
// linked lists of nodes with the interior on the left, a node added at each T-junction, and
// rings that touch at a point merged into one loop there by the clockwise rule.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "coincident.h"
#include "node_id.h"
#include "polygon.h"

namespace flood {

constexpr uint32_t kNoGorge = kNone;

// A node is a reference to a vertex; coincident vertices and bridge copies are distinct nodes.
struct Node {
    Index v;  // vertex (index into the input)
    NodeId prev, next;
    NodeId jump = kNil;              // top: the other bank of its held gorge
    uint32_t gorgeLeft = kNoGorge;   // dormant gorge whose Left end is this node
    uint32_t gorgeRight = kNoGorge;  // dormant gorge whose Right end is this node
    bool alive = true;
    bool wet = false;  // has been in an active chain: the water reached it
};

// The nodes of every loop, indexed by NodeId alone.
class Nodes {
public:
    Node& operator[](NodeId n) { return nodes_[size_t(n)]; }
    const Node& operator[](NodeId n) const { return nodes_[size_t(n)]; }
    NodeId end() const { return NodeId(uint32_t(nodes_.size())); }  // the next node's id
    void push(const Node& n) { nodes_.push_back(n); }
    void clear() { nodes_.clear(); }
    void reserve(size_t n) { nodes_.reserve(n); }

private:
    std::vector<Node> nodes_;
};

// What loop building allocates, kept from run to run with the machine's buffers.
struct LoopScratch {
    std::vector<Index> loop;        // a ring with its T-junctions
    RepeatedPointsScratch repeats;  // the search for shared points (coincident.h)
    std::vector<NodeId> corner, newNext;
    std::vector<std::pair<Point, uint32_t>> outs;  // (where the edge goes, its passage)
};

struct PartLoops {
    uint32_t outerNodes = 0;  // nodes of the outer ring's loop: the first ones appended
    bool touching = false;    // some point was shared: loops were merged there
};

// Appends the loops of `part` to `nodes`, over the vertices as the machine sees them (`pts`,
// indexed like polygon.vertices). `vertices` gets the nodes of loops of several nodes,
// `points` those of one-node loops (Steiner points). The part's rings have three vertices or
// more, or one (a point hole), and finite coordinates: the machine checked.
PartLoops buildLoops(const Polygon& polygon, const Point* pts, const Part& part, Nodes& nodes,
                     std::vector<NodeId>& vertices, std::vector<NodeId>& points,
                     LoopScratch& scratch);

}  // namespace flood
