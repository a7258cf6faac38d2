// Edited traces (issue 25 item 7): a trace written by `flood trace` with one field changed —
// each action renamed to every other, each vertex, finger, count, gorge id and side changed,
// each field dropped, events deleted or swapped — either loads, and then replays, passes the
// invariant scan, narrates and shows in the viewer's model at every step without reading out
// of bounds, or is refused as Malformed naming the line and the event. It crashed the viewer
// (a heap-buffer-overflow in InvariantChecker::P) when one "Raise" became "Bridge". Run it
// under the sanitizers (scripts/sanitize.sh) for the reads that do not crash.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "flood/check/invariants.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/teach/describe.h"
#include "flood/teach/narrate.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "test_support.h"
#if __has_include("model.h")
#include "canvas_geometry.h"
#include "model.h"
#include "scene.h"
#define FLOOD_HAVE_VIEW_MODEL 1
#endif

using namespace flood;
using nlohmann::json;

namespace {

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

std::string traceText(const Trace& t) {
    std::ostringstream out;
    writeTrace(out, t);
    return out.str();
}

// Every one-field edit of event line `i` (0 is the header), as whole trace texts.
std::vector<std::string> mutationsOfLine(const std::vector<std::string>& lines, size_t i,
                                         size_t vertexCount) {
    std::vector<std::string> out;
    const json original = json::parse(lines[i]);
    auto with = [&](const json& event) {
        std::vector<std::string> copy = lines;
        copy[i] = event.dump();
        out.push_back(joined(copy));
    };
    const json lastVertex = json(vertexCount - 1);
    for (int a = 0; a < int(Action::Count); ++a) {  // the action renamed to every other one
        json e = original;
        if (e["action"] == actionName(Action(a))) continue;
        e["action"] = actionName(Action(a));
        with(e);
    }
    for (const char* key :
         {"bottom", "sag", "bridgeTo", "top", "jumpTarget", "culprit", "culprit2", "water"})
        for (const json& v : {json(nullptr), json(0), lastVertex}) {
            json e = original;
            e[key] = v;
            with(e);
        }
    for (const char* fingers : {"before", "after"})
        for (const char* key : {"left", "right", "nextLeft", "nextRight"})
            for (const json& v : {json(nullptr), lastVertex}) {
                json e = original;
                if (!e.contains(fingers))
                    e[fingers] = {{"left", nullptr},
                                  {"right", nullptr},
                                  {"nextLeft", nullptr},
                                  {"nextRight", nullptr}};
                e[fingers][key] = v;
                with(e);
            }
    for (const char* key : {"chainIndex", "cutLeft", "cutRight", "triangleCount", "firstTriangle",
                            "sagTests", "part"}) {
        const uint64_t was = original.contains(key) ? original[key].get<uint64_t>() : 0;
        for (uint64_t v : {uint64_t(0), was + 1, uint64_t(0xffffffffu)}) {
            json e = original;
            e[key] = v;
            with(e);
        }
    }
    for (const char* key : {"gorgePushed", "gorgePopped"})
        for (const json& v : {json(nullptr), json(0), json(5)}) {
            json e = original;
            e[key] = v;
            with(e);
        }
    for (const char* side : {"Left", "Right"}) {
        json e = original;
        e["side"] = side;
        with(e);
    }
    for (auto it = original.begin(); it != original.end(); ++it) {  // each field dropped
        if (it.key() == "action") continue;
        json e = original;
        e.erase(it.key());
        with(e);
    }
    return out;
}

// Whole-log edits: an event deleted, or two neighbours swapped (steps renumbered).
std::vector<std::string> logMutations(const std::vector<std::string>& lines) {
    std::vector<std::string> out;
    const size_t events = lines.size() - 2;
    auto renumbered = [&](std::vector<std::string> copy) {
        for (size_t k = 1; k + 1 < copy.size(); ++k) {
            json e = json::parse(copy[k]);
            if (k == 1) e.erase("step");
            else e["step"] = k - 1;
            copy[k] = e.dump();
        }
        return joined(copy);
    };
    for (size_t k = 1; k <= events; ++k) {
        std::vector<std::string> copy = lines;
        copy.erase(copy.begin() + long(k));
        out.push_back(renumbered(copy));
        if (k < events) {
            copy = lines;
            std::swap(copy[k], copy[k + 1]);
            out.push_back(renumbered(copy));
        }
    }
    return out;
}

// What the viewer does with a loaded trace, short of drawing: replay both ways, the invariant
// scan, the narration and transcript of every step.
void exercise(const Trace& t) {
    Replay replay(t, 2);  // keyframes every few events: restore() runs too
    for (uint32_t s = 0; s <= replay.size(); ++s) replay.seek(s);
    for (uint32_t s = replay.size() + 1; s-- > 0;) replay.seek(s);
    checkInvariants(t);
    for (const Event& e : t.events) {
        narrate(t.polygon, e);
        describeEvent(t.polygon, e);
    }
    transcript(t.events);
}

#ifdef FLOOD_HAVE_VIEW_MODEL
void exerciseViewer(const Trace& t) {
    view::Model m;
    m.openTrace(t, "edited.jsonl");
    m.setViewport({0, 0, 400, 300});
    m.fitCamera({0, 0, 400, 300});
    view::CanvasGeometry g = view::buildCanvasGeometry(m);
    for (uint32_t s = 0; s <= m.steps(); ++s) {
        m.seek(s);
        m.inspection();
        view::buildScene(m);
        view::buildCanvasOverlay(m, {}, g.origin);
    }
    m.showError();
    m.waitForInvariants();
}
#endif

struct Tally {
    size_t loaded = 0, refused = 0;
};

// Every mutation of the trace of `t`: loaded and exercised, or refused with a line number.
void mutateAll(const Trace& t, const std::string& name, Tally& tally, bool viewer) {
    const std::string text = traceText(t);
    const std::vector<std::string> lines = linesOf(text);
    ASSERT_GE(lines.size(), 3u) << name;
    std::vector<std::string> all = logMutations(lines);
    for (size_t i = 1; i + 1 < lines.size(); ++i) {
        std::vector<std::string> m = mutationsOfLine(lines, i, t.polygon.vertices.size());
        all.insert(all.end(), m.begin(), m.end());
    }
    for (const std::string& edited : all) {
        Trace loaded;
        Diagnostic d = parseTrace(edited, name, loaded);
        if (!d.ok()) {
            ++tally.refused;
            EXPECT_EQ(d.status, Status::Malformed) << d.message;
            EXPECT_EQ(d.message.rfind(name + ":", 0), 0u) << d.message;
            continue;
        }
        ++tally.loaded;
        exercise(loaded);
#ifdef FLOOD_HAVE_VIEW_MODEL
        if (viewer) exerciseViewer(loaded);
#else
        (void)viewer;
#endif
    }
}

Trace recordFile(const std::string& rel, bool validated) {
    ReadResult r = readPolygonFile(flood::testing::sourcePath(rel));
    EXPECT_TRUE(r.diagnostic.ok()) << rel << ": " << r.diagnostic.message;
    if (validated) {
        EXPECT_TRUE(validate(r.polygon, rel).ok()) << rel;
    }
    return record(r.polygon);
}

}  // namespace

