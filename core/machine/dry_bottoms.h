// The to-do list of last resort (§4): the part's bottoms, every one of which starts a gorge
// unless the water reaches it first. Internal to core/, not a public API.
#pragma once
#include <cstdint>
#include <vector>

#include "machine/heights.h"

namespace flood {

class DryBottoms {
public:
    // The part's bottoms, emptied for the machine to fill.
    std::vector<NodeId>& reset() {
        bottoms_.clear();
        cursor_ = scans_ = 0;
        return bottoms_;
    }
    // The lowest bottom the water has not reached (kNil if none).
    NodeId lowest(const Heights& heights);

private:
    static constexpr uint32_t kScans = 4;
    std::vector<NodeId> bottoms_;  // lowest first once sorted
    std::vector<HeightKey> keys_;  // scratch for sorting them
    size_t cursor_ = 0;
    uint32_t scans_ = 0;
};

}  // namespace flood
