// The machine's invariants checked on the replay (flood/check/invariants.h): none broken on valid
// input, broken on invalid input before the machine stops (or where it never does), a
// tampered log caught, and the whole check in work linear in the trace.
#include <gtest/gtest.h>

#include <cstdio>

#include "flood/check/invariants.h"
#include "flood/geometry/work.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {
// The Forbidden step (its event index + 1), or one past the log when the machine never stops.
uint32_t forbiddenStep(const Trace& t) {
    for (const Event& e : t.events)
        if (e.action == Action::Forbidden) return e.step + 1;
    return uint32_t(t.events.size()) + 1;
}
Trace recordFile(const std::string& rel) {
    ReadResult r = readPolygonFile(sourcePath(rel));
    EXPECT_TRUE(r.diagnostic.ok()) << rel << ": " << r.diagnostic.message;
    return record(r.polygon);  // --no-validate: the machine sees the invalid polygon
}
}  // namespace

TEST(Invariants, NoneBrokenOnValidInput) {
    size_t runs = 0, steps = 0;
    for (const std::string& family : familyNames())
        for (size_t size : {8, 30, 120, 600})
            for (uint64_t seed = 0; seed < 5; ++seed) {
                Polygon p = generate(family, seed, size);
                ASSERT_TRUE(validate(p, family).ok());
                Trace t = record(p);
                ASSERT_TRUE(t.diagnostic.ok()) << family;
                std::vector<Violation> v = checkInvariants(t);
                ASSERT_TRUE(v.empty())
                    << family << " size " << size << " seed " << seed << ", step " << v[0].step
                    << ": " << invariantName(v[0].which) << ": " << v[0].detail;
                ++runs, steps += t.events.size();
            }
    for (const char* dir : {"polygons", "polygons/regress", "polygons/conjecture"})
        for (const std::string& f : filesIn(sourcePath(dir), ".json")) {
            ReadResult r = readPolygonFile(f);
            if (!r.diagnostic.ok() || !validate(r.polygon, f).ok())
                continue;  // kept as invalid input
            Trace t = record(r.polygon);
            ASSERT_TRUE(t.diagnostic.ok()) << f;
            std::vector<Violation> v = checkInvariants(t);
            ASSERT_TRUE(v.empty()) << f << ", step " << v[0].step << ": "
                                   << invariantName(v[0].which) << ": " << v[0].detail;
            ++runs;
        }
    EXPECT_GT(runs, 400u);
    EXPECT_GT(steps, 50000u);
}

// Named cases: the machine stops later (or never: only the exact checker saw these).
TEST(Invariants, BrokenBeforeTheMachineStopsOnInvalidFiles) {
    struct Case {
        const char* file;
        Invariant which;
        uint32_t step;
    };
    const Case cases[] = {
        {"polygons/invalid/forbidden-ceiling-as-end.json", Invariant::FingersAboveWater, 2},
        {"polygons/invalid/fig11-b-ceiling.json", Invariant::TriangleEmpty, 3},
        {"polygons/invalid/hole-crossing-outer.json", Invariant::TriangleEmpty, 7},
        {"polygons/invalid/forbidden-bad-triangle.json", Invariant::TriangleEmpty, 3},
        {"polygons/invalid/vertex-on-own-edge.json", Invariant::TriangleEmpty, 3},
        {"polygons/invalid/parts-overlapping.json", Invariant::TriangleEmpty, 3},
        {"polygons/invalid/parts-crossing-at-junction.json", Invariant::TriangleEmpty, 3},
    };
    for (const Case& c : cases) {
        Trace t = recordFile(c.file);
        std::vector<Violation> v = checkInvariants(t);
        ASSERT_FALSE(v.empty()) << c.file;
        EXPECT_EQ(v[0].which, c.which) << c.file << ": " << v[0].detail;
        EXPECT_EQ(v[0].step, c.step) << c.file << ": " << v[0].detail;
        EXPECT_LT(v[0].step, forbiddenStep(t)) << c.file;
        EXPECT_FALSE(v[0].vertices.empty());
    }
}

