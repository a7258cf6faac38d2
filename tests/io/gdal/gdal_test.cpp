// GIS formats through GDAL (core/io/gdal/): fixtures made at test time with ogr2ogr from the
// repo's polygons, so nothing binary is committed. Built only with GDAL (tests/CMakeLists.txt).
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "flood/io/gdal/gdal_io.h"
#include "flood/tools/generate.h"
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

// A GeoPackage at `file` with one layer "shapes" holding a feature per WKT geometry.
void writeShapes(const std::string& file, const std::vector<std::string>& wkts) {
    GDALAllRegister();
    GDALDriver* gpkg = GetGDALDriverManager()->GetDriverByName("GPKG");
    GDALDataset* ds = gpkg->Create(file.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    ASSERT_NE(ds, nullptr);
    OGRLayer* layer = ds->CreateLayer("shapes", nullptr, wkbUnknown, nullptr);
    for (const std::string& wkt : wkts) {
        OGRGeometry* g = nullptr;
        ASSERT_EQ(OGRGeometryFactory::createFromWkt(wkt.c_str(), nullptr, &g), OGRERR_NONE) << wkt;
        OGRFeature* f = OGRFeature::CreateFeature(layer->GetLayerDefn());
        f->SetGeometryDirectly(g);
        ASSERT_EQ(layer->CreateFeature(f), OGRERR_NONE);
        OGRFeature::DestroyFeature(f);
    }
    GDALClose(ds);
}

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
        EXPECT_EQ(rows[k]["feature"], k + 1);  // the FID, what --feature takes
        EXPECT_EQ(rows[k]["verdict"], valid ? "ok" : "invalid") << rows[k];
        // Every field of the feature is reported with it.
        EXPECT_EQ(rows[k]["attributes"]["name"], name) << rows[k];
        EXPECT_EQ(rows[k]["attributes"]["kind"], valid ? "valid" : "invalid") << rows[k];
    }
    EXPECT_EQ(rows[kValid.size()]["reason"],
              "hole (ring 1) lies outside its outer ring (ring 0) (global vertex 4)");
    // The FEATURE column is the FID with --where too (it was renumbered from 0), the one
    // --feature opens.
    r = runCli("check " + path("source.gpkg") + " --where \"name = 'invalid/hole-outside'\"");
    EXPECT_EQ(r.code, 4);
    EXPECT_NE(r.out.find("source.gpkg  6        6        8         invalid"), std::string::npos)
        << r.out;
    r = runCli("check " + path("source.gpkg") + " --feature 6");
    EXPECT_NE(r.out.find("source.gpkg  6        6        8         invalid"), std::string::npos)
        << r.out;
    // A GeoJSON read by Flood's reader and through GDAL (--where) numbers its features alike.
    r = runCli("check " + path("source.geojson") + " --where \"name = 'invalid/hole-outside'\"");
    EXPECT_NE(r.out.find("source.geojson  5  "), std::string::npos) << r.out;
    r = runCli("check " + path("source.geojson"));
    EXPECT_NE(r.out.find("source.geojson  5  "), std::string::npos) << r.out;
}

