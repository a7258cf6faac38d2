// The walk of a Spill (spill_walk.h).
#include "machine/spill_walk.h"

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "machine/machine.h"

namespace flood {

Landing walkDown(const Heights& h, const std::vector<GorgeRec>& gorges, Stretches& walked, NodeId t,
                 bool goPrev, uint32_t partNodes) {
    const Nodes& nodes = h.nodes();
    auto prev = [&](NodeId n) { return nodes[n].prev; };
    auto next = [&](NodeId n) { return nodes[n].next; };
    NodeId x = goPrev ? prev(t) : next(t);
    // `drops` counts sags the water fell from whose landing is not settled yet: a sag
    // followed by a ceiling roofs the basin below it (the next bottom is its floor); a
    // sag followed by a top is matched by the bottom of the pocket beyond that top.
    int64_t drops = 0;
    const int dir = goPrev ? 0 : 1;
    const std::vector<Stretches::Position>& pos = walked.positions;
    size_t run = pos.size();  // first position of the stretch this walk records
    int32_t recorded = 0;     // its count's change so far, once it has a position
    for (uint32_t guard = 0; guard <= partNodes; ++guard, x = goPrev ? prev(x) : next(x)) {
        ++work().nodeVisits;
        const Ends& ends = nodes.ends(x);
        const bool wet = nodes.wet(x);
        uint32_t g = goPrev ? ends.gorgeRight : ends.gorgeLeft;
        if (g != kNoGorge && !gorges[g].done && !gorges[g].held) {
            walked.close(run);
            return {g, kNil};
        }
        if (ends.gorgeLeft != kNoGorge || ends.gorgeRight != kNoGorge || x == t) break;
        // Only extremes matter to the walk; the orientation test is spent on them alone
        // (and on every maximum of a stretch being recorded: a later walk may need it).
        const uint32_t at = walked.recordedAt(dir, x);
        const bool fresh = at == kNone && !wet;
        bool minimum = h.lower(x, prev(x)) && h.lower(x, next(x));
        bool maximum = !minimum && h.lower(prev(x), x) && h.lower(next(x), x);
        bool convexHere = (minimum || (maximum && (drops > 0 || fresh))) &&
                          orient(h.at(prev(x)), h.at(x), h.at(next(x))) > 0;
        bool sag = minimum && !convexHere, sensitive = convexHere;  // ceilings and bottoms
        if (fresh) {
            int32_t before = pos.size() > run ? recorded : 0;
            recorded = before + (sag ? 1 : sensitive ? -1 : 0);
            walked.record(dir, {x, uint32_t(walked.stretches.size()), before}, sensitive,
                          nodes.end());
        } else {
            walked.close(run);
        }
        if (sag) {
            ++drops;
        } else if (sensitive && drops > 0) {
            --drops;  // a bottom beyond a top, or a ceiling roofing the basin under the last sag
        } else if (minimum && sensitive && !wet) {
            walked.close(run);
            return {kNoGorge, x};
        }
        if (!fresh && at != kNone && !wet) {
            // Cross the stretch beyond x in one step, up to the node before the first one
            // that got wet since (its links may have changed) and before the first bottom
            // or ceiling the count would reach at zero (it may be the landing): none of
            // the nodes crossed can end the walk, and the count changes by their sum. The
            // stretch's tree finds whichever comes first (a wet node holds INT32_MIN).
            const Stretches::Stretch& rec = walked.stretches[pos[at].stretch];
            const uint32_t a = at + 1;
            if (a < rec.end) {
                uint32_t f = walked.firstAtMost(rec, a - rec.start, int64_t(pos[a].drops) - drops) +
                             rec.start;
                // One past the last node crossed: a wet node (or the stretch's end) is not
                // reached, nor the node before it; a zero-count node is reached live.
                uint32_t b = f == rec.end || nodes.wet(pos[f].node) ? f - 1 : f;
                if (b > a && guard + (b - a) <= partNodes) {
                    drops += pos[b].drops - pos[a].drops;
                    guard += b - a;
                    x = pos[b - 1].node;
                }
            }
        }
    }
    walked.close(run);
    return {};
}

}  // namespace flood
