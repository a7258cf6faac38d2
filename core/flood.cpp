// The flooding machine (Ronfard & Rossignac 1994, §3–§6).
//
// Glossary (the paper's words, used as names below):
//   loop          a circular doubly linked list of nodes; a node is a reference to a vertex.
//                 Rings touching at a shared point are merged into one loop there (§1).
//   active chain  the nodes from Left to Right (next-wards) of the active loop: the part of
//                 the boundary under water in the current gorge.
//   NextLeft      prev(Left); NextRight = next(Right): the fingers.
//   water         the node at the water level: the highest node of the active chain.
//   bottom / sag  convex / concave local minimum; top / ceiling: concave / convex maximum.
//   gorge         a monotone region flooded from a bottom; pending gorges wait on the to-do
//                 list (after a Bridge), held gorges wait at a top for a Jump (after a Spill).
//
// Invariants, true between any two steps on valid input:
//   1. Every triangle cut so far lies below the water of its gorge; the loops bound exactly
//      the part of the polygon not yet triangulated.
//   2. Every node strictly inside the active chain is concave or flat (orient <= 0): the
//      chain is a reflex chain, as in Garey et al.'s monotone triangulation.
//   3. NextLeft and NextRight are above the water; no sag lies in the active gorge below
//      the water.
//   4. A top has a jump pointer only while its gorge is held there.
// When one of these cannot hold — the input is invalid — the machine stops in a Forbidden
// state (§6) instead of producing a wrong triangle.
//
// Sections (search for "[SECTION]"):
//   predicates on nodes     lower(): the paper's below as a total order on nodes; sag ranks
//   a part                  set-up (loops.h builds the loops), the run, the left-behind check
//   events                  begin/emit; forbid() (narrate.cpp words the diagnostic)
//   the decision tree       step(): Fig. 9; the sag search (sag_index.h, sag_banks.h)
//   the five actions        Raise, Bridge, Spill (its walks remembered: stretches.h), Jump, Fill
//   the to-do list          pending gorges, dry bottoms; a gorge retired in retireGorge()
//   the machine's memory    the buffers lent from run to run; then the entry points
#include "flood.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "loops.h"
#include "predicates.h"
#include "ring_area.h"
#include "sag_banks.h"
#include "sag_index.h"
#include "stretches.h"
#include "work.h"

namespace flood {
namespace {

struct GorgeRec {
    NodeId left, right, water;
    bool held = false;  // held at a top (Spill) rather than pending (Bridge)
    bool done = false;
    Index top = kNone;
};

// Exact coordinate permutation making an axis direction +y (a rotation: keeps orientation).
// Only for the axes: off them heights are compared exactly along the direction (heightRank_).
Point toUp(Point p, Up up) {
    if (up.x == 0) return up.y > 0 ? p : Point{-p.x, -p.y};
    return up.x > 0 ? Point{-p.y, p.x} : Point{p.y, -p.x};
}

class Machine {
public:
    struct Buffers;
    // The run's result goes to `out` (its triangles' capacity reused). `keep`, if given, lends
    // the machine its buffers, so that a run on an input no larger than the last one
    // allocates nothing.
    Machine(const Polygon& poly, Listener* listener, const Options& opt, FloodResult& out,
            Buffers* keep)
        : poly_(poly),
          listener_(listener),
          own_(keep ? nullptr : new Buffers),
          b_(keep ? *keep : *own_),
          up_(opt.up),
          general_(!opt.up.axis()),
          result_(out) {
        if (general_ ||
            (opt.up.x == 0 && opt.up.y > 0)) {  // heights are the input's or ranks: no copy
            pts_ = poly.vertices.data();
            return;
        }
        rotated_.clear();
        rotated_.reserve(poly.vertices.size());
        for (Point p : poly.vertices) rotated_.push_back(toUp(p, opt.up));
        pts_ = rotated_.data();
    }

    Machine(const Machine&) = delete;
    Machine& operator=(const Machine&) = delete;

