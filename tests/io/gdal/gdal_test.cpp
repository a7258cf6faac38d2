// GIS formats through GDAL (core/io/gdal/): fixtures made at test time with ogr2ogr from the
// repo's polygons, so nothing binary is committed. Built only with GDAL (tests/CMakeLists.txt).
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/gdal/gdal_io.h"
#include "test_support.h"

namespace flood::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The sample polygons of the fixture, by name; the last two are invalid.
const std::vector<std::string> kValid = {"hole", "holes", "comb", "two-gorges", "steiner"};
const std::vector<std::string> kInvalid = {"invalid/hole-outside", "invalid/self-intersection"};

std::string shell(const std::string& cmd) {
    RunResult r;
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    std::array<char, 4096> buf;
    for (size_t n; p && (n = fread(buf.data(), 1, buf.size(), p)) > 0;) r.out.append(buf.data(), n);
    int status = p ? pclose(p) : -1;
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd << "\n" << r.out;
    return r.out;
}

class Gdal : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = fs::temp_directory_path() / ("flood-gdal-test-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        // One GeoJSON FeatureCollection: each polygon a Feature named after its file.
        json features = json::array();
        auto add = [&](const std::string& name, const char* kind) {
            std::ifstream in(sourcePath("polygons/" + name + ".json"));
            json rings = json::parse(in);
            for (json& ring : rings) ring.push_back(ring[0]);  // GeoJSON rings are closed
            features.push_back({{"type", "Feature"},
                                {"properties", {{"name", name}, {"kind", kind}}},
                                {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}});
        };
        for (const std::string& n : kValid) add(n, "valid");
        for (const std::string& n : kInvalid) add(n, "invalid");
        std::ofstream(dir_ / "source.geojson")
            << json{{"type", "FeatureCollection"}, {"features", features}}.dump();
        for (const auto& [driver, file] : formats())
            shell("ogr2ogr -f '" + driver + "' " + (dir_ / file).string() + " " +
                  (dir_ / "source.geojson").string());
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }

    static std::vector<std::pair<std::string, std::string>> formats() {
        return {{"ESRI Shapefile", "source.shp"},
                {"GPKG", "source.gpkg"},
                {"FlatGeobuf", "source.fgb"},
                {"GeoJSONSeq", "source.geojsonl"}};
    }
    static std::string path(const std::string& file) { return (dir_ / file).string(); }
    static fs::path dir_;
};
fs::path Gdal::dir_;

