// `flood check` through the built binary: verdict counts and exit codes on a FeatureCollection
// mixing valid and invalid features (polygons/datasets/mixed.geojson), the same output for
// any -j, folders, unreadable files among good ones, the sample folders checked against
// `flood triangulate` run on each file, the help, GeoJSON sequences on stdin. --extract:
// check_extract_test.cpp; what a row says: check_rows_test.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "check_run.h"
#include "test_support.h"

using namespace flood::testing;
using nlohmann::json;
namespace fs = std::filesystem;

TEST(Check, CountsPerVerdictInTheTableAndTheJson) {
    CheckRun t = cli("check " + kMixed);
    EXPECT_EQ(t.code, 4) << t.out << t.err;  // worst: invalid (no feature got further and failed)
    EXPECT_TRUE(has(t.out,
                    "check: 9 features in 1 file: 4 ok, 2 malformed, 3 invalid, "
                    "0 forbidden, 0 checker, 0 internal; "))
        << t.out;
    EXPECT_TRUE(has(t.err, "feature 6: not polygonal (LineString), skipped")) << t.err;

    int code = -1;
    json doc = checkJson(kMixed, &code);
    EXPECT_EQ(code, 4);
    const json& s = doc["summary"];
    EXPECT_EQ(s["features"], 9);
    EXPECT_EQ(s["files"], 1);
    EXPECT_EQ(s["code"], 4);
    EXPECT_EQ(s["verdicts"], json::parse(R"({"ok": 4, "malformed": 2, "invalid": 3, "forbidden": 0,
                                             "checker": 0, "internal": 0})"));
    // Feature index -> verdict, id, name: the LineString (6) has no row.
    struct Expect {
        int feature;
        const char* verdict;
        int code;
        json id, name;
        const char* at;
    } expect[] = {
        {0, "ok", 0, "square-with-hole", nullptr, nullptr},
        {1, "invalid", 4, nullptr, "bow-tie", "ring 0 vertex 0 (0, 0)"},
        {2, "ok", 0, "7", "two islands", nullptr},
        {3, "invalid", 4, nullptr, "hole outside", "ring 1 vertex 0 (20, 20)"},
        {4, "invalid", 4, nullptr, "overlapping parts", "ring 0 vertex 1 (10, 0) (part 0)"},
        {5, "malformed", 3, nullptr, "broken coordinates", nullptr},
        {7, "ok", 0, nullptr, "two holes", nullptr},
        {8, "ok", 0, "triangle", "shadowed by its id", nullptr},
        {9, "malformed", 3, nullptr, "no geometry", nullptr},
    };
    const json& rows = doc["features"];
    ASSERT_EQ(rows.size(), std::size(expect));
    for (size_t k = 0; k < rows.size(); ++k) {
        const json& r = rows[k];
        const Expect& e = expect[k];
        EXPECT_EQ(r["file"], kMixed);
        EXPECT_EQ(r["feature"], e.feature);
        EXPECT_EQ(r["verdict"], e.verdict) << r;
        EXPECT_EQ(r["code"], e.code) << r;
        EXPECT_EQ(r["id"], e.id) << r;
        EXPECT_EQ(r["name"], e.name) << r;
        EXPECT_EQ(r["at"], e.at ? json(e.at) : json(nullptr)) << r;
        EXPECT_EQ(r["reason"].is_null(), e.code == 0) << r;
    }
    EXPECT_EQ(rows[3]["reason"],
              "hole (ring 1) lies outside its outer ring (ring 0) (global vertex 4)");
    EXPECT_EQ(rows[5]["reason"],
              "feature 5 polygon 0 ring 0 vertex 2: coordinate is not a pair of numbers (got "
              "[10,\"ten\"])");
    EXPECT_EQ(rows[2]["vertices"], 12);
    // The feature's properties come with its row.
    EXPECT_EQ(rows[1]["attributes"], json({{"name", "bow-tie"}})) << rows[1];
    EXPECT_TRUE(rows[0]["attributes"].empty()) << rows[0];
    // The table shows the id where there is one, else the name.
    EXPECT_TRUE(std::regex_search(t.out, std::regex("mixed.geojson +8 +triangle +3 +ok"))) << t.out;
    EXPECT_TRUE(std::regex_search(
        t.out, std::regex("mixed.geojson +1 +bow-tie +4 +invalid +ring 0 vertex 0")))
        << t.out;
}

