// Every generated family is a valid polygon, at several sizes and under every exact transform.
// Validity is proved here by a slow, independent O(n^2) exact check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <sstream>

#include "flood/geometry/predicates.h"
#include "flood/tools/generate.h"

using flood::Index;
using flood::orient;
using flood::Point;
using flood::Polygon;

namespace {

bool onClosedSegment(Point s, Point p, Point q) {
    return orient(p, q, s) == 0 && std::min(p.x, q.x) <= s.x && s.x <= std::max(p.x, q.x) &&
           std::min(p.y, q.y) <= s.y && s.y <= std::max(p.y, q.y);
}

// Exact point-in-ring by crossing number; s must not lie on the ring.
bool insideRing(Point s, const Polygon& p, Index r) {
    const flood::Ring& ring = p.rings[r];
    bool in = false;
    for (Index i = 0; i < ring.count; ++i) {
        Point a = p.vertices[ring.first + i], b = p.vertices[ring.first + (i + 1) % ring.count];
        if ((a.y > s.y) != (b.y > s.y)) {
            int o = orient(a, b, s);
            if ((b.y > a.y) ? o > 0 : o < 0) in = !in;
        }
    }
    return in;
}

bool onRing(Point s, const Polygon& p, Index r) {
    const flood::Ring& ring = p.rings[r];
    for (Index i = 0; i < ring.count; ++i)
        if (onClosedSegment(s, p.vertices[ring.first + i],
                            p.vertices[ring.first + (i + 1) % ring.count]))
            return true;
    return false;
}

// A vertex of ring r not on ring other (exists when rings only touch at shared points).
bool freeVertex(const Polygon& p, Index r, Index other, Point& out) {
    const flood::Ring& ring = p.rings[r];
    for (Index i = 0; i < ring.count; ++i)
        if (!onRing(p.vertices[ring.first + i], p, other)) {
            out = p.vertices[ring.first + i];
            return true;
        }
    return false;
}

// Returns "" when valid, else what is wrong.
std::string validity(const Polygon& p) {
    std::ostringstream err;
    // Bookkeeping.
    if (p.parts.empty()) return "no parts";
    Index nextRing = 0, nextVertex = 0;
    for (const flood::Part& part : p.parts) {
        if (part.firstRing != nextRing || part.ringCount < 1) return "part bookkeeping";
        nextRing += part.ringCount;
    }
    if (nextRing != p.rings.size()) return "rings not covered by parts";
    std::vector<Index> partOf(p.rings.size());
    std::vector<bool> isPoint(p.rings.size());  // a hole of one vertex: a Steiner point
    for (Index pi = 0; pi < p.parts.size(); ++pi)
        for (Index r = p.parts[pi].firstRing; r < p.parts[pi].firstRing + p.parts[pi].ringCount;
             ++r)
            partOf[r] = pi, isPoint[r] = p.rings[r].count == 1 && r != p.parts[pi].firstRing;
    for (Index r = 0; r < p.rings.size(); ++r) {
        const flood::Ring& ring = p.rings[r];
        if (ring.first != nextVertex) return "ring bookkeeping";
        if (ring.count < 3 && !isPoint[r]) return "ring with fewer than 3 vertices";
        nextVertex += ring.count;
    }
    if (nextVertex != p.vertices.size()) return "vertices not covered by rings";
    for (Point v : p.vertices)
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) return "non-finite coordinate";