    void run() {
        nodes_.clear();
        result_.triangles.clear();
        if (!result_.diagnostic.ok())
            result_.diagnostic = {}, result_.failure = {};  // set together
        if (!up_.valid()) {
            result_.diagnostic = {Status::Usage,
                                  "the flood direction (" + upName(up_) +
                                      ") is not a direction: it must be a nonzero finite vector"};
            return;
        }
        if (general_) rankHeights();
        nodes_.reserve(poly_.vertices.size() * 3 / 2 + 16);  // bridges add two nodes per sag
        result_.triangles.reserve(poly_.vertices.size() + 2 * poly_.rings.size());
        for (uint32_t part = 0; part < poly_.parts.size() && ok(); ++part) floodPart(part);
        result_.steps = step_;
    }

private:
    // ---- [SECTION] predicates on nodes -------------------------------------------------
    Point P(NodeId n) const { return pts_[nodes_[n].v]; }
    // The paper's below, made a strict total order on nodes: coincident vertices (rings
    // touching at a point, bridge copies) are ordered by vertex index, then node id.
    bool lower(NodeId a, NodeId b) const {
        if (general_) {
            const Index va = nodes_[a].v, vb = nodes_[b].v;
            return va != vb ? heightRank_[va] < heightRank_[vb] : a < b;
        }
        Point pa = P(a), pb = P(b);
        if (pa.y != pb.y) return pa.y < pb.y;
        if (pa.x != pb.x) return pa.x < pb.x;
        if (nodes_[a].v != nodes_[b].v) return nodes_[a].v < nodes_[b].v;
        return a < b;
    }
    // The same order as lower(), as a value (sag_index.h): what the sorted sag list is searched
    // with.
    HeightKey key(NodeId n) const {
        if (general_) return {double(heightRank_[nodes_[n].v]), 0, nodes_[n].v, n};
        return {P(n).y, P(n).x, nodes_[n].v, n};
    }
    // Off the axes no coordinate is a height: the vertices are sorted once by the exact
    // comparison along the direction (ties along its perpendicular, then by index, as lower())
    // and compared by rank from then on. Non-finite vertices go last (floodPart refuses them).
    void rankHeights() {
        std::vector<Index> order(poly_.vertices.size());
        std::iota(order.begin(), order.end(), Index(0));
        auto finite = [&](Index v) { return std::isfinite(pts_[v].x) && std::isfinite(pts_[v].y); };
        std::sort(order.begin(), order.end(), [&](Index a, Index b) {
            const bool fa = finite(a), fb = finite(b);
            if (fa != fb || !fa) return fa != fb ? fa : a < b;
            int h = heightSign(up_, pts_[a], pts_[b]);
            if (h == 0) h = acrossSign(up_, pts_[a], pts_[b]);
            return h != 0 ? h > 0 : a < b;
        });
        heightRank_.resize(order.size());
        for (size_t k = 0; k < order.size(); ++k) heightRank_[order[k]] = uint32_t(k);
        work().nodeVisits += order.size();
    }
    // Sorts nodes by lower(), comparing contiguous keys rather than chasing node -> vertex
    // -> point on every comparison; `keys` gets the sorted keys.
    void sortByHeight(std::vector<NodeId>& ns, std::vector<HeightKey>& keys) const {
        keys.resize(ns.size());
        for (size_t i = 0; i < ns.size(); ++i) keys[i] = key(ns[i]);
        std::sort(keys.begin(), keys.end());
        for (size_t i = 0; i < ns.size(); ++i) ns[i] = keys[i].node;
    }
    // Number of sags strictly below node n, by binary search on the contiguous height keys,
    // remembered per node: the water is usually the previous step's Next.
    uint32_t sagsBelow(NodeId n) {
        if (n - partFirstNode_ >= sagsBelow_.size())
            sagsBelow_.resize(nodes_.end() - partFirstNode_, kNone);
        uint32_t& r = sagsBelow_[n - partFirstNode_];
        if (r == kNone) r = sagHeights_.below(key(n));
        return r;
    }
    // The sags' points for the plane index, and their heights for the ranks.
    void indexSags() {
        const size_t count = sags_.size();
        std::vector<Point>& pointOfRank = b_.pointOfRank;
        pointOfRank.resize(count);
        for (size_t k = 0; k < count; ++k) pointOfRank[k] = P(sags_[k]);
        sagIndex_.build(pointOfRank);
        sagHeights_.index();
        unusedSags_ = uint32_t(count);
        // Indexed from the part's first node: per-part work stays proportional to the part.
        sagsBelow_.assign(nodes_.end() - partFirstNode_, kNone);
        work().nodeVisits += sagsBelow_.size();
        for (size_t k = 0; k < count; ++k)
            sagsBelow_[sags_[k] - partFirstNode_] = uint32_t(k);  // a sag's rank
    }
    int turn(NodeId a, NodeId b, NodeId c) const { return orient(P(a), P(b), P(c)); }
    NodeId prev(NodeId n) const { return nodes_[n].prev; }
    NodeId next(NodeId n) const { return nodes_[n].next; }
    bool isMinimum(NodeId n) const { return lower(n, prev(n)) && lower(n, next(n)); }
    bool ok() const { return result_.diagnostic.ok(); }

    // ---- [SECTION] a part: set-up, the run, the left-behind check ---------------------------
    // A part is flooded from the lowest node of its outer loop until no gorge is left; then
    // every node must have been flooded: a loop never reached means a hole outside the outer
    // ring, or loops that cross.
    void floodPart(uint32_t part) {
        const NodeId start = setUp(part);
        if (!ok()) return;
        Event e = begin(Action::Start);
        if (!isMinimum(start) || turn(prev(start), start, next(start)) <= 0)
            return forbid(e, Forbidden::StartNotBottom, start, kNil);
        startGorge(start);
        e.bottom = nodes_[start].v;
        emit(e);
        while (ok() && left_ != kNil) {
            if (budget_-- == 0) {
                Event f = begin(Action::Forbidden);
                return forbid(f, Forbidden::NoProgress, left_, right_);
            }
            step();
        }
        const NodeId alive = ok() ? firstAliveNode(partFirstNode_) : kNil;
        if (alive != kNil) {
            Event f = begin(Action::Forbidden);
            forbid(f, Forbidden::LeftBehind, alive, kNil);
        }
    }

