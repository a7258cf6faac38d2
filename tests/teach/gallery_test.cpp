// The teaching gallery (polygons/gallery.json, docs/TUTORIAL.md) and the replica of the
// paper's Figures 7-8 (polygons/paper-figure-7.json): every entry exists, valid polygons flood
// with their golden action sequence, the two Fig. 11 polygons are refused by validation and
// stop in the forbidden state the paper describes.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/machine/flood.h"
#include "flood/teach/transcript.h"
#include "golden_transcripts.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// The action words of a run, as the transcript groups them (consecutive raises are one).
std::string actionWords(const std::vector<Event>& events) {
    std::string out, sep;
    Action last = Action::Start;
    for (const Event& e : events) {
        if (e.action == Action::Start) continue;
        if (e.action == Action::Raise && last == Action::Raise) continue;
        bool ends = last == Action::Spill || last == Action::Jump || last == Action::Fill;
        out += (out.empty() ? "" : ends ? "; " : ", ");
        out += actionName(e.action);
        last = e.action;
    }
    return out;
}

// The words of a transcript, numbers dropped: "Raise 0-7, Spill" -> "Raise, Spill".
std::string wordsOf(const std::string& transcript) {
    std::string out;
    for (char c : transcript)
        if (!(c >= '0' && c <= '9') && c != '-') out += c;
    std::string squeezed;
    for (size_t i = 0; i < out.size(); ++i)
        if (!(out[i] == ' ' && (i + 1 == out.size() || out[i + 1] == ',' || out[i + 1] == ';')))
            squeezed += out[i];
    return squeezed;
}

struct Entry {
    std::string file, title, description;
};

std::vector<Entry> gallery() {
    std::ifstream in(sourcePath("polygons/gallery.json"));
    EXPECT_TRUE(in) << "polygons/gallery.json is missing";
    std::vector<Entry> out;
    if (!in) return out;
    nlohmann::json j = nlohmann::json::parse(in);
    for (const auto& e : j) out.push_back({e.at("file"), e.at("title"), e.at("description")});
    return out;
}

}  // namespace

// The paper's Fig. 7 caption reads, as action words:
//   Raise, Spill; Raise, Jump; Raise, Bridge, Raise, Spill, Raise, Jump; Raise, Fill;
//   Raise, Bridge; Raise, Jump; Bridge, Raise, Spill, Raise, Jump, Raise, Fill
// It has four Jumps and three Spills. In Flood (as in the paper's §4) only a Spill sets a jump
// pointer and a Jump clears it, so a valid run has as many Jumps as Spills: the caption
// cannot be reproduced word for word. The replica differs in one word, the fifth group
// "Raise 42-45, Jump" becomes "Raise 42-44, Fill 45" (the gorge between the two stalactites
// closes at its ceiling), which also accounts for the paper's three loops: fills = 1 + the
// bridges that split a loop (two stalactites) = 3.
TEST(Gallery, PaperFigure7ActionSequence) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
    EXPECT_EQ(t.triangles.size(), 65u);
    EXPECT_EQ(p.expectedTriangles(), 65u);  // n + 2h - 2 = 65 + 2 - 2
    EXPECT_EQ(actionWords(t.events),
              "Raise, Spill; Raise, Jump; Raise, Bridge, Raise, Spill; Raise, Jump; Raise, Fill; "
              "Raise, Bridge, Raise, Fill; Bridge, Raise, Spill; Raise, Jump; Raise, Fill");
    EXPECT_EQ(wordsOf(transcript(t.events)), actionWords(t.events));
    // The ranges: 0-7, 8-12, 19-26, 27-30 and 42-44 as in the paper; our Bridge cuts the wedge
    // the sag sees (docs/ALGORITHM.md), taking the last number of the raise before it
    // (13-17 + 18, 34-40 + 41) or the first after it (46 + 47-52); our Fill cuts its fan, so
    // the paper's "Raise 31-33, Fill" is "Raise 31-32, Fill 33", and its closing
    // "Raise 53-62, Jump, Raise 63-64, Fill" is "Raise 53-61, Jump; Raise 62-63, Fill 64"
    // (after a Jump at least three triangles remain).
    EXPECT_EQ(transcript(t.events),
              "Raise 0-7, Spill; Raise 8-12, Jump; Raise 13-17, Bridge 18, Raise 19-26, Spill; "
              "Raise 27-30, Jump; Raise 31-32, Fill 33; Raise 34-40, Bridge 41, Raise 42-44, "
              "Fill 45; Bridge 46, Raise 47-52, Spill; Raise 53-61, Jump; Raise 62-63, Fill 64");
}

TEST(Gallery, WordsOfDropsNumbers) {
    EXPECT_EQ(wordsOf("Raise 0-7, Spill; Raise, Bridge 9-10, Fill 11"),
              "Raise, Spill; Raise, Bridge, Fill");
}

// The small gallery polygons flood as their golden transcripts say (tests/golden_transcripts.h).
TEST(Gallery, EveryEntryExistsAndFloodsAsDescribed) {
    const std::map<std::string, std::string>& golden = kGoldenTranscripts;
    const std::map<std::string, Forbidden> refused = {
        {"invalid/fig11-a-sag-start.json", Forbidden::StartNotBottom},
        {"invalid/fig11-b-ceiling.json", Forbidden::CeilingAsEnd},
    };
    auto entries = gallery();
    ASSERT_GE(entries.size(), 10u);
    size_t checkedGolden = 0, checkedRefused = 0;
    for (const Entry& g : entries) {
        SCOPED_TRACE(g.file);
        EXPECT_FALSE(g.title.empty());
        EXPECT_FALSE(g.description.empty());
        EXPECT_EQ(g.description.find('\n'), std::string::npos) << "one line each";
        ReadResult rr = readPolygonFile(sourcePath("polygons/" + g.file));
        ASSERT_TRUE(rr.diagnostic.ok()) << rr.diagnostic.message;
        Diagnostic valid = validate(rr.polygon, g.file);
        Trace t = record(rr.polygon);
        if (g.file.rfind("invalid/", 0) == 0) {
            EXPECT_FALSE(valid.ok()) << "an invalid gallery polygon must be refused";
            EXPECT_FALSE(t.diagnostic.ok()) << "and the machine must stop on it";
            auto r = refused.find(g.file);
            if (r != refused.end()) {
                ASSERT_FALSE(t.events.empty());
                EXPECT_EQ(t.events.back().action, Action::Forbidden);
                EXPECT_EQ(t.events.back().reason, r->second)
                    << forbiddenName(t.events.back().reason);
                ++checkedRefused;
            }
            continue;
        }
        EXPECT_TRUE(valid.ok()) << valid.message;
        EXPECT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
        EXPECT_EQ(t.triangles.size(), rr.polygon.expectedTriangles());
        auto gold = golden.find(g.file);
        if (gold != golden.end()) {
            EXPECT_EQ(transcript(t.events), gold->second);
            ++checkedGolden;
        }
    }
    EXPECT_EQ(checkedGolden, 9u)
        << "the gallery's nine small polygons each have a golden transcript";
    EXPECT_EQ(checkedRefused, refused.size()) << "both Fig. 11 polygons are in the gallery";
}
