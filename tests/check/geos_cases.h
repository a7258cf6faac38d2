// Seeded generator of small polygons and MultiPolygons on a small integer grid, for comparing
// validate() with GEOS (tests/check/geos_diff_test.cpp, scripts/geos-diff.sh). Small coordinates
// make degeneracies common: parts touching or crossing at vertices, T-junctions within and
// between parts, collinear stretches, islands in lakes, holes touching holes. Mutations of
// generated cases and of the sample polygons move a vertex onto another vertex or onto the
// middle of an edge, mirror, reverse a ring or start it elsewhere. Valid and invalid cases both
// come out; which is which is for the oracles to say.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood::testing {

class GeosCases {
public:
    // `samples`: polygons to mutate (the repository's sample polygons).
    GeosCases(uint64_t seed, std::vector<Polygon> samples)
        : state_(seed), samples_(std::move(samples)) {}

    struct Case {
        Polygon polygon;
        std::string family;
    };

    // The next case. Every ring has at least 3 points and no two consecutive equal (GEOS cannot
    // build shorter rings; flood's readers drop repeated points before validation).
    Case next() {
        for (;;) {
            Case c;
            switch (below(10)) {
                case 9: c = {crowd(), "crowd"}; break;
                case 7: c = {cells(), "cells"}; break;
                case 8: c = {tinyTriangles(), "tiny"}; break;
                case 0: c = {fromParts({star(6, 3 + below(5), below(3))}), "star"}; break;
                case 1: c = {fromParts(someParts(2 + below(2))), "parts"}; break;
                case 2: c = {lake(), "lake"}; break;
                case 3: c = {fan(), "fan"}; break;
                case 4: c = {junction(), "junction"}; break;
                case 5: c = {sample(), "sample"}; break;
                default: c = {fromParts(someParts(1 + below(3))), "mutated"}; break;
            }
            if (c.family == "mutated" || c.family == "sample" || below(3) == 0) {
                int k = 1 + int(below(3));
                for (int i = 0; i < k; ++i) mutate(c.polygon);
                if (c.family != "sample" && c.family != "mutated") c.family += "+mutated";
            }
            if (tidy(c.polygon)) return c;
        }
    }

private:
    using Ring = std::vector<Point>;
    using Rings = std::vector<Ring>;  // outer ring, then holes

    uint64_t state_;
    std::vector<Polygon> samples_;

