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
//   predicates on nodes     lower(): the paper's below as a total order on nodes (heights.h)
//   a part                  set-up (loops.h builds the loops), the run, the left-behind check
//   events                  begin/emit; forbid() (narrate.cpp words the diagnostic)
//   the decision tree       step(): Fig. 9; the sag search (sag_search.h)
//   the five actions        Raise, Bridge, Spill (its walk: spill_walk.h), Jump, Fill
//   the to-do list          pending gorges, dry bottoms (dry_bottoms.h); retireGorge()
//   the machine's memory    the buffers lent from run to run (machine.h); the entry points
//                           are in triangulate.cpp
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "machine/machine.h"
#include "machine/spill_walk.h"

namespace flood {
namespace {

// An event nobody records: every field takes any value and keeps none, so a run without a
// listener decides exactly as a recorded one and stores nothing (see flood() below).
struct QuietEvent {
    struct Sink {
        template <class T>
        void operator=(const T&) {}
    };
#define FLOOD_X(kind, type, name, initial) Sink name;
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
};

// Inputs of at most this many loop nodes reserve as if every node were a minimum.
constexpr size_t kUncountedMinima = 256;

// kRecording: events are built (for the listener, or for the failure event); else QuietEvent.
template <bool kRecording>
class Machine {
    using Ev = std::conditional_t<kRecording, Event, QuietEvent>;

public:
    Machine(const Polygon& poly, Listener* listener, const Options& opt, FloodResult& out,
            MachineBuffers* keep)
        : poly_(poly),
          listener_(listener),
          own_(keep ? nullptr : new MachineBuffers),
          b_(keep ? *keep : *own_),
          up_(opt.up),
          heights_(poly, opt.up, b_.nodes, b_.rotated, b_.ranks, b_.rankOrder),
          result_(out) {}

    Machine(const Machine&) = delete;
    Machine& operator=(const Machine&) = delete;

    bool refused() const { return refused_; }
    // Floods only the parts [first, end) of a tiled polygon (Polygon::tiled()), in place of
    // all: set before start().
    void onlyParts(uint32_t first, uint32_t end) { firstPart_ = first, endPart_ = end; }
    uint32_t stepsTaken() const { return step_; }

    void run() {
        if (start()) advance<false>();
    }

    // A run in slices (SteppedRun): start() sets it up, then each advance() takes at most
    // `steps` steps of the parts' floods; it returns false once the run has ended. Unsliced
    // (run()), the loop counts nothing: a small polygon's call pays no slicing.
    bool start() {
        nodes_.clear();
        result_.triangles.clear();
        if (!result_.diagnostic.ok())
            result_.diagnostic = {}, result_.failure = {};  // set together
        if (!up_.valid()) {
            result_.diagnostic = {Status::Usage,
                                  "the flood direction (" + upName(up_) +
                                      ") is not a direction: it must be a nonzero finite vector"};
            return false;
        }
        if (heights_.general()) heights_.rank();
        // Room for every node and gorge of the run, so that neither array moves (a move holds
        // the old and the new array at once): a node per vertex and T-junction, and the two
        // copies a Bridge adds per sag, at most one sag a minimum of a ring (merged loops may
        // need more, and get them); a gorge per Bridge or Spill (no more tops than minima).
        // A small input takes the bound minima <= nodes uncounted (a few KB at most), so a
        // warm call skips the count; a large one counts them (one pass, cheap beside the
        // run) and reserves what it asks, so a warm call on it reserves nothing.
        endPart_ = std::min<uint32_t>(endPart_, uint32_t(poly_.parts.size()));
        const bool all = firstPart_ == 0 && endPart_ == poly_.parts.size();
        const Index firstRing = all ? 0 : poly_.parts[firstPart_].firstRing;
        const Index endRing =
            all ? Index(poly_.rings.size())
                : poly_.parts[endPart_ - 1].firstRing + poly_.parts[endPart_ - 1].ringCount;
        const size_t vertices =
            all ? poly_.vertices.size()
                : partEnd(poly_.parts[endPart_ - 1]) - poly_.rings[firstRing].first;
        const size_t loopNodes = vertices + poly_.splits.size();
        const size_t minima =
            loopNodes <= kUncountedMinima ? loopNodes : heights_.ringMinima(firstRing, endRing);
        if (nodes_.capacity() < loopNodes + 2 * minima + 16)
            nodes_.reserve(loopNodes + 2 * minima + 16);
        if (gorges_.capacity() < 2 * minima + 16) gorges_.reserve(2 * minima + 16);
        const size_t triangles = vertices + 2 * size_t(endRing - firstRing);
        if (result_.triangles.capacity() < triangles) result_.triangles.reserve(triangles);
        nextPart_ = firstPart_;
        return true;
    }
    template <bool kSliced = true>
    bool advance(uint64_t steps = 0) {
        while (ok() && (left_ != kNil || nextPart_ < endPart_)) {
            if (left_ == kNil) beginPart(nextPart_++);
            // The part's flood; a forbidden state ends it too (forbid() drops the fingers).
            if constexpr (kSliced) {
                for (; left_ != kNil && steps; --steps) step();
            } else {
                while (left_ != kNil) step();
            }
            if (left_ != kNil) return true;  // out of steps
            if (ok()) endPart();
        }
        result_.steps = step_;
        return false;
    }

private:
    // ---- [SECTION] predicates on nodes -------------------------------------------------
    Point P(NodeId n) const { return heights_.at(n); }
    bool lower(NodeId a, NodeId b) const { return heights_.lower(a, b); }
    // The paper's convex() predicate on nodes: the corner at b turns left (strictly).
    bool convex(NodeId a, NodeId b, NodeId c) const { return flood::convex(P(a), P(b), P(c)); }
    NodeId prev(NodeId n) const { return nodes_[n].prev; }
    NodeId next(NodeId n) const { return nodes_[n].next; }
    bool isMinimum(NodeId n) const { return lower(n, prev(n)) && lower(n, next(n)); }
    bool ok() const { return result_.diagnostic.ok(); }