// Over the invalid families: how often the lane fires before the machine stops. The figure
// is printed; the floor is what this checker reaches today (families whose defect the
// triangles never touch, like a hole outside, are left to the machine's LeftBehind).
TEST(Invariants, UsuallyBrokenBeforeTheMachineStopsOnInvalidFamilies) {
    size_t runs = 0, before = 0;
    for (const std::string& family : invalidFamilyNames()) {
        size_t mine = 0;
        for (uint64_t seed = 0; seed < 10; ++seed) {
            Trace t = record(generateInvalid(family, seed, 200));
            std::vector<Violation> v = checkInvariants(t);
            ++runs;
            if (!v.empty() && v[0].step < forbiddenStep(t)) ++before, ++mine;
        }
        std::printf("  %-22s %zu/10 before the machine stops\n", family.c_str(), mine);
    }
    std::printf("  all invalid families: %zu/%zu\n", before, runs);
    EXPECT_GE(before * 3, runs);
    for (const char* family :
         {"vertex-on-own-edge", "hole-crossing-outer", "parts-crossing", "part-inside-part"})
        for (uint64_t seed = 0; seed < 4; ++seed) {
            Trace t = record(generateInvalid(family, seed, 200));
            std::vector<Violation> v = checkInvariants(t);
            ASSERT_FALSE(v.empty()) << family << " seed " << seed;
            EXPECT_LT(v[0].step, forbiddenStep(t)) << family << " seed " << seed;
        }
}

// A log that lies about what the machine did is caught at the step that lies.
TEST(Invariants, TamperedLogsAreCaught) {
    Trace good = record(generate("circle-holes", 2, 300));
    ASSERT_TRUE(checkInvariants(good).empty());
    {
        Trace t = good;  // a triangle turned clockwise
        uint32_t k = 0;
        while (t.events[k].triangleCount == 0) ++k;
        std::swap(t.triangles[t.events[k].firstTriangle][0],
                  t.triangles[t.events[k].firstTriangle][1]);
        std::vector<Violation> v = checkInvariants(t);
        ASSERT_FALSE(v.empty());
        EXPECT_EQ(v[0].which, Invariant::TrianglesCounterClockwise);
        EXPECT_EQ(v[0].step, k + 1);
    }
    {
        Trace t = good;  // a gorge taken that was never put on the to-do list
        uint32_t k = 0;
        while (t.events[k].gorgePopped == kNone) ++k;
        t.events[k].gorgePopped += 1000;
        std::vector<Violation> v = checkInvariants(t);
        ASSERT_FALSE(v.empty());
        EXPECT_EQ(v[0].which, Invariant::LoopsConsistent);
        EXPECT_EQ(v[0].step, k + 1);
    }
}

// Work per event stays flat from 2000 to 16000 vertices: the chain is checked where it
// changed, and each triangle in at most kMaxCells grid cells.
TEST(Invariants, WorkIsLinearInTheTrace) {
    for (const char* family : {"circle-holes", "comb", "star", "spiral"}) {
        double perEvent[2];
        int i = 0;
        for (size_t size : {2000, 16000}) {
            Trace t = record(generate(family, 1, size));
            work() = {};
            EXPECT_TRUE(checkInvariants(t).empty());
            double events = double(t.events.size());
            perEvent[i++] = double(work().orientCalls + work().invariantSteps) / events;
        }
        std::printf("  %-14s work per event: %.1f at 2000, %.1f at 16000\n", family, perEvent[0],
                    perEvent[1]);
        EXPECT_LT(perEvent[1], 2000) << family;
        // Eight times the vertices: an O(n^1.5) check would cost 2.8 times as much per event.
        EXPECT_LT(perEvent[1], 2 * perEvent[0]) << family;
    }
}

TEST(Invariants, ProgressAndCancel) {
    Trace t = record(generate("comb", 1, 2000));
    std::atomic<uint32_t> progress{0};
    std::atomic<bool> cancel{false};
    checkInvariants(t, &progress, &cancel);
    EXPECT_EQ(progress.load(), t.events.size());
    cancel = true;
    progress = 0;
    EXPECT_TRUE(checkInvariants(t, &progress, &cancel).empty());
    EXPECT_EQ(progress.load(), 0u);
}

// Found by fuzz_trace on a binary trace: vertices spread so far apart that the grid's cell came
// out 1e-300 wide, and a vertex's cell number (5e121) was converted to an integer — undefined
// (UBSan in the sanitizer build). The cell numbers are clamped while still doubles; the
// invariant scan reads the trace to its end.
TEST(Invariants, FarVerticesDoNotOverflowTheGrid) {
    Trace t;
    Diagnostic d = readTraceFile(sourcePath("tests/traces/fuzz-far-vertex.bin"), t);
    ASSERT_TRUE(d.ok()) << d.message;
    ASSERT_FALSE(t.events.empty());
    std::vector<Violation> v = checkInvariants(t);
    for (const Violation& x : v) EXPECT_LE(x.step, t.events.size());
}
