#include "flood/check/verify.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "check/validate_paths.h"
#include "flood/check/touches.h"
#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"

namespace flood {
namespace {

// Sides lo' < lo and hi' > hi (exact) for coordinates in [lo, hi]: the next multiples of a
// power of two w at least the span (and at least 2^-50 of the magnitude, so that hi / w + 1 is
// exact), a margin as large as the polygon, clamped at +-DBL_MAX. False when no double lies
// beyond (a coordinate is +-DBL_MAX). At subnormal magnitudes 2^-50 of it is below the least
// double, 2^-1074, which w stays at: every double is a multiple of it (and w = 0 would never
// grow to the span).
bool beyond(double lo, double hi, double& outLo, double& outHi) {
    constexpr int kLeastExponent = DBL_MIN_EXP - DBL_MANT_DIG;  // 2^-1074, the least subnormal
    double big = std::max(std::fabs(lo), std::fabs(hi));
    double w = big == 0 ? 1 : std::ldexp(1.0, std::max(std::ilogb(big) - 50, kLeastExponent));
    while (w < hi - lo && std::isfinite(w)) w *= 2;  // hi - lo may be inf: w overflows too
    if (!std::isfinite(w)) w = std::ldexp(1.0, DBL_MAX_EXP - 1);
    outHi = (std::floor(hi / w) + 1) * w;
    outLo = (std::ceil(lo / w) - 1) * w;
    if (std::isinf(outHi)) outHi = DBL_MAX;
    if (std::isinf(outLo)) outLo = -DBL_MAX;
    return outHi > hi && outLo < lo;
}

enum class Side { Inside, Outside, Boundary };

// Where p lies relative to the ring (exact crossing count of a ray to +x).
Side locate(const Polygon& P, const Ring& ring, Point p) {
    bool inside = false;
    for (Index i = 0; i < ring.count; ++i) {
        Point a = P.vertices[ring.first + i], b = P.vertices[ring.first + (i + 1) % ring.count];
        if (p == a) return Side::Boundary;
        if (std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y) && insideSegment(a, b, p))
            return Side::Boundary;
        if ((a.y > p.y) != (b.y > p.y) && (orient(a, b, p) > 0) == (b.y > a.y)) inside = !inside;
    }
    return inside ? Side::Inside : Side::Outside;
}

struct Box {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    void add(Point p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;  // the floods refuse those
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
        y1 = std::max(y1, p.y);
    }
    bool empty() const { return x0 > x1; }
    bool contains(const Box& b) const {
        return x0 <= b.x0 && b.x1 <= x1 && y0 <= b.y0 && b.y1 <= y1;
    }
};

Box ringBox(const Polygon& P, const Ring& r) {
    Box b;
    for (Index v = r.first; v < r.first + r.count; ++v) b.add(P.vertices[v]);
    return b;
}

// The innermost hole of another part that each part lies in (kNone: none), by one exact
// point location per part and hole whose boxes nest: for a polygon that is not valid
// (`flood verify --no-validate`), whose holes around a part need not form a chain; the
// innermost is the one whose own part lies in the most holes. A point location for each hole
// around each part: quadratic on deep nesting, which innermostHoles() spares valid input.
std::vector<Index> nestByPointLocation(const Polygon& P, const std::vector<Index>& partOfRing,
                                       std::vector<Index> holes) {
    const size_t parts = P.parts.size();
    std::vector<std::vector<Index>> containing(parts);
    // A ring with a non-finite coordinate nests nowhere (the floods refuse it).
    auto finite = [&](Index r) {
        for (Index v = P.rings[r].first; v < P.rings[r].first + P.rings[r].count; ++v)
            if (!std::isfinite(P.vertices[v].x) || !std::isfinite(P.vertices[v].y)) return false;
        return true;
    };
    holes.erase(std::remove_if(holes.begin(), holes.end(), [&](Index h) { return !finite(h); }),
                holes.end());
    std::vector<Box> holeBox(P.rings.size()), partBox(parts);
    for (Index h : holes) holeBox[h] = ringBox(P, P.rings[h]);
    for (Index k = 0; k < parts; ++k) partBox[k] = ringBox(P, P.rings[P.parts[k].firstRing]);
    // Sweep in x: holes enter at their left side; a part is tested against the active holes.
    std::vector<Index> order(parts);
    for (Index k = 0; k < parts; ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](Index a, Index b) { return partBox[a].x0 < partBox[b].x0; });
    std::sort(holes.begin(), holes.end(),
              [&](Index a, Index b) { return holeBox[a].x0 < holeBox[b].x0; });
    std::vector<Index> active;
    size_t nextHole = 0;
    for (Index k : order) {
        const Box& pb = partBox[k];
        if (pb.empty() || !finite(P.parts[k].firstRing)) continue;
        while (nextHole < holes.size() && holeBox[holes[nextHole]].x0 <= pb.x0)
            active.push_back(holes[nextHole++]);
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [&](Index h) { return holeBox[h].x1 < pb.x0; }),
                     active.end());
        const Ring& outer = P.rings[P.parts[k].firstRing];
        for (Index h : active) {
            ++work().nestingSteps;
            if (partOfRing[h] == k || !holeBox[h].contains(pb)) continue;
            Side s = Side::Boundary;
            for (Index v = outer.first; v < outer.first + outer.count && s == Side::Boundary; ++v) {
                work().nestingSteps += P.rings[h].count;
                s = locate(P, P.rings[h], P.vertices[v]);
            }
            if (s != Side::Outside) containing[k].push_back(h);  // all on its boundary: inside
        }
    }
    std::vector<Index> innermost(parts, kNone);
    for (Index k = 0; k < parts; ++k)
        for (Index h : containing[k])
            if (innermost[k] == kNone ||
                containing[partOfRing[h]].size() > containing[partOfRing[innermost[k]]].size())
                innermost[k] = h;
    return innermost;
}

}  // namespace

