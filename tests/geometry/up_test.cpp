// The flood direction at any angle (issue 12): heights along d compared exactly as the sign of
// d·(b − a), ties along d⊥ = (d.y, −d.x); the machine flooding along any direction; the axes
// unchanged; --up on the command line.
#include <gtest/gtest.h>

#include <gmp.h>

#include <cfloat>
#include <cmath>
#include <random>

#include <sstream>

#include "flood/check/invariants.h"
#include "flood/check/touches.h"
#include "flood/check/verify.h"
#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/machine/vertex_class.h"
#include "flood/teach/transcript.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// The reference: d·(b − a) in GMP rationals, written out independently of predicates.cpp.
int referenceSign(Up d, Point a, Point b) {
    mpq_t sum, t, u;
    mpq_inits(sum, t, u, nullptr);
    const double terms[4][2] = {{d.x, b.x}, {-d.x, a.x}, {d.y, b.y}, {-d.y, a.y}};
    for (const auto& pr : terms) {
        mpq_set_d(t, pr[0]);
        mpq_set_d(u, pr[1]);
        mpq_mul(t, t, u);
        mpq_add(sum, sum, t);
    }
    int s = mpq_sgn(sum);
    mpq_clears(sum, t, u, nullptr);
    return s;
}

TEST(UpPredicates, AdversarialDoubles) {
    const Up tilted{1, 1e-300};
    // Equal x: only the 1e-300 term decides, and its product underflows in doubles.
    EXPECT_EQ(heightSign(tilted, {1, 0}, {1, 1e-30}), 1);
    EXPECT_EQ(heightSign(tilted, {1, 1e-30}, {1, 0}), -1);
    EXPECT_EQ(heightSign(tilted, {1, 5}, {1, 5}), 0);
    // A tie along d, broken along d⊥ = (1e-300, -1).
    EXPECT_EQ(heightSign(Up{1, 1}, {0, 0}, {1, -1}), 0);
    EXPECT_EQ(acrossSign(Up{1, 1}, {0, 0}, {1, -1}), 1);
    EXPECT_TRUE(belowToward(Up{1, 1}, {0, 0}, {1, -1}));
    EXPECT_FALSE(belowToward(Up{1, 1}, {1, -1}, {0, 0}));
    EXPECT_EQ(heightSign(Up{1, 1}, {0, 0}, {1, -1 + 0x1p-52}), 1);
    // Near overflow: b − a overflows, the exact sum is 0 along (1, 1), 4·DBL_MAX across it.
    const Point lo{-DBL_MAX, DBL_MAX}, hi{DBL_MAX, -DBL_MAX};
    EXPECT_EQ(heightSign(Up{1, 1}, lo, hi), 0);
    EXPECT_EQ(acrossSign(Up{1, 1}, lo, hi), 1);
    EXPECT_EQ(heightSign(Up{DBL_MAX, DBL_MAX}, {0, DBL_MAX}, {DBL_MAX, 0}), 0);
    // Subnormals everywhere.
    const double m = 0x1p-1074;
    EXPECT_EQ(heightSign(Up{m, m}, {0, 0}, {m, -m}), 0);
    EXPECT_EQ(heightSign(Up{m, m}, {0, 0}, {2 * m, -m}), 1);
    EXPECT_EQ(heightSign(Up{m, 3 * m}, {m, 0}, {0, m}), 1);  // m·(−m) + 3m·m > 0
    // Cancellation in the filter: 0.1 + ulp against a y term of the same size.
    const double ulp = std::nextafter(0.1, 1) - 0.1;
    EXPECT_EQ(heightSign(Up{1, 1}, {0.1, 0}, {std::nextafter(0.1, 1), -ulp}), 0);
    EXPECT_EQ(heightSign(Up{1, 1}, {0.1, 0}, {std::nextafter(0.1, 1), -ulp / 2}), 1);
}

