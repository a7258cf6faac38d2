// The ordered set of active edges of a sweep (core/check/validate_edges.cpp; the bank sweep's
// slots, core/machine/sags/sag_banks.cpp): a treap whose nodes are the edge indices themselves,
// its links arrays indexed by edge. Nothing is allocated per insertion (a std::set allocates a
// 40-byte node each time), and an edge is erased or stepped from by its index, without
// comparisons. Priorities are a hash of the index, so the shape is that of a random treap
// whatever the input order: O(log n) expected per operation.
// A caller may ask for a row: while the set holds at most `rowMax` edges it is a sorted array,
// each edge's place in it kept in its `up` link, searched by halves for a new edge's place,
// where the treap chases links scattered over the edge arrays; past rowMax it becomes the treap, and a row again below rowMax / 2
// (validation's sweep; the bank sweep keeps the treap).
// Internal to core/, not a public API.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood {

// The tree's links, indexed by edge: kept by a caller that sweeps often, so that a warm sweep
// allocates nothing.
struct SweepTreeLinks {
    std::vector<Index> left, right, up;
};

// Less(a, b): a before b; a strict total order on the edges present whenever one is inserted.
template <typename Less>
class SweepTree {
public:
    SweepTree(size_t edges, Less less, SweepTreeLinks& links, size_t rowMax = 0)
        : less_(less), left_(links.left), right_(links.right), up_(links.up), rowMax_(rowMax) {
        left_.assign(edges, kNone), right_.assign(edges, kNone), up_.assign(edges, kNone);
        treap_ = rowMax_ == 0;
        if (!treap_) row_.reserve(rowMax_ + 1);
    }

    const Less& less() const { return less_; }
    // Room for the nodes below `size` (those added absent), for a caller whose indices grow
    // as it goes rather than up to a known bound.
    void grow(size_t size) {
        if (size <= left_.size()) return;
        left_.resize(size, kNone), right_.resize(size, kNone), up_.resize(size, kNone);
    }
    Index first() const {
        if (!treap_) return row_.empty() ? kNone : row_[0];
        Index x = root_;
        while (x != kNone && left_[x] != kNone) x = left_[x];
        return x;
    }

    // Inserts e (not present) where the order puts it.
    void insert(Index e) {
        if (!treap_) {  // after the edges e is not before, as the descent below goes
            size_t lo = 0, hi = row_.size();
            while (lo < hi) {
                const size_t mid = (lo + hi) / 2;
                if (less_(e, row_[mid])) hi = mid;
                else lo = mid + 1;
            }
            return rowInsert(e, lo);
        }
        ++size_;
        Index parent = kNone, x = root_;
        bool toLeft = false;
        while (x != kNone) {
            parent = x;
            toLeft = less_(e, x);
            x = toLeft ? left_[x] : right_[x];
        }
        up_[e] = parent;
        if (parent == kNone) root_ = e;
        else (toLeft ? left_ : right_)[parent] = e;
        while (up_[e] != kNone && priority(e) > priority(up_[e])) rotateUp(e);
    }

