// `flood check --findings OUT`, `--extract DIR` of GIS features and datasets of several layers
// (issue 26 §2; cli/check_findings.cpp), read back as a QGIS user reads them: through GDAL's
// API (what ogrinfo and QGIS use) for the count, the fields, the geometries and the CRS.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "test_support.h"
#ifdef FLOOD_GDAL
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#endif

#ifdef FLOOD_GDAL
namespace flood::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// One layer read back: its CRS's EPSG code, and each feature's fields (as text, "" for null),
// FID and geometry (as WKT, "" for none).
struct Layer {
    bool found = false;
    std::string crsCode;  // "EPSG:4326", "" without a CRS
    std::vector<int64_t> fids;
    std::vector<std::map<std::string, std::string>> fields;
    std::vector<std::string> wkt;
};

Layer readBack(const fs::path& file, const std::string& name = "") {
    Layer out;
    GDALAllRegister();
    GDALDataset* ds = static_cast<GDALDataset*>(
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!ds) return out;
    OGRLayer* l = name.empty() ? ds->GetLayer(0) : ds->GetLayerByName(name.c_str());
    if (l) {
        out.found = true;
        const OGRSpatialReference* s = l->GetSpatialRef();
        // A GeoPackage layer without a CRS has its "Undefined geographic SRS".
        if (s && std::string(s->GetName() ? s->GetName() : "").rfind("Undefined", 0) == 0)
            s = nullptr;
        if (s) {
            OGRSpatialReference copy(*s);
            copy.AutoIdentifyEPSG();
            if (const char* code = copy.GetAuthorityCode(nullptr))
                out.crsCode = "EPSG:" + std::string(code);
            else out.crsCode = "?";
        }
        for (OGRFeature* f; (f = l->GetNextFeature()) != nullptr; OGRFeature::DestroyFeature(f)) {
            std::map<std::string, std::string> fields;
            for (int i = 0; i < f->GetFieldCount(); ++i)
                fields[f->GetFieldDefnRef(i)->GetNameRef()] =
                    f->IsFieldSetAndNotNull(i) ? f->GetFieldAsString(i) : "";
            out.fields.push_back(fields);
            out.fids.push_back(f->GetFID());
            std::string wkt;
            if (const OGRGeometry* g = f->GetGeometryRef()) wkt = g->exportToWkt();
            out.wkt.push_back(wkt);
        }
    }
    GDALClose(ds);
    return out;
}

// In the order of their `finding` field: FlatGeobuf's spatial index orders features by place.
Layer byFinding(Layer l) {
    std::vector<size_t> order(l.fields.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return std::stoll(l.fields[a]["finding"]) < std::stoll(l.fields[b]["finding"]);
    });
    Layer out = l;
    for (size_t i = 0; i < order.size(); ++i) {
        out.fields[i] = l.fields[order[i]];
        out.wkt[i] = l.wkt[order[i]];
        out.fids[i] = l.fids[order[i]];
    }
    return out;
}

// A GeoJSON FeatureCollection: "three", a square with three small bow-tie holes (three
// separate crossings: three findings, two culprit edges each), and "fine", a valid triangle.
void writeThree(const fs::path& file) {
    std::string rings = "[[0,0],[100,0],[100,100],[0,100],[0,0]]";
    for (int i = 0; i < 3; ++i) {
        std::string x = std::to_string(2 + 3 * i), x1 = std::to_string(3 + 3 * i);
        rings += ",[[" + x + ",2],[" + x1 + ",3],[" + x1 + ",2],[" + x + ",3],[" + x + ",2]]";
    }
    std::ofstream(file)
        << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"name":"three","pop":3},"geometry":{"type":"Polygon","coordinates":[)"
        << rings
        << R"(]}},{"type":"Feature","properties":{"name":"fine","pop":1},"geometry":{"type":"Polygon","coordinates":[[[200,0],[210,0],[210,10],[200,0]]]}}]})";
}

class CheckFindings : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = scratch("check-findings");
        writeThree(dir_ / "three.geojson");
        const std::string src = (dir_ / "three.geojson").string();
        // Geographic and projected (US survey feet) inputs; a GeoPackage of two layers.
        for (std::string c :
             {"ogr2ogr -f GPKG -a_srs EPSG:4326 -nln parcels DIR/wgs.gpkg SRC",
              "ogr2ogr -f 'ESRI Shapefile' -a_srs EPSG:2249 DIR/ftus.shp SRC",
              "ogr2ogr -f GPKG -a_srs EPSG:3857 -nln parcels DIR/two.gpkg SRC",
              "ogr2ogr -f GPKG -update -a_srs EPSG:3857 -nln roads DIR/two.gpkg SRC"}) {
            for (size_t at; (at = c.find("DIR")) != std::string::npos;)
                c.replace(at, 3, dir_.string());
            c.replace(c.find("SRC"), 3, src);
            RunResult r = runShell(c + " 2>&1");
            ASSERT_EQ(r.code, 0) << c << "\n" << r.out;
        }
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }
    static std::string path(const std::string& f) { return (dir_ / f).string(); }
    static fs::path dir_;
};
fs::path CheckFindings::dir_;

