// The viewer's Transcript panel (viewer/panel_transcript.cpp) draws Model::transcript()'s items
// each followed by its separator: read in order they must be `flood transcript`'s string, with
// the paper's ", " and "; " (Fig. 7's caption).
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "generate.h"
#include "model.h"
#include "replay.h"
#include "test_support.h"
#include "transcript.h"

using namespace flood;
using namespace flood::testing;

namespace {

std::string panelText(const Trace& t) {
    std::string out;
    for (const view::TranscriptItem& it : view::buildTranscript(t)) out += it.text + it.separator;
    return out;
}

}  // namespace

TEST(TranscriptPanel, ItemsKeepThePapersSeparators) {
    size_t withSemicolon = 0;
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json")) {
        Trace t = record(readOrFail(f));
        EXPECT_EQ(panelText(t), transcript(t.events)) << f;
        withSemicolon += transcript(t.events).find("; ") != std::string::npos;
    }
    EXPECT_GT(withSemicolon, 3u);
    for (const std::string& family : familyNames()) {
        Trace t = record(generate(family, 2, 50));
        EXPECT_EQ(panelText(t), transcript(t.events)) << family;
    }
    Trace t = record(readOrFail(sourcePath("polygons/two-gorges.json")));
    auto items = view::buildTranscript(t);
    ASSERT_FALSE(items.empty());
    EXPECT_EQ(items.back().separator, "") << "nothing after the last item";
}
#endif
