// The exact triangulation checker. It is the oracle of every test and of `flood triangulate`'s
// own check, so it deliberately shares no code with what it checks: not the ring orientation
// (ring_area.h's ringOrientation, ringAreaSign) nor the search for coincident points
// (coincident.h) that the machine, validation, the triangle count and the viewer use, only the
// exact predicates and sums (predicates.h, AreaEstimate). A bug in a shared facility must not
// hide in both: the checker stays a separate oracle.
// Rules, checked in this order (the first broken one is reported, naming the rule, the
// triangle number and the vertex indices, and the rule as data: CheckResult::rule):
//   0. every ring has 3 vertices or more (a hole may be a single point), the vertex count fits
//      32-bit indices, and (checked where rule 5 orients the rings) no ring has zero area;
//   1. every triangle index is in range;
//   2. the three vertices of a triangle belong to one part; per part, the triangle count is
//      n + 2h - 2 - 2d - j - p (n vertices, h holes, d = vertices whose point repeats an
//      earlier vertex of the part: by Euler's formula F = 2V - n - 2*chi with V = n - d
//      distinct points and chi = 1 - h, so each point where rings touch removes two
//      triangles; j T-junctions, each a boundary node more at a point already counted; p holes
//      that are single points, which add two triangles where a ring of one vertex would add 3);
//   3. every triangle is counter-clockwise and non-degenerate (exact orient > 0);
//   4. no directed edge appears in two triangles;
//   5. every boundary edge, directed with the interior on its left (outer ring
//      counter-clockwise, holes clockwise, whatever the input orientation), appears exactly once
//      as a directed triangle edge, and its reverse never; an edge with T-junctions
//      (Polygon::splits, each checked to lie strictly inside its edge) counts as its pieces;
//   6. every other directed triangle edge (a, b) has its twin (b, a) in another triangle;
//   7. the sum of the doubled triangle areas equals the doubled polygon area (implied by 3-6;
//      checked in doubles with proven error bounds, so it refuses only a certain mismatch);
//   8. with more than one part, triangles of different parts have disjoint interiors (rules
//      1-7 see one part at a time: overlapping parts would pass them; checker_parts.cpp).
// Vertex identity is by index: coincident copies of a point are different vertices, and a
// triangle may use any copy of its part. Edges, however, are matched through a canonical copy
// (the lowest index of the part with the same coordinates): where a hole touches the outer ring at a point, each wedge
// of interior around that point is bounded by one edge of each ring, so its fan of triangles
// must meet both copies' edges. Without repeated coordinates this is plain index identity.
// Rules 1-7 take linear time but for sorting each vertex's few outgoing edges (EdgeLists, 4
// bytes an edge); rule 8 is a sweep, O(n log n), skipped for a single part.
#include "flood/check/checker.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "check/checker_parts.h"
#include "flood/geometry/predicates.h"
#include "flood/geometry/ring_area.h"  // AreaEstimate only