// A curve is linearised by OGR; a point feature is skipped with a warning, as GeoJSON's are.
TEST_F(Gdal, CurvesAreLinearisedAndOtherGeometriesSkipped) {
    const std::string file = path("curves.gpkg");
    writeShapes(file, {"CURVEPOLYGON(CIRCULARSTRING(0 0,10 10,20 0,10 -10,0 0))", "POINT(1 2)"});
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

namespace flood::testing {
namespace {

// True when a read of a dataset of `total` features reports every one ok, or a failure: what
// must never happen is fewer features, all ok (a corrupt file passing as good).
::testing::AssertionResult nothingLostSilently(const DatasetRead& d, size_t total) {
    size_t ok = 0;
    bool failed = false;
    for (const FeatureRead& f : d.features) {
        if (f.read.diagnostic.ok()) ++ok;
        else failed = true;
    }
    if (failed || ok == total) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << ok << " of " << total << " features read, all ok";
}

// A .shp cut to 250 bytes passed `check` as "1 feature ... 1 ok" and `triangulate` used 1 of
// its features; a GeoPackage with a cut geometry blob was "2 ok": GDAL said `Error in fread()`
// and the feature came back without a geometry, skipped as "not polygonal (null)". An
// unreadable feature is a failure (a row in check, exit 3), never a skip.
TEST_F(Gdal, CorruptOrTruncatedDatasetsFailNotSkip) {
    const size_t total = kValid.size() + kInvalid.size();
    // The Shapefile: its .shp cut inside the second shape, its .shx (the index: after a
    // 100-byte header, each shape's offset in 16-bit words, big-endian) and .dbf intact.
    for (const char* ext : {".shx", ".dbf", ".prj"})
        fs::copy_file(path(std::string("source") + ext), path(std::string("cut") + ext));
    fs::copy_file(path("source.shp"), path("cut.shp"));
    const std::string shx = slurp(path("source.shx"));
    ASSERT_GT(shx.size(), 116u);
    size_t second = 0;
    for (int k = 108; k < 112; ++k) second = second * 256 + static_cast<unsigned char>(shx[k]);
    fs::resize_file(path("cut.shp"), second * 2 + 20);
    RunResult r = runCli("check --json " + path("cut.shp") + " 2>/dev/null");
    EXPECT_EQ(r.code, 3) << r.out;
    json doc = json::parse(r.out);
    EXPECT_EQ(doc["summary"]["features"], total) << r.out;
    EXPECT_EQ(doc["summary"]["verdicts"]["malformed"], total - 1) << r.out;
    EXPECT_EQ(doc["features"][1]["verdict"], "malformed");
    EXPECT_EQ(doc["features"][1]["id"], "1");
    EXPECT_NE(doc["features"][1]["reason"].get<std::string>().find(
                  "feature 1: unreadable: Error in fread()"),
              std::string::npos)
        << doc["features"][1];
    r = runCli("triangulate " + path("cut.shp") + " -o " + path("cut.json"));
    EXPECT_EQ(r.code, 3) << r.out;
    EXPECT_NE(r.out.find("error: " + path("cut.shp") + ": feature 1: unreadable: "),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(path("cut.json")));

    // The GeoPackage: one geometry blob cut short, in place (SQL through GDAL).
    fs::copy_file(path("source.gpkg"), path("blob.gpkg"));
    shell("ogrinfo " + path("blob.gpkg") +
          " -sql \"UPDATE source SET geom = substr(geom, 1, length(geom) - 30) WHERE fid = 2\"");
    DatasetRead d = gdal::readFeatures(path("blob.gpkg"), {});
    ASSERT_EQ(d.features.size(), total);
    EXPECT_EQ(d.features[1].read.diagnostic.status, Status::Malformed);
    EXPECT_EQ(d.features[1].read.diagnostic.message,
              path("blob.gpkg") +
                  ": feature 2: unreadable: Length of input WKB is too small; Unable to read "
                  "geometry");
    EXPECT_TRUE(d.skipped.empty());
    r = runCli("check " + path("blob.gpkg") + " --where \"name = 'holes'\"");
    EXPECT_EQ(r.code, 3) << r.out;

    // FlatGeobuf cut after its first feature: reading stops with an error.
    const std::string fgb = slurp(path("source.fgb"));
    std::ofstream(path("cut.fgb"), std::ios::binary) << fgb.substr(0, fgb.size() * 2 / 3);
    d = gdal::readFeatures(path("cut.fgb"), {});
    ASSERT_FALSE(d.features.empty());
    EXPECT_EQ(d.features.back().read.diagnostic.status, Status::Malformed);
    EXPECT_NE(d.features.back().read.diagnostic.message.find(": reading stopped after "),
              std::string::npos)
        << d.features.back().read.diagnostic.message;

    // No false alarm: a Shapefile record marked deleted in the .dbf (its first byte '*', as
    // editors leave it until a repack) is not read, and that is no corruption.
    for (const char* ext : {".shp", ".shx", ".prj"})
        fs::copy_file(path(std::string("source") + ext), path(std::string("deleted") + ext));
    std::string dbf = slurp(path("source.dbf"));
    const size_t header = size_t(static_cast<unsigned char>(dbf[8])) |
                          size_t(static_cast<unsigned char>(dbf[9])) << 8,
                 record = size_t(static_cast<unsigned char>(dbf[10])) |
                          size_t(static_cast<unsigned char>(dbf[11])) << 8;
    dbf[header + record] = '*';  // the second record
    std::ofstream(path("deleted.dbf"), std::ios::binary) << dbf;
    d = gdal::readFeatures(path("deleted.shp"), {});
    ASSERT_EQ(d.features.size(), total - 1);
    for (const FeatureRead& f : d.features)
        EXPECT_TRUE(f.read.diagnostic.ok()) << f.read.diagnostic.message;
}

// Every length each fixture can be cut to, and bytes flipped through it: the read never
// crashes and never loses a feature silently.
TEST_F(Gdal, CutAndFlippedFixturesNeverLoseAFeatureSilently) {
    const size_t total = kValid.size() + kInvalid.size();
    for (const char* ext : {".shx", ".dbf", ".prj"})
        fs::copy_file(path(std::string("source") + ext), path(std::string("mangled") + ext));
    for (const char* ext : {".shp", ".fgb", ".gpkg"}) {
        const std::string original = slurp(path(std::string("source") + ext));
        const std::string file = path(std::string("mangled") + ext);
        const size_t step = std::max<size_t>(1, original.size() / 40);
        for (size_t n = 0; n < original.size(); n += step) {
            SCOPED_TRACE(std::string(ext) + " cut to " + std::to_string(n));
            std::ofstream(file, std::ios::binary | std::ios::trunc) << original.substr(0, n);
            EXPECT_TRUE(nothingLostSilently(gdal::readFeatures(file, {}), total));
        }
        for (size_t n = 0; n < original.size(); n += step) {
            SCOPED_TRACE(std::string(ext) + " byte " + std::to_string(n) + " flipped");
            std::string bytes = original;
            bytes[n] = char(~bytes[n]);
            std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
            gdal::readFeatures(file, {});  // a crash fails the test; a verdict may be anything
        }
    }
}

}  // namespace
}  // namespace flood::testing

namespace flood::testing {
namespace {

// Flood's GeoJSON reader numbers features as GDAL's GeoJSON driver does (FeatureRead::fid), so
// `flood check x.geojson` and `flood check x.geojson --where ...` (read through GDAL), --feature
// and the viewer name a feature alike: by its integer "id" when every feature has a distinct
// one, else by its position, non-polygonal features counted.
TEST(GeoJsonFids, FloodsReaderNumbersFeaturesAsGdalDoes) {
    const std::string tri =
        R"("geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1],[0,0]]]})";
    const std::string point = R"("geometry":{"type":"Point","coordinates":[0,0]})";
    const std::vector<std::vector<std::string>> collections = {
        {R"("id":5,)" + tri, R"("id":2,)" + tri},           // ids: the FIDs
        {R"("id":"x",)" + tri, tri},                        // a string id: positions
        {point, R"("id":"3",)" + tri, R"("id":7,)" + tri},  // positions, the point too
        {R"("id":5,)" + tri, tri, R"("id":-3,)" + tri},     // one missing: positions
    };
    const fs::path d = scratch("geojson-fids");
    for (size_t k = 0; k < collections.size(); ++k) {
        SCOPED_TRACE(k);
        std::string text = R"({"type":"FeatureCollection","features":[)";
        for (size_t i = 0; i < collections[k].size(); ++i)
            text += (i ? ",{" : "{") + std::string(R"("type":"Feature","properties":{},)") +
                    collections[k][i] + "}";
        const std::string file = (d / ("c" + std::to_string(k) + ".geojson")).string();
        std::ofstream(file) << text << "]}";
        std::vector<int64_t> ours, gdals;
        for (const FeatureRead& f : readFeaturesFile(file, kDefaultMaxInputBytes, false).features)
            ours.push_back(f.fid);
        // A filter that keeps every feature sends the file to GDAL.
        for (const FeatureRead& f : gdal::readFeatures(file, {"", -1, "1 = 1"}).features)
            gdals.push_back(f.fid);
        EXPECT_EQ(ours, gdals);
        EXPECT_FALSE(ours.empty());
    }
    fs::remove_all(d);
}

