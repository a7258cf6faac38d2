// Validity of an input polygon, checked exactly before flooding (docs/ERRORS.md).
//
// Checks, in this order; the first failing check is reported, and within a check its first
// problem in a fixed order — by ring and vertex index (checks 1-3 and 6), the lowest along the
// sweep, where it stops (4), touching points by their coordinates (5) — so the message depends
// on the polygon alone, not on how coincident points are hashed:
//   1. every coordinate is finite;
//   2. every ring has at least 3 distinct points and no zero-length edge — except a hole of
//      exactly one point, a Steiner point the triangulation must use;
//   3. every ring has a non-zero signed area (exact: ring_area.h) — reported after check 4 has
//      looked for a crossing, so a symmetric bow-tie is called a self-crossing;
//   4. no two edges of the polygon (all parts) cross or overlap collinearly; a spike (an edge
//      folding back on the previous one) counts as an overlap. A vertex lying in the interior
//      of an edge of another ring is a touch (a T-junction), checked like a shared vertex in
//      check 5; between rings of one part it is also recorded in Polygon::splits (the loops
//      pass through it twice), between parts not (parts are flooded apart). On its own ring's
//      edge it is refused (a ring must be simple); a point hole may touch nothing;
//   5. where rings meet — a shared vertex (the same coordinates appear as a vertex more than
//      once) or a T-junction, of one part or of several — they touch without crossing: around
//      the point the wedges of the rings do not interleave and the interiors do not overlap;
//      and the touches keep each part's interior connected (no ring touching itself, no cycle
//      of touching rings of one part);
//   6. each hole lies inside its outer ring, and not inside another hole of its part
//      (with 4 and 5, this means hole interiors do not overlap); no outer ring lies inside
//      another part's outer ring (a part in another part's hole, an island in a lake, is fine).
// With 4 and 5, parts overlap only if one lies inside the other, which 6 finds: every overlap
// of parts is detected.
//
// All decisions use the exact flood::orient() and coordinate comparisons; no floating-point
// arithmetic decides anything. Cost: O(n log n) — a sort of the vertices for the sweep (which
// puts coincident vertices side by side, so no search finds them) and a sort of those, a treap
// sweep (sweep_tree.h) with O(1) tests per event, and at a point shared by k rings a sort of
// their 2k rays and O(log k) per ring to find a crossing (validatorSteps in core/geometry/work.h
// counts the work, tests/check/validate_growth_test.cpp bounds it). A small single ring is checked
// by testing its pairs of edges instead of sweeping (pairsClear()), with the sweep's verdicts
// (tests/check/validate_paths_test.cpp). The sweep itself runs first with only the tests
// Shamos-Hoey needs (sweepEdges(minimal)), and again with all of them, whose order fixes the
// message, only when that one finds a problem.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "check/validate_paths.h"
#include "geometry/predicates.h"
#include "geometry/ring_area.h"
#include "geometry/sweep_tree.h"
#include "geometry/work.h"
#include "io/io.h"
#include "io/io_util.h"

namespace flood {
namespace {

using io_detail::formatPoint;

// An edge as the sweep sees it: its lower and upper vertex (both the vertex of a point hole).
// Vertex indices, not points: 8 bytes an edge.
struct Segment {
    Index lo, hi;
};

// The closed bounding box of an edge.
struct EdgeBox {
    double x0, x1, y0, y1;
};

// A vertex as a sweep event: its point and index, so that sorting reads no other array.
struct EventKey {
    Point p;
    Index v;
};

// Where rings touch (check 5): every ring passing through one point, as the wedge of its
// two rays there. A vertex occurrence has owner = its vertex; a T-junction's edge has
// owner = n + its index in `junctions`. Each point's list is sorted by owner.
struct Occurrence {
    Index owner, ring;
    Point from, to;  // the ring arrives from `from` and leaves towards `to`
};

// Every array validation works in, kept between calls on one thread (validate() below) so that
// validating a small polygon allocates nothing once warm: on a 15-vertex polygon the dozens of
// allocations were most of the cost. Each user resets what it uses.
struct Scratch {
    std::vector<EdgeSplit> junctions, splits;
    std::vector<Index> ringOfV, partOfRing, enclosing, groupOf;
    std::vector<int> ringSign;
    std::vector<Point> ringPoints;  // check 2's distinct-point count
    std::vector<Segment> segs;
    std::vector<EdgeBox> boxes;  // pairsClear()'s
    std::vector<EventKey> keys;
    std::vector<Index> bucketStart;  // the event sort's buckets
    std::vector<Index> events, ending, starting, points, newRings, leftmostOf;
    std::vector<char> ringSeen;
    std::vector<std::pair<Index, Index>> leftmost, copies;
    SweepTreeLinks links;
    std::vector<std::vector<Occurrence>> touchPoints;
};

struct Validator {
    const Polygon& P;
    const std::string& name;
    Scratch& s;
    std::vector<EdgeSplit>& junctions;  // vertex strictly inside another ring's edge (check 4)
    std::vector<EdgeSplit>& splits;     // the junctions within one part, for the machine
    std::optional<Index> zeroArea;      // first vertex of the first ring of zero area (check 3)
    bool edgesCrossed = false;          // check 4's problem is a crossing of two edges
    bool pairsFirst = true;  // shortcuts: pairsClear() on small single rings, the minimal sweep
    size_t n = 0;
    std::vector<Index>& ringOfV;  // ring of each vertex
    std::vector<int>& ringSign;   // orientation of each ring: +1 counter-clockwise, -1 clockwise
    std::vector<Index>& partOfRing;
    // Vertices at one point, (the lowest one there, a later one), in the sweep's order: equal
    // points are neighbours in its sorted events, so no search is needed for them.
    std::vector<std::pair<Index, Index>>& copies;

