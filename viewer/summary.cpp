#include "summary.h"

namespace flood::view {

FloodSummary summarizeFlood(const Trace& trace, const std::vector<VertexClass>& classes) {
    FloodSummary s;
    for (VertexClass c : classes) ++s.classes[size_t(c)];
    for (const Event& e : trace.events) {
        ++s.actions[size_t(e.action)];
        s.gorges += e.bottom != kNone;
    }
    s.triangles = uint32_t(trace.triangles.size());
    return s;
}

std::vector<SummaryChange> compareSummaries(const FloodSummary& before, const FloodSummary& after) {
    std::vector<SummaryChange> out;
    out.push_back({"gorges", before.gorges, after.gorges});
    for (VertexClass c :
         {VertexClass::Bottom, VertexClass::Sag, VertexClass::Top, VertexClass::Ceiling})
        out.push_back({std::string(vertexClassName(c)) + "s", before.classes[size_t(c)],
                       after.classes[size_t(c)]});
    for (size_t a = 0; a < size_t(Action::Count); ++a)
        if (Action(a) != Action::Forbidden || before.actions[a] || after.actions[a])
            out.push_back({actionName(Action(a)), before.actions[a], after.actions[a]});
    out.push_back({"triangles", before.triangles, after.triangles});
    return out;
}

}  // namespace flood::view
