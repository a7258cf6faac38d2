// Check 5 of validate(): where rings meet at a point (a shared vertex or a T-junction) they
// touch without crossing, and the touches keep each part's interior connected.
#include <algorithm>

#include "check/validator.h"

namespace flood {
namespace validate_detail {

// --- check 5: rings meeting at a point ---------------------------------------------------

// Groups the ring passages through each touching point: coincident vertices, plus the edge
// of every T-junction, which passes straight through its vertex's point. Then picks the
// machine's splits: a junction whose edge's part has a vertex at the point (the lowest one).
void Validator::collectTouchPoints() {
    // The repeated points (most inputs have none) in coordinate order (x, then y), each
    // point's vertices by index.
    std::sort(copies.begin(), copies.end(),
              [&](std::pair<Index, Index> a, std::pair<Index, Index> b) {
                  Point p = pt(a.first), q = pt(b.first);
                  if (p.x != q.x) return p.x < q.x;
                  if (p.y != q.y) return p.y < q.y;
                  return a.second < b.second;
              });
    groupOf.assign(n, kNone);
    auto vertexOccurrence = [&](Index v) {
        return Occurrence{v, ringOfV[v], pt(prev(v)), pt(next(v))};
    };
    for (size_t i = 0; i < copies.size();) {
        const Index first = copies[i].first, group = Index(touchPoints.size());
        groupOf[first] = group;
        std::vector<Occurrence> occ{vertexOccurrence(first)};
        for (; i < copies.size() && copies[i].first == first; ++i) {
            groupOf[copies[i].second] = group;
            occ.push_back(vertexOccurrence(copies[i].second));
        }
        touchPoints.push_back(std::move(occ));
    }
    for (Index k = 0; k < junctions.size(); ++k) {
        Index v = junctions[k].vertex, e = junctions[k].edge;
        if (groupOf[v] == kNone) {
            groupOf[v] = Index(touchPoints.size());
            touchPoints.push_back({vertexOccurrence(v)});
        }
        touchPoints[groupOf[v]].push_back({Index(n + k), ringOfV[e], pt(e), pt(next(e))});
    }
    // At most one edge passes through a point (two would cross: check 4), so this is linear.
    for (const EdgeSplit& j : junctions) {
        Index part = partOfRing[ringOfV[j.edge]];
        for (const Occurrence& o : touchPoints[groupOf[j.vertex]]) {
            ++work().validatorSteps;
            if (o.owner < n && partOfRing[o.ring] == part) {
                splits.push_back({j.edge, o.owner});
                break;
            }
        }
    }
}

// The lowest chord crossing another, of chords drawn between the two positions of each index
// in `chordAt` (2k positions round a circle, each index 0..k-1 twice), and the lowest chord it
// crosses; {kNone, kNone} when no two cross. Chord c spanning positions a0 < a1 crosses
// another exactly when a position strictly between holds a chord whose other end lies outside
// [a0, a1]: a range-minimum and a range-maximum query of the other ends, O(k log k) in all.
std::pair<Index, Index> lowestCrossingChords(const std::vector<Index>& chordAt) {
    size_t m = chordAt.size(), k = m / 2;
    std::vector<size_t> first(k, m), second(k, m), other(m);
    for (size_t i = 0; i < m; ++i) (first[chordAt[i]] == m ? first : second)[chordAt[i]] = i;
    for (size_t i = 0; i < m; ++i)
        other[i] = first[chordAt[i]] == i ? second[chordAt[i]] : first[chordAt[i]];
    // Bottom-up segment trees over the positions: leaves at m + i.
    std::vector<size_t> lo(2 * m), hi(2 * m);
    for (size_t i = 0; i < m; ++i) lo[m + i] = hi[m + i] = other[i];
    for (size_t i = m - 1; i > 0; --i) {
        lo[i] = std::min(lo[2 * i], lo[2 * i + 1]);
        hi[i] = std::max(hi[2 * i], hi[2 * i + 1]);
    }
    auto crossesSome = [&](size_t a0, size_t a1) {  // over positions (a0, a1)
        size_t least = m, most = 0;
        for (size_t l = a0 + 1 + m, r = a1 + m; l < r; l /= 2, r /= 2) {
            ++work().validatorSteps;
            if (l & 1) least = std::min(least, lo[l]), most = std::max(most, hi[l]), ++l;
            if (r & 1) --r, least = std::min(least, lo[r]), most = std::max(most, hi[r]);
        }
        return least < a0 || most > a1;
    };
    for (Index c = 0; c < k; ++c) {
        if (!crossesSome(first[c], second[c])) continue;
        for (Index d = 0; d < k; ++d) {
            ++work().validatorSteps;
            bool in0 = first[c] < first[d] && first[d] < second[c];
            bool in1 = first[c] < second[d] && second[d] < second[c];
            if (in0 != in1) return {c, d};
        }
    }
    return {kNone, kNone};
}

Diagnostic Validator::checkSharedVertices() {
    if (copies.empty() && junctions.empty()) return {};  // no rings meet: nothing to check
    collectTouchPoints();
    // Around each touching point, every passage contributes a wedge of two rays (to where it
    // comes from and goes to). The rings cross there exactly when two wedges interleave.
    struct Ray {
        Point to;
        Index occ;   // the passage (index into the point's list) whose wedge this ray bounds
        bool after;  // the polygon's interior lies just counter-clockwise of this ray
    };
    std::vector<Ray> rays;
    std::vector<Index> chordAt;
    for (const std::vector<Occurrence>& occ : touchPoints) {
        Point p = pt(occ[0].owner);
        bool pointHole = false;
        for (const Occurrence& o : occ)
            if (o.owner < n && isPoint(o.owner)) {
                const Occurrence& other = o.owner == occ[0].owner ? occ[1] : occ[0];
                Culprits c = atPoint(o.owner);
                blame(c, other);
                Diagnostic d = fail(o.owner,
                                    "point hole coincides with " + occurrenceText(other) +
                                        " (a Steiner point must be strictly inside the polygon)",
                                    c);
                if (stopAt(d)) return d;
                pointHole = true;
                break;
            }
        if (pointHole) continue;  // collecting: the wedges of a point hole mean nothing
        rays.clear();
        for (Index i = 0; i < occ.size(); ++i) {
            const Occurrence& o = occ[i];
            // Walking from -> p -> to, the ring's inside is on the left for a counter-clockwise
            // ring; the polygon's interior is the other side for a hole.
            bool nextAfter =
                (ringSign[o.ring] > 0) != (P.parts[partOfRing[o.ring]].firstRing != o.ring);
            rays.push_back({o.from, i, !nextAfter});
            rays.push_back({o.to, i, nextAfter});
        }
        std::sort(rays.begin(), rays.end(),
                  [&](const Ray& a, const Ray& b) { return angleLess(p, a.to, b.to); });
        // Messages name a vertex: the lowest one among the passages involved.
        auto vertexOf = [&](Index i) {
            Index owner = occ[i].owner;
            return owner < n ? owner : junctions[owner - n].vertex;
        };
        bool junction =
            std::any_of(occ.begin(), occ.end(), [&](const Occurrence& o) { return o.owner >= n; });
        const std::string here = junction ? "at this touching point" : "at this shared vertex";
        chordAt.clear();
        for (const Ray& r : rays) chordAt.push_back(r.occ);
        // The interleaving pair with the lowest passages (occ is sorted by owner), for a
        // stable message.
        auto [c, d] = lowestCrossingChords(chordAt);
        if (c != kNone) {
            Culprits also = atPoint(vertexOf(c));
            blame(also, occ[d]);
            Diagnostic found =
                fail(vertexOf(c),
                     "the boundary crosses itself " + here + " (" + occurrenceText(occ[d]) +
                         " passes through to the other side)",
                     also);
            if (stopAt(found)) return found;
            continue;  // collecting: one finding a point
        }
        // Sectors between consecutive rays must alternate interior / exterior; otherwise two
        // loops overlap here (a loop nested in another with the same orientation, a hole
        // nested in a hole, or a part touching another from inside).
        for (size_t i = 0; i < rays.size(); ++i) {
            ++work().validatorSteps;
            const Ray& a = rays[i];
            const Ray& b = rays[(i + 1) % rays.size()];
            if (a.after == b.after) {
                Index u = std::min(a.occ, b.occ), w = std::max(a.occ, b.occ);
                Culprits also = atPoint(vertexOf(u));
                if (u != w) blame(also, occ[w]);
                Diagnostic found =
                    fail(vertexOf(u),
                         "the interior overlaps itself " + here + " (" +
                             (u == w ? std::string("a ring") : occurrenceText(occ[w])) +
                             " touches here from the inside, with the "
                             "orientation of a nested loop or hole)",
                         also);
                if (stopAt(found)) return found;
                break;  // collecting: one finding a point
            }
        }
    }
    return checkTouchTopology();
}

// Touching is allowed only where it keeps the interior connected and every ring simple (as
// GEOS rules): a ring may not touch itself, and the rings of a part touching each other may not
// close a cycle (two rings touching twice, or three touching in a ring cut the interior in two).
// Rings of different parts may touch anywhere they do not cross (parts are flooded apart).
Diagnostic Validator::checkTouchTopology() {
    std::vector<Index> parent(P.rings.size());
    for (Index r = 0; r < parent.size(); ++r) parent[r] = r;
    auto find = [&](Index r) {
        while (parent[r] != r) r = parent[r] = parent[parent[r]];
        return r;
    };
    // Per point: where each ring passed (ringAt), and each part's first ring there (partRing),
    // valid while their stamp is the point's.
    std::vector<Index> ringStamp(P.rings.size(), kNone), ringAt(P.rings.size());
    std::vector<Index> partStamp(P.parts.size(), kNone), partRing(P.parts.size());
    for (Index t = 0; t < touchPoints.size(); ++t) {
        const std::vector<Occurrence>& occ = touchPoints[t];
        for (Index i = 0; i < occ.size(); ++i) {
            ++work().validatorSteps;
            const Occurrence& b = occ[i];
            Index at = b.owner < n ? b.owner : junctions[b.owner - n].vertex;
            if (ringStamp[b.ring] == t) {
                Culprits also = atPoint(at);
                blame(also, occ[ringAt[b.ring]]);
                Diagnostic d =
                    fail(at,
                         "the ring touches itself here (it also passes through " +
                             occurrenceText(occ[ringAt[b.ring]]) + "): a ring must be simple",
                         also);
                if (stopAt(d)) return d;
                continue;
            }
            ringStamp[b.ring] = t, ringAt[b.ring] = i;
            Index part = partOfRing[b.ring];
            if (partStamp[part] != t) {
                partStamp[part] = t, partRing[part] = b.ring;
                continue;
            }
            Index ra = find(partRing[part]), rb = find(b.ring);
            if (ra == rb) {
                Culprits also = atPoint(at);
                also.rings = {partRing[part], b.ring};
                Diagnostic d = fail(at,
                                    "rings touching here and elsewhere enclose part of the "
                                    "interior: the interior is disconnected",
                                    also);
                if (stopAt(d)) return d;
                continue;
            }
            parent[ra] = rb;
        }
    }
    return {};
}
}  // namespace validate_detail
}  // namespace flood
