// The paper's Fig. 10 as a model (flood/teach/state_table.h): every event has exactly one cell, the
// counts add up to the run, and the cells say what the paper says of each state.
#include <gtest/gtest.h>

#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/teach/state_table.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// Counts add up to the events, and each event's cell holds its own action.
void expectCountsSumToEvents(const Polygon& p, const std::string& what) {
    Trace t = record(p);
    StateTable table = buildStateTable(p, t.events);
    ASSERT_EQ(table.cellOf.size(), t.events.size()) << what;
    uint64_t total = 0;
    for (int r = 0; r < StateTable::kRows; ++r) total += table.rowTotal(r);
    EXPECT_EQ(total, t.events.size()) << what;
    for (size_t i = 0; i < t.events.size(); ++i) {
        EXPECT_EQ(kStateColumns[size_t(table.cellOf[i].column)], t.events[i].action) << what;
        EXPECT_GT(table.count(table.cellOf[i].row, table.cellOf[i].column), 0u) << what;
    }
}

std::vector<Event> eventsOf(const Trace& t, Action a) {
    std::vector<Event> out;
    for (const Event& e : t.events)
        if (e.action == a) out.push_back(e);
    return out;
}

}  // namespace

TEST(StateTable, RowsRoundTrip) {
    for (int r = 0; r < StateTable::kRows; ++r) EXPECT_EQ(Combination::ofRow(r).row(), r);
    for (Action a : kStateColumns) EXPECT_EQ(kStateColumns[size_t(columnOf(a))], a);
    EXPECT_EQ(columnOf(Action::Count), -1);
}

TEST(StateTable, CountsSumToEventsOnGalleryAndFamilies) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json"))
        files.push_back(f);
    size_t runs = 0;
    for (const std::string& f : files) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok()) continue;
        validate(r.polygon, f);
        expectCountsSumToEvents(r.polygon, f);
        ++runs;
    }
    EXPECT_GE(runs, 20u);
    for (const std::string& family : familyNames())
        for (size_t size : {8, 60}) expectCountsSumToEvents(generate(family, 3, size), family);
    for (const std::string& family : invalidFamilyNames())
        expectCountsSumToEvents(generateInvalid(family, 3, 40), "invalid " + family);
}

// The cells of small runs, from their events: the fingers meet exactly on a Fill (or a Bridge
// to a sag below the meeting point); a Spill and a Jump act at a top; Start has no chain yet.
TEST(StateTable, KnownCellsOfSmallSamples) {
    for (const char* f : {"two-gorges.json", "hole.json", "sag.json", "overhang.json"}) {
        SCOPED_TRACE(f);
        Polygon p = readOrFail(sourcePath(std::string("polygons/") + f));
        Trace t = record(p);
        StateTable table = buildStateTable(p, t.events);
        std::vector<VertexClass> classes = classifyVertices(p);
        for (size_t i = 0; i < t.events.size(); ++i) {
            const Event& e = t.events[i];
            Combination k = Combination::ofRow(table.cellOf[i].row);
            bool meet = e.before.nextLeft != kNone && e.before.nextLeft == e.before.nextRight;
            EXPECT_EQ(k.meet, meet) << "step " << i;
            if (e.action == Action::Fill) {
                EXPECT_TRUE(k.meet) << "step " << i;
            }
            if (e.action == Action::Raise) {
                EXPECT_FALSE(k.meet) << "step " << i;
            }
            if (e.action == Action::Start) {
                EXPECT_EQ(k.c, kNoClass);
                EXPECT_EQ(k.next, kNoClass);
            }
            if (e.action == Action::Spill || e.action == Action::Jump) {
                EXPECT_EQ(k.c, int(VertexClass::Top)) << "step " << i;
                EXPECT_EQ(k.c, int(classes[e.top]));
            }
        }
        // Each cell's count is the number of events with that action and combination.
        for (Action a : kStateColumns) {
            std::vector<Event> of = eventsOf(t, a);
            uint64_t inColumn = 0;
            for (int r = 0; r < StateTable::kRows; ++r) inColumn += table.count(r, columnOf(a));
            EXPECT_EQ(inColumn, of.size()) << actionName(a);
        }
    }
    // two-gorges floods "Raise 0, Spill; Raise 1, Jump; Raise 2, Fill 3-4": one Spill, one Jump
    // at a top, one Fill where the fingers meet.
    Polygon p = readOrFail(sourcePath("polygons/two-gorges.json"));
    Trace t = record(p);
    StateTable table = buildStateTable(p, t.events);
    const Event spill = eventsOf(t, Action::Spill).at(0), fill = eventsOf(t, Action::Fill).at(0);
    std::vector<VertexClass> classes = classifyVertices(p);
    Combination atSpill = combinationOf(spill, classes);
    EXPECT_EQ(table.count(atSpill.row(), columnOf(Action::Spill)), 1u);
    Combination atFill = combinationOf(fill, classes);
    EXPECT_TRUE(atFill.meet);
    EXPECT_EQ(atFill.next, int(classes[fill.before.nextLeft]));
    EXPECT_EQ(table.count(atFill.row(), columnOf(Action::Fill)), 1u);
}

// Fig. 11-B: the Left pointer is a ceiling, not a top; the forbidden cell says so.
TEST(StateTable, Fig11bForbiddenAtACeiling) {
    Polygon p = readPolygonFile(sourcePath("polygons/invalid/fig11-b-ceiling.json")).polygon;
    Trace t = record(p);
    ASSERT_FALSE(t.events.empty());
    ASSERT_EQ(t.events.back().action, Action::Forbidden);
    StateTable table = buildStateTable(p, t.events);
    StateCell last = table.cellOf.back();
    EXPECT_EQ(last.column, columnOf(Action::Forbidden));
    Combination k = Combination::ofRow(last.row);
    EXPECT_EQ(k.c, int(VertexClass::Ceiling));
    EXPECT_FALSE(k.meet);
}
