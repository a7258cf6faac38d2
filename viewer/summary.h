// The direction dial's numbers: how a run decomposed the polygon along its direction.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flood/log/replay.h"
#include "flood/machine/vertex_class.h"

namespace flood::view {

// How a run decomposed the polygon along its direction: the vertex classes that direction
// gives (§3), the gorges flooded from a bottom, and the count of each action. The paper's
// remark that the decomposition into gorges is not unique, as numbers (the direction dial).
struct FloodSummary {
    std::array<uint32_t, size_t(VertexClass::Count)> classes{};  // bottoms, sags, tops, ceilings
    uint32_t gorges = 0;  // gorges started at a bottom (Start, and each later bottom reached)
    std::array<uint32_t, size_t(Action::Count)> actions{};
    uint32_t triangles = 0;
};
FloodSummary summarizeFlood(const Trace& trace, const std::vector<VertexClass>& classes);
// One line per quantity, in a fixed order: its name, before and after ("gorges", 3, 5).
struct SummaryChange {
    std::string what;
    int64_t before = 0, after = 0;
    bool changed() const { return before != after; }
};
std::vector<SummaryChange> compareSummaries(const FloodSummary& before, const FloodSummary& after);

}  // namespace flood::view
