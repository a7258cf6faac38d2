// Check 4 of validate(): no two edges cross or overlap — a sweep over the vertices in
// below() order (sweep_tree.h), or on a small polygon a test of every pair of edges with the
// sweep's verdicts. The order of checks and the costs are in validate.cpp's header.
#include <algorithm>
#include <cmath>

#include "check/validator.h"

namespace flood {
namespace validate_detail {

// The vertices in the order of below() on their points, ties by index, into `order`. Sorted as
// (point, index) records, so no comparison reaches into the vertex array: at 10^6 vertices a
// sort of bare indices spent most of its time waiting for memory. A large input is first dealt
// into about n/4 buckets by height (a counting sort), then each bucket is sorted alone, in the
// cache: 2 log2 4 comparisons a vertex instead of about log2 n. The bucket of a height is a
// rounded linear map of it, and rounding is monotone, so a lower bucket never holds a higher
// point: the buckets only share out the work, the exact comparisons decide the order, which is
// the one a single sort gives (a strict total order has one sorted sequence).
void sortVerticesBelow(const std::vector<Point>& V, std::vector<EventKey>& keys,
                       std::vector<Index>& order, std::vector<Index>& start) {
    auto less = [](const EventKey& a, const EventKey& b) {
        return below(a.p, b.p) || (a.p == b.p && a.v < b.v);
    };
    const size_t n = V.size();
    keys.resize(n);
    double lo = n ? V[0].y : 0, hi = lo;
    for (const Point& q : V) lo = std::min(lo, q.y), hi = std::max(hi, q.y);
    const size_t buckets = n / 4;
    const double scale = double(buckets) / (hi - lo);  // inf or 0 when the range is degenerate
    if (n < 4096 || !(scale > 0 && scale < HUGE_VAL)) {
        for (Index v = 0; v < n; ++v) keys[v] = {V[v], v};
        std::sort(keys.begin(), keys.end(), less);
    } else {
        auto bucketOf = [&](double y) { return std::min(size_t((y - lo) * scale), buckets - 1); };
        start.assign(buckets + 1, 0);
        for (const Point& q : V) ++start[bucketOf(q.y) + 1];
        for (size_t b = 1; b <= buckets; ++b) start[b] += start[b - 1];
        for (Index v = 0; v < n; ++v) keys[start[bucketOf(V[v].y)]++] = {V[v], v};
        // start[b] is now where bucket b ends, the next one's start.
        for (size_t b = 0, from = 0; b < buckets; from = start[b++])
            std::sort(keys.begin() + long(from), keys.begin() + long(start[b]), less);
    }
    order.resize(n);
    for (size_t i = 0; i < n; ++i) order[i] = keys[i].v;
}

// --- check 4: edge against edge, by a sweep ----------------------------------------------
//
// Shamos-Hoey: events are the vertices in the order of below() (y, then x: the paper's tilted
// horizontal); the active edges are kept in a balanced tree ordered left to right along the
// sweep line by exact orient() comparisons. Only edges that become neighbours in that order
// are tested, and the lowest violation is always found before the sweep passes it. Edges
// meeting at a shared vertex end and start at one event, so touching rings never disturb the
// order. The same sweep records, for each ring, the ring whose interior immediately encloses
// it (the edge just left of the ring's lowest vertex tells), used by check 6.

struct SweepOrder {
    const std::vector<Segment>* segs;
    const Point* at;  // the polygon's vertices
    // a before b along the sweep line (a left of b), both active at the current event.
    bool operator()(Index ia, Index ib) const {
        if (ia == ib) return false;
        const Point alo = at[(*segs)[ia].lo], ahi = at[(*segs)[ia].hi];
        const Point blo = at[(*segs)[ib].lo], bhi = at[(*segs)[ib].hi];
        if (!below(alo, blo)) {  // a starts at or after b: place a.lo against b
            int o = orientAxisFirst(blo, bhi, alo);
            if (o == 0) o = orientAxisFirst(blo, bhi, ahi);
            if (o != 0) return o > 0;
        } else {
            int o = orientAxisFirst(alo, ahi, blo);
            if (o == 0) o = orientAxisFirst(alo, ahi, bhi);
            if (o != 0) return o < 0;
        }
        return ia < ib;  // collinear: an overlap, reported when they are tested
    }
};

// How edges e and f meet, when the sweep finds them side by side: apart, crossing,
// overlapping, folding back (a spike), or touching (a vertex strictly inside the other's edge,
// a junction). The first problem found is kept in `problem`; later calls do nothing.
void Validator::classifyMeeting(Index e, Index f) {
    ++work().validatorSteps;
    if (problem || e == f) return;
    if (isPoint(f)) std::swap(e, f);
    Point a = pt(e), b = pt(next(e)), c = pt(f), d = pt(next(f));
    if (isPoint(e)) {  // a point against an edge (or another point: met in check 5)
        if (!isPoint(f) && !boxesApart(a, a, c, d) && insideSegment(c, d, a)) touchOnEdge(e, f);
        return;
    }
    // Adjacent edges of one ring meet at their shared vertex; only a spike is wrong.
    bool adjacent = false;
    for (int k = 0; k < 2; ++k) {
        Index e1 = k ? f : e, e2 = k ? e : f;
        if (next(e1) != e2) continue;
        adjacent = true;
        Point p = pt(e1), q = pt(e2), s = pt(next(e2));
        // Collinear, and p and s in one direction from q (orient(q, p, s) is minus this one).
        if (orientAxisFirst(p, q, s) == 0 && half(q, p) == half(q, s)) {
            problemCulprits = atPoint(e2, {e1, e2});
            problem.emplace(e2, "the ring folds back on itself here (spike): edge " + edgeText(e1) +
                                    " overlaps the next edge");
            return;
        }
    }
    if (adjacent || boxesApart(a, b, c, d)) return;
    // With c and d strictly on one side of line ab nothing can happen: no crossing, no overlap,
    // and neither a nor b strictly inside cd (orient(a, b, ·) is affine along cd, so at a point
    // of cd on the line ab its values at c and d have opposite signs or are zero). Likewise
    // with a and b strictly on one side of line cd.
    int o1 = orientAxisFirst(a, b, c), o2 = orientAxisFirst(a, b, d);
    if (o1 * o2 > 0) return;
    int o3 = orientAxisFirst(c, d, a), o4 = orientAxisFirst(c, d, b);
    if (o3 * o4 > 0) return;
    Index lo = std::min(e, f), hi = std::max(e, f);
    if (o1 * o2 < 0 && o3 * o4 < 0) {
        edgesCrossed = true;
        problemCulprits = {};
        problemCulprits.edges = {lo, hi};  // no exact double point: the viewer computes one
        problem.emplace(lo, "edge " + edgeText(lo) + " crosses edge " + edgeText(hi));
        return;
    }
    if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) {
        bool useX = a.x != b.x;
        auto key = [&](Point p) { return useX ? p.x : p.y; };
        double l = std::max(std::min(key(a), key(b)), std::min(key(c), key(d)));
        double h = std::min(std::max(key(a), key(b)), std::max(key(c), key(d)));
        if (l < h) problemCulprits = {}, problemCulprits.edges = {lo, hi};
        if (l < h)
            problem.emplace(lo,
                            "edge " + edgeText(lo) + " overlaps collinear edge " + edgeText(hi));
        return;
    }
    if (o1 == 0 && betweenOnLine(a, b, c)) touchOnEdge(f, e);
    else if (o2 == 0 && betweenOnLine(a, b, d)) touchOnEdge(next(f), e);
    else if (o3 == 0 && betweenOnLine(c, d, a)) touchOnEdge(e, f);
    else if (o4 == 0 && betweenOnLine(c, d, b)) touchOnEdge(next(e), f);
}

// `vertex` lies strictly inside `edge`: a touch between rings (a junction, checked in check 5),
// refused on its own ring or for a point.
void Validator::touchOnEdge(Index vertex, Index edge) {
    if (isPoint(vertex) || ringOfV[vertex] == ringOfV[edge])
        problemCulprits = atPoint(vertex, {edge});
    if (isPoint(vertex))
        problem.emplace(vertex, "point hole lies on edge " + edgeText(edge) +
                                    " (a Steiner point must be strictly inside the polygon)");
    else if (ringOfV[vertex] == ringOfV[edge])
        problem.emplace(vertex, "the ring touches itself here: the vertex lies on its own edge " +
                                    edgeText(edge) + " (a ring must be simple)");
    else junctions.push_back({edge, vertex});
}

// The sweep line's edges are kept in a sorted row up to this many (sweep_tree.h): a real
// coastline's line crosses few edges at a time (docs/BENCHMARKS.md, "Validation cost, round 4").
constexpr size_t kSweepRow = 64;

// The sweep: every pair of edges that become neighbours along the sweep line goes to
// classifyMeeting(); it stops at the first problem. Also fills enclosing[]. The full sweep
// also tests pairs that were neighbours already, around every ending edge: the order of its
// tests decides which of several problems is reported, so every message comes from it. The
// minimal one (`minimal`) tests only new neighbours where a lone vertex passes on or ends, and
// stops at the first problem, or where an edge placed without a comparison (beside a T-junction)
// is out of order: when it finds no problem there is none (Shamos-Hoey), and its tree, copies,
// T-junctions and enclosing[] are the full sweep's (the tree's shape is that of its order);
// otherwise checkEdges() runs the full sweep.
bool Validator::sweepEdges(bool minimal) {
    std::vector<Segment>& segs = s.segs;
    segs.resize(n);
    for (Index v = 0; v < n; ++v) {
        Index w = next(v);
        segs[v] = below(pt(v), pt(w)) ? Segment{v, w} : Segment{w, v};
    }
    // classifyMeeting(), skipped for edges whose boxes are apart (it would find nothing):
    // the box read off segs, without the ring lookups that edge ends cost there.
    const Point* V = P.vertices.data();
    auto meet = [&](Index e, Index f) {
        const Segment g = segs[e], h = segs[f];
        if (boxesApart(V[g.lo], V[g.hi], V[h.lo], V[h.hi])) ++work().validatorSteps;
        else classifyMeeting(e, f);
    };
    // The ring runs from lo to hi along edge e (false for a point hole).
    auto up = [&](Index e) { return segs[e].lo == e && segs[e].hi != e; };
    std::vector<Index>& events = s.events;
    sortVerticesBelow(P.vertices, s.keys, events, s.bucketStart);
    SweepTree<SweepOrder> active(n, SweepOrder{&segs, P.vertices.data()}, s.links, kSweepRow);
    enclosing.assign(P.rings.size(), kNone);
    std::vector<char>& ringSeen = s.ringSeen;
    ringSeen.assign(P.rings.size(), 0);
    std::vector<Index>&ending = s.ending, &starting = s.starting, &points = s.points,
    &newRings = s.newRings;
    std::vector<Index>& leftmostOf = s.leftmostOf;  // of each ring starting at the event
    leftmostOf.assign(P.rings.size(), kNone);
    // The ring whose interior holds what is just right of the active edge before `e`.
    auto enclosingAt = [&](Index e) {
        Index left = active.prev(e);
        if (left == kNone) return kNone;  // nothing to the left: outside everything
        Index tr = ringOfV[left];
        bool rightIsInside = up(left) ? ringSign[tr] < 0 : ringSign[tr] > 0;
        return rightIsInside ? tr : enclosing[tr];
    };
    Index lastPlaced = kNone;  // the minimal sweep's finger: an edge placed at the last event,
    double lastY = 0;          // whose height this is
    // The minimal sweep stops when an edge placed without a search turns out out of order.
    bool misplaced = false;
    auto inOrder = [&](Index a, Index b) {
        return a == kNone || b == kNone || active.less()(a, b);
    };
    for (size_t i = 0; i < n && !problem && !misplaced;) {
        size_t j = i;
        const size_t copiesBefore = copies.size();
        const Point p = s.keys[i].p;  // the sorted records: no read of the vertex array
        ending.clear(), starting.clear(), points.clear(), newRings.clear();
        for (; j < n && s.keys[j].p == p; ++j) {
            Index v = events[j];
            if (j > i) copies.emplace_back(events[i], v);
            Index r = ringOfV[v];
            if (isPoint(v)) {
                points.push_back(v);
                continue;
            }
            // An edge ends at p when v is its upper end (check 2 left no edge of zero length):
            // no read of the other end's point, which lies anywhere in memory.
            for (Index e : {prev(v), v}) (segs[e].hi == v ? ending : starting).push_back(e);
            if (!ringSeen[r]) ringSeen[r] = 1, newRings.push_back(r);  // 2 once placed
        }
        i = j;
        // The minimal sweep, at a lone vertex where the boundary passes on or ends: the tests of
        // the pairs that become neighbours (Shamos-Hoey), no more; anything else as below.
        if (minimal && points.empty() && copies.size() == copiesBefore) {
            if (ending.size() == 1 && starting.size() == 1) {
                // With no problem so far and no edge through p, f lies between e's neighbours:
                // it takes e's place without a comparison. An edge through p is a neighbour, and
                // f's test with it finds the T-junction: then f's place is checked.
                Index e = ending[0], f = starting[0];
                Index before = active.prev(e), after = active.next(e);
                const size_t found = junctions.size();
                active.replace(e, f);
                if (before != kNone) meet(f, before);
                if (after != kNone) meet(f, after);
                if (junctions.size() != found)
                    misplaced = !inOrder(before, f) || !inOrder(f, after);
                lastPlaced = f, lastY = p.y;
                continue;
            }
            if (ending.size() == 2 && starting.empty()) {
                Index e1 = ending[0], e2 = ending[1];
                Index before = active.prev(e1), after = active.next(e1);
                if (after == e2 || before == e2) {  // side by side, as they must be when clean
                    if (after == e2) after = active.next(e2);
                    else before = active.prev(e2);
                    active.erase(e1), active.erase(e2);
                    if (before != kNone && after != kNone) meet(before, after);
                    continue;
                }
            }
        }
        // A lone vertex where the boundary starts: its first edge by a search from the last
        // edge placed (events of one height come left to right), the second beside the first.
        bool placed = false;
        if (minimal && points.empty() && copies.size() == copiesBefore && ending.empty() &&
            starting.size() == 2) {
            Index e1 = starting[0], e2 = starting[1];
            if (lastPlaced != kNone && lastY == p.y && active.contains(lastPlaced))
                active.insertNear(e1, lastPlaced, 3);
            else active.insert(e1);
            const bool e2After = active.less()(e1, e2);
            active.insertBeside(e2, e1, e2After);
            const size_t found = junctions.size();
            for (Index e : {e1, e2}) {
                if (Index before = active.prev(e); before != kNone) meet(e, before);
                if (Index after = active.next(e); after != kNone) meet(e, after);
            }
            if (junctions.size() != found) {  // an edge through p: is e2 beside e1 after all?
                Index left = e2After ? e1 : e2, right = e2After ? e2 : e1;
                misplaced =
                    !inOrder(active.prev(left), left) || !inOrder(right, active.next(right));
            }
            lastPlaced = e1, lastY = p.y, placed = true;
        }
        bool handedOver = false;
        for (Index e : ending) {
            Index before = active.prev(e), after = active.next(e);
            if (before != kNone) meet(e, before);
            if (after != kNone) meet(e, after);
            // Where the boundary passes on, the last edge to end hands its place to the first
            // to start when that one lies between the same neighbours: two comparisons instead
            // of a search, the same tree, and the same tests in the same order.
            Index f = e == ending.back() && !starting.empty() ? starting[0] : kNone;
            handedOver = f != kNone && (before == kNone || active.less()(before, f)) &&
                         (after == kNone || active.less()(f, after));
            if (handedOver) active.replace(e, f);
            else active.erase(e);
            if (before != kNone && after != kNone) meet(before, after);
            if (handedOver && before != kNone) meet(f, before);
            if (handedOver && after != kNone) meet(f, after);
        }
        for (size_t k = placed ? starting.size() : handedOver ? 1 : 0; k < starting.size(); ++k) {
            Index e = starting[k];
            active.insert(e);
            if (Index before = active.prev(e); before != kNone) meet(e, before);
            if (Index after = active.next(e); after != kNone) meet(e, after);
        }
        // A point hole is an edge of no length: placed in the active edges for an instant,
        // its neighbours tell whether it lies on an edge and which ring encloses it.
        for (Index v : points) {
            active.insert(v);
            if (Index before = active.prev(v); before != kNone) meet(v, before);
            if (Index after = active.next(v); after != kNone) meet(v, after);
            enclosing[ringOfV[v]] = enclosingAt(v);
            active.erase(v);
        }
        if (problem) break;
        // Rings whose lowest vertex is p, left to right: the edge just left of a ring's
        // leftmost edge bounds the face the ring lies in.
        if (newRings.empty()) continue;
        for (Index e : starting) {
            ++work().validatorSteps;
            Index r = ringOfV[e], &best = leftmostOf[r];
            if (ringSeen[r] == 1 && (best == kNone || active.less()(e, best))) best = e;
        }
        std::vector<std::pair<Index, Index>>& leftmost = s.leftmost;  // (leftmost edge, ring)
        leftmost.clear();
        for (Index r : newRings) leftmost.emplace_back(leftmostOf[r], r), ringSeen[r] = 2;
        std::sort(leftmost.begin(), leftmost.end(),
                  [&](auto a, auto b) { return active.less()(a.first, b.first); });
        for (auto [e, r] : leftmost) enclosing[r] = enclosingAt(e);
    }
    return !problem && !misplaced;
}

// One junction per edge and point, ordered by edge, then along the edge from its start
// (the order the flood machine and the checker walk it in).
void Validator::orderJunctions() {
    std::sort(junctions.begin(), junctions.end(), [&](const EdgeSplit& s, const EdgeSplit& t) {
        if (s.edge != t.edge) return s.edge < t.edge;
        Point a = pt(s.edge), b = pt(next(s.edge)), p = pt(s.vertex), q = pt(t.vertex);
        if (p != q)
            return a.x != b.x ? (a.x < b.x ? p.x < q.x : p.x > q.x)
                              : (a.y < b.y ? p.y < q.y : p.y > q.y);
        return s.vertex < t.vertex;
    });
    junctions.erase(std::unique(junctions.begin(), junctions.end(),
                                [&](const EdgeSplit& s, const EdgeSplit& t) {
                                    return s.edge == t.edge && pt(s.vertex) == pt(t.vertex);
                                }),
                    junctions.end());
}

// Check 4 on a small polygon: every pair of edges whose boxes meet goes to classifyMeeting(),
// with no sort and no tree. When no pair shows anything (no problem, no vertex on another
// edge, no point twice), the sweep would find nothing either — its tests are these on fewer
// pairs — and the rings are disjoint closed curves: ringsApartNesting() nests them. Whatever a
// pair shows is forgotten and left to the sweep, whose order decides which problem is
// reported. Below kPairsUpTo vertices this costs fewer instructions than the sweep
// (docs/BENCHMARKS.md, "Validation cost"); a point hole (an edge of no extent) always sweeps.
constexpr size_t kPairsUpTo = 96;

bool Validator::pairsClear() {
    const Point* V = P.vertices.data();
    std::vector<EdgeBox>& boxes = s.boxes;  // each edge's box, computed once, not once a pair
    boxes.resize(n);
    for (Index e = 0; e < n; ++e) {
        Point a = V[e], b = V[next(e)];
        boxes[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    }
    for (Index e = 0; e < n; ++e) {
        const EdgeBox a = boxes[e];
        for (Index f = e + 1; f < n; ++f) {
            const EdgeBox& b = boxes[f];  // as boxesApart()
            if (a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0) continue;
            if (V[e] == V[f]) return false;  // a point twice: the rings touch there
            classifyMeeting(e, f);
            if (problem || !junctions.empty()) return false;
        }
    }
    return true;
}

// enclosing[] for rings that meet nowhere: a ring lies inside another exactly when its first
// vertex does (exact winding numbers), and the innermost of the rings around it is the one
// with the most rings around itself.
void Validator::ringsApartNesting() {
    const Index R = Index(P.rings.size());
    enclosing.assign(R, kNone);
    if (R == 1) return;
    std::vector<char>& around = s.ringSeen;  // around[r * R + t]: ring t winds around ring r
    around.assign(size_t(R) * R, 0);
    std::vector<Index>& depth = s.newRings;  // how many rings wind around each
    depth.assign(R, 0);
    for (Index r = 0; r < R; ++r) {
        const Point p = pt(P.rings[r].first);
        for (Index t = 0; t < R; ++t) {
            if (t == r) continue;
            const Ring& ring = P.rings[t];
            int winding = 0;
            for (Index v = ring.first; v < ring.first + ring.count; ++v) {
                const Point a = pt(v),
                            b = pt(v + 1 == ring.first + ring.count ? ring.first : v + 1);
                if (a.y <= p.y) {
                    if (b.y > p.y && orient(a, b, p) > 0) ++winding;  // upward, p on its left
                } else if (b.y <= p.y && orient(a, b, p) < 0) {
                    --winding;  // downward, p on its right
                }
            }
            if (winding != 0) around[size_t(r) * R + t] = 1, ++depth[r];
        }
    }
    for (Index r = 0; r < R; ++r)
        for (Index t = 0; t < R; ++t)
            if (around[size_t(r) * R + t] &&
                (enclosing[r] == kNone || depth[t] > depth[enclosing[r]]))
                enclosing[r] = t;
}

Diagnostic Validator::checkEdges() {
    if (pairsFirst && n <= kPairsUpTo &&
        std::none_of(P.rings.begin(), P.rings.end(), [](const Ring& r) { return r.count == 1; }) &&
        pairsClear()) {
        ringsApartNesting();
        return {};
    }
    if (pairsFirst) {
        if (sweepEdges(true)) {
            orderJunctions();
            return {};
        }
        copies.clear();
    }
    problem.reset(), problemCulprits = {}, edgesCrossed = false, junctions.clear();
    sweepEdges(false);
    if (problem) return fail(problem->first, problem->second, problemCulprits);
    orderJunctions();
    return {};
}
}  // namespace validate_detail
}  // namespace flood
