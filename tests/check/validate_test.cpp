// validate(): what it accepts (touching rings, T-junctions, point holes), each class it rejects
// with its position, GEOS's verdicts on earcut's fixtures, a million vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "flood/check/checker.h"
#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "io_test_support.h"
#include "test_support.h"

using namespace flood;
using flood::testing::writtenAndRead;

TEST(Validate, AcceptsSimpleAndTouching) {
    Polygon sq = square();
    EXPECT_TRUE(validate(sq, "sq").ok());
    EXPECT_TRUE(sq.splits.empty());
    Polygon p = square();
    p.addRing({{0, 0}, {2, 3}, {3, 2}}, false);  // hole touching the outer ring at a corner
    p.addRing({{5, 5}, {6, 5}, {6, 6}, {5, 6}}, false);
    p.addRing({{6, 6}, {7, 6}, {7, 7}}, false);  // holes touching each other at a vertex
    Diagnostic d = validate(p, "t");
    EXPECT_TRUE(d.ok()) << d.message;
    EXPECT_TRUE(p.splits.empty());
}

// A hole vertex inside an outer edge (a T-junction) touches like a shared vertex: accepted and
// recorded as a split of that edge; so is a single-point hole (a Steiner point).
TEST(Validate, AcceptsTJunctionsAndPointHoles) {
    Polygon p;
    p.addRing({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, true);
    p.addRing({{5, 0}, {6, 1}, {4, 1}}, false);  // vertex 4 on edge 0-1
    p.addRing({{2, 5}, {3, 6}, {2, 7}, {1, 6}}, false);
    p.addRing({{3, 6}, {10, 8}, {4, 5}},
              false);            // touches ring 2 at (3, 6), ring 0 inside edge 1-2
    p.addRing({{8, 2}}, false);  // a Steiner point
    Diagnostic d = validate(p, "t");
    ASSERT_TRUE(d.ok()) << d.message;
    ASSERT_EQ(p.splits.size(), 2u);
    EXPECT_EQ(p.splits[0].edge, 0u);
    EXPECT_EQ(p.splits[0].vertex, 4u);
    EXPECT_EQ(p.splits[1].edge, 1u);
    EXPECT_EQ(p.splits[1].vertex, 12u);
    // n + 2h - 2 = 15 + 8 - 2, minus 2 for the shared point, 1 per T-junction, 1 per point.
    EXPECT_EQ(p.expectedTriangles(), 21u - 2 - 2 - 1);
    // Several vertices on one edge are ordered along the edge's direction.
    Polygon q;
    q.addRing({{10, 0}, {10, 10}, {0, 10}, {0, 0}}, true);
    q.addRing({{3, 10}, {4, 9}, {2, 9}}, false);
    q.addRing({{7, 10}, {8, 9}, {6, 9}}, false);
    ASSERT_TRUE(validate(q, "q").ok());
    ASSERT_EQ(q.splits.size(), 2u);
    EXPECT_EQ(q.splits[0].vertex, 7u);  // (7, 10) comes first walking from (10, 10) to (0, 10)
    EXPECT_EQ(q.splits[1].vertex, 4u);
}

struct InvalidCase {
    const char* what;
    Polygon polygon;
    const char* expect;
};

TEST(Validate, RejectsEachClassWithPosition) {
    auto poly = [](std::vector<std::vector<Point>> rings) {
        Polygon p;
        for (size_t i = 0; i < rings.size(); ++i) p.addRing(rings[i], i == 0);
        return p;
    };
    double nan = std::nan("");
    std::vector<InvalidCase> cases = {
        {"nan", poly({{{0, 0}, {1, 0}, {1, nan}}}),
         "N: ring 0 vertex 2 (1, nan): coordinate is not a finite"},
        {"few", poly({{{0, 0}, {1, 0}, {0, 0}, {1, 0}}}),
         "N: ring 0 vertex 0 (0, 0): ring has 2 distinct points"},
        {"zero", poly({{{0, 0}, {1, 1}, {2, 2}}}), "ring 0 vertex 0 (0, 0): ring has zero area"},
        {"cross", poly({{{0, 0}, {10, 10}, {10, 0}, {0, 12}}}),
         "ring 0 vertex 0 (0, 0): edge ring 0 edge 0-1"},
        {"on own edge", poly({{{0, 0}, {10, 0}, {10, 10}, {6, 3}, {5, 0}, {4, 3}, {0, 10}}}),
         "ring 0 vertex 4 (5, 0): the ring touches itself here: the vertex lies on its own edge "
         "ring 0 edge 0-1"},
        {"T-junction crossing",
         poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 0}, {6, 1}, {4, -2}}}), "cross"},
        {"point on edge", poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 0}}}),
         "ring 1 vertex 0 (5, 0): point hole lies on edge ring 0 edge 0-1"},
        {"point on vertex", poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{10, 10}}}),
         "point hole coincides with ring 0 vertex 2"},
        {"point outside", poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{20, 5}}}),
         "ring 1 vertex 0 (20, 5): hole (ring 1) lies outside its outer ring (ring 0)"},
        {"point outer ring", poly({{{1, 1}}}), "ring has 1 distinct point, at least 3 are needed"},
        {"two-point hole", poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {3, 3}}}),
         "ring has 2 distinct points, at least 3 are needed (or exactly one, a point hole)"},
        {"overlap", poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 0}, {4, 0}, {3, 1}}}),
         "edge ring 0 edge 0-1 (0, 0)-(10, 0)"},
        {"overlap at shared vertex",
         poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{0, 0}, {0, 4}, {1, 1}}}),
         "overlaps collinear edge"},
        {"spike", poly({{{0, 0}, {10, 0}, {5, 0}, {5, 5}}}), "spike"},
        {"outside", poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{20, 20}, {21, 20}, {21, 21}}}),
         "ring 1 vertex 0 (20, 20): hole (ring 1) lies outside its outer ring (ring 0)"},
        {"nested holes",
         poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
               {{1, 1}, {9, 1}, {9, 9}, {1, 9}},
               {{2, 2}, {3, 2}, {3, 3}}}),
         "ring 2 vertex 0 (2, 2): hole (ring 2) lies inside another hole (ring 1)"},
        {"cross at shared vertex",
         poly({{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
               {{5, 5}, {6, 4}, {6, 6}},
               {{5, 5}, {4, 6}, {4, 4}},
               {{5, 5}, {5.5, 7}, {4.5, 7}}}),
         "ok"},  // placeholder replaced below
        {"figure eight crossing", poly({{{0, 0}, {2, 2}, {4, 4}, {0, 5}, {2, 2}, {4, 0}}}),
         "crosses itself at this shared vertex"},
        {"same-orientation loop inside",
         poly({{{0, 0}, {10, 0}, {10, 10}, {5, 10}, {4, 8}, {6, 8}, {5, 10}, {0, 10}}}),
         "crosses itself at this shared vertex"},
    };
    // Three holes fanning around one shared point without crossing: valid.
    auto fanCase = std::find_if(cases.begin(), cases.end(), [](const InvalidCase& c) {
        return std::string(c.what) == "cross at shared vertex";
    });
    Diagnostic fan = validate(fanCase->polygon, "N");
    EXPECT_TRUE(fan.ok()) << fan.message;
    cases.erase(fanCase);
    // A ring touching itself at a vertex (an hourglass of two lobes) is not simple: GEOS
    // calls it a ring self-intersection, and so do we.
    Polygon bowTie = poly({{{0, 0}, {2, 2}, {0, 4}, {4, 4}, {2, 2}, {4, 0}}});
    Diagnostic bow = validate(bowTie, "N");
    EXPECT_EQ(bow.status, Status::Invalid);
    EXPECT_TRUE(contains(bow.message, "touches itself")) << bow.message;
    for (InvalidCase& c : cases) {
        Diagnostic d = validate(c.polygon, "N");
        EXPECT_EQ(d.status, Status::Invalid) << c.what;
        EXPECT_TRUE(contains(d.message, c.expect)) << c.what << ": " << d.message;
        EXPECT_TRUE(contains(d.message, "global vertex")) << c.what << ": " << d.message;
    }
}

