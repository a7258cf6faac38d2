// validate() where parts of a MultiPolygon meet: through a vertex on another part's edge
// (a T-junction between parts), at shared vertices, along a collinear stretch, nested in a
// hole or in the other part. Between parts a T-junction is a touch point like any other (the
// wedges must not interleave, the interiors not overlap there) but not a split of the machine:
// parts are flooded apart. Verdicts are GEOS 3.11's (tests/check/geos_diff_test.cpp compares
// generated cases with GEOS itself).
#include <gtest/gtest.h>

#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

using Rings = std::vector<std::vector<Point>>;  // an outer ring, then its holes

Polygon multi(const std::vector<Rings>& parts) {
    Polygon p;
    for (const Rings& rs : parts)
        for (size_t i = 0; i < rs.size(); ++i) p.addRing(rs[i], i == 0);
    return p;
}

const std::vector<Point> kSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};

// Every quarter turn and mirror of p gets the same verdict; valid ones triangulate exactly.
void expectVerdict(const Polygon& p, bool valid, const std::string& what,
                   const std::string& reason = "") {
    for (int rot = 0; rot < 4; ++rot)
        for (bool mirror : {false, true})
            for (bool reverse : {false, true}) {
                Polygon q = transform(p, rot, mirror, reverse, 0);
                std::string how = what + " (rotation " + std::to_string(rot) +
                                  (mirror ? ", mirrored" : "") + (reverse ? ", reversed" : "") +
                                  ")";
                Diagnostic d = validate(q, what);
                EXPECT_EQ(d.ok(), valid) << how << ": " << d.message;
                if (!valid && !reason.empty()) {
                    EXPECT_NE(d.message.find(reason), std::string::npos)
                        << how << ": " << d.message;
                }
                if (valid && d.ok()) expectTriangulates(q, how);
            }
}

}  // namespace

// The differential fuzzer's finding: a part entering another through a vertex on its edge and
// leaving through another such vertex; no two edges cross. It used to be accepted and
// triangulated with overlapping triangles.
TEST(ValidateParts, PartsCrossingThroughVerticesOnEdgesAreRefused) {
    Polygon p = multi({{kSquare}, {{{2, 0}, {3, 2}, {4, 2}, {6, -2}}}});
    expectVerdict(p, false, "crossing through T-junctions",
                  "the boundary crosses itself at this touching point");
    // The GEOS-differential case: a hole of a big part with vertices on a small part's edges.
    Polygon q = multi({{{{6, 6}, {10, 6}, {10, 10}, {6, 10}}},
                       {{{-4, -4}, {14, -4}, {14, 14}, {-4, 14}}, {{8, 6}, {1, 5}, {6, 8}}}});
    expectVerdict(q, false, "hole crossing a part through T-junctions");
}

TEST(ValidateParts, PartsTouchingAtATJunctionFromOutsideAreValid) {
    Polygon p = multi({{kSquare}, {{{2, 0}, {3, -2}, {1, -2}}}});
    expectVerdict(p, true, "touching from outside");
    Polygon q = p;
    ASSERT_TRUE(validate(q, "t").ok());
    EXPECT_TRUE(q.splits.empty())
        << "a T-junction between parts is no split: parts are flooded apart";
}

TEST(ValidateParts, PartsAlongACollinearStretchAreRefused) {
    Polygon p = multi({{kSquare}, {{{4, 1}, {6, 1}, {6, 3}, {4, 3}}}});
    expectVerdict(p, false, "collinear stretch", "overlaps collinear edge");
    Polygon q = multi({{kSquare}, {{{4, 0}, {6, 0}, {6, 4}, {4, 4}}}});  // a whole shared edge
    expectVerdict(q, false, "shared edge", "overlaps collinear edge");
}

TEST(ValidateParts, PartsCrossingAtSharedVerticesAreRefused) {
    // Two diamonds through (0, 0) and (0, 4), the second's wedge interleaving the first's at both.
    Polygon p = multi({{{{0, 0}, {2, 2}, {0, 4}, {-2, 2}}}, {{{0, 0}, {1, 2}, {0, 4}, {-4, 2}}}});
    expectVerdict(p, false, "interleaving wedges",
                  "the boundary crosses itself at this shared vertex");
    Polygon q =
        multi({{{{0, 0}, {2, 2}, {0, 4}, {-2, 2}}}, {{{0, 0}, {2, -2}, {0, -4}, {-2, -2}}}});
    expectVerdict(q, true, "touching at a vertex");
}

