// The validator's work grows as n log n on its adversaries: k rings through one point (as parts
// and as holes), an invalid crossing at a point shared by k rings, k parts. Work is counted, not
// timed (flood/geometry/work.h): exact orientation tests plus validatorSteps (pair tests, wedge
// comparisons, loop iterations). Per vertex it must stay within 3x of the smallest k's figure
// (log n alone grows about 2x from 10^2 to 10^5).
#include <gtest/gtest.h>

#include <functional>

#include "flood/geometry/work.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

// k thin triangles with their apex at the origin, fanning over x = m at heights y0 + step * j.
void addFan(Polygon& p, size_t k, double y0, double step, bool outer) {
    double m = 8.0 * double(k);
    for (size_t i = 0; i < k; ++i)
        p.addRing({{0, 0}, {m, y0 + step * double(2 * i)}, {m, y0 + step * double(2 * i + 1)}},
                  outer);
}

Polygon fanOfParts(size_t k) {
    Polygon p;
    addFan(p, k, 0, 1, true);
    return p;
}

Polygon fanOfHoles(size_t k) {
    Polygon p;
    double m = 8.0 * double(k);
    p.addRing({{-1, -1}, {m + 1, -1}, {m + 1, double(2 * k + 1)}, {-1, double(2 * k + 1)}}, true);
    addFan(p, k, 0, 1, false);
    return p;
}

// k - 2 fan triangles below, then two diamonds through (0, 0) and (0, 4) whose wedges
// interleave at both: the only problem is the crossing at the shared point of k rings, between
// its last two rings (a pair search from the lowest rings up meets it last).
Polygon crossingAtSharedPoint(size_t k) {
    Polygon p;
    addFan(p, k - 2, -1, -1, true);
    p.addRing({{0, 0}, {2, 2}, {0, 4}, {-2, 2}}, true);
    p.addRing({{0, 0}, {1, 2}, {0, 4}, {-4, 2}}, true);
    return p;
}

Polygon manyParts(size_t k) {
    Polygon p;
    size_t w = 1;
    while (w * w < k) ++w;
    for (size_t i = 0; i < k; ++i) {
        double x = 3.0 * double(i % w), y = 3.0 * double(i / w);
        p.addRing({{x, y}, {x + 2, y}, {x + 2, y + 2}, {x, y + 2}}, true);
    }
    return p;
}

struct Adversary {
    const char* name;
    std::function<Polygon(size_t)> make;
    bool valid;
    std::function<std::string(size_t)> message;  // for an invalid one: the diagnosis at k
};

std::string crossingMessage(size_t k) {
    return "ring " + std::to_string(k - 2) +
           " vertex 0 (0, 0): the boundary crosses itself at this "
           "shared vertex (ring " +
           std::to_string(k - 1) +
           " vertex 0 (0, 0) passes through to the "
           "other side)";
}

}  // namespace

TEST(ValidateGrowth, WorkPerVertexStaysNearlyFlat) {
    const Adversary adversaries[] = {
        {"k rings through a point (parts)", fanOfParts, true, {}},
        {"k rings through a point (holes)", fanOfHoles, true, {}},
        {"crossing at a point shared by k rings", crossingAtSharedPoint, false, crossingMessage},
        {"k parts", manyParts, true, {}},
    };
    for (const Adversary& a : adversaries) {
        double base = 0;
        for (size_t k : {100, 1000, 10000, 100000}) {
            Polygon p = a.make(k);
            work() = {};
            Diagnostic d = validate(p, "g");
            double perVertex =
                double(work().orientCalls + work().validatorSteps) / double(p.vertices.size());
            EXPECT_EQ(d.ok(), a.valid) << a.name << " at k = " << k << ": " << d.message;
            if (!a.valid) {
                EXPECT_NE(d.message.find(a.message(k)), std::string::npos)
                    << a.name << ": " << d.message;
            }
            if (base == 0) base = perVertex;
            std::cout << "[ WORK ] " << a.name << ", k = " << k << ": " << perVertex
                      << " per vertex\n";
            EXPECT_LE(perVertex, 3 * base)
                << a.name << " at k = " << k << " (k = 100: " << base << ")";
        }
    }
}
