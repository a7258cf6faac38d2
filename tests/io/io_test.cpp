// File formats: parsing (GeoJSON, ring arrays, WKT), error messages, the writers. Validation:
// tests/check/validate_test.cpp; trace files: tests/log/trace_io_test.cpp.
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

// A Steiner point is written as a closed ring of one point, [p, p] (WKT (x y, x y)): read as a
// one-vertex hole, without a warning about the closing point.
TEST(IoRead, PointHoles) {
    for (const char* text : {"[[[0,0],[4,0],[4,4],[0,4]],[[1,1],[1,1]],[[2,3]]]",
                             "POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,1 1),(2 3))"}) {
        ReadResult r = parsePolygon(text, "p");
        ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
        EXPECT_TRUE(r.warnings.empty()) << text << ": " << r.warnings[0];
        ASSERT_EQ(r.polygon.rings.size(), 3u);
        EXPECT_EQ(r.polygon.rings[1].count, 1u);
        EXPECT_EQ(r.polygon.rings[2].count, 1u);
        EXPECT_TRUE(validate(r.polygon, "p").ok());
        EXPECT_EQ(r.polygon.expectedTriangles(), 6u);
    }
}

TEST(IoRead, RingArrayAndClosingPointAndDuplicates) {
    ReadResult r = parsePolygon(
        "[[[0,0],[10,0],[10,0],[10,10],[0,10],[0,0]],"
        "[[2,2],[2,4],[4,4],[4,2]]]",
        "t.json");
    ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    ASSERT_EQ(r.polygon.rings.size(), 2u);
    EXPECT_EQ(r.polygon.rings[0].count, 4u);  // duplicate and closing point dropped
    EXPECT_EQ(r.polygon.rings[1].count, 4u);
    EXPECT_EQ(r.polygon.parts.size(), 1u);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_TRUE(contains(r.warnings[0], "t.json: ring 0 vertex 2 (10, 0): repeated point"))
        << r.warnings[0];
}

TEST(IoRead, GeoJsonKinds) {
    ReadResult a =
        parsePolygon(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]})", "a");
    ASSERT_TRUE(a.diagnostic.ok()) << a.diagnostic.message;
    EXPECT_EQ(a.polygon.vertices.size(), 3u);
    ReadResult m = parsePolygon(R"({"type":"MultiPolygon","coordinates":[
        [[[0,0],[1,0],[1,1]]], [[[5,5],[6,5],[6,6]],[[5.1,5.05],[5.2,5.05],[5.2,5.1]]]]})",
                                "m");
    ASSERT_TRUE(m.diagnostic.ok()) << m.diagnostic.message;
    EXPECT_EQ(m.polygon.parts.size(), 2u);
    EXPECT_EQ(m.polygon.rings.size(), 3u);
    ReadResult fc = parsePolygon(R"({"type":"FeatureCollection","features":[
        {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1]]]}},
        {"type":"Feature","properties":{},"geometry":{"type":"Point","coordinates":[0,0]}},
        {"type":"Feature","geometry":{"type":"MultiPolygon","coordinates":[[[[2,0],[3,0],[3,1]]]]}}]})",
                                 "fc");
    ASSERT_TRUE(fc.diagnostic.ok()) << fc.diagnostic.message;
    EXPECT_EQ(fc.polygon.parts.size(), 2u);
    ASSERT_EQ(fc.warnings.size(), 1u);  // the Point is skipped, with a warning
    EXPECT_TRUE(contains(fc.warnings[0], "feature 1")) << fc.warnings[0];
    ReadResult mp = parsePolygon("[[[[0,0],[1,0],[1,1]]],[[[2,0],[3,0],[3,1]]]]", "mp");
    ASSERT_TRUE(mp.diagnostic.ok()) << mp.diagnostic.message;
    EXPECT_EQ(mp.polygon.parts.size(), 2u);
}