    // The part's loops, sags and bottoms; the lowest node of the outer loop, where the water
    // starts (kNil, forbidden, when a ring cannot be a loop).
    NodeId setUp(uint32_t part) {
        const Part& pa = poly_.parts[part];
        part_ = part;
        partNodes_ = 0;
        partFirstNode_ = nodes_.end();
        for (Index v = poly_.rings[pa.firstRing].first; v < partEnd(pa); ++v) {
            if (!std::isfinite(pts_[v].x) || !std::isfinite(pts_[v].y)) {
                Event f = begin(Action::Forbidden);
                forbid(f, Forbidden::NotFinite, kNil, kNil, v);
                return kNil;
            }
        }
        for (Index r = pa.firstRing; r < pa.firstRing + pa.ringCount; ++r) {
            const Ring& ring = poly_.rings[r];
            bool steiner = ring.count == 1 && r != pa.firstRing;  // a point hole
            if (ring.count < 3 && !steiner) {
                Event f = begin(Action::Forbidden);
                forbid(f, Forbidden::ShortLoop, kNil, kNil, ring.count ? ring.first : kNone, r);
                return kNil;
            }
        }
        std::vector<NodeId>& partVertices = b_.partVertices;  // nodes of the part's loops
        std::vector<NodeId>& points = b_.points;              // one-node loops: Steiner points
        partVertices.clear();
        points.clear();
        const PartLoops loops = buildLoops(poly_, pts_, pa, nodes_, partVertices, points, b_.loops);
        partNodes_ = nodes_.end() - partFirstNode_;
        findSags(partVertices, points, loops.touching);
        gorges_.clear();
        todo_.clear();
        budget_ = 8ull * partNodes_ + 64;
        NodeId start = kNil;
        for (uint32_t i = 0; i < loops.outerNodes; ++i) {
            NodeId n = partVertices[i];
            if (start == kNil || lower(n, start)) start = n;
        }
        return start;
    }

    // The sags of the part, sorted by height (§4), and its bottoms, both taken from its minima
    // (kept in bottoms_ until the bottoms are sorted out of them: no node is classified twice).
    void findSags(const std::vector<NodeId>& partVertices, const std::vector<NodeId>& points,
                  bool touching) {
        sags_.clear();
        bottoms_.clear();
        for (NodeId n : partVertices)
            if (isMinimum(n)) bottoms_.push_back(n);
        for (NodeId n : bottoms_)
            if (turn(prev(n), n, next(n)) <= 0) sags_.push_back(n);
        // A point hole is a hole whose lowest vertex is its only one: a sag.
        sags_.insert(sags_.end(), points.begin(), points.end());
        sortByHeight(sags_, sagHeights_.keys());
        indexSags();
        prepareBanks(touching);
        // The bottoms, lowest first: every one of them starts a gorge unless the water
        // reaches it first. They are the to-do list of last resort (see lowestDryBottom()).
        size_t bottoms = 0;
        for (NodeId n : bottoms_)
            if (turn(prev(n), n, next(n)) > 0) bottoms_[bottoms++] = n;
        bottoms_.resize(bottoms);
        bottomCursor_ = 0;
        bottomScans_ = 0;  // sorted only if the fallback is asked often (takeNextGorge())
        walked_.clear(partFirstNode_);
    }

    NodeId firstAliveNode(NodeId from) const {
        for (NodeId n = from; n < nodes_.end(); n = n + 1)
            if (nodes_[n].alive) return n;
        return kNil;
    }

    // ---- [SECTION] events -----------------------------------------------------------------
    Fingers fingers() const {
        if (left_ == kNil) return {};
        return {nodes_[left_].v, nodes_[right_].v, nodes_[prev(left_)].v, nodes_[next(right_)].v};
    }
    Event begin(Action a) {
        Event e;
        e.action = a;
        e.part = part_;
        if (listener_) e.before = fingers();
        e.firstTriangle = uint32_t(result_.triangles.size());
        return e;
    }
    void emit(Event& e) {
        e.step = step_++;
        e.triangleCount = uint32_t(result_.triangles.size()) - e.firstTriangle;
        if (listener_) {
            e.after = fingers();
            e.water = water_ == kNil ? kNone : nodes_[water_].v;
            listener_->onEvent(e);
        }
    }
    Index partEnd(const Part& pa) const {
        const Ring& last = poly_.rings[pa.firstRing + pa.ringCount - 1];
        return last.first + last.count;
    }
    // `vertex`: a culprit given as a vertex index rather than a node (before loops exist);
    // `ring`: the ring of fewer than three vertices of a ShortLoop, which bounds no area.
    void forbid(Event& e, Forbidden why, NodeId a, NodeId b, Index vertex = kNone,
                Index ring = kNone) {
        e.action = Action::Forbidden;
        e.reason = why;
        e.culprit = a == kNil ? vertex : nodes_[a].v;
        e.culprit2 = b == kNil ? kNone : nodes_[b].v;
        if (!listener_) e.before = fingers();
        emit(e);
        e.after = fingers();
        result_.failure = e;
        Diagnostic& d = result_.diagnostic = {Status::Forbidden, describeForbidden(poly_, e),
                                              forbiddenCulprits(poly_, e)};
        if (ring != kNone) {
            d.message += " (ring " + std::to_string(ring) + " has " +
                         std::to_string(poly_.rings[ring].count) + " vertices)";
            d.culprits = {};
            d.culprits.rings = {ring};
        }
        left_ = right_ = kNil;
    }
    static void mark(Event& e, Test t, bool r) {
        e.tested |= uint8_t(1u << int(t));
        if (r) e.passed |= uint8_t(1u << int(t));
    }