namespace flood {

namespace {

// The directed triangle edges, grouped by their start: the ends of the edges leaving vertex a
// are to[at[a], at[a + 1]), sorted. 4 bytes an edge and 4 a vertex — a hash table of edges
// took 36 bytes an edge and was the peak memory of `flood triangulate`. Lookups are binary
// searches in one vertex's short list.
class EdgeLists {
public:
    EdgeLists(size_t n, const std::vector<Triangle>& triangles, const std::vector<Index>& C)
        : at_(n + 1, 0), to_(triangles.size() * 3) {
        for (const Triangle& tri : triangles)
            for (Index v : tri) ++at_[C[v] + 1];
        for (size_t a = 0; a < n; ++a) at_[a + 1] += at_[a];
        std::vector<uint32_t> fill(at_.begin(), at_.end() - 1);
        for (const Triangle& tri : triangles)
            for (int k = 0; k < 3; ++k) to_[fill[C[tri[k]]]++] = C[tri[(k + 1) % 3]];
        fill = {};
        // A list is a vertex's few outgoing edges, sorted by insertion; a long one (a fan)
        // by std::sort, so a vertex of high degree costs no quadratic time.
        for (size_t a = 0; a < n; ++a) {
            const uint32_t first = at_[a], last = at_[a + 1];
            if (last - first > 16) {
                std::sort(to_.begin() + first, to_.begin() + last);
                continue;
            }
            for (uint32_t i = first + 1; i < last; ++i)
                for (uint32_t j = i; j > first && to_[j - 1] > to_[j]; --j)
                    std::swap(to_[j - 1], to_[j]);
        }
        used_.assign(to_.size(), false);
    }
    // A directed edge in two triangles: two equal ends in one list.
    bool anyTwice() const {
        for (size_t a = 0; a + 1 < at_.size(); ++a)
            for (uint32_t i = at_[a]; i + 1 < at_[a + 1]; ++i)
                if (to_[i] == to_[i + 1]) return true;
        return false;
    }
    // The edge's slot, or kNone.
    uint32_t find(Index a, Index b) const {
        auto first = to_.begin() + at_[a], last = to_.begin() + at_[a + 1];
        auto it = std::lower_bound(first, last, b);
        return it != last && *it == b ? uint32_t(it - to_.begin()) : kNone;
    }
    bool contains(Index a, Index b) const { return find(a, b) != kNone; }
    // Boundary edges are marked on their slot (rule 5), so rule 6 knows them.
    bool marked(uint32_t slot) const { return used_[slot]; }
    void mark(uint32_t slot) { used_[slot] = true; }
    // Rule 6 over the lists themselves: every unmarked edge (a, b) has its twin (b, a). One
    // search an edge, where going through the triangles needs two (the edge's own slot too).
    bool allTwinned() const {
        for (size_t a = 0; a + 1 < at_.size(); ++a)
            for (uint32_t i = at_[a]; i < at_[a + 1]; ++i)
                if (!used_[i] && !contains(to_[i], Index(a))) return false;
        return true;
    }

private:
    std::vector<uint32_t> at_, to_;
    std::vector<bool> used_;
};

inline uint64_t edgeKey(Index a, Index b) { return (uint64_t(a) << 32) | b; }

// canonical[v] = the lowest index of the same part whose point equals vertex v's point
// (0.0 == -0.0).
std::vector<Index> canonicalVertices(const std::vector<Point>& V, const std::vector<Index>& part) {
    size_t cap = 16;
    while (cap < V.size() * 2) cap <<= 1;
    // A slot holds a vertex and 32 bits of its hash: a probe compares points only where
    // the hashes agree, so passing an occupied slot costs no look-up in V (a cache miss).
    const uint64_t kEmpty = ~uint64_t(0);
    std::vector<uint64_t> slots(cap, kEmpty);
    std::vector<Index> canonical(V.size());
    auto hash = [&](Index v) {
        return pointHash(V[v]) ^ uint64_t(part[v]) * 0x94d049bb133111ebULL;
    };
    // The slots are looked at in random order: ask for a later vertex's slot ahead of time.
    constexpr Index kAhead = 16;
    for (Index v = 0; v < V.size(); ++v) {
        if (v + kAhead < V.size()) __builtin_prefetch(&slots[hash(v + kAhead) & (cap - 1)]);
        const uint64_t h = hash(v), tag = h >> 32;
        for (size_t i = h & (cap - 1);; i = (i + 1) & (cap - 1)) {
            if (slots[i] == kEmpty) {
                slots[i] = tag << 32 | v;
                canonical[v] = v;
                break;
            }
            const Index w = Index(slots[i]);
            if (slots[i] >> 32 == tag && V[w] == V[v] && part[w] == part[v]) {
                canonical[v] = w;
                break;
            }
        }
    }
    return canonical;
}

CheckResult fail(CheckRule rule, const std::string& s, std::vector<uint32_t> triangles = {},
                 std::vector<uint32_t> vertices = {}, std::vector<uint32_t> rings = {}) {
    CheckResult r{false, s, {}, rule};
    r.culprits.triangles = std::move(triangles);
    r.culprits.vertices = std::move(vertices);
    r.culprits.rings = std::move(rings);
    return r;
}
const CheckResult kPass{true, "", {}, CheckRule::None};

std::string triName(size_t t, const Triangle& tri) {
    std::ostringstream o;
    o << "triangle " << t << " (" << tri[0] << ", " << tri[1] << ", " << tri[2] << ")";
    return o.str();
}

// Rule 3: counter-clockwise and non-degenerate. Indices out of range are rule 1's.
CheckResult counterClockwise(const std::vector<Point>& V, const std::vector<Triangle>& triangles) {
    for (size_t t = 0; t < triangles.size(); ++t) {
        const Triangle& tri = triangles[t];
        if (tri[0] >= V.size() || tri[1] >= V.size() || tri[2] >= V.size()) continue;
        int o = orient(V[tri[0]], V[tri[1]], V[tri[2]]);
        if (o == 0)
            return fail(CheckRule::CounterClockwise,
                        "degenerate-triangle: " + triName(t, tri) + " has zero area", {uint32_t(t)},
                        {tri[0], tri[1], tri[2]});
        if (o < 0)
            return fail(CheckRule::CounterClockwise,
                        "clockwise-triangle: " + triName(t, tri) + " is clockwise", {uint32_t(t)},
                        {tri[0], tri[1], tri[2]});
    }
    return kPass;
}

// One function per rule, run in order; each leaves behind what later rules use.
struct Checker {
    const Polygon& polygon;
    const std::vector<Triangle>& triangles;
    const std::vector<Point>& V = polygon.vertices;
    const size_t n = polygon.vertices.size();
    std::vector<Index> partOfRing, partOfVertex;
    std::vector<Index> C;            // canonical copy of each vertex (see the top)
    std::optional<EdgeLists> edges;  // rule 4 on
    std::vector<char> forwardRing;   // the ring's own direction has the interior on its left
    AreaEstimate polygonArea;        // doubled, rule 7
    AreaEstimate triangleArea;       // doubled, rule 7 (checkTriangles)