TEST(IoRead, Wkt) {
    ReadResult r =
        parsePolygon("polygon ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 4, 4 4, 2 2))", "w");
    ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    EXPECT_EQ(r.polygon.rings.size(), 2u);
    EXPECT_EQ(r.polygon.rings[0].count, 4u);
    ReadResult m =
        parsePolygon("MULTIPOLYGON Z (((0 0 1, 1 0 1, 1 1 1)), ((5 5 0, 6 5 0, 6 6 0)))", "m");
    ASSERT_TRUE(m.diagnostic.ok()) << m.diagnostic.message;
    EXPECT_EQ(m.polygon.parts.size(), 2u);
    ReadResult n = parsePolygon("POLYGON((0 0, 1 0, inf 1, nan 2))", "n");
    ASSERT_TRUE(n.diagnostic.ok()) << n.diagnostic.message;
    EXPECT_TRUE(std::isinf(n.polygon.vertices[2].x));
    EXPECT_TRUE(std::isnan(n.polygon.vertices[3].x));
    ReadResult e = parsePolygon("POLYGON((0 0, 1 0,\n  1 x1))", "e.wkt");
    EXPECT_EQ(e.diagnostic.status, Status::Malformed);
    EXPECT_TRUE(contains(e.diagnostic.message, "e.wkt:2:5:")) << e.diagnostic.message;
    EXPECT_EQ(parsePolygon("POLYGON EMPTY", "e").diagnostic.status, Status::Malformed);
    EXPECT_EQ(parsePolygon("LINESTRING(0 0, 1 1)", "e").diagnostic.status, Status::Malformed);
    EXPECT_EQ(parsePolygon("POLYGON((0 0, 1 0, 1 1)) extra", "e").diagnostic.status,
              Status::Malformed);
}

// Z, M and ZM points (3 or 4 ordinates), with the tag, without it, or run together with the
// keyword: the extra ordinates are dropped. POLYGON ZM with four ordinates used to be refused.
TEST(IoRead, WktDimensions) {
    for (const char* text :
         {"POLYGON ZM ((0 0 1 2, 4 0 1 2, 4 4 1 2, 0 4 1 2, 0 0 1 2))",
          "POLYGON ((0 0 1 2, 4 0 1 2, 4 4 1 2, 0 4 1 2, 0 0 1 2))",
          "POLYGON M ((0 0 1, 4 0 1, 4 4 1, 0 4 1, 0 0 1))",
          "POLYGONZM((0 0 1 2,4 0 1 2,4 4 1 2,0 4 1 2))", "polygonz ((0 0 1, 4 0 1, 4 4 1, 0 4 1))",
          "MULTIPOLYGON ZM (((0 0 1 2, 4 0 1 2, 4 4 1 2, 0 4 1 2)))"}) {
        ReadResult r = parsePolygon(text, "z");
        ASSERT_TRUE(r.diagnostic.ok()) << text << ": " << r.diagnostic.message;
        ASSERT_EQ(r.polygon.vertices.size(), 4u) << text;
        EXPECT_EQ(r.polygon.vertices[2], (Point{4, 4})) << text;
    }
    ReadResult five = parsePolygon("POLYGON ZM ((0 0 1 2 3, 4 0 1 2, 4 4 1 2))", "f");
    EXPECT_TRUE(contains(five.diagnostic.message, "f:1:22: WKT: expected ')', found '3'"))
        << five.diagnostic.message;
    EXPECT_TRUE(contains(parsePolygon("POLYGON Q ((0 0, 1 0, 1 1))", "q").diagnostic.message,
                         "q:1:9: WKT: unexpected \"Q\" after POLYGON"));
}

