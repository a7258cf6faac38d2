// Narration (flood/teach/narrate.h): one sentence per event, for every action and every forbidden
// reason, naming the fingers, the triangles and why the machine chose what it did.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstring>

#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/teach/narrate.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

bool has(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// The narration of the first event of kind `a` in the run of polygons/`file`.
std::string first(const std::string& file, Action a, Event* out = nullptr) {
    Polygon p = readOrFail(sourcePath("polygons/" + file));
    Trace t = record(p);
    for (const Event& e : t.events)
        if (e.action == a) {
            if (out) *out = e;
            return narrate(p, e);
        }
    ADD_FAILURE() << "no " << actionName(a) << " in " << file;
    return "";
}

}  // namespace

TEST(Narrate, EveryEventIsOneSentence) {
    for (const char* f : {"hole.json", "paper-figure-7.json", "pending-bottoms.json"}) {
        Polygon p = readOrFail(sourcePath(std::string("polygons/") + f));
        Trace t = record(p);
        for (const Event& e : t.events) {
            std::string s = narrate(p, e);
            ASSERT_FALSE(s.empty());
            EXPECT_EQ(s.back(), '.') << s;
            EXPECT_EQ(s.find('\n'), std::string::npos) << s;
            for (unsigned char c : s) EXPECT_LT(c, 128u) << "ASCII only: " << s;
        }
    }
}

TEST(Narrate, RaiseSaysWhichFingerIsLowerAndWhatIsCut) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    bool sawRange = false;
    for (const Event& e : t.events) {
        if (e.action != Action::Raise) continue;
        std::string s = narrate(p, e);
        const char* lower = e.side == Side::Left ? "NextLeft (vertex " : "NextRight (vertex ";
        EXPECT_EQ(s.rfind(lower, 0), 0u) << s;
        EXPECT_TRUE(has(s, "is lower than")) << s;
        EXPECT_TRUE(has(s, "no sag lies between the water and")) << s;
        EXPECT_TRUE(has(s, e.side == Side::Left ? "left bank" : "right bank")) << s;
        if (e.triangleCount > 1) {
            std::string range = std::to_string(e.firstTriangle) + "-" +
                                std::to_string(e.firstTriangle + e.triangleCount - 1);
            EXPECT_TRUE(has(s, "cutting triangles " + range)) << s;
            sawRange = true;
        }
        if (e.triangleCount == 0) {
            EXPECT_TRUE(has(s, "cutting no triangle")) << s;
        }
    }
    EXPECT_TRUE(sawRange);
}

TEST(Narrate, StartBridgeSpillJumpFill) {
    Event e;
    std::string start = first("hole.json", Action::Start, &e);
    EXPECT_TRUE(has(start, "starts at bottom vertex 0")) << start;

    std::string bridge = first("hole.json", Action::Bridge, &e);
    EXPECT_TRUE(has(bridge, "Sag vertex " + std::to_string(e.sag) + " of hole 1")) << bridge;
    EXPECT_TRUE(has(bridge, "bridge joins it to the water at vertex " + std::to_string(e.bridgeTo)))
        << bridge;
    EXPECT_TRUE(has(bridge, "to-do list")) << bridge;

    std::string spill = first("hole.json", Action::Spill, &e);
    EXPECT_TRUE(has(spill, "is a top with no jump pointer")) << spill;
    EXPECT_TRUE(has(spill, "pending gorge")) << spill;  // around the hole onto the other half
    std::string spillToBottom = first("two-gorges.json", Action::Spill, &e);
    EXPECT_TRUE(has(spillToBottom, "to bottom vertex " + std::to_string(e.bottom)))
        << spillToBottom;

    std::string jump = first("hole.json", Action::Jump, &e);
    EXPECT_TRUE(has(jump, "jump pointer is set")) << jump;
    EXPECT_TRUE(has(jump, "other bank at vertex " + std::to_string(e.jumpTarget))) << jump;

    std::string fill = first("monotone.json", Action::Fill, &e);
    EXPECT_TRUE(has(fill, "NextLeft and NextRight meet at vertex ")) << fill;
    EXPECT_TRUE(has(fill, "cutting triangle 3")) << fill;
    EXPECT_TRUE(has(fill, "the part is done")) << fill;
    std::string fillThenPending = first("sag.json", Action::Fill, &e);
    EXPECT_TRUE(has(fillThenPending, "taken from the to-do list")) << fillThenPending;

    std::string sameNext = first("touching-hole.json", Action::Bridge, &e);
    EXPECT_FALSE(sameNext.empty());
}

