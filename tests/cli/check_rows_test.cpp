// `flood check` through the built binary, what a row says: every finding of a feature with its
// location, control characters escaped, warnings naming the feature.
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