// A layer whose second feature comes with a GDAL error that has no message, and whose
// attribute filter fails without one: what a driver may do (issue 25 item 11).
class SilentLayer : public OGRLayer {
public:
    SilentLayer() : defn_(new OGRFeatureDefn("silent")) {
        defn_->Reference();
        defn_->SetGeomType(wkbPolygon);
    }
    ~SilentLayer() override { defn_->Release(); }
    void ResetReading() override { next_ = 0; }
    OGRFeature* GetNextFeature() override {
        if (next_ == 2) return nullptr;
        auto* f = new OGRFeature(defn_);
        f->SetFID(next_++);
        if (next_ == 2) {
            CPLError(CE_Failure, CPLE_FileIO, "%s", "");
        } else {
            OGRGeometry* g = nullptr;
            OGRGeometryFactory::createFromWkt("POLYGON((0 0,1 0,0 1,0 0))", nullptr, &g);
            f->SetGeometryDirectly(g);
        }
        return f;
    }
    OGRErr SetAttributeFilter(const char*) override { return OGRERR_FAILURE; }
    OGRFeatureDefn* GetLayerDefn() override { return defn_; }
    int TestCapability(const char*) override { return FALSE; }

private:
    OGRFeatureDefn* defn_;
    int next_ = 0;
};

