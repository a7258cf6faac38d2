// Replay rebuilds the machine-visible state from the event log alone, with keyframes.
#include <gtest/gtest.h>

#include "generate.h"
#include "replay.h"
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