TEST(Check, ExitCodeIsZeroOnlyWhenAllPassElseTheWorstClass) {
    EXPECT_EQ(
        cli("check " + sourcePath("polygons/hole.json") + " " + sourcePath("polygons/holes.json"))
            .code,
        0);
    // Without validation the invalid features reach the machine: forbidden (5) for the bow-tie
    // and the hole outside, and the overlapping parts (flooded apart) are caught by the exact
    // checker, which sees all parts together: a checker rejection (6) outranks the rest.
    int code = -1;
    json doc = checkJson("--no-validate " + kMixed, &code);
    EXPECT_EQ(code, 6);
    EXPECT_EQ(doc["summary"]["verdicts"]["checker"], 1) << doc["summary"];
    EXPECT_EQ(doc["features"][4]["verdict"], "checker");
    EXPECT_EQ(doc["summary"]["verdicts"]["forbidden"], 2) << doc["summary"];
    EXPECT_EQ(doc["features"][1]["verdict"], "forbidden");
    EXPECT_TRUE(has(doc["features"][1]["at"].get<std::string>(), " at step "))
        << doc["features"][1];
    // Another checker rejection in a second file keeps the worst class.
    doc = checkJson(
        "--no-validate " + kMixed + " " + sourcePath("polygons/invalid/checker-rejects.json"),
        &code);
    EXPECT_EQ(code, 6);
    EXPECT_EQ(doc["features"].back()["verdict"], "checker");
    EXPECT_EQ(doc["summary"]["code"], 6);
    EXPECT_EQ(cli("check").code, 2);
    EXPECT_EQ(cli("check -j 0 " + kMixed).code, 2);
}

TEST(Check, SameOutputForAnyNumberOfJobs) {
    std::string inputs = kMixed + " " + sourcePath("polygons") + " /nonexistent.json";
    for (const char* flags : {"", "--json ", "--no-validate "}) {
        CheckRun one = cli(std::string("check -j 1 ") + flags + inputs);
        CheckRun four = cli(std::string("check -j 4 ") + flags + inputs);
        EXPECT_EQ(one.code, four.code) << flags;
        EXPECT_GT(one.out.size(), 1000u) << flags;
        EXPECT_EQ(timeless(one.out), timeless(four.out)) << flags;
        EXPECT_EQ(one.err, four.err) << flags;  // warnings in input order too
    }
}

TEST(Check, FoldersAreCheckedRecursivelyInSortedOrder) {
    fs::path d = scratch("folder");
    fs::create_directories(d / "b" / "deeper");
    fs::copy_file(kMixed, d / "b" / "deeper" / "mixed.geojson");
    fs::copy_file(sourcePath("polygons/hole.json"), d / "a.json");
    fs::copy_file(sourcePath("polygons/invalid/nan.wkt"), d / "b" / "nan.WKT");
    std::ofstream(d / "notes.txt") << "not a polygon";
    fs::create_directories(d / "empty");
    json doc = checkJson(d.string() + " " + (d / "empty").string());
    std::vector<std::string> files;
    for (const json& r : doc["features"]) files.push_back(r["file"]);
    ASSERT_EQ(files.size(), 1u + 1u + 9u + 1u) << doc;
    EXPECT_EQ(files[0], (d / "a.json").string());
    EXPECT_EQ(files[1], (d / "b" / "deeper" / "mixed.geojson").string());
    EXPECT_EQ(files[10], (d / "b" / "nan.WKT").string());
    EXPECT_EQ(doc["features"][10]["verdict"], "invalid");
    // A folder with no polygon file is a row, not a silent pass.
    EXPECT_EQ(files[11], (d / "empty").string());
    EXPECT_EQ(doc["features"][11]["verdict"], "malformed");
    EXPECT_EQ(doc["features"][11]["reason"].get<std::string>().rfind(
                  "folder holds no polygon file (.json, .geojson, .wkt", 0),
              0u)
        << doc["features"][11];
    fs::remove_all(d);
}