    Checker(const Polygon& p, const std::vector<Triangle>& t) : polygon(p), triangles(t) {}

    bool isPointHole(Index r) const {
        return polygon.rings[r].count == 1 && partOfRing[r] != kNone &&
               polygon.parts[partOfRing[r]].firstRing != r;
    }

    // The directed boundary edges, in ring order: each ring edge, cut at its T-junctions, with
    // the interior on its left. `visit` returns false to stop.
    template <typename Visit>
    void eachBoundaryEdge(Visit&& visit) const {
        auto split = polygon.splits.begin();
        for (Index r = 0; r < polygon.rings.size(); ++r) {
            const Ring& ring = polygon.rings[r];
            if (isPointHole(r)) continue;
            const bool forward = forwardRing[r];
            for (Index i = 0; i < ring.count; ++i) {
                const Index edge = ring.first + i, to = ring.first + (i + 1) % ring.count;
                Index from = edge;
                while (split != polygon.splits.end() && split->edge < edge) ++split;
                for (; split != polygon.splits.end() && split->edge == edge; ++split) {
                    if (!visit(forward ? BoundaryEdge{from, split->vertex, r}
                                       : BoundaryEdge{split->vertex, from, r}))
                        return;
                    from = split->vertex;
                }
                if (!visit(forward ? BoundaryEdge{from, to, r} : BoundaryEdge{to, from, r})) return;
            }
        }
    }

    // Rule 0: rings long enough to judge, indices that fit; ring -> part and vertex -> part
    // (vertices are stored ring by ring).
    CheckResult rings() {
        if (n >= kNone)
            return fail(CheckRule::Rings, "polygon: too many vertices for 32-bit indices");
        partOfRing.assign(polygon.rings.size(), kNone);
        for (Index p = 0; p < polygon.parts.size(); ++p) {
            const Part& part = polygon.parts[p];
            for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
                partOfRing[r] = p;
        }
        partOfVertex.assign(n, kNone);
        for (Index r = 0; r < polygon.rings.size(); ++r) {
            const Ring& ring = polygon.rings[r];
            if (ring.count < 3 && !isPointHole(r)) {
                std::ostringstream o;
                o << "ring-too-short: ring " << r << " has " << ring.count << " vertices";
                return fail(CheckRule::Rings, o.str(), {}, {}, {r});
            }
            for (Index i = 0; i < ring.count; ++i) partOfVertex[ring.first + i] = partOfRing[r];
        }
        return kPass;
    }

    // Rule 1: indices in range.
    CheckResult indices() {
        for (size_t t = 0; t < triangles.size(); ++t)
            for (Index v : triangles[t])
                if (v >= n) {
                    std::ostringstream o;
                    o << "index-out-of-range: " << triName(t, triangles[t]) << " uses vertex " << v
                      << " but the polygon has " << n << " vertices";
                    return fail(CheckRule::Indices, o.str(), {uint32_t(t)});
                }
        return kPass;
    }

