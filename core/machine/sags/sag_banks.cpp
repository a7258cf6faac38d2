#include "machine/sags/sag_banks.h"

#include <algorithm>
#include <memory>

#include "flood/geometry/predicates.h"
#include "geometry/sweep_tree.h"

namespace flood {

namespace {

constexpr uint32_t kNoEdge = UINT32_MAX;
constexpr uint32_t kKeptScratchNodes = 1u << 16;  // as the sag heights' keys (giveBackIfLarge)
// How far along its loop, each way, a minimum looks for an edge crossing the line to start its
// search from; beyond, the search descends from the root. Measured at 10^5 (sag search work
// units, star / circle-jagged): 1 step 996k / 1.08M, 2 891k / 1.11M, 3 843k / 977k, 8 790k / 956k.
constexpr int kAround = 3;

// The sweep's geometry. An edge is named by its tail node t (the edge t -> next[t]). A vertex
// is placed among the edges crossing the line by its side of each edge compared; their order
// along the line holds as long as no two of them meet below it, and the sweep stops at the
// first pair that meets (Shamos–Hoey: that pair is adjacent before).
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

// The edges crossing the sweep line, left to right, each in a slot. A slot opens with an edge
// at a minimum and closes at a maximum; at a regular vertex the edge leaving it takes the place
// of the edge arriving there, in the same slot: no edge lies between them at that point (or the
// checks before would have stopped the sweep), so the order holds without moving anything. The
// slots are the nodes of a treap (sweep_tree.h), for a descent from the root, and of a list,
// for steps to a neighbour; a closed slot's id is reused, so both grow with the most edges
// crossing the line at once, not with the loops.
struct Slot {
    uint32_t tail;         // the edge held: tail -> next[tail]
    uint32_t left, right;  // the neighbouring slots along the line (kNone at the ends)
    uint32_t up;           // 1 when the edge goes up from its tail: its ends' order
};  // 16 bytes, the ends read through the points: ~500,000 cross the line on ortho-spiral 10^6

struct Unordered {  // the treap's own order is never asked: slots go in beside a known one
    bool operator()(Index, Index) const { return false; }
};

struct StatusMemory {
    std::vector<Slot> slots;
    std::vector<uint32_t> slotOf;  // by edge: the slot holding it, or kNone
    SweepTreeLinks links;
};

class Status {
public:
    Status(const Sweep& sweep, uint32_t edges, StatusMemory& m)
        : sweep_(sweep), slots_(m.slots), slotOf_(m.slotOf), tree_(0, Unordered{}, m.links) {
        slots_.clear();
        slots_.reserve(std::min<size_t>(edges, kFirstSlots));
        tree_.grow(slots_.capacity());
        slotOf_.assign(edges, kNone);
    }

    const Slot& operator[](uint32_t s) const { return slots_[s]; }
    uint32_t slotOf(uint32_t tail) const { return slotOf_[tail]; }
    uint32_t last() const { return last_; }

    // The first slot whose edge is not left of p, kNone if none; `side`: p's side of its edge
    // (Sweep::side), 1 if none. The search starts from slot `near` when it is not kNone (a slot
    // found near p along its loop), stepping along the list at most kReach slots, and from the
    // root otherwise or beyond. Each slot compared with p is one node visit.
    uint32_t search(Point p, uint32_t near, int& side) {
        side = 1;
        if (near != kNone) {
            int s = sideOf(near, p);
            if (s < 0) {  // near is left of p: the answer is further right
                for (int k = 0; k < kReach; ++k) {
                    const uint32_t r = slots_[near].right;
                    if (r == kNone) return kNone;
                    if ((s = sideOf(r, p)) >= 0) return side = s, r;
                    near = r;
                }
            } else {  // near is not left of p: it is the answer, or one further left is
                for (int k = 0; k < kReach; ++k) {
                    const uint32_t l = slots_[near].left;
                    if (l == kNone) return side = s, near;
                    const int sl = sideOf(l, p);
                    if (sl < 0) return side = s, near;
                    near = l, s = sl;
                }
            }
        }
        return tree_.firstWhere([&](Index x) {
            const int s = sideOf(x, p);
            if (s < 0) return false;
            side = s;  // the last slot answering true is the one returned
            return true;
        });
    }

