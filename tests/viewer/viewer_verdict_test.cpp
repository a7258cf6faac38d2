// The viewer's model without a window: its verdict (the core's Verdict, one line per finding),
// what the culprits blame, find, traces opened like polygons, the recent files.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "viewer_model_support.h"  // the model, the tests' helpers

// ---- verdicts, culprits, find, traces (issue 11) ------------------------------------------
namespace {
std::string invalidPath(const std::string& f) {
    return std::string(FLOOD_SOURCE_DIR) + "/polygons/invalid/" + f;
}
size_t countKind(const Model& m, Verdict k) {
    size_t n = 0;
    for (const auto& l : m.verdictLines()) n += l.kind == k;
    return n;
}
}  // namespace

TEST(ViewerVerdict, ValidSampleIsOkOnlyBecauseTheCheckerPassed) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    ASSERT_EQ(m.verdictLines().size(), 1u) << m.verdict();
    EXPECT_EQ(m.verdictLines()[0].kind, Verdict::Ok);
    EXPECT_TRUE(m.check().ok);
    EXPECT_FALSE(m.failed());
    EXPECT_EQ(m.exitCode(), 0);
    EXPECT_EQ(m.firstErrorStep(), kNone);
    EXPECT_FALSE(m.showError());
}

TEST(ViewerVerdict, InvalidInputNeverSaysOk) {
    Model m;
    m.open(invalidPath("self-intersection.json"));
    EXPECT_EQ(countKind(m, Verdict::Invalid), 1u) << m.verdict();
    EXPECT_EQ(countKind(m, Verdict::Ok), 0u) << m.verdict();
    EXPECT_EQ(m.verdict().find("ok"), std::string::npos) << m.verdict();
    EXPECT_TRUE(m.failed());
    EXPECT_EQ(m.exitCode(), 4);
}

TEST(ViewerVerdict, ForbiddenRunWithoutValidationHasItsOwnLine) {
    // As `--no-validate`: the polygon is flooded as read; some forbidden-*.json stops the machine.
    bool seen = false;
    for (const char* f : {"forbidden-left-behind.json", "forbidden-bad-triangle.json",
                          "forbidden-fill-open.json", "forbidden-spill-no-bottom.json"}) {
        ReadResult r = readPolygonFile(invalidPath(f));
        ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
        Model m;
        m.openPolygon(r.polygon, f, Diagnostic{});
        if (countKind(m, Verdict::Forbidden) == 0) continue;
        seen = true;
        EXPECT_EQ(m.verdictLines().size(), 1u) << m.verdict();
        EXPECT_EQ(m.exitCode(), 5);
        ASSERT_NE(m.firstErrorStep(), kNone);
        EXPECT_EQ(m.trace().events[m.firstErrorStep() - 1].action, Action::Forbidden);
        const Event& e = m.trace().events[m.firstErrorStep() - 1];
        if (e.culprit != kNone) {
            EXPECT_EQ(m.errorCulprits().vertices.front(), e.culprit) << f;
        }
        EXPECT_EQ(m.trace().diagnostic.culprits.vertices, m.errorCulprits().vertices) << f;
    }
    EXPECT_TRUE(seen);
}

