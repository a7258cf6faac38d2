// The paper's Fig. 10, "Vertex combinations and states": for every event, the combination the
// machine looked at (the classes of C and Next, and whether the fingers meet) against the state
// it went to (raise, fill, bridge, spill, jump, forbidden), and how often each cell occurs over
// a trace; and the whole table, every combination with the states the decision tree allows in
// it (allowedStates) or X, a forbidden state. GUI-free: the viewer's State table panel and
// `flood transcript --table` draw it with the run's counts.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/machine/events.h"
#include "flood/machine/vertex_class.h"

namespace flood {

// One class slot more than VertexClass: "no vertex", for events before there is a chain
// (Start, and the forbidden states found before it: a short ring, a start that is no bottom).
constexpr int kClassSlots = int(VertexClass::Count) + 1;
constexpr int kNoClass = int(VertexClass::Count);

// A row of the table. C is the end of the chain that acts (Event::side), Next its finger;
// when the fingers meet, C is Left and Next the vertex where they meet.
struct Combination {
    int c = kNoClass, next = kNoClass;  // VertexClass values, or kNoClass
    bool meet = false;
    int row() const { return (c * kClassSlots + next) * 2 + int(meet); }
    static Combination ofRow(int row);
};

// The columns, in the paper's order (R, F, B, S, J, X), then Start: the machine's entry,
// not one of the paper's states, kept so that every event has a cell.
constexpr std::array<Action, 7> kStateColumns = {Action::Raise, Action::Fill, Action::Bridge,
                                                 Action::Spill, Action::Jump, Action::Forbidden,
                                                 Action::Start};
int columnOf(Action a);

struct StateCell {
    int row = 0, column = 0;
};

struct StateTable {
    static constexpr int kRows = kClassSlots * kClassSlots * 2;
    static constexpr int kColumns = int(kStateColumns.size());
    std::array<uint64_t, size_t(kRows) * kColumns> counts{};
    std::vector<StateCell> cellOf;  // per event, in log order

    uint64_t count(int row, int column) const {
        return counts[size_t(row) * kColumns + size_t(column)];
    }
    uint64_t rowTotal(int row) const;
};

// The combination of one event; `classes` from classifyVertices() of the traced polygon
// (a vertex it does not hold has no class).
Combination combinationOf(const Event& e, const std::vector<VertexClass>& classes);

StateTable buildStateTable(const Polygon& polygon, const std::vector<Event>& events,
                           Up up = Up::PlusY);

// The complete table. The states the machine can go to from combination `k` on valid input:
// bit columnOf(a) for each action a (Start only without a chain), derived from the decision
// tree (decision_tree.h) by following every path whose tests' answers the classes allow
// (what a test's answer says of C's class and of the fingers meeting: see state_table.cpp; no
// test looks at Next's class, so it only says where a run's events fell). 0: a
// forbidden combination, where every step ends in a forbidden state (X). The forbidden
// column itself is never set: any step may end in X on invalid input.
uint8_t allowedStates(const Combination& k);
inline bool allowedCell(int row, int column) {
    return allowedStates(Combination::ofRow(row)) >> column & 1;
}
inline bool forbiddenCombination(int row) { return allowedStates(Combination::ofRow(row)) == 0; }

// The table as text, as the paper draws it: for fingers apart and fingers meeting, a grid of
// C's class (rows) against Next's (columns); in each cell the states allowed there, with the
// run's count after each state it reached ("R12 b": 12 raises, bridges allowed but none
// made), or X for a forbidden combination; then the events without a chain (Start, and the
// forbidden states met before one).
std::string formatStateTable(const StateTable& table);

}  // namespace flood
