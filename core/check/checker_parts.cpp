// Rule 8 of the exact checker: triangles of different parts have disjoint interiors.
//
// Rules 1-7 prove that each part's triangles, all counter-clockwise, have exactly that part's
// boundary as their boundary, so the number of a part's triangles over a point is the winding
// number of the part's boundary there. Parts overlap exactly where the winding numbers of all
// parts sum to more than 1. A sweep finds out. Events are the edges' ends in lexicographic
// order (x, then y), as if the sweep line were turned slightly, so vertical edges need no
// special case. The sweep keeps the edges crossing the sweep line bottom to top, and for each
// the winding sum of the gap just above it: an edge directed from its lexicographically lower
// end has its part's interior above it (+1), the other way below (-1), so a gap's sum is the
// one below it plus the sign of the edge between them.
// The order is sound until two edges cross properly, and Shamos and Hoey's argument holds: the
// first proper crossing is between edges that were neighbours, so testing each new pair of
// neighbours finds it. Touching is not crossing: at a point where parts meet (a shared vertex,
// a vertex inside another part's edge, wedges fanned around one point) the edges ending there
// leave, the edges passing through are cut there, and they re-enter with the edges starting
// there in angular order, the winding sums of the new gaps counted up from the gap below the
// point. Collinear edges along the same stretch (parts touching along it) sort with the
// interior-below one first, so the count between them never exceeds the sums either side.
// Parts that a vertical or horizontal line sets apart from every other part overlap none and
// are left out of the sweep (on islands side by side, all of them); when the rest overlap,
// every part is swept, so the overlap reported is the whole sweep's first.
// This checker is an oracle: it uses only the polygon's vertices, its boundary edges and
// orient(), and deliberately neither calls nor shares code with core/check/validate.cpp; the
// one piece both use is the cut of boxes by lines (geometry/boxes_apart.h), tested alone.
#include "check/checker_parts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "geometry/boxes_apart.h"
#include "geometry/number_text.h"  // formatPoint: shortest round-trip

