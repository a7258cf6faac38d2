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
// their 2k rays and O(log k) per ring to find a crossing (validatorSteps in flood/geometry/work.h
// counts the work, tests/check/validate_growth_test.cpp bounds it). A small polygon is checked
// by testing its pairs of edges instead of sweeping (pairsClear()), its rings then nested by
// winding numbers, with the sweep's verdicts (tests/check/validate_paths_test.cpp). The sweep
// itself runs first with only the tests Shamos-Hoey needs (sweepEdges(minimal)), and again
// with all of them, whose order fixes the message, only when that one finds a problem. A MultiPolygon whose parts fall into groups
// that lines set apart is validated group by group (validate_groups.cpp), and whole only when
// a group fails, so the message is still the whole sweep's.
//
// Where each check lives: this file holds checks 1-3 and 6, the order they run in and the
// entry points; check 4 is validate_edges.cpp, check 5 validate_touches.cpp, every finding
// (validateAll()) validate_all.cpp, the groups of parts validate_groups.cpp; the validator's
// state is check/validator.h.
#include <string>

#include "check/validate_paths.h"
#include "check/validator.h"
#include "flood/geometry/ring_area.h"

namespace flood {
namespace validate_detail {

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

}  // namespace validate_detail

namespace {

using validate_detail::kGroupsFrom;
using validate_detail::kReusedUpTo;
using validate_detail::Scratch;
using validate_detail::Validator;
using validate_detail::validGroupByGroup;

// Small polygons reuse this thread's scratch; a large one gets its own, freed on return, so
// that no thread keeps a large polygon's arrays (flooding comes next and needs the memory).
// `shortcuts`: the pair test of a small ring, the minimal sweep, a MultiPolygon group by group.
Diagnostic validateIn(Polygon& polygon, const std::string& name, bool shortcuts,
                      std::vector<Index>* enclosing, const TaskRunner& run = {}) {
    thread_local Scratch reused;
    if (shortcuts && polygon.vertices.size() >= kGroupsFrom &&
        validGroupByGroup(polygon, name, reused, enclosing, run))
        return {};
    Scratch fresh;
    Validator v(polygon, name, polygon.vertices.size() <= kReusedUpTo ? reused : fresh);
    v.pairsFirst = shortcuts;
    Diagnostic d = v.run();
    polygon.splits.assign(d.ok() ? v.splits.begin() : v.splits.end(), v.splits.end());
    polygon.pointsDistinct = d.ok() && v.touchPoints.empty();  // check 5 grouped every shared point
    if (enclosing)
        enclosing->assign(d.ok() ? v.enclosing.begin() : v.enclosing.end(), v.enclosing.end());
    return d;
}

}  // namespace

Diagnostic validateBySweep(Polygon& polygon, const std::string& name,
                           std::vector<Index>* enclosing) {
    return validateIn(polygon, name, false, enclosing);
}

Diagnostic validateNesting(Polygon& polygon, const std::string& name,
                           std::vector<Index>& enclosing) {
    return validateIn(polygon, name, true, &enclosing);
}

Diagnostic validate(Polygon& polygon, const std::string& name, const TaskRunner& run) {
    return validateIn(polygon, name, true, nullptr, run);
}

}  // namespace flood
