// The flood machine on generated and hand-drawn polygons: every result is proven by the
// exact checker; small cases also have golden transcripts (the paper's Fig. 7 notation).
#include <gtest/gtest.h>

#include "flood/log/replay.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "golden_transcripts.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// At least 10,000 polygons per run: every family, several sizes and seeds, each under
// the 8 rotations/mirrors, with ring orientation reversed and ring starts shifted.
TEST(Flood, GeneratedFamiliesAreExactValid) {
    size_t count = 0;
    for (const std::string& family : familyNames()) {
        for (size_t size : {8, 30, 120}) {
            for (uint64_t seed = 0; seed < 25; ++seed) {
                Polygon base = generate(family, seed, size);
                for (int rotation = 0; rotation < 4; ++rotation) {
                    for (bool mirror : {false, true}) {
                        Polygon p =
                            transform(base, rotation, mirror, seed % 2 == 1, seed * 7 + size);
                        std::string what = family + " size " + std::to_string(size) + " seed " +
                                           std::to_string(seed) + " rot " +
                                           std::to_string(rotation) + (mirror ? " mirrored" : "");
                        ASSERT_TRUE(validate(p, what).ok()) << what << " is not a valid polygon";
                        FloodResult r = triangulate(p);
                        ASSERT_TRUE(r.diagnostic.ok()) << what << ": " << r.diagnostic.message;
                        CheckResult c = checkTriangulation(p, r.triangles);
                        ASSERT_TRUE(c.ok) << what << ": " << c.reason;
                        ++count;
                    }
                }
            }
        }
    }
    EXPECT_GE(count, 10000u);
}

TEST(Flood, LargeGeneratedPolygons) {
    for (const std::string& family : familyNames())
        expectTriangulates(generate(family, 42, 5000), family + " size 5000");
}

TEST(Flood, EveryChosenVerticalGivesAValidTriangulation) {
    for (const char* family : {"comb", "spiral", "touching-holes", "rooms"}) {
        Polygon p = generate(family, 3, 200);
        for (Up up : {Up::PlusY, Up::MinusY, Up::PlusX, Up::MinusX})
            expectTriangulates(p, std::string(family) + " up " + upName(up), Options{up});
    }
}

// Recording is observation only: the same triangles in the same order with a listener.
TEST(Flood, ListenerDoesNotChangeTheTriangulation) {
    struct Counter : Listener {
        size_t n = 0;
        void onEvent(const Event&) override { ++n; }
    };
    for (const std::string& family : familyNames()) {
        Polygon p = generate(family, 7, 300);
        FloodResult quiet = triangulate(p);
        Counter counter;
        FloodResult heard = triangulate(p, &counter);
        EXPECT_EQ(quiet.triangles, heard.triangles) << family;
        EXPECT_EQ(quiet.steps, heard.steps) << family;
        EXPECT_EQ(counter.n, heard.steps) << family;
    }
}

TEST(Flood, SamplePolygonsAreExactValidInEveryPosition) {
    auto files = filesIn(sourcePath("polygons"), ".json");
    ASSERT_FALSE(files.empty());
    for (const std::string& f : files) {
        ReadResult rr = readPolygonFile(f);
        ASSERT_TRUE(rr.diagnostic.ok()) << rr.diagnostic.message;
        ASSERT_TRUE(validate(rr.polygon, f).ok());
        for (int rotation = 0; rotation < 4; ++rotation)
            for (bool mirror : {false, true})
                for (size_t shift : {0, 1, 5})
                    expectTriangulates(transform(rr.polygon, rotation, mirror, false, shift), f);
    }
}

std::string transcriptOf(const std::string& file) {
    return transcript(record(readOrFail(sourcePath("polygons/" + file))).events);
}

// Golden transcripts (tests/golden_transcripts.h): each small polygon shows one situation of
// the paper.
TEST(Flood, GoldenTranscripts) {
    for (const auto& [file, golden] : kGoldenTranscripts)
        EXPECT_EQ(transcriptOf(file), golden) << file;
}

// Each of the five actions appears where the polygon calls for it.
TEST(Flood, ActionsAppearWhereExpected) {
    auto count = [](const Trace& t, Action a) {
        return std::count_if(t.events.begin(), t.events.end(),
                             [&](const Event& e) { return e.action == a; });
    };
    Trace mono = record(readOrFail(sourcePath("polygons/monotone.json")));
    EXPECT_EQ(count(mono, Action::Bridge) + count(mono, Action::Spill) + count(mono, Action::Jump),
              0);
    EXPECT_EQ(count(mono, Action::Fill), 1);
    Trace holes = record(readOrFail(sourcePath("polygons/holes.json")));
    EXPECT_EQ(count(holes, Action::Bridge), 4) << "one bridge per hole";
    EXPECT_EQ(count(holes, Action::Spill), count(holes, Action::Jump))
        << "every spill is answered by a jump";
}

// Invalid input ends in a forbidden state (or at worst a result the checker rejects) —
// never a crash, a hang or a silent success.
TEST(Flood, InvalidLoopsEndInAForbiddenState) {
    Polygon hourglass;  // Fig. 11-A: the loop crosses itself
    hourglass.addRing({{0, 0}, {4, 4}, {4, 0}, {0, 4}}, true);
    FloodResult r = triangulate(hourglass);
    bool rejected = !r.diagnostic.ok() || !checkTriangulation(hourglass, r.triangles).ok;
    EXPECT_TRUE(rejected);

    Polygon outside;  // a hole outside its outer ring is never reached by the water
    outside.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    outside.addRing({{10, 10}, {10, 12}, {12, 12}}, false);
    r = triangulate(outside);
    EXPECT_EQ(r.diagnostic.status, Status::Forbidden);
    EXPECT_EQ(r.failure.reason, Forbidden::LeftBehind);
    EXPECT_NE(r.diagnostic.message.find("ring 1"), std::string::npos) << r.diagnostic.message;
}

TEST(Flood, InvalidPeerFixturesNeverCrashOrPassSilently) {
    std::string dir = sharedPath("peers/earcut/fixtures");
    auto files = filesIn(dir, ".json");
    if (files.empty()) GTEST_SKIP() << dir << " is absent: peer fixtures not checked";
    for (const std::string& f : files) {
        ReadResult rr = readPolygonFile(f);
        if (!rr.diagnostic.ok()) continue;
        FloodResult r = triangulate(rr.polygon);  // deliberately without validation
        if (r.diagnostic.ok() && checkTriangulation(rr.polygon, r.triangles).ok) continue;
        // Only validation finds T-junctions (touching2): a valid input failing unvalidated
        // must have some, and must flood once they are known.
        if (!validate(rr.polygon, f).ok()) continue;
        EXPECT_FALSE(rr.polygon.splits.empty())
            << f << ": valid input that did not flood: " << r.diagnostic.message;
        expectTriangulates(rr.polygon, f);
    }
}

}  // namespace
