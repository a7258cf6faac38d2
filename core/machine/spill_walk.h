// The walk of a Spill (§5, Fig. 5): from a top without a jump pointer, down its far side to
// where the water lands, skipping the sags it drips from. Stretches already walked are crossed
// in one step (stretches.h), so walks from the tops along a spiral arm do not retrace the arm.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <vector>

#include "machine/heights.h"
#include "machine/stretches.h"

namespace flood {

struct GorgeRec;  // machine.h

// Where the water of a Spill lands: a pending gorge met on the way (it collects the water), or
// else a dry bottom; neither when the walk cannot tell.
struct Landing {
    uint32_t gorge = kNoGorge;
    NodeId bottom = kNil;
};

// Walks from top t prev-wards (goPrev) or next-wards; `partNodes` bounds the walk.
Landing walkDown(const Heights& heights, const std::vector<GorgeRec>& gorges, Stretches& walked,
                 NodeId t, bool goPrev, uint32_t partNodes);

}  // namespace flood