// EMPTY where the WKT grammar allows it (GEOS's tests use it): an EMPTY hole or part is
// dropped with a warning naming its place; nothing left is "polygon has no rings", as for
// JSON. These used to be "expected '(', found 'E'".
TEST(IoRead, WktEmpty) {
    ReadResult hole =
        parsePolygon("POLYGON((0 0,4 0,4 4,0 4,0 0), EMPTY, (1 1,1 2,2 2,1 1))", "h.wkt");
    ASSERT_TRUE(hole.diagnostic.ok()) << hole.diagnostic.message;
    EXPECT_EQ(hole.polygon.rings.size(), 2u);
    ASSERT_EQ(hole.warnings.size(), 1u);
    EXPECT_EQ(hole.warnings[0], "h.wkt:1:32: WKT: EMPTY hole dropped");
    ReadResult part = parsePolygon("MULTIPOLYGON(EMPTY, ((0 0,4 0,4 4,0 0)), (EMPTY))", "p.wkt");
    ASSERT_TRUE(part.diagnostic.ok()) << part.diagnostic.message;
    EXPECT_EQ(part.polygon.parts.size(), 1u);
    ASSERT_EQ(part.warnings.size(), 2u);
    EXPECT_EQ(part.warnings[0], "p.wkt:1:14: WKT: EMPTY polygon dropped");
    EXPECT_EQ(part.warnings[1], "p.wkt:1:42: WKT: EMPTY polygon dropped");
    struct Case {
        const char* text;
        const char* message;
    } bad[] = {
        {"POLYGON EMPTY", "e:1:9: WKT: POLYGON EMPTY: polygon has no rings"},
        {"POLYGON Z EMPTY", "e:1:11: WKT: POLYGON EMPTY: polygon has no rings"},
        {"POLYGON(EMPTY)", "e:1:8: WKT: POLYGON (EMPTY): polygon has no rings"},
        {"MULTIPOLYGON EMPTY", "e:1:14: WKT: MULTIPOLYGON EMPTY: no polygon"},
        {"MULTIPOLYGON(EMPTY, (EMPTY))", "e:1:13: WKT: every polygon of the MULTIPOLYGON is EMPTY"},
        {"POLYGON(EMPTY, (0 0, 1 0, 1 1))",
         "e:1:15: WKT: the outer ring is EMPTY but holes follow"},
        {"POLYGON((0 0, 1 0, 1 1), EMPTI)", "e:1:26: WKT: expected '(' or EMPTY, found \"EMPTI\""},
    };
    for (const Case& c : bad) {
        ReadResult r = parsePolygon(c.text, "e");
        EXPECT_EQ(r.diagnostic.status, Status::Malformed) << c.text;
        EXPECT_TRUE(contains(r.diagnostic.message, c.message))
            << c.text << ": " << r.diagnostic.message;
    }
}

// An empty array says what is missing: [] has no rings, [[]] is a ring with no points (it used
// to be told it is not "an array of rings").
TEST(IoRead, EmptyArrays) {
    ReadResult none = parsePolygon("[]", "a.json");
    EXPECT_EQ(none.diagnostic.message, "a.json: polygon 0: polygon has no rings");
    ReadResult ring = parsePolygon("[[]]", "b.json");
    ASSERT_TRUE(ring.diagnostic.ok()) << ring.diagnostic.message;
    Diagnostic v = validate(ring.polygon, "b.json");
    EXPECT_EQ(v.status, Status::Invalid);
    EXPECT_TRUE(contains(v.message, "b.json: ring 0: ring is empty")) << v.message;
    ReadResult point = parsePolygon("[[[]]]", "c.json");
    EXPECT_TRUE(
        contains(point.diagnostic.message,
                 "c.json: polygon 0 ring 0 vertex 0: coordinate is not a pair of numbers (got [])"))
        << point.diagnostic.message;
}

// Only the first kMaxWarnings warnings are kept; the rest are counted.
TEST(IoRead, WarningsCapped) {
    std::string text = "[[[0,0]";
    for (int i = 0; i < 1000; ++i) text += ",[0,0]";
    text += ",[10,0],[10,10],[0,10]]]";
    ReadResult r = parsePolygon(text, "w");
    ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    EXPECT_EQ(r.warnings.size(), kMaxWarnings);
    EXPECT_EQ(r.warningsOmitted, 1000 - kMaxWarnings);
    EXPECT_EQ(r.polygon.vertices.size(), 4u);
}