    // ---- [SECTION] a part: set-up, the run, the left-behind check ---------------------------
    // A part is flooded from the lowest node of its outer loop until no gorge is left
    // (advance() steps it); then every node must have been flooded: a loop never reached
    // means a hole outside the outer ring, or loops that cross.
    void beginPart(uint32_t part) {
        const NodeId start = setUp(part);
        if (!ok()) return;
        Ev e = begin(Action::Start);
        if (!isMinimum(start) || !convex(prev(start), start, next(start)))
            return forbid(e, Forbidden::StartNotBottom, start, kNil);
        startGorge(start);
        e.bottom = nodes_[start].v;
        emit(e);
    }
    void step() {
        if (budget_-- == 0) {
            Ev f = begin(Action::Forbidden);
            return forbid(f, Forbidden::NoProgress, left_, right_);
        }
        decide();
    }
    void endPart() {
        // Every node the part had was cut off (the usual end): nothing to look for.
        const NodeId alive = killed_ < partNodes_ ? firstAliveNode(partFirstNode_) : kNil;
        if (alive != kNil) {
            Ev f = begin(Action::Forbidden);
            forbid(f, Forbidden::LeftBehind, alive, kNil);
        }
    }

    // The part's loops, sags and bottoms; the lowest node of the outer loop, where the water
    // starts (kNil, forbidden, when a ring cannot be a loop).
    NodeId setUp(uint32_t part) {
        const Part& pa = poly_.parts[part];
        part_ = part;
        partNodes_ = killed_ = 0;
        partFirstNode_ = nodes_.end();
        // validate() passed on a polygon whose points are distinct: its coordinates are finite.
        const Index checkEnd = poly_.pointsDistinct ? 0 : partEnd(pa);
        for (Index v = poly_.rings[pa.firstRing].first; v < checkEnd; ++v) {
            const Point p = heights_.points()[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                Ev f = begin(Action::Forbidden);
                forbid(f, Forbidden::NotFinite, kNil, kNil, v);
                return kNil;
            }
        }
        for (Index r = pa.firstRing; r < pa.firstRing + pa.ringCount; ++r) {
            const Ring& ring = poly_.rings[r];
            bool steiner = ring.count == 1 && r != pa.firstRing;  // a point hole
            if (ring.count < 3 && !steiner) {
                Ev f = begin(Action::Forbidden);
                forbid(f, Forbidden::ShortLoop, kNil, kNil, ring.count ? ring.first : kNone, r);
                return kNil;
            }
        }
        std::vector<NodeId>& partVertices = b_.partVertices;  // nodes of the part's loops
        std::vector<NodeId>& points = b_.points;              // one-node loops: Steiner points
        partVertices.clear();
        points.clear();
        const PartLoops loops =
            buildLoops(poly_, heights_.points(), pa, nodes_, partVertices, points, b_.loops);
        partNodes_ = nodes_.end() - partFirstNode_;
        NodeId start = findSags(partVertices, points, loops);
        gorges_.clear();
        todo_.clear();
        budget_ = 8ull * partNodes_ + 64;
        if (loops.touching) {  // merged loops: the outer ring's lowest node may not be a minimum
            start = kNil;
            for (uint32_t i = 0; i < loops.outerNodes; ++i) {
                NodeId n = partVertices[i];
                if (start == kNil || lower(n, start)) start = n;
            }
        }
        // The set-up's scratch is dead from here on (loops.h).
        giveBackIfLarge(partVertices);
        giveBackIfLarge(points);
        RepeatedPointsScratch& repeats = b_.loops.repeats;
        for (auto* v : {&repeats.start, &repeats.fill, &repeats.table}) giveBackIfLarge(*v);
        giveBackIfLarge(repeats.hash);
        giveBackIfLarge(repeats.byBucket);
        giveBackIfLarge(repeats.copies);
        return start;
    }

