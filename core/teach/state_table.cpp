#include "flood/teach/state_table.h"

namespace flood {

Combination Combination::ofRow(int row) {
    Combination k;
    k.meet = row % 2 != 0;
    k.next = row / 2 % kClassSlots;
    k.c = row / 2 / kClassSlots;
    return k;
}

int columnOf(Action a) {
    for (size_t i = 0; i < kStateColumns.size(); ++i)
        if (kStateColumns[i] == a) return int(i);
    return -1;
}

uint64_t StateTable::rowTotal(int row) const {
    uint64_t n = 0;
    for (int c = 0; c < kColumns; ++c) n += count(row, c);
    return n;
}

Combination combinationOf(const Event& e, const std::vector<VertexClass>& classes) {
    auto classOf = [&](Index v) { return v < classes.size() ? int(classes[v]) : kNoClass; };
    const Fingers& f = e.before;
    Combination k;
    // The decision tree's first test (Fig. 9); until it runs the fingers are only candidates.
    k.meet = f.nextLeft != kNone && f.nextLeft == f.nextRight;
    bool left = k.meet || e.side == Side::Left;
    k.c = classOf(left ? f.left : f.right);
    k.next = classOf(left ? f.nextLeft : f.nextRight);
    return k;
}

StateTable buildStateTable(const Polygon& polygon, const std::vector<Event>& events, Up up) {
    std::vector<VertexClass> classes = classifyVertices(polygon, up);
    StateTable t;
    t.cellOf.reserve(events.size());
    for (const Event& e : events) {
        StateCell cell{combinationOf(e, classes).row(), columnOf(e.action)};
        t.cellOf.push_back(cell);
        ++t.counts[size_t(cell.row) * StateTable::kColumns + size_t(cell.column)];
    }
    return t;
}

}  // namespace flood
