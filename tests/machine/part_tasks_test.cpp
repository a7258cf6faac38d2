// triangulate() with a TaskRunner: a MultiPolygon's parts flooded as tasks give the serial
// run's result, triangle for triangle, and the serial run's failure when a part is forbidden.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// The pieces side by side along x, apart, each part of each a part of one polygon.
Polygon sideBySide(const std::vector<Polygon>& pieces) {
    std::vector<Point> offsets;
    double x = 0;
    for (const Polygon& piece : pieces) {
        double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
        for (Point v : piece.vertices) x0 = std::min(x0, v.x), x1 = std::max(x1, v.x);
        offsets.push_back({x - x0, 0});
        x += x1 - x0 + 1;
    }
    return layout(pieces, offsets);
}

// Floods p serially, then as tasks run backwards and on two threads: the same result each
// time. Returns how often the runner was called.
size_t expectSerialResult(const Polygon& p, const std::string& what, const Options& o = {}) {
    const FloodResult serial = triangulate(p, nullptr, o);
    Backwards back;
    for (const TaskRunner& run : {back.runner(), TaskRunner(twoThreads)}) {
        const FloodResult r = triangulate(p, nullptr, o, run);
        EXPECT_TRUE(r.triangles == serial.triangles) << what;
        EXPECT_EQ(r.steps, serial.steps) << what;
        EXPECT_EQ(r.diagnostic.status, serial.diagnostic.status) << what;
        EXPECT_EQ(r.diagnostic.message, serial.diagnostic.message) << what;
        EXPECT_EQ(r.diagnostic.culprits.vertices, serial.diagnostic.culprits.vertices) << what;
        EXPECT_EQ(r.failure.step, serial.failure.step) << what;
        EXPECT_EQ(r.failure.reason, serial.failure.reason) << what;
    }
    return back.calls;
}

TEST(PartTasks, ValidMultiPolygonsGiveTheSerialTriangles) {
    std::vector<Polygon> inputs;
    for (uint64_t seed : {1, 2}) inputs.push_back(generate("islands", seed, 50000));
    // Parts of every kind the machine meets: holes, touching rings, T-junctions, Steiner
    // points, many minima.
    std::vector<Polygon> mix;
    const char* families[] = {"star",    "circle-holes", "touching-holes", "t-junctions",
                              "steiner", "rooms",        "comb",           "touching-outer"};
    for (uint64_t k = 0; k < 24; ++k) mix.push_back(generate(families[k % 8], k, 2000));
    inputs.push_back(sideBySide(mix));
    for (size_t i = 0; i < inputs.size(); ++i) {
        Polygon& p = inputs[i];
        const std::string what = "input " + std::to_string(i);
        ASSERT_GE(p.vertices.size(), 32768u) << what;
        ASSERT_TRUE(validate(p, what).ok()) << what;
        EXPECT_EQ(expectSerialResult(p, what), 1u) << what << ": the tasks were not used";
        const FloodResult r = triangulate(p, nullptr, {}, twoThreads);
        ASSERT_TRUE(r.diagnostic.ok()) << what << ": " << r.diagnostic.message;
        const CheckResult c = checkTriangulation(p, r.triangles);
        EXPECT_TRUE(c.ok) << what << ": " << c.reason;
    }
}

// A part that cannot be flooded, first, in the middle or last: the run falls back to the
// serial one, so the failure, its step and its message are the serial run's.
TEST(PartTasks, AForbiddenPartGivesTheSerialFailure) {
    const Polygon islands = generate("islands", 3, 15000);
    const Polygon bad = generateInvalid("hole-outside", 1, 40);
    for (size_t at = 0; at < 4; ++at) {
        std::vector<Polygon> pieces(3, islands);
        pieces.insert(pieces.begin() + std::ptrdiff_t(at), bad);
        const Polygon p = sideBySide(pieces);  // unvalidated, as --no-validate floods it
        const std::string what = "the invalid piece at " + std::to_string(at);
        ASSERT_GE(p.vertices.size(), 32768u) << what;
        ASSERT_EQ(triangulate(p).diagnostic.status, Status::Forbidden) << what;
        EXPECT_EQ(expectSerialResult(p, what), 1u) << what;
    }
}

// Where the run stays serial the runner is not called: a small polygon, a single part, a
// vertical off +y, a listener.
TEST(PartTasks, SerialRunsLeaveTheRunnerAlone) {
    Polygon small = generate("islands", 1, 2000), one = generate("circle-holes", 1, 40000),
            many = generate("islands", 1, 50000);
    for (Polygon* p : {&small, &one, &many}) ASSERT_TRUE(validate(*p, "p").ok());
    EXPECT_EQ(expectSerialResult(small, "small"), 0u);
    EXPECT_EQ(expectSerialResult(one, "one part"), 0u);
    EXPECT_EQ(expectSerialResult(many, "up +x", Options{Up::PlusX}), 0u);
    struct Counter : Listener {
        size_t n = 0;
        void onEvent(const Event&) override { ++n; }
    } counter;
    Backwards back;
    const FloodResult r = triangulate(many, &counter, {}, back.runner());
    EXPECT_EQ(back.calls, 0u);
    EXPECT_TRUE(r.triangles == triangulate(many).triangles);
    EXPECT_EQ(counter.n, r.steps);  // every event heard, in one run
}

}  // namespace
