// The paper's Fig. 9 as a model (flood/teach/decision_tree.h): every event of the samples, the
// invalid inputs and the generated families follows a path of the tree that ends in its own
// action (a forbidden event: in a stop naming its reason), the answers on the path are the
// ones the event recorded, and the layout draws no box over another.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/teach/decision_tree.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

using Kind = DecisionNode::Kind;

// Checks one event's path; returns its leaf (-1 when it does not fit).
int expectPathOfOwnAction(const Event& e, const std::string& what) {
    const DecisionTree& t = decisionTree();
    DecisionPath p = decisionPath(e);
    EXPECT_TRUE(p.ok()) << what << ": event " << e.step << " (" << actionName(e.action)
                        << ") fits no path";
    if (!p.ok()) return -1;
    const DecisionNode& leaf = t.nodes[size_t(p.leaf)];
    EXPECT_EQ(p.steps.back().node, p.leaf) << what;
    EXPECT_EQ(leaf.action, e.action) << what << ": event " << e.step;
    if (e.action == Action::Forbidden) {
        EXPECT_EQ(leaf.kind, Kind::Stop) << what;
        EXPECT_NE(std::find(leaf.reasons.begin(), leaf.reasons.end(), e.reason), leaf.reasons.end())
            << what << ": event " << e.step << " stops in " << leaf.label << ", not "
            << forbiddenName(e.reason);
    }
    // The answers are the recorded ones, and the tests that ran are exactly the recorded ones.
    uint8_t ran = 0;
    for (size_t i = 0; i < p.steps.size(); ++i) {
        const PathStep& s = p.steps[i];
        const DecisionNode& n = t.nodes[size_t(s.node)];
        if (i > 0) {  // each step is a child of the one before
            const DecisionNode& parent = t.nodes[size_t(p.steps[i - 1].node)];
            EXPECT_TRUE(parent.yes == s.node || parent.no == s.node) << what;
            if (parent.kind == Kind::Test && parent.yes != parent.no && p.steps[i - 1].ran) {
                EXPECT_EQ(p.steps[i - 1].answer ? parent.yes : parent.no, s.node) << what;
            }
        }
        if (n.kind != Kind::Test) continue;
        EXPECT_EQ(s.ran, e.didTest(n.test)) << what << ": " << n.label;
        if (!s.ran) continue;
        ran |= uint8_t(1u << int(n.test));
        EXPECT_EQ(s.answer, e.testResult(n.test))
            << what << ": event " << e.step << ", " << n.label;
    }
    EXPECT_EQ(ran, e.tested) << what << ": event " << e.step;
    return p.leaf;
}

// Every event of `p`'s run; the leaves reached go to `leaves`.
void expectEveryEventFits(const Polygon& p, const std::string& what, std::set<int>& leaves) {
    Trace t = record(p);
    for (const Event& e : t.events) leaves.insert(expectPathOfOwnAction(e, what));
    // countPaths: each node counts the events whose path holds it; every event enters at a root.
    std::vector<uint64_t> counts = countPaths(t.events), expected(decisionTree().nodes.size(), 0);
    for (const Event& e : t.events)
        for (const PathStep& s : decisionPath(e).steps) ++expected[size_t(s.node)];
    EXPECT_EQ(counts, expected) << what;
    uint64_t rootSum = 0;
    for (int r : decisionTree().roots) rootSum += counts[size_t(r)];
    EXPECT_EQ(rootSum, t.events.size()) << what;
}

}  // namespace