    // Opens slots for the edges a and b (a left of b) that start at p, just before slot
    // `right` (kNone: at the end of the line), without a comparison.
    // `aUp`: edge a goes up from its tail (else b does: they share their lower end).
    void open(uint32_t a, uint32_t b, bool aUp, uint32_t right) {
        const uint32_t sa = take(a, aUp), sb = take(b, !aUp);
        const uint32_t left = right == kNone ? last_ : slots_[right].left;
        if (tree_.empty()) tree_.insert(sa);
        else if (right != kNone) tree_.insertBeside(sa, right, false);
        else tree_.insertBeside(sa, left, true);
        tree_.insertBeside(sb, sa, true);
        slots_[sa].left = left, slots_[sa].right = sb;
        slots_[sb].left = sa, slots_[sb].right = right;
        if (left != kNone) slots_[left].right = sa;
        (right == kNone ? last_ : slots_[right].left) = sb;
    }

    // The edge `starts`, from lo up to hi, takes the slot of the edge `ends`, which leaves the
    // line at lo.
    void pass(uint32_t s, uint32_t ends, uint32_t starts, bool up) {
        slotOf_[ends] = kNone, slotOf_[starts] = s;
        Slot& slot = slots_[s];
        slot.tail = starts, slot.up = up;
    }

    void close(uint32_t s) {
        Slot& slot = slots_[s];
        if (slot.left != kNone) slots_[slot.left].right = slot.right;
        (slot.right == kNone ? last_ : slots_[slot.right].left) = slot.left;
        tree_.erase(s);
        slotOf_[slot.tail] = kNone;
        slot.right = free_, free_ = s;
    }

private:
    static constexpr int kReach = 4;
    static constexpr size_t kFirstSlots = 1u << 14;  // room made at once, before any growth

    int sideOf(uint32_t s, Point p) const {
        ++work().nodeVisits;
        const Slot& x = slots_[s];
        const Point a = sweep_.point[x.tail], b = sweep_.point[sweep_.next[x.tail]];
        return x.up ? sweep_.side(a, b, p) : sweep_.side(b, a, p);
    }

    uint32_t take(uint32_t tail, bool up) {
        uint32_t s = free_;
        if (s != kNone) free_ = slots_[s].right;
        else s = uint32_t(slots_.size()), slots_.emplace_back(), tree_.grow(slots_.capacity());
        slots_[s].tail = tail, slots_[s].up = up;
        slotOf_[tail] = s;
        return s;
    }

    const Sweep& sweep_;
    std::vector<Slot>& slots_;
    std::vector<uint32_t>& slotOf_;
    SweepTree<Unordered> tree_;
    uint32_t last_ = kNone, free_ = kNone;
};

// The nodes lowest first (belowToward). Along an axis the order is a comparison of two
// coordinates: the heights are sorted as contiguous keys (negation is exact) rather than
// through the node's point on every comparison, and only a run of equal heights is then sorted
// on the tie-break along the level line, read through the points: 16-byte keys rather than 24
// (on ortho-spiral the keys were the run's peak). The points are distinct, so the order is the
// same either way.
struct SweepKey {
    double h;
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
    auto across = [&](uint32_t i) {
        const double a = alongX ? -point[i].y : point[i].x;
        return negative ? -a : a;
    };
    keys.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
        const double h = alongX ? point[i].x : point[i].y;
        keys[i] = {negative ? -h : h, i};
    }
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.h < b.h; });
    for (uint32_t i = 0; i < n; ++i) order[i] = keys[i].node;
    if (n > kKeptScratchNodes) std::vector<SweepKey>().swap(keys);  // not through the sweep
    for (uint32_t i = 0, j; i < n; i = j) {  // each run of one height, along the level line
        const double h = alongX ? point[order[i]].x : point[order[i]].y;
        for (j = i + 1; j < n && (alongX ? point[order[j]].x : point[order[j]].y) == h;) ++j;
        if (j - i == 2) {  // the usual tie: a horizontal edge's ends
            if (across(order[i + 1]) < across(order[i])) std::swap(order[i], order[i + 1]);
        } else if (j - i > 2) {
            std::sort(order.begin() + i, order.begin() + j,
                      [&](uint32_t a, uint32_t b) { return across(a) < across(b); });
        }
    }
}

}  // namespace