// The issue's own edit: hole.json's trace with its first "Raise" renamed "Bridge" is refused,
// and the message names the line and the event.
TEST(TraceMutation, RaiseRenamedBridgeIsRefusedNamingTheLine) {
    Trace t = recordFile("polygons/hole.json", true);
    std::vector<std::string> lines = linesOf(traceText(t));
    size_t i = 1;
    while (i + 1 < lines.size() && lines[i].find("\"Raise\"") == std::string::npos) ++i;
    ASSERT_LT(i + 1, lines.size());
    lines[i].replace(lines[i].find("\"Raise\""), 7, "\"Bridge\"");
    Trace loaded;
    Diagnostic d = parseTrace(joined(lines), "t.jsonl", loaded);
    ASSERT_EQ(d.status, Status::Malformed);
    EXPECT_EQ(d.message, "t.jsonl:" + std::to_string(i + 1) + ": event " + std::to_string(i - 1) +
                             " (Bridge): \"sag\" or \"bridgeTo\" is missing: a Bridge joins a "
                             "sag to the chain");
    EXPECT_TRUE(loaded.events.empty());
}

// Every event the machine records passes the check parseTrace makes: valid and invalid input,
// Steiner points, several parts, spills and jumps, and a run stopped in a forbidden state.
TEST(TraceMutation, EveryRecordedEventPasses) {
    std::vector<Trace> traces;
    for (const std::string& f :
         flood::testing::filesIn(flood::testing::sourcePath("polygons"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (r.diagnostic.ok()) traces.push_back(record(r.polygon));
    }
    for (const std::string& f :
         flood::testing::filesIn(flood::testing::sourcePath("polygons/invalid"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (r.diagnostic.ok()) traces.push_back(record(r.polygon));
    }
    for (const std::string& family : familyNames())
        traces.push_back(record(generate(family, 3, 300)));
    for (const std::string& family : invalidFamilyNames())
        traces.push_back(record(generateInvalid(family, 3, 300)));
    size_t events = 0;
    for (const Trace& t : traces)
        for (const Event& e : t.events) {
            const char* problem =
                eventProblem(e, t.polygon.vertices.size(), t.polygon.parts.size());
            EXPECT_EQ(problem, nullptr) << "event " << e.step << ": " << problem;
            ++events;
        }
    EXPECT_GT(events, 10000u);
}

// Thousands of one-field edits of real traces: none crashes the replay, the invariant scan,
// the narration or the viewer's model; some load, the rest are refused naming their line.
TEST(TraceMutation, EditedTracesLoadAndReplayOrAreRefused) {
    Tally tally;
    mutateAll(recordFile("polygons/hole.json", true), "hole.jsonl", tally, true);
    mutateAll(recordFile("polygons/steiner.json", true), "steiner.jsonl", tally, false);
    mutateAll(recordFile("polygons/pending-bottoms.json", true), "pending.jsonl", tally, false);
    mutateAll(recordFile("polygons/touching-hole.json", true), "touching.jsonl", tally, false);
    mutateAll(record(generate("islands", 1, 12)), "islands.jsonl", tally, false);
    mutateAll(recordFile("polygons/invalid/forbidden-jump-wrong-side.json", false),
              "jump-wrong-side.jsonl", tally, false);
    std::printf("  %zu edited traces loaded and replayed, %zu refused\n", tally.loaded,
                tally.refused);
    EXPECT_GT(tally.loaded, 1000u);
    EXPECT_GT(tally.refused, 1000u);
}
