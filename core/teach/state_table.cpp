#include "flood/teach/state_table.h"

#include <array>
#include <sstream>

#include "flood/teach/decision_tree.h"

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

namespace {

bool isMax(int c) { return c == int(VertexClass::Top) || c == int(VertexClass::Ceiling); }

// What an answer to a test of Fig. 9 says of a combination. Whether the fingers meet is part of
// it. "Next above C" says C is no maximum (top or ceiling) and "Next below C" that it is one:
// at a maximum the chain can only look down (its finger is a ring neighbour, or after a spill a
// node of the chain held there, both below it). "C a top" tells a top from a ceiling. Nothing
// the tree tests says anything of Next's class: a finger is a ring neighbour of C only while
// the loop there is the ring's (a held chain at a jump, a T-junction or rings touching at a
// point give it other neighbours), so Next's column only says where a run's events fell.
bool consistent(Test t, bool answer, const Combination& k) {
    switch (t) {
        case Test::SameNext: return answer == k.meet;
        case Test::NextAbove: return answer != isMax(k.c);
        case Test::CIsTop: return (k.c == int(VertexClass::Top)) == answer;
        default: return true;  // which finger is lower, sags, jump pointers: not classes
    }
}

// Every action reachable from `node` by answers consistent with `k`; a Check passes.
void reach(const DecisionTree& t, int node, const Combination& k, uint8_t& states) {
    if (node < 0) return;
    const DecisionNode& n = t.nodes[size_t(node)];
    switch (n.kind) {
        case DecisionNode::Kind::Action: states |= uint8_t(1u << columnOf(n.action)); return;
        case DecisionNode::Kind::Stop: return;
        case DecisionNode::Kind::Check: return reach(t, n.yes, k, states);
        case DecisionNode::Kind::Test:
            if (n.yes == n.no) return reach(t, n.yes, k, states);  // it only chooses C
            if (consistent(n.test, true, k)) reach(t, n.yes, k, states);
            if (consistent(n.test, false, k)) reach(t, n.no, k, states);
            return;
    }
}

std::array<uint8_t, StateTable::kRows> deriveTable() {
    const DecisionTree& t = decisionTree();
    std::array<uint8_t, StateTable::kRows> out{};
    for (int r = 0; r < StateTable::kRows; ++r) {
        const Combination k = Combination::ofRow(r);
        const bool chain = k.c != kNoClass && k.next != kNoClass;
        // Without a chain only the set-up runs (Start); with one, a step.
        if (!chain && k.c == kNoClass && k.next == kNoClass && !k.meet)
            reach(t, t.roots[0], k, out[size_t(r)]);
        if (chain) reach(t, t.roots[1], k, out[size_t(r)]);
    }
    return out;
}

}  // namespace

uint8_t allowedStates(const Combination& k) {
    static const std::array<uint8_t, StateTable::kRows> table = deriveTable();
    return table[size_t(k.row())];
}

std::string formatStateTable(const StateTable& table) {
    constexpr const char* kLetters = "RFBSJX";  // kStateColumns' letters, Start apart
    const int classes = int(VertexClass::Count);
    // A cell: each allowed state, upper case with its count when the run reached it, lower
    // case when not; X for a forbidden combination; an X with its count for forbidden events.
    auto cell = [&](int row) {
        std::string s;
        const uint8_t allowed = allowedStates(Combination::ofRow(row));
        for (int c = 0; c < 6; ++c) {
            const uint64_t n = table.count(row, c);
            const bool x = c == columnOf(Action::Forbidden);
            if (!(allowed >> c & 1) && !n && !(x && !allowed)) continue;
            if (!s.empty()) s += ' ';
            s += n || x ? kLetters[c] : char(kLetters[c] - 'A' + 'a');
            if (n) s += std::to_string(n);
        }
        return s;
    };
    size_t width = 8;
    for (int r = 0; r < StateTable::kRows; ++r) width = std::max(width, cell(r).size() + 2);
    auto pad = [](const std::string& s, size_t w) {
        return s.size() < w ? s + std::string(w - s.size(), ' ') : s;
    };
    std::ostringstream os;
    os << "Fig. 10: vertex combinations and states (R raise, F fill, B bridge, S spill, J jump, X "
          "forbidden)\n"
          "A state with a count: this run went there that often; lower case: allowed, not "
          "reached; X alone: a forbidden combination\n";
    for (int meet = 0; meet < 2; ++meet) {
        os << "\n"
           << (meet ? "Fingers meet (C: Left; Next: the vertex where NextLeft and NextRight meet)"
                    : "Fingers apart (C: the end of the chain that acts; Next: its finger)")
           << "\n"
           << pad("C \\ Next", 10);
        std::string line;
        for (int n = 0; n < classes; ++n) line += pad(vertexClassName(VertexClass(n)), width);
        os << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
        for (int c = 0; c < classes; ++c) {
            line = pad(vertexClassName(VertexClass(c)), 10);
            for (int n = 0; n < classes; ++n)
                line += pad(cell(Combination{c, n, meet != 0}.row()), width);
            os << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
        }
    }
    const int none = Combination{}.row();
    os << "\nNo chain yet: Start " << table.count(none, columnOf(Action::Start))
       << ", forbidden before a chain " << table.count(none, columnOf(Action::Forbidden)) << "\n";
    return os.str();
}

}  // namespace flood
