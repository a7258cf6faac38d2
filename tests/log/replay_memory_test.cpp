// Replay keyframes stay small and seeks stay short on every generated family, at every size:
// counted in bytes and in events re-applied, never timed.
#include <gtest/gtest.h>

#include <string>

#include "flood/log/prefix_tree.h"
#include "flood/log/replay.h"
#include "flood/tools/generate.h"

using namespace flood;

namespace {

// Keyframes cost at most this many bytes per event of the log they index: the spacing rule
// lets a keyframe copy Replay::kKeyframeRatio = 16 indices (64 bytes) per event since the one
// before, and what keyframes share (dormant gorges, their chains, jump pointers, bridges) is
// stored once per push, a few indices per event. 64 bytes is also under half of an Event
// (112 bytes): the keyframes never cost more than the log itself. Before the shared lists, a
// monotone staircase (one new dormant gorge per step, all waiting at once) took 182 bytes
// per event at 10^4 vertices and 12,355 at 10^5 (1.2 GB).
constexpr double kBytesPerEvent = 64;

// A seek re-applies at most this many events. Keyframes come every 256 events of work
// (the default interval) unless the one due would copy more than 16 indices per event since
// the last: then it waits for enough events to pay for its copy, so the gap is about the
// active chain's length / 16. The longest chains here (comb, equal-heights at 10^5, about 15k
// vertices) give under 1,000 events; 16 intervals leave room. The hard cap, whatever the
// input, is Replay::kMaxWorkFactor intervals (32,768 events).
constexpr uint32_t kMaxSeekEvents = 16 * 256;

TEST(ReplayMemory, KeyframesLinearAndSeeksShortOnEveryFamily) {
    for (size_t n : {1000u, 10000u, 100000u})
        for (const std::string& family : familyNames()) {
            SCOPED_TRACE(family + " at " + std::to_string(n));
            Trace t = record(generate(family, 1, n));
            ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
            Replay replay(t);
            const double events = double(t.events.size());
            EXPECT_LT(double(replay.keyframeBytes()), kBytesPerEvent * events)
                << replay.keyframeBytes() / events << " bytes per event";
            EXPECT_LE(replay.maxSeekEvents(), kMaxSeekEvents);
            EXPECT_LE(replay.maxSeekEvents(), 256 * Replay::kMaxWorkFactor);
            // Backward seeks restore a keyframe each time; none re-applies more than promised.
            uint32_t most = 0;
            for (uint32_t k = 0; k <= 200; ++k) {
                replay.seek(uint32_t(uint64_t(replay.size()) * (200 - k) / 200));
                most = std::max(most, replay.lastSeekEvents());
            }
            EXPECT_LE(most, replay.maxSeekEvents());
        }
}

// The worst seek is real: seeking to the step before the farthest keyframe re-applies exactly
// maxSeekEvents(), and the shared lists restore the same state as stepping there.
TEST(ReplayMemory, WorstSeekIsMeasuredAndExact) {
    for (const char* family : {"staircase", "rooms", "comb"}) {
        SCOPED_TRACE(family);
        Trace t = record(generate(family, 2, 4000));
        ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
        Replay seeker(t), stepper(t, 1u << 30);  // stepper: the first keyframe only
        uint32_t worst = 0, at = 0;
        for (uint32_t s = 0; s <= seeker.size(); ++s) {
            seeker.seek(0);  // from the start, so the seek restores the keyframe nearest s
            seeker.seek(s);
            if (seeker.lastSeekEvents() > worst) worst = seeker.lastSeekEvents(), at = s;
        }
        EXPECT_EQ(worst, seeker.maxSeekEvents());
        for (uint32_t s : {at, seeker.size() / 3, seeker.size() / 2, 7u, seeker.size()}) {
            const ReplayState& want = stepper.seek(s);
            const ReplayState& got = seeker.seek(s);
            EXPECT_TRUE(got == want) << "step " << s;
        }
    }
}

// Stepping back restores the keyframe before, but rewrites only the dormant gorges and jump
// pointers the steps since it changed: an event changes at most two dormant positions (a
// Spill pushes one and takes one) and one jump pointer, so at most 3 per event re-applied.
// The staircase keeps up to n/2 gorges dormant: before, every step back rewrote them all.
TEST(ReplayMemory, SteppingBackRewritesOnlyWhatChanged) {
    Trace t = record(generate("staircase", 1, 100000));
    ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
    Replay replay(t);
    for (uint32_t start : {replay.size() / 3, 2 * replay.size() / 3}) {
        replay.seek(start);
        ASSERT_GT(replay.state().dormant.size(), 10000u);
        size_t most = 0;
        for (int k = 0; k < 600; ++k) {
            replay.seek(replay.state().step - 1);
            most = std::max(most, replay.lastSeekRestored());
        }
        EXPECT_LE(most, 3u * replay.maxSeekEvents() + 3) << "from step " << start;
        // What stayed is right: the same state as a seek from the start of a fresh replay.
        Replay fresh(t);
        const ReplayState& want = fresh.seek(replay.state().step);
        EXPECT_TRUE(replay.state() == want) << "at step " << want.step;
    }
}

// Versions of a list share the prefix they keep: only the entries after it cost a node, and
// loading a version can skip the prefix it shares with another.
TEST(PrefixTree, VersionsShareTheirPrefix) {
    PrefixTree<int> tree;
    std::vector<std::vector<int>> versions = {{1, 2, 3}, {1, 2, 3, 4, 5}, {1, 2}, {1, 2, 9}, {},
                                              {7}};
    std::vector<size_t> keep = {0, 3, 2, 2, 0, 0};
    std::vector<uint32_t> heads;
    for (size_t v = 0; v < versions.size(); ++v)
        heads.push_back(
            tree.store(versions[v].size(), keep[v], [&](size_t i) { return versions[v][i]; }));
    EXPECT_EQ(tree.nodeCount(), 3u + 2 + 0 + 1 + 0 + 1);
    for (size_t v = 0; v < versions.size(); ++v) {
        std::vector<int> back(versions[v].size(), -1);
        tree.load(heads[v], back.size(), 0, [&](size_t i, int x) { back[i] = x; });
        EXPECT_EQ(back, versions[v]) << "version " << v;
    }
    auto common = [&](size_t a, size_t b) {
        return tree.commonPrefix(heads[a], versions[a].size(), heads[b], versions[b].size());
    };
    EXPECT_EQ(common(0, 1), 3u);
    EXPECT_EQ(common(1, 3), 2u);
    EXPECT_EQ(common(3, 5), 0u);  // {7} is a new node, not an entry of {1, 2, 9}
    EXPECT_EQ(common(4, 4), 0u);
    std::vector<int> tail(5, -1);
    tree.load(heads[1], 5, 3, [&](size_t i, int x) { tail[i] = x; });  // entries 3 and 4 only
    EXPECT_EQ(tail, (std::vector<int>{-1, -1, -1, 4, 5}));
}

}  // namespace
