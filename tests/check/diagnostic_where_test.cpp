// Where a diagnostic points (flood/check/diagnostic_where.h) comes from its culprits: on every
// invalid sample it is the location validate() puts first in its message, and `flood check`'s
// AT column shows exactly it (never a cut of the message text).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "flood/check/diagnostic_where.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {
std::vector<std::string> invalidSamples() {
    std::vector<std::string> out;
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (r.diagnostic.ok() && !validate(r.polygon, f).ok()) out.push_back(f);
    }
    return out;
}
}  // namespace

TEST(DiagnosticWhere, IsTheLocationTheValidatorsMessageStartsWith) {
    std::vector<std::string> files = invalidSamples();
    ASSERT_GT(files.size(), 10u);
    size_t vertices = 0, ringsOnly = 0;
    for (const std::string& f : files) {
        Polygon p = readPolygonFile(f).polygon;
        Diagnostic d = validate(p, f);
        Where w = whereOf(p, d.culprits);
        ASSERT_FALSE(w.text.empty()) << d.message;
        EXPECT_EQ(d.message, f + ": " + w.text + ": " + reasonOf(d.message, f, w)) << f;
        if (w.vertex != kNone) {
            ++vertices;
            EXPECT_EQ(p.rings[w.ring].first + w.vertex, d.culprits.vertices.front()) << f;
        } else {
            ++ringsOnly;
            EXPECT_EQ(w.text, "ring " + std::to_string(w.ring)) << f;
        }
    }
    EXPECT_GT(vertices, 10u);
    EXPECT_GE(ringsOnly, 1u);  // empty-ring.json
}

TEST(DiagnosticWhere, AReasonWithoutALocationIsTheMessageAfterTheName) {
    Where none;
    EXPECT_EQ(reasonOf("a.json: polygon has no rings", "a.json", none), "polygon has no rings");
    Where ring1;
    ring1.ring = 1, ring1.text = "ring 1";
    // "ring 12" is not "ring 1": only a whole location is taken off.
    EXPECT_EQ(reasonOf("a.json: ring 12: ring is empty", "a.json", ring1),
              "ring 12: ring is empty");
    EXPECT_EQ(reasonOf("a.json: ring 1: ring is empty", "a.json", ring1), "ring is empty");
}

TEST(DiagnosticWhere, CheckShowsItInTheAtColumn) {
    for (const std::string& f : invalidSamples()) {
        Polygon p = readPolygonFile(f).polygon;
        Diagnostic d = validate(p, f);
        Where w = whereOf(p, d.culprits);
        RunResult r = runCli("check --json -j 1 '" + f + "'");
        nlohmann::json doc = nlohmann::json::parse(r.out.substr(r.out.find('{')), nullptr, false);
        ASSERT_TRUE(doc.is_object()) << r.out;
        const nlohmann::json& row = doc["features"][0];
        std::string at = w.text;
        if (p.parts.size() > 1)
            for (size_t k = 0; k < p.parts.size(); ++k)
                if (w.ring >= p.parts[k].firstRing &&
                    w.ring < p.parts[k].firstRing + p.parts[k].ringCount)
                    at += " (part " + std::to_string(k) + ")";
        EXPECT_EQ(row["at"], at) << f;
        EXPECT_EQ(row["reason"], reasonOf(d.message, f, w)) << f;
    }
}