struct SagBanks::Scratch {
    std::vector<uint32_t> prev, order, label[2];
    std::vector<SweepKey> keys;
    StatusMemory status;
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
    for (Side& s : side_)  // capacity kept: a warm build allocates nothing
        s.listed.clear(), s.before.clear(), s.begin.clear(), s.ranks.clear(), s.edges = 0;
}

void SagBanks::Side::group(const std::vector<uint32_t>& label, size_t edgeCount) {
    edges = edgeCount;
    begin.assign(edges + 2, 0);
    for (uint32_t t : label)
        if (t != kNoEdge) ++begin[t + 2];
    for (size_t k = 2; k < begin.size(); ++k) begin[k] += begin[k - 1];
    ranks.resize(begin.back());
    for (uint32_t r = 0; r < label.size(); ++r)  // ranks ascending within each edge
        if (label[r] != kNoEdge) ranks[begin[label[r] + 1]++] = r;
    begin.pop_back();
    // Edge t's list is begin[t] .. begin[t + 1]: the edges with one keep their begin, in place.
    listed.assign((edges + 63) / 64, 0);
    before.resize(listed.size());
    uint32_t lists = 0;
    for (uint32_t t = 0; t < edges; ++t) {
        if (t % 64 == 0) before[t / 64] = lists;
        if (begin[t + 1] == begin[t]) continue;
        listed[t / 64] |= uint64_t(1) << (t % 64);
        begin[lists++] = begin[t];
    }
    begin[lists] = begin[edges];
    begin.resize(size_t(lists) + 1);
    if (edges > kKeptScratchNodes) begin.shrink_to_fit();  // the array over every edge goes
}