// Every format by its extension: a point per finding at its exact place, with its fields and
// the input's CRS; the culprit edges as lines, in the GeoPackage's second layer or in the
// file OUT_edges.EXT beside the others.
TEST_F(CheckFindings, EveryFindingIsAPointWithItsFieldsInTheInputCrs) {
    for (const auto& [input, crs] : std::vector<std::pair<std::string, std::string>>{
             {"wgs.gpkg", "EPSG:4326"}, {"ftus.shp", "EPSG:2249"}})
        for (const char* ext : {"gpkg", "geojson", "fgb", "shp"}) {
            SCOPED_TRACE(input + " --findings out." + ext);
            const std::string out = path("out." + std::string(ext));
            RunResult r = runCli("check " + path(input) + " --findings " + out);
            EXPECT_EQ(r.code, 4) << r.out;  // the verdict's code, the findings written
            EXPECT_TRUE(has(
                r.out, "check: wrote 3 findings to " + out +
                           " (layer findings) and 6 culprit edges to " +
                           (std::string(ext) == "gpkg" ? out + " (layer finding_edges)"
                                                       : path("out_edges." + std::string(ext)))))
                << r.out;
            Layer l = byFinding(readBack(out, std::string(ext) == "gpkg" ? "findings" : ""));
            ASSERT_TRUE(l.found);
            EXPECT_EQ(l.crsCode, crs);
            ASSERT_EQ(l.fields.size(), 3u);
            for (size_t i = 0; i < 3; ++i) {
                auto& f = l.fields[i];
                EXPECT_EQ(f["finding"], std::to_string(i + 1));
                EXPECT_EQ(f["file"], path(input));
                EXPECT_EQ(f["layer"], input == "wgs.gpkg" ? "parcels" : "ftus");
                EXPECT_EQ(f["fid"], input == "wgs.gpkg" ? "1" : "0");
                EXPECT_EQ(f["name"], "three");
                EXPECT_EQ(f["status"], "invalid");
                EXPECT_EQ(f["ring"], std::to_string(i + 1));
                EXPECT_EQ(f["vertex"], "0");
                const std::string x = std::to_string(2 + 3 * i), x1 = std::to_string(3 + 3 * i);
                EXPECT_TRUE(has(f["reason"], "(" + x + ", 2)-(" + x1 + ", 3) crosses"))
                    << f["reason"];
                EXPECT_EQ(f["message"].rfind(path(input) + ": ring " + std::to_string(i + 1) +
                                                 " vertex 0 (" + x + ", 2): edge ",
                                             0),
                          0u)
                    << f["message"];
                EXPECT_EQ(l.wkt[i], "POINT (" + std::to_string(2 + 3 * i) + ".5 2.5)");
            }
            const fs::path edgesFile = std::string(ext) == "gpkg"
                                           ? fs::path(out)
                                           : dir_ / ("out_edges." + std::string(ext));
            Layer e =
                byFinding(readBack(edgesFile, std::string(ext) == "gpkg" ? "finding_edges" : ""));
            ASSERT_TRUE(e.found);
            EXPECT_EQ(e.crsCode, crs);
            ASSERT_EQ(e.fields.size(), 6u);
            // Finding 1's two edges: ring 1's edges 0-1 and 2-3, which cross at (2.5, 2.5).
            EXPECT_EQ(e.fields[0]["finding"], "1");
            EXPECT_EQ(e.fields[1]["finding"], "1");
            EXPECT_EQ(e.fields[5]["finding"], "3");
            EXPECT_EQ(e.fields[0]["name"], "three");
            EXPECT_EQ(e.wkt[0], "LINESTRING (2 2,3 3)");
            EXPECT_EQ(e.fields[0]["vertex"], "0");
            EXPECT_EQ(e.wkt[1], "LINESTRING (3 2,2 3)");
            EXPECT_EQ(e.fields[1]["vertex"], "2");
            EXPECT_EQ(e.fields[1]["ring"], "1");
        }
}

