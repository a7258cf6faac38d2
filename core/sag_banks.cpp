#include "sag_banks.h"

#include <algorithm>
#include <memory>
#include <set>

#include "predicates.h"

namespace flood {

namespace {

constexpr uint32_t kNoEdge = UINT32_MAX;
constexpr uint32_t kKeptScratchNodes = 1u << 16;  // as the sag heights' keys (giveBackIfLarge)

// The edges crossing the sweep line, left to right. An edge is named by its tail node t (the
// edge t -> next[t]). Edges are compared where the later-starting one begins, which is on the
// sweep line: the order of the edges along it as long as no two of them meet below it, and
// the sweep stops at the first pair that meets (Shamos–Hoey: that pair is adjacent before).
struct Sweep {
    const Point* point;
    const std::vector<uint32_t>& next;
    Up vertical;
    bool up(uint32_t t) const { return belowToward(vertical, point[t], point[next[t]]); }
    Point lo(uint32_t t) const { return up(t) ? point[t] : point[next[t]]; }
    Point hi(uint32_t t) const { return up(t) ? point[next[t]] : point[t]; }
    // The side of the upward edge lo -> hi that p is on (+1 left, -1 right, 0 on it), for p
    // strictly between its ends in height: along +y, beyond the edge's x-range no orientation
    // is needed; off it the orientation decides alone.
    int side(Point lo, Point hi, Point p) const {
        if (vertical == Up::PlusY) {
            if (p.x < lo.x && p.x < hi.x) return 1;
            if (p.x > lo.x && p.x > hi.x) return -1;
        }
        return orient(lo, hi, p);
    }
    // While a minimum's two edges are inserted where the search put the point: the edges
    // around them, left to right (the ends may be kNoEdge), whose order is already known.
    uint32_t known[4] = {kNoEdge, kNoEdge, kNoEdge, kNoEdge};
    int knownAt(uint32_t t) const {
        for (int k = 0; k < 4; ++k)
            if (known[k] == t) return k;
        return -1;
    }
    // Edges a and b share a point other than a common end, or overlap there. Exact; two
    // orientations decide the usual case (b wholly on one side of a's line).
    bool meet(uint32_t a, uint32_t b) const {
        Point a0 = point[a], a1 = point[next[a]], b0 = point[b], b1 = point[next[b]];
        if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) {
            Point p = (a0 == b0 || a0 == b1) ? a0 : a1;
            Point q = p == a0 ? a1 : a0, r = p == b0 ? b1 : b0;
            if (q == r) return true;  // the same segment twice
            if (orient(p, q, r) != 0) return false;
            return (q.x < p.x) == (r.x < p.x) && (q.x > p.x) == (r.x > p.x) &&
                   (q.y < p.y) == (r.y < p.y) &&
                   (q.y > p.y) == (r.y > p.y);  // collinear, one way from p: overlapping
        }
        if (std::max(a0.x, a1.x) < std::min(b0.x, b1.x) ||
            std::max(b0.x, b1.x) < std::min(a0.x, a1.x) ||
            std::max(a0.y, a1.y) < std::min(b0.y, b1.y) ||
            std::max(b0.y, b1.y) < std::min(a0.y, a1.y))
            return false;  // apart
        int o1 = orient(a0, a1, b0), o2 = orient(a0, a1, b1);
        if (o1 * o2 > 0) return false;
        int o3 = orient(b0, b1, a0), o4 = orient(b0, b1, a1);
        if (o3 * o4 > 0) return false;
        if (o1 && o2 && o3 && o4) return true;  // a proper crossing
        return (o1 == 0 && insideSegment(a0, a1, b0)) || (o2 == 0 && insideSegment(a0, a1, b1)) ||
               (o3 == 0 && insideSegment(b0, b1, a0)) || (o4 == 0 && insideSegment(b0, b1, a1));
    }
    // meet(a, b) for an edge b starting on the sweep line at a point known to be strictly on
    // side `pSide` of edge a (the sweep found it there): b stays clear of a when its upper end
    // is on that side of a's line too, which one orientation tells.
    bool meetFrom(uint32_t a, uint32_t b, int pSide) const {
        if (orient(lo(a), hi(a), hi(b)) == pSide) return false;
        return meet(a, b);
    }
};

// An edge in the sweep's set, with its ends (lower first) at hand for the comparisons. It is
// mutable: at a regular vertex the edge leaving it takes the place of the edge arriving there,
// which keeps the order (no edge lies between them at that point, or the checks before would
// have stopped the sweep).
struct Active {
    mutable uint32_t tail;
    mutable Point lo, hi;
};

struct EdgeLess {
    using is_transparent = void;  // a point is looked up among the edges crossing the line
    const Sweep* sweep;
    // Edge a is left of edge b on the sweep line.
    bool operator()(const Active& a, const Active& b) const {
        if (a.tail == b.tail) return false;
        if (sweep->known[1] != kNoEdge) {
            int ka = sweep->knownAt(a.tail), kb = sweep->knownAt(b.tail);
            if (ka >= 0 && kb >= 0) return ka < kb;
        }
        if (a.lo == b.lo) return orient(b.lo, b.hi, a.hi) > 0;  // both start here: by direction
        if (belowToward(sweep->vertical, b.lo, a.lo)) return sweep->side(b.lo, b.hi, a.lo) > 0;
        return sweep->side(a.lo, a.hi, b.lo) < 0;
    }
    bool operator()(const Active& e, Point p) const { return sweep->side(e.lo, e.hi, p) < 0; }
    bool operator()(Point p, const Active& e) const { return sweep->side(e.lo, e.hi, p) > 0; }
};

// The sweep's set allocates one node per edge inserted and frees it when the edge ends: a free
// list of node-sized slots, carved from chunks freed together, spares malloc that pair of calls
// (a tenth of the sweep's instructions) and keeps the live nodes close in memory.
class NodePool {
public:
    void* get(size_t bytes) {
        if (bytes != slot_) return ::operator new(bytes);  // not the set's node (first fixes it)
        if (free_) {
            void* p = free_;
            free_ = *static_cast<void**>(p);
            return p;
        }
        if (left_ == 0) {
            chunks_.emplace_back(new Slot[kChunk]);
            next_ = chunks_.back().get(), left_ = kChunk;
        }
        --left_;
        return next_++;
    }
    void put(void* p, size_t bytes) {
        if (bytes != slot_) return ::operator delete(p);
        *static_cast<void**>(p) = free_;
        free_ = p;
    }
    void fix(size_t bytes) {
        if (slot_ == 0 && bytes <= sizeof(Slot)) slot_ = bytes;
    }

private:
    struct alignas(16) Slot {
        unsigned char bytes[80];
    };
    static constexpr size_t kChunk = 1024;
    std::vector<std::unique_ptr<Slot[]>> chunks_;
    Slot* next_ = nullptr;
    size_t left_ = 0, slot_ = 0;
    void* free_ = nullptr;
};

template <class T>
struct PoolAllocator {
    using value_type = T;
    NodePool* pool;
    explicit PoolAllocator(NodePool* p) : pool(p) {}
    template <class U>
    PoolAllocator(const PoolAllocator<U>& o) : pool(o.pool) {}  // NOLINT: rebinding
    T* allocate(size_t n) {
        if (n != 1) return std::allocator<T>().allocate(n);
        pool->fix(sizeof(T));
        return static_cast<T*>(pool->get(sizeof(T)));
    }
    void deallocate(T* p, size_t n) {
        if (n != 1) return std::allocator<T>().deallocate(p, n);
        pool->put(p, sizeof(T));
    }
    template <class U>
    bool operator==(const PoolAllocator<U>& o) const {
        return pool == o.pool;
    }
    template <class U>
    bool operator!=(const PoolAllocator<U>& o) const {
        return pool != o.pool;
    }
};

// The nodes lowest first (belowToward). Along an axis the order is a comparison of two
// coordinates, sorted as contiguous keys (negation is exact) rather than through the node's
// point on every comparison; the points are distinct, so the order is the same either way.
struct SweepKey {
    double h, across;  // the height, then the tie-break along the tilted level line
    uint32_t node;
};

void sweepOrder(const Point* point, Up up, std::vector<uint32_t>& order,
                std::vector<SweepKey>& keys) {
    const uint32_t n = uint32_t(order.size());
    if (!up.axis()) {
        for (uint32_t i = 0; i < n; ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](uint32_t a, uint32_t b) { return belowToward(up, point[a], point[b]); });
        return;
    }
    using Key = SweepKey;
    // belowToward's four axis cases: +y (y, x), -y (-y, -x), +x (x, -y), -x (-x, y).
    const bool alongX = up.y == 0, negative = alongX ? up.x < 0 : up.y < 0;
    keys.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
        const Point p = point[i];
        double h = alongX ? p.x : p.y, across = alongX ? -p.y : p.x;
        if (negative) h = -h, across = -across;
        keys[i] = {h, across, i};
    }
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return a.h < b.h || (a.h == b.h && a.across < b.across);
    });
    for (uint32_t i = 0; i < n; ++i) order[i] = keys[i].node;
    if (n > kKeptScratchNodes) std::vector<SweepKey>().swap(keys);  // not through the sweep
}