    // Inserts e (not present) just after x (present) when `after`, else just before it, without
    // a comparison: for an e that the order puts there, the same tree as insert(e).
    void insertBeside(Index e, Index x, bool after) {
        if (!treap_) return rowInsert(e, indexOf(x) + (after ? 1 : 0));
        ++size_;
        const std::vector<Index>& down = after ? right_ : left_;  // x's side where e goes
        const std::vector<Index>& other = after ? left_ : right_;
        Index parent = x;
        bool toDown = true;      // e becomes parent's `down` child, else its `other` child
        if (down[x] != kNone) {  // then the nearest node there, whose `other` side is empty
            parent = down[x];
            while (other[parent] != kNone) parent = other[parent];
            toDown = false;
        }
        up_[e] = parent;
        (toDown == after ? right_ : left_)[parent] = e;
        while (up_[e] != kNone && priority(e) > priority(up_[e])) rotateUp(e);
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

    bool contains(Index e) const { return up_[e] != kNone || (treap_ && root_ == e); }
    bool empty() const { return treap_ ? root_ == kNone : row_.empty(); }

    // The first node in the order for which notBefore(x) holds, kNone if none: a descent from
    // the root, asking at each node, for a predicate false on a prefix of the order and true
    // after it (a lower bound; the caller counts its own questions).
    template <typename NotBefore>
    Index firstWhere(NotBefore notBefore) const {
        if (!treap_) {
            size_t lo = 0, hi = row_.size();
            while (lo < hi) {
                const size_t mid = (lo + hi) / 2;
                if (notBefore(row_[mid])) hi = mid;
                else lo = mid + 1;
            }
            return lo < row_.size() ? row_[lo] : kNone;
        }
        Index found = kNone;
        for (Index x = root_; x != kNone;) {
            if (notBefore(x)) found = x, x = left_[x];
            else x = right_[x];
        }
        return found;
    }

    // Removes e (present): rotated down to a leaf, then cut off.
    void erase(Index e) {
        if (!treap_) {
            const size_t at = indexOf(e);
            row_.erase(row_.begin() + std::ptrdiff_t(at));
            up_[e] = kNone;
            renumber(at);
            return;
        }
        while (left_[e] != kNone || right_[e] != kNone) {
            Index l = left_[e], r = right_[e];
            rotateUp(r == kNone || (l != kNone && priority(l) > priority(r)) ? l : r);
        }
        Index p = up_[e];
        if (p == kNone) root_ = kNone;
        else (left_[p] == e ? left_ : right_)[p] = kNone;
        up_[e] = kNone;
        if (--size_ < rowMax_ / 2) toRow();
    }

    // Puts f (not present) in the place of e (present, then removed), without a comparison:
    // for an f that the order puts between e's neighbours, the same tree as erase(e) then
    // insert(f). A treap with distinct priorities has one shape per order, so rotations that
    // restore the heap order of f's priority make it.
    void replace(Index e, Index f) {
        if (!treap_) {
            row_[indexOf(e)] = f;
            up_[f] = up_[e], up_[e] = kNone;
            return;
        }
        Index p = up_[e];
        left_[f] = left_[e], right_[f] = right_[e], up_[f] = p;
        if (left_[f] != kNone) up_[left_[f]] = f;
        if (right_[f] != kNone) up_[right_[f]] = f;
        if (p == kNone) root_ = f;
        else (left_[p] == e ? left_ : right_)[p] = f;
        left_[e] = right_[e] = up_[e] = kNone;
        while (up_[f] != kNone && priority(f) > priority(up_[f])) rotateUp(f);
        for (;;) {
            Index l = left_[f], r = right_[f];
            Index top = r == kNone || (l != kNone && priority(l) > priority(r)) ? l : r;
            if (top == kNone || priority(top) < priority(f)) break;
            rotateUp(top);
        }
    }

    // The neighbours of e (present) in the order, or kNone.
    Index prev(Index e) const {
        if (treap_) return step(e, left_, right_);
        const size_t i = indexOf(e);
        return i == 0 ? kNone : row_[i - 1];
    }
    Index next(Index e) const {
        if (treap_) return step(e, right_, left_);
        const size_t i = indexOf(e) + 1;
        return i == row_.size() ? kNone : row_[i];
    }

private:
    // In the row, up_ holds each edge's place in it.
    size_t indexOf(Index e) const { return up_[e]; }
    void renumber(size_t from) {
        for (size_t i = from; i < row_.size(); ++i) up_[row_[i]] = Index(i);
    }
    void rowInsert(Index e, size_t at) {
        row_.insert(row_.begin() + std::ptrdiff_t(at), e);
        renumber(at);
        if (row_.size() > rowMax_) toTreap();
    }
    // The row as the treap its order and priorities make (a Cartesian tree, built on a stack:
    // the tree insertions would make).
    void toTreap() {
        std::vector<Index>& stack = stack_;
        stack.clear();
        for (Index e : row_) {
            Index last = kNone;
            while (!stack.empty() && priority(stack.back()) < priority(e)) {
                last = stack.back();
                stack.pop_back();
            }
            left_[e] = last, right_[e] = kNone;
            if (last != kNone) up_[last] = e;
            up_[e] = stack.empty() ? kNone : stack.back();
            if (!stack.empty()) right_[stack.back()] = e;
            stack.push_back(e);
        }
        root_ = stack.empty() ? kNone : stack.front();
        size_ = row_.size();
        row_.clear();
        treap_ = true;
    }
    void toRow() {
        row_.clear();
        for (Index x = first(); x != kNone; x = next(x)) row_.push_back(x);
        for (Index x : row_) left_[x] = right_[x] = kNone;
        renumber(0);
        root_ = kNone;
        treap_ = false;
    }

    // A random-looking priority per index; ties go to the lower index.
    static uint64_t priority(Index e) {
        uint64_t h = (uint64_t(e) + 1) * 0x9E3779B97F4A7C15ull;
        h ^= h >> 29;
        return (h & ~uint64_t(0xffffffff)) | e;
    }

    // The nearest node on the `down` side: the extreme of that subtree, else the first
    // ancestor reached from its `other` side.
    Index step(Index e, const std::vector<Index>& down, const std::vector<Index>& other) const {
        if (down[e] != kNone) {
            Index x = down[e];
            while (other[x] != kNone) x = other[x];
            return x;
        }
        Index x = e, p = up_[e];
        while (p != kNone && down[p] == x) x = p, p = up_[p];
        return p;
    }

    // x takes its parent's place; the parent becomes x's child.
    void rotateUp(Index x) {
        Index p = up_[x], g = up_[p];
        if (left_[p] == x) {
            left_[p] = right_[x];
            if (right_[x] != kNone) up_[right_[x]] = p;
            right_[x] = p;
        } else {
            right_[p] = left_[x];
            if (left_[x] != kNone) up_[left_[x]] = p;
            left_[x] = p;
        }
        up_[p] = x;
        up_[x] = g;
        if (g == kNone) root_ = x;
        else (left_[g] == p ? left_ : right_)[g] = x;
    }

    Less less_;
    std::vector<Index>&left_, &right_, &up_;
    Index root_ = kNone;
    size_t rowMax_;      // 0: always the treap
    bool treap_ = true;  // else the row
    size_t size_ = 0;    // the treap's
    std::vector<Index> row_, stack_;
};

}  // namespace flood
