// Transcript items (flood/teach/transcript.h): each covers its events (a whole run of raises, or one
// other action), shows the triangles they cut, and carries the paper's separator; joined they
// are flood::transcript(), the golden transcripts where there are some.
#include <gtest/gtest.h>

#include "flood/log/replay.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "golden_transcripts.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

Event event(Action a, uint32_t firstTriangle, uint32_t count) {
    Event e;
    e.action = a;
    e.firstTriangle = firstTriangle;
    e.triangleCount = count;
    return e;
}

// The items checked against the events, rule by rule, without the grouping code's help.
void expectItemsOf(const std::vector<Event>& events, const std::vector<TranscriptItem>& items) {
    size_t next = 0;  // the first event no item has covered yet
    for (size_t k = 0; k < items.size(); ++k) {
        SCOPED_TRACE("item " + std::to_string(k) + " '" + items[k].text + "'");
        const TranscriptItem& it = items[k];
        while (next < events.size() && events[next].action == Action::Start) ++next;
        ASSERT_EQ(it.firstEvent, next) << "items cover the events in order, Starts skipped";
        ASSERT_LE(it.firstEvent, it.lastEvent);
        ASSERT_LT(it.lastEvent, events.size());
        Action a = events[it.firstEvent].action;
        uint32_t first = UINT32_MAX, count = 0;
        for (uint32_t i = it.firstEvent; i <= it.lastEvent; ++i) {
            EXPECT_EQ(events[i].action, a) << "event " << i;
            if (events[i].triangleCount && first == UINT32_MAX) first = events[i].firstTriangle;
            count += events[i].triangleCount;
        }
        if (a == Action::Raise) {  // one item per run of raises: the run ends with the item
            bool runEnds = it.lastEvent + 1 == events.size() ||
                           events[it.lastEvent + 1].action != Action::Raise;
            EXPECT_TRUE(runEnds) << "event " << it.lastEvent + 1 << " is a Raise too";
        } else {
            EXPECT_EQ(it.firstEvent, it.lastEvent) << "only raises merge";
        }
        std::string text = actionName(a);
        if (count == 1) text += " " + std::to_string(first);
        if (count > 1)
            text += " " + std::to_string(first) + "-" + std::to_string(first + count - 1);
        EXPECT_EQ(it.text, text);
        bool ends = a == Action::Spill || a == Action::Jump || a == Action::Fill;
        EXPECT_EQ(it.endsGroup, ends);
        EXPECT_EQ(it.separator, k + 1 == items.size() ? "" : ends ? "; " : ", ");
        next = it.lastEvent + 1;
    }
    for (; next < events.size(); ++next)
        EXPECT_EQ(events[next].action, Action::Start) << "event " << next << " is in no item";
}

}  // namespace

// A log written by hand: a run of raises is one item, a Start ends a run without an item of
// its own, a raise cutting nothing shows no range, a Spill, Jump or Fill ends a group.
TEST(TranscriptItems, GroupAHandWrittenLog) {
    std::vector<Event> ev{
        event(Action::Start, 0, 0),  event(Action::Raise, 0, 1), event(Action::Raise, 1, 2),
        event(Action::Bridge, 3, 0), event(Action::Raise, 3, 0), event(Action::Spill, 3, 0),
        event(Action::Raise, 3, 1),  event(Action::Start, 4, 0), event(Action::Raise, 4, 1),
        event(Action::Jump, 5, 0),   event(Action::Fill, 5, 2)};
    std::vector<TranscriptItem> items = transcriptItems(ev);
    struct Want {
        uint32_t first, last;
        const char* text;
        const char* separator;
    };
    const Want want[] = {{1, 2, "Raise 0-2", ", "}, {3, 3, "Bridge", ", "},
                         {4, 4, "Raise", ", "},     {5, 5, "Spill", "; "},
                         {6, 6, "Raise 3", ", "},   {8, 8, "Raise 4", ", "},
                         {9, 9, "Jump", "; "},      {10, 10, "Fill 5-6", ""}};
    ASSERT_EQ(items.size(), std::size(want));
    for (size_t k = 0; k < items.size(); ++k) {
        EXPECT_EQ(items[k].firstEvent, want[k].first) << k;
        EXPECT_EQ(items[k].lastEvent, want[k].last) << k;
        EXPECT_EQ(items[k].text, want[k].text) << k;
        EXPECT_EQ(items[k].separator, want[k].separator) << k;
    }
    EXPECT_TRUE(items.back().endsGroup) << "the last Fill ends its group, with nothing after it";
    expectItemsOf(ev, items);
    EXPECT_EQ(transcript(ev), "Raise 0-2, Bridge, Raise, Spill; Raise 3, Raise 4, Jump; Fill 5-6");
}

TEST(TranscriptItems, NoneForNoEventsOrStartsOnly) {
    EXPECT_TRUE(transcriptItems({}).empty());
    EXPECT_TRUE(transcriptItems({event(Action::Start, 0, 0), event(Action::Start, 0, 0)}).empty());
    EXPECT_EQ(transcript(std::vector<Event>{event(Action::Start, 0, 0)}), "");
}

// hole.json's items, read off its events: "Raise, Bridge 0, Raise 1, Spill; Raise 2-3, Jump;
// Raise 4-5, Fill 6-7" (tests/golden_transcripts.h) after the Start at event 0. Two of its
// raise items span two raises (one cutting nothing); "Raise 4-5" is one raise cutting two.
TEST(TranscriptItems, HoleItemsNameTheirEvents) {
    Trace t = record(readOrFail(sourcePath("polygons/hole.json")));
    std::vector<TranscriptItem> items = transcriptItems(t.events);
    ASSERT_EQ(t.events.size(), 11u);
    ASSERT_EQ(items.size(), 8u);
    const uint32_t first[] = {1, 2, 3, 5, 6, 8, 9, 10}, last[] = {1, 2, 4, 5, 7, 8, 9, 10};
    for (size_t k = 0; k < items.size(); ++k) {
        EXPECT_EQ(items[k].firstEvent, first[k]) << items[k].text;
        EXPECT_EQ(items[k].lastEvent, last[k]) << items[k].text;
    }
    EXPECT_EQ(items[4].text, "Raise 2-3");
    EXPECT_EQ(items[6].text, "Raise 4-5");
    expectItemsOf(t.events, items);
}

// Every sample and generated family: the rules hold, and the items joined are the transcript
// (the golden one where there is one).
TEST(TranscriptItems, JoinedAreTheTranscriptOfEverySample) {
    size_t golden = 0;
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json")) {
        SCOPED_TRACE(f);
        Trace t = record(readOrFail(f));
        std::vector<TranscriptItem> items = transcriptItems(t.events);
        expectItemsOf(t.events, items);
        std::string joined;
        for (const TranscriptItem& it : items) joined += it.text + it.separator;
        EXPECT_EQ(joined, transcript(t.events));
        EXPECT_EQ(transcript(items), joined);
        std::string name = f.substr(f.rfind('/') + 1);
        if (auto g = kGoldenTranscripts.find(name); g != kGoldenTranscripts.end()) {
            EXPECT_EQ(joined, g->second);
            ++golden;
        }
    }
    EXPECT_EQ(golden, kGoldenTranscripts.size()) << "every golden transcript was compared";
    for (const std::string& family : familyNames()) {
        SCOPED_TRACE(family);
        Trace t = record(generate(family, 3, 80));
        std::vector<TranscriptItem> items = transcriptItems(t.events);
        expectItemsOf(t.events, items);
        EXPECT_EQ(transcript(items), transcript(t.events));
    }
}