    Validator(const Polygon& p, const std::string& nm, Scratch& scratch)
        : P(p),
          name(nm),
          s(scratch),
          junctions(scratch.junctions),
          splits(scratch.splits),
          n(p.vertices.size()),
          ringOfV(scratch.ringOfV),
          ringSign(scratch.ringSign),
          partOfRing(scratch.partOfRing),
          copies(scratch.copies),
          groupOf(scratch.groupOf),
          enclosing(scratch.enclosing),
          touchPoints(scratch.touchPoints) {
        junctions.clear(), splits.clear(), copies.clear(), touchPoints.clear();
    }

    Index next(Index v) const {
        const Ring& r = P.rings[ringOfV[v]];
        return v + 1 == r.first + r.count ? r.first : v + 1;
    }
    Index prev(Index v) const {
        const Ring& r = P.rings[ringOfV[v]];
        return v == r.first ? r.first + r.count - 1 : v - 1;
    }
    Point pt(Index v) const { return P.vertices[v]; }
    // A hole of a single point (a Steiner point): no edges, no area.
    bool isPoint(Index v) const { return P.rings[ringOfV[v]].count == 1; }

    // "ring R vertex V (x, y)" for global vertex v.
    std::string at(Index v) const {
        Index r = ringOfV[v];
        return "ring " + std::to_string(r) + " vertex " + std::to_string(v - P.rings[r].first) +
               " " + formatPoint(pt(v));
    }
    // Blames v (first), its ring, and whatever else `also` names; every vertex named adds
    // its ring, so the culprits are the ones the message names.
    Diagnostic fail(Index v, const std::string& reason, Culprits also = {}) const {
        Diagnostic d{Status::Invalid, name + ": " + at(v) + ": " + reason + " (global vertex " +
                                          std::to_string(v) + ")"};
        Culprits& c = d.culprits;
        c = std::move(also);
        c.vertices.insert(c.vertices.begin(), v);
        for (Index e : c.edges) c.vertices.push_back(e), c.vertices.push_back(next(e));
        for (Index u : c.vertices) c.rings.push_back(ringOfV[u]);
        for (auto* list : {&c.vertices, &c.rings, &c.edges}) {
            std::vector<uint32_t> seen;  // unique, first mention first
            for (uint32_t x : *list)
                if (std::find(seen.begin(), seen.end(), x) == seen.end()) seen.push_back(x);
            *list = std::move(seen);
        }
        return d;
    }
    Diagnostic emptyRing(Index r) const {
        Diagnostic d{Status::Invalid, name + ": ring " + std::to_string(r) +
                                          ": ring is empty, it needs at least 3 distinct points"};
        d.culprits.rings = {r};
        return d;
    }
    static Culprits ringsCulprits(std::vector<uint32_t> rings) {
        Culprits c;
        c.rings = std::move(rings);
        return c;
    }
    // The culprits of a vertex lying at its exact point (touches, spikes, vertices on edges).
    Culprits atPoint(Index v, std::vector<uint32_t> edges = {}) const {
        Culprits c;
        c.edges = std::move(edges);
        c.hasPoint = true;
        c.x = pt(v).x, c.y = pt(v).y;
        return c;
    }
    // "ring R edge A-B (x, y)-(x, y)" for the edge e -> next(e).
    std::string edgeText(Index e) const {
        Index r = ringOfV[e];
        return "ring " + std::to_string(r) + " edge " + std::to_string(e - P.rings[r].first) + "-" +
               std::to_string(next(e) - P.rings[r].first) + " " + formatPoint(pt(e)) + "-" +
               formatPoint(pt(next(e)));
    }