    // The sags of the part, sorted by height (§4), and its bottoms, both taken from its minima
    // (kept in the bottoms' list until the bottoms are sorted out of them: no node is
    // classified twice). Returns the lowest minimum of the outer ring's nodes: unless loops
    // were merged, the outer loop is that ring, and its lowest node is one of its minima.
    NodeId findSags(const std::vector<NodeId>& partVertices, const std::vector<NodeId>& points,
                    const PartLoops& loops) {
        std::vector<NodeId>& sags = sags_.sags();
        std::vector<NodeId>& bottoms = bottoms_.reset();
        sags.clear();
        heights_.minima(partVertices, bottoms);
        const NodeId outerEnd = partFirstNode_ + loops.outerNodes;  // the outer ring's nodes
        NodeId lowest = kNil;
        // The bottoms, lowest first: every one of them starts a gorge unless the water
        // reaches it first. They are the to-do list of last resort (dry_bottoms.h).
        size_t kept = 0;
        for (NodeId n : bottoms) {
            if (n < outerEnd && (lowest == kNil || lower(n, lowest))) lowest = n;
            if (!convex(prev(n), n, next(n))) sags.push_back(n);
            else bottoms[kept++] = n;
        }
        bottoms.resize(kept);
        // A point hole is a hole whose lowest vertex is its only one: a sag.
        sags.insert(sags.end(), points.begin(), points.end());
        sags_.index(heights_, partFirstNode_, poly_.rings[poly_.parts[part_].firstRing].first,
                    loops.touching, poly_.pointsDistinct);
        walked_.clear(partFirstNode_, nodes_.capacity() - size_t(partFirstNode_));
        return lowest;
    }

    NodeId firstAliveNode(NodeId from) const {
        for (NodeId n = from; n < nodes_.end(); n = n + 1)
            if (nodes_.alive(n)) return n;
        return kNil;
    }

