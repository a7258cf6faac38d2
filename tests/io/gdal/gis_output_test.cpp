// `flood triangulate IN -o OUT` for GIS outputs (cli/triangulate_gis.cpp, core/io/gdal/
// gdal_write.cpp), read back as a user reads them: through GDAL (the API ogrinfo uses) for the
// driver, the CRS, the fields and the feature count. The fixture: three parcels, two of them
// neighbours sharing an edge, the third a bow-tie, made at test time with ogr2ogr.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <fstream>
#include <map>

#include "test_support.h"

namespace flood::testing {
namespace {

namespace fs = std::filesystem;

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

Dataset open(const fs::path& file) {
    GDALAllRegister();
    return Dataset(static_cast<GDALDataset*>(
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
}

// Each feature of a dataset's only layer: its fields by name, as text.
struct Layer {
    std::string driver, crs;  // "" when the layer has no CRS
    std::string crsCode;      // "EPSG:4326", ...
    OGRwkbGeometryType type = wkbUnknown;
    std::vector<int64_t> fids;
    std::vector<std::map<std::string, std::string>> features;
    std::vector<double> areas;
};

Layer readBack(const fs::path& file) {
    Layer out;
    Dataset ds = open(file);
    if (!ds) return out;
    out.driver = ds->GetDriver()->GetDescription();
    OGRLayer* l = ds->GetLayer(0);
    if (const OGRSpatialReference* s = l->GetSpatialRef()) {
        out.crs = s->GetName();
        OGRSpatialReference copy(*s);
        copy.AutoIdentifyEPSG();
        if (const char* code = copy.GetAuthorityCode(nullptr))
            out.crsCode = "EPSG:" + std::string(code);
    }
    for (OGRFeature* f; (f = l->GetNextFeature()) != nullptr; OGRFeature::DestroyFeature(f)) {
        std::map<std::string, std::string> fields;
        for (int i = 0; i < f->GetFieldCount(); ++i)
            if (f->IsFieldSetAndNotNull(i))
                fields[f->GetFieldDefnRef(i)->GetNameRef()] = f->GetFieldAsString(i);
        out.fids.push_back(f->GetFID());
        out.features.push_back(fields);
        const OGRGeometry* g = f->GetGeometryRef();
        out.type = g ? wkbFlatten(g->getGeometryType()) : wkbUnknown;
        out.areas.push_back(g && OGR_GT_IsSurface(out.type)    ? g->toPolygon()->get_Area()
                            : g && out.type == wkbMultiPolygon ? g->toMultiPolygon()->get_Area()
                                                               : 0);
    }
    return out;
}

class GisOutput : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = scratch("gis-output");
        std::ofstream(dir_ / "parcels.geojson") << R"({"type":"FeatureCollection","features":[
{"type":"Feature","properties":{"name":"France","pop":67.5},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]}},
{"type":"Feature","properties":{"name":"Spain","pop":47.5},"geometry":{"type":"Polygon","coordinates":[[[2,0],[4,0],[4,2],[2,2],[2,0]]]}},
{"type":"Feature","properties":{"name":"Bow-tie","pop":1},"geometry":{"type":"Polygon","coordinates":[[[0,5],[2,7],[2,5],[0,7],[0,5]]]}}]})";
        const std::string src = (dir_ / "parcels.geojson").string();
        for (const char* cmd :
             {"ogr2ogr -f GPKG -a_srs EPSG:4326 -nln parcels DIR/parcels.gpkg SRC",
              "ogr2ogr -f FlatGeobuf -a_srs EPSG:2249 DIR/ftus.fgb SRC"}) {
            std::string c = cmd;
            c.replace(c.find("DIR"), 3, dir_.string());
            c.replace(c.find("SRC"), 3, src);
            RunResult r = runShell(c + " 2>&1");
            ASSERT_EQ(r.code, 0) << c << "\n" << r.out;
        }
    }
    static std::string path(const std::string& f) { return (dir_ / f).string(); }
    static fs::path dir_;
};
fs::path GisOutput::dir_;