    // validateAll(): every finding goes to the sink and the checks go on; without a sink the
    // first problem ends validation.
    std::function<void(Diagnostic&&)> sink;
    // True when validation stops at `d`; else `d` has gone to the sink.
    bool stopAt(Diagnostic& d) {
        if (!sink) return true;
        sink(std::move(d));
        return false;
    }
    void index();  // ringOfV, partOfRing
    Diagnostic run();
    void collectAll(bool& complete);
    bool collectRingFindings();
    bool collectEdgeFindings(bool& complete);
    Diagnostic checkRings();
    Diagnostic checkEdges();        // sweepEdges(), then orderJunctions()
    bool sweepEdges(bool minimal);  // false: stopped at a problem (or by minimal's doubt)
    bool pairsClear();
    void classifyMeeting(Index e, Index f);
    void touchOnEdge(Index vertex, Index edge);
    void orderJunctions();
    std::optional<std::pair<Index, std::string>> problem;  // check 4's: vertex to report, reason
    Culprits problemCulprits;                              // and what else it names
    Diagnostic checkSharedVertices();
    Diagnostic checkTouchTopology();
    Diagnostic checkHoles();

    std::vector<Index>& groupOf;    // touch point (index into touchPoints) of each vertex, or kNone
    std::vector<Index>& enclosing;  // innermost ring whose interior contains each ring
    std::vector<std::vector<Occurrence>>& touchPoints;  // see Occurrence
    void collectTouchPoints();
    std::string occurrenceText(const Occurrence& o) const {
        return o.owner < n ? at(o.owner) : "edge " + edgeText(junctions[o.owner - n].edge);
    }
    // What occurrenceText names, added to c.
    void blame(Culprits& c, const Occurrence& o) const {
        if (o.owner < n) c.vertices.push_back(o.owner);
        else c.edges.push_back(junctions[o.owner - n].edge);
    }
};

// --- exact geometric helpers -------------------------------------------------------------

// orient(), answered at once where the three points lie on one vertical or horizontal line,
// or two of them are one point: collinear exactly, a case the filter cannot decide (its
// determinant is zero), so orient() would go on to expansions. Orthogonal polygons make most
// of the validator's collinear triples; the two edges starting at a vertex, compared in the
// sweep, make the repeated points.
int orientAxisFirst(Point a, Point b, Point c) {
    if ((a.x == b.x && b.x == c.x) || (a.y == b.y && b.y == c.y)) return 0;
    if (c == a || c == b || a == b) return 0;
    return orient(a, b, c);
}

// insideSegment(a, b, c) for a c known to be collinear with a and b: the comparisons alone.
bool betweenOnLine(Point a, Point b, Point c) {
    if (c == a || c == b) return false;
    if (a.x != b.x) return (a.x < c.x && c.x < b.x) || (b.x < c.x && c.x < a.x);
    return (a.y < c.y && c.y < b.y) || (b.y < c.y && c.y < a.y);
}

// The closed bounding boxes of segments ab and cd do not meet: the segments cannot cross,
// overlap or touch. Comparisons only.
bool boxesApart(Point a, Point b, Point c, Point d) {
    return std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
           std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y);
}

// Half of the plane around p in which direction p->a lies: 0 for angles [0, pi), 1 for
// [pi, 2 pi). Exact: only comparisons.
int half(Point p, Point a) { return (a.y > p.y || (a.y == p.y && a.x > p.x)) ? 0 : 1; }

// Direction p->a comes before p->b counter-clockwise from the +x axis.
bool angleLess(Point p, Point a, Point b) {
    ++work().validatorSteps;
    int ha = half(p, a), hb = half(p, b);
    if (ha != hb) return ha < hb;
    return orientAxisFirst(p, a, b) > 0;
}

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

// --- checks 1 to 3: coordinates and rings ------------------------------------------------

Diagnostic Validator::checkRings() {
    for (Index v = 0; v < n; ++v)
        if (!std::isfinite(pt(v).x) || !std::isfinite(pt(v).y))
            return fail(v, "coordinate is not a finite number");
    std::vector<Point>& tmp = s.ringPoints;
    for (Index r = 0; r < P.rings.size(); ++r) {
        const Ring& ring = P.rings[r];
        if (ring.count == 0) return emptyRing(r);
        bool outer = P.parts[partOfRing[r]].firstRing == r;
        if (ring.count == 1 && !outer) continue;  // a Steiner point
        // Three distinct points are usually among the first few: then nothing is sorted.
        const Point* q = P.vertices.data() + ring.first;
        Index second = 1;
        while (second < ring.count && q[second] == q[0]) ++second;
        Index third = second + 1;
        while (third < ring.count && (q[third] == q[0] || q[third] == q[second])) ++third;
        if (third >= ring.count) {
            tmp.assign(q, q + ring.count);
            std::sort(tmp.begin(), tmp.end(),
                      [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
            size_t distinct = std::unique(tmp.begin(), tmp.end()) - tmp.begin();
            if (distinct < 3)
                return fail(ring.first, "ring has " + std::to_string(distinct) + " distinct point" +
                                            (distinct == 1 ? "" : "s") + ", at least 3 are needed" +
                                            (outer ? "" : " (or exactly one, a point hole)"));
        }
        for (Index v = ring.first; v < ring.first + ring.count; ++v)
            if (pt(v) == pt(next(v)))
                return fail(v, "repeated consecutive point (zero-length edge)", atPoint(v, {v}));
    }
    ringSign.assign(P.rings.size(), 0);
    for (Index r = 0; r < P.rings.size(); ++r) {
        const Ring& ring = P.rings[r];
        if (ring.count == 1) continue;  // a point hole (an outer ring of one point failed above)
        ringSign[r] = ringAreaSign(P, ring.first, ring.count);
        if (ringSign[r] == 0 && !zeroArea) zeroArea = ring.first;
    }
    return {};
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
    SweepTree<SweepOrder> active(n, SweepOrder{&segs, P.vertices.data()}, s.links);
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

// Check 4 on a small single ring: every pair of edges whose boxes meet goes to
// classifyMeeting(), with no sort and no tree. When no pair shows anything (no problem, no
// vertex on another edge, no point twice), the sweep would find nothing either — its tests are
// these on fewer pairs — and a single ring encloses nothing and lies in nothing. Whatever a pair
// shows is forgotten and left to the sweep, whose order decides which problem is reported.
// Below kPairsUpTo vertices this costs fewer instructions than the sweep (docs/BENCHMARKS.md,
// "Validation cost").
constexpr size_t kPairsUpTo = 96;

bool Validator::pairsClear() {
    const Point* V = P.vertices.data();
    std::vector<EdgeBox>& boxes = s.boxes;  // each edge's box, computed once, not once a pair
    boxes.resize(n);
    for (Index e = 0; e < n; ++e) {
        Point a = V[e], b = V[e + 1 == n ? 0 : e + 1];
        boxes[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    }
    for (Index e = 0; e < n; ++e) {
        const EdgeBox a = boxes[e];
        for (Index f = e + 1; f < n; ++f) {
            const EdgeBox& b = boxes[f];  // as boxesApart()
            if (a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0) continue;
            if (V[e] == V[f]) return false;  // a point twice: the rings (here one) touch there
            classifyMeeting(e, f);
            if (problem || !junctions.empty()) return false;
        }
    }
    return true;
}

Diagnostic Validator::checkEdges() {
    if (pairsFirst && P.rings.size() == 1 && n <= kPairsUpTo && pairsClear()) {
        enclosing.assign(1, kNone);
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

// --- check 5: rings meeting at a point ---------------------------------------------------

// Groups the ring passages through each touching point: coincident vertices, plus the edge
// of every T-junction, which passes straight through its vertex's point. Then picks the
// machine's splits: a junction whose edge's part has a vertex at the point (the lowest one).
void Validator::collectTouchPoints() {
    // The repeated points (most inputs have none) in coordinate order (x, then y), each
    // point's vertices by index.
    std::sort(copies.begin(), copies.end(),
              [&](std::pair<Index, Index> a, std::pair<Index, Index> b) {
                  Point p = pt(a.first), q = pt(b.first);
                  if (p.x != q.x) return p.x < q.x;
                  if (p.y != q.y) return p.y < q.y;
                  return a.second < b.second;
              });
    groupOf.assign(n, kNone);
    auto vertexOccurrence = [&](Index v) {
        return Occurrence{v, ringOfV[v], pt(prev(v)), pt(next(v))};
    };
    for (size_t i = 0; i < copies.size();) {
        const Index first = copies[i].first, group = Index(touchPoints.size());
        groupOf[first] = group;
        std::vector<Occurrence> occ{vertexOccurrence(first)};
        for (; i < copies.size() && copies[i].first == first; ++i) {
            groupOf[copies[i].second] = group;
            occ.push_back(vertexOccurrence(copies[i].second));
        }
        touchPoints.push_back(std::move(occ));
    }
    for (Index k = 0; k < junctions.size(); ++k) {
        Index v = junctions[k].vertex, e = junctions[k].edge;
        if (groupOf[v] == kNone) {
            groupOf[v] = Index(touchPoints.size());
            touchPoints.push_back({vertexOccurrence(v)});
        }
        touchPoints[groupOf[v]].push_back({Index(n + k), ringOfV[e], pt(e), pt(next(e))});
    }
    // At most one edge passes through a point (two would cross: check 4), so this is linear.
    for (const EdgeSplit& j : junctions) {
        Index part = partOfRing[ringOfV[j.edge]];
        for (const Occurrence& o : touchPoints[groupOf[j.vertex]]) {
            ++work().validatorSteps;
            if (o.owner < n && partOfRing[o.ring] == part) {
                splits.push_back({j.edge, o.owner});
                break;
            }
        }
    }
}

// The lowest chord crossing another, of chords drawn between the two positions of each index
// in `chordAt` (2k positions round a circle, each index 0..k-1 twice), and the lowest chord it
// crosses; {kNone, kNone} when no two cross. Chord c spanning positions a0 < a1 crosses
// another exactly when a position strictly between holds a chord whose other end lies outside
// [a0, a1]: a range-minimum and a range-maximum query of the other ends, O(k log k) in all.
std::pair<Index, Index> lowestCrossingChords(const std::vector<Index>& chordAt) {
    size_t m = chordAt.size(), k = m / 2;
    std::vector<size_t> first(k, m), second(k, m), other(m);
    for (size_t i = 0; i < m; ++i) (first[chordAt[i]] == m ? first : second)[chordAt[i]] = i;
    for (size_t i = 0; i < m; ++i)
        other[i] = first[chordAt[i]] == i ? second[chordAt[i]] : first[chordAt[i]];
    // Bottom-up segment trees over the positions: leaves at m + i.
    std::vector<size_t> lo(2 * m), hi(2 * m);
    for (size_t i = 0; i < m; ++i) lo[m + i] = hi[m + i] = other[i];
    for (size_t i = m - 1; i > 0; --i) {
        lo[i] = std::min(lo[2 * i], lo[2 * i + 1]);
        hi[i] = std::max(hi[2 * i], hi[2 * i + 1]);
    }
    auto crossesSome = [&](size_t a0, size_t a1) {  // over positions (a0, a1)
        size_t least = m, most = 0;
        for (size_t l = a0 + 1 + m, r = a1 + m; l < r; l /= 2, r /= 2) {
            ++work().validatorSteps;
            if (l & 1) least = std::min(least, lo[l]), most = std::max(most, hi[l]), ++l;
            if (r & 1) --r, least = std::min(least, lo[r]), most = std::max(most, hi[r]);
        }
        return least < a0 || most > a1;
    };
    for (Index c = 0; c < k; ++c) {
        if (!crossesSome(first[c], second[c])) continue;
        for (Index d = 0; d < k; ++d) {
            ++work().validatorSteps;
            bool in0 = first[c] < first[d] && first[d] < second[c];
            bool in1 = first[c] < second[d] && second[d] < second[c];
            if (in0 != in1) return {c, d};
        }
    }
    return {kNone, kNone};
}

Diagnostic Validator::checkSharedVertices() {
    if (copies.empty() && junctions.empty()) return {};  // no rings meet: nothing to check
    collectTouchPoints();
    // Around each touching point, every passage contributes a wedge of two rays (to where it
    // comes from and goes to). The rings cross there exactly when two wedges interleave.
    struct Ray {
        Point to;
        Index occ;   // the passage (index into the point's list) whose wedge this ray bounds
        bool after;  // the polygon's interior lies just counter-clockwise of this ray
    };
    std::vector<Ray> rays;
    std::vector<Index> chordAt;
    for (const std::vector<Occurrence>& occ : touchPoints) {
        Point p = pt(occ[0].owner);
        bool pointHole = false;
        for (const Occurrence& o : occ)
            if (o.owner < n && isPoint(o.owner)) {
                const Occurrence& other = o.owner == occ[0].owner ? occ[1] : occ[0];
                Culprits c = atPoint(o.owner);
                blame(c, other);
                Diagnostic d = fail(o.owner,
                                    "point hole coincides with " + occurrenceText(other) +
                                        " (a Steiner point must be strictly inside the polygon)",
                                    c);
                if (stopAt(d)) return d;
                pointHole = true;
                break;
            }
        if (pointHole) continue;  // collecting: the wedges of a point hole mean nothing
        rays.clear();
        for (Index i = 0; i < occ.size(); ++i) {
            const Occurrence& o = occ[i];
            // Walking from -> p -> to, the ring's inside is on the left for a counter-clockwise
            // ring; the polygon's interior is the other side for a hole.
            bool nextAfter =
                (ringSign[o.ring] > 0) != (P.parts[partOfRing[o.ring]].firstRing != o.ring);
            rays.push_back({o.from, i, !nextAfter});
            rays.push_back({o.to, i, nextAfter});
        }
        std::sort(rays.begin(), rays.end(),
                  [&](const Ray& a, const Ray& b) { return angleLess(p, a.to, b.to); });
        // Messages name a vertex: the lowest one among the passages involved.
        auto vertexOf = [&](Index i) {
            Index owner = occ[i].owner;
            return owner < n ? owner : junctions[owner - n].vertex;
        };
        bool junction =
            std::any_of(occ.begin(), occ.end(), [&](const Occurrence& o) { return o.owner >= n; });
        const std::string here = junction ? "at this touching point" : "at this shared vertex";
        chordAt.clear();
        for (const Ray& r : rays) chordAt.push_back(r.occ);
        // The interleaving pair with the lowest passages (occ is sorted by owner), for a
        // stable message.
        auto [c, d] = lowestCrossingChords(chordAt);
        if (c != kNone) {
            Culprits also = atPoint(vertexOf(c));
            blame(also, occ[d]);
            Diagnostic found =
                fail(vertexOf(c),
                     "the boundary crosses itself " + here + " (" + occurrenceText(occ[d]) +
                         " passes through to the other side)",
                     also);
            if (stopAt(found)) return found;
            continue;  // collecting: one finding a point
        }
        // Sectors between consecutive rays must alternate interior / exterior; otherwise two
        // loops overlap here (a loop nested in another with the same orientation, a hole
        // nested in a hole, or a part touching another from inside).
        for (size_t i = 0; i < rays.size(); ++i) {
            ++work().validatorSteps;
            const Ray& a = rays[i];
            const Ray& b = rays[(i + 1) % rays.size()];
            if (a.after == b.after) {
                Index u = std::min(a.occ, b.occ), w = std::max(a.occ, b.occ);
                Culprits also = atPoint(vertexOf(u));
                if (u != w) blame(also, occ[w]);
                Diagnostic found =
                    fail(vertexOf(u),
                         "the interior overlaps itself " + here + " (" +
                             (u == w ? std::string("a ring") : occurrenceText(occ[w])) +
                             " touches here from the inside, with the "
                             "orientation of a nested loop or hole)",
                         also);
                if (stopAt(found)) return found;
                break;  // collecting: one finding a point
            }
        }
    }
    return checkTouchTopology();
}

// Touching is allowed only where it keeps the interior connected and every ring simple (as
// GEOS rules): a ring may not touch itself, and the rings of a part touching each other may not
// close a cycle (two rings touching twice, or three touching in a ring cut the interior in two).
// Rings of different parts may touch anywhere they do not cross (parts are flooded apart).
Diagnostic Validator::checkTouchTopology() {
    std::vector<Index> parent(P.rings.size());
    for (Index r = 0; r < parent.size(); ++r) parent[r] = r;
    auto find = [&](Index r) {
        while (parent[r] != r) r = parent[r] = parent[parent[r]];
        return r;
    };
    // Per point: where each ring passed (ringAt), and each part's first ring there (partRing),
    // valid while their stamp is the point's.
    std::vector<Index> ringStamp(P.rings.size(), kNone), ringAt(P.rings.size());
    std::vector<Index> partStamp(P.parts.size(), kNone), partRing(P.parts.size());
    for (Index t = 0; t < touchPoints.size(); ++t) {
        const std::vector<Occurrence>& occ = touchPoints[t];
        for (Index i = 0; i < occ.size(); ++i) {
            ++work().validatorSteps;
            const Occurrence& b = occ[i];
            Index at = b.owner < n ? b.owner : junctions[b.owner - n].vertex;
            if (ringStamp[b.ring] == t) {
                Culprits also = atPoint(at);
                blame(also, occ[ringAt[b.ring]]);
                Diagnostic d =
                    fail(at,
                         "the ring touches itself here (it also passes through " +
                             occurrenceText(occ[ringAt[b.ring]]) + "): a ring must be simple",
                         also);
                if (stopAt(d)) return d;
                continue;
            }
            ringStamp[b.ring] = t, ringAt[b.ring] = i;
            Index part = partOfRing[b.ring];
            if (partStamp[part] != t) {
                partStamp[part] = t, partRing[part] = b.ring;
                continue;
            }
            Index ra = find(partRing[part]), rb = find(b.ring);
            if (ra == rb) {
                Culprits also = atPoint(at);
                also.rings = {partRing[part], b.ring};
                Diagnostic d = fail(at,
                                    "rings touching here and elsewhere enclose part of the "
                                    "interior: the interior is disconnected",
                                    also);
                if (stopAt(d)) return d;
                continue;
            }
            parent[ra] = rb;
        }
    }
    return {};
}

// --- check 6: holes inside their outer ring, not inside each other -----------------------
// Uses enclosing[], the innermost ring whose interior contains each ring (from the sweep).

Diagnostic Validator::checkHoles() {
    for (Index r = 0; r < P.rings.size(); ++r) {
        const Part& part = P.parts[partOfRing[r]];
        Index outer = part.firstRing, e = enclosing[r];
        Index v = P.rings[r].first;
        auto sameHole = [&](Index x) {
            return x != kNone && partOfRing[x] == partOfRing[r] && x != outer;
        };
        Diagnostic d;
        if (r == outer) {
            if (e != kNone && P.parts[partOfRing[e]].firstRing == e)
                d = fail(v,
                         "outer ring " + std::to_string(r) + " lies inside the outer ring " +
                             std::to_string(e) + " of another part: parts overlap",
                         ringsCulprits({r, e}));
        } else if (e == outer) {
        } else if (sameHole(e)) {
            d = fail(v,
                     "hole (ring " + std::to_string(r) + ") lies inside another hole (ring " +
                         std::to_string(e) + "): holes overlap",
                     ringsCulprits({r, e}));
        } else {
            d = fail(v,
                     "hole (ring " + std::to_string(r) + ") lies outside its outer ring (ring " +
                         std::to_string(outer) + ")" +
                         (e == kNone ? std::string()
                                     : ", inside ring " + std::to_string(e) + " instead"),
                     ringsCulprits(e == kNone ? std::vector<uint32_t>{r, outer}
                                              : std::vector<uint32_t>{r, outer, e}));
        }
        if (!d.ok() && stopAt(d)) return d;
    }
    return {};
}

void Validator::index() {
    ringOfV.resize(n);
    partOfRing.resize(P.rings.size());
    for (Index k = 0; k < P.parts.size(); ++k)
        for (Index r = P.parts[k].firstRing; r < P.parts[k].firstRing + P.parts[k].ringCount; ++r)
            partOfRing[r] = k;
    for (Index r = 0; r < P.rings.size(); ++r)
        for (Index v = P.rings[r].first; v < P.rings[r].first + P.rings[r].count; ++v)
            ringOfV[v] = r;
}

Diagnostic Validator::run() {
    if (P.rings.empty()) return {Status::Invalid, name + ": polygon has no rings"};
    index();
    Diagnostic d = checkRings();
    if (d.ok()) d = checkEdges();
    // A ring of zero area is reported as such unless the sweep found it crossing itself (a
    // symmetric bow-tie): the crossing is the truth, zero area only its consequence.
    if (zeroArea && (d.ok() || !edgesCrossed)) d = fail(*zeroArea, "ring has zero area");
    if (d.ok()) d = checkSharedVertices();
    if (d.ok()) d = checkHoles();
    return d;
}

// --- every finding (validateAll) ----------------------------------------------------------
//
// The checks above stop at the first problem: past a crossing the sweep's order means nothing.
// Collecting goes check by check and stops after the first check that found anything, since
// each later check needs the earlier ones clean: checks 1-2 on every vertex and ring; check 4
// on every pair of edges whose boxes meet (a sweep over the boxes along x, no order needed);
// zero areas; then, on a polygon whose edges are clean, the sweep as validate() runs it and
// checks 5 and 6 going on past each finding.

// Checks 1-2 on every vertex and ring; true when something was found.
bool Validator::collectRingFindings() {
    bool found = false;
    for (Index v = 0; v < n; ++v)
        if (!std::isfinite(pt(v).x) || !std::isfinite(pt(v).y)) {
            sink(fail(v, "coordinate is not a finite number"));
            found = true;
        }
    if (found) return true;  // the rings' points are not yet points
    for (Index r = 0; r < P.rings.size(); ++r) {
        const Ring& ring = P.rings[r];
        if (ring.count == 0) {
            sink(emptyRing(r));
            found = true;
            continue;
        }
        bool outer = P.parts[partOfRing[r]].firstRing == r;
        if (ring.count == 1 && !outer) continue;
        std::vector<Point> pts(P.vertices.begin() + ring.first,
                               P.vertices.begin() + ring.first + ring.count);
        std::sort(pts.begin(), pts.end(),
                  [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        size_t distinct = std::unique(pts.begin(), pts.end()) - pts.begin();
        if (distinct < 3) {
            sink(fail(ring.first, "ring has " + std::to_string(distinct) + " distinct point" +
                                      (distinct == 1 ? "" : "s") + ", at least 3 are needed" +
                                      (outer ? "" : " (or exactly one, a point hole)")));
            found = true;
            continue;
        }
        for (Index v = ring.first; v < ring.first + ring.count; ++v)
            if (pt(v) == pt(next(v))) {
                sink(fail(v, "repeated consecutive point (zero-length edge)", atPoint(v, {v})));
                found = true;
            }
    }
    return found;
}

// Check 4 on every pair of edges whose boxes meet, by a sweep of the boxes along x; the
// findings in the order of the vertex each names. Gives up (`complete` false) past a work cap:
// long edges over many others make the pairs quadratic.
bool Validator::collectEdgeFindings(bool& complete) {
    std::vector<EdgeBox> box(n);
    std::vector<Index> order(n);
    for (Index e = 0; e < n; ++e) {
        Point a = pt(e), b = pt(next(e));
        box[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
        order[e] = e;
    }
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
        const double xa = box[a].x0, xb = box[b].x0;
        return xa < xb || (xa == xb && a < b);
    });
    std::vector<Diagnostic> found;
    const uint64_t cap = 64 * uint64_t(n) + (uint64_t(1) << 22);
    uint64_t pairs = 0;
    std::vector<Index> active;
    for (Index e : order) {
        const EdgeBox a = box[e];
        active.erase(
            std::remove_if(active.begin(), active.end(), [&](Index f) { return box[f].x1 < a.x0; }),
            active.end());
        for (Index f : active) {
            if (++pairs > cap) {
                complete = false;
                break;
            }
            if (box[f].y1 < a.y0 || a.y1 < box[f].y0) continue;
            classifyMeeting(std::min(e, f), std::max(e, f));
            if (!problem) continue;
            found.push_back(fail(problem->first, problem->second, problemCulprits));
            problem.reset(), problemCulprits = {};
        }
        if (!complete) break;
        active.push_back(e);
    }
    junctions.clear();
    std::stable_sort(found.begin(), found.end(), [](const Diagnostic& x, const Diagnostic& y) {
        return x.culprits.vertices[0] < y.culprits.vertices[0];
    });
    for (Diagnostic& d : found) sink(std::move(d));
    return !found.empty();
}

void Validator::collectAll(bool& complete) {
    if (P.rings.empty()) return;
    index();
    if (collectRingFindings()) return;
    checkRings();  // clean now: the rings' orientations and the first zero area
    bool crossed = collectEdgeFindings(complete);
    for (Index r = 0; r < P.rings.size(); ++r)
        if (P.rings[r].count > 1 && ringSign[r] == 0 && !crossed)
            sink(fail(P.rings[r].first, "ring has zero area"));
    if (crossed || !complete) return;
    // The edges are clean: the sweep gives the order, touches and nesting checks 5-6 read.
    problem.reset(), junctions.clear(), copies.clear();
    if (!checkEdges().ok()) return;  // cannot be: every pair was clean
    if (checkSharedVertices().ok()) checkHoles();
}

// Small polygons reuse this thread's scratch; a large one gets its own, freed on return, so
// that no thread keeps a large polygon's arrays (flooding comes next and needs the memory).
Diagnostic validateIn(Polygon& polygon, const std::string& name, bool pairsFirst,
                      std::vector<Index>* enclosing = nullptr) {
    constexpr size_t kReusedUpTo = 1 << 14;  // vertices: at most a few MB kept per thread
    thread_local Scratch reused;
    Scratch fresh;
    Validator v(polygon, name, polygon.vertices.size() <= kReusedUpTo ? reused : fresh);
    v.pairsFirst = pairsFirst;
    Diagnostic d = v.run();
    polygon.splits.assign(d.ok() ? v.splits.begin() : v.splits.end(), v.splits.end());
    polygon.pointsDistinct = d.ok() && v.touchPoints.empty();  // check 5 grouped every shared point
    if (enclosing)
        enclosing->assign(d.ok() ? v.enclosing.begin() : v.enclosing.end(), v.enclosing.end());
    return d;
}

}  // namespace

Diagnostic validateBySweep(Polygon& polygon, const std::string& name) {
    return validateIn(polygon, name, false);
}

Diagnostic validateNesting(Polygon& polygon, const std::string& name,
                           std::vector<Index>& enclosing) {
    return validateIn(polygon, name, true, &enclosing);
}

Diagnostic validate(Polygon& polygon, const std::string& name) {
    return validateIn(polygon, name, true);
}

Findings validateAll(const Polygon& polygon, const std::string& name, size_t maxFindings) {
    Polygon copy = polygon;
    return validateAll(polygon, name, validate(copy, name), maxFindings);
}

Findings validateAll(const Polygon& polygon, const std::string& name, Diagnostic first,
                     size_t maxFindings) {
    Findings out;
    if (first.ok()) return out;
    std::string verdict = first.message;
    out.list.push_back(std::move(first));
    Scratch fresh;
    Validator v(polygon, name, fresh);
    v.sink = [&](Diagnostic&& d) {
        if (d.message == verdict) return;  // listed first already
        if (out.list.size() < std::max<size_t>(1, maxFindings)) out.list.push_back(std::move(d));
        else ++out.omitted;
    };
    v.collectAll(out.complete);
    return out;
}

}  // namespace flood