// NUL bytes are binary data, whatever else the text holds (it used to be "empty input").
TEST(IoRead, BinaryData) {
    ReadResult z = parsePolygon(std::string(100, '\0'), "z.bin");
    EXPECT_EQ(z.diagnostic.message,
              "z.bin: binary data (a NUL byte at byte 0), not GeoJSON or WKT");
    ReadResult mid = parsePolygon(std::string("[[[0,0],\0[1,0],[1,1]]]", 22), "m");
    EXPECT_TRUE(contains(mid.diagnostic.message, "m: binary data (a NUL byte at byte 8)"))
        << mid.diagnostic.message;
    std::string text;
    Diagnostic dir =
        readInputFile(source("polygons"), text, kDefaultMaxInputBytes, "GeoJSON or WKT");
    EXPECT_TRUE(contains(dir.message, "polygons: is a directory, not a file")) << dir.message;
    Diagnostic cap = readInputFile(source("polygons/hole.json"), text, 10, "GeoJSON or WKT");
    EXPECT_TRUE(contains(cap.message, "hole.json: input is larger than the limit of 10 bytes"))
        << cap.message;
    EXPECT_TRUE(readInputFile(source("polygons/hole.json"), text, 1000, "x").ok());
    EXPECT_TRUE(contains(text, "[[")) << text;
}

TEST(IoRead, MalformedMessages) {
    ReadResult j = parsePolygon("[[[0,0],[1,0]\n,,]]", "bad.json");
    EXPECT_EQ(j.diagnostic.status, Status::Malformed);
    EXPECT_TRUE(contains(j.diagnostic.message, "bad.json:2:2: JSON syntax error"))
        << j.diagnostic.message;
    ReadResult s = parsePolygon("[[[0,0],[1,0],[1,\"a\"]]]", "s.json");
    EXPECT_EQ(s.diagnostic.status, Status::Malformed);
    EXPECT_TRUE(contains(s.diagnostic.message, "s.json: polygon 0 ring 0 vertex 2"))
        << s.diagnostic.message;
    ReadResult ring =
        parsePolygon(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1]], 5]})", "r");
    EXPECT_TRUE(contains(ring.diagnostic.message, "ring 1: ring is not an array"))
        << ring.diagnostic.message;
    std::string deep(100000, '[');
    ReadResult d = parsePolygon(deep, "deep.json");
    EXPECT_EQ(d.diagnostic.status, Status::Malformed);
    EXPECT_TRUE(contains(d.diagnostic.message, "deep.json:1:65: JSON nested deeper than 64"))
        << d.diagnostic.message;
    EXPECT_EQ(parsePolygon("   \n", "empty").diagnostic.status, Status::Malformed);
    EXPECT_EQ(readPolygonFile("/nonexistent/x.json").diagnostic.status, Status::Malformed);
}

