// `flood check` through the built binary: verdict counts and exit codes on a FeatureCollection
// mixing valid and invalid features (polygons/datasets/mixed.geojson), the same output for
// any -j, folders, --extract files that fail the same way, unreadable files among good ones,
// and the sample folders checked against `flood triangulate` run on each file.
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

#include "test_support.h"

using namespace flood::testing;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string kMixed = sourcePath("polygons/datasets/mixed.geojson");

struct CheckRun {
    int code = -1;
    std::string out, err;
};

// stdout and stderr apart: the table and the JSON are stdout only.
CheckRun cli(const std::string& args) {
    fs::path err = fs::temp_directory_path() / ("flood-check-stderr-" + std::to_string(getpid()));
    std::string cmd = std::string(FLOOD_CLI) + " " + args + " 2>" + err.string();
    RunResult run = runShell(cmd);
    CheckRun r;
    r.code = run.code;
    r.out = std::move(run.out);
    r.err = slurp(err);
    fs::remove(err);
    return r;
}

json checkJson(const std::string& args, int* code = nullptr) {
    CheckRun r = cli("check --json " + args);
    if (code) *code = r.code;
    json doc = json::parse(r.out, nullptr, false);
    EXPECT_FALSE(doc.is_discarded()) << r.out << r.err;
    return doc;
}

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// The only part of the output that depends on the run: the time.
std::string timeless(std::string s) {
    s = std::regex_replace(s, std::regex("; [0-9.]+ s\n"), "; T s\n");
    return std::regex_replace(s, std::regex("\"seconds\": [0-9.e+-]+"), "\"seconds\": T");
}

}  // namespace

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