// Random directions and points across the whole exponent range, many of them near a tie:
// b is a moved along d⊥ (where heights tie) and then nudged by an ulp or two.
TEST(UpPredicates, AgreeWithRationalsOnNearTies) {
    std::mt19937_64 rng(12);
    std::uniform_int_distribution<int> exponent(-1070, 1020);
    std::uniform_real_distribution<double> unit(-1, 1);
    // A random mantissa or a small integer, scaled by a power of two: wide or narrow exponents.
    auto any = [&] {
        double m = rng() % 2 ? unit(rng) : double(int(rng() % 17) - 8);
        return std::ldexp(m, exponent(rng) / (rng() % 4 == 0 ? 1 : 8));
    };
    int ties = 0;
    for (int i = 0; i < 20000; ++i) {
        Up d{any(), any()};
        if (!d.valid()) continue;
        Point a{any(), any()}, b;
        double t = any();
        b = {a.x + t * d.y, a.y - t * d.x};
        for (int k = int(rng() % 3); k-- > 0;)
            b.x = std::nextafter(b.x, (rng() & 1) ? INFINITY : -INFINITY);
        if (!std::isfinite(b.x) || !std::isfinite(b.y)) continue;
        const int want = referenceSign(d, a, b);
        ties += want == 0;
        ASSERT_EQ(heightSign(d, a, b), want)
            << "d = (" << d.x << ", " << d.y << "), a = (" << a.x << ", " << a.y << "), b = ("
            << b.x << ", " << b.y << ")";
        ASSERT_EQ(acrossSign(d, a, b), referenceSign(Up{d.y, -d.x}, a, b));
    }
    EXPECT_GT(ties, 100) << "the generator should produce exact ties";
}

// Along the axes belowToward is the comparison of today: coordinates after the machine's exact
// quarter turn (+x: (−y, x); −y: (−x, −y); −x: (y, −x)), then below(); any length of d.
TEST(UpPredicates, AxesAreTheCoordinateOrder) {
    auto turned = [](Up up, Point p) -> Point {
        if (up.x == 0) return up.y > 0 ? p : Point{-p.x, -p.y};
        return up.x > 0 ? Point{-p.y, p.x} : Point{p.y, -p.x};
    };
    std::mt19937_64 rng(3);
    for (Up up : {Up::PlusY, Up::MinusY, Up::PlusX, Up::MinusX})
        for (int i = 0; i < 2000; ++i) {
            Point a{double(rng() % 5), double(rng() % 5)}, b{double(rng() % 5), double(rng() % 5)};
            const bool want = below(turned(up, a), turned(up, b));
            EXPECT_EQ(belowToward(up, a, b), want);
            EXPECT_EQ(belowToward(Up{up.x * 7, up.y * 7}, a, b), want);
            // The general stages agree with the fast path.
            int h = heightSign(up, a, b);
            EXPECT_EQ(h != 0 ? h > 0 : acrossSign(up, a, b) > 0, want);
        }
}

TEST(UpParse, AnglesVectorsAndAxes) {
    EXPECT_EQ(upFromDegrees(90), Up::PlusY);
    EXPECT_EQ(upFromDegrees(0), Up::PlusX);
    EXPECT_EQ(upFromDegrees(180), Up::MinusX);
    EXPECT_EQ(upFromDegrees(270), Up::MinusY);
    EXPECT_EQ(upFromDegrees(-90), Up::MinusY);
    EXPECT_EQ(upFromDegrees(450), Up::PlusY);
    EXPECT_NEAR(upDegrees(upFromDegrees(17)), 17, 1e-12);
    EXPECT_NEAR(upDegrees(upFromDegrees(-27)), 333, 1e-12);
    EXPECT_EQ(upDegrees(Up::MinusY), 270);
    Up d;
    std::string why;
    ASSERT_TRUE(parseUp("-x", d, why));
    EXPECT_EQ(d, Up::MinusX);
    ASSERT_TRUE(parseUp("90", d, why));
    EXPECT_EQ(d, Up::PlusY);
    ASSERT_TRUE(parseUp("1,-2.5", d, why));
    EXPECT_EQ(d, (Up{1, -2.5}));
    ASSERT_TRUE(parseUp("4.9e-324,0", d, why)) << why;
    EXPECT_EQ(upName(d), "5e-324,0");
    EXPECT_EQ(upName(Up{1, 1e-300}), "1,1e-300");
    for (const char* bad : {"banana", "0,0", "1,nan", "inf", "1,", ",2", "", "12deg", "1,2,3"}) {
        EXPECT_FALSE(parseUp(bad, d, why)) << bad;
        EXPECT_NE(why.find(std::string("'") + bad + "'"), std::string::npos) << why;
    }
}

