// Metamorphic tests: exact transforms of a polygon — scaling by 2^k for k from -1000 to 1000
// and to both ends of the double range (subnormal included), a quarter turn, a mirror, a shift
// by 2^40 — must not change any verdict, `flood verify`'s included. Every predicate is
// exact for every finite double, so validate() must give the same Status, the flood must
// succeed exactly when it did, and its triangles must pass the exact checker with the same
// count. Whatever computes with coordinates outside the predicates (the sag index's pruning,
// the height buckets) may only be conservative; these tests catch one that is not.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "flood/check/touches.h"
#include "flood/check/verify.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using flood::testing::filesIn;
using flood::testing::sourcePath;

namespace {

constexpr int kScales[] = {-1000, -500, 0, 500, 1000};
constexpr double kShift = 0x1p40;

// a + b is a double exactly (Knuth's two-sum: the rounding error is zero).
bool sumIsExact(double a, double b) {
    double s = a + b, bv = s - a, av = s - bv;
    return (a - av) + (b - bv) == 0 && std::isfinite(s);
}

// `p` with every vertex mapped by f, or nothing when f is not exact on some coordinate.
// The T-junctions are dropped: validate() must find them again.
std::optional<Polygon> mapped(const Polygon& p,
                              const std::function<std::optional<Point>(Point)>& f) {
    Polygon q = p;
    q.splits.clear();
    for (Point& v : q.vertices) {
        std::optional<Point> w = f(v);
        if (!w) return std::nullopt;
        v = *w;
    }
    return q;
}

// Scaling by 2^k is exact unless a coordinate becomes subnormal (or overflows): then it does
// not scale back, and the input is skipped at that k.
std::optional<Polygon> scaled(const Polygon& p, int k) {
    return mapped(p, [k](Point v) -> std::optional<Point> {
        Point w{std::ldexp(v.x, k), std::ldexp(v.y, k)};
        if (std::ldexp(w.x, -k) != v.x || std::ldexp(w.y, -k) != v.y) return std::nullopt;
        return w;
    });
}

struct Variant {
    std::string name;
    Polygon polygon;
    bool scaleOnly;  // heights keep their order: even an invalid input floods the same way
};

// The scales tested: the fixed ones, and the edges of the double range for this input (its
// largest coordinate just below DBL_MAX, where differences and spans overflow; its smallest
// nonzero one at the least normal double, where products underflow; and its lowest set bit
// at the least subnormal, 2^-1074, where a small integer polygon is subnormal throughout).
std::vector<int> scalesFor(const Polygon& p) {
    std::vector<int> ks(std::begin(kScales), std::end(kScales));
    int eMax = INT_MIN, eMin = INT_MAX, lowBit = INT_MAX;
    for (Point v : p.vertices)
        for (double c : {v.x, v.y})
            if (c != 0 && std::isfinite(c)) {
                int e;
                double m = std::frexp(c, &e);  // |c| in [2^(e-1), 2^e)
                eMax = std::max(eMax, e), eMin = std::min(eMin, e);
                int low = e - 53;  // c = M 2^(e-53), M an integer: its lowest set bit
                for (double M = std::ldexp(std::fabs(m), 53); std::fmod(M, 2) == 0; M /= 2) ++low;
                lowBit = std::min(lowBit, low);
            }
    if (eMax != INT_MIN)
        ks.push_back(1024 - eMax), ks.push_back(-1021 - eMin), ks.push_back(-1074 - lowBit);
    return ks;
}

// The transformed copies of `p`; `skipped` names the ones that would not be exact.
std::vector<Variant> variants(const Polygon& p, std::vector<std::string>& skipped) {
    std::vector<Variant> out;
    for (int k : scalesFor(p)) {
        std::string s = "2^" + std::to_string(k);
        std::optional<Polygon> q = scaled(p, k);
        if (!q) {
            skipped.push_back(s + " (a coordinate would be subnormal or overflow)");
            continue;
        }
        out.push_back({s, *q, true});
        out.push_back({s + " turned 90°",
                       *mapped(*q,
                               [](Point v) {
                                   return Point{-v.y, v.x};
                               }),
                       false});
        out.push_back({s + " mirrored",
                       *mapped(*q,
                               [](Point v) {
                                   return Point{-v.x, v.y};
                               }),
                       false});
    }
    // The shift is exact only where every coordinate + 2^40 is a double (integer families are;
    // the sin/cos ones are not): checked per coordinate, the input skipped otherwise.
    std::optional<Polygon> shifted = mapped(p, [](Point v) -> std::optional<Point> {
        if (!sumIsExact(v.x, kShift) || !sumIsExact(v.y, kShift)) return std::nullopt;
        return Point{v.x + kShift, v.y + kShift};
    });
    if (shifted) out.push_back({"shifted by 2^40", *shifted, false});
    else skipped.push_back("shift by 2^40 (not exact)");
    return out;
}

// `flood verify` of p as the CLI runs it: p validated (its T-junctions found), or not, then
// its T-junctions found as on the unvalidated path.
Verification verified(Polygon p, bool valid) {
    if (!valid) findTouches(p);
    return verify(p);
}

// Every variant of `original` gets the original's verdicts (validation, and the flood of a
// valid polygon: exact, same triangle count; of an invalid one: the same Status under scaling;
// the verification (the polygon and its complement, flooded and checked exactly) of a valid
// one passes, of an invalid one ends caught by the same check under scaling).
void expectSameVerdicts(const Polygon& original, const std::string& what) {
    Polygon base = original;
    base.splits.clear();
    const Status valid = validate(base, what).status;
    const FloodResult baseFlood = triangulate(base);
    const Verification baseVerified = verified(base, valid == Status::Ok);
    if (valid == Status::Ok) {
        ASSERT_TRUE(baseFlood.diagnostic.ok()) << what << ": " << baseFlood.diagnostic.message;
        ASSERT_EQ(baseFlood.triangles.size(), base.expectedTriangles()) << what;
        ASSERT_TRUE(baseVerified.ok()) << what << ": " << baseVerified.summary();
    }
    std::vector<std::string> skipped;
    for (Variant& v : variants(original, skipped)) {
        const std::string name = what + " " + v.name;
        Diagnostic d = validate(v.polygon, name);
        EXPECT_EQ(d.status, valid) << name << ": " << d.message;
        FloodResult r = triangulate(v.polygon);
        const Verification ver = verified(v.polygon, d.ok());
        if (valid == Status::Ok) {
            EXPECT_TRUE(r.diagnostic.ok()) << name << ": " << r.diagnostic.message;
            CheckResult c = checkTriangulation(v.polygon, r.triangles);
            EXPECT_TRUE(c.ok) << name << ": " << c.reason;
            EXPECT_EQ(r.triangles.size(), baseFlood.triangles.size()) << name;
            EXPECT_TRUE(ver.ok()) << name << ": " << ver.summary();
            EXPECT_EQ(ver.complementFlood.triangles.size(),
                      baseVerified.complementFlood.triangles.size())
                << name;
        } else if (v.scaleOnly) {
            EXPECT_EQ(r.diagnostic.status, baseFlood.diagnostic.status)
                << name << ": " << r.diagnostic.message;
            EXPECT_EQ(ver.caught(), baseVerified.caught()) << name << ": " << ver.summary();
        }
    }
    for (const std::string& s : skipped) std::cout << "  " << what << ": skipped " << s << "\n";
}

}  // namespace

TEST(Metamorphic, SamplePolygonsAtEveryScale) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    ASSERT_FALSE(files.empty());
    for (const std::string& f : files) {
        ReadResult r = readPolygonFile(f);
        ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
        expectSameVerdicts(r.polygon, f);
    }
}

// Invalid polygons (not malformed files, which never reach a verdict): refused the same way.
TEST(Metamorphic, InvalidSamplesAtEveryScale) {
    int tested = 0;
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json")) {
        ReadResult r = readPolygonFile(f);
        if (!r.diagnostic.ok()) continue;
        Polygon p = r.polygon;
        ASSERT_FALSE(validate(p, f).ok()) << f << " is in polygons/invalid but validates";
        expectSameVerdicts(r.polygon, f);
        ++tested;
    }
    EXPECT_GE(tested, 20);
}

TEST(Metamorphic, GeneratedFamiliesAtEveryScale) {
    for (const std::string& family : familyNames())
        for (size_t size : {30, 300})
            expectSameVerdicts(generate(family, 1, size), family + " size " + std::to_string(size));
}