// Triangles as sorted corner coordinates: formats may reorder or reorient rings (Shapefile
// stores outer rings clockwise), but the triangles, as point sets, must be the same.
std::vector<std::array<std::pair<double, double>, 3>> geometric(const Polygon& p,
                                                                const std::vector<Triangle>& t) {
    std::vector<std::array<std::pair<double, double>, 3>> out;
    for (const Triangle& tri : t) {
        std::array<std::pair<double, double>, 3> c;
        for (int k = 0; k < 3; ++k) c[k] = {p.vertices[tri[k]].x, p.vertices[tri[k]].y};
        std::sort(c.begin(), c.end());
        out.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
}

gdal::Selection named(const std::string& name) { return {"", -1, "name = '" + name + "'"}; }

TEST_F(Gdal, EveryFormatGivesTheTrianglesOfTheGeoJsonSource) {
    for (const auto& [driver, file] : formats()) {
        for (const std::string& name : kValid) {
            SCOPED_TRACE(driver + " " + name);
            Polygon expected = readOrFail(sourcePath("polygons/" + name + ".json"));
            ReadResult r = gdal::readPolygon(path(file), named(name));
            ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
            ASSERT_TRUE(validate(r.polygon, file).ok());
            EXPECT_EQ(r.polygon.vertices.size(), expected.vertices.size());
            FloodResult got = expectTriangulates(r.polygon, file),
                        want = expectTriangulates(expected, name);
            EXPECT_EQ(geometric(r.polygon, got.triangles), geometric(expected, want.triangles));
        }
    }
}

TEST_F(Gdal, LayerFeatureAndWhereChoose) {
    const std::string two = path("two-layers.gpkg");
    shell("ogr2ogr -f GPKG " + two + " " + path("source.geojson") + " -nln first");
    shell("ogr2ogr -update " + two + " " + path("source.geojson") +
          " -nln second -where \"name = 'comb'\"");
    // Two layers and none chosen: refused, naming both.
    DatasetRead d = gdal::readFeatures(two, {});
    ASSERT_EQ(d.features.size(), 1u);
    EXPECT_EQ(d.features[0].read.diagnostic.status, Status::Malformed);
    EXPECT_NE(d.features[0].read.diagnostic.message.find("--layer (layers: first, second)"),
              std::string::npos)
        << d.features[0].read.diagnostic.message;
    d = gdal::readFeatures(two, {"second", -1, ""});
    ASSERT_EQ(d.features.size(), 1u);
    EXPECT_EQ(d.features[0].name, "comb");
    d = gdal::readFeatures(two, {"nope", -1, ""});
    EXPECT_NE(d.features[0].read.diagnostic.message.find("no layer \"nope\""), std::string::npos);
    // GeoPackage FIDs count from 1: FID 2 is the second feature, "holes".
    d = gdal::readFeatures(two, {"first", 2, ""});
    ASSERT_EQ(d.features.size(), 1u);
    EXPECT_EQ(d.features[0].id, "2");
    EXPECT_EQ(d.features[0].name, "holes");
    d = gdal::readFeatures(two, {"first", -1, "name LIKE 'invalid/%'"});
    ASSERT_EQ(d.features.size(), 2u);
    EXPECT_EQ(d.features[1].name, "invalid/self-intersection");
    d = gdal::readFeatures(two, {"first", 2, "name = 'comb'"});  // both must hold
    EXPECT_EQ(d.features[0].read.diagnostic.status, Status::Malformed);
    EXPECT_NE(d.features[0].read.diagnostic.message.find("no polygon found"), std::string::npos);
    RunResult missing = runCli("check " + path("absent.gpkg"));
    EXPECT_EQ(missing.code, 3);
    EXPECT_NE(missing.out.find("cannot open file: No such file or directory"), std::string::npos)
        << missing.out;
    // Through the command line: the feature chosen is the one triangulated.
    RunResult r = runCli("verify " + two + " --layer first --where \"name = 'comb'\"");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("verify: ok: 18 vertices in 1 rings"), std::string::npos) << r.out;
}

TEST_F(Gdal, CheckReportsVerdictsWithFidsAndNames) {
    RunResult r = runCli("check --json " + path("source.gpkg") + " 2>/dev/null");
    EXPECT_EQ(r.code, 4) << r.out;
    json doc = json::parse(r.out);
    const json& rows = doc["features"];
    ASSERT_EQ(rows.size(), kValid.size() + kInvalid.size());
    for (size_t k = 0; k < rows.size(); ++k) {
        bool valid = k < kValid.size();
        const std::string& name = valid ? kValid[k] : kInvalid[k - kValid.size()];
        EXPECT_EQ(rows[k]["id"], std::to_string(k + 1)) << rows[k];  // GeoPackage FIDs
        EXPECT_EQ(rows[k]["name"], name);
        EXPECT_EQ(rows[k]["feature"], k);
        EXPECT_EQ(rows[k]["verdict"], valid ? "ok" : "invalid") << rows[k];
        // Every field of the feature is reported with it.
        EXPECT_EQ(rows[k]["attributes"]["name"], name) << rows[k];
        EXPECT_EQ(rows[k]["attributes"]["kind"], valid ? "valid" : "invalid") << rows[k];
    }
    EXPECT_EQ(rows[kValid.size()]["reason"],
              "hole (ring 1) lies outside its outer ring (ring 0) (global vertex 4)");
    // The table's ID/NAME column carries the FID.
    r = runCli("check " + path("source.gpkg") + " --where \"name = 'invalid/hole-outside'\"");
    EXPECT_EQ(r.code, 4);
    EXPECT_NE(r.out.find("source.gpkg  0        6        8         invalid"), std::string::npos)
        << r.out;
}