using Set = std::set<Active, EdgeLess, PoolAllocator<Active>>;

}  // namespace

struct SagBanks::Scratch {
    std::vector<uint32_t> prev, rankOf, order, label[2];
    std::vector<SweepKey> keys;
    std::vector<Set::iterator> at;
    NodePool pool;  // outlives every build's set: its nodes go back to the free list
};

SagBanks::SagBanks() = default;
SagBanks::~SagBanks() = default;
SagBanks::SagBanks(const SagBanks& o) : side_(o.side_), built_(o.built_) {}
SagBanks& SagBanks::operator=(const SagBanks& o) {
    side_ = o.side_, built_ = o.built_;
    return *this;
}
SagBanks::SagBanks(SagBanks&&) noexcept = default;
SagBanks& SagBanks::operator=(SagBanks&&) noexcept = default;

void SagBanks::clear() {
    built_ = false;
    for (Side& s : side_) s.begin.clear(), s.ranks.clear();
}

void SagBanks::Side::group(const std::vector<uint32_t>& label, size_t edges) {
    begin.assign(edges + 2, 0);
    for (uint32_t t : label)
        if (t != kNoEdge) ++begin[t + 2];
    for (size_t k = 2; k < begin.size(); ++k) begin[k] += begin[k - 1];
    ranks.resize(begin.back());
    for (uint32_t r = 0; r < label.size(); ++r)  // ranks ascending within each edge
        if (label[r] != kNoEdge) ranks[begin[label[r] + 1]++] = r;
    begin.pop_back();
}

