// A large GeoJSON geometry read in pieces by several threads (parsePolygon with a TaskRunner,
// io_json_fast.cpp's parsePieces, cut by io_json_cut.cpp's cutCoordinates): the polygon, its
// warnings and every message are the one-piece read's.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "flood/io/io.h"
#include "flood/tools/generate.h"
#include "io/io_json.h"
#include "io_test_support.h"
#include "test_support.h"

namespace flood {
namespace {

using testing::Backwards;
using testing::twoThreads;
using testing::io::describe;

// The coordinates alone: a bare array of polygons (several parts) or of rings (one).
std::string bare(const std::string& geometry) {
    const size_t at = geometry.find("\"coordinates\":");
    if (at == std::string::npos) return geometry;  // one part: written bare already
    const size_t open = geometry.find('[', at);
    return geometry.substr(open, geometry.rfind(']') - open + 1);
}

// White space between every bracket and comma, as a pretty printer leaves it.
std::string spaced(const std::string& text) {
    std::string out;
    for (char c : text) {
        out += c;
        if (c == ']' || c == ',' || c == '[') out += c == ',' ? "\n  " : " ";
    }
    return out;
}

// `text` read in pieces, run backwards and on two threads: the one-piece read each time.
// Returns whether the pieces were read (false: the document was read in one).
bool expectSameInPieces(const std::string& text, int bareDepth, const std::string& what) {
    const ReadResult whole = parsePolygon(text, "p.json");
    bool pieces = true;
    Backwards back;
    for (const TaskRunner& run : {back.runner(), TaskRunner(twoThreads)}) {
        std::optional<ReadResult> read = io_detail::parsePieces(text, bareDepth, "p.json", run);
        pieces = pieces && read.has_value() && back.most >= 2;
        if (read) {
            EXPECT_TRUE(describe(*read) == describe(whole)) << what;  // (too long to print)
        }
    }
    return pieces;
}

TEST(JsonPieces, GeometriesReadTheSameInPieces) {
    for (const char* family : {"islands", "circle-holes", "grid-holes", "steiner", "t-junctions",
                               "touching-holes", "rooms", "star"}) {
        for (uint64_t seed : {1, 2}) {
            const Polygon p = generate(family, seed, 6000);
            const std::string geometry = geoJsonGeometry(p);
            const int depth = p.parts.size() > 1 ? 4 : 3;
            const std::string what = std::string(family) + " seed " + std::to_string(seed);
            for (const std::string& text :
                 {geometry, bare(geometry), spaced(geometry), spaced(bare(geometry))}) {
                const bool isBare = text[0] == '[';
                // A ring that is most of the document (star's only ring, circle-holes'
                // outer one) would make one piece most of it: that is read in one.
                const bool bigRing =
                    family == std::string("star") || family == std::string("circle-holes");
                EXPECT_EQ(expectSameInPieces(text, isBare ? depth : 0, what), !bigRing) << what;
            }
        }
    }
}

// Documents the pieces must not read as they seem: each is read in one, so its polygon,
// warnings and message are the one-piece read's.
TEST(JsonPieces, AnythingUnusualIsReadInOne) {
    const Polygon p = generate("islands", 3, 4000);
    const std::string g = geoJsonGeometry(p);
    const size_t late = g.find("[[[", g.size() * 7 / 8);  // a polygon in the last piece
    ASSERT_NE(late, std::string::npos);
    const std::string point = g.substr(late + 2, g.find(']', late) - late - 1);  // "[x,y]"
    // Every point given a z member that holds what a cut looks for: "]]],".
    std::string tricky;
    for (size_t i = 0; i < g.size(); ++i) {
        if (g[i] == ']' && i > 0 && std::isdigit(static_cast<unsigned char>(g[i - 1])))
            tricky += ",\"]]],\"";
        tricky += g[i];
    }
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"repeated point", g.substr(0, late + 2) + point + "," + g.substr(late + 2)},
        {"bad number", g.substr(0, late + 3) + "01" + g.substr(late + 3)},
        {"empty ring", g.substr(0, late) + "[[]]," + g.substr(late)},
        {"a member after", g.substr(0, g.size() - 1) + ",\"bbox\":[0,0,1,1]}"},
        {"trailing text", g + " []"},
        {"z members with brackets", tricky},
        {"type after", "{\"coordinates\":" + bare(g) + ",\"type\":\"MultiPolygon\"}"},
        {"a feature", "{\"type\":\"Feature\",\"geometry\":" + g + "}"},
    };
    for (const auto& [what, text] : cases)
        EXPECT_FALSE(expectSameInPieces(text, 0, what)) << what << ": read in pieces";
    // Each change aside, the same document reads in pieces.
    EXPECT_TRUE(expectSameInPieces(g, 0, "as written"));
}

// Every cut falls between two whole elements: the text before it closes as many brackets as
// it opens, but for the array's own.
TEST(JsonPieces, CutsFallBetweenElements) {
    for (const char* family : {"islands", "circle-holes"}) {
        const Polygon p = generate(family, 5, 8000);
        const std::string g = spaced(geoJsonGeometry(p));
        for (size_t pieces : {2, 3, 8, 64}) {
            const std::optional<io_detail::CoordinateCut> cut = io_detail::cutCoordinates(
                g, g[0] == '[' ? (p.parts.size() > 1 ? 4 : 3) : 0, pieces);
            ASSERT_TRUE(cut) << family;
            EXPECT_EQ(cut->depth, p.parts.size() > 1 ? 4 : 3);
            EXPECT_EQ(g[cut->open], '[');
            EXPECT_EQ(g[cut->close], ']');
            EXPECT_GE(cut->commas.size(), pieces / 2) << family << " " << pieces;
            EXPECT_LT(cut->commas.size(), pieces);
            for (size_t c : cut->commas) {
                int depth = 0;
                for (size_t i = cut->open + 1; i < c; ++i) depth += (g[i] == '[') - (g[i] == ']');
                EXPECT_EQ(depth, 0) << family << " cut at " << c;
                EXPECT_EQ(g[c], ',');
            }
        }
    }
}

// Through the file reader, from kPiecesFrom bytes: the same polygon with and without threads.
TEST(JsonPieces, ALargeFileReadsTheSameOnTwoThreads) {
    const Polygon p = generate("islands", 1, 450000);
    const std::filesystem::path file = testing::scratch("pieces") / "islands.json";
    ASSERT_TRUE(saveGeoJson(p, file.string()).ok());
    ASSERT_GE(std::filesystem::file_size(file), io_detail::kPiecesFrom);
    Backwards back;
    const ReadResult one = readPolygonFile(file.string());
    EXPECT_TRUE(describe(readPolygonFile(file.string(), kDefaultMaxInputBytes, nullptr,
                                         back.runner())) == describe(one));
    EXPECT_EQ(back.calls, 1u);
    EXPECT_TRUE(describe(readPolygonFile(file.string(), kDefaultMaxInputBytes, nullptr,
                                         twoThreads)) == describe(one));
    EXPECT_EQ(one.polygon.vertices.size(), p.vertices.size());
    std::filesystem::remove_all(file.parent_path());
}

}  // namespace
}  // namespace flood