// Each extension gives its GDAL format (ogrinfo opens it with that driver), with the input's
// CRS, the source fields and FID on every triangle, and both neighbouring parcels: 2 + 2
// triangles; the bow-tie is reported (exit 4, as `flood check`) and left out.
TEST_F(GisOutput, TheExtensionChoosesTheFormatAndEveryFeatureKeepsItsFieldsAndCrs) {
    const std::map<std::string, std::string> drivers = {
        {"geojson", "GeoJSON"}, {"shp", "ESRI Shapefile"}, {"gpkg", "GPKG"}, {"fgb", "FlatGeobuf"},
        {"csv", "CSV"},         {"kml", "LIBKML"}};
    for (const auto& [ext, driver] : drivers) {
        SCOPED_TRACE(ext);
        const std::string out = path("tri." + ext);
        RunResult r = runCli("triangulate " + path("parcels.gpkg") + " -o " + out);
        EXPECT_EQ(r.code, 4) << r.out;
        EXPECT_NE(r.out.find("error: invalid polygon: " + path("parcels.gpkg") + ": feature 3: "),
                  std::string::npos)
            << r.out;
        EXPECT_NE(r.out.find("2 of 3 features written"), std::string::npos) << r.out;
        Layer l = readBack(out);
        EXPECT_EQ(l.driver == "KML" ? "LIBKML" : l.driver, driver);
        EXPECT_EQ(l.crsCode, "EPSG:4326") << l.crs;
        ASSERT_EQ(l.features.size(), 4u);
        std::map<std::string, std::string> fidOf;
        double area = 0;
        for (size_t i = 0; i < 4; ++i) {
            auto& f = l.features[i];
            const std::string name = f.count("name") ? f["name"] : f["Name"];  // KML's own
            EXPECT_TRUE(name == "France" || name == "Spain") << name;
            EXPECT_EQ(std::stod(f["pop"]), name == "France" ? 67.5 : 47.5);
            EXPECT_EQ(f["src_fid"], name == "France" ? "1" : "2");
            EXPECT_TRUE(f["triangle"] == "0" || f["triangle"] == "1");
            area += l.areas[i];
        }
        EXPECT_EQ(area, 8.0);
    }
}

// A CRS in US survey feet (FlatGeobuf to FlatGeobuf) was "(unknown)".
TEST_F(GisOutput, AProjectedCrsIsKept) {
    RunResult r = runCli("triangulate " + path("ftus.fgb") + " --where \"name <> 'Bow-tie'\" -o " +
                         path("ftus-tri.fgb"));
    EXPECT_EQ(r.code, 0) << r.out;
    Layer l = readBack(path("ftus-tri.fgb"));
    EXPECT_EQ(l.crsCode, "EPSG:2249") << l.crs;
    EXPECT_NE(l.crs.find("ftUS"), std::string::npos) << l.crs;
    EXPECT_EQ(l.features.size(), 4u);
    // --where "name='France'" into a GeoPackage: one feature's triangles, WGS 84 still.
    r = runCli("triangulate " + path("parcels.gpkg") + " --where \"name='France'\" -o " +
               path("fr.gpkg"));
    EXPECT_EQ(r.code, 0) << r.out;
    l = readBack(path("fr.gpkg"));
    EXPECT_EQ(l.crsCode, "EPSG:4326") << l.crs;
    EXPECT_EQ(l.features.size(), 2u);
}