TEST(ValidateParts, IslandInALakeIsValidAndMayTouchTheLake) {
    Rings lake{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {8, 2}, {8, 8}, {2, 8}}};
    expectVerdict(multi({lake, {{{4, 4}, {6, 4}, {6, 6}, {4, 6}}}}), true, "island in a lake");
    // Touching the lake's shore from inside the lake: at a vertex, and at a T-junction.
    expectVerdict(multi({lake, {{{2, 2}, {6, 4}, {4, 6}}}}), true, "island at a shore vertex");
    expectVerdict(multi({lake, {{{5, 2}, {6, 4}, {4, 4}}}}), true, "island at a shore T-junction");
    // Reaching through the shore into the land: the interiors overlap.
    expectVerdict(multi({lake, {{{5, 2}, {6, 4}, {4, 4}, {5, 0}}}}), false,
                  "island crossing the shore");
    expectVerdict(multi({lake, {{{5, 2}, {6, 1}, {4, 1}}}}), false,
                  "island on the land side of the shore",
                  "the interior overlaps itself at this touching point");
}

TEST(ValidateParts, PartInsideAnotherPartIsRefused) {
    expectVerdict(multi({{kSquare}, {{{1, 1}, {2, 1}, {2, 2}}}}), false, "part inside a part",
                  "parts overlap");
    // Touching the outer part's edge from inside: caught at the touch.
    expectVerdict(multi({{kSquare}, {{{2, 0}, {3, 1}, {1, 1}}}}), false,
                  "part inside touching at a T-junction",
                  "the interior overlaps itself at this touching point");
    expectVerdict(multi({{kSquare}, {{{0, 0}, {2, 1}, {1, 2}}}}), false,
                  "part inside touching at a vertex",
                  "the interior overlaps itself at this shared vertex");
}

// At one point: a part's outer edge passes through, a hole of that part touches it from inside
// (a split the machine needs), and another part touches from outside (no split). Whichever
// vertex the sweep meets first, the split is the hole's vertex.
TEST(ValidateParts, SplitsStayPerPartAtAMixedTouchPoint) {
    Polygon p = multi({{{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{4, 0}, {5, 2}, {3, 2}}},
                       {{{4, 0}, {3, -2}, {5, -2}}}});
    expectVerdict(p, true, "hole and part at one T-junction");
    for (bool mirror : {false, true}) {
        Polygon q = transform(p, 0, mirror, false, 0);
        ASSERT_TRUE(validate(q, "mixed").ok());
        ASSERT_EQ(q.splits.size(), 1u) << (mirror ? "mirrored" : "as given");
        EXPECT_EQ(q.splits[0].edge, 0u);
        EXPECT_EQ(q.splits[0].vertex, 4u) << "the hole's vertex, not the other part's";
    }
}

// A symmetric bow-tie has zero area because it crosses itself: the crossing is the reason.
TEST(ValidateParts, BowTieIsReportedAsACrossing) {
    Polygon p = multi({{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}});
    Diagnostic d = validate(p, "bow-tie");
    EXPECT_NE(d.message.find("crosses edge"), std::string::npos) << d.message;
    // A ring of zero area without a crossing is still called so.
    Polygon q = multi({{{{0, 0}, {5, 5}, {10, 10}, {5, 5}}}});
    EXPECT_NE(validate(q, "flat").message.find("ring has zero area"), std::string::npos);
}

// Cases the GEOS-differential test found (polygons/regress/geos-VERDICT-*.json, VERDICT being
// GEOS's: valid or invalid): the same verdict in every quarter turn, mirror and orientation.
TEST(ValidateParts, GeosFoundCasesKeepGeosVerdictInEveryOrientation) {
    size_t files = 0;
    for (const std::string& path : filesIn(sourcePath("polygons/regress"), ".json")) {
        std::string name = std::filesystem::path(path).filename().string();
        bool invalid = name.rfind("geos-invalid-", 0) == 0;
        if (!invalid && name.rfind("geos-valid-", 0) != 0) continue;
        ReadResult r = readPolygonFile(path);
        ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
        expectVerdict(r.polygon, !invalid, name);
        ++files;
    }
    EXPECT_GE(files, 7u);
}

// A hole touching its outer ring at two points cuts the interior in two, also when a vertex of
// another part sits at one of the touches (the touches of one part used to be linked only
// between neighbours in vertex order, so the other part's vertex hid this one).
TEST(ValidateParts, CycleOfTouchesIsFoundWithAnotherPartAtTheTouch) {
    Polygon p = multi({{{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{2, 0}, {4, 3}, {6, 0}, {4, 5}}},
                       {{{2, 0}, {1, -2}, {3, -2}}}});
    expectVerdict(p, false, "hole cycle beside another part", "the interior is disconnected");
}
