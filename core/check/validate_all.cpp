// validateAll(): every finding of validate()'s checks, not only the first.
#include <algorithm>

#include "check/validator.h"

namespace flood {
namespace validate_detail {

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

}  // namespace validate_detail

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
    validate_detail::Scratch fresh;
    validate_detail::Validator v(polygon, name, fresh);
    v.sink = [&](Diagnostic&& d) {
        if (d.message == verdict) return;  // listed first already
        if (out.list.size() < std::max<size_t>(1, maxFindings)) out.list.push_back(std::move(d));
        else ++out.omitted;
    };
    v.collectAll(out.complete);
    return out;
}

}  // namespace flood
