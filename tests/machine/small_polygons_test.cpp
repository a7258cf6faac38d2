// Small polygons (issue 13): a Triangulator keeps its working memory from call to call, so a
// call allocates nothing once its buffers have grown; a polygon validated without shared
// points is flooded without the search for touching rings. Results are those of a fresh
// triangulate(): the same triangles, whatever was flooded before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include "flood/geometry/predicates.h"
#include "flood/geometry/up.h"
#include "flood/geometry/work.h"
#include "flood/machine/vertex_class.h"
#include "flood/tools/generate.h"
#include "machine/sags/sag_banks.h"
#include "test_support.h"

// Allocations made by this thread, counted by the replaced global operator new (it forwards
// to malloc; the rest of the suite sees no difference).
namespace {
thread_local uint64_t tAllocations = 0;
}
void* operator new(std::size_t size) {
    ++tAllocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    ++tAllocations;
    return std::malloc(size ? size : 1);
}
// Every form is replaced, so no allocation made by one form (simdjson's nothrow new, say) is
// freed by another's allocator: AddressSanitizer reports that mismatch.
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
    return operator new(size, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace flood {
namespace {

using testing::sharedPath;
using testing::sourcePath;

Polygon validated(const std::string& path) {
    ReadResult rr = readPolygonFile(path);
    EXPECT_TRUE(rr.diagnostic.ok()) << rr.diagnostic.message;
    EXPECT_TRUE(validate(rr.polygon, path).ok()) << path;
    return std::move(rr.polygon);
}

// Every input the tests below flood: the samples, and earcut's fixtures when shared/ is there.
std::vector<Polygon> inputs() {
    std::vector<Polygon> out;
    for (const std::string& f : testing::filesIn(sourcePath("polygons"), ".json"))
        out.push_back(validated(f));
    for (const std::string& f : testing::filesIn(sharedPath("peers/earcut/fixtures"), ".json")) {
        ReadResult rr = readPolygonFile(f);
        if (rr.diagnostic.ok() && validate(rr.polygon, f).ok())
            out.push_back(std::move(rr.polygon));
    }
    for (const std::string& family : familyNames()) out.push_back(generate(family, 7, 300));
    for (Polygon& p : out) EXPECT_TRUE(validate(p, "input").ok());
    return out;
}

TEST(SmallPolygons, ValidationTellsWhetherPointsRepeat) {
    Polygon holes = validated(sourcePath("polygons/holes.json"));
    EXPECT_TRUE(holes.pointsDistinct);
    EXPECT_FALSE(
        validated(sourcePath("polygons/touching-hole.json")).pointsDistinct);  // a shared vertex
    EXPECT_FALSE(
        validated(sourcePath("polygons/t-junction.json")).pointsDistinct);  // a vertex on an edge
    holes.addRing({{1, 1}, {1, 1.5}, {1.5, 1}}, false);                     // not validated since
    EXPECT_FALSE(holes.pointsDistinct);
}

TEST(SmallPolygons, NoTouchingPointSearchWithoutRepeatedPoints) {
    Polygon holes = validated(sourcePath("polygons/holes.json"));
    work() = {};
    FloodResult r = triangulate(holes);
    ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    EXPECT_EQ(work().touchSearchNodes, 0u);
    EXPECT_TRUE(checkTriangulation(holes, r.triangles).ok);

    // Not known (not validated): the machine looks, and finds the same triangles.
    Polygon unknown = holes;
    unknown.pointsDistinct = false;
    work() = {};
    EXPECT_EQ(triangulate(unknown).triangles, r.triangles);
    EXPECT_EQ(work().touchSearchNodes, holes.vertices.size());

    // Rings that touch are still merged where they touch.
    Polygon touching = validated(sourcePath("polygons/touching-hole.json"));
    work() = {};
    FloodResult t = triangulate(touching);
    ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
    EXPECT_GT(work().touchSearchNodes, 0u);
    EXPECT_TRUE(checkTriangulation(touching, t.triangles).ok);
}

TEST(SmallPolygons, TriangulatorAllocatesNothingOnceWarm) {
    for (const char* name :
         {"polygons/holes.json", "polygons/touching-hole.json", "polygons/t-junction.json",
          "polygons/steiner.json", "polygons/comb.json"}) {
        Polygon p = validated(sourcePath(name));
        Triangulator t;
        const size_t triangles = t.run(p).triangles.size();
        ASSERT_TRUE(t.run(p).diagnostic.ok()) << name;
        const uint64_t before = tAllocations;
        for (int i = 0; i < 3; ++i) EXPECT_EQ(t.run(p).triangles.size(), triangles);
        EXPECT_EQ(tAllocations - before, 0u) << name;
    }
}

// The bank lists' sweep (core/machine/sags/sag_banks.h) keeps its arrays and its set's nodes: built
// again on loops no larger than before, it allocates nothing, and labels the same.
TEST(SmallPolygons, SagBanksAllocateNothingOnceWarm) {
    for (const char* family : {"star", "circle-jagged"}) {
        Polygon p = generate(family, 7, 5000);
        const uint32_t n = uint32_t(p.vertices.size());
        std::vector<uint32_t> next(n), sags;
        for (uint32_t i = 0; i < n; ++i) next[i] = (i + 1) % n;
        for (uint32_t i = 0; i < n; ++i)  // the local minima, lowest first
            if (below(p.vertices[i], p.vertices[(i + n - 1) % n]) &&
                below(p.vertices[i], p.vertices[next[i]]))
                sags.push_back(i);
        std::sort(sags.begin(), sags.end(),
                  [&](uint32_t a, uint32_t b) { return below(p.vertices[a], p.vertices[b]); });
        ASSERT_GT(sags.size(), 100u) << family;
        SagBanks banks;
        ASSERT_TRUE(banks.build(p.vertices, next, sags, Up::PlusY, true)) << family;
        std::vector<int64_t> first;
        auto none = [](uint32_t) { return false; };
        for (uint32_t t = 0; t < n; ++t) first.push_back(banks.lowest(t % 2, t, -1, n, none));
        const uint64_t before = tAllocations;
        ASSERT_TRUE(banks.build(p.vertices, next, sags, Up::PlusY, true)) << family;
        EXPECT_EQ(tAllocations - before, 0u) << family;
        for (uint32_t t = 0; t < n; ++t)
            EXPECT_EQ(banks.lowest(t % 2, t, -1, n, none), first[t]) << family << " edge " << t;
    }
}

// A Triangulator on a polygon large enough that the sag search builds the bank lists.
TEST(SmallPolygons, TriangulatorAllocatesNothingOnceWarmWithTheBanks) {
    for (const char* family : {"star", "circle-jagged", "circle-smooth"}) {
        Polygon p = generate(family, 7, 20000);
        ASSERT_TRUE(validate(p, family).ok()) << family;
        Triangulator t;
        const size_t triangles = t.run(p).triangles.size();
        ASSERT_TRUE(t.run(p).diagnostic.ok()) << family;
        const uint64_t before = tAllocations;
        EXPECT_EQ(t.run(p).triangles.size(), triangles) << family;
        EXPECT_EQ(tAllocations - before, 0u) << family;
    }
}

// Off the axes the machine ranks the vertices by height: that order is lent too.
TEST(SmallPolygons, TriangulatorAllocatesNothingOnceWarmAlongAnyDirection) {
    std::vector<std::string> files = {sourcePath("polygons/holes.json"),
                                      sourcePath("polygons/touching-hole.json"),
                                      sourcePath("polygons/steiner.json")};
    const std::string building = sharedPath("peers/earcut/fixtures/building.json");
    if (std::ifstream(building)) files.push_back(building);
    for (const std::string& name : files) {
        Polygon p = validated(name);
        for (Up up : {Up::MinusY, Up::PlusX, upFromDegrees(30), upFromDegrees(200)}) {
            Options o;
            o.up = up;
            Triangulator t;
            const size_t triangles = t.run(p, nullptr, o).triangles.size();
            ASSERT_TRUE(t.run(p, nullptr, o).diagnostic.ok()) << name;
            const uint64_t before = tAllocations;
            for (int i = 0; i < 3; ++i) EXPECT_EQ(t.run(p, nullptr, o).triangles.size(), triangles);
            EXPECT_EQ(tAllocations - before, 0u) << name << " along " << upName(up);
        }
    }
}

// The per-call work on a small polygon stays a few steps per vertex: no search for features
// the input does not have (touching rings when validation saw no repeated point, heights
// ranked along an axis), counted by the machine's work counters (work.h), not by a clock.
TEST(SmallPolygons, WorkPerCallIsAFewStepsPerVertex) {
    Triangulator t;
    for (const Polygon& p : inputs()) {
        if (p.vertices.size() > 200) continue;
        t.run(p);
        work() = {};
        ASSERT_TRUE(t.run(p).diagnostic.ok());
        const uint64_t n = p.vertices.size();
        const WorkCounters w = work();
        if (p.pointsDistinct) {
            EXPECT_EQ(w.touchSearchNodes, 0u) << n;
        }
        EXPECT_EQ(w.heightCalls, 0u) << n;  // along +y heights are coordinates
        // At most 13.6 and 8.5 a vertex today (touching-holes 82 and 160, earcut's fixtures).
        EXPECT_LE(w.nodeVisits, 16 * n + 16) << n;
        EXPECT_LE(w.orientCalls, 10 * n + 16) << n;
    }
}

// Without a listener no event is built; a run that ends in a forbidden state is flooded again,
// recording, for its failure event. That event is the one a listener sees last, and the run
// cuts the same triangles in the same steps.
TEST(SmallPolygons, AnUnrecordedRefusalCarriesTheRecordedFailure) {
    struct Last : Listener {
        Event last;
        void onEvent(const Event& e) override { last = e; }
    };
    std::vector<Polygon> invalid;
    for (const std::string& family : invalidFamilyNames())
        for (uint64_t seed = 1; seed <= 3; ++seed)
            invalid.push_back(generateInvalid(family, seed, 40));
    size_t refused = 0;
    Triangulator t;
    for (const Polygon& p : invalid) {
        Last heard;
        const FloodResult recorded = triangulate(p, &heard);
        for (const FloodResult& quiet : {triangulate(p), t.run(p)}) {
            EXPECT_EQ(quiet.diagnostic.status, recorded.diagnostic.status);
            EXPECT_EQ(quiet.triangles, recorded.triangles);
            EXPECT_EQ(quiet.steps, recorded.steps);
            if (recorded.diagnostic.status != Status::Forbidden) continue;
            EXPECT_FALSE(quiet.diagnostic.message.empty());
            EXPECT_EQ(quiet.failure.action, Action::Forbidden);
            EXPECT_EQ(quiet.failure.reason, heard.last.reason);
            EXPECT_EQ(quiet.failure.step, heard.last.step);
            EXPECT_EQ(quiet.failure.culprit, heard.last.culprit);
            EXPECT_EQ(quiet.failure.culprit2, heard.last.culprit2);
            EXPECT_EQ(quiet.failure.tested, heard.last.tested);
            EXPECT_EQ(quiet.failure.passed, heard.last.passed);
        }
        refused += recorded.diagnostic.status == Status::Forbidden;
    }
    EXPECT_GT(refused, invalid.size() / 4);  // the machine itself refuses many of them
}

TEST(SmallPolygons, TriangulateAllocatesOnlyItsResult) {
    Polygon p = validated(sourcePath("polygons/holes.json"));
    triangulate(p);  // this thread's buffers grow once
    const uint64_t before = tAllocations;
    FloodResult r = triangulate(p);
    EXPECT_TRUE(r.diagnostic.ok());
    EXPECT_EQ(tAllocations - before, 1u);  // the triangles returned
}

// A part with few sags has its sag ranks counted on their keys, one with more read through the
// cache of recent answers (sag_search.h), cleared only where an earlier run wrote it. Parts on
// both sides of that threshold, flooded in turn by one Triangulator along four directions, give
// a fresh call's triangles, and those are a valid triangulation.
TEST(SmallPolygons, FewAndManySagsGiveTheSameTriangles) {
    std::vector<Polygon> all;
    size_t few = 0, many = 0;
    for (const char* family : {"circle-holes", "grid-holes", "comb", "star", "rooms"})
        for (size_t size : {10, 20, 40, 80, 160, 320}) {
            all.push_back(generate(family, 3, size));
            ASSERT_TRUE(validate(all.back(), family).ok()) << family << " " << size;
            const std::vector<VertexClass> c = classifyVertices(all.back());
            const auto sags = std::count(c.begin(), c.end(), VertexClass::Sag);
            few += sags >= 1 && sags <= 8;
            many += sags > 8;
        }
    EXPECT_GE(few, 5u);
    EXPECT_GE(many, 5u);
    Triangulator t;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t k = 0; k < all.size(); ++k) {
            const Polygon& p = all[pass ? all.size() - 1 - k : k];
            for (Up up : {Up::PlusY, Up::MinusY, Up::PlusX, Up{0.8660254037844387, 0.5}}) {
                Options o;
                o.up = up;
                const FloodResult fresh = triangulate(p, nullptr, o);
                ASSERT_TRUE(fresh.diagnostic.ok()) << k << ": " << fresh.diagnostic.message;
                EXPECT_EQ(t.run(p, nullptr, o).triangles, fresh.triangles) << k;
                EXPECT_TRUE(checkTriangulation(p, fresh.triangles).ok) << k;
            }
        }
}

TEST(SmallPolygons, ReusedBuffersGiveTheSameTriangles) {
    std::vector<Polygon> all = inputs();
    Triangulator t;
    // Forwards, then backwards: each polygon sees buffers left by a larger and a smaller one.
    for (int pass = 0; pass < 2; ++pass)
        for (size_t k = 0; k < all.size(); ++k) {
            const Polygon& p = all[pass ? all.size() - 1 - k : k];
            FloodResult fresh = triangulate(p);
            const FloodResult& reused = t.run(p);
            EXPECT_EQ(reused.triangles, fresh.triangles) << k;
            EXPECT_EQ(reused.steps, fresh.steps) << k;
            EXPECT_EQ(reused.diagnostic.message, fresh.diagnostic.message) << k;
            EXPECT_TRUE(fresh.diagnostic.ok()) << k << ": " << fresh.diagnostic.message;
            for (Up up : {Up::MinusY, Up::PlusX}) {
                Options o;
                o.up = up;
                EXPECT_EQ(t.run(p, nullptr, o).triangles, triangulate(p, nullptr, o).triangles)
                    << k;
            }
        }
}

}  // namespace
}  // namespace flood
