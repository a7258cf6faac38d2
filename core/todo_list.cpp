#include "todo_list.h"

namespace flood {

TodoList todoList(const ReplayState& state) {
    TodoList list;
    // ReplayState::dormant is in the order the gorges were put away: the machine's to-do list
    // is a stack (Machine::takeNextGorge pops its back), so reading it backwards is stack order.
    for (size_t i = state.dormant.size(); i-- > 0;) {
        const Gorge& g = state.dormant[i];
        TodoEntry t;
        t.gorge = g.id;
        t.dormant = i;
        if (!g.chain.empty()) t.left = g.chain.front(), t.right = g.chain.back();
        if (!g.held) {
            list.pending.push_back(t);
            continue;
        }
        t.top = g.top;
        for (const auto& [top, target] : state.jumps)
            if (top == g.top) t.jumpTarget = target;
        list.held.push_back(t);
    }
    return list;
}

}  // namespace flood
