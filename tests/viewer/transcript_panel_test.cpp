// The viewer's Transcript panel (viewer/panel_transcript.cpp) draws Model::transcript()'s items
// each followed by its separator: they are the core's items (flood/teach/transcript.h), so read in
// order they are `flood transcript`'s string, with the paper's ", " and "; " (Fig. 7's caption).
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "flood/log/replay.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "model.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

void expectCoreItems(const view::Model& m, const std::string& what) {
    SCOPED_TRACE(what);
    std::vector<TranscriptItem> core = transcriptItems(m.trace().events);
    const std::vector<TranscriptItem>& shown = m.transcript();
    ASSERT_EQ(shown.size(), core.size());
    for (size_t i = 0; i < core.size(); ++i) {
        EXPECT_EQ(shown[i].firstEvent, core[i].firstEvent) << "item " << i;
        EXPECT_EQ(shown[i].lastEvent, core[i].lastEvent) << "item " << i;
        EXPECT_EQ(shown[i].text, core[i].text) << "item " << i;
        EXPECT_EQ(shown[i].separator, core[i].separator) << "item " << i;
    }
    EXPECT_EQ(transcript(shown), transcript(m.trace().events));
}

}  // namespace

TEST(TranscriptPanel, ShowsTheCoresItems) {
    size_t withSemicolon = 0;
    for (const std::string& f : filesIn(sourcePath("polygons"), ".json")) {
        view::Model m;
        m.open(f);
        expectCoreItems(m, f);
        withSemicolon += transcript(m.transcript()).find("; ") != std::string::npos;
    }
    EXPECT_GT(withSemicolon, 3u);
    for (const std::string& family : familyNames()) {
        view::Model m;
        m.openPolygon(generate(family, 2, 50), family, {});
        expectCoreItems(m, family);
    }
}
#endif