const double kAngles[] = {17, 90, 200, 333};

std::vector<std::pair<std::string, Polygon>> validSamples() {
    std::vector<std::pair<std::string, Polygon>> out;
    for (const char* dir : {"polygons", "polygons/tutorial", "polygons/regress"})
        for (const std::string& f : filesIn(sourcePath(dir), ".json")) {
            ReadResult r = readPolygonFile(f);
            if (r.diagnostic.ok() && validate(r.polygon, f).ok()) out.emplace_back(f, r.polygon);
        }
    return out;
}

TEST(UpFlood, SamplePolygonsAreExactValidAtAnyAngle) {
    auto samples = validSamples();
    ASSERT_GE(samples.size(), 12u);
    for (const auto& [f, p] : samples)
        for (double angle : kAngles)
            for (size_t shift : {0, 3})
                expectTriangulates(transform(p, 0, false, false, shift),
                                   f + " at " + std::to_string(angle) + "°",
                                   Options{upFromDegrees(angle)});
}

TEST(UpFlood, GeneratedFamiliesAreExactValidAtAnyAngle) {
    for (const std::string& family : familyNames())
        for (size_t size : {8, 40, 300})
            for (uint64_t seed = 0; seed < 3; ++seed) {
                Polygon p = generate(family, seed, size);
                const std::string what =
                    family + " size " + std::to_string(size) + " seed " + std::to_string(seed);
                ASSERT_TRUE(validate(p, what).ok()) << what;
                for (double angle : kAngles)
                    expectTriangulates(p, what + " at " + std::to_string(angle) + "°",
                                       Options{upFromDegrees(angle)});
            }
}

// The axes flood as they did before any angle was possible (transcripts of the build before
// this change: the quarter-turn fast path is unchanged).
TEST(UpFlood, AxisTranscriptsAreAsBefore) {
    Polygon p = readOrFail(sourcePath("polygons/overhang.json"));
    EXPECT_EQ(transcript(record(p, Options{Up::MinusY}).events),
              "Raise, Bridge 0, Raise 1, Spill; Raise, Jump; Raise 2-3, Fill 4; Raise 5-6, Fill 7");
    EXPECT_EQ(transcript(record(p, Options{Up::PlusX}).events),
              "Raise, Bridge 0, Raise 1, Spill; Raise 2, Jump; Raise 3-5, Fill 6; Fill 7");
    EXPECT_EQ(transcript(record(p, Options{Up::MinusX}).events),
              "Raise, Bridge 0, Raise 1, Fill 2; Raise 3, Spill; Raise, Jump; Raise 4-5, Fill 6-7");
    EXPECT_EQ(transcript(record(p, Options{upFromDegrees(180)}).events),
              transcript(record(p, Options{Up::MinusX}).events));
}

// An axis tilted by the least double, d = axis + 2^-1074·d⊥, orders every pair of these
// inputs' vertices as the axis does (its tie-break is d⊥), but goes the way of every other
// direction: exact heights sorted into ranks. The floods must be the axis floods, step for step.
TEST(UpFlood, TheGeneralPathFloodsAnAxisAsTheFastPathDoes) {
    std::vector<std::pair<std::string, Polygon>> inputs = validSamples();
    for (const std::string& family : familyNames())
        inputs.emplace_back(family, generate(family, 5, 200));
    for (const auto& [what, p] : inputs)
        for (Up axis : {Up::PlusY, Up::MinusY, Up::PlusX, Up::MinusX}) {
            const Up tilted{axis.x + 0x1p-1074 * axis.y, axis.y - 0x1p-1074 * axis.x};
            ASSERT_FALSE(tilted.axis());
            Trace fast = record(p, Options{axis}), general = record(p, Options{tilted});
            ASSERT_TRUE(fast.diagnostic.ok()) << what << ": " << fast.diagnostic.message;
            EXPECT_EQ(general.triangles, fast.triangles) << what << " along " << upName(axis);
            EXPECT_EQ(transcript(general.events), transcript(fast.events))
                << what << " along " << upName(axis);
        }
}

