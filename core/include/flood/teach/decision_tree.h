// The paper's Fig. 9, "Decision tree for flooding actions", as data: the tests the machine
// makes (core/machine/flood.cpp, Machine::step()), each with a yes and a no child, the five actions
// and the forbidden states as leaves, and a layout to draw it by. GUI-free: the viewer's
// Decision panel draws it with the current event's path lit.
//
// An event's path is read from what the event recorded (Event::tested/passed, its action and
// its Forbidden reason), never re-derived from the geometry. Besides the recorded tests the
// tree holds the machine's guards that record no test bit ("Check" nodes: the step budget,
// the fingers passing each other, the set-up of a part); an event stops at a guard when it is
// forbidden for one of that guard's reasons and recorded no test beyond it. An action can
// itself fail while it cuts (a fill whose fan is not convex, a spill finding no bottom): its
// one child is the forbidden state it then ends in.
//
// Three roots, top to bottom: the set-up of a part (ending in Start), a step of the machine,
// and the end of a part (vertices left behind).
#pragma once
#include <cstdint>
#include <vector>

#include "flood/machine/events.h"

namespace flood {

struct DecisionNode {
    enum class Kind : uint8_t {
        Test,    // a recorded Test: yes/no children (yes == no: it only chooses C and Next)
        Check,   // a guard without a Test bit: `yes` goes on, `no` is the Stop it ends in
        Action,  // one of the five actions (or Start); `no`, if any, the Stop it can fail in
        Stop,    // a forbidden state: `reasons` are the Forbidden values that end here
    };
    Kind kind = Kind::Test;
    Test test = Test::Count;         // Test
    Action action = Action::Count;   // Action; Forbidden for a Stop
    std::vector<Forbidden> reasons;  // Check and Stop: the forbidden states reached through it
    int yes = -1, no = -1;           // children (node indices), -1 for none
    const char* label = "";          // short text for the node's box
    const char* detail = "";         // a sentence for its tooltip (a Stop: its reasons' texts)
    // Layout: the box's centre, `column` = depth from its root, `row` in leaf slots (a node
    // sits midway between its first and last child). Boxes are kBoxWidth x kBoxHeight cells.
    double column = 0, row = 0;
    // Where a path can end: an action taken, or a forbidden state (an action with a Stop
    // child is still a leaf of the decision: the path goes on only when the action failed).
    bool leaf() const { return kind == Kind::Stop || kind == Kind::Action; }
};

struct DecisionTree {
    static constexpr double kBoxWidth = 0.84, kBoxHeight = 0.7;  // of a column, of a row
    std::vector<DecisionNode> nodes;
    std::vector<int> roots;  // set-up, step, end of a part
    int columns = 0, rows = 0;
};

// The tree, built and laid out once.
const DecisionTree& decisionTree();

// One node of a path and how the event answered it. `ran` false: a test the machine reached
// but did not need (the spill walk met a pending gorge before landing); an Action node on a
// path that goes on to a Stop has answer false (it failed).
struct PathStep {
    int node = -1;
    bool ran = true;
    bool answer = true;
};
struct DecisionPath {
    std::vector<PathStep> steps;  // from a root to `leaf`, the leaf included
    int leaf = -1;                // -1: the event does not fit the tree (a bug, tested never)
    bool ok() const { return leaf >= 0; }
};

DecisionPath decisionPath(const Event& e);

// For every node, how many of `events` have a path through it (leaves: ending there).
std::vector<uint64_t> countPaths(const std::vector<Event>& events);

// The first event at or after index `from` whose path ends at `leaf`; events.size() if none.
size_t nextEventEndingAt(const std::vector<Event>& events, int leaf, size_t from);

}  // namespace flood
