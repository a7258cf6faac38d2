// The validator's working state, shared by the files that hold its checks (internal to
// core/check; the public door is validate() and validateAll() in io/io.h). Where each check
// lives: validate.cpp (checks 1-3 and 6, the order they run in, the entry points),
// validate_edges.cpp (check 4: the sweep and the small-polygon pair test), validate_touches.cpp
// (check 5: rings meeting at a point), validate_all.cpp (every finding, for validateAll()),
// validate_groups.cpp (a MultiPolygon group by group).
#pragma once
#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "flood/io/io.h"
#include "geometry/number_text.h"
#include "geometry/sweep_tree.h"

namespace flood {
namespace validate_detail {

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
// A thread keeps one Scratch for polygons of up to this many vertices: at most a few MB.
constexpr size_t kReusedUpTo = 1 << 14;

struct Validator {
    const Polygon& P;
    const std::string& name;
    Scratch& s;
    std::vector<EdgeSplit>& junctions;  // vertex strictly inside another ring's edge (check 4)
    std::vector<EdgeSplit>& splits;     // the junctions within one part, for the machine
    std::optional<Index> zeroArea;      // first vertex of the first ring of zero area (check 3)
    bool edgesCrossed = false;          // check 4's problem is a crossing of two edges
    bool pairsFirst = true;  // shortcuts: pairsClear() on small polygons, the minimal sweep
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
    void ringsApartNesting();
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

// validate() on a MultiPolygon of at least kGroupsFrom vertices whose parts fall into groups
// apart (validate_groups.cpp): true when every group is valid, then the polygon's splits and
// pointsDistinct, and `enclosing` if given, are set as the whole polygon's validation sets
// them; false when there is one group, or a group is invalid (validate the whole polygon).
// Groups of up to kReusedUpTo vertices are validated in `reused`. With `run`, the groups are
// validated as kGroupTasks tasks (runs of groups of about equal size) given to it.
constexpr size_t kGroupsFrom = 64;
constexpr size_t kGroupTasks = 8;
bool validGroupByGroup(Polygon& polygon, const std::string& name, Scratch& reused,
                       std::vector<Index>* enclosing, const TaskRunner& run = {});

// --- exact geometric helpers -------------------------------------------------------------

// orient(), answered at once where the three points lie on one vertical or horizontal line,
// or two of them are one point: collinear exactly, a case the filter cannot decide (its
// determinant is zero), so orient() would go on to expansions. Orthogonal polygons make most
// of the validator's collinear triples; the two edges starting at a vertex, compared in the
// sweep, make the repeated points.
inline int orientAxisFirst(Point a, Point b, Point c) {
    if ((a.x == b.x && b.x == c.x) || (a.y == b.y && b.y == c.y)) return 0;
    if (c == a || c == b || a == b) return 0;
    return orient(a, b, c);
}

// insideSegment(a, b, c) for a c known to be collinear with a and b: the comparisons alone.
inline bool betweenOnLine(Point a, Point b, Point c) {
    if (c == a || c == b) return false;
    if (a.x != b.x) return (a.x < c.x && c.x < b.x) || (b.x < c.x && c.x < a.x);
    return (a.y < c.y && c.y < b.y) || (b.y < c.y && c.y < a.y);
}

// The closed bounding boxes of segments ab and cd do not meet: the segments cannot cross,
// overlap or touch. Comparisons only.
inline bool boxesApart(Point a, Point b, Point c, Point d) {
    return std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
           std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y);
}

// Half of the plane around p in which direction p->a lies: 0 for angles [0, pi), 1 for
// [pi, 2 pi). Exact: only comparisons.
inline int half(Point p, Point a) { return (a.y > p.y || (a.y == p.y && a.x > p.x)) ? 0 : 1; }

// Direction p->a comes before p->b counter-clockwise from the +x axis.
inline bool angleLess(Point p, Point a, Point b) {
    ++work().validatorSteps;
    int ha = half(p, a), hb = half(p, b);
    if (ha != hb) return ha < hb;
    return orientAxisFirst(p, a, b) > 0;
}

// The vertices in the order of below() on their points, ties by index (validate_edges.cpp).
void sortVerticesBelow(const std::vector<Point>& V, std::vector<EventKey>& keys,
                       std::vector<Index>& order, std::vector<Index>& start);

}  // namespace validate_detail
}  // namespace flood