// k separate crossings give k findings in the layer, read back with ogrinfo as a user would; a valid input writes the layer empty (an earlier run's findings do not stay).
TEST_F(CheckFindings, KCrossingsAreKPointsAndNoneLeaveTheLayerEmpty) {
    const fs::path in = dir_ / "k.json";
    std::string rings = "[[0,0],[1000,0],[1000,1000],[0,1000]]";
    const int k = 7;
    for (int i = 0; i < k; ++i) {
        std::string x = std::to_string(2 + 3 * i), x1 = std::to_string(3 + 3 * i);
        rings += ",[[" + x + ",2],[" + x1 + ",3],[" + x1 + ",2],[" + x + ",3]]";
    }
    std::ofstream(in) << "[" << rings << "]";
    const std::string out = path("k.gpkg");
    RunResult r = runCli("check " + in.string() + " --findings " + out);
    EXPECT_EQ(r.code, 4) << r.out;
    RunResult info = runShell("ogrinfo -so " + out + " findings 2>&1");
    ASSERT_EQ(info.code, 0) << info.out;
    EXPECT_TRUE(has(info.out, "Feature Count: " + std::to_string(k) + "\n")) << info.out;
    EXPECT_TRUE(has(info.out, "Geometry: Point\n")) << info.out;
    // A ring array has no CRS: the layer has none either (GeoPackage's "undefined").
    EXPECT_EQ(readBack(out, "findings").crsCode, "");
    r = runCli("check " + sourcePath("polygons/hole.json") + " --findings " + out);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(readBack(out, "findings").fields.size(), 0u);
    EXPECT_TRUE(readBack(out, "finding_edges").found);
}

// Failures that are not validation's have one point each where they know a place (a forbidden
// transition's vertex), none where they do not (an unreadable file: a null geometry).
TEST_F(CheckFindings, ForbiddenAndMalformedRowsAreFindingsToo) {
    const std::string out = path("other.geojson");
    RunResult r = runCli("check --no-validate " +
                         sourcePath("polygons/invalid/forbidden-ceiling-as-end.json") + " " +
                         sourcePath("polygons/invalid/malformed-json.json") + " --findings " + out);
    EXPECT_EQ(r.code, 5) << r.out;
    Layer l = readBack(out);
    ASSERT_EQ(l.fields.size(), 2u);
    EXPECT_EQ(l.fields[0]["status"], "forbidden");
    EXPECT_EQ(l.wkt[0], "POINT (2 5)");  // ring 0 vertex 3, the culprit
    EXPECT_EQ(l.fields[0]["vertex"], "3");
    EXPECT_EQ(l.fields[1]["status"], "malformed");
    EXPECT_EQ(l.wkt[1], "");
    EXPECT_TRUE(has(l.fields[1]["reason"], "JSON syntax error")) << l.fields[1]["reason"];
}

// The feature's name is its "name" or, as Natural Earth spells it, "NAME" property.
TEST_F(CheckFindings, ANameOrNAMEPropertyNamesTheFinding) {
    const fs::path in = dir_ / "upper.geojson";
    std::ofstream(in)
        << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"NAME":"Canada"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]}}]})";
    const std::string out = path("upper.geojson-findings.gpkg");
    RunResult r = runCli("check " + in.string() + " --findings " + out);
    EXPECT_EQ(r.code, 4) << r.out;
    Layer l = readBack(out, "findings");
    ASSERT_EQ(l.fields.size(), 1u);
    EXPECT_EQ(l.fields[0]["name"], "Canada");
    EXPECT_EQ(l.fields[0]["fid"], "0");
    EXPECT_EQ(l.crsCode, "EPSG:4326");  // GeoJSON's, as ogrinfo reads the file
}

// Inputs in different CRSs: the layer has none, and the warning names each.
TEST_F(CheckFindings, InputsInDifferentCrssGiveALayerWithoutOneAndSaySo) {
    const std::string out = path("mixed.gpkg");
    RunResult r =
        runCli("check " + path("wgs.gpkg") + " " + path("ftus.shp") + " --findings " + out);
    EXPECT_EQ(r.code, 4) << r.out;
    EXPECT_TRUE(has(r.out, "warning: " + out + ": the inputs have different CRSs (" +
                               path("wgs.gpkg") + " (layer parcels): EPSG:4326, " +
                               path("ftus.shp") +
                               " (layer ftus): EPSG:2249): the layers are written without one"))
        << r.out;
    Layer l = readBack(out, "findings");
    EXPECT_EQ(l.fields.size(), 6u);
    EXPECT_EQ(l.crsCode, "");
}

// An OUT no format writes is a usage error before anything is checked, as `triangulate -o`.
TEST_F(CheckFindings, AnUnknownExtensionIsAUsageError) {
    RunResult r = runCli("check " + path("wgs.gpkg") + " --findings " + path("out.xyz"));
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_EQ(r.out, "error: --findings " + path("out.xyz") +
                         ": no format writes .xyz: it is written through GDAL, in any vector "
                         "format it creates (.geojson, .shp, .gpkg, .fgb, .kml, .csv, ...: "
                         "`ogrinfo --formats`)\n");
    r = runCli("check " + path("wgs.gpkg") + " --findings -");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_TRUE(has(r.out, "--findings needs a file")) << r.out;
    EXPECT_FALSE(fs::exists(path("out.xyz")));
}