    // ---- [SECTION] the decision tree (Fig. 9) ----------------------------------------------
    void step() {
        work().nodeVisits += 4;  // Left, Right and the fingers
        NodeId nl = prev(left_), nr = next(right_);
        Event e = begin(Action::Raise);
        bool same = nl == nr;
        mark(e, Test::SameNext, same);
        if (same) {
            // The fingers meet, but a hole may still hang in the gorge below them.
            NodeId s = findSag(nl, e);
            mark(e, Test::SagInside, s != kNil);
            if (s != kNil) return bridge(e, s);
            return fill(e);
        }
        if (nl == right_ || nr == left_) return forbid(e, Forbidden::FillOpen, nl, nr);
        bool leftLower = lower(nl, nr);
        mark(e, Test::LeftLower, leftLower);
        Side side = leftLower ? Side::Left : Side::Right;
        NodeId c = leftLower ? left_ : right_;
        NodeId nx = leftLower ? nl : nr;
        e.side = side;
        bool up = lower(c, nx);
        mark(e, Test::NextAbove, up);
        if (up) {
            NodeId s = findSag(nx, e);
            mark(e, Test::SagInside, s != kNil);
            if (s != kNil) return bridge(e, s);
            return raise(e, side);
        }
        // C is a local maximum of the loop: a top, or a ceiling reached too early.
        bool top = turn(prev(c), c, next(c)) <= 0;
        mark(e, Test::CIsTop, top);
        if (!top) return forbid(e, Forbidden::CeilingAsEnd, c, nx);
        bool jumpSet = nodes_[c].jump != kNil;
        mark(e, Test::JumpSet, jumpSet);
        if (jumpSet) return jump(e, side, c);
        spill(e, side, c);
    }

    // The lowest unused sag above the water and below Next inside the quadrangle
    // Left, Right, NextRight, NextLeft (§4, §5). Sags are sorted, so the scan starts at the
    // water level and stops at Next.
    NodeId findSag(NodeId nx, Event& e) {
        WorkCounters& w = work();
        const uint64_t before = w.nodeVisits + w.sagTests + w.orientCalls;  // not all ten counters
        NodeId s = searchSag(nx, e);
        w.sagSearch += w.nodeVisits + w.sagTests + w.orientCalls - before;
        return s;
    }
    NodeId searchSag(NodeId nx, Event& e) {
        if (unusedSags_ == 0)
            return kNil;  // every sag bridged already (or none): no bracket to search
        // Ranks bracketing the water and Next: the number of sags below each.
        int64_t lo = int64_t(sagsBelow(water_)) - 1;
        if (lo + 1 < int64_t(sags_.size()) && sags_[size_t(lo + 1)] == water_)
            ++lo;  // the water is itself a sag
        int64_t hi = sagsBelow(nx);
        if (hi <= lo + 1) return kNil;
        Point l = P(left_), r = P(right_), nl = P(prev(left_)), nr = P(next(right_));
        // Where such a sag can be: the quadrangle's box, the water's height band, and the
        // interior side of both banks (left of NextLeft->Left and of Right->NextRight).
        SagIndex::Region region;
        region.xMin = std::min(std::min(l.x, r.x), std::min(nl.x, nr.x));
        region.xMax = std::max(std::max(l.x, r.x), std::max(nl.x, nr.x));
        if (general_) {  // no coordinate is a height: the quadrangle's box bounds y too
            region.yMin = std::min(std::min(l.y, r.y), std::min(nl.y, nr.y));
            region.yMax = std::max(std::max(l.y, r.y), std::max(nl.y, nr.y));
        } else {
            region.yMin = P(water_).y;
            region.yMax = P(nx).y;
        }
        region.lines[0][0] = nl, region.lines[0][1] = l;
        region.lines[1][0] = r, region.lines[1][1] = nr;
        region.lineCount = 2;
        auto test = [&](uint32_t rank) {
            ++e.sagTests;
            ++work().sagTests;
            return inside(sagIndex_.point(rank), l, r, nr, nl);
        };
        if (!banksTried_ && treeWork_ > partNodes_ / 2) buildBanks();
        if (banks_.built()) {
            // The lowest such sag sees a bank that is an input edge across open water: it is
            // the first unused sag of the bank's list in the bracket (ALGORITHM.md §4). The
            // exact test confirms it; were it refused, the plane index below decides.
            int64_t k = bankCandidate(lo, hi);
            if (k == -1) return kNil;
            if (k >= 0 && test(uint32_t(k))) {
                return useSag(k);
            }
        }
        // The next few ranks first, in order: in a wide gorge (a strip under a row of holes)
        // the lowest sag is usually the next one up, which the tree would reach only after
        // visiting every box whose rank range begins below it.
        int64_t k = -1;
        for (int64_t end = std::min(hi, lo + 1 + kProbes); lo + 1 < end && k < 0;) {
            const uint32_t rank = uint32_t(++lo);
            ++work().nodeVisits;
            const Point s = sagIndex_.point(rank);
            if (!sagIndex_.used(rank) && s.x >= region.xMin && s.x <= region.xMax && test(rank))
                k = rank;
        }
        if (k < 0) {
            const uint64_t before = work().nodeVisits;
            k = sagIndex_.lowest(lo, hi, region, test);
            treeWork_ += work().nodeVisits - before;
        }
        if (k < 0) return kNil;
        return useSag(k);
    }
    NodeId useSag(int64_t rank) {
        sagIndex_.markUsed(uint32_t(rank));
        --unusedSags_;
        return sags_[size_t(rank)];
    }

