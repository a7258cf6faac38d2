// Seeded generator of invalid polygons (see generate.h): each a valid family with one defect.
#include <algorithm>
#include <cmath>

#include "flood/io/io.h"
#include "flood/tools/generate.h"
#include "tools/generate_parts.h"

namespace flood {

// [SECTION] invalid families
//
// Each is a valid family with one seeded defect of a kind validate() refuses, built so the
// defect is certain (tests/tools/generate_test.cpp checks validate() refuses every one measured).
// For the paper's open conjecture (docs/ALGORITHM.md §6): what the flood and the complement see.

namespace generate_detail {
namespace {

std::vector<Rings> partsOf(const Polygon& p) {
    std::vector<Rings> parts;
    for (const Part& part : p.parts) {
        parts.emplace_back();
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
            parts.back().emplace_back(p.vertices.begin() + p.rings[r].first,
                                      p.vertices.begin() + p.rings[r].first + p.rings[r].count);
    }
    return parts;
}

Polygon polygonOf(const std::vector<Rings>& parts) {
    Polygon p;
    for (const Rings& rings : parts)
        for (size_t r = 0; r < rings.size(); ++r) p.addRing(rings[r], r == 0);
    return p;
}

size_t pick(Rng& rng, size_t n) { return size_t(rng.next() % n); }

// Between consecutive vertices a, b of the star, out to 8a and 8b beyond the star (radii are
// at least 0.15 R): a -> 8b -> 8a -> b, whose first and last edges are the diagonals of a
// convex quadrilateral, so they cross.
Polygon bowtieStar(Rng& rng, size_t size) {
    auto parts = partsOf(star(rng, std::max<size_t>(size, 6)));
    Pts& r = parts[0][0];
    size_t i = pick(rng, r.size());
    Point a = r[i], b = r[(i + 1) % r.size()];
    r.insert(r.begin() + long(i) + 1, {{8 * b.x, 8 * b.y}, {8 * a.x, 8 * a.y}});
    return polygonOf(parts);
}

// The star pinched at its centre: two vertices half a turn apart moved to (0, 0). The star is
// strictly star-shaped around it, so the new edges cross nothing; the ring touches itself.
Polygon selfTouchingStar(Rng& rng, size_t size) {
    auto parts = partsOf(star(rng, std::max<size_t>(size, 8)));
    Pts& r = parts[0][0];
    size_t i = pick(rng, r.size());
    r[i] = r[(i + r.size() / 2) % r.size()] = {0, 0};
    return polygonOf(parts);
}

// A spike: after vertex i, the midpoint of the edge into it (exact: integer coordinates).
Polygon spikeStar(Rng& rng, size_t size) {
    auto parts = partsOf(star(rng, std::max<size_t>(size, 4)));
    Pts& r = parts[0][0];
    size_t i = pick(rng, r.size());
    Point a = r[(i + r.size() - 1) % r.size()], b = r[i];
    r.insert(r.begin() + long(i) + 1, {(a.x + b.x) / 2, (a.y + b.y) / 2});
    return polygonOf(parts);
}

// grid-holes with a hole of the first column moved 2 to the left, across the outer ring's
// left side x = 0 (every hole spans [a, a + 2] in x).
Polygon holeCrossingOuter(Rng& rng, size_t size) {
    Polygon base = gridHoles(rng, size);
    auto parts = partsOf(base);
    int k = std::max(1, int(std::sqrt(double(size) / 4.0)));
    size_t hole = 1 + pick(rng, size_t(k));  // holes of column 0 come first
    for (Point& q : parts[0][hole]) q.x -= 2;
    return polygonOf(parts);
}

// grid-holes with a copy of one hole shifted by (1, 1): it overlaps the original.
Polygon holesOverlapping(Rng& rng, size_t size) {
    auto parts = partsOf(gridHoles(rng, size));
    Pts copy = parts[0][1 + pick(rng, parts[0].size() - 1)];
    for (Point& q : copy) q = {q.x + 1, q.y + 1};
    parts[0].push_back(copy);
    return polygonOf(parts);
}

// grid-holes with a small square hole inside one of its square or diamond holes (a triangle's
// centre (a + 1, b + 0.75) holds it too): a hole in a hole, touching nothing.
Polygon holeInHole(Rng& rng, size_t size) {
    auto parts = partsOf(gridHoles(rng, size));
    const Pts& h = parts[0][1 + pick(rng, parts[0].size() - 1)];
    double a = h[0].x, b = h[0].y;
    for (Point q : h) a = std::min(a, q.x), b = std::min(b, q.y);
    parts[0].push_back({{a + 0.875, b + 0.625},
                        {a + 0.875, b + 0.875},
                        {a + 1.125, b + 0.875},
                        {a + 1.125, b + 0.625}});
    return polygonOf(parts);
}

// grid-holes with a square hole beyond the outer ring (touching nothing).
Polygon holeOutside(Rng& rng, size_t size) {
    auto parts = partsOf(gridHoles(rng, size));
    double side = parts[0][0][1].x, y = double(pick(rng, size_t(side - 1)));
    parts[0].push_back({{side + 1, y}, {side + 1, y + 1}, {side + 2, y + 1}, {side + 2, y}});
    return polygonOf(parts);
}

// grid-holes with a thin hole on the outer ring's bottom side: their edges overlap along y = 0.
Polygon collinearOverlap(Rng& rng, size_t size) {
    auto parts = partsOf(gridHoles(rng, size));
    double side = parts[0][0][1].x, x = 0.5 + double(pick(rng, size_t(side - 1)));
    parts[0].push_back({{x, 0}, {x, 0.5}, {x + 0.5, 0.5}, {x + 0.5, 0}});
    return polygonOf(parts);
}

// A comb whose teeth hang from the top; one tooth's tip reaches the bottom side, a vertex
// inside the ring's own edge.
Polygon vertexOnOwnEdge(Rng& rng, size_t size) {
    int k = std::max(2, int(size / 3));
    double W = 4.0 * k;
    size_t t = pick(rng, size_t(k));
    Pts r = {{0, 0}, {W, 0}, {W, 4}};
    for (int i = k - 1; i >= 0; --i) {
        double d = size_t(i) == t ? 0 : rng.range(1, 3);
        r.insert(r.end(), {{4.0 * i + 3, 4}, {4.0 * i + 2, d}, {4.0 * i + 1, 4}});
    }
    r.push_back({0, 4});
    return polygonOf({{r}});
}

// islands with a copy of one island's outer ring shifted by (1, 1), a part of its own: the
// parts' edges cross.
Polygon partsCrossing(Rng& rng, size_t size) {
    auto parts = partsOf(islands(rng, size));
    Pts copy = parts[pick(rng, parts.size())][0];
    for (Point& q : copy) q = {q.x + 1, q.y + 1};
    parts.push_back({copy});
    return polygonOf(parts);
}

// islands with a small triangle part on the land of one island (between its outer ring and
// its hole, if any): one part inside another, no edges meeting.
Polygon partInsidePart(Rng& rng, size_t size) {
    auto parts = partsOf(islands(rng, size));
    Point o = parts[pick(rng, parts.size())][0][0];  // the island's lower left corner
    parts.push_back(
        {{{o.x + 0.25, o.y + 0.25}, {o.x + 0.75, o.y + 0.25}, {o.x + 0.5, o.y + 0.75}}});
    return polygonOf(parts);
}

// Rows of diamond holes touching tip to tip across the outer ring, left side to right side
// (T-junctions there). One row is complete: its touches close a cycle with the outer ring and
// cut the interior in two. The others miss a diamond and are valid.
Polygon touchCycle(Rng& rng, size_t size) {
    const int k = std::max(2, int(size / 8)), rows = 2;
    const double W = 2.0 * k;
    Rings rings = {{{0, 0}, {W, 0}, {W, 4.0 * rows}, {0, 4.0 * rows}}};
    size_t closed = pick(rng, rows);
    for (int j = 0; j < rows; ++j) {
        double y = 4.0 * j + 2;
        size_t gap = size_t(j) == closed ? size_t(k) : pick(rng, size_t(k));
        for (int i = 0; i < k; ++i)
            if (size_t(i) != gap)
                rings.push_back(
                    {{2.0 * i, y}, {2.0 * i + 1, y - 1}, {2.0 * i + 2, y}, {2.0 * i + 1, y + 1}});
    }
    return polygonOf({rings});
}

// Random rings on a small integer lattice (crossings, overlaps, touches of every kind, by
// chance), drawn again until validate() refuses them: 1 to 3 parts of 1 to 3 rings, 3 to 7
// vertices each, on a lattice of side 8 (larger sizes: more parts, on a larger lattice).
Polygon randomLattice(Rng& rng, size_t size) {
    const int side = 8 + int(std::sqrt(double(size))), extra = int(size / 30);
    for (;;) {
        std::vector<Rings> parts(size_t(rng.range(1, 3 + extra)));
        for (Rings& rings : parts) {
            rings.resize(size_t(rng.range(1, 3)));
            for (Pts& r : rings)
                for (int v = 0, n = rng.range(3, 7); v < n; ++v)
                    r.push_back(pt(rng.range(0, side), rng.range(0, side)));
        }
        Polygon p = polygonOf(parts);
        if (!validate(p, "random-lattice").ok()) return p;
    }
}

const Family kInvalidFamilies[] = {
    {"bowtie-star", "star with two crossing edges (a bow-tie) out between two vertices",
     bowtieStar},
    {"self-touching", "star pinched at its centre: the ring passes twice through (0, 0)",
     selfTouchingStar},
    {"spike", "star with a spike: a vertex folding back onto the edge into it", spikeStar},
    {"vertex-on-own-edge", "comb whose tooth tip lies inside the ring's own bottom edge",
     vertexOnOwnEdge},
    {"hole-crossing-outer", "grid-holes with a hole moved across the outer ring",
     holeCrossingOuter},
    {"holes-overlapping", "grid-holes with a shifted copy of a hole overlapping it",
     holesOverlapping},
    {"hole-in-hole", "grid-holes with a hole inside another hole", holeInHole},
    {"hole-outside", "grid-holes with a hole beyond the outer ring", holeOutside},
    {"collinear-overlap", "grid-holes with a hole whose edge overlaps the outer ring's",
     collinearOverlap},
    {"parts-crossing", "islands with a shifted copy of an island crossing it", partsCrossing},
    {"part-inside-part", "islands with a small part on an island's land", partInsidePart},
    {"random-lattice",
     "random rings on a small integer lattice, drawn until validate() refuses them", randomLattice},
    {"touch-cycle", "a row of holes touching tip to tip from side to side: the interior cut in two",
     touchCycle},
};

}  // namespace
}  // namespace generate_detail

using generate_detail::descriptionIn;
using generate_detail::kInvalidFamilies;
using generate_detail::makeFrom;
using generate_detail::namesOf;

std::vector<std::string> invalidFamilyNames() { return namesOf(kInvalidFamilies); }
std::string invalidFamilyDescription(const std::string& family) {
    return descriptionIn(kInvalidFamilies, family);
}
Polygon generateInvalid(const std::string& family, uint64_t seed, size_t size) {
    return makeFrom(kInvalidFamilies, family, seed, size, 0x7654321);
}

}  // namespace flood