// A GeoPackage of two layers is checked layer by layer (it was one "malformed" row saying
// "2 layers: choose one with --layer"); --layer still picks one.
TEST_F(CheckFindings, EveryLayerOfADatasetIsChecked) {
    RunResult r = runCli("check --json " + path("two.gpkg"));
    EXPECT_EQ(r.code, 4) << r.out;
    json doc = json::parse(r.out.substr(0, r.out.rfind('}') + 1));
    ASSERT_EQ(doc["features"].size(), 4u) << doc.dump(1);
    std::vector<std::string> seen;
    for (const json& f : doc["features"])
        seen.push_back(f["layer"].get<std::string>() + " " +
                       std::to_string(f["feature"].get<int>()) + " " +
                       f["verdict"].get<std::string>());
    EXPECT_EQ(seen, (std::vector<std::string>{"parcels 1 invalid", "parcels 2 ok",
                                              "roads 1 invalid", "roads 2 ok"}));
    r = runCli("check " + path("two.gpkg"));
    EXPECT_TRUE(has(r.out, path("two.gpkg") + " (layer roads) ")) << r.out;
    EXPECT_TRUE(has(r.out, path("two.gpkg") + " (layer parcels) ")) << r.out;
    r = runCli("check --json --layer roads " + path("two.gpkg"));
    doc = json::parse(r.out.substr(0, r.out.rfind('}') + 1));
    ASSERT_EQ(doc["features"].size(), 2u);
    EXPECT_EQ(doc["features"][0]["layer"], "roads");
    // Both layers' findings in one findings layer, each saying its layer.
    const std::string out = path("two-findings.gpkg");
    r = runCli("check " + path("two.gpkg") + " --findings " + out);
    Layer l = readBack(out, "findings");
    ASSERT_EQ(l.fields.size(), 6u);
    EXPECT_EQ(l.fields[0]["layer"], "parcels");
    EXPECT_EQ(l.fields[5]["layer"], "roads");
    EXPECT_EQ(l.crsCode, "EPSG:3857");
}

// --extract of a GIS feature keeps it as the feature it was: its fields, its FID and its CRS,
// in its dataset's format (a GeoPackage, a Shapefile: it used to be a bare ring array no GIS
// tool opens), and checked again it fails the same way.
TEST_F(CheckFindings, ExtractKeepsTheFeatureWithItsFieldsAndCrs) {
    const fs::path out = dir_ / "extract";
    for (const auto& [input, crs] : std::vector<std::pair<std::string, std::string>>{
             {"wgs.gpkg", "EPSG:4326"}, {"ftus.shp", "EPSG:2249"}, {"two.gpkg", "EPSG:3857"}}) {
        SCOPED_TRACE(input);
        fs::remove_all(out);
        RunResult r = runCli("check --json --extract " + out.string() + " " + path(input));
        EXPECT_EQ(r.code, 4) << r.out;
        json doc = json::parse(r.out.substr(0, r.out.rfind('}') + 1));
        std::vector<std::string> extracted;
        for (const json& f : doc["features"])
            if (f["extracted"].is_string()) extracted.push_back(f["extracted"]);
        const std::string stem = fs::path(input).stem().string();
        const std::string ext = fs::path(input).extension().string();
        const int64_t fid = ext == ".shp" ? 0 : 1;
        std::vector<std::string> want = {
            (out / (stem + "_feature" + std::to_string(fid) + ext)).string()};
        if (input == "two.gpkg")
            want = {(out / "two_parcels_feature1.gpkg").string(),
                    (out / "two_roads_feature1.gpkg").string()};
        EXPECT_EQ(extracted, want);
        for (const std::string& file : extracted) {
            Layer l = readBack(file);
            ASSERT_TRUE(l.found) << file;
            EXPECT_EQ(l.crsCode, crs);
            ASSERT_EQ(l.fields.size(), 1u);
            EXPECT_EQ(l.fields[0]["name"], "three");
            EXPECT_EQ(l.fields[0]["pop"], "3");
            EXPECT_EQ(l.fids[0], fid);
            RunResult again = runShell("ogrinfo -so -al " + file + " 2>&1");
            EXPECT_EQ(again.code, 0) << again.out;
            json re = json::parse(runCli("check --json " + file).out);
            EXPECT_EQ(re["features"][0]["verdict"], "invalid");
            EXPECT_EQ(re["features"][0]["findings"].size(), 3u);
            EXPECT_EQ(re["features"][0]["reason"], doc["features"][0]["reason"]);
        }
    }
}

}  // namespace
}  // namespace flood::testing
#endif