    // Rule 2: one part per triangle, and the count per part.
    CheckResult partsAndCount() {
        C = canonicalVertices(V, partOfVertex);
        std::vector<size_t> countOfPart(polygon.parts.size(), 0);
        for (size_t t = 0; t < triangles.size(); ++t) {
            const Triangle& tri = triangles[t];
            Index p = partOfVertex[tri[0]];
            if (p == kNone || partOfVertex[tri[1]] != p || partOfVertex[tri[2]] != p)
                return fail(
                    CheckRule::PartsAndCount,
                    "mixed-parts: " + triName(t, tri) + " has vertices from different parts",
                    {uint32_t(t)}, {tri[0], tri[1], tri[2]});
            countOfPart[p]++;
        }
        std::vector<size_t> copiesOfPart(polygon.parts.size(), 0);  // d: repeated points per part
        for (Index v = 0; v < n; ++v)
            if (C[v] != v) copiesOfPart[partOfVertex[v]]++;
        // j + p: T-junctions and point holes per part. A split must lie strictly inside its edge.
        std::vector<size_t> lessOfPart(polygon.parts.size(), 0);
        for (const EdgeSplit& sp : polygon.splits) {
            Index b = kNone;  // where the split edge ends
            if (sp.edge < n && sp.vertex < n) {
                const Ring& ring = polygon.rings[polygon.ringOf(sp.edge)];
                b = sp.edge + 1 == ring.first + ring.count ? ring.first : sp.edge + 1;
            }
            if (b == kNone || partOfVertex[sp.vertex] != partOfVertex[sp.edge] ||
                !insideSegment(V[sp.edge], V[b], V[sp.vertex])) {
                std::ostringstream o;
                o << "bad-split: vertex " << sp.vertex << " does not lie strictly inside edge ("
                  << sp.edge << ", " << b << ")";
                return fail(CheckRule::PartsAndCount, o.str(), {}, {sp.vertex});
            }
            lessOfPart[partOfVertex[sp.edge]]++;
        }
        for (Index r = 0; r < polygon.rings.size(); ++r)
            if (isPointHole(r)) lessOfPart[partOfRing[r]]++;
        for (Index p = 0; p < polygon.parts.size(); ++p) {
            const Part& part = polygon.parts[p];
            size_t verts = 0;
            for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
                verts += polygon.rings[r].count;
            size_t d = copiesOfPart[p];
            size_t expected = verts + 2 * (part.ringCount - 1) - 2 - 2 * d - lessOfPart[p];
            if (countOfPart[p] != expected) {
                std::ostringstream o;
                o << "triangle-count: part " << p << " has " << countOfPart[p]
                  << " triangles, expected n + 2h - 2 - 2d - j - p = " << expected
                  << " (n = " << verts << ", h = " << part.ringCount - 1 << ", d = " << d
                  << " repeated points, j + p = " << lessOfPart[p]
                  << " T-junctions and point holes)";
                std::vector<uint32_t> rings;  // the part's
                for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
                    rings.push_back(r);
                return fail(CheckRule::PartsAndCount, o.str(), {}, {}, std::move(rings));
            }
        }
        return kPass;
    }

    // Rule 4: directed triangle edges are distinct.
    CheckResult distinctEdges() {
        if (triangles.size() * 3 >= kNone)
            return fail(CheckRule::DistinctEdges, "too many triangles for 32-bit edge indices");
        edges.emplace(n, triangles, C);
        if (!edges->anyTwice()) return kPass;
        // Which repeat comes first, in triangle order (the message names both triangles).
        std::unordered_map<uint64_t, uint32_t> seen;
        for (size_t t = 0; t < triangles.size(); ++t) {
            const Triangle& tri = triangles[t];
            for (int k = 0; k < 3; ++k) {
                Index a = tri[k], b = tri[(k + 1) % 3];
                auto [it, fresh] = seen.emplace(edgeKey(C[a], C[b]), uint32_t(t));
                if (fresh) continue;
                uint32_t other = it->second;
                std::ostringstream o;
                o << "edge-used-twice: directed edge (" << a << ", " << b << ") is in "
                  << triName(other, triangles[other]) << " and " << triName(t, tri);
                return fail(CheckRule::DistinctEdges, o.str(), {other, uint32_t(t)}, {a, b});
            }
        }
        return kPass;  // unreachable: anyTwice() saw a repeat
    }

