// The to-do list model (flood/teach/todo_list.h): at every step of runs with bridges and spills it
// holds exactly the replay state's pending and held gorges, the pending ones in the order the
// machine takes them, the held ones with the top and jump pointer their Jump will use.
#include <gtest/gtest.h>

#include <algorithm>

#include "flood/log/replay.h"
#include "flood/teach/todo_list.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// Returns how many steps had a non-empty list.
size_t expectListMatchesReplay(const Polygon& polygon, const std::string& what) {
    Trace t = record(polygon);
    Replay replay(t, 16);
    size_t busy = 0;
    for (uint32_t step = 0; step < t.events.size(); ++step) {
        const ReplayState& s = replay.seek(step);  // the state the event `step` starts from
        TodoList list = todoList(s);
        size_t pending = 0, held = 0;
        for (const Gorge& g : s.dormant) (g.held ? held : pending)++;
        EXPECT_EQ(list.pending.size(), pending) << what << " at step " << step;
        EXPECT_EQ(list.held.size(), held) << what << " at step " << step;
        busy += pending + held > 0;
        for (const TodoEntry& h : list.held) {
            const Gorge& g = s.dormant[h.dormant];
            EXPECT_TRUE(g.held);
            EXPECT_EQ(h.gorge, g.id);
            EXPECT_EQ(h.top, g.top);
            EXPECT_NE(h.jumpTarget, kNone) << what << ": a held gorge's top has its jump pointer";
        }
        const Event& e = t.events[step];
        // A Fill takes the pending gorge on top of the stack.
        if (e.action == Action::Fill && e.gorgePopped != kNone) {
            EXPECT_FALSE(list.pending.empty()) << what;
            if (!list.pending.empty()) {
                EXPECT_EQ(list.pending.front().gorge, e.gorgePopped) << what << " at step " << step;
            }
        }
        // A Jump takes a held gorge at its top, along the jump pointer the Spill set.
        if (e.action == Action::Jump) {
            auto it = std::find_if(list.held.begin(), list.held.end(),
                                   [&](const TodoEntry& h) { return h.gorge == e.gorgePopped; });
            EXPECT_NE(it, list.held.end()) << what << " at step " << step;
            if (it == list.held.end()) continue;
            EXPECT_EQ(it->top, e.top);
            EXPECT_EQ(it->jumpTarget, e.jumpTarget);
        }
    }
    return busy;
}

}  // namespace

TEST(TodoList, MatchesReplayStateAtEveryStep) {
    size_t busy = 0;
    for (const char* f :
         {"polygons/paper-figure-7.json", "polygons/holes.json", "polygons/pending-bottoms.json",
          "polygons/comb.json", "polygons/two-gorges.json"})
        busy += expectListMatchesReplay(readOrFail(sourcePath(f)), f);
    for (const std::string& family : familyNames())
        busy += expectListMatchesReplay(generate(family, 2, 300), family);
    EXPECT_GT(busy, 100u);  // the runs do put gorges away
}

TEST(TodoList, EmptyBeforeTheFirstStep) {
    Trace t = record(readOrFail(sourcePath("polygons/paper-figure-7.json")));
    Replay replay(t);
    TodoList list = todoList(replay.seek(0));
    EXPECT_TRUE(list.pending.empty());
    EXPECT_TRUE(list.held.empty());
}
