#include "flood/teach/decision_tree.h"

#include <algorithm>
#include <unordered_map>

namespace flood {

namespace {

using Kind = DecisionNode::Kind;

// The nodes in the order Machine::floodPart() and Machine::step() meet them
// (core/machine/flood.cpp).
class Builder {
public:
    DecisionTree tree;

    int test(Test t, const char* label, int yes, int no) {
        DecisionNode n;
        n.kind = Kind::Test, n.test = t, n.label = label, n.detail = testText(t), n.yes = yes,
        n.no = no;
        return add(n);
    }
    int check(const char* label, const char* detail, int yes, int stop) {
        DecisionNode n;
        n.kind = Kind::Check, n.label = label, n.detail = detail, n.yes = yes, n.no = stop;
        n.reasons = tree.nodes[size_t(stop)].reasons;
        return add(n);
    }
    int action(Action a, int fails = -1) {
        DecisionNode n;
        n.kind = Kind::Action, n.action = a, n.label = actionName(a), n.detail = actionMeaning(a),
        n.no = fails;
        return add(n);
    }
    int stop(std::vector<Forbidden> reasons, const char* label) {
        DecisionNode n;
        n.kind = Kind::Stop, n.action = Action::Forbidden, n.reasons = std::move(reasons),
        n.label = label;
        return add(n);
    }

private:
    int add(DecisionNode n) {
        tree.nodes.push_back(std::move(n));
        return int(tree.nodes.size()) - 1;
    }
};

// Children in drawing order, top to bottom: a guard's stop first (the tree reads as a
// staircase), a test's yes before its no, a pass-through test's one child once.
std::vector<int> childrenOf(const DecisionNode& n) {
    if (n.kind == Kind::Check) return {n.no, n.yes};
    std::vector<int> out;
    if (n.yes >= 0) out.push_back(n.yes);
    if (n.no >= 0 && n.no != n.yes) out.push_back(n.no);
    return out;
}

// Leaves take consecutive rows; a node sits midway between its first and last child, so the
// nodes of one column keep their subtrees' order and never share a row.
void layout(DecisionTree& t, int node, int depth, int& nextRow) {
    DecisionNode& n = t.nodes[size_t(node)];
    n.column = depth;
    t.columns = std::max(t.columns, depth + 1);
    std::vector<int> kids = childrenOf(n);
    if (kids.empty()) {
        n.row = nextRow++;
        return;
    }
    for (int k : kids) layout(t, k, depth + 1, nextRow);
    t.nodes[size_t(node)].row =
        (t.nodes[size_t(kids.front())].row + t.nodes[size_t(kids.back())].row) / 2;
}

DecisionTree build() {
    Builder b;
    // Set-up of a part (Machine::floodPart): the checks before the water starts.
    int start = b.action(Action::Start);
    int startNotBottom = b.stop({Forbidden::StartNotBottom}, "StartNot\nBottom");
    int bottom =
        b.check("bottom?", "the lowest vertex of the outer ring is a bottom (convex minimum)",
                start, startNotBottom);
    int shortLoop = b.stop({Forbidden::ShortLoop}, "Short\nLoop");
    int rings =
        b.check("rings >= 3?", "every ring has three vertices or more (a hole may be one point)",
                bottom, shortLoop);
    int notFinite = b.stop({Forbidden::NotFinite}, "Not\nFinite");
    int setup =
        b.check("finite?", "every coordinate of the part is a finite number", rings, notFinite);

    // A step (Machine::step), in the order of ALGORITHM.md §4.
    int spill = b.action(Action::Spill, b.stop({Forbidden::SpillNoBottom}, "Spill\nNoBottom"));
    int walk = b.test(Test::WalkLanded, "landed?", spill, spill);
    int jump = b.action(Action::Jump, b.stop({Forbidden::JumpWrongSide}, "Jump\nWrongSide"));
    int jumpSet = b.test(Test::JumpSet, "jump set?", jump, walk);
    int ceiling = b.stop({Forbidden::CeilingAsEnd}, "Ceiling\nAsEnd");
    int top = b.test(Test::CIsTop, "C a top?", jumpSet, ceiling);
    int raise = b.action(Action::Raise, b.stop({Forbidden::NoProgress}, "No\nProgress"));
    int bridgeUp = b.action(Action::Bridge, b.stop({Forbidden::NoProgress}, "No\nProgress"));
    int sagUp = b.test(Test::SagInside, "sag inside?", bridgeUp, raise);
    int above = b.test(Test::NextAbove, "Next above?", sagUp, top);
    int leftLower = b.test(Test::LeftLower, "NL lower?", above, above);
    int crossed = b.stop({Forbidden::FillOpen}, "FillOpen");
    int apart = b.check(
        "apart?",
        "NextLeft is not Right and NextRight is not Left: the fingers have not passed each other",
        leftLower, crossed);
    int fill = b.action(Action::Fill, b.stop({Forbidden::FillOpen, Forbidden::BadTriangle},
                                             "FillOpen\nBadTriangle"));
    int bridgeMeet = b.action(Action::Bridge, b.stop({Forbidden::NoProgress}, "No\nProgress"));
    int sagMeet = b.test(Test::SagInside, "sag inside?", bridgeMeet, fill);
    int same = b.test(Test::SameNext, "NL == NR?", sagMeet, apart);
    int budget = b.stop({Forbidden::NoProgress}, "No\nProgress");
    int step =
        b.check("budget?", "the machine is within its step budget (8 steps per node of the part)",
                same, budget);

    // End of a part (after the loop): every node must have been flooded.
    int end = b.stop({Forbidden::LeftBehind}, "Left\nBehind");

    DecisionTree t = std::move(b.tree);
    t.roots = {setup, step, end};
    int row = 0;
    for (int r : t.roots) layout(t, r, 0, row);
    t.rows = row;
    return t;
}

bool has(const std::vector<Forbidden>& reasons, Forbidden f) {
    return std::find(reasons.begin(), reasons.end(), f) != reasons.end();
}

// The root an event starts from: Start and the forbidden states before a chain exists come
// from the set-up, LeftBehind from the end of a part, everything else from a step.
int rootOf(const DecisionTree& t, const Event& e) {
    if (e.action == Action::Start) return t.roots[0];
    if (e.action == Action::Forbidden && e.tested == 0) {
        if (e.reason == Forbidden::NotFinite || e.reason == Forbidden::ShortLoop ||
            e.reason == Forbidden::StartNotBottom)
            return t.roots[0];
        if (e.reason == Forbidden::LeftBehind) return t.roots[2];
    }
    return t.roots[1];
}

}  // namespace

const DecisionTree& decisionTree() {
    static const DecisionTree tree = build();
    return tree;
}

DecisionPath decisionPath(const Event& e) {
    const DecisionTree& t = decisionTree();
    DecisionPath path;
    const bool forbidden = e.action == Action::Forbidden;
    uint8_t seen = 0;  // the tests on the path so far
    for (int at = rootOf(t, e); at >= 0;) {
        const DecisionNode& n = t.nodes[size_t(at)];
        PathStep s{at, true, true};
        int next = -1;
        switch (n.kind) {
            case Kind::Test:
                if (e.didTest(n.test)) {
                    s.answer = e.testResult(n.test);
                    seen |= uint8_t(1u << int(n.test));
                    next = s.answer ? n.yes : n.no;
                } else if (n.yes == n.no) {
                    s.ran = false;
                    next = n.yes;
                } else {
                    return DecisionPath{};  // a test the event should have made
                }
                break;
            case Kind::Check:
                // Stopped here: forbidden for this guard's reason, and no test ran beyond it.
                s.answer = !(forbidden && has(n.reasons, e.reason) && (e.tested & ~seen) == 0);
                next = s.answer ? n.yes : n.no;
                break;
            case Kind::Action:
                if (e.action == n.action) {
                    path.steps.push_back(s);
                    path.leaf = at;
                    return path;
                }
                if (!forbidden || n.no < 0) return DecisionPath{};
                s.answer = false;
                next = n.no;
                break;
            case Kind::Stop:
                if (!forbidden || !has(n.reasons, e.reason)) return DecisionPath{};
                path.steps.push_back(s);
                path.leaf = at;
                return path;
        }
        path.steps.push_back(s);
        at = next;
    }
    return DecisionPath{};
}

namespace {
// All that decisionPath() reads of an event: events with one key share one path, and a run
// has a few dozen keys however long it is.
uint32_t pathKey(const Event& e) {
    return uint32_t(e.action) | uint32_t(e.reason) << 8 | uint32_t(e.tested) << 16 |
           uint32_t(e.passed) << 24;
}
}  // namespace

std::vector<uint64_t> countPaths(const std::vector<Event>& events) {
    // Per key: its events and one of them. Runs of one action share a key: count a run at once.
    std::unordered_map<uint32_t, std::pair<uint64_t, const Event*>> byKey;
    for (size_t i = 0; i < events.size();) {
        const uint32_t key = pathKey(events[i]);
        size_t j = i + 1;
        while (j < events.size() && pathKey(events[j]) == key) ++j;
        auto& entry = byKey.try_emplace(key, 0, &events[i]).first->second;
        entry.first += j - i;
        i = j;
    }
    std::vector<uint64_t> counts(decisionTree().nodes.size(), 0);
    for (const auto& [key, entry] : byKey)
        for (const PathStep& s : decisionPath(*entry.second).steps)
            counts[size_t(s.node)] += entry.first;
    return counts;
}

size_t nextEventEndingAt(const std::vector<Event>& events, int leaf, size_t from) {
    std::unordered_map<uint32_t, bool> endsThere;
    for (size_t i = from; i < events.size(); ++i) {
        auto [it, fresh] = endsThere.try_emplace(pathKey(events[i]), false);
        if (fresh) it->second = decisionPath(events[i]).leaf == leaf;
        if (it->second) return i;
    }
    return events.size();
}

}  // namespace flood
