#include "flood/teach/todo_list.h"

#include <unordered_map>

namespace flood {

TodoList todoList(const ReplayState& state) {
    TodoList list;
    std::unordered_map<Index, Index> jumpOf(state.jumps.begin(),
                                            state.jumps.end());  // top -> target
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
        if (auto j = jumpOf.find(g.top); j != jumpOf.end()) t.jumpTarget = j->second;
        list.held.push_back(t);
    }
    return list;
}

}  // namespace flood
