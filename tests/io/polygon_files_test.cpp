// Which files are polygons (flood/io/io.h): the one listing of a folder the viewer, the tests
// and pytest use.
#include <gtest/gtest.h>

#include <fstream>

#include "flood/io/io.h"
#include "test_support.h"

using namespace flood;

TEST(PolygonFiles, AFoldersOwnPolygonFilesSortedButTheGalleryIndex) {
    const std::filesystem::path d = flood::testing::scratch("polygon-files");
    for (const char* name : {"b.wkt", "a.json", "C.GeoJSON", "gallery.json", "notes.txt",
                             "trace.jsonl", "sub/d.json"}) {
        std::filesystem::create_directories((d / name).parent_path());
        std::ofstream(d / name) << "[]";
    }
    std::filesystem::create_directories(d / "folder.json");  // a folder, whatever its name
    std::vector<std::string> want;
    for (const char* name : {"C.GeoJSON", "a.json", "b.wkt"}) want.push_back((d / name).string());
    EXPECT_EQ(polygonFiles(d.string()), want);
    EXPECT_TRUE(polygonFiles((d / "missing").string()).empty());
    std::filesystem::remove_all(d);
}

TEST(PolygonFiles, NamesTheReadersTake) {
    EXPECT_TRUE(polygonFileName("x/a.json"));
    EXPECT_TRUE(polygonFileName("a.WKT"));
    EXPECT_TRUE(polygonFileName("a.geojson"));
    EXPECT_FALSE(polygonFileName("a.jsonl"));
    EXPECT_FALSE(polygonFileName("a.shp"));
    EXPECT_FALSE(polygonFileName("json"));
    EXPECT_EQ(polygonFormats(), ".json, .geojson, .wkt");
}

// The sample polygons every test iterates over: all of polygons/ but the gallery's index.
TEST(PolygonFiles, TheSamplesAreThePolygonsOfPolygonsFolder) {
    std::vector<std::string> samples = polygonFiles(flood::testing::sourcePath("polygons"));
    EXPECT_GE(samples.size(), 10u);
    for (const std::string& f : samples) {
        EXPECT_EQ(f.find("gallery.json"), std::string::npos);
        EXPECT_TRUE(readPolygonFile(f).diagnostic.ok()) << f;
    }
}
