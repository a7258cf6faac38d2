// T-junctions without validation (see touches.h).
//
// Per part, the distinct points go into a k-d tree (median splits, leaves of 8), each node
// holding the exact bounding box of its points. Each edge walks down into the nodes whose
// closed box it meets — decided exactly by comparisons and orient() against the box's corners,
// which are input coordinates — and tests the points of the leaves it reaches with
// insideSegment(). A point on the edge lies in every box above it, so none is missed.
//
// Nothing here compares two edges, so crossing or overlapping edges cannot make an order
// inconsistent. Cost: O(m log m) to build the tree (its distinct points found by
// coincident.h's hash); per edge, the nodes its segment meets — O(log m) for an edge as
// short as its neighbourhood, O(sqrt m) at most for a long one — plus the points of those
// leaves. Clustered adversaries (many long edges through dense points) can
// still make it super-linear, hence the cap.
#include "flood/check/touches.h"

#include <algorithm>
#include <cmath>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "geometry/coincident.h"

namespace flood {
namespace {

// Default cap: a few seconds of work at most per 10^6 vertices. Above every generated family
// at 10^5 vertices (at most 45 steps per vertex, but 290 and 360 for the long-edged star and
// circle-jagged, about sqrt(m) per vertex, under the 2^24 constant), and above every family
// with T-junctions at 10^6 (t-junctions: about 50).
uint64_t defaultCap(size_t n) { return (uint64_t(1) << 24) + 256 * uint64_t(n); }

struct Spot {  // a distinct point of the part, with the vertices a split there may name
    Point p;
    Index lowest, other;  // the lowest vertex there, the lowest of another ring (or kNone)
};

struct Node {  // a subtree of spots [begin, end) and the exact bounding box of their points
    double x0, y0, x1, y1;
    Index begin, end, left, right;  // children kNone at a leaf
};

struct PartSearch {
    const Polygon& P;
    Index firstVertex, endVertex;  // the part's vertices
    std::vector<Index> ringOfV;    // ring of each vertex of the part (offset firstVertex)
    uint64_t& steps;
    std::vector<EdgeSplit>& out;
    std::vector<Spot> spots;
    std::vector<Node> tree;

    static constexpr Index kLeaf = 8;

    Point pt(Index v) const { return P.vertices[v]; }
    Index ring(Index v) const { return ringOfV[v - firstVertex]; }
    Index next(Index v) const {
        const Ring& r = P.rings[ring(v)];
        return v + 1 == r.first + r.count ? r.first : v + 1;
    }

    // A k-d tree: split at the median of the wider side of the box.
    Index build(Index begin, Index end) {
        Node nd{INFINITY, INFINITY, -INFINITY, -INFINITY, begin, end, kNone, kNone};
        for (Index i = begin; i < end; ++i) {
            Point p = spots[i].p;
            nd.x0 = std::min(nd.x0, p.x), nd.x1 = std::max(nd.x1, p.x);
            nd.y0 = std::min(nd.y0, p.y), nd.y1 = std::max(nd.y1, p.y);
        }
        Index at = Index(tree.size());
        tree.push_back(nd);
        if (end - begin <= kLeaf) return at;
        // Compare the spans without subtracting (no overflow): x wider if x1 - x0 >= y1 - y0.
        bool byX = nd.x1 - nd.x0 >= nd.y1 - nd.y0 || std::isinf(nd.x1 - nd.x0);
        Index mid = begin + (end - begin) / 2;
        std::nth_element(
            spots.begin() + begin, spots.begin() + mid, spots.begin() + end,
            [byX](const Spot& a, const Spot& b) { return byX ? a.p.x < b.p.x : a.p.y < b.p.y; });
        Index l = build(begin, mid), r = build(mid, end);
        tree[at].left = l, tree[at].right = r;
        return at;
    }

    // The segment a-b may meet the closed box: the boxes overlap and the corners are not all
    // strictly on one side of its line. Only a pruning test, so the filter's sign suffices: a
    // corner it cannot decide counts as on the line, and the leaves test exactly.
    static bool meets(Point a, Point b, const Node& n) {
        if (std::max(a.x, b.x) < n.x0 || std::min(a.x, b.x) > n.x1 || std::max(a.y, b.y) < n.y0 ||
            std::min(a.y, b.y) > n.y1)
            return false;
        auto holds = [&n](Point p) {
            return n.x0 <= p.x && p.x <= n.x1 && n.y0 <= p.y && p.y <= n.y1;
        };
        if (holds(a) || holds(b)) return true;  // most edges are short: no line test above them
        int s = 0;
        for (Point c :
             {Point{n.x0, n.y0}, Point{n.x1, n.y0}, Point{n.x1, n.y1}, Point{n.x0, n.y1}}) {
            int o = orientFiltered(a, b, c);
            if (o == 0 || (s != 0 && o != s)) return true;
            s = o;
        }
        return false;
    }

