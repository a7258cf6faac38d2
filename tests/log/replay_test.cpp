// Replay rebuilds the machine-visible state from the event log alone, with keyframes.
#include <gtest/gtest.h>

#include "flood/log/replay.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

std::vector<Trace> sampleTraces() {
    std::vector<Trace> traces;
    for (const std::string& family : familyNames())
        for (uint64_t seed : {1, 2}) traces.push_back(record(generate(family, seed, 150)));
    return traces;
}

// The replayed chain agrees with the fingers of every event: it runs from Left to Right,
// every bridge and jump splices chains consistently, and the run ends with nothing active.
TEST(Replay, ChainEndsAreLeftAndRightAtEveryStep) {
    for (const Trace& t : sampleTraces()) {
        ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
        Replay replay(t, 16);
        for (uint32_t k = 1; k <= replay.size(); ++k) {
            const ReplayState& s = replay.seek(k);
            if (s.fingers.left == kNone) {
                EXPECT_TRUE(s.chain.empty()) << "step " << k;
                continue;
            }
            ASSERT_FALSE(s.chain.empty()) << "step " << k;
            EXPECT_EQ(s.chain.front(), s.fingers.left) << "step " << k;
            EXPECT_EQ(s.chain.back(), s.fingers.right) << "step " << k;
        }
        const ReplayState& end = replay.seek(replay.size());
        EXPECT_EQ(end.triangleCount, t.triangles.size());
        EXPECT_TRUE(end.dormant.empty());
        EXPECT_TRUE(end.jumps.empty());
    }
}

// Seeking anywhere equals stepping there; stepping backward returns identical states.
TEST(Replay, SeekEqualsSteppingForwardAndBackward) {
    for (const Trace& t : sampleTraces()) {
        Replay stepper(t, 1u << 30);  // no keyframes but the first: pure stepping
        Replay seeker(t, 8);
        std::vector<ReplayState> forward;
        for (uint32_t k = 0; k <= stepper.size(); ++k) forward.push_back(stepper.seek(k));
        for (uint32_t k = seeker.size() + 1; k-- > 0;)
            ASSERT_TRUE(seeker.seek(k) == forward[k]) << "backward seek to " << k;
        for (uint32_t k : {7u, 3u, 40u, 0u, 99u, 12u}) {
            if (k <= seeker.size()) {
                ASSERT_TRUE(seeker.seek(k) == forward[k]) << "seek " << k;
            }
        }
    }
}

TEST(Replay, ForbiddenRunEndsOnTheForbiddenStep) {
    Polygon outside;
    outside.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    outside.addRing({{10, 10}, {10, 12}, {12, 12}}, false);
    Trace t = record(outside);
    ASSERT_FALSE(t.events.empty());
    EXPECT_EQ(t.events.back().action, Action::Forbidden);
    Replay replay(t);
    EXPECT_TRUE(replay.seek(replay.size()).forbidden);
    EXPECT_FALSE(replay.seek(replay.size() - 1).forbidden);
}

}  // namespace

// The replay state's operator== (flood/log/replay.h) sees a change in any one field, a dormant
// gorge's included.
TEST(Replay, StatesDifferingInAnyFieldAreUnequal) {
    Trace t = record(generate("staircase", 1, 60));
    Replay replay(t);
    ReplayState base;
    for (uint32_t s = 0; s <= replay.size() && base.dormant.empty(); ++s) base = replay.seek(s);
    ASSERT_FALSE(base.dormant.empty()) << "a step with a gorge waiting";
    ASSERT_FALSE(base.chain.empty());
    EXPECT_TRUE(base == ReplayState(base));
    std::vector<void (*)(ReplayState&)> changes{
        [](ReplayState& s) { ++s.step; },
        [](ReplayState& s) { ++s.part; },
        [](ReplayState& s) { ++s.fingers.nextRight; },
        [](ReplayState& s) { ++s.water; },
        [](ReplayState& s) { ++s.triangleCount; },
        [](ReplayState& s) { s.chain.pop_back(); },
        [](ReplayState& s) { s.dormant.pop_back(); },
        [](ReplayState& s) { ++s.dormant[0].id; },
        [](ReplayState& s) { s.dormant[0].held = !s.dormant[0].held; },
        [](ReplayState& s) { ++s.dormant[0].top; },
        [](ReplayState& s) { s.dormant[0].chain.push_back(0); },
        [](ReplayState& s) { s.jumps.emplace_back(1, 2); },
        [](ReplayState& s) { s.bridges.emplace_back(1, 2); },
        [](ReplayState& s) { s.forbidden = !s.forbidden; },
    };
    for (size_t i = 0; i < changes.size(); ++i) {
        ReplayState changed = base;
        changes[i](changed);
        EXPECT_FALSE(changed == base) << "change " << i;
        EXPECT_TRUE(changed != base) << "change " << i;
    }
}
