// Loop building (§1), the flood machine's set-up: a part's rings become circular doubly
// linked lists of nodes with the interior on the left, a node added at each T-junction, and
// rings that touch at a point merged into one loop there by the clockwise rule.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "flood/geometry/polygon.h"
#include "geometry/coincident.h"
#include "machine/node_id.h"

namespace flood {

constexpr uint32_t kNoGorge = kNone;

// A node is a reference to a vertex; coincident vertices and bridge copies are distinct nodes.
// Sixteen bytes, what every node needs: the few that end a dormant gorge keep that in an Ends
// record of their own, and the flags live beside the nodes (Nodes), a byte each.
struct Node {
    Index v;  // vertex (index into the input)
    NodeId prev, next;
    uint32_t ends = kNone;  // its Ends record in Nodes; kNone: it ends no dormant gorge
};

// What a node at an end of a dormant gorge knows of it (empty for every other node).
struct Ends {
    NodeId jump = kNil;              // top: the other bank of its held gorge
    uint32_t gorgeLeft = kNoGorge;   // dormant gorge whose Left end is this node
    uint32_t gorgeRight = kNoGorge;  // dormant gorge whose Right end is this node
    bool empty() const { return jump == kNil && gorgeLeft == kNoGorge && gorgeRight == kNoGorge; }
};

// The nodes of every loop, indexed by NodeId alone, with their flags and Ends records.
class Nodes {
public:
    Node& operator[](NodeId n) { return nodes_[size_t(n)]; }
    const Node& operator[](NodeId n) const { return nodes_[size_t(n)]; }
    NodeId end() const { return NodeId(uint32_t(nodes_.size())); }  // the next node's id
    void push(const Node& n) {
        nodes_.push_back(n);
        flags_.push_back(kAlive);
    }
    // `count` new alive nodes, to be filled in by the caller: a loop's nodes in one go.
    Node* append(uint32_t count) {
        const size_t at = nodes_.size();
        if (count <= 8) {  // a point hole, a small hole: resize() is a call, push() inline
            for (uint32_t i = 0; i < count; ++i) push(Node{});
        } else {
            nodes_.resize(at + count);
            flags_.resize(at + count, kAlive);
        }
        return nodes_.data() + at;
    }
    void clear() {
        nodes_.clear();
        flags_.clear();
        ends_.clear();
        free_ = kNone;
    }
    size_t capacity() const { return nodes_.capacity(); }
    void reserve(size_t n) {
        nodes_.reserve(n);
        flags_.reserve(n);
    }

    bool alive(NodeId n) const { return flags_[size_t(n)] & kAlive; }
    bool wet(NodeId n) const { return flags_[size_t(n)] & kWet; }  // the water reached it
    void kill(NodeId n) { flags_[size_t(n)] &= uint8_t(~kAlive); }
    void wetten(NodeId n) { flags_[size_t(n)] |= kWet; }

    const Ends& ends(NodeId n) const {
        const uint32_t at = nodes_[size_t(n)].ends;
        return at == kNone ? kNoEnds : ends_[at];
    }
    // Applies `edit` to n's Ends record, made when n has none and given back once empty: only
    // the nodes ending a dormant gorge now hold one.
    template <class Edit>
    void editEnds(NodeId n, Edit edit) {
        uint32_t& at = nodes_[size_t(n)].ends;
        if (at == kNone) {
            if (free_ == kNone) {
                at = uint32_t(ends_.size());
                ends_.emplace_back();
            } else {
                at = free_;
                free_ = ends_[at].gorgeLeft;
                ends_[at] = Ends{};
            }
        }
        edit(ends_[at]);
        if (ends_[at].empty()) ends_[at].gorgeLeft = free_, free_ = at, at = kNone;
    }

private:
    static constexpr uint8_t kAlive = 1, kWet = 2;
    static constexpr Ends kNoEnds{};
    std::vector<Node> nodes_;
    std::vector<uint8_t> flags_;  // per node: kAlive, kWet
    std::vector<Ends> ends_;      // the records of the nodes that hold one, and free ones
    uint32_t free_ = kNone;       // the first free record; each links the next by its gorgeLeft
};

// Scratch arrays are lent from run to run up to this many elements; a larger one is given back
// once its step is done, rather than held resident under the rest of the run.
constexpr size_t kLentScratch = size_t(1) << 16;
template <class T>
void giveBackIfLarge(std::vector<T>& v) {
    if (v.capacity() > kLentScratch) std::vector<T>().swap(v);
}

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
