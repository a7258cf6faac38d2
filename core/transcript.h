// The paper's transcript of a run (Fig. 7): "Raise 0-7, Spill; Raise 8-12, Jump; ...".
#pragma once
#include <string>
#include <vector>

#include "events.h"

namespace flood {

// Consecutive raises are one item "Raise first-last" (their triangles); an action that cut
// triangles shows their range; items are separated by ", " and a Spill, Jump or Fill ends a
// group with "; ". Start events are not part of the paper's vocabulary and are omitted.
std::string transcript(const std::vector<Event>& events);

// The triangle range of an item: "8-12", "8" or "" when it cut none.
std::string triangleRange(uint32_t first, uint32_t count);

}  // namespace flood