TEST(Check, AnUnreadableFileIsARowAndTheOthersAreChecked) {
    fs::path d = scratch("unreadable");
    int code = -1;
    json doc = checkJson(sourcePath("polygons/hole.json") + " " + (d / "missing.json").string() +
                             " " + sourcePath("polygons/holes.json") + " " +
                             sourcePath("polygons/invalid/nul-bytes.json"),
                         &code);
    EXPECT_EQ(code, 3);
    const json& rows = doc["features"];
    ASSERT_EQ(rows.size(), 4u) << doc;
    EXPECT_EQ(rows[0]["verdict"], "ok");
    EXPECT_EQ(rows[1]["verdict"], "malformed");
    EXPECT_EQ(rows[1]["feature"], nullptr);
    EXPECT_EQ(rows[1]["reason"], "cannot open file: No such file or directory");
    EXPECT_EQ(rows[2]["verdict"], "ok");
    EXPECT_TRUE(has(rows[3]["reason"].get<std::string>(), "binary data")) << rows[3];
    // --max-input-bytes counts per file, like the other reading commands.
    doc = checkJson("--max-input-bytes 100 " + sourcePath("polygons/hole.json") + " " +
                    sourcePath("polygons/holes.json"));
    EXPECT_EQ(doc["features"][0]["verdict"], "ok");
    EXPECT_TRUE(
        has(doc["features"][1]["reason"].get<std::string>(), "larger than the limit of 100 bytes"))
        << doc["features"][1];
    fs::remove_all(d);
}

// The sample folders: each file's row (or each feature's, for a FeatureCollection) has the
// exit code `flood triangulate` gives that file alone.
TEST(Check, SampleFoldersAgreeWithTriangulateFileByFile) {
    fs::path d = scratch("smoke");
    for (const char* folder : {"polygons", "polygons/invalid"}) {
        std::vector<std::string> files;
        for (auto& e : fs::recursive_directory_iterator(sourcePath(folder))) {
            std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".json" || ext == ".geojson" || ext == ".wkt"))
                files.push_back(e.path().string());
        }
        std::sort(files.begin(), files.end());
        // One expected (file, code) per row.
        std::vector<std::pair<std::string, int>> expected;
        std::map<int, size_t> perCode;
        for (const std::string& f : files) {
            json doc = json::parse(slurp(f), nullptr, false);
            std::vector<std::string> alone{f};
            if (doc.is_object() && doc.value("type", "") == "FeatureCollection") {
                alone.clear();
                for (size_t i = 0; i < doc["features"].size(); ++i) {
                    const json& g = doc["features"][i]["geometry"];
                    if (g.is_object() && (g["type"] == "LineString" || g["type"] == "Point"))
                        continue;
                    fs::path one = d / ("feature" + std::to_string(i) + ".json");
                    std::ofstream(one) << doc["features"][i].dump();
                    alone.push_back(one.string());
                }
            }
            for (const std::string& a : alone) {
                int code = cli("triangulate -o /dev/null " + a).code;
                expected.push_back({f, code});
                ++perCode[code];
            }
        }
        json doc = checkJson(sourcePath(folder));
        const json& rows = doc["features"];
        ASSERT_EQ(rows.size(), expected.size()) << folder;
        for (size_t k = 0; k < rows.size(); ++k) {
            EXPECT_EQ(rows[k]["file"], expected[k].first);
            EXPECT_EQ(rows[k]["code"], expected[k].second) << rows[k];
        }
        const json& v = doc["summary"]["verdicts"];
        EXPECT_EQ(v["ok"], perCode[0]) << folder;
        EXPECT_EQ(v["malformed"], perCode[3]) << folder;
        EXPECT_EQ(v["invalid"], perCode[4]) << folder;
        EXPECT_EQ(
            v["forbidden"].get<size_t>() + v["checker"].get<size_t>() + v["internal"].get<size_t>(),
            perCode[5] + perCode[6])
            << folder;
        EXPECT_GT(perCode[4], 5u) << folder << ": the invalid samples are there";
    }
    fs::remove_all(d);
}

