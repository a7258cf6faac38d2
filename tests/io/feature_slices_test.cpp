// A FeatureCollection read in slices by several threads (parseFeatures with a TaskRunner,
// core/io/io_json_cut.cpp) reads as the one-piece parse does: the same features, numbers,
// messages and skipped lines, valid or broken, whatever order the tasks run in.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "flood/io/io.h"
#include "io/io_json.h"
#include "io_test_support.h"
#include "test_support.h"

namespace flood {
namespace {

using testing::Backwards;
using testing::twoThreads;

// Everything a read holds, as text: equal texts, equal reads.
std::string describe(const DatasetRead& d) {
    std::string s;
    for (const std::string& k : d.skipped) s += "skipped " + k + "\n";
    for (const FeatureRead& f : d.features) {
        s += "feature " + std::to_string(f.index) + " fid " + std::to_string(f.fid) + " whole " +
             std::to_string(f.wholeFile) + " id " + f.id + " name " + f.name + " layer " + f.layer +
             " source " + f.source + "\n";
        for (const auto& [k, v] : f.attributes) s += "  attribute " + k + "=" + v + "\n";
        s += testing::io::describe(f.read);
        s += "\n";
    }
    return s;
}

// A feature whose properties hold what a byte scan could stumble on: brackets, commas, quotes
// and escapes in strings, and a nested member called "features".
std::string feature(size_t i, bool withId = true) {
    std::string f = "{\"type\":\"Feature\",";
    if (withId) f += "\"id\":" + std::to_string(1000 + i) + ",";
    f += "\"properties\":{\"name\":\"f" + std::to_string(i) +
         " ],}{[\\\" \\\\\",\"features\":[1,{\"a\":\"]\"}],\"n\":" + std::to_string(i) + "},";
    const double x = double(i % 100) * 20, y = double(i / 100) * 20;
    auto square = [](double x0, double y0, double s) {
        char b[200];
        std::snprintf(b, sizeof b, "[[%g,%g],[%g,%g],[%g,%g],[%g,%g],[%g,%g]]", x0, y0, x0 + s, y0,
                      x0 + s, y0 + s, x0, y0 + s, x0, y0);
        return std::string(b);
    };
    if (i % 7 == 3)  // not polygonal: skipped, with a line saying so
        f += "\"geometry\":{\"type\":\"Point\",\"coordinates\":[1,2]}";
    else if (i % 5 == 1)  // two parts, one with a hole
        f += "\"geometry\":{\"type\":\"MultiPolygon\",\"coordinates\":[[" + square(x, y, 8) + "," +
             square(x + 2, y + 2, 3) + "],[" + square(x + 10, y, 8) + "]]}";
    else {  // a ring with a repeated point (a warning), padded with many vertices
        std::string ring = "[[" + std::to_string(x) + "," + std::to_string(y) + "]";
        for (int k = 1; k <= 60; ++k)
            ring += ",[" + std::to_string(x + 8.0 * k / 60) + "," + std::to_string(y) + "]";
        ring += ",[" + std::to_string(x + 8) + "," + std::to_string(y) + "]";  // repeated
        ring += ",[" + std::to_string(x + 8) + "," + std::to_string(y + 8) + "],[" +
                std::to_string(x) + "," + std::to_string(y + 8) + "]]";
        f += "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[" + ring + "]}";
    }
    return f + "}";
}

// A collection of `n` features, several MiB for n in the thousands: several slices.
std::string collection(size_t n, const std::string& between = ",", bool ids = true) {
    std::string t = "{\"type\":\"FeatureCollection\",\"name\":\"x[,]\",\"features\":[\n";
    for (size_t i = 0; i < n; ++i) t += (i ? between : "") + feature(i, ids) + "\n";
    return t + "],\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"EPSG:3857\"}}}\n";
}

void expectSame(const std::string& text, const std::string& what, size_t minSlices = 0) {
    const std::string serial = describe(parseFeatures(text, "c.json", true));
    Backwards back;
    EXPECT_EQ(describe(parseFeatures(text, "c.json", true, nullptr, back.runner())), serial)
        << what;
    EXPECT_GE(back.most, minSlices) << what << ": the collection was not cut";
    EXPECT_EQ(describe(parseFeatures(text, "c.json", true, nullptr, twoThreads)), serial) << what;
}

TEST(FeatureSlices, ACollectionReadsTheSameInSlices) {
    const std::string text = collection(500);
    ASSERT_GT(text.size(), size_t(4) << 16);  // over four slices of 64 KiB
    DatasetRead d = parseFeatures(text, "c.json", false);
    ASSERT_EQ(d.features.size() + d.skipped.size(), 500u);
    EXPECT_FALSE(d.skipped.empty());
    EXPECT_EQ(d.features[1].fid, 1001);  // every id distinct: the ids are the FIDs
    // The scans, the slices and the features' polygons are each a run of tasks.
    Backwards back;
    DatasetRead s = parseFeatures(text, "c.json", false, nullptr, back.runner());
    EXPECT_EQ(back.calls, 3u);
    EXPECT_EQ(describe(s), describe(d));
    expectSame(text, "valid", 4);
    // Without ids, and with one id repeated, the FIDs are the positions.
    expectSame(collection(500, ",", false), "no ids", 4);
    std::string repeated = text;
    repeated.replace(repeated.find("\"id\":1400"), 9, "\"id\":1001");
    expectSame(repeated, "repeated id", 4);
    // The progress record counts every Feature the parser meets.
    ReadProgress serial, sliced;
    parseFeatures(text, "c.json", false, &serial);
    parseFeatures(text, "c.json", false, &sliced, twoThreads);
    EXPECT_EQ(sliced.featuresParsed.load(), 500u);
    EXPECT_EQ(sliced.featuresRead.load(), serial.featuresRead.load());
    EXPECT_GE(serial.featuresParsed.load(), 500u);  // and objects two deep elsewhere
}

TEST(FeatureSlices, ABrokenCollectionSaysWhatTheOnePieceParseSays) {
    const std::string good = collection(200);  // three slices
    ASSERT_GT(good.size(), size_t(2) << 16);
    const size_t middle = good.find("\"id\":1150");  // in a later slice
    ASSERT_NE(middle, std::string::npos);
    auto edit = [&](size_t at, size_t erase, const std::string& insert) {
        std::string t = good;
        return t.replace(at, erase, insert);
    };
    const size_t close = good.rfind(']');  // the features array's end
    const struct {
        const char* what;
        std::string text;
    } cases[] = {
        {"two commas", collection(200, ",,")},
        {"an empty element", edit(good.find(",", middle), 1, ", ,")},
        {"a trailing comma", edit(close, 0, ",")},
        {"a leading comma", edit(good.find('[') + 1, 0, ",")},
        {"a broken number in a later slice", edit(good.find("[[", middle) + 2, 0, "-,")},
        {"a missing bracket", edit(good.find("]]", middle), 1, "")},
        {"text after the document", good + "{}"},
        {"an unclosed string at the end", good + "\""},
        {"two features arrays", edit(good.size() - 2, 0, ",\"features\":[]")},
        {"features, then not an array", edit(good.size() - 2, 0, ",\"features\":5")},
        {"a name with an escape", edit(good.find("\"features\":["), 10, "\"feat\\u0075res\"")},
        {"features not an array", "{\"type\":\"FeatureCollection\",\"features\":{\"a\":[1,2]}}"},
        {"no features", "{\"type\":\"FeatureCollection\",\"features\":[ ]}"},
        {"not a collection", edit(good.find("FeatureCollection"), 17, "Thing")},
        {"an invalid byte in a string", edit(good.find("f160"), 1, "\x01")},
    };
    for (const auto& c : cases) expectSame(c.text, c.what);
}

TEST(FeatureSlices, TheCutFindsTheArraysCommasOnly) {
    const std::string text =
        R"({"features":[{"a":[1,2],"features":[3,4]},"x,]",5 , [6,7]], "b":[8,9]})";
    std::optional<io_detail::FeatureCut> cut = io_detail::cutFeatures(text);
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->open, text.find('['));
    EXPECT_EQ(cut->close, text.find("], \"b\""));
    std::vector<size_t> commas = {text.find(",\"x"), text.find(",5"), text.find(", [6")};
    EXPECT_EQ(cut->commas, commas);
    // Anything it could misread is left to the parser.
    for (const char* doubtful :
         {R"({"features":[1,2],"features":[3]})", R"({"f\"eatures":[1]})", R"({"features":[1,2)",
          R"({"features":["1,2]})", R"([{"features":[1,2]}])", R"({"other":[1,2]})"})
        EXPECT_FALSE(io_detail::cutFeatures(doubtful)) << doubtful;
}

}  // namespace
}  // namespace flood