TEST(Narrate, ForbiddenFromTheMachine) {
    // The paper's Fig. 11 polygons, flooded without validation.
    Event e;
    std::string a = first("invalid/fig11-a-sag-start.json", Action::Forbidden, &e);
    EXPECT_TRUE(has(a, "StartNotBottom")) << a;
    EXPECT_TRUE(has(a, forbiddenText(Forbidden::StartNotBottom))) << a;
    std::string b = first("invalid/fig11-b-ceiling.json", Action::Forbidden, &e);
    EXPECT_TRUE(has(b, "a ceiling, not a top")) << b;
    EXPECT_TRUE(has(b, forbiddenText(Forbidden::CeilingAsEnd))) << b;
}

TEST(Narrate, EveryForbiddenReason) {
    Polygon p = readOrFail(sourcePath("polygons/monotone.json"));
    for (int r = 1; r < int(Forbidden::Count); ++r) {
        Event e;
        e.action = Action::Forbidden;
        e.reason = Forbidden(r);
        e.culprit = 2;
        e.culprit2 = 3;
        std::string s = narrate(p, e);
        EXPECT_TRUE(has(s, forbiddenName(e.reason))) << s;
        EXPECT_TRUE(has(s, forbiddenText(e.reason))) << s;
        EXPECT_EQ(s.back(), '.') << s;
    }
}

TEST(Narrate, SurvivesIndicesOutsideThePolygon) {
    Polygon p = readOrFail(sourcePath("polygons/monotone.json"));
    Event e;
    e.action = Action::Jump;
    e.top = 999;
    e.jumpTarget = kNone;
    std::string s = narrate(p, e);
    EXPECT_TRUE(has(s, "vertex 999")) << s;
    EXPECT_TRUE(has(s, "no vertex")) << s;
}

namespace {

// The first word said twice in a row in `s` ("vertex vertex"), case-insensitive; numbers are
// not words ("triangles 3 4" is no repetition). Empty when there is none.
std::string repeatedWord(const std::string& s) {
    std::string last, word;
    auto endWord = [&]() -> bool {
        if (word.empty()) return false;
        bool number = word.find_first_not_of("0123456789") == std::string::npos;
        bool again = !number && word == last;
        if (!number) last = word;
        word.clear();
        return again;
    };
    for (char ch : s) {
        if (std::isalpha(static_cast<unsigned char>(ch)) ||
            std::isdigit(static_cast<unsigned char>(ch))) {
            word += char(std::tolower(static_cast<unsigned char>(ch)));
            continue;
        }
        std::string w = word;
        if (endWord()) return w;
    }
    std::string w = word;
    return endWord() ? w : "";
}

// Every sentence of the run of `p`, checked for a repeated word.
void expectNoRepeatedWord(const Polygon& p, const std::string& what) {
    Trace t = record(p);
    for (const Event& e : t.events) {
        std::string s = narrate(p, e);
        EXPECT_EQ(repeatedWord(s), "") << what << ", step " << e.step << ": " << s;
    }
}

}  // namespace

TEST(Narrate, RepeatedWordFinder) {
    EXPECT_EQ(repeatedWord("The vertex vertex 7 is"), "vertex");
    EXPECT_EQ(repeatedWord("The Vertex, vertex 7"), "vertex");
    EXPECT_EQ(repeatedWord("triangles 3 3 and vertex 7"), "");
    EXPECT_EQ(repeatedWord("at vertex 7 and vertex 8 of hole 1"), "");
    EXPECT_EQ(repeatedWord("vertex 7 vertex 8"), "vertex") << "numbers are dropped";
    EXPECT_EQ(repeatedWord("ends in the the"), "the");
}