// The core split: each feature read alone; parsePolygon's reading of the file is unchanged.
TEST(Check, ParseFeaturesSplitsACollectionAndLeavesOtherFilesWhole) {
    flood::ReadResult whole = flood::readPolygonFile(kMixed);
    EXPECT_EQ(whole.diagnostic.status, flood::Status::Malformed);
    // Feature 5 has one polygon: the place is named within the feature, as check names it.
    EXPECT_TRUE(has(whole.diagnostic.message, "feature 5 polygon 0 ring 0 vertex 2"))
        << whole.diagnostic.message;

    flood::DatasetRead d = flood::readFeaturesFile(kMixed, flood::kDefaultMaxInputBytes, false);
    ASSERT_EQ(d.features.size(), 9u);
    ASSERT_EQ(d.skipped.size(), 1u);
    EXPECT_FALSE(d.features[0].wholeFile);
    EXPECT_EQ(d.features[6].index, 7u);
    EXPECT_EQ(d.features[2].read.polygon.parts.size(), 2u);  // a MultiPolygon stays one feature
    EXPECT_EQ(d.features[2].read.polygon.rings.size(), 3u);
    EXPECT_TRUE(d.features[2].source.empty());
    EXPECT_EQ(d.features[5].read.diagnostic.status,
              flood::Status::Malformed);  // "feature 5 polygon 0 ..."
    flood::DatasetRead kept = flood::readFeaturesFile(kMixed, flood::kDefaultMaxInputBytes, true);
    EXPECT_TRUE(has(kept.features[1].source, "\"bow-tie\"")) << kept.features[1].source;

    for (const char* other : {"polygons/holes.json", "polygons/invalid/malformed-json.json",
                              "polygons/invalid/nan.wkt", "polygons/invalid/deep-nesting.json"}) {
        flood::ReadResult r = flood::readPolygonFile(sourcePath(other));
        flood::DatasetRead one =
            flood::readFeaturesFile(sourcePath(other), flood::kDefaultMaxInputBytes, true);
        ASSERT_EQ(one.features.size(), 1u) << other;
        EXPECT_TRUE(one.features[0].wholeFile);
        EXPECT_EQ(one.features[0].read.diagnostic.message, r.diagnostic.message) << other;
        EXPECT_EQ(one.features[0].read.polygon.vertices.size(), r.polygon.vertices.size()) << other;
    }
}

