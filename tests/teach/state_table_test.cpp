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

// ---- the complete table: every combination, each cell's states or X -----------------------

namespace {
// Every event of a run lands in a cell the table allows, or is a forbidden state; an event in a
// forbidden combination is always a forbidden state. Returns the forbidden events.
size_t expectCellsAllowed(const Polygon& p, const std::string& what) {
    Trace t = record(p);
    StateTable table = buildStateTable(p, t.events);
    size_t forbidden = 0;
    for (size_t i = 0; i < t.events.size(); ++i) {
        const StateCell c = table.cellOf[i];
        if (t.events[i].action == Action::Forbidden) {
            ++forbidden;
            continue;
        }
        EXPECT_TRUE(allowedCell(c.row, c.column))
            << what << " step " << i + 1 << ": " << actionName(t.events[i].action) << " at C "
            << Combination::ofRow(c.row).c << " Next " << Combination::ofRow(c.row).next
            << (Combination::ofRow(c.row).meet ? " meet" : "");
        EXPECT_FALSE(forbiddenCombination(c.row)) << what << " step " << i + 1;
    }
    return forbidden;
}
}  // namespace

TEST(StateTable, EveryCellReachedIsAllowedOnGalleryAndFamilies) {
    size_t runs = 0;
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok() || !validate(r.polygon, f).ok()) continue;
        EXPECT_EQ(expectCellsAllowed(r.polygon, f), 0u) << f;
        ++runs;
    }
    EXPECT_GE(runs, 14u);
    for (const std::string& family : familyNames())
        for (uint64_t seed : {1, 2, 3})
            for (size_t size : {8, 60, 400})
                EXPECT_EQ(expectCellsAllowed(generate(family, seed, size), family), 0u) << family;
}

// Forbidden combinations are where the machine rejects: valid runs never reach them (above),
// and a ceiling met as an end with the fingers apart (CeilingAsEnd, Fig. 11-B) is one on every
// invalid sample and family. (On invalid input the machine may also act where the table says
// X: the classes are the rings', and crossing rings make a loop that is no ring.)
TEST(StateTable, ForbiddenCombinationsAreWhereTheMachineRejects) {
    size_t ceilings = 0;
    auto check = [&](const Polygon& p, const std::string& what) {
        Trace t = record(p);
        StateTable table = buildStateTable(p, t.events);
        for (size_t i = 0; i < t.events.size(); ++i)
            if (t.events[i].action == Action::Forbidden &&
                t.events[i].reason == Forbidden::CeilingAsEnd) {
                EXPECT_TRUE(forbiddenCombination(table.cellOf[i].row)) << what << " step " << i + 1;
                ++ceilings;
            }
    };
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (r.diagnostic.ok()) check(r.polygon, f);
    }
    for (const std::string& family : invalidFamilyNames())
        for (uint64_t seed : {1, 2, 3}) check(generateInvalid(family, seed, 40), family);
    EXPECT_GE(ceilings, 1u);
    // Each forbidden combination has no action cell; an allowed one has at least one.
    for (int r = 0; r < StateTable::kRows; ++r) {
        uint8_t states = allowedStates(Combination::ofRow(r));
        EXPECT_EQ(states >> columnOf(Action::Forbidden) & 1, 0) << r;
        EXPECT_EQ(forbiddenCombination(r), states == 0) << r;
    }
}

// What the paper says of the states (§4, Fig. 9), read off the derived table: raises and
// bridges go up from a vertex that is no maximum, spills and jumps happen at a top, a ceiling
// as an end with the fingers apart is forbidden (Fig. 11-B), the fingers meeting allow a fill
// or a bridge to a sag below, Start has no chain; Next's class decides nothing.
TEST(StateTable, DerivedCellsSayWhatThePaperSays) {
    using V = VertexClass;
    auto states = [](V c, V next, bool meet) {
        return allowedStates(Combination{int(c), int(next), meet});
    };
    auto bit = [](Action a) { return uint8_t(1u << columnOf(a)); };
    const uint8_t sj = bit(Action::Spill) | bit(Action::Jump);
    const uint8_t rb = bit(Action::Raise) | bit(Action::Bridge);
    const uint8_t fb = bit(Action::Fill) | bit(Action::Bridge);
    for (int n = 0; n < int(V::Count); ++n) {
        const V next = V(n);
        for (V c : {V::Regular, V::Bottom, V::Sag}) EXPECT_EQ(states(c, next, false), rb);
        EXPECT_EQ(states(V::Top, next, false), sj);
        EXPECT_EQ(states(V::Ceiling, next, false), 0);
        for (int c = 0; c < int(V::Count); ++c) EXPECT_EQ(states(V(c), next, true), fb);
    }
    EXPECT_EQ(allowedStates(Combination{}), bit(Action::Start));
    EXPECT_EQ(allowedStates(Combination{kNoClass, int(V::Regular), false}), 0);
    EXPECT_EQ(allowedStates(Combination{kNoClass, kNoClass, true}), 0);
}

// The printed table: the two grids, each cell's states with the run's counts.
TEST(StateTable, FormattedTableCountsTheRun) {
    Polygon p = readOrFail(sourcePath("polygons/two-gorges.json"));
    Trace t = record(p);
    StateTable table = buildStateTable(p, t.events);
    std::string text = formatStateTable(table);
    EXPECT_NE(text.find("Fingers apart"), std::string::npos) << text;
    EXPECT_NE(text.find("Fingers meet"), std::string::npos) << text;
    EXPECT_NE(text.find("No chain yet: Start 1, forbidden before a chain 0"), std::string::npos)
        << text;
    // The Fill of two-gorges: one, in the meet grid at a ceiling; the spill: "S1" in a top row.
    std::string meet = text.substr(text.find("Fingers meet"));
    EXPECT_NE(meet.find("F1"), std::string::npos) << meet;
    std::string apart = text.substr(0, text.find("Fingers meet"));
    size_t topRow = apart.find("\ntop ");
    ASSERT_NE(topRow, std::string::npos) << apart;
    std::string top = apart.substr(topRow, apart.find('\n', topRow + 1) - topRow);
    EXPECT_NE(top.find("S1"), std::string::npos) << top;
    EXPECT_NE(top.find("J1"), std::string::npos) << top;
    size_t ceilingRow = apart.find("\nceiling ");
    std::string ceiling = apart.substr(ceilingRow, apart.find('\n', ceilingRow + 1) - ceilingRow);
    EXPECT_NE(ceiling.find("X"), std::string::npos) << ceiling;
}
