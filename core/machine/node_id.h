// A node of the flood machine's loops (loops.h) by its own type, so that a node id and a
// vertex index (Index) cannot be mixed up: the compiler refuses either in place of the other.
// Internal to core/, not a public API.
#pragma once
#include <cstdint>

#include "flood/geometry/polygon.h"

namespace flood {

enum class NodeId : uint32_t {};
constexpr NodeId kNil{kNone};  // no node

// Node ids count up from a part's first node: offsets from it, and back.
constexpr uint32_t operator-(NodeId a, NodeId b) { return uint32_t(a) - uint32_t(b); }
constexpr NodeId operator+(NodeId a, uint32_t k) { return NodeId(uint32_t(a) + k); }

}  // namespace flood