// The progress line is for people: on a terminal (script(1) gives one), never in a pipe.
TEST(Check, ProgressLineOnlyOnATerminal) {
    CheckRun piped = cli("check " + kMixed);
    EXPECT_FALSE(has(piped.err, "features checked")) << piped.err;
    if (!fs::exists("/usr/bin/script")) GTEST_SKIP() << "no script(1) to make a terminal";
    fs::path out = fs::temp_directory_path() / ("flood-check-tty-" + std::to_string(getpid()));
    std::string inner = std::string(FLOOD_CLI) + " check -j 1 " + kMixed + " > " + out.string();
    FILE* p = popen(("/usr/bin/script -qec '" + inner + "' /dev/null").c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string tty;
    char buf[4096];
    for (size_t k; (k = fread(buf, 1, sizeof buf, p)) > 0;) tty.append(buf, k);
    pclose(p);
    EXPECT_TRUE(has(tty, "features checked")) << tty;
    EXPECT_TRUE(has(tty, "\r\033[K")) << "the line is erased at the end";
    EXPECT_EQ(timeless(slurp(out)), timeless(piped.out)) << "stdout is the same table either way";
    fs::remove(out);
}

// `check --help` said ".json, .geojson, .wkt found recursively" while a folder search found
// .shp, .gpkg, .fgb, ... too (issue 30 §4): the help lists every format, and every format it
// lists is found in a folder.
TEST(Check, HelpListsEveryFormatAFolderSearchFinds) {
    RunResult help = runCli("check --help");
    ASSERT_EQ(help.code, 0) << help.out;
    const std::string lead = "in folders, recursively: ";
    const size_t at = help.out.find(lead);
    ASSERT_NE(at, std::string::npos) << help.out;
    const std::string list =
        help.out.substr(at + lead.size(), help.out.find(';', at) - at - lead.size());
    std::vector<std::string> exts;
    for (size_t from = 0; from < list.size();) {
        size_t comma = std::min(list.find(", ", from), list.size());
        exts.push_back(list.substr(from, comma - from));
        from = comma + 2;
    }
    ASSERT_GE(exts.size(), 3u) << list;
#ifdef FLOOD_GDAL
    for (const char* gis : {".shp", ".gpkg", ".fgb"})
        EXPECT_NE(std::find(exts.begin(), exts.end(), gis), exts.end()) << list;
#endif
    fs::path d = scratch("help-formats");
    for (const std::string& ext : exts) {
        ASSERT_EQ(ext[0], '.') << list;
        std::ofstream(d / ("x" + ext)) << "x";
    }
    std::ofstream(d / "x.txt") << "x";  // not listed: not found
    json doc = checkJson(d.string());
    EXPECT_EQ(doc["summary"]["files"], exts.size()) << doc["summary"];
    // The message of a folder without any names them too.
    fs::create_directories(d / "empty");
    doc = checkJson((d / "empty").string());
    EXPECT_EQ(doc["features"][0]["reason"], "folder holds no polygon file (" + list + ")");
    fs::remove_all(d);
}

namespace {

// A GeoJSON text sequence piped in (GeoJSONSeq, RFC 8142: a Feature per line, or after each
// record separator 0x1E, as `ogr2ogr -f GeoJSONSeq /vsistdout/` writes it) is a dataset of
// features, not one malformed document; a broken record leaves it one document, whose reader
// names the line.
TEST(Check, GeoJsonSequenceOnStdin) {
    const fs::path dir = scratch("check-geojsonseq");
    const std::string a =
        R"({"type":"Feature","properties":{"name":"a"},"geometry":{"type":"Polygon",)"
        R"("coordinates":[[[0,0],[1,0],[0,1],[0,0]]]}})";
    const std::string bowtie =
        R"({"type":"Feature","properties":{"name":"b"},"geometry":{"type":"Polygon",)"
        R"("coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]}})";
    const std::vector<std::pair<std::string, std::string>> forms = {
        {"lines.geojsonl", a + "\n" + bowtie + "\n"},
        {"separated.geojsons", "\x1e" + a + "\n\x1e" + bowtie + "\n"},
    };
    for (const auto& [file, text] : forms) {
        SCOPED_TRACE(file);
        std::ofstream((dir / file).string(), std::ios::binary) << text;
        int code = -1;
        json doc = checkJson("- < " + (dir / file).string(), &code);
        ASSERT_TRUE(doc.contains("features")) << doc.dump();
        ASSERT_EQ(doc["features"].size(), 2u) << doc.dump();
        EXPECT_EQ(doc["features"][0]["verdict"], "ok");
        EXPECT_EQ(doc["features"][0]["name"], "a");
        EXPECT_EQ(doc["features"][1]["verdict"], "invalid");
        EXPECT_EQ(code, 4);
    }
    std::ofstream((dir / "broken.geojsonl").string()) << a << "\n"
                                                      << R"({"type":"Feature")";
    CheckRun broken = cli("check - < " + (dir / "broken.geojsonl").string());
    EXPECT_EQ(broken.code, 3);
    EXPECT_TRUE(has(broken.out, "malformed")) << broken.out;
    EXPECT_TRUE(has(broken.out, "2:")) << broken.out;
    fs::remove_all(dir);
}

}  // namespace
