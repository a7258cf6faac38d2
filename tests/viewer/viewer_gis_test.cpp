// The viewer's --layer and --where for GIS datasets (Model::gisLayer, gisWhere), with
// --feature N: a GeoPackage of two layers made here with ogr2ogr from GeoJSON. Compiles to
// nothing without the viewer; skipped, saying why, without GDAL or its ogr2ogr.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "model.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using flood::testing::runShell;
using flood::testing::scratch;

#ifdef FLOOD_GDAL
TEST(ViewerGis, LayerWhereAndFeatureChooseWhatOpens) {
    if (runShell("command -v ogr2ogr").code != 0)
        GTEST_SKIP() << "ogr2ogr (gdal-bin) is not installed";
    std::filesystem::path d = scratch("viewer-gis");
    // a: a square (4 vertices), b: a square with a hole (8), c: a triangle (3).
    std::ofstream(d / "src.geojson") << R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "a"},
         "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}},
        {"type": "Feature", "properties": {"name": "b"},
         "geometry": {"type": "Polygon", "coordinates": [[[20,0],[30,0],[30,10],[20,10],[20,0]],
                                                       [[23,3],[23,7],[27,7],[27,3],[23,3]]]}},
        {"type": "Feature", "properties": {"name": "c"},
         "geometry": {"type": "Polygon", "coordinates": [[[40,0],[50,0],[45,8],[40,0]]]}}]})";
    std::string gpkg = (d / "two.gpkg").string(), src = (d / "src.geojson").string();
    ASSERT_EQ(runShell("ogr2ogr -f GPKG " + gpkg + " " + src + " -nln first 2>&1").code, 0);
    ASSERT_EQ(
        runShell("ogr2ogr -update " + gpkg + " " + src + " -nln second -where \"name = 'c'\" 2>&1")
            .code,
        0);

    Model m;
    m.gisLayer = "second";
    m.open(gpkg);
    ASSERT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), 3u);
    EXPECT_EQ(m.exitCode(), 0) << m.verdict();

    m.gisLayer = "first", m.gisWhere = "name = 'b'";
    m.open(gpkg);
    ASSERT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), 8u);
    EXPECT_EQ(m.polygon().rings.size(), 2u);
    EXPECT_EQ(m.exitCode(), 0) << m.verdict();

    // --feature N is the FID, as in `flood check` and `flood --feature`, whatever --where
    // keeps: c is FID 3 (it was "the second of b, c", 1), and a, FID 1, is filtered out.
    m.gisWhere = "name <> 'a'";
    ASSERT_TRUE(m.openFeature(gpkg, 3)) << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), 3u);
    EXPECT_EQ(m.feature(), 3u);
    EXPECT_EQ(m.path(), gpkg + "#3");
    EXPECT_FALSE(m.openFeature(gpkg, 1));
    EXPECT_EQ(m.openDiagnostic().status, Status::Usage) << m.openDiagnostic().message;
    EXPECT_NE(m.openDiagnostic().message.find("no polygonal feature 1 (the collection's FIDs run "
                                              "2..3)"),
              std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), 3u) << "a failed open keeps what was loaded";

    // A filter GDAL refuses and a layer that is not there: failures naming the file, the
    // loaded polygon kept.
    m.gisWhere = "no_such_field = 1";
    m.open(gpkg);
    EXPECT_FALSE(m.openDiagnostic().ok());
    EXPECT_NE(m.openDiagnostic().message.find(gpkg), std::string::npos)
        << m.openDiagnostic().message;
    m.gisLayer = "third", m.gisWhere = "";
    m.open(gpkg);
    EXPECT_FALSE(m.openDiagnostic().ok());
    EXPECT_NE(m.openDiagnostic().message.find("third"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.polygon().vertices.size(), 3u);
    std::filesystem::remove_all(d);
}
#else
TEST(ViewerGis, LayerWhereAndFeatureChooseWhatOpens) {
    GTEST_SKIP()
        << "built without GDAL (libgdal-dev): the viewer's --layer and --where are not there";
}
#endif

#endif
