// earcut's 59 test polygons (../shared/peers/earcut, a suite none of us wrote): the ones GEOS
// calls valid must triangulate exact-valid; the others must be refused with a diagnostic or
// triangulate only after reported cleaning — never crash, hang or pass silently.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>

#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// fixture name -> GEOS verdict, from the README's table.
std::map<std::string, std::string> geosVerdicts() {
    std::map<std::string, std::string> verdicts;
    std::ifstream in(sharedPath("peers/earcut/README.md"));
    std::regex row(R"(^\| ([a-z0-9-]+) \|.*\| ([^|]+) \|\s*$)");
    std::smatch m;
    for (std::string line; std::getline(in, line);)
        if (std::regex_match(line, m, row) && m[1] != "fixture") verdicts[m[1]] = m[2];
    return verdicts;
}

TEST(Peers, GeosValidFixturesTriangulateExactly) {
    auto verdicts = geosVerdicts();
    if (verdicts.empty()) GTEST_SKIP() << sharedPath("peers/earcut") << " is absent";
    ASSERT_EQ(verdicts.size(), 59u);
    size_t valid = 0, checked = 0;
    for (auto& [name, verdict] : verdicts) {
        if (verdict != "Valid Geometry") continue;
        ++valid;
        std::string path = sharedPath("peers/earcut/fixtures/" + name + ".json");
        ReadResult rr = readPolygonFile(path);
        ASSERT_TRUE(rr.diagnostic.ok()) << rr.diagnostic.message;
        Diagnostic d = validate(rr.polygon, path);
        ASSERT_TRUE(d.ok()) << d.message;
        expectTriangulates(rr.polygon, name);
        ++checked;
    }
    // touching2 (a T-junction) and steiner (point holes) among them.
    EXPECT_EQ(checked, 32u);
    EXPECT_EQ(valid, 32u);
}

TEST(Peers, InvalidFixturesAreRefusedOrCleaned) {
    auto verdicts = geosVerdicts();
    if (verdicts.empty()) GTEST_SKIP() << sharedPath("peers/earcut") << " is absent";
    for (auto& [name, verdict] : verdicts) {
        if (verdict == "Valid Geometry") continue;
        std::string path = sharedPath("peers/earcut/fixtures/" + name + ".json");
        ReadResult rr = readPolygonFile(path);
        if (!rr.diagnostic.ok()) continue;  // refused while reading, with a message
        Diagnostic d = validate(rr.polygon, path);
        if (!d.ok()) {
            EXPECT_EQ(d.status, Status::Invalid) << name;
            EXPECT_NE(d.message.find(name), std::string::npos)
                << "message names the file: " << d.message;
            continue;
        }
        // Accepted after cleaning (repeated points dropped, reported as warnings): then it
        // must triangulate exactly.
        EXPECT_FALSE(rr.warnings.empty())
            << name << " is GEOS-invalid (" << verdict << ") but was accepted without any cleaning";
        expectTriangulates(rr.polygon, name);
    }
}

}  // namespace