TEST(DecisionTree, EveryEventOfSamplesInvalidInputsAndFamiliesEndsInItsOwnAction) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    for (const char* dir :
         {"polygons/invalid", "polygons/tutorial", "polygons/regress", "polygons/conjecture"})
        for (const char* ext : {".json", ".wkt"})
            for (const std::string& f : filesIn(sourcePath(dir), ext)) files.push_back(f);
    std::set<int> leaves;
    size_t runs = 0;
    for (const std::string& f : files) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok()) continue;
        validate(r.polygon, f);  // as the CLI does: T-junctions known; invalid input flooded anyway
        expectEveryEventFits(r.polygon, f, leaves);
        ++runs;
    }
    EXPECT_GE(runs, 30u);
    for (const std::string& family : familyNames())
        for (size_t size : {8, 60, 400})
            expectEveryEventFits(generate(family, 5, size), family, leaves);
    for (const std::string& family : invalidFamilyNames())
        expectEveryEventFits(generateInvalid(family, 5, 40), "invalid " + family, leaves);
    // Every action is met, and every forbidden state the invalid samples are named for.
    std::set<Action> actions;
    std::set<Forbidden> stops;
    for (int leaf : leaves) {
        if (leaf < 0) continue;
        const DecisionNode& n = decisionTree().nodes[size_t(leaf)];
        actions.insert(n.action);
        if (n.kind == Kind::Stop) stops.insert(n.reasons.begin(), n.reasons.end());
    }
    EXPECT_EQ(actions.size(), size_t(Action::Count));
    for (Forbidden f : {Forbidden::StartNotBottom, Forbidden::CeilingAsEnd,
                        Forbidden::JumpWrongSide, Forbidden::SpillNoBottom, Forbidden::FillOpen,
                        Forbidden::LeftBehind, Forbidden::ShortLoop, Forbidden::NotFinite})
        EXPECT_TRUE(stops.count(f)) << forbiddenName(f) << " never reached";
}

TEST(DecisionTree, HoldsEveryTestActionAndForbiddenState) {
    const DecisionTree& t = decisionTree();
    std::set<flood::Test> tests;
    std::set<Action> actions;
    std::set<Forbidden> reasons;
    for (const DecisionNode& n : t.nodes) {
        if (n.kind == Kind::Test) tests.insert(n.test);
        if (n.leaf()) actions.insert(n.action);
        if (n.kind == Kind::Stop) reasons.insert(n.reasons.begin(), n.reasons.end());
        // Every child is one column to the right; a guard's no is a stop.
        for (int c : {n.yes, n.no}) {
            if (c < 0) continue;
            EXPECT_EQ(t.nodes[size_t(c)].column, n.column + 1) << n.label;
        }
        if (n.kind == Kind::Check) {
            EXPECT_EQ(t.nodes[size_t(n.no)].kind, Kind::Stop) << n.label;
        }
        if (n.kind == Kind::Test || n.kind == Kind::Check) {
            EXPECT_TRUE(n.yes >= 0 && n.no >= 0) << n.label;
        }
        if (n.kind == Kind::Stop) {
            EXPECT_TRUE(n.yes < 0 && n.no < 0) << n.label;
        }
    }
    EXPECT_EQ(tests.size(), size_t(flood::Test::Count));
    EXPECT_EQ(actions.size(), size_t(Action::Count));
    EXPECT_EQ(reasons.size(), size_t(Forbidden::Count) - 1);  // all but None
}

TEST(DecisionTree, LayoutHasNoOverlappingBoxes) {
    const DecisionTree& t = decisionTree();
    ASSERT_GT(t.columns, 0);
    ASSERT_GT(t.rows, 0);
    const double w = DecisionTree::kBoxWidth, h = DecisionTree::kBoxHeight;
    for (size_t i = 0; i < t.nodes.size(); ++i) {
        const DecisionNode& a = t.nodes[i];
        EXPECT_GE(a.column - w / 2, -0.5) << a.label;
        EXPECT_LE(a.column + w / 2, t.columns - 0.5) << a.label;
        EXPECT_GE(a.row - h / 2, -0.5) << a.label;
        EXPECT_LE(a.row + h / 2, t.rows - 0.5) << a.label;
        for (size_t j = i + 1; j < t.nodes.size(); ++j) {
            const DecisionNode& b = t.nodes[j];
            bool apart = std::abs(a.column - b.column) >= w || std::abs(a.row - b.row) >= h;
            EXPECT_TRUE(apart) << a.label << " (" << a.column << ", " << a.row << ") overlaps "
                               << b.label << " (" << b.column << ", " << b.row << ")";
        }
    }
}