    // Nonzero area, distinct points within a ring.
    for (Index r = 0; r < p.rings.size(); ++r) {
        if (isPoint[r]) continue;
        flood::ExactSum area;
        const flood::Ring& ring = p.rings[r];
        for (Index i = 0; i < ring.count; ++i)
            area.addCross(p.vertices[ring.first + i],
                          p.vertices[ring.first + (i + 1) % ring.count]);
        if (area.sign() == 0) return "ring with zero area";
        std::vector<Point> pts(p.vertices.begin() + ring.first,
                               p.vertices.begin() + ring.first + ring.count);
        std::sort(pts.begin(), pts.end(),
                  [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        for (size_t i = 1; i < pts.size(); ++i)
            if (pts[i] == pts[i - 1]) return "ring repeats a point";
    }

    // Edges: any two meet at most at a point that is an endpoint of both, or at a vertex of one
    // inside the other when their rings differ but share a part (a T-junction, a touch).
    std::vector<std::pair<Index, Index>> touches;  // rings touching at a T-junction
    struct Edge {
        Point a, b;
        Index ring;
    };
    std::vector<Edge> edges;
    for (Index r = 0; r < p.rings.size(); ++r) {
        const flood::Ring& ring = p.rings[r];
        for (Index i = 0; i < ring.count && !isPoint[r]; ++i)
            edges.push_back(
                {p.vertices[ring.first + i], p.vertices[ring.first + (i + 1) % ring.count], r});
    }
    for (size_t i = 0; i < edges.size(); ++i)
        for (size_t j = i + 1; j < edges.size(); ++j) {
            const Edge& e = edges[i];
            const Edge& f = edges[j];
            int o1 = orient(e.a, e.b, f.a), o2 = orient(e.a, e.b, f.b);
            int o3 = orient(f.a, f.b, e.a), o4 = orient(f.a, f.b, e.b);
            if (o1 * o2 < 0 && o3 * o4 < 0) {
                err << "edges " << i << " and " << j << " cross";
                return err.str();
            }
            auto endpointOf = [](Point s, const Edge& g) { return s == g.a || s == g.b; };
            bool junctionAllowed = e.ring != f.ring && partOf[e.ring] == partOf[f.ring];
            for (Point s : {f.a, f.b})
                if (onClosedSegment(s, e.a, e.b) && !endpointOf(s, e)) {
                    if (junctionAllowed && !onClosedSegment(s == f.a ? f.b : f.a, e.a, e.b)) {
                        touches.push_back({e.ring, f.ring});
                        continue;
                    }
                    err << "vertex (" << s.x << ", " << s.y << ") of edge " << j << " touches edge "
                        << i;
                    return err.str();
                }
            for (Point s : {e.a, e.b})
                if (onClosedSegment(s, f.a, f.b) && !endpointOf(s, f)) {
                    if (junctionAllowed && !onClosedSegment(s == e.a ? e.b : e.a, f.a, f.b)) {
                        touches.push_back({e.ring, f.ring});
                        continue;
                    }
                    err << "vertex (" << s.x << ", " << s.y << ") of edge " << i << " touches edge "
                        << j;
                    return err.str();
                }
            if ((e.a == f.a && e.b == f.b) || (e.a == f.b && e.b == f.a)) return "repeated edge";
        }

    // Steiner points: strictly inside the outer ring, on no ring (checked below: not inside a
    // hole), at no other vertex.
    for (Index r = 0; r < p.rings.size(); ++r) {
        if (!isPoint[r]) continue;
        Point s = p.vertices[p.rings[r].first];
        for (Index g = 0; g < p.rings.size(); ++g)
            if (g != r && onRing(s, p, g)) return "point hole on a ring";
    }

    // Nesting: holes inside their outer ring and outside each other; parts outside each other.
    for (Index pi = 0; pi < p.parts.size(); ++pi) {
        const flood::Part& part = p.parts[pi];
        Index outer = part.firstRing;
        for (Index h = outer + 1; h < outer + part.ringCount; ++h) {
            Point s;
            if (!freeVertex(p, h, outer, s) || !insideRing(s, p, outer)) return "hole not inside";
            for (Index g = outer + 1; g < outer + part.ringCount; ++g)
                if (g != h && (!freeVertex(p, h, g, s) || insideRing(s, p, g)))
                    return "hole inside another hole";
        }
        for (Index qi = 0; qi < p.parts.size(); ++qi) {
            Point s;
            if (qi != pi && (!freeVertex(p, outer, p.parts[qi].firstRing, s) ||
                             insideRing(s, p, p.parts[qi].firstRing)))
                return "part inside another part";
        }
    }

    // Touching rings form a forest (a cycle of touches would cut off a piece of interior).
    std::vector<Index> parent(p.rings.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::function<Index(Index)> find = [&](Index x) {
        return parent[x] == x ? x : parent[x] = find(parent[x]);
    };
    std::map<std::pair<double, double>, std::vector<Index>> at;
    for (Index r = 0; r < p.rings.size(); ++r)
        for (Index i = 0; i < p.rings[r].count; ++i) {
            Point v = p.vertices[p.rings[r].first + i];
            at[{v.x + 0.0, v.y + 0.0}].push_back(r);
        }
    for (auto& [point, rings] : at)
        for (size_t k = 1; k < rings.size(); ++k) touches.push_back({rings[0], rings[k]});
    // A T-junction at a shared vertex of its edge's ring is one touch, counted once.
    std::sort(touches.begin(), touches.end());
    touches.erase(std::unique(touches.begin(), touches.end()), touches.end());
    for (auto [ra, rb] : touches) {
        if (partOf[ra] != partOf[rb]) continue;
        Index a = find(ra), b = find(rb);
        if (a == b) return "rings touch in a cycle";
        parent[a] = b;
    }
    return "";
}

}  // namespace

TEST(Generate, ValidatorRejectsBadPolygons) {
    Polygon bowtie;
    bowtie.addRing({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, true);
    EXPECT_NE(validity(bowtie), "");
    Polygon touching;  // vertex on another ring's edge interior: a T-junction, fine
    touching.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    touching.addRing({{2, 0}, {3, 1}, {1, 1}}, false);
    EXPECT_EQ(validity(touching), "");
    touching.addRing({{2, 4}, {1, 3}, {3, 1}}, false);  // touching both closes a cycle
    EXPECT_NE(validity(touching), "");
    Polygon selfTouching;  // vertex on its own ring's edge interior
    selfTouching.addRing({{0, 0}, {10, 0}, {10, 10}, {6, 3}, {5, 0}, {4, 3}, {0, 10}}, true);
    EXPECT_NE(validity(selfTouching), "");
    Polygon steiner;
    steiner.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    steiner.addRing({{1, 1}}, false);
    EXPECT_EQ(validity(steiner), "");
    steiner.addRing({{4, 2}}, false);  // on the outer ring
    EXPECT_NE(validity(steiner), "");
    Polygon sharedVertex;  // the same at a shared vertex is fine
    sharedVertex.addRing({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    sharedVertex.addRing({{2, 0}, {3, 1}, {1, 1}}, false);
    EXPECT_EQ(validity(sharedVertex), "");
    Polygon outside;
    outside.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    outside.addRing({{5, 5}, {6, 5}, {6, 6}}, false);
    EXPECT_NE(validity(outside), "");
    Polygon backtrack;
    backtrack.addRing({{0, 0}, {4, 0}, {2, 0}, {2, 3}}, true);
    EXPECT_NE(validity(backtrack), "");
}

TEST(Generate, EveryFamilyValidAtSeveralSizes) {
    auto names = flood::familyNames();
    EXPECT_GE(names.size(), 15u);
    for (const std::string& name : names) {
        EXPECT_FALSE(flood::familyDescription(name).empty()) << name;
        for (size_t size : {3, 10, 40, 150, 1000})
            for (uint64_t seed : {1, 2, 3}) {
                Polygon p = flood::generate(name, seed, size);
                ASSERT_GE(p.vertices.size(), 3u) << name;
                if (p.vertices.size() > 3000) continue;  // too slow for the O(n^2) check
                EXPECT_EQ(validity(p), "") << name << " size " << size << " seed " << seed;
            }
    }
}

TEST(Generate, LargerSpiralsValid) {
    // The curved and spiral families at the sizes benchmarks use (O(n^2): a few seconds).
    for (const char* name : {"spiral", "ortho-spiral", "circle-holes"}) {
        Polygon p = flood::generate(name, 3, 2000);
        EXPECT_EQ(validity(p), "") << name;
    }
}

TEST(Generate, EveryTransformValid) {
    for (const std::string& name : flood::familyNames()) {
        Polygon base = flood::generate(name, 7, 40);
        if (base.vertices.size() > 600) continue;
        for (int rot = 0; rot < 4; ++rot)
            for (bool mirror : {false, true})
                for (bool reverse : {false, true}) {
                    size_t shift = size_t(rot * 3 + mirror + 1);
                    Polygon t = flood::transform(base, rot, mirror, reverse, shift);
                    ASSERT_EQ(t.vertices.size(), base.vertices.size());
                    EXPECT_EQ(validity(t), "")
                        << name << " rot " << rot << " mirror " << mirror << " reverse " << reverse;
                    // Orientation flips exactly with mirror xor reverse.
                    flood::ExactSum a, b;
                    const flood::Ring& r = base.rings[0];
                    for (Index i = 0; i < r.count; ++i) {
                        a.addCross(base.vertices[r.first + i],
                                   base.vertices[r.first + (i + 1) % r.count]);
                        b.addCross(t.vertices[r.first + i],
                                   t.vertices[r.first + (i + 1) % r.count]);
                    }
                    EXPECT_EQ(a.sign() * b.sign(), (mirror != reverse) ? -1 : 1) << name;
                }
    }
}

TEST(Generate, TransformsAreExact) {
    Polygon p = flood::generate("star", 5, 20);
    Polygon q = flood::transform(flood::transform(p, 1, false, false, 0), 3, false, false, 0);
    EXPECT_EQ(p.vertices, q.vertices);
    q = flood::transform(flood::transform(p, 0, true, true, 3), 0, true, true, 0);
    // Mirrored twice and reversed twice: same vertex set per ring, shifted start.
    std::vector<std::pair<double, double>> a, b;
    for (Point v : p.vertices) a.push_back({v.x, v.y});
    for (Point v : q.vertices) b.push_back({v.x, v.y});
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
    for (Point v : flood::transform(p, 2, true, false, 0).vertices)
        EXPECT_FALSE(std::signbit(v.x) && v.x == 0) << "negative zero";
}

TEST(Generate, DeterministicAndSized) {
    for (const std::string& name : flood::familyNames()) {
        Polygon a = flood::generate(name, 42, 5000), b = flood::generate(name, 42, 5000);
        EXPECT_EQ(a.vertices, b.vertices) << name;
        EXPECT_GE(a.vertices.size(), 500u) << name;
        EXPECT_LE(a.vertices.size(), 20000u) << name;
        Polygon c = flood::generate(name, 43, 5000);
        if (name != "ortho-spiral") {
            EXPECT_NE(a.vertices, c.vertices) << name;
        }
    }
}
