// The ordered set of active edges of a sweep (core/validate.cpp): a treap whose nodes are the
// edge indices themselves, its links in one record per edge (SweepNode). Nothing is allocated per
// insertion (a std::set allocates a 40-byte node each time), and an edge is erased or stepped
// from by its index, without comparisons. Priorities are a hash of the index, so the shape is
// that of a random treap whatever the input order: O(log n) expected per operation.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <vector>

#include "polygon.h"

namespace flood {

// One edge's record: the tree's links (kid[0] left, kid[1] right, up the parent), and beside
// them the edge's lower and upper vertex, for the order to read. A step of a search reads one
// 20-byte record instead of three link arrays and an edge array scattered apart: at 10^6
// vertices the sweep waited on those reads (docs/BENCHMARKS.md, "Validation cost, round 3").
struct SweepNode {
    Index kid[2], up;
    Index lo, hi;  // the caller's: the tree neither reads nor writes them
};

// The records, indexed by edge: kept by a caller that sweeps often, so that a warm sweep
// allocates nothing.
using SweepTreeLinks = std::vector<SweepNode>;

// Less(a, b): a before b; a strict total order on the edges present whenever one is inserted.
template <typename Less>
class SweepTree {
public:
    // Clears the links of `edges` records (their lo and hi are left as they are).
    SweepTree(size_t edges, Less less, SweepTreeLinks& nodes) : less_(less), t_(nodes) {
        t_.resize(edges);
        for (SweepNode& x : t_) x.kid[0] = x.kid[1] = x.up = kNone;
    }

    const Less& less() const { return less_; }
    Index first() const {
        Index x = root_;
        while (x != kNone && t_[x].kid[0] != kNone) x = t_[x].kid[0];
        return x;
    }

    // Inserts e (not present) where the order puts it.
    void insert(Index e) {
        Index parent = kNone, x = root_;
        int side = 0;
        while (x != kNone) {
            parent = x;
            side = less_(e, x) ? 0 : 1;
            x = t_[x].kid[side];
        }
        t_[e].up = parent;
        if (parent == kNone) root_ = e;
        else t_[parent].kid[side] = e;
        while (t_[e].up != kNone && priority(e) > priority(t_[e].up)) rotateUp(e);
    }

    // Inserts e (not present) just after x (present) when `after`, else just before it, without
    // a comparison: for an e that the order puts there, the same tree as insert(e).
    void insertBeside(Index e, Index x, bool after) {
        const int down = after ? 1 : 0, other = 1 - down;  // x's side where e goes, and the other
        Index parent = x;
        int side = down;                 // e becomes parent's child on this side
        if (t_[x].kid[down] != kNone) {  // then the nearest node there, whose `other` side is empty
            parent = t_[x].kid[down];
            while (t_[parent].kid[other] != kNone) parent = t_[parent].kid[other];
            side = other;
        }
        t_[e].up = parent;
        t_[parent].kid[side] = e;
        while (t_[e].up != kNone && priority(e) > priority(t_[e].up)) rotateUp(e);
    }

    // Inserts e (not present) where the order puts it, looking first within `reach` steps of
    // `near` (present), then from the root: a finger search, for keys inserted near each other.
    void insertNear(Index e, Index near, int reach) {
        const bool after = less_(near, e);
        Index x = near;
        for (int k = 0; k < reach; ++k) {
            Index y = after ? next(x) : prev(x);
            if (y == kNone || (after ? less_(e, y) : less_(y, e))) return insertBeside(e, x, after);
            x = y;
        }
        insert(e);
    }

    bool contains(Index e) const { return t_[e].up != kNone || root_ == e; }

    // Removes e (present): rotated down to a leaf, then cut off.
    void erase(Index e) {
        while (t_[e].kid[0] != kNone || t_[e].kid[1] != kNone) {
            Index l = t_[e].kid[0], r = t_[e].kid[1];
            rotateUp(r == kNone || (l != kNone && priority(l) > priority(r)) ? l : r);
        }
        Index p = t_[e].up;
        if (p == kNone) root_ = kNone;
        else t_[p].kid[t_[p].kid[0] == e ? 0 : 1] = kNone;
        t_[e].up = kNone;
    }

    // Puts f (not present) in the place of e (present, then removed), without a comparison:
    // for an f that the order puts between e's neighbours, the same tree as erase(e) then
    // insert(f). A treap with distinct priorities has one shape per order, so rotations that
    // restore the heap order of f's priority make it.
    void replace(Index e, Index f) {
        Index p = t_[e].up;
        t_[f].kid[0] = t_[e].kid[0], t_[f].kid[1] = t_[e].kid[1], t_[f].up = p;
        for (Index k : t_[f].kid)
            if (k != kNone) t_[k].up = f;
        if (p == kNone) root_ = f;
        else t_[p].kid[t_[p].kid[0] == e ? 0 : 1] = f;
        t_[e].kid[0] = t_[e].kid[1] = t_[e].up = kNone;
        while (t_[f].up != kNone && priority(f) > priority(t_[f].up)) rotateUp(f);
        for (;;) {
            Index l = t_[f].kid[0], r = t_[f].kid[1];
            Index top = r == kNone || (l != kNone && priority(l) > priority(r)) ? l : r;
            if (top == kNone || priority(top) < priority(f)) break;
            rotateUp(top);
        }
    }

    // The neighbours of e (present) in the order, or kNone.
    Index prev(Index e) const { return step(e, 0); }
    Index next(Index e) const { return step(e, 1); }

private:
    // A random-looking priority per index; ties go to the lower index.
    static uint64_t priority(Index e) {
        uint64_t h = (uint64_t(e) + 1) * 0x9E3779B97F4A7C15ull;
        h ^= h >> 29;
        return (h & ~uint64_t(0xffffffff)) | e;
    }

    // The nearest node on side `down`: the extreme of that subtree, else the first ancestor
    // reached from its other side.
    Index step(Index e, int down) const {
        const int other = 1 - down;
        if (t_[e].kid[down] != kNone) {
            Index x = t_[e].kid[down];
            while (t_[x].kid[other] != kNone) x = t_[x].kid[other];
            return x;
        }
        Index x = e, p = t_[e].up;
        while (p != kNone && t_[p].kid[down] == x) x = p, p = t_[p].up;
        return p;
    }

    // x takes its parent's place; the parent becomes x's child.
    void rotateUp(Index x) {
        Index p = t_[x].up, g = t_[p].up;
        const int side = t_[p].kid[0] == x ? 0 : 1, other = 1 - side;  // x is p's child on `side`
        const Index inner = t_[x].kid[other];
        t_[p].kid[side] = inner;
        if (inner != kNone) t_[inner].up = p;
        t_[x].kid[other] = p;
        t_[p].up = x;
        t_[x].up = g;
        if (g == kNone) root_ = x;
        else t_[g].kid[t_[g].kid[0] == p ? 0 : 1] = x;
    }

    Less less_;
    SweepTreeLinks& t_;
    Index root_ = kNone;
};

}  // namespace flood
