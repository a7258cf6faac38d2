// The trace file (flood/log/trace_io.h), version 2: an event line leaves out what its action does
// not use and what is at its initial value, reads back to the same events on every family,
// and version 1 files (every field written) still read.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using flood::testing::readOrFail;
using flood::testing::sourcePath;
using flood::testing::writtenAndRead;

namespace {

TEST(TraceFormat, RoundTripOnEveryFamily) {
    for (const std::string& family : familyNames()) {
        SCOPED_TRACE(family);
        Trace t = record(generate(family, 3, 1000));
        Trace back = writtenAndRead(t);
        ASSERT_EQ(back.events.size(), t.events.size());
        for (size_t i = 0; i < t.events.size(); ++i)  // every field (FLOOD_EVENT_FIELDS)
            ASSERT_TRUE(back.events[i] == t.events[i]) << "event " << i << " changed on the way";
        EXPECT_EQ(back.triangles, t.triangles);
        // The log read back keeps no slack (96 bytes an event, tests/log/trace_memory_test.cpp).
        EXPECT_EQ(back.events.capacity(), back.events.size());
    }
}

// Version 1 wrote every field of every event (a Bridge's null "top" and "culprit" too); those
// files, written by the build before version 2, read to the events a run records today.
TEST(TraceFormat, Version1FilesStillRead) {
    for (const char* name :
         {"holes-v1", "forbidden-jump-wrong-side-v1", "forbidden-spill-no-bottom-v1"}) {
        SCOPED_TRACE(name);
        Trace old;
        Diagnostic d =
            readTraceFile(sourcePath(std::string("tests/traces/") + name + ".jsonl"), old);
        ASSERT_TRUE(d.ok()) << d.message;
        Trace now = record(old.polygon);
        ASSERT_EQ(old.events.size(), now.events.size());
        for (size_t i = 0; i < now.events.size(); ++i)
            EXPECT_TRUE(old.events[i] == now.events[i]) << "event " << i;
        EXPECT_EQ(old.triangles, now.triangles);
        EXPECT_EQ(old.diagnostic.status, now.diagnostic.status);
    }
}

// What an event line holds: its action's fields only, defaults left out. A Raise names no
// sag, top or culprit; a Bridge names its sag but not the top its storage shares.
TEST(TraceFormat, LinesHoldOnlyWhatTheActionUses) {
    Trace t = record(readOrFail(sourcePath("polygons/holes.json")));
    std::ostringstream out;
    writeTrace(out, t);
    std::istringstream lines(out.str());
    std::string line;
    std::getline(lines, line);  // header
    bool sawBridge = false, sawSpill = false;
    for (const Event& e : t.events) {
        std::getline(lines, line);
        SCOPED_TRACE(line);
        const bool bridge = e.action == Action::Bridge, spill = e.action == Action::Spill;
        sawBridge |= bridge, sawSpill |= spill;
        EXPECT_EQ(line.find("\"sag\"") != std::string::npos, bridge);
        EXPECT_EQ(line.find("\"top\"") != std::string::npos, spill || e.action == Action::Jump);
        EXPECT_EQ(line.find("\"culprit\""), std::string::npos);
        EXPECT_EQ(line.find("null"), std::string::npos);  // every kNone is a default
    }
    EXPECT_TRUE(sawBridge && sawSpill);
}

// Bytes a `flood trace` file spends per event: version 1 wrote about 590 on circle-holes
// (every field of every event, most of them null or 0).
TEST(TraceFormat, FileBytesPerEvent) {
    Trace t = record(generate("circle-holes", 1, 20000));
    std::ostringstream out;
    writeTrace(out, t);
    EXPECT_LT(double(out.str().size()) / double(t.events.size()), 400.0);
}

}  // namespace
