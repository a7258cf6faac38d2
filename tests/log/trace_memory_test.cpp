// A trace's memory on every generated family, counted in bytes (never timed): its event log,
// most of it, is at most 100 bytes an event (the replay's keyframes beside it:
// tests/log/replay_memory_test.cpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "flood/log/replay.h"
#include "flood/tools/generate.h"

using namespace flood;

namespace {

// An event is 96 bytes (flood/machine/events.h); a log kept at the size it needs is 96 an event
// (tests/log/trace_format_test.cpp: a log read back from its file too). Before:
// 112-byte events in a log reserved for 1.5 events a vertex and doubled when that ran out,
// 112 to 224 bytes an event (grid-holes 185, touching-holes 224 at 10^5 vertices).
constexpr double kLogBytesPerEvent = 100;

TEST(TraceMemory, LogAtMost100BytesPerEventOnEveryFamily) {
    for (const std::string& family : familyNames()) {
        SCOPED_TRACE(family);
        Trace t = record(generate(family, 1, 20000));
        ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
        const double events = double(t.events.size());
        EXPECT_LE(double(t.events.capacity() * sizeof(Event)), kLogBytesPerEvent * events)
            << t.events.capacity() << " events held for " << t.events.size();
    }
}

}  // namespace

// The table of docs/BENCHMARKS.md ("Memory"), not run by default: per family, events per
// vertex, the log's and the keyframes' bytes per event at FLOOD_TABLE_SIZE vertices (10^5).
TEST(TraceMemory, DISABLED_TablePerFamily) {
    const char* size = std::getenv("FLOOD_TABLE_SIZE");
    const size_t n = size ? std::strtoul(size, nullptr, 10) : 100000;
    std::printf("| family | vertices | events/vertex | log B/event | keyframes B/event |\n");
    std::printf("|---|---:|---:|---:|---:|\n");
    for (const std::string& family : familyNames()) {
        Trace t = record(generate(family, 1, n));
        ASSERT_TRUE(t.diagnostic.ok()) << family << ": " << t.diagnostic.message;
        Replay replay(t);
        const double events = double(t.events.size());
        std::printf("| %s | %zu | %.2f | %.1f | %.1f |\n", family.c_str(),
                    t.polygon.vertices.size(), events / double(t.polygon.vertices.size()),
                    double(t.events.capacity() * sizeof(Event)) / events,
                    double(replay.keyframeBytes()) / events);
    }
}