    static constexpr int64_t kProbes = 4;  // ranks findSag tests before the sag tree

    // The bank lists (core/sag_banks.h) are built once the plane index has visited more than
    // half a box per node of the part: a part whose gorges it prunes well never pays the sweep.
    // Labels are only sound on loops whose edges are the input's and meet only at their
    // ends; where points are shared (touching rings, T-junctions) the plane index alone is
    // used. The initial links are kept for the sweep, which may run after edits. Off the axes
    // the sweep runs along the direction itself (its rays are the lines across it).
    void prepareBanks(bool touching) {
        banks_.clear();
        banksTried_ = touching || sags_.empty();
        treeWork_ = 0;
        partFirstVertex_ = poly_.rings[poly_.parts[part_].firstRing].first;
        initialNodes_ = partNodes_;
        initialNext_.clear();
        if (banksTried_) return;
        initialNext_.resize(initialNodes_);
        for (uint32_t i = 0; i < initialNodes_; ++i)
            initialNext_[i] = next(partFirstNode_ + i) - partFirstNode_;
    }
    void buildBanks() {
        banksTried_ = true;
        std::vector<Point> point(initialNodes_);
        for (uint32_t i = 0; i < initialNodes_; ++i) point[i] = P(partFirstNode_ + i);
        std::vector<uint32_t> sagOfRank(sags_.size());
        for (size_t k = 0; k < sags_.size(); ++k) sagOfRank[k] = sags_[k] - partFirstNode_;
        if (!banks_.build(point, initialNext_, sagOfRank, general_ ? up_ : Up::PlusY))
            banks_.clear();  // crossing edges
    }
    // The input edge from node a to node b, as its tail's initial node; kNone when a -> b
    // is not an input edge (a diagonal). Without shared points a vertex has one initial node.
    uint32_t inputEdge(NodeId a, NodeId b) const {
        uint32_t t = nodes_[a].v - partFirstVertex_;
        if (t >= initialNodes_ || initialNext_[t] + partFirstVertex_ != nodes_[b].v) return kNone;
        return t;
    }
    // The bank lists' answer for the active gorge: a rank, -1 for no sag, -2 when neither
    // bank is an input edge.
    int64_t bankCandidate(int64_t lo, int64_t hi) const {
        auto used = [&](uint32_t rank) { return sagIndex_.used(rank); };
        uint32_t t = inputEdge(prev(left_), left_);
        if (t != kNone) return banks_.lowest(true, t, lo, hi, used);
        t = inputEdge(right_, next(right_));
        if (t != kNone) return banks_.lowest(false, t, lo, hi, used);
        return -2;
    }

    // ---- [SECTION] the five actions ----------------------------------------------------------
    void cutTriangle(NodeId a, NodeId b, NodeId c) {
        result_.triangles.push_back({nodes_[a].v, nodes_[b].v, nodes_[c].v});
        ++cut_;
    }
    void unlink(NodeId n) {
        nodes_[prev(n)].next = next(n);
        nodes_[next(n)].prev = prev(n);
        nodes_[n].alive = false;
    }

    // Raise: Next joins the chain; the wedge of chain nodes it sees is cut off (Fig. 2).
    void raise(Event& e, Side side) {
        uint32_t guard = partNodes_ + 2;  // a walk longer than the part means broken loops
        if (side == Side::Left) {
            NodeId nl = prev(left_), c = left_;
            while (c != right_ && turn(nl, c, next(c)) > 0) {
                if (guard-- == 0 || !nodes_[c].alive)
                    return forbid(e, Forbidden::NoProgress, c, nl);
                ++work().nodeVisits;
                NodeId n = next(c);
                cutTriangle(nl, c, n);
                unlink(c);
                c = n;
            }
            left_ = water_ = nl;
            makeWet(nl);
        } else {
            NodeId nr = next(right_), c = right_;
            while (c != left_ && turn(prev(c), c, nr) > 0) {
                if (guard-- == 0 || !nodes_[c].alive)
                    return forbid(e, Forbidden::NoProgress, c, nr);
                ++work().nodeVisits;
                NodeId p = prev(c);
                cutTriangle(p, c, nr);
                unlink(c);
                c = p;
            }
            right_ = water_ = nr;
            makeWet(nr);
        }
        emit(e);
    }