    // ---- [SECTION] events -----------------------------------------------------------------
    Fingers fingers() const {
        if (left_ == kNil) return {};
        return {nodes_[left_].v, nodes_[right_].v, nodes_[prev(left_)].v, nodes_[next(right_)].v};
    }
    Ev begin(Action a) {
        if constexpr (!kRecording) {
            return Ev{};
        } else {
            Ev e;
            e.action = a;
            e.part = part_;
            if (listener_) e.before = fingers();
            e.firstTriangle = uint32_t(result_.triangles.size());
            return e;
        }
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
    // Unrecorded, an event only counts its step; a forbidden state stops the run, and flood()
    // runs it again recording, for the failure event and its diagnostic.
    void emit(QuietEvent&) { ++step_; }
    void forbid(QuietEvent&, Forbidden, NodeId, NodeId, Index = kNone, Index = kNone) {
        refused_ = true;
        result_.diagnostic.status = Status::Forbidden;
        left_ = right_ = kNil;
    }
    static void mark(QuietEvent&, Test, bool) {}
    static void mark(Event& e, Test t, bool r) {
        e.tested |= uint8_t(1u << int(t));
        e.passed |= uint8_t(unsigned(r) << int(t));  // no branch: r is the test just decided
    }

    // ---- [SECTION] the decision tree (Fig. 9) ----------------------------------------------
    void decide() {
        work().nodeVisits += 4;  // Left, Right and the fingers
        NodeId nl = prev(left_), nr = next(right_);
        Ev e = begin(Action::Raise);
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
        bool top = !convex(prev(c), c, next(c));
        mark(e, Test::CIsTop, top);
        if (!top) return forbid(e, Forbidden::CeilingAsEnd, c, nx);
        bool jumpSet = nodes_.ends(c).jump != kNil;
        mark(e, Test::JumpSet, jumpSet);
        if (jumpSet) return jump(e, side, c);
        spill(e, side, c);
    }

    // The lowest unused sag above the water and below Next inside the quadrangle
    // Left, Right, NextRight, NextLeft (§4, §5): sag_search.h.
    NodeId findSag(NodeId nx, Ev& e) {
        if constexpr (kRecording) {
            return sags_.find(left_, right_, water_, nx, e);
        } else {
            return sags_.find(left_, right_, water_, nx, uncounted_);
        }
    }

    // ---- [SECTION] the five actions ----------------------------------------------------------
    void cutTriangle(NodeId a, NodeId b, NodeId c) {
        result_.triangles.push_back({nodes_[a].v, nodes_[b].v, nodes_[c].v});
        ++cut_;
    }
    void unlink(NodeId n) {
        nodes_[prev(n)].next = next(n);
        nodes_[next(n)].prev = prev(n);
        kill(n);
    }
    void kill(NodeId n) {  // counted, so that the left-behind check can tell none is left
        killed_ += nodes_.alive(n);
        nodes_.kill(n);
    }

    // Cuts off the wedge of chain nodes that `apex` sees (a Raise, each half of a Bridge): from
    // `c` along the chain, towards next() if `forward` else prev(), while the node is convex
    // and not `stop`, each triangle in the loop's order. False if the walk ran longer than the
    // part (broken loops), `c` then the node where it failed.
    bool cutWedge(NodeId& c, NodeId stop, NodeId apex, bool forward, uint32_t& guard) {
        while (c != stop) {
            const NodeId along = forward ? next(c) : prev(c);
            const NodeId a = forward ? apex : along, b = forward ? along : apex;
            if (!convex(a, c, b)) return true;
            if (guard-- == 0 || !nodes_.alive(c)) return false;
            ++work().nodeVisits;
            cutTriangle(a, c, b);
            unlink(c);
            c = along;
        }
        return true;
    }

    // Raise: Next joins the chain; the wedge of chain nodes it sees is cut off (Fig. 2).
    void raise(Ev& e, Side side) {
        uint32_t guard = partNodes_ + 2;  // a walk longer than the part means broken loops
        const bool left = side == Side::Left;
        NodeId& end = left ? left_ : right_;
        const NodeId joining = left ? prev(end) : next(end);  // Next, off the acting end
        NodeId c = end;
        if (!cutWedge(c, left ? right_ : left_, joining, left, guard))
            return forbid(e, Forbidden::NoProgress, c, joining);
        end = water_ = joining;
        makeWet(joining);
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
    void bridge(Ev& e, NodeId s) {
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
        if (!cutWedge(x, left_, s, false, guard)) return forbid(e, Forbidden::NoProgress, x, s);
        e.cutLeft = cut_ - before;
        before = cut_;
        NodeId y = c2;  // right half: c2 .. Right, s2
        if (!cutWedge(y, right2, s2, true, guard)) return forbid(e, Forbidden::NoProgress, y, s);
        e.cutRight = cut_ - before;
        if (point) {
            right_ = right2;
        } else {
            e.gorgePushed = pushGorge(s2, right2, s2, false);
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
    void spill(Ev& e, Side side, NodeId t) {
        e.action = Action::Spill;
        NodeId other = side == Side::Left ? right_ : left_;
        nodes_.editEnds(t, [&](Ends& x) { x.jump = other; });
        e.top = nodes_[t].v;
        e.jumpTarget = nodes_[other].v;
        e.gorgePushed = pushGorge(left_, right_, water_, true);
        const Landing land =
            walkDown(heights_, gorges_, walked_, t, side == Side::Left, partNodes_);
        if (land.gorge != kNoGorge) {
            e.gorgePopped = land.gorge;
            resumeGorge(land.gorge);
            return emit(e);
        }
        if (land.bottom != kNil) {
            mark(e, Test::WalkLanded, true);
            e.bottom = nodes_[land.bottom].v;
            startGorge(land.bottom);
            return emit(e);
        }
        // The walk cannot tell where a drip from a sag lands when the basin below it is
        // bounded by another part of the boundary (a spiral, say). Any gorge not flooded
        // yet will do: flooding it reaches this top from its far side in time.
        mark(e, Test::WalkLanded, false);
        if (takeNextGorge(e)) return emit(e);
        forbid(e, Forbidden::SpillNoBottom, t, kNil);
    }

    // Jump: the water reached a held top from its far side; the chain continues on the
    // other bank, where the jump pointer leads (Fig. 6). The two chains meet at the top.
    void jump(Ev& e, Side side, NodeId t) {
        e.action = Action::Jump;
        const Ends ends = nodes_.ends(t);
        uint32_t g = side == Side::Left ? ends.gorgeRight : ends.gorgeLeft;
        e.top = nodes_[t].v;
        e.jumpTarget = nodes_[ends.jump].v;
        if (g == kNoGorge || gorges_[g].done || !gorges_[g].held)
            return forbid(e, Forbidden::JumpWrongSide, t, ends.jump);
        e.gorgePopped = g;
        const GorgeRec& rec = retireGorge(g);
        if (side == Side::Left) left_ = rec.left;
        else right_ = rec.right;
        nodes_.editEnds(t, [](Ends& x) { x.jump = kNil; });
        water_ = t;
        emit(e);
    }

    // Fill: NextLeft and NextRight are one node: the fan from it closes the loop (Fig. 3).
    // Then the next pending gorge on the to-do list becomes active.
    void fill(Ev& e) {
        e.action = Action::Fill;
        NodeId apex = prev(left_);
        if (left_ == right_) return forbid(e, Forbidden::FillOpen, apex, left_);
        uint32_t guard = partNodes_ + 2;
        for (NodeId c = left_; c != right_;) {
            NodeId n = next(c);
            if (guard-- == 0) return forbid(e, Forbidden::FillOpen, apex, c);  // Right unreachable
            ++work().nodeVisits;
            if (!convex(apex, c, n)) return forbid(e, Forbidden::BadTriangle, c, n);
            c = n;
        }
        for (NodeId c = left_; c != right_;) {
            NodeId n = next(c);
            cutTriangle(apex, c, n);
            kill(c);
            c = n;
        }
        kill(right_);
        kill(apex);
        left_ = right_ = water_ = kNil;
        takeNextGorge(e);
        emit(e);
    }

    // ---- [SECTION] the to-do list and the gorges -------------------------------------------
    // The next gorge to flood: the last pending gorge on the to-do list, else the lowest
    // bottom the water has not reached. False when neither exists.
    bool takeNextGorge(Ev& e) {
        while (!todo_.empty()) {
            uint32_t g = todo_.back();
            todo_.pop_back();
            if (gorges_[g].done) continue;
            e.gorgePopped = g;
            resumeGorge(g);
            return true;
        }
        NodeId b = bottoms_.lowest(heights_);
        if (b == kNil) return false;
        e.bottom = nodes_[b].v;
        startGorge(b);
        return true;
    }

    void startGorge(NodeId bottom) {
        left_ = right_ = water_ = bottom;
        makeWet(bottom);
    }
    void makeWet(NodeId n) {
        nodes_.wetten(n);
        walked_.markWet(n);
    }

    uint32_t pushGorge(NodeId l, NodeId r, NodeId w, bool held) {
        uint32_t id = uint32_t(gorges_.size());
        gorges_.push_back({l, r, w, held, false});
        nodes_.editEnds(l, [id](Ends& x) { x.gorgeLeft = id; });
        nodes_.editEnds(r, [id](Ends& x) { x.gorgeRight = id; });
        if (!held) todo_.push_back(id);
        return id;
    }
    // A gorge is flooded again (Jump, or taken from the to-do list): its ends forget it.
    const GorgeRec& retireGorge(uint32_t g) {
        GorgeRec& rec = gorges_[g];
        rec.done = true;
        nodes_.editEnds(rec.left, [](Ends& x) { x.gorgeLeft = kNoGorge; });
        nodes_.editEnds(rec.right, [](Ends& x) { x.gorgeRight = kNoGorge; });
        return rec;
    }
    void resumeGorge(uint32_t g) {
        const GorgeRec& rec = retireGorge(g);
        left_ = rec.left;
        right_ = rec.right;
        water_ = rec.water;
    }

    // ---- [SECTION] the machine's memory -----------------------------------------------------
    const Polygon& poly_;
    Listener* listener_;
    std::unique_ptr<MachineBuffers> own_;  // when none are lent
    MachineBuffers& b_;                    // the buffers of this run: lent, or own_
    const Up up_;                          // the chosen vertical
    Heights heights_;                      // the vertices as the machine sees them, and below
    Nodes& nodes_ = b_.nodes;
    SagSearch& sags_ = b_.sags;
    DryBottoms& bottoms_ = b_.bottoms;
    std::vector<GorgeRec>& gorges_ = b_.gorges;
    Stretches& walked_ = b_.walked;          // spill walks remembered (stretches.h)
    std::vector<uint32_t>& todo_ = b_.todo;  // pending gorges (ids), last pushed first
    NodeId left_ = kNil, right_ = kNil, water_ = kNil, partFirstNode_ = NodeId(0);
    uint32_t part_ = 0, partNodes_ = 0, killed_ = 0, cut_ = 0, step_ = 0;  // killed_: of the part
    uint32_t nextPart_ = 0;                          // the part advance() sets up next
    uint32_t firstPart_ = 0, endPart_ = UINT32_MAX;  // the parts flooded (onlyParts())
    uint64_t budget_ = 0;
    FloodResult& result_;
    bool refused_ = false;  // quiet: a forbidden state was reached
    Event uncounted_;       // quiet: the sag search counts its tests into an event; this one
};

}  // namespace

// With nobody listening no event is built. A run that ends in a forbidden state is then run
// again recording (as before: the same decisions, on the same buffers), so that its result
// carries the failure event and the diagnostic that names it, exactly as a recorded run would.
void flood(const Polygon& poly, Listener* listener, const Options& options, FloodResult& out,
           MachineBuffers* keep) {
    if (listener) return Machine<true>(poly, listener, options, out, keep).run();
    Machine<false> quiet(poly, nullptr, options, out, keep);
    quiet.run();
    if (quiet.refused()) Machine<true>(poly, nullptr, options, out, keep).run();
}

bool floodParts(const Polygon& poly, const Options& options, uint32_t firstPart, uint32_t endPart,
                FloodResult& out) {
    Machine<false> quiet(poly, nullptr, options, out, nullptr);
    quiet.onlyParts(firstPart, endPart);
    quiet.run();
    return out.diagnostic.ok();
}

struct SteppedRun::Impl {
    FloodResult result;
    Machine<true> machine;
    bool going;
    Impl(const Polygon& poly, Listener* listener, const Options& options)
        : machine(poly, listener, options, result, nullptr), going(machine.start()) {}
};
SteppedRun::SteppedRun(const Polygon& polygon, Listener* listener, const Options& options)
    : impl_(new Impl(polygon, listener, options)) {}
SteppedRun::~SteppedRun() = default;
bool SteppedRun::advance(uint64_t steps) {
    return impl_->going = impl_->going && impl_->machine.advance(steps);
}
uint32_t SteppedRun::steps() const { return impl_->machine.stepsTaken(); }
FloodResult& SteppedRun::result() { return impl_->result; }

}  // namespace flood