    // p lies in the closed bounding box of a and b: cheap, before the exact test.
    static bool inBox(Point a, Point b, Point p) {
        return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
               std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
    }

    // Tests edge e against the spots of every leaf whose box it meets.
    void query(Index e, uint64_t cap) {
        Point a = pt(e), b = pt(next(e));
        Index stack[64];  // depth <= log2(m) + 1 < 64
        int top = 0;
        stack[top++] = 0;
        while (top > 0 && steps <= cap) {
            const Node& n = tree[stack[--top]];
            ++steps;
            if (!meets(a, b, n)) continue;
            if (n.left != kNone) {
                stack[top++] = n.left, stack[top++] = n.right;
                continue;
            }
            steps += n.end - n.begin;
            for (Index i = n.begin; i < n.end; ++i) {
                const Spot& sp = spots[i];
                Index v = ring(sp.lowest) != ring(e) ? sp.lowest : sp.other;
                if (v != kNone && inBox(a, b, sp.p) && insideSegment(a, b, sp.p))
                    out.push_back({e, v});
            }
        }
    }

    bool run(uint64_t cap) {
        std::vector<Index> vertices;
        for (Index v = firstVertex; v < endVertex; ++v)
            if (P.rings[ring(v)].count > 1) vertices.push_back(v);  // a point hole touches nothing
        // A spot per distinct point, at its lowest vertex; each later copy (in vertex order
        // within a point, as repeatedPoints gives them) may be the lowest of another ring.
        std::vector<std::pair<uint32_t, uint32_t>> copies =
            repeatedPoints(vertices.size(), [&](size_t i) { return pt(vertices[i]); });
        std::vector<Index> spotOf(vertices.size(), kNone);
        for (auto [first, later] : copies) spotOf[later] = 0;  // not a spot of its own
        for (size_t i = 0; i < vertices.size(); ++i)
            if (spotOf[i] == kNone)
                spotOf[i] = Index(spots.size()),
                spots.push_back({pt(vertices[i]), vertices[i], kNone});
        for (auto [first, later] : copies) {
            Spot& s = spots[spotOf[first]];
            if (s.other == kNone && ring(vertices[later]) != ring(s.lowest))
                s.other = vertices[later];
        }
        steps += spots.size();
        if (spots.empty()) return true;
        build(0, Index(spots.size()));
        for (Index e = firstVertex; e < endVertex && steps <= cap; ++e)
            if (P.rings[ring(e)].count > 1 && pt(e) != pt(next(e))) query(e, cap);
        return steps <= cap;
    }
};

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

TouchSearch findTouches(Polygon& polygon, uint64_t maxSteps) {
    TouchSearch result;
    const uint64_t cap = maxSteps ? maxSteps : defaultCap(polygon.vertices.size());
    std::vector<EdgeSplit> splits;
    for (const Part& part : polygon.parts) {
        if (part.ringCount == 0) continue;
        const Ring& first = polygon.rings[part.firstRing];
        const Ring& last = polygon.rings[part.firstRing + part.ringCount - 1];
        PartSearch s{polygon, first.first, last.first + last.count, {}, result.steps, splits,
                     {},      {}};
        if (s.endVertex == s.firstVertex) continue;
        // A T-junction is a vertex inside an edge of another ring: a part needs two rings
        // that are not single points (a point hole touches nothing).
        int rings = 0;
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
            rings += polygon.rings[r].count > 1;
        if (rings < 2) continue;
        bool allFinite = true;
        for (Index v = s.firstVertex; v < s.endVertex; ++v)
            allFinite &= finite(polygon.vertices[v]);
        if (!allFinite) continue;
        s.ringOfV.resize(s.endVertex - s.firstVertex);
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
            for (Index v = polygon.rings[r].first;
                 v < polygon.rings[r].first + polygon.rings[r].count; ++v)
                s.ringOfV[v - s.firstVertex] = r;
        if (!s.run(cap)) {
            result.complete = false;
            splits.clear();
            break;
        }
    }
    work().touchSteps += result.steps;
    const std::vector<Point>& V = polygon.vertices;
    auto end = [&](Index e) {
        const Ring& r = polygon.rings[polygon.ringOf(e)];
        return e + 1 == r.first + r.count ? r.first : e + 1;
    };
    // validate()'s order: by edge, then along the edge from its start.
    std::sort(splits.begin(), splits.end(), [&](const EdgeSplit& s, const EdgeSplit& t) {
        if (s.edge != t.edge) return s.edge < t.edge;
        Point a = V[s.edge], b = V[end(s.edge)], p = V[s.vertex], q = V[t.vertex];
        if (a.x != b.x) return a.x < b.x ? p.x < q.x : p.x > q.x;
        return a.y < b.y ? p.y < q.y : p.y > q.y;
    });
    polygon.splits = std::move(splits);
    polygon.pointsDistinct = false;  // not validated: the machine looks for shared points itself
    return result;
}

}  // namespace flood