    // Bridge: the sag s is joined to the water node (the highest node of the chain) by an
    // internal edge, doubled into two references each (Fig. 4). The gorge splits in two: the
    // left half stays active, the right half goes on the to-do list. The wedges the sag sees
    // on either side are cut at once, so both half-chains stay reflex (invariant 2).
    //
    // A Steiner point (a one-node loop) bounds nothing, so it splits nothing: the diagonal is
    // an antenna c -> s -> c' into the gorge, s stays inside the chain as the water node
    // (reflex: the whole gorge above it is open), and no gorge is pushed.
    void bridge(Event& e, NodeId s) {
        e.action = Action::Bridge;
        NodeId c = water_;
        e.sag = nodes_[s].v;
        e.bridgeTo = nodes_[c].v;
        if (listener_) {
            uint32_t i = 0;
            for (NodeId x = left_; x != c && i <= partNodes_ * 2; x = next(x)) ++i;
            e.chainIndex = i;
        }
        const bool point = prev(s) == s;
        NodeId s2 = point ? s : nodes_.end(), c2 = nodes_.end() + !point;
        if (!point) nodes_.push(Node{nodes_[s].v, prev(s), c2});
        nodes_.push(Node{nodes_[c].v, s2, next(c)});
        if (!point) nodes_[prev(s)].next = s2;
        nodes_[next(c)].prev = c2;
        nodes_[c].next = s;
        nodes_[s].prev = c;
        nodes_[s2].next = c2;
        partNodes_ += point ? 1 : 2;
        NodeId right2 = (right_ == c) ? c2 : right_;
        // Left half: Left .. c, s. Cut while the node before s is convex.
        NodeId x = c;
        uint32_t before = cut_, guard = partNodes_ + 2;
        while (x != left_ && turn(prev(x), x, s) > 0) {
            if (guard-- == 0 || !nodes_[x].alive) return forbid(e, Forbidden::NoProgress, x, s);
            ++work().nodeVisits;
            NodeId p = prev(x);
            cutTriangle(p, x, s);
            unlink(x);
            x = p;
        }
        e.cutLeft = cut_ - before;
        before = cut_;
        NodeId y = c2;
        while (y != right2 && turn(s2, y, next(y)) > 0) {
            if (guard-- == 0 || !nodes_[y].alive) return forbid(e, Forbidden::NoProgress, y, s);
            ++work().nodeVisits;
            NodeId n = next(y);
            cutTriangle(s2, y, n);
            unlink(y);
            y = n;
        }
        e.cutRight = cut_ - before;
        if (point) {
            right_ = right2;
        } else {
            e.gorgePushed = pushGorge(s2, right2, s2, false, kNone);
            right_ = s;
        }
        water_ = s;
        makeWet(s);
        makeWet(s2);
        emit(e);
    }

    // Spill: C is a top without a jump pointer. Its gorge is held there, the jump pointer
    // set to the other bank, and the water runs down the far side of the top to the next
    // bottom, skipping the sags it drips from (Fig. 5). A pending gorge met on the way
    // is the one that collects the water: it is taken off the to-do list.
    void spill(Event& e, Side side, NodeId t) {
        e.action = Action::Spill;
        NodeId other = side == Side::Left ? right_ : left_;
        nodes_[t].jump = other;
        e.top = nodes_[t].v;
        e.jumpTarget = nodes_[other].v;
        e.gorgePushed = pushGorge(left_, right_, water_, true, nodes_[t].v);
        bool goPrev = side == Side::Left;
        NodeId x = goPrev ? prev(t) : next(t);
        // `drops` counts sags the water fell from whose landing is not settled yet: a sag
        // followed by a ceiling roofs the basin below it (the next bottom is its floor); a
        // sag followed by a top is matched by the bottom of the pocket beyond that top.
        // Stretches already walked are crossed in one step (stretches.h), so walks from the
        // tops along a spiral arm do not retrace the arm.
        int64_t drops = 0;
        const int dir = goPrev ? 0 : 1;
        const std::vector<Stretches::Position>& pos = walked_.positions;
        size_t run = pos.size();  // first position of the stretch this walk records
        for (uint32_t guard = 0; guard <= partNodes_; ++guard, x = goPrev ? prev(x) : next(x)) {
            ++work().nodeVisits;
            Node& nd = nodes_[x];
            uint32_t g = goPrev ? nd.gorgeRight : nd.gorgeLeft;
            if (g != kNoGorge && !gorges_[g].done && !gorges_[g].held) {
                walked_.close(run);
                e.gorgePopped = g;
                resumeGorge(g);
                return emit(e);
            }
            if (nd.gorgeLeft != kNoGorge || nd.gorgeRight != kNoGorge || x == t) break;
            // Only extremes matter to the walk; the orientation test is spent on them alone
            // (and on every maximum of a stretch being recorded: a later walk may need it).
            const uint32_t at = walked_.recordedAt(dir, x);
            const bool fresh = at == kNone && !nd.wet;
            bool minimum = isMinimum(x);
            bool maximum = !minimum && lower(prev(x), x) && lower(next(x), x);
            bool convexHere =
                (minimum || (maximum && (drops > 0 || fresh))) && turn(prev(x), x, next(x)) > 0;
            bool sag = minimum && !convexHere, sensitive = convexHere;  // ceilings and bottoms
            if (fresh) {
                int32_t before = pos.size() > run ? pos.back().drops + pos.back().delta : 0;
                int8_t delta = sag ? 1 : sensitive ? -1 : 0;
                walked_.record(dir,
                               {x, uint32_t(walked_.stretches.size()), before, delta, sensitive},
                               nodes_.end());
            } else {
                walked_.close(run);
            }
            if (sag) {
                ++drops;
            } else if (sensitive && drops > 0) {
                --drops;  // a bottom beyond a top, or a ceiling roofing the basin under the last sag
            } else if (minimum && sensitive && !nd.wet) {
                walked_.close(run);
                mark(e, Test::WalkLanded, true);
                e.bottom = nd.v;
                startGorge(x);
                return emit(e);
            }
            if (!fresh && at != kNone && !nd.wet) {
                // Cross the stretch beyond x in one step, up to the node before the first one
                // that got wet since (its links may have changed) and before the first bottom
                // or ceiling the count would reach at zero (it may be the landing): none of
                // the nodes crossed can end the walk, and the count changes by their sum. The
                // stretch's tree finds whichever comes first (a wet node holds INT32_MIN).
                const Stretches::Stretch& rec = walked_.stretches[pos[at].stretch];
                const uint32_t a = at + 1;
                if (a < rec.end) {
                    uint32_t f =
                        walked_.firstAtMost(rec, a - rec.start, int64_t(pos[a].drops) - drops) +
                        rec.start;
                    // One past the last node crossed: a wet node (or the stretch's end) is not
                    // reached, nor the node before it; a zero-count node is reached live.
                    uint32_t b = f == rec.end || nodes_[pos[f].node].wet ? f - 1 : f;
                    if (b > a && guard + (b - a) <= partNodes_) {
                        drops += pos[b].drops - pos[a].drops;
                        guard += b - a;
                        x = pos[b - 1].node;
                    }
                }
            }
        }
        walked_.close(run);
        // The walk cannot tell where a drip from a sag lands when the basin below it is
        // bounded by another part of the boundary (a spiral, say). Any gorge not flooded
        // yet will do: flooding it reaches this top from its far side in time.
        mark(e, Test::WalkLanded, false);
        if (takeNextGorge(e)) return emit(e);
        forbid(e, Forbidden::SpillNoBottom, t, kNil);
    }