bool SagBanks::build(const Point* point, const std::vector<uint32_t>& next,
                     const std::vector<uint32_t>& sagOfRank, Up up, bool simple) {
    clear();
    const uint32_t n = uint32_t(next.size());
    if (!scratch_) scratch_ = std::make_unique<Scratch>();
    Scratch& s = *scratch_;
    std::vector<uint32_t>&prev = s.prev, &order = s.order;
    prev.resize(n), order.resize(n);
    for (uint32_t i = 0; i < n; ++i) prev[next[i]] = i;
    sweepOrder(point, up, order, s.keys);

    Sweep sweep{point, next, up};
    Status active(sweep, n, s.status);
    std::vector<uint32_t>* label = s.label;
    for (int k = 0; k < 2; ++k) label[k].assign(sagOfRank.size(), kNoEdge);
    auto meet = [&](uint32_t l, uint32_t r) {  // the edges of slots l and r (either may be kNone)
        return l != kNone && r != kNone && sweep.meet(active[l].tail, active[r].tail);
    };
    // The sags are ranked in the sweep's order (the heights' below()), so the sweep meets them
    // by rank: the next rank's sag is the only one it can meet next.
    const uint32_t sags = uint32_t(sagOfRank.size());
    uint32_t rank = 0;
    for (uint32_t p : order) {
        ++work().nodeVisits;
        const uint32_t in = prev[p], out = p;  // the edges in -> p and p -> next[p]
        const bool lone = next[p] == p;        // a point hole: no edges
        const bool inEnds = !lone && sweep.up(in), outEnds = !lone && !sweep.up(out);
        if (inEnds != outEnds) {  // a regular vertex: one edge ends here, the other starts
            const uint32_t ends = inEnds ? in : out, starts = inEnds ? out : in;
            const uint32_t slot = active.slotOf(ends);
            if (slot == kNone) return false;
            active.pass(slot, ends, starts, inEnds);  // out goes up from p when in ends
            // The end of the edge that left, hence strictly between the neighbours (the
            // sweep has found no meeting so far): one orientation each clears the new edge.
            if (simple) continue;
            const uint32_t l = active[slot].left, r = active[slot].right;
            if (l != kNone && sweep.meetFrom(active[l].tail, starts, -1)) return false;
            if (r != kNone && sweep.meetFrom(active[r].tail, starts, 1)) return false;
            continue;
        }
        if (inEnds) {  // a maximum: both edges leave the line
            const uint32_t a = active.slotOf(in), b = active.slotOf(out);
            if (a == kNone || b == kNone) return false;
            active.close(a);
            const uint32_t after = active[b].right;
            active.close(b);
            if (!simple && after != kNone && meet(active[after].left, after)) return false;
            continue;
        }
        // A minimum (or a point hole): where p falls among the edges crossing the line. The
        // edges of its loop nearest to it that cross the line are most often its neighbours
        // there (none can lie between the two unless it crosses the line between them under
        // the chain that joins them, above the line): the search starts from the first found
        // within kAround steps each way, one visit a step.
        uint32_t near = kNone, back = prev[p], ahead = p;
        auto crossing = [&](uint32_t t) {
            ++work().nodeVisits;
            return (near = active.slotOf(t)) != kNone;
        };
        for (int k = 0; !lone && k < kAround; ++k) {  // until the two ways meet, on a small loop
            if ((back = prev[back]) == ahead || crossing(back)) break;
            if ((ahead = next[ahead]) == back || crossing(ahead)) break;
        }
        int onRight = 1;
        const uint32_t right = active.search(point[p], near, onRight);  // first not left of p
        if (onRight == 0) return false;                                 // p on an edge
        const uint32_t left = right == kNone ? active.last() : active[right].left;
        if (rank < sags && sagOfRank[rank] == p) {  // a sag: the edges just left and right of it
            if (right != kNone) label[1][rank] = active[right].tail;
            if (left != kNone) label[0][rank] = active[left].tail;
            ++rank;
        }
        if (lone) continue;
        // Both edges start here; the one turning left of the other goes first. Collinear, they
        // overlap (both go up from p).
        const Point hiIn = point[in], hiOut = point[next[p]];  // both above p
        const int turn = orient(point[p], hiOut, hiIn);
        if (turn == 0) return false;
        const bool inLeft = turn > 0;
        const uint32_t a = inLeft ? in : out, b = inLeft ? out : in;
        active.open(a, b, !inLeft, right);  // no comparison; out goes up from its tail p
        if (simple) continue;
        if (left != kNone && sweep.meetFrom(active[left].tail, a, -1)) return false;
        if (right != kNone && sweep.meetFrom(active[right].tail, b, 1)) return false;
    }
    if (rank != sags) return false;  // not the sweep's order: no lists rather than wrong ones
    // Large loops give the scratch back (it would add to the run's peak); small ones keep it.
    // The sweep's part goes before the lists are grouped, which would otherwise sit on it.
    const bool large = n > kKeptScratchNodes;
    if (large) {
        std::vector<Slot>().swap(s.status.slots);
        SweepTreeLinks& links = s.status.links;
        for (auto* v : {&prev, &order, &s.status.slotOf, &links.left, &links.right, &links.up})
            std::vector<uint32_t>().swap(*v);
    }
    side_[0].group(label[0], n);
    side_[1].group(label[1], n);
    built_ = true;
    if (large) scratch_.reset();
    return true;
}

}  // namespace flood