TEST(Validate, EarcutFixturesMatchGeos) {
    std::string dir = std::string(FLOOD_SHARED_DIR) + "/peers/earcut/fixtures";
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no earcut fixtures at " << dir;
    // GEOS verdicts from the README table: fixture -> "Valid Geometry" or the reason.
    std::ifstream readme(std::string(FLOOD_SHARED_DIR) + "/peers/earcut/README.md");
    std::map<std::string, bool> geosValid;
    std::regex row(R"(^\| ([a-z0-9-]+) \|.*\| ([^|]+) \|\s*$)");
    for (std::string line; std::getline(readme, line);) {
        std::smatch m;
        if (std::regex_match(line, m, row) && m[1] != "fixture")
            geosValid[m[1]] = m[2].str().rfind("Valid Geometry", 0) == 0;
    }
    ASSERT_EQ(geosValid.size(), 59u);
    size_t files = 0;
    std::vector<std::string> disagreements;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        std::string stem = entry.path().stem().string();
        ReadResult r = readPolygonFile(entry.path().string());
        ASSERT_TRUE(r.diagnostic.ok() || r.diagnostic.status == Status::Malformed) << stem;
        bool ok = r.diagnostic.ok() && validate(r.polygon, stem).ok();
        ASSERT_TRUE(geosValid.count(stem)) << stem;
        if (ok != geosValid[stem]) disagreements.push_back(stem);
    }
    EXPECT_EQ(files, 59u);
    // validate() accepts exactly GEOS's valid fixtures (touching2's T-junction and steiner's
    // single-point holes included).
    std::sort(disagreements.begin(), disagreements.end());
    std::string list;
    for (auto& s : disagreements) list += s + " ";
    EXPECT_EQ(list, "") << "validate() disagrees with GEOS on: " << list;
}

TEST(Validate, OneMillionVerticesAtScale) {
    Polygon p;
    std::vector<Point> ring;
    const int n = 1000000;
    for (int i = 0; i < n / 2; ++i) ring.push_back({double(i), double(i % 2)});  // zigzag
    for (int i = n / 2 - 1; i >= 0; --i) ring.push_back({double(i), 10.0 + (i % 3)});
    p.addRing(ring, true);
    Diagnostic d = validate(p, "big");
    EXPECT_TRUE(d.ok()) << d.message;
    p.vertices[n / 2 + 7].y = -1;  // a spike down through the zigzag: edges now cross
    EXPECT_EQ(validate(p, "big").status, Status::Invalid);
}
