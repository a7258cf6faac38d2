// The to-do list of §4 at a replayed step: the pending gorges (halves split off by a Bridge) in
// stack order, the one the next Fill takes first; and the held gorges (chains held at a top by
// a Spill) with their tops and jump pointers, the latest first. GUI-free: read from
// ReplayState::dormant and ReplayState::jumps, for the viewer's To-do list panel.
#pragma once
#include <cstdint>
#include <vector>

#include "flood/log/replay.h"

namespace flood {

struct TodoEntry {
    uint32_t gorge = 0;                 // its id (Event::gorgePushed)
    size_t dormant = 0;                 // its position in ReplayState::dormant (for its chain)
    Index left = kNone, right = kNone;  // its chain's ends
    Index top = kNone;                  // held: the top it waits at
    Index jumpTarget = kNone;           // held: the top's jump pointer, the chain's other bank
};

struct TodoList {
    std::vector<TodoEntry> pending;  // top of the stack first
    std::vector<TodoEntry> held;     // latest first
};

TodoList todoList(const ReplayState& state);

}  // namespace flood