// On a valid polygon the holes around a part form a chain, and the innermost one is the ring
// just around its outer ring, which validation's sweep finds for check 6 (validateNesting()):
// the same hole as the point locations find, whose interior holds the part.
std::vector<Index> innermostHoles(const Polygon& P, bool pointLocation) {
    const size_t parts = P.parts.size();
    std::vector<Index> partOfRing(P.rings.size());
    std::vector<Index> holes;  // rings that bound an area and are not outer
    for (Index k = 0; k < parts; ++k)
        for (Index r = P.parts[k].firstRing; r < P.parts[k].firstRing + P.parts[k].ringCount; ++r) {
            partOfRing[r] = k;
            if (r != P.parts[k].firstRing && P.rings[r].count > 1) holes.push_back(r);
        }
    if (holes.empty() || parts < 2) return std::vector<Index>(parts, kNone);
    Polygon copy = P;  // validation records the T-junctions it finds in it
    std::vector<Index> enclosing;
    if (!pointLocation && validateNesting(copy, "polygon", enclosing).ok()) {
        std::vector<Index> innermost(parts, kNone);
        bool lakes = true;  // each part in nothing or in a hole of another part
        for (Index k = 0; k < parts && lakes; ++k) {
            ++work().nestingSteps;
            const Index e = enclosing[P.parts[k].firstRing];
            lakes = e == kNone || (partOfRing[e] != k && P.parts[partOfRing[e]].firstRing != e &&
                                   P.rings[e].count > 1);
            innermost[k] = e;
        }
        if (lakes) return innermost;
    }
    return nestByPointLocation(P, partOfRing, std::move(holes));
}

namespace {

// The box's sides x0, y0, x1, y1 beyond the polygon; false when a side has no double beyond.
bool boxAround(const Polygon& p, double side[4]) {
    Box b;
    for (Point q : p.vertices) b.add(q);
    if (b.empty()) b = {0, 0, 0, 0};
    bool x = beyond(b.x0, b.x1, side[0], side[2]);
    return beyond(b.y0, b.y1, side[1], side[3]) && x;
}

}  // namespace