// A curve is linearised by OGR; a point feature is skipped with a warning, as GeoJSON's are.
TEST_F(Gdal, CurvesAreLinearisedAndOtherGeometriesSkipped) {
    GDALAllRegister();
    const std::string file = path("curves.gpkg");
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
    GDALDataset* ds = driver->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    ASSERT_NE(ds, nullptr);
    OGRLayer* layer = ds->CreateLayer("shapes", nullptr, wkbUnknown, nullptr);
    for (const char* wkt :
         {"CURVEPOLYGON(CIRCULARSTRING(0 0,10 10,20 0,10 -10,0 0))", "POINT(1 2)"}) {
        OGRGeometry* g = nullptr;
        ASSERT_EQ(OGRGeometryFactory::createFromWkt(wkt, nullptr, &g), OGRERR_NONE);
        OGRFeature* f = OGRFeature::CreateFeature(layer->GetLayerDefn());
        f->SetGeometryDirectly(g);
        ASSERT_EQ(layer->CreateFeature(f), OGRERR_NONE);
        OGRFeature::DestroyFeature(f);
    }
    GDALClose(ds);
    DatasetRead d = gdal::readFeatures(file, {});
    ASSERT_EQ(d.features.size(), 1u);
    ASSERT_TRUE(d.features[0].read.diagnostic.ok()) << d.features[0].read.diagnostic.message;
    Polygon& p = d.features[0].read.polygon;
    EXPECT_GT(p.vertices.size(), 16u);  // the circle as many segments
    EXPECT_TRUE(validate(p, file).ok());
    expectTriangulates(p, file);
    ASSERT_EQ(d.skipped.size(), 1u);
    EXPECT_EQ(d.skipped[0], file + ": feature 2: not polygonal (Point), skipped");
}

// A folder's GIS datasets are found with its GeoJSON: every .fgb, .shp, ... is a file checked.
TEST_F(Gdal, CheckFindsGisFilesInFolders) {
    const std::string folder = path("folder");
    fs::create_directories(folder + "/deeper");
    shell("ogr2ogr -f FlatGeobuf " + folder + "/a.fgb " + path("source.geojson"));
    shell("ogr2ogr -f 'ESRI Shapefile' " + folder + "/deeper/b.shp " + path("source.geojson"));
    RunResult r = runCli("check --json " + folder + " 2>/dev/null");
    EXPECT_EQ(r.code, 4) << r.out;
    json s = json::parse(r.out)["summary"];
    EXPECT_EQ(s["files"], 2);  // the Shapefile's .dbf, .shx, .prj are not datasets of their own
    EXPECT_EQ(s["features"], 2 * (kValid.size() + kInvalid.size()));
    // A Shapefile keeps no hole-to-outer link: OGR reassembles rings by containment, so the
    // hole outside its outer ring comes back as a second part, and that feature is valid.
    EXPECT_EQ(s["verdicts"]["invalid"], 2 * kInvalid.size() - 1);
}