    // Jump: the water reached a held top from its far side; the chain continues on the
    // other bank, where the jump pointer leads (Fig. 6). The two chains meet at the top.
    void jump(Event& e, Side side, NodeId t) {
        e.action = Action::Jump;
        uint32_t g = side == Side::Left ? nodes_[t].gorgeRight : nodes_[t].gorgeLeft;
        e.top = nodes_[t].v;
        e.jumpTarget = nodes_[nodes_[t].jump].v;
        if (g == kNoGorge || gorges_[g].done || !gorges_[g].held)
            return forbid(e, Forbidden::JumpWrongSide, t, nodes_[t].jump);
        e.gorgePopped = g;
        const GorgeRec& rec = retireGorge(g);
        if (side == Side::Left) left_ = rec.left;
        else right_ = rec.right;
        nodes_[t].jump = kNil;
        water_ = t;
        emit(e);
    }

    // Fill: NextLeft and NextRight are one node: the fan from it closes the loop (Fig. 3).
    // Then the next pending gorge on the to-do list becomes active.
    void fill(Event& e) {
        e.action = Action::Fill;
        NodeId apex = prev(left_);
        if (left_ == right_) return forbid(e, Forbidden::FillOpen, apex, left_);
        uint32_t guard = partNodes_ + 2;
        for (NodeId c = left_; c != right_;) {
            NodeId n = next(c);
            if (guard-- == 0) return forbid(e, Forbidden::FillOpen, apex, c);  // Right unreachable
            ++work().nodeVisits;
            if (turn(apex, c, n) <= 0) return forbid(e, Forbidden::BadTriangle, c, n);
            c = n;
        }
        for (NodeId c = left_; c != right_;) {
            NodeId n = next(c);
            cutTriangle(apex, c, n);
            nodes_[c].alive = false;
            c = n;
        }
        nodes_[right_].alive = nodes_[apex].alive = false;
        left_ = right_ = water_ = kNil;
        takeNextGorge(e);
        emit(e);
    }

    // ---- [SECTION] the to-do list and the gorges -------------------------------------------
    // The next gorge to flood: the last pending gorge on the to-do list, else the lowest
    // bottom the water has not reached. False when neither exists.
    bool takeNextGorge(Event& e) {
        while (!todo_.empty()) {
            uint32_t g = todo_.back();
            todo_.pop_back();
            if (gorges_[g].done) continue;
            e.gorgePopped = g;
            resumeGorge(g);
            return true;
        }
        NodeId b = lowestDryBottom();
        if (b == kNil) return false;
        e.bottom = nodes_[b].v;
        startGorge(b);
        return true;
    }

    // The lowest bottom the water has not reached (kNil if none). Most runs ask a few times
    // (the last time to learn there is none), so the first asks scan the list, dropping the
    // bottoms reached since (they stay reached); after kBottomScans the list is sorted once
    // and a cursor walks it, as the paper's sorted list would.
    static constexpr uint32_t kBottomScans = 4;
    NodeId lowestDryBottom() {
        if (bottomScans_ < kBottomScans) {
            ++bottomScans_;
            NodeId best = kNil;
            size_t kept = 0;
            work().nodeVisits += bottoms_.size();
            for (NodeId b : bottoms_) {
                if (nodes_[b].wet || !nodes_[b].alive) continue;
                bottoms_[kept++] = b;
                if (best == kNil || lower(b, best)) best = b;
            }
            bottoms_.resize(kept);
            if (bottomScans_ == kBottomScans) sortByHeight(bottoms_, bottomKeys_);
            return best;
        }
        for (; bottomCursor_ < bottoms_.size(); ++bottomCursor_) {
            ++work().nodeVisits;
            NodeId b = bottoms_[bottomCursor_];
            if (!nodes_[b].wet && nodes_[b].alive) return b;
        }
        return kNil;
    }

    void startGorge(NodeId bottom) {
        left_ = right_ = water_ = bottom;
        makeWet(bottom);
    }
    void makeWet(NodeId n) {
        nodes_[n].wet = true;
        walked_.markWet(n);
    }