class SilentDataset : public GDALDataset {
public:
    int GetLayerCount() override { return 1; }
    OGRLayer* GetLayer(int k) override { return k == 0 ? &layer_ : nullptr; }

private:
    SilentLayer layer_;
};

// GDAL's own words where it has some; where it has none, what failed is named, never "unknown
// GDAL error"; "0 layers: choose one with --layer" and "no polygon found (Polygon)" for POLYGON
// EMPTY said nothing of what was wrong.
TEST_F(Gdal, MessagesSayWhatIsWrong) {
    GDALAllRegister();
    auto message = [](const std::string& file, const gdal::Selection& s = {}) {
        DatasetRead d = gdal::readFeatures(file, s);
        EXPECT_EQ(d.features.size(), 1u) << file;
        return d.features.empty() ? std::string() : d.features[0].read.diagnostic.message;
    };
    { std::ofstream(path("notes.txt")) << "hello\n"; }
    EXPECT_EQ(message(path("notes.txt")),
              path("notes.txt") +
                  ": not a vector dataset GDAL can open: no GDAL driver "
                  "recognises it");
    // A GeoPackage without tables (GDAL opens it as no vector dataset), a KML without any.
    GDALDriver* gpkg = GetGDALDriverManager()->GetDriverByName("GPKG");
    GDALClose(gpkg->Create(path("empty.gpkg").c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    EXPECT_EQ(
        message(path("empty.gpkg")),
        path("empty.gpkg") + ": the dataset has no layers (GDAL's GeoPackage driver finds none)");
    std::ofstream(path("empty.kml"))
        << "<?xml version=\"1.0\"?><kml xmlns=\"http://www.opengis.net/kml/2.2\">"
           "<Document></Document></kml>";
    EXPECT_EQ(message(path("empty.kml")), path("empty.kml") + ": the dataset has no layers");
    EXPECT_EQ(message(path("empty.kml"), {"parcels", -1, ""}),
              path("empty.kml") + ": no layer \"parcels\" (the dataset has no layers)");

    // Empty polygons and collections holding other things: the feature and what it holds.
    const std::string file = path("empties.gpkg");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"POLYGON EMPTY", "feature 1: POLYGON EMPTY has no rings"},
        {"MULTIPOLYGON EMPTY", "feature 2: MULTIPOLYGON EMPTY has no rings"},
        {"GEOMETRYCOLLECTION(POLYGON EMPTY)", "feature 3: GEOMETRYCOLLECTION EMPTY has no rings"},
        {"GEOMETRYCOLLECTION(POLYGON((0 0,1 0,0 1,0 0)),POINT(1 2))",
         "feature 4: the GEOMETRYCOLLECTION holds a POINT: only polygons are triangulated"},
        {"TIN(((0 0,1 0,0 1,0 0)))",
         "feature 5: a TIN is not read: only POLYGON, MULTIPOLYGON and collections of them are "
         "triangulated"},
    };
    std::vector<std::string> wkts;
    for (const auto& c : cases) wkts.push_back(c.first);
    writeShapes(file, wkts);
    DatasetRead d = gdal::readFeatures(file, {});
    ASSERT_EQ(d.features.size(), cases.size());
    for (size_t k = 0; k < cases.size(); ++k) {
        EXPECT_EQ(d.features[k].read.diagnostic.status, Status::Malformed) << cases[k].first;
        EXPECT_EQ(d.features[k].read.diagnostic.message, file + ": " + cases[k].second);
    }
    RunResult r = runCli("triangulate " + file + " --feature 1 -o " + path("never.json"));
    EXPECT_EQ(r.code, 3) << r.out;
    EXPECT_EQ(r.out, "error: " + file + ": " + cases[0].second + "\n");

    // A driver's failure without a message: its class and number.
    auto* silent = new GDALDriver();
    silent->SetDescription("FloodTestSilent");
    silent->SetMetadataItem(GDAL_DCAP_VECTOR, "YES");
    silent->pfnOpen = [](GDALOpenInfo* info) -> GDALDataset* {
        const std::string name = info->pszFilename;
        return name.size() > 7 && name.substr(name.size() - 7) == ".silent" ? new SilentDataset
                                                                            : nullptr;
    };
    GetGDALDriverManager()->RegisterDriver(silent);
    { std::ofstream(path("x.silent")) << "x"; }
    d = gdal::readFeatures(path("x.silent"), {});
    ASSERT_EQ(d.features.size(), 2u);
    EXPECT_TRUE(d.features[0].read.diagnostic.ok()) << d.features[0].read.diagnostic.message;
    EXPECT_EQ(d.features[1].read.diagnostic.message,
              path("x.silent") +
                  ": feature 1: unreadable: GDAL reported a failure without a "
                  "message (CPLE_FileIO, error number 3)");
    EXPECT_EQ(message(path("x.silent"), {"", -1, "a = 1"}),
              path("x.silent") +
                  ": layer silent: --where 'a = 1' is not a valid attribute "
                  "filter: GDAL's SetAttributeFilter failed without a message");
    GetGDALDriverManager()->DeregisterDriver(silent);
    delete silent;
}

}  // namespace
}  // namespace flood::testing

