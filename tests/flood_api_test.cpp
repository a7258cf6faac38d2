// The front door (flood/flood_api.h) as a C++ caller meets it: rings open or closed (as OGR,
// GEOS and WKT store them) give the same triangles; invalid input gets a diagnostic.
#include <gtest/gtest.h>

#include "flood/check/checker.h"
#include "flood/flood_api.h"

using namespace flood;

TEST(FloodApi, ClosedRingsAreAcceptedAsOGRAndGEOSStoreThem) {
    const Rings open = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {2, 4}, {4, 4}, {4, 2}}};
    Rings closed = open;
    for (auto& ring : closed) ring.push_back(ring.front());
    Triangulation a = triangulateParts({open}), b = triangulateParts({closed});
    ASSERT_TRUE(a.ok()) << a.diagnostic.message;
    ASSERT_TRUE(b.ok()) << b.diagnostic.message;
    EXPECT_EQ(b.polygon.vertices, a.polygon.vertices);  // the closing points are no vertices
    EXPECT_EQ(b.triangles, a.triangles);
    EXPECT_EQ(b.triangles.size(), 8u + 2 * 1 - 2);
    EXPECT_TRUE(checkTriangulation(b.polygon, b.triangles).ok);
    // A point hole stays a point; a repeated point inside a ring is still refused.
    Triangulation steiner = triangulateParts({{closed[0], {{5, 5}}}});
    EXPECT_TRUE(steiner.ok()) << steiner.diagnostic.message;
    Triangulation repeated = triangulateParts({{{{0, 0}, {10, 0}, {10, 0}, {0, 10}, {0, 0}}}});
    EXPECT_EQ(repeated.diagnostic.status, Status::Invalid);
    EXPECT_NE(repeated.diagnostic.message.find("repeated consecutive point"), std::string::npos)
        << repeated.diagnostic.message;
}
