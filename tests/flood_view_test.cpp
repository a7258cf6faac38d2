// The front door over the caller's own points (flood/geometry/point_view.h): any point type,
// read in place, gives exactly what the copying triangulateParts gives.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flood/flood_api.h"
#include "flood/tools/generate.h"

using namespace flood;

namespace {

struct FloatXY {  // members x, y of another type than double
    float x, y;
};
struct Packed {  // neither x/y nor [0]/[1]: read through a PointAccess
    int64_t u, v;
};

// A generated polygon as the copying API takes it, as one part per part.
std::vector<Rings> partsOf(const Polygon& p) {
    std::vector<Rings> parts;
    for (const Part& part : p.parts) {
        Rings rings;
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
            const Ring& ring = p.rings[r];
            rings.emplace_back(p.vertices.begin() + ring.first,
                               p.vertices.begin() + ring.first + ring.count);
        }
        parts.push_back(std::move(rings));
    }
    return parts;
}

}  // namespace

template <>
struct flood::PointAccess<Packed> {
    static double x(const Packed& p) { return double(p.u); }
    static double y(const Packed& p) { return double(p.v); }
};

TEST(FloodView, SameTrianglesAsTheCopyingApiOnEveryFamily) {
    size_t compared = 0;
    for (const std::string& family : familyNames())
        for (uint64_t seed = 1; seed <= 3; ++seed) {
            const std::vector<Rings> parts = partsOf(generate(family, seed, 60));
            const Triangulation copied = triangulateParts(parts);
            ASSERT_TRUE(copied.ok()) << family << " " << seed << ": " << copied.diagnostic.message;

            // [0]/[1] points in flat arrays, rings as spans over them, closed as OGR stores them.
            std::vector<std::vector<std::vector<std::array<double, 2>>>> arrays;
            for (const Rings& rings : parts) {
                arrays.emplace_back();
                for (const std::vector<Point>& ring : rings) {
                    arrays.back().emplace_back();
                    for (Point p : ring) arrays.back().back().push_back({p.x, p.y});
                    if (ring.size() > 3) arrays.back().back().push_back(arrays.back().back()[0]);
                }
            }
            std::vector<std::vector<Span<const std::array<double, 2>>>> spans;
            for (const auto& rings : arrays) {
                spans.emplace_back();
                for (const auto& ring : rings) spans.back().push_back({ring.data(), ring.size()});
            }
            const Triangulation viewed = triangulatePartsView(spans);
            ASSERT_TRUE(viewed.ok()) << family << " " << seed << ": " << viewed.diagnostic.message;
            EXPECT_EQ(viewed.polygon.vertices, copied.polygon.vertices) << family << " " << seed;
            EXPECT_EQ(viewed.triangles, copied.triangles) << family << " " << seed;
            if (parts.size() == 1) {  // one polygon: its rings alone
                EXPECT_EQ(triangulateView(spans[0]).triangles, copied.triangles) << family;
            }
            ++compared;
        }
    EXPECT_GE(compared, 3 * familyNames().size());
}

TEST(FloodView, AnyPointTypeReadsTheSameCoordinates) {
    // A square with a square hole, in three caller types.
    const std::vector<std::vector<FloatXY>> f = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                                 {{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
    const std::vector<std::vector<Packed>> q = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                                {{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
    double outer[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    double hole[5][2] = {{3, 3}, {3, 7}, {7, 7}, {7, 3}, {3, 3}};  // closed
    const std::vector<Span<double[2]>> c = {{outer, 4}, {hole, 5}};
    const Rings copy = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
    const Triangulation want = triangulateParts({copy});
    ASSERT_TRUE(want.ok());
    for (const Triangulation& t : {triangulateView(f), triangulateView(q), triangulateView(c)}) {
        ASSERT_TRUE(t.ok()) << t.diagnostic.message;
        EXPECT_EQ(t.polygon.vertices, want.polygon.vertices);
        EXPECT_EQ(t.triangles, want.triangles);
        EXPECT_EQ(t.triangles.size(), 8u);
    }
}

TEST(FloodView, InvalidInputGetsTheSameDiagnostic) {
    const std::vector<std::vector<std::array<double, 2>>> bowtie = {
        {{0, 0}, {4, 2}, {4, 0}, {0, 3}}};
    const Triangulation t = triangulateView(bowtie);
    const Triangulation want = triangulateParts({{{{0, 0}, {4, 2}, {4, 0}, {0, 3}}}});
    EXPECT_EQ(t.diagnostic.status, Status::Invalid);
    EXPECT_TRUE(t.triangles.empty());
    EXPECT_EQ(t.diagnostic.message, want.diagnostic.message);
    EXPECT_NE(t.diagnostic.message.find("ring 0"), std::string::npos) << t.diagnostic.message;
}