double ringArea(const std::vector<Point>& v) {
    double a = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        const Point& p = v[i];
        const Point& q = v[(i + 1) % v.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a / 2;
}

TEST_F(Gdal, TrianglesWrittenAsGeoPackageAndFlatGeobufReadBack) {
    GDALAllRegister();
    for (const std::string& name : kValid) {
        Polygon p = readOrFail(sourcePath("polygons/" + name + ".json"));
        double area = 0;  // outer rings minus holes (integer coordinates: exact in doubles)
        for (const Part& part : p.parts)
            for (Index k = part.firstRing; k < part.firstRing + part.ringCount; ++k) {
                const Ring& ring = p.rings[k];
                area += std::abs(ringArea({p.vertices.begin() + ring.first,
                                           p.vertices.begin() + ring.first + ring.count})) *
                        (k == part.firstRing ? 1 : -1);
            }
        for (const std::string ext : {"gpkg", "fgb"}) {
            SCOPED_TRACE(name + "." + ext);
            const std::string out = path(name + "-triangles." + ext);
            RunResult r =
                runCli("triangulate " + sourcePath("polygons/" + name + ".json") + " -o " + out);
            ASSERT_EQ(r.code, 0) << r.out;
            GDALDataset* ds = static_cast<GDALDataset*>(
                GDALOpenEx(out.c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
            ASSERT_NE(ds, nullptr);
            OGRLayer* layer = ds->GetLayerByName("triangles");
            ASSERT_NE(layer, nullptr);
            EXPECT_EQ(size_t(layer->GetFeatureCount()), p.expectedTriangles());
            double sum = 0;
            for (OGRFeature* f; (f = layer->GetNextFeature()) != nullptr;
                 OGRFeature::DestroyFeature(f))
                sum += f->GetGeometryRef()->toPolygon()->get_Area();
            GDALClose(ds);
            EXPECT_EQ(sum, area);
        }
    }
    // A folder that does not exist: exit 8, the reason on one line, nothing left behind.
    for (const std::string ext : {"gpkg", "fgb"}) {
        RunResult r = runCli("triangulate " + sourcePath("polygons/hole.json") + " -o " +
                             path("missing/t." + ext));
        EXPECT_EQ(r.code, 8) << r.out;
        EXPECT_EQ(r.out.rfind("error: " + path("missing/t." + ext) + ": cannot write: ", 0), 0u)
            << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    }
    EXPECT_FALSE(fs::exists(path("missing")));
    // ogrinfo, as a user would look: the layer and its count.
    std::string info = shell("ogrinfo -so " + path("comb-triangles.gpkg") + " triangles");
    EXPECT_NE(info.find("Feature Count: 16"), std::string::npos) << info;
}

// GDAL is a module loaded on first use (core/io/gdal/gdal_module.h): the command is not linked to
// it, so a run that reads no GIS dataset never loads its ~110 libraries.
TEST_F(Gdal, TheCommandLoadsGdalOnlyForGisDatasets) {
    RunResult ldd = runShell(std::string("ldd ") + FLOOD_CLI + " 2>&1");
    ASSERT_EQ(ldd.code, 0) << ldd.out;
    EXPECT_EQ(ldd.out.find("libgdal"), std::string::npos) << ldd.out;
    RunResult r = runCli("triangulate " + path("source.gpkg") + " --feature 1 -o " +
                         path("module-loaded.json"));
    EXPECT_EQ(r.code, 0) << r.out;
}

// A module that cannot be loaded: one message naming the dataset and where it was looked for,
// the exit code of an unreadable file; Flood's own formats are unaffected.
TEST_F(Gdal, AMissingModuleIsNamedNotACrash) {
    const std::string env = "FLOOD_GDAL_MODULE=" + path("no-such-module.so") + " ";
    RunResult r = runShell(env + FLOOD_CLI + " triangulate " + path("source.gpkg") + " -o " +
                           path("never.json") + " 2>&1");
    EXPECT_EQ(r.code, int(Status::Malformed)) << r.out;
    EXPECT_NE(r.out.find(path("source.gpkg") + ": GIS datasets need Flood's GDAL module"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("no-such-module.so"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(path("never.json")));
    RunResult own = runShell(env + FLOOD_CLI + " triangulate " + sourcePath("polygons/hole.json") +
                             " -o " + path("own.json") + " 2>&1");
    EXPECT_EQ(own.code, 0) << own.out;
}

}  // namespace
}  // namespace flood::testing