// Turning the input a quarter turn and the direction with it gives the same triangles; so
// does scaling the input (or the direction) by a power of two, at every scale.
TEST(UpFlood, TurningInputAndDirectionTogetherChangesNothing) {
    std::vector<std::pair<std::string, Polygon>> inputs = validSamples();
    for (const std::string& family : familyNames())
        inputs.emplace_back(family, generate(family, 9, 120));
    auto scaled = [](Polygon p, int e) {
        for (Point& v : p.vertices) v = {std::ldexp(v.x, e), std::ldexp(v.y, e)};
        return p;
    };
    for (const auto& [what, p] : inputs)
        for (double angle : {17.0, 200.0}) {
            const Up d = upFromDegrees(angle);
            FloodResult base = triangulate(p, nullptr, Options{d});
            ASSERT_TRUE(base.diagnostic.ok()) << what << ": " << base.diagnostic.message;
            Polygon turned = transform(p, 1, false, false, 0);
            EXPECT_EQ(triangulate(turned, nullptr, Options{Up{-d.y, d.x}}).triangles,
                      base.triangles)
                << what << " at " << angle << "°, turned";
            EXPECT_EQ(
                triangulate(p, nullptr, Options{Up{std::ldexp(d.x, -1060), std::ldexp(d.y, -1060)}})
                    .triangles,
                base.triangles)
                << what << " at " << angle << "°, subnormal direction";
            for (int e : {-1000, 900}) {
                Polygon s = scaled(p, e);
                bool exact = true;  // a subnormal's last bits may be lost: then skip that scale
                for (size_t i = 0; i < s.vertices.size(); ++i)
                    exact &= std::ldexp(s.vertices[i].x, -e) == p.vertices[i].x &&
                             std::ldexp(s.vertices[i].y, -e) == p.vertices[i].y &&
                             std::isfinite(s.vertices[i].x) && std::isfinite(s.vertices[i].y);
                if (!exact) continue;
                s.splits = p.splits;
                EXPECT_EQ(triangulate(s, nullptr, Options{d}).triangles, base.triangles)
                    << what << " at " << angle << "°, scaled by 2^" << e;
            }
        }
}

// The paper's verification (the polygon and its complement) at an angle; invalid input,
// unvalidated, ends in a verdict at any angle (never a crash or a hang).
TEST(UpFlood, VerificationAtAnAngle) {
    for (const auto& [f, p] : validSamples())
        for (double angle : {17.0, 200.0}) {
            Verification v = verify(p, Options{upFromDegrees(angle)});
            EXPECT_TRUE(v.ok()) << f << " at " << angle << "°\n" << v.summary();
        }
    Polygon bowtie;
    bowtie.addRing({{0, 0}, {4, 4}, {4, 0}, {0, 4}}, true);
    EXPECT_FALSE(verify(bowtie, Options{upFromDegrees(17)}).ok());
    Polygon outside;
    outside.addRing({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, true);
    outside.addRing({{10, 10}, {10, 12}, {12, 12}}, false);
    EXPECT_EQ(triangulate(outside, nullptr, Options{upFromDegrees(333)}).failure.reason,
              Forbidden::LeftBehind);
    int tried = 0;
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok()) continue;
        findTouches(r.polygon);  // as --no-validate does
        for (double angle : {17.0, 200.0}) {
            FloodResult fr = triangulate(r.polygon, nullptr, Options{upFromDegrees(angle)});
            if (fr.diagnostic.ok()) checkTriangulation(r.polygon, fr.triangles);
            ++tried;
        }
    }
    EXPECT_GE(tried, 40);
}

TEST(UpFlood, NoDirectionIsRefused) {
    Polygon p = readOrFail(sourcePath("polygons/hole.json"));
    for (Up bad : {Up{0, 0}, Up{NAN, 1}, Up{1, INFINITY}}) {
        FloodResult r = triangulate(p, nullptr, Options{bad});
        EXPECT_EQ(r.diagnostic.status, Status::Usage);
        EXPECT_NE(r.diagnostic.message.find("flood direction"), std::string::npos)
            << r.diagnostic.message;
        EXPECT_TRUE(r.triangles.empty());
    }
}