// A lecturer reads the narration aloud: no sentence of the gallery, the samples, the invalid
// samples or the generated families says a word twice in a row.
TEST(Narrate, NoWordRepeatedOnGalleryAndSamples) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json"))
        files.push_back(f);
    for (const std::string& f : files) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok()) continue;  // unreadable samples have no run to narrate
        validate(r.polygon, f);
        expectNoRepeatedWord(r.polygon, f);
    }
    for (const std::string& family : familyNames())
        for (size_t size : {8, 40}) expectNoRepeatedWord(generate(family, 1, size), family);
    for (const std::string& family : invalidFamilyNames())
        expectNoRepeatedWord(generateInvalid(family, 1, 40), "invalid " + family);
    // A coordinate that is not a number: the machine's own refusal (reading refuses it first).
    Polygon nan;
    nan.addRing({{0, 0}, {1, 0}, {std::nan(""), 1}}, true);
    expectNoRepeatedWord(nan, "a NaN coordinate");
}

namespace {

// What a sentence says by number, read back from its text (the test's cross-check only: the
// narration hands the same as data): every "vertex N", and "triangle(s) A[-B]".
struct Said {
    std::vector<Index> vertices;
    uint32_t firstTriangle = 0, triangleCount = 0;
};
Said readBack(const std::string& s) {
    Said said;
    for (size_t at = s.find("vertex "); at != std::string::npos; at = s.find("vertex ", at + 1))
        if (std::isdigit(static_cast<unsigned char>(s[at + 7])))
            said.vertices.push_back(Index(std::stoul(s.substr(at + 7))));
    for (const char* word : {"cutting triangles ", "cutting triangle "}) {
        const size_t at = s.find(word);
        if (at == std::string::npos) continue;
        size_t used = 0;
        const std::string range = s.substr(at + std::strlen(word));
        said.firstTriangle = uint32_t(std::stoul(range, &used));
        said.triangleCount = 1;
        if (range[used] == '-')
            said.triangleCount =
                uint32_t(std::stoul(range.substr(used + 1))) - said.firstTriangle + 1;
        break;
    }
    return said;
}

}  // namespace

// The viewer labels what a sentence names from the narration's data: the data must be every
// vertex and triangle the text names, in the text's order, with a role each.
TEST(Narrate, NamedVerticesAndTrianglesAreWhatTheTextSays) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json"))
        files.push_back(f);
    size_t named = 0;
    for (const std::string& f : files) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok()) continue;
        validate(r.polygon, f);
        Trace t = record(r.polygon);
        for (const Event& e : t.events) {
            const Narration n = narration(r.polygon, e);
            EXPECT_EQ(n.text, narrate(r.polygon, e));
            const Said said = readBack(n.text);
            std::vector<Index> data;
            for (const NamedVertex& v : n.vertices) {
                data.push_back(v.vertex);
                EXPECT_GT(std::strlen(v.role), 0u) << f << ": " << n.text;
            }
            EXPECT_EQ(data, said.vertices) << f << ", step " << e.step + 1 << ": " << n.text;
            EXPECT_EQ(n.firstTriangle, said.firstTriangle) << f << ": " << n.text;
            EXPECT_EQ(n.triangleCount, said.triangleCount) << f << ": " << n.text;
            named += data.size();
        }
    }
    EXPECT_GT(named, 500u);
}

// Issue 27's example, Fig. 7 step 23: the sag, NextRight as it was before the Bridge, and the
// chain vertex the bridge joins, each with its role.
TEST(Narrate, Figure7Step23NamesTheSagNextRightBeforeAndTheBridgeEnd) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    ASSERT_GE(t.events.size(), 23u);
    const Event& e = t.events[22];  // step 23, as the viewer and the CLI number it
    ASSERT_EQ(e.action, Action::Bridge);
    const Narration n = narration(p, e);
    ASSERT_EQ(n.vertices.size(), 3u) << n.text;
    EXPECT_EQ(n.vertices[0].vertex, 35u);
    EXPECT_STREQ(n.vertices[0].role, "sag");
    EXPECT_EQ(n.vertices[1].vertex, 14u);
    EXPECT_STREQ(n.vertices[1].role, "NextRight before");
    EXPECT_EQ(n.vertices[2].vertex, 51u);
    EXPECT_STREQ(n.vertices[2].role, "bridge end");
    EXPECT_EQ(n.firstTriangle, 18u);
    EXPECT_EQ(n.triangleCount, 1u);
    // The fingers it names as before are the event's before, not its after.
    EXPECT_EQ(e.before.nextRight, 14u);
    EXPECT_NE(e.after.nextRight, 14u);
}