    uint32_t pushGorge(NodeId l, NodeId r, NodeId w, bool held, Index top) {
        uint32_t id = uint32_t(gorges_.size());
        gorges_.push_back({l, r, w, held, false, top});
        nodes_[l].gorgeLeft = id;
        nodes_[r].gorgeRight = id;
        if (!held) todo_.push_back(id);
        return id;
    }
    // A gorge is flooded again (Jump, or taken from the to-do list): its ends forget it.
    const GorgeRec& retireGorge(uint32_t g) {
        GorgeRec& rec = gorges_[g];
        rec.done = true;
        nodes_[rec.left].gorgeLeft = kNoGorge;
        nodes_[rec.right].gorgeRight = kNoGorge;
        return rec;
    }
    void resumeGorge(uint32_t g) {
        const GorgeRec& rec = retireGorge(g);
        left_ = rec.left;
        right_ = rec.right;
        water_ = rec.water;
    }

    // ---- [SECTION] the machine's memory -----------------------------------------------------
public:
    // What the machine allocates, lent by a Triangulator (or the thread, for small inputs)
    // from run to run; the members below of the same names refer to them.
    struct Buffers {
        std::vector<Point> rotated, pointOfRank;
        Nodes nodes;
        std::vector<NodeId> sags, partVertices, points, bottoms;
        std::vector<uint32_t> initialNext, sagsBelow, todo;
        SagIndex sagIndex;
        SagBanks banks;
        SagHeights sagHeights;
        std::vector<HeightKey> bottomKeys;
        std::vector<GorgeRec> gorges;
        Stretches walked;
        LoopScratch loops;
    };

private:
    const Polygon& poly_;
    Listener* listener_;
    std::unique_ptr<Buffers> own_;  // when none are lent
    Buffers& b_;                    // the buffers of this run: lent, or own_
    std::vector<Point>& rotated_ =
        b_.rotated;                     // the vertices turned so that the chosen vertical is +y
    const Point* pts_ = nullptr;        // the vertices as the machine sees them (rotated_ or input)
    const Up up_;                       // the chosen vertical
    const bool general_;                // off the axes: heights are heightRank_, never coordinates
    std::vector<uint32_t> heightRank_;  // per vertex, off the axes: its rank by height along up_
    Nodes& nodes_ = b_.nodes;
    std::vector<NodeId>& sags_ = b_.sags;
    SagIndex& sagIndex_ = b_.sagIndex;  // the sags by height rank, searchable by x
    SagBanks& banks_ = b_.banks;  // the sags each input edge sees, once the plane index is costly
    bool banksTried_ = false;
    uint64_t treeWork_ = 0;  // box visits of the plane index in this part
    uint32_t partFirstVertex_ = 0, initialNodes_ = 0;
    std::vector<uint32_t>& initialNext_ =
        b_.initialNext;                       // per initial node of the part (local ids): next
    SagHeights& sagHeights_ = b_.sagHeights;  // the sags' heights by rank (sag_index.h)
    std::vector<HeightKey>& bottomKeys_ = b_.bottomKeys;  // scratch for sorting the bottoms
    std::vector<uint32_t>& sagsBelow_ =
        b_.sagsBelow;  // per node of the part (from partFirstNode_): sags below it, kNone until asked
    std::vector<NodeId>& bottoms_ =
        b_.bottoms;  // bottoms; lowest first once sorted (lowestDryBottom())
    size_t bottomCursor_ = 0;
    uint32_t bottomScans_ = 0;
    std::vector<GorgeRec>& gorges_ = b_.gorges;
    Stretches& walked_ = b_.walked;          // spill walks remembered (stretches.h)
    std::vector<uint32_t>& todo_ = b_.todo;  // pending gorges (ids), last pushed first
    NodeId left_ = kNil, right_ = kNil, water_ = kNil, partFirstNode_ = NodeId(0);
    uint32_t part_ = 0, partNodes_ = 0, cut_ = 0, step_ = 0;
    uint64_t budget_ = 0;
    uint32_t unusedSags_ = 0;  // sags of the part not bridged yet
    FloodResult& result_;
};

}  // namespace

// Inputs up to this size reuse their thread's buffers: a program flooding many small polygons
// allocates little more than each result, and a thread keeps at most ~1 MB after a big one.
constexpr size_t kThreadBufferVertices = 4096;

FloodResult triangulate(const Polygon& polygon, Listener* listener, const Options& options) {
    thread_local Machine::Buffers buffers;
    thread_local bool lent = false;  // a listener that triangulates too gets buffers of its own
    struct Lending {
        bool active;
        ~Lending() {
            if (active) lent = false;
        }
    } lending{!lent && polygon.vertices.size() <= kThreadBufferVertices};
    if (lending.active) lent = true;
    FloodResult result;
    Machine(polygon, listener, options, result, lending.active ? &buffers : nullptr).run();
    return result;
}

struct Triangulator::Workspace {
    Machine::Buffers buffers;
    FloodResult result;
};
Triangulator::Triangulator() : workspace_(new Workspace) {}
Triangulator::~Triangulator() = default;
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&&) noexcept = default;
const FloodResult& Triangulator::run(const Polygon& polygon, Listener* listener,
                                     const Options& options) {
    Workspace& w = *workspace_;
    Machine(polygon, listener, options, w.result, &w.buffers).run();  // refills the last result
    return w.result;
}

}  // namespace flood