TEST(ViewerVerdict, CheckerRejectionIsShownAndBlamesTheTriangle) {
    // A recorded run of a valid polygon with two triangles swapped in orientation: only the
    // exact checker can tell.
    Polygon p = squareWithHole(false, false);
    ASSERT_TRUE(validate(p, "square").ok());
    Trace t = record(p);
    ASSERT_TRUE(t.diagnostic.ok());
    std::swap(t.triangles[3][0], t.triangles[3][1]);
    Model m;
    m.openTrace(t, "tampered.jsonl");
    ASSERT_EQ(m.verdictLines().size(), 1u) << m.verdict();
    EXPECT_EQ(m.verdictLines()[0].kind, Verdict::Checker);
    EXPECT_NE(m.verdict().find("clockwise-triangle: triangle 3"), std::string::npos) << m.verdict();
    EXPECT_EQ(m.errorCulprits().triangles, std::vector<uint32_t>{3});
    EXPECT_EQ(m.firstErrorStep(), m.triangleStep(3));
    EXPECT_EQ(m.exitCode(), 6);

    Model file;  // the committed one: a ring through one point twice
    file.open(invalidPath("checker-rejects.json"));
    EXPECT_EQ(countKind(file, Verdict::Ok), 0u) << file.verdict();
    EXPECT_TRUE(file.failed());

    // As `--no-validate`: only the checker's rejection (triangle-count), blaming the part's ring.
    ReadResult r = readPolygonFile(invalidPath("checker-rejects.json"));
    Model unchecked;
    unchecked.openPolygon(r.polygon, "checker-rejects.json", Diagnostic{});
    ASSERT_EQ(unchecked.verdictLines().size(), 1u) << unchecked.verdict();
    EXPECT_EQ(unchecked.verdictLines()[0].kind, Verdict::Checker) << unchecked.verdict();
    EXPECT_NE(unchecked.verdict().find("triangle-count"), std::string::npos) << unchecked.verdict();
    EXPECT_EQ(unchecked.errorCulprits().rings, std::vector<uint32_t>{0});
    EXPECT_EQ(unchecked.exitCode(), 6);
    unchecked.setViewport({0, 0, 800, 600});
    EXPECT_TRUE(unchecked.showError());
}

TEST(ViewerCulprits, ValidationBlamesWhatItsMessageNames) {
    // Every vertex the culprits list is named in the message as "ring R vertex V" or as an
    // edge "ring R edge A-B"; the first is the message's global vertex.
    for (const char* f :
         {"self-intersection.json", "spike.json", "vertex-on-own-edge.json", "hole-outside.json",
          "holes-overlapping.json", "point-hole-on-edge.json", "crossing-at-shared-vertex.json",
          "collinear-overlap.json", "zero-area.json"}) {
        Model m;
        m.open(invalidPath(f));
        const Diagnostic& d = m.inputDiagnostic();
        ASSERT_FALSE(d.ok()) << f;
        const Culprits& c = d.culprits;
        ASSERT_FALSE(c.vertices.empty()) << f << ": " << d.message;
        EXPECT_NE(d.message.find("(global vertex " + std::to_string(c.vertices[0]) + ")"),
                  std::string::npos)
            << f << ": " << d.message;
        const Polygon& P = m.polygon();
        for (uint32_t r : c.rings)
            EXPECT_NE(d.message.find("ring " + std::to_string(r)), std::string::npos)
                << f << ": " << d.message;
        for (uint32_t e : c.edges) {
            uint32_t r = P.ringOf(e), local = e - P.rings[r].first;
            if (e == c.vertices[0] && d.message.find("the next edge") != std::string::npos)
                continue;
            EXPECT_NE(d.message.find("ring " + std::to_string(r) + " edge " +
                                     std::to_string(local) + "-"),
                      std::string::npos)
                << f << ": " << d.message;
        }
        EXPECT_EQ(m.offenders().empty(), false);
        for (uint32_t v : c.vertices)
            EXPECT_TRUE(std::binary_search(m.offenders().begin(), m.offenders().end(), v));
        m.setViewport({0, 0, 800, 600});
        EXPECT_TRUE(m.showError()) << f;
        EXPECT_TRUE(m.errorView());
        for (uint32_t v : c.vertices)
            EXPECT_TRUE(m.camera().viewport().contains(m.camera().toScreen(P.vertices[v]))) << f;
    }
}

TEST(ViewerCulprits, GeneratedInvalidFamiliesBlameTheNamedVertex) {
    for (const std::string& family : invalidFamilyNames())
        for (uint64_t seed : {1, 2, 3}) {
            Polygon p = generateInvalid(family, seed, 200);
            Diagnostic d = validate(p, family);
            if (d.ok()) continue;  // random-lattice may need another seed; others always fail
            const Culprits& c = d.culprits;
            ASSERT_FALSE(c.vertices.empty()) << family << ": " << d.message;
            EXPECT_NE(d.message.find("(global vertex " + std::to_string(c.vertices[0]) + ")"),
                      std::string::npos)
                << family << ": " << d.message;
            uint32_t r = p.ringOf(c.vertices[0]);
            EXPECT_NE(d.message.find("ring " + std::to_string(r) + " vertex " +
                                     std::to_string(c.vertices[0] - p.rings[r].first)),
                      std::string::npos)
                << family << ": " << d.message;
            for (uint32_t x : c.rings) EXPECT_LT(x, p.rings.size());
            for (uint32_t v : c.vertices) EXPECT_TRUE(contains(c.rings, p.ringOf(v))) << family;
        }
}

