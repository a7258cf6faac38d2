// An event in one line (flood/teach/describe.h), as the viewer's Events panel, timeline and caption
// show it: the action, the vertices it moved, the triangles it cut.
#include <gtest/gtest.h>

#include "flood/log/replay.h"
#include "flood/teach/describe.h"
#include "flood/teach/narrate.h"
#include "flood/teach/transcript.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

// two-gorges.json (0,0) (4,1) (5,6) (6,2) (10,0.5) (10,10) (0,10): the water starts at vertex
// 0, rises on the right to 1 and to the top 2, spills over it into the gorge of bottom 4,
// rises there to 3 and 2, jumps back to 0, rises to 6 and fills at 5.
TEST(DescribeEvent, TwoGorgesLineByLine) {
    Trace t = record(readOrFail(sourcePath("polygons/two-gorges.json")));
    std::vector<std::string> lines;
    for (const Event& e : t.events) lines.push_back(describeEvent(t.polygon, e));
    EXPECT_EQ(lines, (std::vector<std::string>{
                         "Start at bottom 0 (part 0)",
                         "Raise Right: NextRight 1 joins the chain",
                         "Raise Right: NextRight 2 joins the chain; triangle 0",
                         "Spill over top 2 (jump -> 0), new gorge at 4",
                         "Raise Left: NextLeft 3 joins the chain",
                         "Raise Left: NextLeft 2 joins the chain; triangle 1",
                         "Jump from top 2 to 0",
                         "Raise Left: NextLeft 6 joins the chain; triangle 2",
                         "Fill at 5; triangles 3-4",
                     }));
}

// A Bridge names its sag, the chain vertex it joins and the gorge it leaves pending.
TEST(DescribeEvent, BridgeNamesThePendingGorge) {
    Trace t = record(readOrFail(sourcePath("polygons/pending-bottoms.json")));
    ASSERT_EQ(t.events[2].action, Action::Bridge);
    EXPECT_EQ(describeEvent(t.polygon, t.events[2]),
              "Bridge sag 4 to 1, gorge 0 pending; triangle 0");
}

// Every event of every sample: one line, opening with its action, ending with the triangles
// it cut; a Forbidden event says what describeForbidden() says.
TEST(DescribeEvent, EveryEventOfEverySample) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json"))
        if (f.find("forbidden-") != std::string::npos) files.push_back(f);
    size_t forbidden = 0;
    for (const std::string& f : files) {
        SCOPED_TRACE(f);
        Trace t = record(readOrFail(f));
        for (const Event& e : t.events) {
            std::string line = describeEvent(t.polygon, e);
            EXPECT_EQ(line.find('\n'), std::string::npos) << line;
            EXPECT_EQ(line.rfind(actionName(e.action), 0), 0u) << line;
            std::string cut =
                e.triangleCount == 0 ? ""
                : e.triangleCount == 1
                    ? "; triangle " + triangleRange(e.firstTriangle, 1)
                    : "; triangles " + triangleRange(e.firstTriangle, e.triangleCount);
            if (cut.empty()) EXPECT_EQ(line.find("; triangle"), std::string::npos) << line;
            else EXPECT_EQ(line.substr(line.size() - cut.size()), cut) << line;
            if (e.action == Action::Forbidden) {
                ++forbidden;
                EXPECT_EQ(line, "Forbidden: " + describeForbidden(t.polygon, e) + cut);
            }
        }
    }
    EXPECT_GE(forbidden, 8u) << "each forbidden-*.json sample stops in a Forbidden event";
}

// A Spill says where the water goes on, by its vertex: a new gorge at a bottom, or the pending
// gorge it runs into (no "new gorge at -", issue 26).
TEST(DescribeEvent, EverySpillNamesWhereTheWaterGoes) {
    size_t resumed = 0;
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json")) {
        SCOPED_TRACE(f);
        Trace t = record(readOrFail(f));
        for (const Event& e : t.events) {
            if (e.action != Action::Spill) continue;
            std::string line = describeEvent(t.polygon, e);
            EXPECT_EQ(line.find("at -"), std::string::npos) << line;
            EXPECT_TRUE(line.find(", new gorge at ") != std::string::npos ||
                        line.find(", into pending gorge ") != std::string::npos)
                << line;
            if (e.bottom == kNone) {
                ++resumed;
                EXPECT_NE(line.find(" at " + std::to_string(e.after.left)), std::string::npos)
                    << line;
            }
        }
    }
    EXPECT_GE(resumed, 1u) << "a sample spills into a pending gorge";
}

// Coordinates in a forbidden transition's line read as written: the shortest text that reads
// back as the same double (-127.71, not -127.70999999999999; issue 26).
TEST(DescribeEvent, ForbiddenCoordinatesAreShortestRoundTrip) {
    Polygon p;
    p.addRing({{-127.71, 50.1}, {-127.7, 50.3}, {-127.6, 50.1}}, true);
    Event e;
    e.action = Action::Forbidden;
    e.reason = Forbidden::StartNotBottom;
    e.culprit = 0;
    const std::string s = describeForbidden(p, e);
    EXPECT_NE(s.find("(ring 0 vertex 0, -127.71, 50.1)"), std::string::npos) << s;
    EXPECT_EQ(s.find("9999"), std::string::npos) << s;
}