namespace flood::testing {
namespace {

// GDAL's GeoJSON driver refuses an object over OGR_GEOJSON_MAX_OBJ_SIZE MB (200 unless set)
// with "Failed to read GeoJSON data" alone. Flood lifts that limit unless the user set it
// (--max-input-bytes is its own); a limit the user set is named when it is what refused the file.
TEST_F(Gdal, AGeoJsonOverTheUsersSizeLimitIsNamed) {
    const Polygon islands = generate("islands", 1, 100000);
    json multi = json::array();
    for (const Part& part : islands.parts) {
        json rings = json::array();
        for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
            json ring = json::array();
            const Ring& g = islands.rings[r];
            for (Index v = g.first; v <= g.first + g.count; ++v) {  // closed
                const Point p = islands.vertices[v == g.first + g.count ? g.first : v];
                ring.push_back({p.x, p.y});
            }
            rings.push_back(ring);
        }
        multi.push_back(rings);
    }
    const json collection = {
        {"type", "FeatureCollection"},
        {"features",
         {{{"type", "Feature"},
           {"properties", {{"name", "big"}}},
           {"geometry", {{"type", "MultiPolygon"}, {"coordinates", multi}}}}}}};
    const std::string file = path("big.geojson");
    { std::ofstream(file) << collection.dump(); }
    ASSERT_GT(fs::file_size(file), 1u << 20);
    const std::string kept = CPLGetConfigOption("OGR_GEOJSON_MAX_OBJ_SIZE", "");
    CPLSetConfigOption("OGR_GEOJSON_MAX_OBJ_SIZE", "1");
    DatasetRead refused = gdal::readFeatures(file, named("big"));
    ASSERT_EQ(refused.features.size(), 1u);
    EXPECT_EQ(refused.features[0].read.diagnostic.status, Status::Malformed);
    EXPECT_NE(refused.features[0].read.diagnostic.message.find(
                  "over OGR_GEOJSON_MAX_OBJ_SIZE=1, the most GDAL's GeoJSON driver reads"),
              std::string::npos)
        << refused.features[0].read.diagnostic.message;
    CPLSetConfigOption("OGR_GEOJSON_MAX_OBJ_SIZE", "0");  // what Flood sets when it is unset
    DatasetRead read = gdal::readFeatures(file, named("big"));
    ASSERT_EQ(read.features.size(), 1u);
    EXPECT_TRUE(read.features[0].read.diagnostic.ok()) << read.features[0].read.diagnostic.message;
    EXPECT_EQ(read.features[0].read.polygon.vertices.size(), islands.vertices.size());
    CPLSetConfigOption("OGR_GEOJSON_MAX_OBJ_SIZE", kept.empty() ? nullptr : kept.c_str());
    // From the command line, the user's setting is kept and named; unset, the file is read.
    const std::string where = " --where \"name = 'big'\" " + file + " -o " + path("big.json");
    RunResult capped = runShell("OGR_GEOJSON_MAX_OBJ_SIZE=1 " + std::string(FLOOD_CLI) +
                                " triangulate" + where + " 2>&1");
    EXPECT_EQ(capped.code, 3) << capped.out;
    EXPECT_NE(capped.out.find("OGR_GEOJSON_MAX_OBJ_SIZE=1"), std::string::npos) << capped.out;
    RunResult plain = runShell("env -u OGR_GEOJSON_MAX_OBJ_SIZE " + std::string(FLOOD_CLI) +
                               " triangulate" + where + " 2>&1");
    EXPECT_EQ(plain.code, 0) << plain.out;
}

}  // namespace
}  // namespace flood::testing