    // Ring orientations (rule 0's last condition: none of zero area) and the polygon's doubled
    // area. Computed here, not by ring_area.h's ringAreaSign, so the oracle shares no
    // orientation code with what it checks.
    CheckResult orientRings() {
        forwardRing.assign(polygon.rings.size(), 0);
        for (Index r = 0; r < polygon.rings.size(); ++r) {
            const Ring& ring = polygon.rings[r];
            if (isPointHole(r)) continue;  // no edges, no area; rule 2 counted its triangles
            auto edge = [&](Index i) {
                return std::pair{V[ring.first + i], V[ring.first + (i + 1) % ring.count]};
            };
            AreaEstimate ringArea;
            for (Index i = 0; i < ring.count; ++i) ringArea.addCross(edge(i).first, edge(i).second);
            int s = ringArea.sign();
            if (s == 0) {  // zero or too close to tell: exact arithmetic says
                ExactSum exact;
                for (Index i = 0; i < ring.count; ++i)
                    exact.addCross(edge(i).first, edge(i).second);
                s = exact.sign();
            }
            if (s == 0) {
                std::ostringstream o;
                o << "ring-zero-area: ring " << r << " has zero signed area";
                return fail(CheckRule::Rings, o.str(), {}, {}, {r});
            }
            bool outer = partOfRing[r] != kNone && polygon.parts[partOfRing[r]].firstRing == r;
            forwardRing[r] = outer ? s > 0 : s < 0;
            for (Index i = 0; i < ring.count; ++i) {
                auto [a, b] = edge(i);
                polygonArea.addCross(forwardRing[r] ? a : b, forwardRing[r] ? b : a);
            }
        }
        return kPass;
    }

    // Rule 5: every boundary edge once, from the inside (and no two rings share one).
    CheckResult boundaryEdges() {
        std::optional<CheckResult> failed;
        eachBoundaryEdge([&](BoundaryEdge e) {
            const Index a = e.a, b = e.b,
                        r = e.ring;  // named, not bound: lambdas below capture them
            uint32_t slot = edges->find(C[a], C[b]);
            if (slot != kNone && edges->marked(slot)) {
                Index earlier = kNone;  // the ring of the first boundary edge with this segment
                eachBoundaryEdge([&](BoundaryEdge f) {
                    if (C[f.a] != C[a] || C[f.b] != C[b]) return true;
                    earlier = f.ring;
                    return false;
                });
                std::ostringstream o;
                o << "boundary-edge-shared: rings " << earlier << " and " << r
                  << " share the boundary segment (" << a << ", " << b << ")";
                failed = fail(CheckRule::BoundaryEdges, o.str(), {}, {a, b}, {earlier, r});
                return false;
            }
            if (edges->contains(C[b], C[a])) {
                auto uses = [&](const Triangle& tri) {  // the reversed edge
                    for (int k = 0; k < 3; ++k)
                        if (C[tri[k]] == C[b] && C[tri[(k + 1) % 3]] == C[a]) return true;
                    return false;
                };
                uint32_t user = uint32_t(std::find_if(triangles.begin(), triangles.end(), uses) -
                                         triangles.begin());
                std::ostringstream o;
                o << "boundary-edge-reversed: " << triName(user, triangles[user])
                  << " uses boundary edge (" << b << ", " << a << ") of ring " << r
                  << " from outside";
                failed = fail(CheckRule::BoundaryEdges, o.str(), {user}, {b, a}, {r});
                return false;
            }
            if (slot == kNone) {
                std::ostringstream o;
                o << "boundary-edge-missing: no triangle has boundary edge (" << a << ", " << b
                  << ") of ring " << r;
                failed = fail(CheckRule::BoundaryEdges, o.str(), {}, {a, b}, {r});
                return false;
            }
            edges->mark(slot);
            return true;
        });
        return failed ? *failed : kPass;
    }

    // Rule 6: interior edges come in twins.
    CheckResult interiorTwins() {
        if (edges->allTwinned()) return kPass;
        // The first unmatched edge in triangle order (the message names its triangle).
        for (size_t t = 0; t < triangles.size(); ++t) {
            const Triangle& tri = triangles[t];
            for (int k = 0; k < 3; ++k) {
                Index a = tri[k], b = tri[(k + 1) % 3];
                if (edges->marked(edges->find(C[a], C[b]))) continue;
                if (!edges->contains(C[b], C[a])) {
                    std::ostringstream o;
                    o << "unmatched-edge: " << triName(t, tri) << " has interior edge (" << a
                      << ", " << b << ") but no triangle has (" << b << ", " << a << ")";
                    return fail(CheckRule::InteriorTwins, o.str(), {uint32_t(t)}, {a, b});
                }
            }
        }
        return kPass;
    }