TEST(ViewerCulprits, CrossingEdgesGiveTheCrossingPoint) {
    Model m;
    m.open(invalidPath("self-intersection.json"));  // (0,0)-(10,10) crosses (10,0)-(0,12)
    const Culprits& c = m.inputDiagnostic().culprits;
    ASSERT_EQ(c.edges.size(), 2u) << m.inputDiagnostic().message;
    EXPECT_TRUE(contains(c.edges, 0) && contains(c.edges, 2));
    EXPECT_EQ(c.vertices.size(), 4u);
    Point p;
    ASSERT_TRUE(m.errorPoint(p));
    EXPECT_NEAR(p.x, 60.0 / 11, 1e-9);
    EXPECT_NEAR(p.y, 60.0 / 11, 1e-9);

    Model touch;  // a vertex on its own edge: the point is exact, the vertex's coordinates
    touch.open(invalidPath("vertex-on-own-edge.json"));
    const Culprits& t = touch.inputDiagnostic().culprits;
    ASSERT_TRUE(t.hasPoint) << touch.inputDiagnostic().message;
    EXPECT_EQ(Point({t.x, t.y}), touch.polygon().vertices[t.vertices[0]]);
    EXPECT_EQ(t.edges.size(), 1u);
}

TEST(ViewerFind, EachQueryKindCentresAndSeeks) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    m.fitCamera({0, 0, 800, 600});
    const Polygon& P = m.polygon();
    Vec2 mid{400, 300};
    auto near = [&](Point p) {
        Vec2 s = m.camera().toScreen(p);
        return std::abs(s.x - mid.x) < 1e-6 && std::abs(s.y - mid.y) < 1e-6;
    };
    FindTarget f = m.find("v5");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_TRUE(near(P.vertices[5]));
    ASSERT_NE(f.seekTo, kNone);
    EXPECT_EQ(m.step(), f.seekTo);
    const Event& e = m.trace().events[m.step() - 1];
    bool involved = false;
    for (Index u :
         {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight, e.bottom, e.sag, e.top})
        involved |= u == 5;
    EXPECT_TRUE(involved);

    f = m.find(" T3 ");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_EQ(m.step(), m.triangleStep(3));
    EXPECT_GE(m.state().triangleCount, 4u);

    f = m.find("s7");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_EQ(m.step(), 7u);

    f = m.find("r0");
    ASSERT_TRUE(f.ok) << f.message;
    EXPECT_EQ(m.step(), 7u) << "a ring does not seek";
    for (Index i = 0; i < P.rings[0].count; ++i)
        EXPECT_TRUE(
            m.camera().viewport().contains(m.camera().toScreen(P.vertices[P.rings[0].first + i])));
}

TEST(ViewerFind, BadQueriesSayWhy) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    m.seek(4);
    for (auto [q, why] : std::vector<std::pair<std::string, std::string>>{
             {"", "type v"},
             {"x12", "start with v"},
             {"v", "a number must follow"},
             {"v1x", "a number must follow"},
             {"v-1", "a number must follow"},
             {"v999999", "no vertex 999999: there are"},
             {"t999999", "no triangle"},
             {"s999999", "no step"},
             {"r99", "no ring 99"},
             {"v99999999999999999999", "a number must follow"}}) {
        FindTarget f = m.find(q);
        EXPECT_FALSE(f.ok) << q;
        EXPECT_NE(f.message.find(why), std::string::npos) << q << ": " << f.message;
        EXPECT_EQ(m.step(), 4u) << "a bad query moves nothing";
    }
}

