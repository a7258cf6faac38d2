// A run in slices (SteppedRun, Recording) is the run whole: the same events, triangles and
// diagnostic however small the slices, on valid families, multi-part ones and invalid input
// that ends in a forbidden state.
#include <gtest/gtest.h>

#include <cmath>

#include "flood/log/replay.h"
#include "flood/tools/generate.h"

using namespace flood;

namespace {

struct Collect : Listener {
    std::vector<Event> events;
    void onEvent(const Event& e) override { events.push_back(e); }
};

// The run whole, through triangulate() (the listener's path and the quiet one).
struct Whole {
    std::vector<Event> events;
    FloodResult result;
    std::vector<Triangle> quietTriangles;
    Status quietStatus;
};
Whole whole(const Polygon& p, const Options& o) {
    Collect c;
    Whole w;
    w.result = triangulate(p, &c, o);
    w.events = std::move(c.events);
    FloodResult quiet = triangulate(p, nullptr, o);
    w.quietTriangles = std::move(quiet.triangles);
    w.quietStatus = quiet.diagnostic.status;
    return w;
}

void expectSame(const Trace& t, const Whole& w, const std::string& what) {
    ASSERT_EQ(t.events.size(), w.events.size()) << what;
    for (size_t i = 0; i < t.events.size(); ++i)
        ASSERT_TRUE(t.events[i] == w.events[i]) << what << ": event " << i;
    EXPECT_EQ(t.triangles.size(), w.result.triangles.size()) << what;
    EXPECT_TRUE(t.triangles == w.result.triangles) << what;
    EXPECT_TRUE(t.triangles == w.quietTriangles || !t.diagnostic.ok()) << what;
    EXPECT_EQ(t.diagnostic.status, w.result.diagnostic.status) << what;
    EXPECT_EQ(t.diagnostic.status, w.quietStatus) << what;
    EXPECT_EQ(t.diagnostic.message, w.result.diagnostic.message) << what;
}

// Records `p` `slice` steps at a time, counting the slices; checks that each slice takes what it may and no more.
Trace inSlices(const Polygon& p, const Options& o, uint64_t slice, uint32_t& slices) {
    Recording r(p, o);
    slices = 0;
    uint32_t before = r.steps();
    while (r.advance(slice)) {
        ++slices;
        // Each step is an event; a part begun in the slice adds its Start, one ended its check.
        EXPECT_GE(r.steps() - before, slice) << "a slice not ended by the run takes all it may";
        EXPECT_LE(r.steps() - before, slice + 2 * p.parts.size());
        before = r.steps();
    }
    EXPECT_LE(r.steps() - before, slice + 2 * p.parts.size())
        << "the last slice: its steps, plus each part's Start and end check";
    ++slices;  // the last
    return r.take();
}

TEST(SteppedRun, SlicesRecordTheRunWhole) {
    size_t forbidden = 0, multiPart = 0;
    auto check = [&](const Polygon& p, const std::string& name) {
        const Whole w = whole(p, {});
        forbidden += !w.result.diagnostic.ok();
        multiPart += p.parts.size() > 1;
        for (uint64_t slice : {1, 2, 7, 64, 100000}) {
            uint32_t slices = 0;
            const Trace t = inSlices(p, {}, slice, slices);
            expectSame(t, w, name + " in slices of " + std::to_string(slice));
            if (slice == 1) {
                EXPECT_GE(slices + 2 * p.parts.size(), w.events.size()) << name;
            }
        }
    };
    for (const std::string& family : familyNames())
        for (uint64_t seed : {1, 2, 3}) check(generate(family, seed, 300), family);
    for (const std::string& family : invalidFamilyNames())
        for (uint64_t seed : {1, 2}) check(generateInvalid(family, seed, 200), family);
    EXPECT_GT(forbidden, 5u) << "invalid input must reach forbidden states mid-run";
    EXPECT_GT(multiPart, 5u) << "parts must follow one another across slices";
}

TEST(SteppedRun, ASliceOfNothingTakesNoStep) {
    const Polygon p = generate("comb", 1, 200);
    Recording r(p);
    EXPECT_TRUE(r.advance(3));
    const uint32_t taken = r.steps();
    EXPECT_TRUE(r.advance(0));
    EXPECT_EQ(r.steps(), taken);
    while (r.advance(50)) {
    }
    EXPECT_FALSE(r.advance(50)) << "a run that has ended stays ended";
    const Trace t = r.take();
    EXPECT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
    EXPECT_EQ(t.events.size(), record(p).events.size());
}

TEST(SteppedRun, ADirectionThatIsNoneEndsAtOnce) {
    const Polygon p = generate("star", 1, 50);
    Options o;
    o.up = Up{0, 0};
    Recording r(p, o);
    EXPECT_FALSE(r.advance(1));
    const Trace t = r.take();
    EXPECT_EQ(t.diagnostic.status, Status::Usage);
    EXPECT_TRUE(t.events.empty());
    EXPECT_EQ(t.diagnostic.message, triangulate(p, nullptr, o).diagnostic.message);
}

}  // namespace
