// Fault injection for the writers (issue 25), in the spirit of SQLite's: every run of a writer
// whose writes fail after N bytes, as on a full disk, for N across the whole output, must exit 8
// naming OUT, leave no temporary beside it and leave an existing OUT as it was; writes cut
// short without an error must still give the whole output. tests/cli/write_faults.c is the
// LD_PRELOAD library that makes the faults.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "test_support.h"
#ifdef FLOOD_GDAL
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#endif

using namespace flood::testing;
namespace fs = std::filesystem;

namespace {

// flood with the fault library loaded (after a sanitizer's runtime, which must come first:
// tests/CMakeLists.txt) and `env` ("FLOOD_FAULT_BYTES=N ..."); stdout and stderr.
RunResult faulted(const std::string& env, const std::string& args) {
    return runShell("LD_PRELOAD='" FLOOD_WRITE_FAULTS "' " + env + " " + FLOOD_CLI + " " + args +
                    " 2>&1");
}

// The names in `d`, but for the edges `check --findings` writes beside OUT in a format of one
// layer (out_edges.fgb: written first, so OUT stays as it was when either fails).
std::vector<std::string> listing(const fs::path& d) {
    std::vector<std::string> names;
    for (auto& e : fs::directory_iterator(d))
        if (e.path().filename().string().find("_edges.") == std::string::npos)
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Budgets spread over [0, total): the first bytes, a page's edges, every fraction, the last.
std::vector<unsigned long long> budgets(unsigned long long total) {
    std::set<unsigned long long> n = {0, 1, 4096, 4097, total - 2000, total - 1};
    for (int k = 1; k < 10; ++k) n.insert(total * k / 10);
    std::vector<unsigned long long> out;
    for (unsigned long long b : n)
        if (b < total) out.push_back(b);
    return out;
}

#ifdef FLOOD_GDAL
// The feature count of a layer (triangles, findings), or -1 when the file is no dataset with
// that layer.
long long featureCount(const fs::path& file, const std::string& name) {
    GDALAllRegister();
    GDALDataset* ds = static_cast<GDALDataset*>(
        GDALOpenEx(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!ds) return -1;
    OGRLayer* layer = ds->GetLayerByName(name.c_str());
    long long n = -1;
    if (layer) {
        n = 0;
        for (OGRFeature* f; (f = layer->GetNextFeature()) != nullptr; OGRFeature::DestroyFeature(f))
            ++n;
    }
    GDALClose(ds);
    return n;
}
#endif

struct Writer {
    std::string name, format, ext;
    bool existingGeoPackage = false;  // OUT is a GeoPackage of two layers: the update path
    bool findings = false;            // `check --findings OUT` (exit 4: the input's findings)
};

}  // namespace

TEST(WriteFaults, AFullDiskFailsEveryWriterAndKeepsTheOldFile) {
    const fs::path d = scratch("write-faults");
    // Enough triangles for the formats to write in many pieces (pages, buffers).
    const fs::path in = d / "in.json";
    RunResult g = runCli("generate circle-jagged 3000 -o " + in.string());
    ASSERT_EQ(g.code, 0) << g.out;
    std::vector<Writer> writers = {{"json", "json", ".json"}};
#ifdef FLOOD_GDAL
    writers.push_back({"gpkg", "gpkg", ".gpkg"});
    writers.push_back({"fgb", "fgb", ".fgb"});
    writers.push_back({"gpkg into an existing GeoPackage", "gpkg", ".gpkg", true});
    writers.push_back({"check --findings gpkg", "gpkg", ".gpkg", false, true});
    writers.push_back({"check --findings fgb", "fgb", ".fgb", false, true});
    // A face with 400 separate crossings: 400 findings, in many pages.
    {
        std::ofstream crossings(d / "crossings.json");
        crossings << "[[[0,0],[10000,0],[10000,10000],[0,10000]]";
        for (int i = 0; i < 400; ++i)
            crossings << ",[[" << 2 + 3 * i << ",2],[" << 3 + 3 * i << ",3],[" << 3 + 3 * i
                      << ",2],[" << 2 + 3 * i << ",3]]";
        crossings << "]";
    }
#endif
    for (const Writer& w : writers) {
        SCOPED_TRACE(w.name);
        const fs::path dir = d / ("w" + std::to_string(&w - writers.data()));
        fs::create_directories(dir);
        const fs::path out = dir / ("out" + w.ext), report = d / "report";
        const std::string args =
            w.findings
                ? "check " + (d / "crossings.json").string() + " --findings " + out.string()
                : "triangulate " + in.string() + " --format " + w.format + " -o " + out.string();
        const int ok = w.findings ? 4 : 0;  // the exit code of a run whose writing succeeds
        auto makeOld = [&] {
            fs::remove(out);
            if (w.existingGeoPackage) {
                RunResult r =
                    runShell("ogr2ogr -f GPKG " + out.string() + " " +
                             sourcePath("polygons/datasets/mixed.geojson") + " -nln parcels 2>&1");
                ASSERT_EQ(r.code, 0) << r.out;
            } else {
                std::ofstream(out) << "old";
            }
            ASSERT_EQ(chmod(out.c_str(), 0640), 0);
        };
        // Counted without a fault: the bytes the run writes to files, and the good output.
        makeOld();
        fs::remove(report);
        RunResult r = faulted("FLOOD_FAULT_REPORT=" + report.string(), args);
        ASSERT_EQ(r.code, ok) << r.out;
        unsigned long long total = 0;
        std::ifstream(report) >> total;
        ASSERT_GT(total, 20000u) << "the fault library counted no writes";
        const std::string good = slurp(out);
#ifdef FLOOD_GDAL
        const std::string layer = w.findings ? "findings" : "triangles";
        const long long triangles = w.format == "json" ? 0 : featureCount(out, layer);
        ASSERT_NE(triangles, -1);
#endif
        const std::vector<unsigned long long> ns = budgets(total);
        for (size_t i = 0; i < ns.size(); ++i) {
            const unsigned long long n = ns[i];
            SCOPED_TRACE("writes fail after " + std::to_string(n) + " of " + std::to_string(total) +
                         " bytes");
            // OUT there or not, in turn (always there for the update of a GeoPackage)
            const bool existing = w.existingGeoPackage || i % 2 == 0;
            if (existing) makeOld();
            else fs::remove(out);
            const std::string old = existing ? slurp(out) : "";
            struct stat before = {}, after = {};
            if (existing) {
                ASSERT_EQ(stat(out.c_str(), &before), 0);
            }
            r = faulted("FLOOD_FAULT_BYTES=" + std::to_string(n), args);
            EXPECT_EQ(r.code, 8) << r.out;
            // (check --findings fgb: OUT or the edges beside it, out_edges.fgb, written first)
            const std::string named =
                w.findings && w.format == "fgb" && r.out.find("_edges.fgb") != std::string::npos
                    ? (dir / "out_edges.fgb").string()
                    : out.string();
            EXPECT_EQ(r.out.rfind("error: " + named + ": cannot write: ", 0), 0u) << r.out;
            EXPECT_EQ(listing(dir), existing ? std::vector<std::string>{out.filename()}
                                             : std::vector<std::string>{})
                << "a temporary left beside OUT, or OUT made";
            if (!existing) continue;
            EXPECT_TRUE(slurp(out) == old) << "OUT changed";  // (not its bytes printed)
            ASSERT_EQ(stat(out.c_str(), &after), 0);
            EXPECT_EQ(after.st_ino, before.st_ino);
            EXPECT_EQ(after.st_mode, before.st_mode);
        }
        // Writes cut short without an error (from the first byte, and half way): a writer
        // that loops gets the whole output, the same bytes as without a fault.
        for (unsigned long long n : {0ull, total / 2}) {
            SCOPED_TRACE("writes cut short after " + std::to_string(n) + " bytes");
            makeOld();
            r = faulted("FLOOD_FAULT=short FLOOD_FAULT_BYTES=" + std::to_string(n), args);
            EXPECT_EQ(r.code, ok) << r.out;
#ifdef FLOOD_GDAL
            if (w.format != "json") {
                EXPECT_EQ(featureCount(out, layer), triangles);
                continue;
            }
#endif
            EXPECT_TRUE(slurp(out) == good) << "not the output of a run without faults";
        }
    }
    fs::remove_all(d);
}