// The binary form (`flood trace --format bin`) opens by its first bytes, whatever its name; a
// damaged one fails naming the file and keeps what was loaded.
TEST(ViewerTraces, BinaryTraceOpensByItsMagic) {
    std::string dir = ::testing::TempDir();
    Polygon p = squareWithHole(false, true);
    ASSERT_TRUE(validate(p, "square").ok());
    Trace t = record(p);
    std::ostringstream out;
    writeBinaryTrace(out, t);
    const std::string bin = out.str();
    std::ofstream(dir + "saved.trace", std::ios::binary) << bin;
    Model m;
    m.open(dir + "saved.trace");
    ASSERT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.steps(), t.events.size());
    EXPECT_EQ(m.verdictLines().at(0).kind, Verdict::Ok) << m.verdict();
    std::ofstream(dir + "cut.bin", std::ios::binary) << bin.substr(0, bin.size() - 3);
    m.open(dir + "cut.bin");
    EXPECT_EQ(m.exitCode(), 3);
    EXPECT_NE(m.openDiagnostic().message.find("cut.bin: "), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.steps(), t.events.size()) << "a failed open keeps the loaded run";
}

TEST(ViewerTraces, OpenLikeAPolygonAndFailWithTheLine) {
    std::string dir = ::testing::TempDir();
    Polygon p = squareWithHole(false, true);
    ASSERT_TRUE(validate(p, "square").ok());
    Trace t = record(p);
    std::ostringstream out;
    writeTrace(out, t);
    std::string text = out.str();
    std::ofstream(dir + "good.jsonl") << text;
    Model m;
    m.open(dir + "good.jsonl");
    EXPECT_TRUE(m.openDiagnostic().ok()) << m.openDiagnostic().message;
    EXPECT_EQ(m.steps(), t.events.size());
    EXPECT_EQ(m.verdictLines().at(0).kind, Verdict::Ok) << m.verdict();
    EXPECT_EQ(m.recentFiles().front().front(), '/');

    Model byHeader;  // any name: the header line says it is a trace
    std::ofstream(dir + "trace-saved-as.txt") << text;
    byHeader.open(dir + "trace-saved-as.txt");
    EXPECT_EQ(byHeader.steps(), t.events.size()) << byHeader.verdict();

    // Truncated mid-way: a failure naming a line; what was loaded stays.
    std::ofstream(dir + "truncated.jsonl") << text.substr(0, text.size() / 2);
    m.open(dir + "truncated.jsonl");
    EXPECT_EQ(m.openDiagnostic().status, Status::Malformed);
    EXPECT_NE(m.openDiagnostic().message.find("truncated.jsonl:"), std::string::npos)
        << m.openDiagnostic().message;
    EXPECT_EQ(m.exitCode(), 3);
    EXPECT_EQ(m.steps(), t.events.size()) << "a failed open keeps the loaded run";
    EXPECT_EQ(m.path(), dir + "good.jsonl");

    // A malformed third line: the message names line 3.
    std::istringstream lines(text);
    std::string l1, l2, rest, l;
    std::getline(lines, l1), std::getline(lines, l2);
    while (std::getline(lines, l)) rest += l + "\n";
    std::ofstream(dir + "bad-line.jsonl") << l1 << "\n" << l2 << "\n{\"action\": 12,\n" << rest;
    Model fresh;
    fresh.open(dir + "bad-line.jsonl");
    EXPECT_EQ(fresh.exitCode(), 3);
    EXPECT_NE(fresh.openDiagnostic().message.find("bad-line.jsonl:3:"), std::string::npos)
        << fresh.openDiagnostic().message;
    EXPECT_TRUE(fresh.failed());
    EXPECT_EQ(fresh.verdictLines().at(0).kind, Verdict::Malformed);
}

TEST(ViewerRecent, AbsolutePathsSavedOnEveryOpen) {
    std::string file = ::testing::TempDir() + "viewer-recent/recent.txt";
    std::remove(file.c_str());
    Model m;
    m.recentPath = file;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
    std::ifstream in(file);
    std::string first;
    ASSERT_TRUE(std::getline(in, first));
    EXPECT_EQ(first.front(), '/');
    EXPECT_NE(first.find("paper-figure-7.json"), std::string::npos);
    m.open("/nonexistent/polygon.json");
    EXPECT_EQ(m.recentFiles().size(), 1u) << "failed opens are not recent";
    EXPECT_NE(m.path().find("paper-figure-7.json"), std::string::npos);
}

#endif