TEST(DecisionTree, PathsOfHandMadeEvents) {
    const DecisionTree& t = decisionTree();
    auto leafLabel = [&](const Event& e) {
        DecisionPath p = decisionPath(e);
        return p.ok() ? std::string(t.nodes[size_t(p.leaf)].label) : std::string("none");
    };
    auto mark = [](Event& e, flood::Test test, bool r) {
        e.tested |= uint8_t(1u << int(test));
        if (r) e.passed |= uint8_t(1u << int(test));
    };
    Event ceiling;  // Fig. 11-B: C is a maximum but not a top
    ceiling.action = Action::Forbidden, ceiling.reason = Forbidden::CeilingAsEnd;
    mark(ceiling, flood::Test::SameNext, false), mark(ceiling, flood::Test::LeftLower, true);
    mark(ceiling, flood::Test::NextAbove, false), mark(ceiling, flood::Test::CIsTop, false);
    EXPECT_EQ(leafLabel(ceiling), "Ceiling\nAsEnd");
    Event budget;  // the step budget ran out before any test
    budget.action = Action::Forbidden, budget.reason = Forbidden::NoProgress;
    DecisionPath p = decisionPath(budget);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p.steps.size(), 2u);  // the guard, its stop
    EXPECT_EQ(p.steps[0].node, t.roots[1]);
    EXPECT_FALSE(p.steps[0].answer);
    Event stuck = ceiling;  // the same tests, but the raise's walk made no progress
    stuck.reason = Forbidden::NoProgress;
    stuck.passed |= uint8_t(1u << int(flood::Test::NextAbove));
    mark(stuck, flood::Test::SagInside, false);
    stuck.tested &= uint8_t(~(1u << int(flood::Test::CIsTop)));
    p = decisionPath(stuck);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(t.nodes[size_t(p.steps[p.steps.size() - 2].node)].action, Action::Raise);
    EXPECT_FALSE(p.steps[p.steps.size() - 2].answer);  // the raise failed
    Event bad = ceiling;  // a raise that never asked whether Next is above C
    bad.action = Action::Raise, bad.reason = Forbidden::None;
    bad.tested &= uint8_t(~(1u << int(flood::Test::NextAbove)));
    EXPECT_FALSE(decisionPath(bad).ok());
    Event spill;  // the walk met a pending gorge: WalkLanded reached but not run
    spill.action = Action::Spill;
    mark(spill, flood::Test::SameNext, false), mark(spill, flood::Test::LeftLower, false),
        mark(spill, flood::Test::NextAbove, false);
    mark(spill, flood::Test::CIsTop, true), mark(spill, flood::Test::JumpSet, false);
    p = decisionPath(spill);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(t.nodes[size_t(p.steps[p.steps.size() - 2].node)].test, flood::Test::WalkLanded);
    EXPECT_FALSE(p.steps[p.steps.size() - 2].ran);
}

TEST(DecisionTree, NextEventEndingAtALeaf) {
    Trace t = record(readOrFail(sourcePath("polygons/paper-figure-7.json")));
    const int fill = decisionPath(t.events.back()).leaf;  // the run ends in a Fill
    ASSERT_GE(fill, 0);
    size_t first = nextEventEndingAt(t.events, fill, 0);
    ASSERT_LT(first, t.events.size());
    EXPECT_EQ(t.events[first].action, Action::Fill);
    for (size_t i = 0; i < first; ++i) EXPECT_NE(decisionPath(t.events[i]).leaf, fill);
    EXPECT_EQ(nextEventEndingAt(t.events, fill, t.events.size()), t.events.size());
}
