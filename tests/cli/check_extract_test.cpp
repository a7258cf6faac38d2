// `flood check --extract DIR` through the built binary: extracted features fail the same way,
// their names never collide, a file is never overwritten, stdin and a folder that cannot be
// made.
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