namespace flood {

namespace {

bool lexLess(Point p, Point q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }

// An edge by its ends' vertex indices, its points read from the polygon: 16 bytes, where
// the points themselves took 48 (with the edge's ends for messages) and were the checker's
// peak on polygons of many parts.
struct Segment {
    Index lo, hi;  // the lexicographically lower and higher end
    Index part;
    int sign;  // +1: the part's interior lies above the edge (lo is its start); -1: below
    Index a() const { return sign > 0 ? lo : hi; }  // the directed boundary edge, for messages
    Index b() const { return sign > 0 ? hi : lo; }
};

// The sweep's edges and the points their ends index.
struct Edges {
    const std::vector<Point>& V;
    std::vector<Segment> segs;
    Point lo(Index s) const { return V[segs[s].lo]; }
    Point hi(Index s) const { return V[segs[s].hi]; }
    int orientTo(Index s, Point p) const { return orient(lo(s), hi(s), p); }
    // Where t lies relative to s's line: from t's start, or along t when t starts on that
    // line. +1 above, -1 below, 0 collinear.
    int side(Index s, Index t) const {
        int o = orientTo(s, lo(t));
        return o != 0 ? o : orientTo(s, hi(t));
    }
    // The two edges cross at a single point inside both.
    bool crossProperly(Index s, Index t) const {
        int o1 = orientTo(s, lo(t)), o2 = orientTo(s, hi(t));
        if (o1 == 0 || o2 == 0 || o1 == o2) return false;
        int o3 = orientTo(t, lo(s)), o4 = orientTo(t, hi(s));
        return o3 != 0 && o4 != 0 && o3 != o4;
    }
};

struct At {
    Point p;  // a lookup key: the event point
};

// Bottom-to-top order of edges crossing the sweep line at once (so the later start lies
// within the other edge's span), and of such edges against the event point.
struct Below {
    using is_transparent = void;
    const Edges* edges;
    bool operator()(Index i, Index j) const {
        if (i == j) return false;
        const Edges& e = *edges;
        int o = lexLess(e.lo(j), e.lo(i)) ? -e.side(j, i) : e.side(i, j);  // > 0: j above i
        if (o != 0) return o > 0;
        const Segment &s = e.segs[i], &t = e.segs[j];
        return s.sign != t.sign ? s.sign < t.sign : i < j;  // collinear: interior-below first
    }
    bool operator()(Index i, At k) const { return edges->orientTo(i, k.p) > 0; }
    bool operator()(At k, Index i) const { return edges->orientTo(i, k.p) < 0; }
};

std::string edgeName(const Segment& s) {
    std::ostringstream o;
    o << "edge (" << s.a() << ", " << s.b() << ") of part " << s.part;
    return o.str();
}

std::string vertexName(const std::vector<Point>& V, Index v) {
    return "vertex " + std::to_string(v) + " " + formatPoint(V[v]);
}

PartsOverlap crossing(const Segment& s, const Segment& t, const std::string& where) {
    return {"parts-overlap: " + edgeName(s) + " crosses " + edgeName(t) + where,
            {s.a(), s.b(), t.a(), t.b()},
            {s.part, t.part}};
}

// The sweep over `edges` (the header comment): the first overlap found, or none.
PartsOverlap sweep(Edges& edges) {
    const std::vector<Point>& V = edges.V;
    std::vector<Segment>& segs = edges.segs;
    // An edge's end: its vertex, the edge and whether it starts there in one word (8 bytes;
    // the sort reads the point through the vertex).
    struct End {
        Index vertex;
        uint32_t segAndStart;  // seg << 1 | start
        Index seg() const { return segAndStart >> 1; }
        bool start() const { return segAndStart & 1; }
    };
    std::vector<End> ends;
    ends.reserve(2 * segs.size());
    for (Index s = 0; s < segs.size(); ++s) {
        ends.push_back({segs[s].lo, s << 1 | 1});
        ends.push_back({segs[s].hi, s << 1});
    }
    std::sort(ends.begin(), ends.end(),
              [&V](const End& e, const End& f) { return lexLess(V[e.vertex], V[f.vertex]); });

    using Status = std::set<Index, Below>;
    Status status(Below{&edges});
    std::vector<int> above(segs.size(), 0);  // winding sum of the gap just above each edge
    std::vector<Index> fan;                  // the edges leaving the event point
    auto overlapAbove = [&](Status::iterator top, Index vertex) {
        std::map<Index, int> winding;  // per part, of the gap above `top`: only on failure
        for (auto it = status.begin();; ++it) {
            winding[segs[*it].part] += segs[*it].sign;
            if (it == top) break;
        }
        std::vector<Index> covering;
        for (auto [part, w] : winding)
            if (w > 0) covering.push_back(part);
        std::ostringstream o;
        if (covering.size() >= 2)
            o << "parts-overlap: parts " << covering[0] << " and " << covering[1] << " overlap";
        else
            o << "parts-overlap: part " << (covering.empty() ? kNone : covering[0])
              << " covers an area twice";
        o << " beside " << vertexName(V, vertex);
        return PartsOverlap{o.str(), {vertex}, covering};
    };
    for (size_t e0 = 0, e1; e0 < ends.size(); e0 = e1) {
        const Point p = V[ends[e0].vertex];
        const Index vertex = ends[e0].vertex;
        fan.clear();
        for (e1 = e0; e1 < ends.size() && V[ends[e1].vertex] == p; ++e1)
            if (ends[e1].start()) fan.push_back(ends[e1].seg());
        // The edges at p, contiguous in the status: those ending there, and those passing
        // through, to be cut at p.
        const size_t starting = fan.size();
        auto first = status.lower_bound(At{p}), last = first;
        for (; last != status.end() && edges.orientTo(*last, p) == 0; ++last) {
            ++work().checkerSteps;
            if (edges.hi(*last) != p) fan.push_back(*last);
        }
        // Edges passing through one point cross there unless they are collinear.
        for (size_t k = starting + 1; k < fan.size(); ++k) {
            if (edges.orientTo(fan[k - 1], edges.hi(fan[k])) != 0)
                return crossing(segs[fan[k - 1]], segs[fan[k]], " at " + vertexName(V, vertex));
        }
        int count = first == status.begin() ? 0 : above[*std::prev(first)];
        status.erase(first, last);
        std::sort(fan.begin(), fan.end(), status.key_comp());
        const auto next = last;  // the first edge above p
        auto lowest = next;      // the lowest edge of the fan once inserted
        for (size_t k = 0; k < fan.size(); ++k) {
            ++work().checkerSteps;
            auto it = status.insert(next, fan[k]);
            if (k == 0) lowest = it;
        }
        for (auto it = lowest; it != next; ++it) {
            count += segs[*it].sign;
            above[*it] = count;
            if (count > 1) return overlapAbove(it, vertex);
        }
        // New neighbours: below and above the fan (inside it, edges meet only at p).
        for (auto upper : {lowest, next})
            if (upper != status.begin() && upper != status.end() &&
                edges.crossProperly(*std::prev(upper), *upper))
                return crossing(segs[*std::prev(upper)], segs[*upper], "");
    }
    return {};
}

// The parts that a vertical or horizontal line sets apart from every other part
// (geometry/boxes_apart.h) overlap none: their edges need not be swept. Empty: none known.
std::vector<char> partsAlone(const std::vector<Point>& V, const std::vector<Index>& partOfVertex,
                             const std::vector<BoundaryEdge>& boundary) {
    Index parts = 0;
    for (const BoundaryEdge& e : boundary) {
        const Index part = partOfVertex[e.a];
        if (part == kNone) return {};  // in no part (rule 2 refuses it): no shortcut
        parts = std::max(parts, part + 1);
    }
    std::vector<Box> boxes(parts);
    for (const BoundaryEdge& e : boundary) boxes[partOfVertex[e.a]].add(V[e.a]);
    size_t groupCount = 0;
    std::vector<Index> groupOf = groupsApart(boxes, groupCount);
    std::vector<Index> size(groupCount, 0);
    for (Index g : groupOf) ++size[g];
    std::vector<char> alone(parts);
    for (Index k = 0; k < parts; ++k) alone[k] = size[groupOf[k]] == 1;
    return alone;
}

}  // namespace

PartsOverlap partsOverlap(const std::vector<Point>& V, const std::vector<Index>& partOfVertex,
                          std::vector<BoundaryEdge> boundary) {
    for (Index v = 0; v < V.size(); ++v)
        if (!std::isfinite(V[v].x) || !std::isfinite(V[v].y))
            return {"non-finite-coordinate: " + vertexName(V, v) + " cannot be swept", {v}, {}};
    // The edges of the parts that are not alone, or of every part.
    const std::vector<char> alone = partsAlone(V, partOfVertex, boundary);
    auto edgesOf = [&](bool all) {
        Edges edges{V, {}};
        if (all) edges.segs.reserve(boundary.size());
        for (const BoundaryEdge& e : boundary) {
            Point pa = V[e.a], pb = V[e.b];
            if (pa == pb) continue;  // no extent, no side (rule 3 already refuses such edges)
            if (!all && alone[partOfVertex[e.a]]) continue;
            bool up = lexLess(pa, pb);
            edges.segs.push_back({up ? e.a : e.b, up ? e.b : e.a, partOfVertex[e.a], up ? 1 : -1});
        }
        return edges;
    };
    // Sweep only the parts not alone; if those overlap, sweep them all, so that the overlap
    // reported is the one the whole sweep meets first.
    if (std::find(alone.begin(), alone.end(), 1) != alone.end()) {
        Edges crowded = edgesOf(false);
        if (crowded.segs.empty() || sweep(crowded).reason.empty()) return {};
    }
    Edges edges = edgesOf(true);
    boundary = {};
    return sweep(edges);
}

}  // namespace flood
