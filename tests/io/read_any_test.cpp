// The choice of reader (flood/io/gdal/read_any.h), the one place the CLI and the viewer choose
// GDAL or the core's readers, in a build with GDAL and without.
#include "flood/io/gdal/read_any.h"

#include <gtest/gtest.h>

#include "test_support.h"

using namespace flood;
using flood::testing::sourcePath;

TEST(ReadAny, OwnFormatsGoToTheCoresReaders) {
    const std::string hole = sourcePath("polygons/hole.json");
    ReadResult any = gdal::readAny(hole, {});
    ReadResult core = readPolygonFile(hole);
    ASSERT_TRUE(any.diagnostic.ok()) << any.diagnostic.message;
    EXPECT_EQ(any.polygon.vertices.size(), core.polygon.vertices.size());
    bool gis = true;
    DatasetRead d = gdal::readAnyFeatures(hole, {}, kDefaultMaxInputBytes, false, gis);
    EXPECT_FALSE(gis);
    ASSERT_EQ(d.features.size(), 1u);
    EXPECT_TRUE(d.features[0].read.diagnostic.ok());
    // The byte cap is the caller's.
    EXPECT_EQ(gdal::readAny(hole, {}, 10).diagnostic.status, Status::Malformed);
}

TEST(ReadAny, ASelectionIsGdalsOrRefusedWithoutIt) {
    const std::string mixed = sourcePath("polygons/datasets/mixed.geojson");
    gdal::Selection s;
    s.where = "1 = 1";
    bool gis = false;
    DatasetRead d = gdal::readAnyFeatures(mixed, s, kDefaultMaxInputBytes, false, gis);
    ReadResult r = gdal::readAny(mixed, s);
    if (gdal::built()) {
        EXPECT_TRUE(gis);
        EXPECT_TRUE(gdal::listedFile("x/a.GPKG"));
        EXPECT_EQ(gdal::listedFormats().rfind(polygonFormats() + ", .shp", 0), 0u)
            << gdal::listedFormats();
        EXPECT_NE(r.diagnostic.status, Status::Usage) << r.diagnostic.message;
    } else {
        EXPECT_FALSE(gis);
        ASSERT_EQ(d.features.size(), 1u);
        EXPECT_EQ(d.features[0].read.diagnostic.status, Status::Usage);
        EXPECT_EQ(r.diagnostic.status, Status::Usage);
        EXPECT_EQ(r.diagnostic.message.rfind(mixed + ": --layer", 0), 0u) << r.diagnostic.message;
        EXPECT_FALSE(gdal::listedFile("x/a.gpkg"));
        EXPECT_EQ(gdal::listedFormats(), polygonFormats());
    }
    EXPECT_TRUE(gdal::listedFile("x/a.wkt"));
    EXPECT_FALSE(gdal::listedFile("x/a.txt"));
}
