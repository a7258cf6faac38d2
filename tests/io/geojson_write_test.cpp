// Writing a polygon as GeoJSON (flood/io/io.h): what is written reads back as the same
// polygon, a MultiPolygon keeps its parts, and saving is atomic.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "flood/io/io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using flood::testing::scratch;
using flood::testing::slurp;

namespace {
void expectSame(const Polygon& a, const Polygon& b) {
    EXPECT_EQ(a.vertices, b.vertices);
    ASSERT_EQ(a.rings.size(), b.rings.size());
    ASSERT_EQ(a.parts.size(), b.parts.size());
    for (size_t i = 0; i < a.parts.size(); ++i)
        EXPECT_EQ(a.parts[i].ringCount, b.parts[i].ringCount);
}
}  // namespace

TEST(GeoJsonWrite, GeometryReadsBackAsTheSamePolygon) {
    // Doubles that need all 17 digits, a hole, and a MultiPolygon of two parts.
    ReadResult one = parsePolygon(
        "[[[0.1,0.2],[10.000000000000002,0],[10,10],[0,10]],[[2,2],[2,3],[3,3],[3,2]]]", "one");
    ASSERT_TRUE(one.diagnostic.ok());
    ReadResult two = parsePolygon(
        R"({"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]],[[[5,5],[6,5],[6,6],[5,5]]]]})",
        "two");
    ASSERT_TRUE(two.diagnostic.ok());
    for (const Polygon* p : {&one.polygon, &two.polygon}) {
        const std::string text = geoJsonGeometry(*p);
        EXPECT_EQ(
            text.rfind(p->parts.size() == 1 ? R"({"type":"Polygon")" : R"({"type":"MultiPolygon")",
                       0),
            0u)
            << text;
        ReadResult back = parsePolygon(text, "back");
        ASSERT_TRUE(back.diagnostic.ok()) << back.diagnostic.message;
        expectSame(back.polygon, *p);
    }
}

TEST(GeoJsonWrite, EveryGeneratedFamilyRoundTrips) {
    for (const std::string& family : familyNames()) {
        Polygon p = generate(family, 7, 200);
        ReadResult back = parsePolygon(geoJsonGeometry(p), family);
        ASSERT_TRUE(back.diagnostic.ok()) << family << ": " << back.diagnostic.message;
        expectSame(back.polygon, p);
    }
}

TEST(GeoJsonWrite, SaveReplacesTheFileWholeOrNotAtAll) {
    const auto dir = scratch("geojson_write");
    const std::string path = (dir / "face.geojson").string();
    ReadResult square = parsePolygon("[[[0,0],[2,0],[2,2],[0,2]]]", "square");
    ASSERT_TRUE(saveGeoJson(square.polygon, path).ok());
    ReadResult back = readPolygonFile(path);
    ASSERT_TRUE(back.diagnostic.ok()) << back.diagnostic.message;
    expectSame(back.polygon, square.polygon);

    // A folder that does not exist: WriteFailed naming the path, nothing left in the folder.
    Diagnostic d = saveGeoJson(square.polygon, (dir / "missing" / "x.geojson").string());
    EXPECT_EQ(d.status, Status::WriteFailed);
    EXPECT_NE(d.message.find("missing/x.geojson"), std::string::npos) << d.message;
    EXPECT_EQ(d.message.rfind("error: ", 0), std::string::npos)
        << "a diagnostic, not a printed line";
    size_t entries = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        entries += e.path().filename() != "face.geojson";
    EXPECT_EQ(entries, 0u) << "a temporary file was left behind";
    EXPECT_EQ(slurp(path), geoJsonGeometry(square.polygon) + "\n") << "the saved file changed";
}