// 1e-400 was read as 0 while 1e400 was refused: a nonzero literal below the doubles is refused
// by every reader, with its place; a subnormal (1e-310, 5e-324) is a double and read exactly.
TEST(IoRead, UnderflowingLiteralsAreRefusedLikeOverflowingOnes) {
    const std::string tail =
        ": number out of range: 1e-400 underflows to 0 (the least double is "
        "4.9e-324)";
    struct Case {
        std::string text, name, message;
    } cases[] = {
        // A bare ring array (the fast reader declines it, the tree reader says why).
        {"[[[0,0],[10,0],\n [10,1e-400]]]", "a.json", "a.json:2:6" + tail},
        // GeoJSON, the literal in a Feature's properties (refused as 1e400 there is).
        {R"({"type":"Feature","properties":{"p":1e-400},"geometry":{"type":"Polygon",)"
         R"("coordinates":[[[0,0],[10,0],[0,10]]]}})",
         "f.json", "f.json:1:37" + tail},
        // Digits without an exponent, and the upper-case E.
        {"[[[0,0],[10,0],[0,0." + std::string(400, '0') + "1]]]", "digits.json",
         "digits.json:1:19: number out of range: 0.00000"},
        {"[[[0,0],[10,0],[0,-1E-400]]]", "upper.json",
         "upper.json:1:19: number out of range: -1E-400"},
        {"POLYGON ((0 0, 10 0, 10 1e-400, 0 10, 0 0))", "a.wkt", "a.wkt:1:25: WKT" + tail},
    };
    for (const Case& c : cases) {
        ReadResult r = parsePolygon(c.text, c.name);
        EXPECT_EQ(r.diagnostic.status, Status::Malformed) << c.name;
        EXPECT_EQ(r.diagnostic.message.rfind(c.message, 0), 0u) << r.diagnostic.message;
    }
    // flood check's reader of collections agrees: the file is one malformed row.
    DatasetRead d = parseFeatures(
        R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
        R"("geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[0,1e-400]]]}}]})",
        "fc.json", false);
    ASSERT_EQ(d.features.size(), 1u);
    EXPECT_TRUE(d.features[0].wholeFile);
    EXPECT_NE(d.features[0].read.diagnostic.message.find("underflows to 0"), std::string::npos)
        << d.features[0].read.diagnostic.message;
    // Zero however written, and subnormals, are numbers.
    for (const char* zero : {"0e-999", "0.0E-400", "-0.000e-5000", "1e-310", "5e-324", "3e-324"}) {
        const std::string z = zero;
        for (const std::string& text : {"[[[0,0],[10,0],[10,10],[5," + z + "]]]",
                                        "POLYGON ((0 0, 10 0, 10 10, 5 " + z + "))"}) {
            ReadResult r = parsePolygon(text, "z");
            EXPECT_TRUE(r.diagnostic.ok()) << text << ": " << r.diagnostic.message;
            ASSERT_EQ(r.polygon.vertices.size(), 4u) << text;
            EXPECT_EQ(r.polygon.vertices[3].y, std::strtod(zero, nullptr)) << text;
        }
    }
    // A trace's line (its header holds the polygon).
    Trace t;
    Diagnostic td = parseTrace(
        R"({"flood_trace":1,"vertices":[[0,0],[1e-400,0],[0,1]],"rings":[[0,3]]})", "t.jsonl", t);
    EXPECT_FALSE(td.ok());
    EXPECT_NE(td.message.find("underflows to 0"), std::string::npos) << td.message;
}

TEST(IoWrite, JsonRoundTripsExactly) {
    Polygon p;
    p.addRing({{0.1, 1e-300}, {1.0 / 3, 2}, {123456789.123456789, -0.5}}, true);
    std::vector<Triangle> t = {{0, 1, 2}};
    std::ostringstream out;
    writeJson(out, p, t);
    ReadResult back = parsePolygon(out.str(), "x");  // {"vertices":..} is not a polygon file
    EXPECT_EQ(back.diagnostic.status, Status::Malformed);
    auto j = nlohmann::json::parse(out.str());
    ASSERT_EQ(j["vertices"].size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(j["vertices"][i][0].get<double>(), p.vertices[i].x);
        EXPECT_EQ(j["vertices"][i][1].get<double>(), p.vertices[i].y);
    }
    EXPECT_EQ(j["triangles"][0][2].get<int>(), 2);
}

TEST(IoWrite, ObjAndSvg) {
    Polygon p = square();
    std::vector<Triangle> t = {{0, 1, 2}, {0, 2, 3}};
    std::ostringstream obj, svg;
    writeObj(obj, p, t);
    EXPECT_TRUE(contains(obj.str(), "v 10 10 0\n"));
    EXPECT_TRUE(contains(obj.str(), "f 1 3 4\n"));
    writeSvg(svg, p, t);
    EXPECT_TRUE(contains(svg.str(), "<svg"));
    EXPECT_TRUE(contains(svg.str(), "L10 -10 "));  // y flipped
    EXPECT_TRUE(contains(svg.str(), "M0 0 "));
    EXPECT_TRUE(contains(svg.str(), "</svg>"));
}

TEST(IoWrite, WktAndRingArrayAgree) {
    ReadResult a = parsePolygon("[[[0,0],[10,0],[10,10],[0,10]],[[2,2],[2,4],[4,4]]]", "a");
    ReadResult b = parsePolygon("POLYGON((0 0,10 0,10 10,0 10,0 0),(2 2,2 4,4 4,2 2))", "b");
    ASSERT_EQ(a.polygon.vertices.size(), b.polygon.vertices.size());
    for (size_t i = 0; i < a.polygon.vertices.size(); ++i)
        EXPECT_EQ(a.polygon.vertices[i], b.polygon.vertices[i]);
}