// Each extracted file, run through `flood triangulate` (with the same --no-validate), exits
// with the row's code and the same message; invalid ones fail `flood verify` alike.
TEST(Check, ExtractedFeaturesReproduceTheirFailure) {
    for (std::string flags : {"", "--no-validate "}) {
        fs::path d = scratch("extract");
        fs::path out = d / "failing";
        int code = -1;
        json doc = checkJson(flags + "--extract " + out.string() + " " + kMixed + " " +
                                 sourcePath("polygons/invalid/nan.wkt") + " " +
                                 sourcePath("polygons/invalid/malformed-json.json") + " " +
                                 sourcePath("polygons/hole.json") + " /nonexistent.json",
                             &code);
        // Unvalidated, the overlapping parts are a checker rejection (6), the worst class.
        EXPECT_EQ(code, flags.empty() ? 4 : 6);
        size_t extracted = 0, failing = 0;
        for (const json& r : doc["features"]) {
            if (r["code"] == 0) {
                EXPECT_TRUE(r["extracted"].is_null()) << r;
                continue;
            }
            ++failing;
            if (r["file"] == "/nonexistent.json") {
                EXPECT_TRUE(r["extracted"].is_null()) << "nothing to extract: " << r;
                continue;
            }
            ASSERT_TRUE(r["extracted"].is_string()) << r;
            ++extracted;
            std::string path = r["extracted"];
            std::string stem = fs::path(r["file"].get<std::string>()).stem().string();
            int feature = r["feature"].is_null() ? 0 : r["feature"].get<int>();
            EXPECT_EQ(fs::path(path).parent_path(), out);
            EXPECT_EQ(fs::path(path).stem().string(), stem + "_feature" + std::to_string(feature));
            CheckRun t = cli("triangulate " + flags + path);
            EXPECT_EQ(t.code, r["code"]) << path << ": " << t.err;
            std::string reason = r["reason"];
            std::string at = r["at"].is_null() ? "" : r["at"].get<std::string>();
            at = std::regex_replace(at, std::regex(" \\(part [0-9]+\\)$"), "");  // check's addition
            if (r["verdict"] == "invalid") {
                EXPECT_TRUE(has(t.err, path + ": " + at + ": " + reason)) << t.err << " vs " << r;
                EXPECT_EQ(cli("verify " + path).code, 4);
            } else if (r["verdict"] == "forbidden") {
                EXPECT_TRUE(has(t.err, reason)) << t.err << " vs " << r;
            } else if (r["verdict"] == "malformed" && has(reason, "coordinate")) {
                // "feature 5 polygon 0 ..." in the collection is "polygon 0 ..." alone.
                EXPECT_TRUE(has(t.err, reason.substr(reason.find("polygon 0")))) << t.err;
            }
        }
        EXPECT_GE(failing, 6u) << flags;
        EXPECT_EQ(extracted, failing - 1);  // all but the missing file
        size_t files = std::distance(fs::directory_iterator(out), fs::directory_iterator());
        EXPECT_EQ(files, extracted);
        fs::remove_all(d);
    }
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
    EXPECT_TRUE(has(whole.diagnostic.message, "feature 5 polygon 7 ring 0 vertex 2"))
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

TEST(Check, StdinAndAnExtractFolderThatCannotBeMade) {
    CheckRun s = cli("check --json - < " + sourcePath("polygons/invalid/hole-outside.json"));
    EXPECT_EQ(s.code, 4) << s.err;
    EXPECT_TRUE(has(s.out, "\"file\": \"-\"")) << s.out;
    fs::path d = scratch("badextract");
    std::ofstream(d / "file") << "x";
    CheckRun e = cli("check --extract " + (d / "file").string() + " " + kMixed);
    EXPECT_EQ(e.code, 8) << e.err;
    EXPECT_TRUE(has(e.err, "cannot create the --extract folder")) << e.err;
    fs::remove_all(d);
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

// Two inputs with one stem (a.json in two folders) do not overwrite each other's repros.
TEST(Check, ExtractedNamesNeverCollide) {
    fs::path d = scratch("stems");
    fs::create_directories(d / "copy");
    fs::copy_file(kMixed, d / "copy" / "mixed.geojson");
    json doc =
        checkJson("--extract " + (d / "out").string() + " " + kMixed + " " + (d / "copy").string());
    std::set<std::string> names;
    for (const json& r : doc["features"])
        if (r["extracted"].is_string())
            names.insert(fs::path(r["extracted"].get<std::string>()).filename());
    EXPECT_EQ(names.size(), 10u);
    EXPECT_TRUE(names.count("mixed_feature1.json") && names.count("mixed-2_feature1.json")) << doc;
    fs::remove_all(d);
}

// Every finding of a feature (issue 26 §2): a face with three separate crossings lists three,
// in the table under its row and in the JSON with their locations as numbers.
TEST(Check, EveryFindingOfAFeatureIsListedWithItsLocation) {
    fs::path d = scratch("findings");
    fs::path in = d / "three.geojson";
    std::string rings = "[[0,0],[100,0],[100,100],[0,100],[0,0]]";
    for (int i = 0; i < 3; ++i) {
        std::string x = std::to_string(2 + 3 * i), x1 = std::to_string(3 + 3 * i);
        rings += ",[[" + x + ",2],[" + x1 + ",3],[" + x1 + ",2],[" + x + ",3],[" + x + ",2]]";
    }
    std::ofstream(in) << "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\","
                         "\"properties\":{\"name\":\"three\"},\"geometry\":{\"type\":"
                         "\"Polygon\",\"coordinates\":["
                      << rings << "]}}]}";
    CheckRun table = cli("check " + in.string());
    EXPECT_EQ(table.code, 4);
    for (const char* crossing :
         {"(2, 2)-(3, 3) crosses", "(5, 2)-(6, 3) crosses", "(8, 2)-(9, 3) crosses"})
        EXPECT_TRUE(has(table.out, crossing)) << crossing << "\n" << table.out;
    EXPECT_TRUE(has(table.out, "check: 1 feature in 1 file")) << table.out;

    json doc = checkJson(in.string());
    const json& f = doc["features"][0];
    ASSERT_EQ(f["findings"].size(), 3u) << f.dump(1);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(f["findings"][i]["x"], 2.5 + 3 * i);
        EXPECT_EQ(f["findings"][i]["y"], 2.5);
        EXPECT_EQ(f["findings"][i]["ring"], i + 1);
    }
    EXPECT_EQ(f["x"], 2.5);
    EXPECT_EQ(f["findings_omitted"], 0);

    json two = checkJson("--max-findings 2 " + in.string());
    EXPECT_EQ(two["features"][0]["findings"].size(), 2u);
    EXPECT_EQ(two["features"][0]["findings_omitted"], 1);
    EXPECT_TRUE(has(cli("check --max-findings 2 " + in.string()).out,
                    "and 1 more findings (--max-findings)"));
    fs::remove_all(d);
}

// --extract used to replace whatever held an extracted name: an earlier run's repros, or an
// input being checked. A taken name gets -2, -3, ... and "extracted" says which was written.
TEST(Check, ExtractNeverOverwritesAFile) {
    fs::path d = scratch("extract-no-overwrite");
    const fs::path out = d / "out";
    fs::create_directories(out);
    // An input that is checked lives in the folder, under the name feature 1 would get.
    const fs::path input = out / "mixed_feature1.json";
    fs::copy_file(sourcePath("polygons/invalid/hole-outside.json"), input);
    const std::string inputText = slurp(input);
    json first = checkJson("--extract " + out.string() + " " + kMixed + " " + input.string());
    EXPECT_EQ(slurp(input), inputText);
    std::map<std::string, std::string> extracted;  // file#feature -> name
    for (const json& r : first["features"])
        if (r["extracted"].is_string())
            extracted[r["file"].get<std::string>() + "#" + r["feature"].dump()] =
                fs::path(r["extracted"].get<std::string>()).filename();
    EXPECT_EQ(extracted[kMixed + "#1"], "mixed_feature1-2.json") << first;
    EXPECT_EQ(extracted[input.string() + "#null"], "mixed_feature1_feature0.json") << first;
    // Again: every name is taken now, none is replaced.
    std::map<std::string, std::string> before;
    for (auto& e : fs::directory_iterator(out)) before[e.path().filename()] = slurp(e.path());
    for (auto& [name, text] : before) std::ofstream(out / name) << "precious " << name;
    int code = -1;
    json second =
        checkJson("--extract " + out.string() + " " + kMixed + " " + input.string(), &code);
    EXPECT_EQ(code, 4);
    for (auto& [name, text] : before) EXPECT_EQ(slurp(out / name), "precious " + name) << name;
    size_t fresh = 0;
    for (const json& r : second["features"])
        if (r["extracted"].is_string()) {
            std::string name = fs::path(r["extracted"].get<std::string>()).filename();
            EXPECT_EQ(before.count(name), 0u) << name;
            EXPECT_TRUE(fs::exists(r["extracted"].get<std::string>()));
            ++fresh;
        }
    EXPECT_EQ(fresh, extracted.size());
    EXPECT_EQ(size_t(std::distance(fs::directory_iterator(out), fs::directory_iterator())),
              before.size() + fresh);
    fs::remove_all(d);
}

// A feature's name with an ESC reached the terminal raw, and a newline forged a table row:
// control characters are shown escaped in the table and the warnings (the JSON escapes them).
TEST(Check, ControlCharactersInNamesAreEscaped) {
    fs::path d = scratch("control");
    const std::string ring = "[[[0,0],[4,0],[4,4],[0,4],[0,0]]]";
    std::ofstream(d / "ctl.json")
        << R"({"type":"FeatureCollection","features":[)"
        << R"({"type":"Feature","properties":{"name":"evil\u001b[31mred\nforged  row \u0085x\u007f"},)"
        << R"("geometry":{"type":"Polygon","coordinates":)" << ring << "}},"
        << R"({"type":"Feature","id":"a\rb\tc","properties":{},)"
        << R"("geometry":{"type":"Polygon","coordinates":)" << ring << "}},"
        << R"({"type":"Feature","properties":{},"geometry":{"type":"Point\u001b]0;x","coordinates":[0,0]}}]})";
    CheckRun r = cli("check " + (d / "ctl.json").string());
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    for (const std::string& s : {r.out, r.err}) {
        EXPECT_EQ(s.find('\x1b'), std::string::npos) << s;
        EXPECT_EQ(s.find('\r'), std::string::npos) << s;
        EXPECT_EQ(s.find('\x7f'), std::string::npos) << s;
        EXPECT_EQ(s.find("\xc2\x85"), std::string::npos) << s;
    }
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 4) << r.out;  // head, 2 rows, sum
    EXPECT_TRUE(has(r.out, "evil\\e[31mred\\nforged  row \\u0085x\\x7f")) << r.out;
    EXPECT_TRUE(has(r.out, "a\\rb\\tc")) << r.out;
    EXPECT_TRUE(has(r.err, "not polygonal (Point\\e]0;x), skipped")) << r.err;
    // The JSON keeps the text itself, escaped as JSON escapes it.
    json doc = checkJson((d / "ctl.json").string());
    EXPECT_EQ(doc["features"][0]["name"], "evil\x1b[31mred\nforged  row \xc2\x85x\x7f");
    fs::remove_all(d);
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

// 2,000 features with a repeated point printed 2,000 identical lines that named no feature
// (issue 30 §4): each warning names its feature, and past the first few of a kind the rest of
// that kind are one line with their count.
TEST(Check, WarningsNameTheFeatureAndFoldRepeats) {
    fs::path d = scratch("warnings");
    json features = json::array();
    for (int i = 0; i < 2000; ++i)
        features.push_back({{"type", "Feature"},
                            {"properties", json::object()},
                            {"geometry",
                             {{"type", "Polygon"},
                              {"coordinates", {{{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 0}}}}}}});
    const std::string file = (d / "rep.geojson").string();
    std::ofstream(file) << json{{"type", "FeatureCollection"}, {"features", features}}.dump();
    CheckRun r = cli("check " + file);
    EXPECT_EQ(r.code, 0) << r.err;
    std::string want;
    for (int i = 0; i < 3; ++i)
        want += "warning: " + file + ": feature " + std::to_string(i) +
                ": ring 0 vertex 2 (10, 0): repeated point dropped\n";
    want += "warning: " + file + ": \u2026 and 1,997 more like it (repeated point dropped)\n";
    EXPECT_EQ(r.err, want);
#ifdef FLOOD_GDAL
    // A GIS dataset's warnings name the feature by its FID.
    const std::string gpkg = (d / "rep.gpkg").string();
    RunResult g = runShell("ogr2ogr -f GPKG " + gpkg + " " + file + " -limit 2 2>&1");
    ASSERT_EQ(g.code, 0) << g.out;
    r = cli("check " + gpkg);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.err, "warning: " + gpkg +
                               ": feature 2: ring 0 vertex 2 (10, 0): repeated "
                               "point dropped\n"))
        << r.err;
#endif
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