bool SagBanks::build(const Point* point, const std::vector<uint32_t>& next,
                     const std::vector<uint32_t>& sagOfRank, Up up, bool simple) {
    clear();
    const uint32_t n = uint32_t(next.size());
    if (!scratch_) scratch_ = std::make_unique<Scratch>();
    Scratch& s = *scratch_;
    std::vector<uint32_t>&prev = s.prev, &rankOf = s.rankOf, &order = s.order;
    prev.resize(n), rankOf.assign(n, kNoEdge), order.resize(n);
    for (uint32_t i = 0; i < n; ++i) prev[next[i]] = i;
    for (uint32_t r = 0; r < sagOfRank.size(); ++r) rankOf[sagOfRank[r]] = r;
    sweepOrder(point, up, order, s.keys);

    Sweep sweep{point, next, up};
    Set active(EdgeLess{&sweep}, PoolAllocator<Active>(&s.pool));
    std::vector<Set::iterator>& at = s.at;
    at.assign(n, active.end());
    std::vector<uint32_t>* label = s.label;
    for (int k = 0; k < 2; ++k) label[k].assign(sagOfRank.size(), kNoEdge);
    auto meetsBefore = [&](Set::iterator it) {  // it and the edge before it meet
        return !simple && it != active.begin() && it != active.end() &&
               sweep.meet(std::prev(it)->tail, it->tail);
    };
    for (uint32_t p : order) {
        ++work().nodeVisits;
        const uint32_t in = prev[p], out = p;  // the edges in -> p and p -> next[p]
        const bool lone = next[p] == p;        // a point hole: no edges
        const bool inEnds = !lone && sweep.up(in), outEnds = !lone && !sweep.up(out);
        if (inEnds != outEnds) {  // a regular vertex: one edge ends here, the other starts
            const uint32_t ends = inEnds ? in : out, starts = inEnds ? out : in;
            if (at[ends] == active.end()) return false;
            Set::iterator it = at[ends];
            at[ends] = active.end();
            it->tail = starts, it->lo = sweep.lo(starts), it->hi = sweep.hi(starts);
            at[starts] = it;
            // The end of the edge that left, hence strictly between the neighbours (the
            // sweep has found no meeting so far): one orientation each clears the new edge.
            if (simple) continue;
            if (it != active.begin() && sweep.meetFrom(std::prev(it)->tail, starts, -1))
                return false;
            if (std::next(it) != active.end() && sweep.meetFrom(std::next(it)->tail, starts, 1))
                return false;
            continue;
        }
        if (inEnds) {  // a maximum: both edges leave the line
            if (at[in] == active.end() || at[out] == active.end()) return false;
            active.erase(at[in]);
            Set::iterator after = active.erase(at[out]);
            at[in] = at[out] = active.end();
            if (meetsBefore(after)) return false;
            continue;
        }
        // A minimum (or a point hole): where p falls among the edges crossing the line.
        Set::iterator right = active.lower_bound(point[p]);  // the first edge not left of p
        if (right != active.end() && sweep.side(right->lo, right->hi, point[p]) == 0)
            return false;            // p on an edge
        if (rankOf[p] != kNoEdge) {  // a sag: the edges just left and right of it
            if (right != active.end()) label[1][rankOf[p]] = right->tail;
            if (right != active.begin()) label[0][rankOf[p]] = std::prev(right)->tail;
        }
        if (lone) continue;
        // Both edges start here; the one turning left of the other goes first. Collinear, they
        // overlap (both go up from p).
        const int turn = orient(point[p], sweep.hi(out), sweep.hi(in));
        if (turn == 0) return false;
        const bool inLeft = turn > 0;
        const uint32_t a = inLeft ? in : out, b = inLeft ? out : in;
        // Inserted beside the edges the search just compared p with, without comparing again.
        sweep.known[0] = right == active.begin() ? kNoEdge : std::prev(right)->tail;
        sweep.known[1] = a, sweep.known[2] = b;
        sweep.known[3] = right == active.end() ? kNoEdge : right->tail;
        Set::iterator ib = active.emplace_hint(right, Active{b, point[p], sweep.hi(b)});
        Set::iterator ia = active.emplace_hint(ib, Active{a, point[p], sweep.hi(a)});
        sweep.known[1] = kNoEdge;
        if (ia->tail != a || ib->tail != b || std::next(ia) != ib) return false;
        at[a] = ia, at[b] = ib;
        if (simple) continue;
        if (ia != active.begin() && sweep.meetFrom(std::prev(ia)->tail, a, -1)) return false;
        if (std::next(ib) != active.end() && sweep.meetFrom(std::next(ib)->tail, b, 1))
            return false;
    }
    side_[0].group(label[0], n);
    side_[1].group(label[1], n);
    built_ = true;
    // Large loops give the scratch back (it would add to the run's peak); small ones keep it.
    // The set is emptied first: its nodes live in the scratch's pool.
    active.clear();
    if (n > kKeptScratchNodes) scratch_.reset();
    return true;
}

}  // namespace flood