    // Rule 7: areas. Rules 3-6 imply it: the triangles' boundary is then exactly the
    // polygon's, so by Green's theorem their areas sum to its area. Checked all the same, as a
    // guard on the code of rules 4-6, in doubles: a sum differing by more than the two error
    // bounds differs exactly (no exact sum of 10^6 triangles is needed to prove what holds).
    CheckResult area() {
        const double gap = std::fabs(triangleArea.value() - polygonArea.value());
        if (triangleArea.finite() && polygonArea.finite() &&
            gap * (1 - 0x1p-52) > triangleArea.bound() + polygonArea.bound()) {
            std::ostringstream o;
            o.precision(17);
            o << "area-mismatch: triangles cover doubled area " << triangleArea.value()
              << ", the polygon has " << polygonArea.value();
            return fail(CheckRule::Area, o.str());
        }
        return kPass;
    }

    // Rule 8: parts do not overlap. A single part has nothing to overlap.
    CheckResult partsDisjoint() {
        if (polygon.parts.size() <= 1) return kPass;
        // Rules 2-7's edge lists and canonical copies are not needed any more: the sweep's
        // arrays take their place instead of adding to them.
        edges.reset();
        C = {};
        std::vector<BoundaryEdge> boundaryEdges;
        boundaryEdges.reserve(n + polygon.splits.size());
        eachBoundaryEdge([&](BoundaryEdge e) {
            boundaryEdges.push_back(e);
            return true;
        });
        PartsOverlap overlap = partsOverlap(V, partOfVertex, std::move(boundaryEdges));
        if (overlap.reason.empty()) return kPass;
        std::vector<uint32_t> rings;  // the overlapping parts' outer rings
        for (Index p : overlap.parts)
            if (p < polygon.parts.size()) rings.push_back(polygon.parts[p].firstRing);
        return fail(CheckRule::PartsDisjoint, overlap.reason, {}, std::move(overlap.vertices),
                    std::move(rings));
    }
};

}  // namespace

TriangleCheck checkTriangles(const Polygon& polygon, const std::vector<Triangle>& triangles) {
    const std::vector<Point>& V = polygon.vertices;
    TriangleCheck each{counterClockwise(V, triangles), {}};
    for (const Triangle& tri : triangles)
        if (tri[0] < V.size() && tri[1] < V.size() && tri[2] < V.size())
            each.area.addTriangle(V[tri[0]], V[tri[1]], V[tri[2]]);
    return each;
}

CheckResult checkTriangulation(const Polygon& polygon, const std::vector<Triangle>& triangles) {
    return checkTriangulation(polygon, triangles, {});
}

CheckResult checkTriangulation(const Polygon& polygon, const std::vector<Triangle>& triangles,
                               const std::function<TriangleCheck()>& triangleCheck) {
    using Rule = CheckResult (Checker::*)();
    Checker checker(polygon, triangles);
    for (Rule rule : {&Checker::rings, &Checker::indices, &Checker::partsAndCount}) {
        CheckResult r = (checker.*rule)();
        if (!r.ok) return r;
    }
    // Rule 3 here, or from the caller once a later rule needs it: it is reported before them.
    std::optional<TriangleCheck> each;
    if (!triangleCheck) {
        each = checkTriangles(polygon, triangles);
        if (!each->rule3.ok) return each->rule3;
    }
    auto rule3 = [&]() -> const CheckResult& {
        if (!each) each = triangleCheck();
        return each->rule3;
    };
    for (Rule rule : {&Checker::distinctEdges, &Checker::orientRings, &Checker::boundaryEdges,
                      &Checker::interiorTwins}) {
        CheckResult r = (checker.*rule)();
        if (!r.ok) return rule3().ok ? r : rule3();
    }
    if (!rule3().ok) return rule3();
    checker.triangleArea = each->area;
    for (Rule rule : {&Checker::area, &Checker::partsDisjoint}) {
        CheckResult r = (checker.*rule)();
        if (!r.ok) return r;
    }
    return kPass;
}

}  // namespace flood