Polygon complementOf(const Polygon& input) {
    double side[4];
    Polygon halved;
    bool useHalved = false;
    if (!boxAround(input, side)) {  // a coordinate is +-DBL_MAX: halve everything if that is exact
        halved = input;
        bool exact = true;
        for (Point& p : halved.vertices) {
            Point h{p.x * 0.5, p.y * 0.5};
            exact &= h.x * 2 == p.x && h.y * 2 == p.y;
            p = h;
        }
        // Otherwise the box touches the polygon at DBL_MAX (the floods then judge it).
        if (exact) useHalved = boxAround(halved, side);
    }
    const Polygon& polygon = useHalved ? halved : input;
    const double x0 = side[0], y0 = side[1], x1 = side[2], y1 = side[3];
    auto ring = [&](Index r) {
        const Ring& g = polygon.rings[r];
        return std::vector<Point>(polygon.vertices.begin() + g.first,
                                  polygon.vertices.begin() + g.first + g.count);
    };
    std::vector<Index> innermost = innermostHoles(polygon);
    // The islands of each lake, in part order: lake r's are islands[start[r] .. start[r + 1]).
    const size_t parts = polygon.parts.size();
    std::vector<Index> start(polygon.rings.size() + 1, 0), islands(parts);
    for (Index k = 0; k < parts; ++k)
        if (innermost[k] != kNone) ++start[innermost[k] + 1];
    for (size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index k = 0; k < parts; ++k)
        if (innermost[k] != kNone) islands[fill[innermost[k]]++] = k;
    Polygon c;
    c.addRing({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, true);
    for (Index k = 0; k < parts; ++k)
        if (innermost[k] == kNone) c.addRing(ring(polygon.parts[k].firstRing), false);
    // Each lake a part, the islands in it its holes; a point hole has no complement.
    for (const Part& part : polygon.parts)
        for (Index r = part.firstRing + 1; r < part.firstRing + part.ringCount; ++r) {
            if (polygon.rings[r].count <= 1) continue;
            c.addRing(ring(r), true);
            for (Index i = start[r]; i < start[r + 1]; ++i)
                c.addRing(ring(polygon.parts[islands[i]].firstRing), false);
        }
    // Parts that touched at a T-junction are now rings of one part touching there.
    findTouches(c);
    return c;
}

const char* caughtName(Caught c) {
    switch (c) {
        case Caught::Nothing: return "nothing";
        case Caught::Polygon: return "polygon";
        case Caught::Complement: return "complement";
        case Caught::Checker: return "checker";
    }
    return "?";
}

Caught Verification::caught() const {
    if (!flood.diagnostic.ok()) return Caught::Polygon;
    if (!complementFlood.diagnostic.ok()) return Caught::Complement;
    if (!check.ok || !complementCheck.ok) return Caught::Checker;
    return Caught::Nothing;
}

Verification verify(const Polygon& polygon, const Options& options) {
    Verification v;
    v.flood = triangulate(polygon, nullptr, options);
    if (v.flood.diagnostic.ok()) v.check = checkTriangulation(polygon, v.flood.triangles);
    Polygon complement = complementOf(polygon);
    v.complementFlood = triangulate(complement, nullptr, options);
    if (v.complementFlood.diagnostic.ok())
        v.complementCheck = checkTriangulation(complement, v.complementFlood.triangles);
    return v;
}

std::string Verification::summary() const {
    auto side = [](const char* what, const FloodResult& f, const CheckResult& c) {
        std::string s = what;
        if (!f.diagnostic.ok()) return s + ": flooding stopped: " + f.diagnostic.message;
        if (!c.ok)
            return s + ": " + std::to_string(f.triangles.size()) +
                   " triangles, NOT a triangulation: " + c.reason;
        return s + ": " + std::to_string(f.triangles.size()) + " triangles, exact triangulation";
    };
    return side("polygon", flood, check) + "\n" +
           side("complement", complementFlood, complementCheck);
}

}  // namespace flood
