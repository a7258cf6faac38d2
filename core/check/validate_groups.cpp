// validate() on a MultiPolygon, group by group (core/geometry/boxes_apart.h): parts whose
// boxes a line separates cannot cross, touch or lie inside one another, so checks 4-6 between
// them have nothing to find, and each group is validated alone as a polygon of its own. Only
// a valid polygon is decided here: when a group fails, the caller validates the whole
// polygon, so that the first problem reported, and its message, are the ones the whole
// sweep finds.
#include <atomic>

#include "check/validator.h"
#include "geometry/boxes_apart.h"

namespace flood {
namespace validate_detail {

bool validGroupByGroup(Polygon& polygon, const std::string& name, Scratch& reused,
                       std::vector<Index>* enclosing, const TaskRunner& run) {
    const Polygon& P = polygon;
    if (P.parts.size() < 2) return false;
    // Else the whole polygon is validated, so that nothing outside the groups goes unchecked.
    if (!P.tiled()) return false;
    std::vector<Box> boxes(P.parts.size());
    for (Index k = 0; k < P.parts.size(); ++k) {
        const Part& part = P.parts[k];
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r)
            for (Index v = P.rings[r].first; v < P.rings[r].first + P.rings[r].count; ++v) {
                if (!std::isfinite(P.vertices[v].x) || !std::isfinite(P.vertices[v].y))
                    return false;  // check 1 fails: the whole polygon reports it
                boxes[k].add(P.vertices[v]);
            }
    }
    size_t groupCount = 0;
    const std::vector<Index> groupOf = groupsApart(boxes, groupCount);
    if (groupCount < 2) return false;
    // The parts of each group, in order: a counting sort.
    std::vector<Index> start(groupCount + 1, 0), parts(P.parts.size());
    for (Index g : groupOf) ++start[g + 1];
    for (size_t g = 0; g < groupCount; ++g) start[g + 1] += start[g];
    {
        std::vector<Index> fill(start.begin(), start.end() - 1);
        for (Index k = 0; k < P.parts.size(); ++k) parts[fill[groupOf[k]]++] = k;
    }
    // The groups in runs of about equal size, a task each: a task validates its groups in
    // order, each as a polygon of its own, until one fails.
    std::vector<size_t> groupSize(groupCount, 0);
    for (Index k = 0; k < P.parts.size(); ++k) groupSize[groupOf[k]] += P.partVertices(k);
    const std::vector<size_t> runs =
        cutEvenly(groupCount, run ? kGroupTasks : 1, [&](size_t g) { return groupSize[g]; });
    struct Task {
        std::vector<EdgeSplit> splits;
        bool pointsDistinct = true, valid = true;
    };
    std::vector<Task> tasks(runs.size() - 1);
    std::atomic<bool> failed{false};
    if (enclosing) enclosing->assign(P.rings.size(), kNone);  // each task writes its own rings
    runTasks(run, tasks.size(), [&](size_t t) {
        Task& task = tasks[t];
        Scratch taskScratch;  // the caller's thread-kept scratch is lent only to a lone task
        Scratch& small = tasks.size() == 1 ? reused : taskScratch;
        Polygon sub;                          // the group as a polygon, its vertices and rings
        std::vector<Index> vertexOf, ringOf;  // numbered from 0: their numbers in `polygon`
        for (size_t g = runs[t]; g < runs[t + 1] && !failed; ++g) {
            sub.vertices.clear(), sub.rings.clear(), sub.parts.clear();
            vertexOf.clear(), ringOf.clear();
            for (Index i = start[g]; i < start[g + 1]; ++i) {
                const Part& part = P.parts[parts[i]];
                sub.parts.push_back({Index(sub.rings.size()), part.ringCount});
                for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
                    const Ring& ring = P.rings[r];
                    sub.rings.push_back({Index(sub.vertices.size()), ring.count});
                    ringOf.push_back(r);
                    for (Index v = ring.first; v < ring.first + ring.count; ++v) {
                        sub.vertices.push_back(P.vertices[v]);
                        vertexOf.push_back(v);
                    }
                }
            }
            Scratch fresh;  // for a large group: not kept by the thread
            Validator v(sub, name, sub.vertices.size() <= kReusedUpTo ? small : fresh);
            if (!v.run().ok()) {
                task.valid = false;
                failed = true;
                return;
            }
            for (const EdgeSplit& s : v.splits)
                task.splits.push_back({vertexOf[s.edge], vertexOf[s.vertex]});
            task.pointsDistinct = task.pointsDistinct && v.touchPoints.empty();
            if (enclosing)
                for (Index r = 0; r < sub.rings.size(); ++r)
                    if (v.enclosing[r] != kNone) (*enclosing)[ringOf[r]] = ringOf[v.enclosing[r]];
        }
    });
    if (failed) return false;
    std::vector<EdgeSplit> splits;
    bool pointsDistinct = true;
    for (Task& task : tasks) {
        splits.insert(splits.end(), task.splits.begin(), task.splits.end());
        pointsDistinct = pointsDistinct && task.pointsDistinct;
    }
    // Splits of one edge come from one group, in the order validate() gives them.
    std::stable_sort(splits.begin(), splits.end(),
                     [](const EdgeSplit& a, const EdgeSplit& b) { return a.edge < b.edge; });
    polygon.splits = std::move(splits);
    polygon.pointsDistinct = pointsDistinct;
    return true;
}

}  // namespace validate_detail
}  // namespace flood