// --per-feature multipolygon: one feature per source feature, its FID kept where the format
// keeps FIDs (GeoPackage), its area the parcel's.
TEST_F(GisOutput, OneMultiPolygonPerFeature) {
    RunResult r = runCli("triangulate " + path("parcels.gpkg") + " --per-feature multipolygon -o " +
                         path("multi.gpkg"));
    EXPECT_EQ(r.code, 4) << r.out;
    Layer l = readBack(path("multi.gpkg"));
    EXPECT_EQ(l.type, wkbMultiPolygon);
    ASSERT_EQ(l.features.size(), 2u);
    EXPECT_EQ(l.fids, (std::vector<int64_t>{1, 2}));
    EXPECT_EQ(l.features[0]["name"], "France");
    EXPECT_EQ(l.features[0].count("triangle"), 0u);
    EXPECT_EQ(l.areas, (std::vector<double>{4, 4}));
}

// An extension nothing writes is a usage error and writes nothing; .json stays Flood's own
// JSON; --format names a GDAL driver whatever the extension.
TEST_F(GisOutput, AnUnknownExtensionIsAUsageError) {
    const std::string hole = sourcePath("polygons/hole.json");
    for (const char* ext : {"png", "xyz"}) {
        RunResult r = runCli("triangulate " + hole + " -o " + path(std::string("tri.") + ext));
        EXPECT_EQ(r.code, 2) << r.out;
        EXPECT_NE(r.out.find("no format writes ." + std::string(ext)), std::string::npos) << r.out;
        EXPECT_FALSE(fs::exists(path(std::string("tri.") + ext)));
    }
    RunResult r = runCli("triangulate " + hole + " --format nosuchformat -o " + path("t.gpkg"));
    EXPECT_EQ(r.code, 2) << r.out;
    r = runCli("triangulate " + hole + " -o " + path("own.json"));
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(slurp(path("own.json")).rfind("{\"vertices\"", 0), 0u) << slurp(path("own.json"));
    // A single polygon without a CRS: one feature, FID 0, no CRS.
    r = runCli("triangulate " + hole + " --format GeoJSON -o " + path("hole.txt"));
    EXPECT_EQ(r.code, 0) << r.out;
    Layer l = readBack(path("hole.txt"));
    EXPECT_EQ(l.driver, "GeoJSON");
    ASSERT_FALSE(l.features.empty());
    EXPECT_EQ(l.features[0]["src_fid"], "0");
}

// A GeoJSON read by Flood's own reader gets its fields and CRS (GeoJSON's: WGS 84) through
// GDAL, matched by FID.
TEST_F(GisOutput, AGeoJsonInputKeepsItsFieldsToo) {
    RunResult r = runCli("triangulate " + path("parcels.geojson") + " -o " + path("json.gpkg"));
    EXPECT_EQ(r.code, 4) << r.out;
    EXPECT_NE(r.out.find(path("parcels.geojson") + ": feature 2: "), std::string::npos) << r.out;
    Layer l = readBack(path("json.gpkg"));
    EXPECT_EQ(l.crsCode, "EPSG:4326") << l.crs;
    ASSERT_EQ(l.features.size(), 4u);
    for (auto& f : l.features)
        EXPECT_EQ(f["name"], f["src_fid"] == "0" ? "France" : "Spain") << f["src_fid"];
}

// A Shapefile replaced by one without a CRS loses its old .prj: it would describe the new
// layer wrongly.
TEST_F(GisOutput, AShapefileReplacedKeepsNoStaleSideFile) {
    const std::string shp = path("replaced.shp");
    ASSERT_EQ(runCli("triangulate " + path("parcels.gpkg") + " -o " + shp).code, 4);
    ASSERT_TRUE(fs::exists(path("replaced.prj")));
    RunResult r = runCli("triangulate " + sourcePath("polygons/hole.json") + " -o " + shp);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_FALSE(fs::exists(path("replaced.prj")));
    Layer l = readBack(shp);
    EXPECT_EQ(l.crs, "");
    EXPECT_EQ(l.features.size(), 8u);
    for (const char* side : {".shx", ".dbf"}) EXPECT_TRUE(fs::exists(path("replaced") + side));
}

}  // namespace
}  // namespace flood::testing
