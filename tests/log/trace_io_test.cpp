// Trace files: round trips, their errors naming the line, non-finite coordinates, long
// literals cut in messages.
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

TEST(TraceIo, RoundTripAndErrors) {
    ReadResult r = readPolygonFile(source("polygons/hole.json"));
    ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    Trace t = record(r.polygon);
    Trace back = writtenAndRead(t);
    ASSERT_EQ(back.events.size(), t.events.size());
    for (size_t i = 0; i < t.events.size(); ++i)  // every field (FLOOD_EVENT_FIELDS)
        EXPECT_TRUE(back.events[i] == t.events[i]) << "event " << i << " changed on the way";
    EXPECT_EQ(back.triangles, t.triangles);
    EXPECT_EQ(back.polygon.vertices.size(), t.polygon.vertices.size());
    // T-junctions travel with the polygon.
    ReadResult tjRead = readPolygonFile(source("polygons/t-junction.json"));
    Polygon& tj = tjRead.polygon;
    ASSERT_TRUE(validate(tj, "tj").ok());
    ASSERT_FALSE(tj.splits.empty());
    Trace withSplits = record(tj);
    Trace tjBack = writtenAndRead(withSplits);
    ASSERT_EQ(tjBack.polygon.splits.size(), tj.splits.size());
    for (size_t i = 0; i < tj.splits.size(); ++i) {
        EXPECT_EQ(tjBack.polygon.splits[i].edge, tj.splits[i].edge);
        EXPECT_EQ(tjBack.polygon.splits[i].vertex, tj.splits[i].vertex);
    }
    EXPECT_TRUE(checkTriangulation(tjBack.polygon, tjBack.triangles).ok);
    // Damage: wrong version, bad line, truncated, index out of range.
    std::ostringstream out;
    writeTrace(out, t);
    std::string text = out.str();
    std::string v2 = text;
    const std::string version = "\"version\":" + std::to_string(kTraceFormatVersion);
    v2.replace(v2.find(version), version.size(), "\"version\":99");
    EXPECT_TRUE(contains(parseTrace(v2, "t", back).message, "t:1: trace format version 99"));
    std::string bad = text;
    size_t line2 = bad.find('\n') + 1;
    bad.insert(line2, "{not json\n");
    Diagnostic db = parseTrace(bad, "t", back);
    EXPECT_EQ(db.status, Status::Malformed);
    EXPECT_TRUE(contains(db.message, "t:2:")) << db.message;
    EXPECT_TRUE(back.events.empty());
    std::string trunc = text.substr(0, text.rfind('\n', text.size() - 2) + 1);
    EXPECT_TRUE(contains(parseTrace(trunc, "t", back).message, "truncated"));
    std::string idx = text;
    size_t w = idx.find("\"water\":", line2);
    idx.replace(w, 9, "\"water\":999999,\"x\":");
    Diagnostic di = parseTrace(idx, "t", back);
    EXPECT_EQ(di.status, Status::Malformed) << di.message;
    // Every prefix of a trace is rejected or accepted without crashing.
    for (size_t cut = 0; cut < text.size(); cut += 7) parseTrace(text.substr(0, cut), "t", back);
}

// Correct at scale (validation's speed is measured in bench/, not here).
// Non-finite coordinates (only an unvalidated run holds them) are written as "NaN",
// "Infinity", "-Infinity" and read back as the same values (nlohmann wrote null, unreadable).
TEST(TraceIo, NonFiniteCoordinatesRoundTrip) {
    Trace t;
    double inf = std::numeric_limits<double>::infinity();
    t.polygon.addRing({{0, 0}, {inf, 0}, {1, std::nan("")}, {-inf, 1}}, true);
    t.diagnostic = {Status::Forbidden, "forbidden transition NotFinite"};
    std::ostringstream out;
    writeTrace(out, t);
    EXPECT_TRUE(
        contains(out.str(), R"([[0.0,0.0],["Infinity",0.0],[1.0,"NaN"],["-Infinity",1.0]])"))
        << out.str();
    Trace back;
    Diagnostic d = parseTrace(out.str(), "t.jsonl", back);
    ASSERT_TRUE(d.ok()) << d.message;
    ASSERT_EQ(back.polygon.vertices.size(), 4u);
    EXPECT_EQ(back.polygon.vertices[1].x, inf);
    EXPECT_TRUE(std::isnan(back.polygon.vertices[2].y));
    EXPECT_EQ(back.polygon.vertices[3].x, -inf);
    std::string text = out.str();
    text.replace(text.find("\"NaN\""), 5, "\"nan\"");
    EXPECT_TRUE(
        contains(parseTrace(text, "t", back).message, "t:1: vertex 2 is not a pair of numbers"));
}

// A long literal in a trace is cut in the message too.
TEST(TraceIo, LongLiteralsCut) {
    Trace back;
    std::string junk(1000000, 'q');
    for (const std::string& text :
         {"{\"format\":\"" + junk, "{\"format\":" + junk + "}", "[\"" + junk + "\"]"}) {
        Diagnostic d = parseTrace(text, "t", back);
        EXPECT_EQ(d.status, Status::Malformed);
        EXPECT_LT(d.message.size(), 400u) << d.message.substr(0, 400);
    }
}
