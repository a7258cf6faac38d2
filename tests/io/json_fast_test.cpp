// The fast JSON reader (core/io/io_json_fast.cpp) against the document-tree reader it stands in
// for: every document it reads must read to the same polygon and warnings there, and every
// document it declines must be one the tree reader reads or explains (the same message).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include "flood/tools/generate.h"
#include "flood/tools/shrink.h"
#include "io/io_json.h"
#include "io/io_util.h"
#include "test_support.h"

namespace {

using namespace flood;
using flood::io_detail::parseJsonFast;
using flood::io_detail::parseJsonTree;

size_t firstBracket(const std::string& text) {
    size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (i < text.size() && std::strchr(" \t\r\n", text[i])) ++i;
    return i;
}

std::optional<ReadResult> fast(const std::string& text) {
    return parseJsonFast(text, text.size(), firstBracket(text), "doc");
}

// Bit for bit: -0.0 is not 0.0 here.
bool samePoint(Point a, Point b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSame(const ReadResult& a, const ReadResult& b, const std::string& what) {
    ASSERT_EQ(a.diagnostic.ok(), b.diagnostic.ok()) << what << ": " << b.diagnostic.message;
    EXPECT_EQ(a.diagnostic.message, b.diagnostic.message) << what;
    ASSERT_EQ(a.polygon.vertices.size(), b.polygon.vertices.size()) << what;
    for (size_t i = 0; i < a.polygon.vertices.size(); ++i)
        ASSERT_TRUE(samePoint(a.polygon.vertices[i], b.polygon.vertices[i]))
            << what << " vertex " << i;
    ASSERT_EQ(a.polygon.rings.size(), b.polygon.rings.size()) << what;
    for (size_t r = 0; r < a.polygon.rings.size(); ++r) {
        EXPECT_EQ(a.polygon.rings[r].first, b.polygon.rings[r].first) << what;
        EXPECT_EQ(a.polygon.rings[r].count, b.polygon.rings[r].count) << what;
    }
    ASSERT_EQ(a.polygon.parts.size(), b.polygon.parts.size()) << what;
    for (size_t p = 0; p < a.polygon.parts.size(); ++p) {
        EXPECT_EQ(a.polygon.parts[p].firstRing, b.polygon.parts[p].firstRing) << what;
        EXPECT_EQ(a.polygon.parts[p].ringCount, b.polygon.parts[p].ringCount) << what;
    }
    EXPECT_EQ(a.warnings, b.warnings) << what;
    EXPECT_EQ(a.warningsOmitted, b.warningsOmitted) << what;
}

// Read by the fast reader, and to what the tree reader reads.
void expectFast(const std::string& text) {
    std::optional<ReadResult> f = fast(text);
    ASSERT_TRUE(f.has_value()) << "declined: " << text.substr(0, 200);
    expectSame(*f, parseJsonTree(text, "doc"), text.substr(0, 200));
    expectSame(*f, parsePolygon(text, "doc"), text.substr(0, 200));
}

// Declined, so parsePolygon says what the tree reader says.
void expectDeclined(const std::string& text) {
    EXPECT_FALSE(fast(text).has_value()) << text;
    expectSame(parsePolygon(text, "doc"), parseJsonTree(text, "doc"), text);
}

TEST(JsonFast, ReadsRingArraysAndGeoJsonAsTheTreeReaderDoes) {
    expectFast("[[[0,0],[4,0],[4,4],[0,4]]]");
    expectFast("[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,2],[2,2],[2,1],[1,1]]]");
    expectFast("[[[[0,0],[1,0],[0,1]]],[[[5,5],[6,5],[5,6]]]]");
    expectFast("\xEF\xBB\xBF \n [ [ [0, 0] , [1e0, 0.0], [0,1.5e-3] ] ]\n");
    // Repeated points warn, closing points go silently, a point hole is [p, p].
    expectFast("[[[0,0],[0,0],[4,0],[4,4],[4,4],[0,4],[0,0]],[[2,2],[2,2]]]");
    // "-0" is an integer to the tree reader: +0.0; "-0.0" stays -0.0.
    expectFast("[[[-0,-0.0],[4,0],[4,4]]]");
    // Digits beyond a double, tiny and huge values, integers past 2^53 and 2^64.
    expectFast(
        "[[[0.1000000000000000055511151231257827,1e-300],[9007199254740993,"
        "18446744073709551617],[-4.9e-324,1.7976931348623157e308]]]");
    expectFast(
        "[[[0.30000000000000001665334536938,2.2250738585072011e-308],[7.3177701707893310e+15,"
        "-123456789012345678901234567890e-10],[1e23,8.98846567431158e307]]]");
    // Members after x and y (z, m) are ignored but must be valid.
    expectFast("[[[0,0,7],[4,0,\"z\",{\"a\":[null,true]}],[4,4,1.5]]]");
    expectFast("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]]}");
    expectFast(
        "{\"bbox\":[0,0,4,4],\"type\":\"MultiPolygon\",\"crs\":{\"x\":\"\\u00e9\"},"
        "\"coordinates\":[[[[0,0],[4,0],[4,4]]],[[[9,9],[8,9],[9,8]]]]}");
    expectFast(
        "{\"t\\u0079pe\":\"Feature\",\"properties\":{\"name\":\"a\\\"b\",\"n\":[1,{}]},"
        "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]]}}");
    expectFast(
        "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\",\"geometry\":"
        "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]]},\"properties\":null},"
        "{\"geometry\":{\"type\":\"MultiPolygon\",\"coordinates\":[[[[5,5],[6,5],[6,6]]]]}}]}");
    expectFast(
        "{\"type\":\"GeometryCollection\",\"geometries\":[{\"type\":\"Polygon\","
        "\"coordinates\":[[[0,0],[4,0],[4,4]]]},{\"type\":\"Feature\",\"geometry\":"
        "{\"type\":\"Polygon\",\"coordinates\":[[[5,5],[6,5],[6,6]]]}}]}");
}

TEST(JsonFast, ReadsEveryGeneratedFamilyAndSample) {
    for (const std::string& family : familyNames()) {
        std::ostringstream text;
        writePolygonJson(text, generate(family, 3, 300));
        expectFast(text.str());
    }
    for (const std::string& path :
         flood::testing::filesIn(flood::testing::sourcePath("polygons"), ".json")) {
        std::string text = flood::testing::slurp(path);
        std::optional<ReadResult> f = fast(text);
        if (f) expectSame(*f, parseJsonTree(text, path), path);
        else expectSame(parsePolygon(text, path), parseJsonTree(text, path), path);
    }
}

TEST(JsonFast, DeclinesWhatOnlyTheTreeReaderCanExplain) {
    // Syntax errors, anywhere: also in a member the fast reader does not need.
    expectDeclined("[[[0,0],[4,0],[4,4]],]");
    expectDeclined("[[[0,0],[4,0],[4,4]]] x");
    expectDeclined("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]],\"p\":[1,,2]}");
    expectDeclined("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]],\"p\":tru}");
    expectDeclined("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]],\"p\":\"a\tb\"}");
    expectDeclined("[[[0,0],[4,0],[4,1e999]]]");
    expectDeclined("[[[0,0],[4,0],[4,1e-400]]]");  // underflow: the tree reader decides
    expectDeclined("[[[0,0],[4,0],[4,1.]]]");
    expectDeclined("[[[0,0],[4,0],[4,-]]]");
    expectDeclined("[[[0,0],[4,0],[4,1e+]]]");
    expectDeclined("[[[0,0],[4,0],[4,+1]]]");
    expectDeclined("[[[0,0],[4,0],[4,01]]]");
    // Structure problems and what the tree reader reads differently or warns about.
    expectDeclined("[[[0,0],[4,0],[4]]]");
    expectDeclined("[[[0,0],[4,0],[4,\"4\"]]]");
    expectDeclined("[[]]");
    expectDeclined("[]");
    expectDeclined("[[[[[0,0]]]]]");
    expectDeclined("{\"coordinates\":[[[0,0],[4,0],[4,4]]],\"type\":\"Polygon\"}");
    expectDeclined(
        "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]],\"type\":\"Point\"}");
    expectDeclined(
        "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]],"
        "\"coordinates\":[[[0,0],[5,0],[5,5]]]}");
    expectDeclined("{\"type\":\"Point\",\"coordinates\":[0,0]}");
    expectDeclined(
        "{\"type\":\"FeatureCollection\",\"features\":[{\"geometry\":{\"type\":\"Point\","
        "\"coordinates\":[0,0]}},{\"geometry\":{\"type\":\"Polygon\",\"coordinates\":"
        "[[[0,0],[4,0],[4,4]]]}}]}");
    expectDeclined("{\"type\":\"Feature\",\"geometry\":null}");
    // Nested deeper than the tree reader allows.
    expectDeclined("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[4,0],[4,4]]],\"p\":" +
                   std::string(100, '[') + std::string(100, ']') + "}");
}

// The file reader leaves simdjson its padding, so a large file is not copied: the read-ahead
// capacity is there when the fast reader runs.
TEST(JsonFast, FileReaderLeavesTheReadAhead) {
    auto dir = flood::testing::scratch("json-fast");
    std::string path = (dir / "p.json").string();
    {
        std::ofstream out(path);
        out << "[[[0,0],[4,0],[4,4]]]";
    }
    std::string text;
    ASSERT_TRUE(readInputFile(path, text, kDefaultMaxInputBytes, "JSON").ok());
    EXPECT_GE(text.capacity(), text.size() + io_detail::kReadAhead);
    std::filesystem::remove_all(dir);
}

}  // namespace