    uint64_t rand() {  // splitmix64: the same sequence on every platform
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    uint64_t below(uint64_t k) { return rand() % k; }
    double coord(int lo, int hi) { return double(lo + int(below(uint64_t(hi - lo + 1)))); }

    // A star-shaped ring in [lo, hi]^2 (hi >= lo + 2): grid points sorted by angle round a grid centre (points at equal
    // angles give collinear or crossing edges, on purpose). Angles only order the generation.
    Ring starRing(int lo, int hi, size_t count) {
        Point c{coord(lo + 1, hi - 1), coord(lo + 1, hi - 1)};
        Ring r;
        for (size_t i = 0; i < count; ++i) {
            Point q{coord(lo, hi), coord(lo, hi)};
            if (q != c) r.push_back(q);
        }
        std::sort(r.begin(), r.end(), [&](Point a, Point b) {
            return std::atan2(a.y - c.y, a.x - c.x) < std::atan2(b.y - c.y, b.x - c.x);
        });
        r.erase(std::unique(r.begin(), r.end()), r.end());
        if (below(2)) std::reverse(r.begin(), r.end());
        return r;
    }
    Ring box(double x0, double y0, double x1, double y1) {
        return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    }
    Rings star(int size, size_t count, size_t holes) {
        Rings rs{starRing(0, size, count)};
        for (size_t h = 0; h < holes; ++h) rs.push_back(starRing(1, size - 1, 3 + below(2)));
        return rs;
    }
    Rings shape() {
        double x = coord(0, 6), y = coord(0, 6);
        switch (below(3)) {
            case 0: return {box(x, y, x + coord(1, 3), y + coord(1, 3))};
            case 1: return {{{x, y}, {x + coord(1, 3), y}, {x, y + coord(1, 3)}}};
            default: return star(8, 3 + below(4), below(2));
        }
    }
    std::vector<Rings> someParts(size_t k) {
        std::vector<Rings> ps;
        for (size_t i = 0; i < k; ++i) ps.push_back(shape());
        return ps;
    }
    static Polygon fromParts(const std::vector<Rings>& parts) {
        Polygon p;
        for (const Rings& rs : parts)
            for (size_t i = 0; i < rs.size(); ++i) p.addRing(rs[i], i == 0);
        return p;
    }
    // A square with a hole, an island in the hole, sometimes a lake in the island: touching
    // each other where the grid makes them.
    Polygon lake() {
        double a = coord(2, 3), b = coord(7, 8);
        Rings outer{box(0, 0, 10, 10), box(a, a, b, b)};
        std::vector<Rings> ps{outer};
        double c = coord(int(a), int(a) + 2), d = coord(int(b) - 2, int(b));
        if (c < d) {
            Rings island{box(c, c, d, d)};
            if (d - c >= 2 && below(2)) island = {starRing(int(c), int(d), 3 + below(4))};
            if (d - c >= 2 && below(2))
                island.push_back(box(c + 1, c + 1, d - coord(0, 1), d - coord(0, 1)));
            ps.push_back(island);
        }
        if (below(2))
            ps.push_back({box(coord(0, 10), coord(0, 10), coord(0, 10) + 1, coord(0, 10) + 1)});
        return fromParts(ps);
    }
    // Triangles (parts, or holes of a big square) with a common apex: they touch there, and
    // cross there when two wedges interleave.
    Polygon fan() {
        Point apex{coord(3, 5), coord(3, 5)};
        bool holes = below(2);
        std::vector<Rings> ps;
        if (holes) ps.push_back({box(-1, -1, 10, 10)});
        size_t k = 2 + below(3);
        for (size_t i = 0; i < k; ++i) {
            Ring t{apex, {coord(0, 9), coord(0, 9)}, {coord(0, 9), coord(0, 9)}};
            if (holes) ps[0].push_back(t);
            else ps.push_back({t});
        }
        return fromParts(ps);
    }
    // A part with a vertex at the middle of another part's (or a hole's) edge: touching from
    // outside, or crossing through.
    Polygon junction() {
        double x = coord(0, 3) * 2, y = coord(0, 3) * 2, w = coord(1, 3) * 2, h = coord(1, 3) * 2;
        Rings a{box(x, y, x + w, y + h)};
        Point m{x + w / 2, y};  // middle of the bottom edge
        Ring b{m, {coord(0, 10), coord(-3, 10)}, {coord(0, 10), coord(-3, 10)}};
        if (below(3) == 0) b.push_back({coord(0, 10), coord(-3, 10)});
        if (below(2)) {  // as a hole of a bigger part touching a's edge from inside, or crossing
            Rings big{box(-4, -4, 14, 14), b};
            return fromParts({a, big});
        }
        if (below(2)) {  // or within one part: a hole with a vertex on its outer ring's edge
            a.push_back(b);
            return fromParts({a});
        }
        return fromParts({a, {b}});
    }
    // Unit cells of a grid, as parts or as holes of a square round them: cells meeting at
    // corners touch (holes round a cell close a cycle), cells side by side share an edge.
    Polygon cells() {
        bool holes = below(2);
        std::vector<Rings> ps;
        if (holes) ps.push_back({box(0, 0, 6, 6)});
        for (int x = 1; x < 5; ++x)
            for (int y = 1; y < 5; ++y) {
                if (below(3)) continue;
                Ring c = box(x, y, x + 1, y + 1);
                if (holes) ps[0].push_back(c);
                else ps.push_back({c});
            }
        if (ps.empty() || (holes && ps[0].size() == 1)) ps.push_back({box(1, 1, 2, 2)});
        return fromParts(ps);
    }
    // Triangles on a 4 x 4 grid, as parts or as holes of a square round them.
    Polygon tinyTriangles() {
        bool holes = below(2);
        std::vector<Rings> ps;
        if (holes) ps.push_back({box(-1, -1, 4, 4)});
        for (size_t i = 0, k = 2 + below(3); i < k; ++i) {
            Ring t{
                {coord(0, 3), coord(0, 3)}, {coord(0, 3), coord(0, 3)}, {coord(0, 3), coord(0, 3)}};
            if (holes) ps[0].push_back(t);
            else ps.push_back({t});
        }
        return fromParts(ps);
    }
    // Rings crowding one point: triangles with their apex there or with the point in the middle
    // of an edge, as parts or as holes of a square round them, some twice (touching elsewhere
    // too): crossings, overlaps, T-junctions and cycles at one point, within and between parts.
    Polygon crowd() {
        Point p{4, 4};
        std::vector<Rings> ps{{box(-2, -2, 10, 10)}};
        bool outerToo = below(2);  // the square is a part; otherwise the rings are all parts
        for (size_t i = 0, k = 2 + below(4); i < k; ++i) {
            Point a{coord(0, 8), coord(0, 8)}, b{coord(0, 8), coord(0, 8)};
            Ring t = below(2) ? Ring{p, a, b} : Ring{{2 * p.x - a.x, 2 * p.y - a.y}, a, b};
            if (outerToo && below(2)) ps[0].push_back(t);
            else ps.push_back({t});
        }
        if (!outerToo) ps.erase(ps.begin());
        return fromParts(ps);
    }
    Polygon sample() {
        if (samples_.empty()) return fromParts({star(6, 5, 1)});
        return samples_[below(samples_.size())];
    }

    // One mutation of p, at random.
    void mutate(Polygon& p) {
        size_t n = p.vertices.size();
        if (n == 0) return;
        Index v = Index(below(n));
        switch (below(6)) {
            case 0:  // onto another vertex
                p.vertices[v] = p.vertices[below(n)];
                break;
            case 1:
            case 2: {  // onto an edge at a quarter, half or three quarters: exactly on it for
                       // small integer coordinates; near it otherwise, judged all the same
                Index e = Index(below(n));
                Index r = p.ringOf(e);
                Index f = e + 1 == p.rings[r].first + p.rings[r].count ? p.rings[r].first : e + 1;
                Point a = p.vertices[e], b = p.vertices[f];
                double t = double(1 + below(3)) / 4;
                p.vertices[v] = {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
                break;
            }
            case 3:  // mirror the whole polygon
                for (Point& q : p.vertices) q.x = 0.0 - q.x;
                break;
            case 4: {  // reverse one ring
                const flood::Ring& r = p.rings[p.ringOf(v)];
                std::reverse(p.vertices.begin() + r.first, p.vertices.begin() + r.first + r.count);
                break;
            }
            default: {  // start one ring elsewhere
                const flood::Ring& r = p.rings[p.ringOf(v)];
                std::rotate(p.vertices.begin() + r.first, p.vertices.begin() + v,
                            p.vertices.begin() + r.first + r.count);
                break;
            }
        }
        p.splits.clear();
    }

    // Drops consecutive repeated points (as flood's readers do); false when a ring ends up
    // with fewer than 3 points.
    static bool tidy(Polygon& p) {
        Polygon out;
        for (const Part& part : p.parts)
            for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
                const flood::Ring& ring = p.rings[r];
                Ring pts;
                for (Index i = 0; i < ring.count; ++i) {
                    Point q = p.vertices[ring.first + i];
                    if (pts.empty() || pts.back() != q) pts.push_back(q);
                }
                while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
                if (pts.size() < 3) return false;
                out.addRing(pts, r == part.firstRing);
            }
        p = std::move(out);
        return true;
    }
};

}  // namespace flood::testing