// Work stays linear off the axes too (tests/machine/growth_test.cpp's measure, plus the exact
// height tests of the one sort, which are O(log n) a vertex).
TEST(UpFlood, WorkPerVertexStaysLinearAtAnAngle) {
    const size_t maxN = [] {
        const char* cap = std::getenv("FLOOD_GROWTH_MAX_N");
        return cap && *cap ? size_t(std::strtoull(cap, nullptr, 10)) : size_t(100000);
    }();
    for (const char* family : {"comb", "spiral", "islands", "ortho-spiral", "star"}) {
        double first = 0;
        for (size_t n = 1000; n <= 100000 && n <= maxN; n *= 10) {
            Polygon p = generate(family, 7, n);
            ASSERT_TRUE(validate(p, family).ok());
            work() = {};
            FloodResult r = triangulate(p, nullptr, Options{upFromDegrees(17)});
            const WorkCounters& w = work();
            const double perVertex =
                double(w.nodeVisits + w.sagTests + w.orientCalls + w.heightCalls) /
                double(p.vertices.size());
            ASSERT_TRUE(r.diagnostic.ok()) << family << " at " << n << ": " << r.diagnostic.message;
            if (n == 1000) first = perVertex;
            EXPECT_LE(perVertex, 2.0 * first) << family << " at " << n << ": " << perVertex
                                              << " per vertex, " << first << " at 1000";
        }
    }
}

// A trace keeps its direction: saved and loaded, and the invariants and vertex classes read it.
TEST(UpTrace, DirectionRoundTripsAndDrivesTheInvariants) {
    Polygon p = readOrFail(sourcePath("polygons/holes.json"));
    for (Up up : {Up::PlusY, Up::MinusX, upFromDegrees(17), Up{1, 1e-300}}) {
        Trace t = record(p, Options{up});
        ASSERT_TRUE(t.diagnostic.ok()) << t.diagnostic.message;
        std::ostringstream out;
        writeTrace(out, t);
        EXPECT_EQ(out.str().find("\"up\"") != std::string::npos, up != Up::PlusY)
            << upName(up);  // +y: as before
        Trace back;
        ASSERT_TRUE(parseTrace(out.str(), "t", back).ok());
        EXPECT_EQ(back.up, up);
        EXPECT_TRUE(checkInvariants(back).empty()) << upName(up);
    }
    // The classes follow the direction: a square turned 45° has one bottom at its lowest corner.
    Polygon square;
    square.addRing({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true);
    std::vector<VertexClass> c = classifyVertices(square, upFromDegrees(45));
    EXPECT_EQ(c[0], VertexClass::Bottom);
    EXPECT_EQ(c[1], VertexClass::Regular);
    EXPECT_EQ(c[2], VertexClass::Ceiling);
    EXPECT_EQ(c[3], VertexClass::Regular);
    Trace bad = record(square, Options{upFromDegrees(45)});
    std::string text;
    {
        std::ostringstream out;
        writeTrace(out, bad);
        text = out.str();
    }
    const size_t at = text.find("\"up\":[");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 6, "\"up\":[0,0],\"was\":[");
    Trace back;
    Diagnostic d = parseTrace(text, "t", back);
    EXPECT_EQ(d.status, Status::Malformed);
    EXPECT_NE(d.message.find("\"up\""), std::string::npos) << d.message;
}

TEST(UpCli, AngleVectorAndAxes) {
    const std::string hole = sourcePath("polygons/hole.json");
    for (const char* up :
         {"--up 17", "--up 1,2", "--up=-y", "--up=-30.5", "--up x", "--up=-1,0.25"}) {
        RunResult r = runCli("triangulate " + hole + " " + up + " -o /dev/null");
        EXPECT_EQ(r.code, 0) << up << ": " << r.out;
    }
    for (const char* up : {"banana", "0,0", "1,nan"}) {
        RunResult r = runCli("triangulate " + hole + " --up=" + up);
        EXPECT_EQ(r.code, 2) << up << ": " << r.out;
        EXPECT_NE(r.out.find(std::string("'") + up + "'"), std::string::npos) << r.out;
    }
}

}  // namespace
