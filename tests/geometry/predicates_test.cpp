// Exactness of orient(), inside() and ExactSum on nasty inputs, against a GMP reference.
#include <gmp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"

using flood::ExactSum;
using flood::inside;
using flood::orient;
using flood::Point;

namespace {

// Reference: sign of the doubled area computed with rationals.
int orientRef(Point a, Point b, Point c) {
    mpq_t acx, bcy, acy, bcx, t, u;
    mpq_inits(acx, bcy, acy, bcx, t, u, nullptr);
    mpq_set_d(t, a.x), mpq_set_d(u, c.x), mpq_sub(acx, t, u);
    mpq_set_d(t, b.y), mpq_set_d(u, c.y), mpq_sub(bcy, t, u);
    mpq_set_d(t, a.y), mpq_set_d(u, c.y), mpq_sub(acy, t, u);
    mpq_set_d(t, b.x), mpq_set_d(u, c.x), mpq_sub(bcx, t, u);
    mpq_mul(t, acx, bcy);
    mpq_mul(u, acy, bcx);
    mpq_sub(t, t, u);
    int s = mpq_sgn(t);
    mpq_clears(acx, bcy, acy, bcx, t, u, nullptr);
    return s;
}

// Checks orient against the reference and its permutation antisymmetry.
void expectOrient(Point a, Point b, Point c) {
    int r = orientRef(a, b, c);
    ASSERT_EQ(orient(a, b, c), r) << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x
                                  << "," << c.y;
    ASSERT_EQ(orient(b, c, a), r);
    ASSERT_EQ(orient(c, a, b), r);
    ASSERT_EQ(orient(b, a, c), -r);
    ASSERT_EQ(orient(a, c, b), -r);
    ASSERT_EQ(orient(c, b, a), -r);
}

double randomMagnitude(std::mt19937_64& rng, int minExp, int maxExp) {
    std::uniform_real_distribution<double> m(0.5, 1.0);
    std::uniform_int_distribution<int> e(minExp, maxExp);
    double v = std::ldexp(m(rng), e(rng));
    return (rng() & 1) ? v : -v;
}

}  // namespace

TEST(Orient, SimpleCases) {
    EXPECT_EQ(orient({0, 0}, {1, 0}, {0, 1}), 1);
    EXPECT_EQ(orient({0, 0}, {0, 1}, {1, 0}), -1);
    EXPECT_EQ(orient({0, 0}, {1, 1}, {2, 2}), 0);
    EXPECT_EQ(orient({0, 0}, {0, 0}, {2, 2}), 0);
    EXPECT_EQ(orient({3, 3}, {3, 3}, {3, 3}), 0);
}

TEST(Orient, NearlyCollinearOnDiagonal) {
    // Points on y = x, with the third nudged by one ulp-scale step either way.
    const double eps = std::ldexp(1.0, -52);
    for (int i = 0; i < 200; ++i) {
        double t = 0.5 + i * 0.0123;
        Point a{t, t}, b{24 + t, 24 + t}, c{12 + t, 12 + t};
        expectOrient(a, b, c);
        expectOrient(a, b, {c.x, std::nextafter(c.y, 100.0)});
        expectOrient(a, b, {c.x, std::nextafter(c.y, -100.0)});
        expectOrient({0.5 + eps, 0.5}, {12, 12}, {24, 24});
        expectOrient({0.5, 0.5 + eps * i}, {12, 12}, {24, 24});
    }
    // The classic: orient((x, x), (12, 12), (24, 24)) for x near 0.5 on a 2^-53 grid.
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j)
            expectOrient({0.5 + i * eps, 0.5 + j * eps}, {12, 12}, {24, 24});
}

TEST(Orient, IntegerGrid) {
    for (int ax = -3; ax <= 3; ++ax)
        for (int ay = -3; ay <= 3; ++ay)
            for (int bx = -2; bx <= 2; ++bx)
                for (int by = -2; by <= 2; ++by)
                    for (int cx = -2; cx <= 2; ++cx)
                        for (int cy = -2; cy <= 2; ++cy)
                            expectOrient({double(ax), double(ay)}, {double(bx), double(by)},
                                         {double(cx), double(cy)});
    // Large integers where products exceed 2^53.
    const double big = 9007199254740993.0 - 1;  // 2^53
    expectOrient({big, big - 1}, {big - 2, big - 3}, {big - 4, big - 5});
    expectOrient({big, big - 1}, {big - 2, big - 3}, {big - 4, big - 4});
}

TEST(Orient, HugeAndTinyCoordinates) {
    expectOrient({1e300, 1e300}, {-1e300, -1e300}, {1e300, -1e300});
    expectOrient({1e300, 1e300}, {-1e300, -1e300}, {0.5e300, 0.5e300});
    expectOrient({1e308, 1e308}, {-1e308, -1e308}, {1.5e308, 1.5e308});
    expectOrient({1e308, 1e308}, {-1e308, -1e308}, {1.5e308, std::nextafter(1.5e308, 0.0)});
    const double dmax = std::numeric_limits<double>::max();
    expectOrient({dmax, dmax}, {-dmax, -dmax}, {dmax, -dmax});
    expectOrient({dmax, 0}, {-dmax, 0}, {0, std::numeric_limits<double>::denorm_min()});
    expectOrient({1e-300, 1e-300}, {2e-300, 2e-300}, {3e-300, 3e-300});
    expectOrient({1e-300, 1e-300}, {2e-300, 2e-300}, {3e-300, std::nextafter(3e-300, 1.0)});
    const double sub = std::numeric_limits<double>::denorm_min();
    expectOrient({0, 0}, {sub, sub}, {2 * sub, 2 * sub});
    expectOrient({0, 0}, {sub, 0}, {0, sub});
    expectOrient({0, 0}, {3 * sub, sub}, {6 * sub, 2 * sub + sub});
    expectOrient({sub, sub}, {1, 1}, {1e300, 1e300});
    expectOrient({sub, 0}, {1, 1}, {1e300, 1e300});
    expectOrient({1e-200, 1e200}, {1e200, 1e-200}, {-1e-200, 1e200 + 1e184});
}

TEST(Orient, RandomNearlyCollinearAgainstGmp) {
    std::mt19937_64 rng(12345);
    const int ranges[][2] = {{-10, 10},    {-1074, -1000}, {-600, -400}, {400, 600},
                             {1000, 1023}, {-1074, 1023},  {-30, 30}};
    for (auto& range : ranges) {
        for (int i = 0; i < 3000; ++i) {
            Point a{randomMagnitude(rng, range[0], range[1]),
                    randomMagnitude(rng, range[0], range[1])};
            Point b{randomMagnitude(rng, range[0], range[1]),
                    randomMagnitude(rng, range[0], range[1])};
            // c on the segment ab (rounded), then nudged by a few ulps.
            double t = std::ldexp(double(rng() % 1024), -10);
            Point c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            if (!std::isfinite(c.x) || !std::isfinite(c.y))
                c = {a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
            int nudge = int(rng() % 5) - 2;
            for (int k = 0; k < std::abs(nudge); ++k)
                c.y = std::nextafter(c.y, nudge > 0 ? HUGE_VAL : -HUGE_VAL);
            expectOrient(a, b, c);
            // And fully random triples of mixed magnitudes.
            Point d{randomMagnitude(rng, range[0], range[1]),
                    randomMagnitude(rng, range[0], range[1])};
            expectOrient(a, b, d);
        }
    }
}

TEST(Inside, ConvexQuadrangle) {
    // Left (0,0), Right (4,0), NextRight (4,4), NextLeft (0,4): counter-clockwise square.
    Point l{0, 0}, r{4, 0}, nr{4, 4}, nl{0, 4};
    EXPECT_TRUE(inside({2, 2}, l, r, nr, nl));
    EXPECT_TRUE(inside({0.001, 3.999}, l, r, nr, nl));
    for (Point corner : {l, r, nr, nl}) EXPECT_FALSE(inside(corner, l, r, nr, nl));
    EXPECT_FALSE(inside({2, 0}, l, r, nr, nl));  // on edges: boundary is not inside
    EXPECT_FALSE(inside({4, 2}, l, r, nr, nl));
    EXPECT_FALSE(inside({2, 4}, l, r, nr, nl));
    EXPECT_FALSE(inside({0, 2}, l, r, nr, nl));
    EXPECT_FALSE(inside({5, 2}, l, r, nr, nl));
    EXPECT_FALSE(inside({2, -1e-300}, l, r, nr, nl));
    EXPECT_TRUE(inside({2, 1e-300}, l, r, nr, nl));
    // Same answers for the clockwise order.
    EXPECT_TRUE(inside({2, 2}, l, nl, nr, r));
    EXPECT_FALSE(inside({2, 0}, l, nl, nr, r));
}

TEST(Inside, ConcaveAndDegenerateQuadrangles) {
    // Dart, reflex at NextRight.
    Point a{0, 0}, b{4, 2}, c{2, 2}, d{0, 4};  // reflex at c
    EXPECT_TRUE(inside({1, 2}, a, b, c, d));
    EXPECT_FALSE(inside({3, 2.5}, a, b, c, d));  // in the notch, outside
    EXPECT_FALSE(inside({3, 1.5}, a, b, c, d));  // on edge a-b
    EXPECT_FALSE(inside(c, a, b, c, d));
    EXPECT_FALSE(inside({1, 3}, a, b, c, d));  // on edge c-d
    EXPECT_TRUE(inside({1, 2.9}, a, b, c, d));
    // Self-crossing (bow-tie) order: both lobes count, the crossing point is on the boundary.
    Point l{0, 0}, r{4, 4}, nr{4, 0}, nl{0, 4};
    EXPECT_TRUE(inside({1, 2}, l, r, nr, nl));
    EXPECT_TRUE(inside({3, 2}, l, r, nr, nl));
    EXPECT_FALSE(inside({2, 2}, l, r, nr, nl));
    EXPECT_FALSE(inside({2, 1}, l, r, nr, nl));
    // Triangle with a repeated vertex (NextLeft == Left).
    Point t0{0, 0}, t1{4, 0}, t2{0, 4};
    EXPECT_TRUE(inside({1, 1}, t0, t1, t2, t0));
    EXPECT_FALSE(inside({2, 2}, t0, t1, t2, t0));
    EXPECT_FALSE(inside({3, 3}, t0, t1, t2, t0));
    // Fully degenerate: collinear quadrangle has no interior.
    EXPECT_FALSE(inside({1, 1}, {0, 0}, {4, 4}, {3, 3}, {2, 2}));
    EXPECT_FALSE(inside({1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}));
    // Nearly degenerate: a sliver, s one ulp above/below its long edge.
    Point s0{0, 0}, s1{1, 1}, s2{1, std::nextafter(1.0, 2.0)}, s3{0.5, std::nextafter(0.5, 1.0)};
    EXPECT_FALSE(inside({0.25, 0.25}, s0, s1, s2, s3));
}

TEST(ExactSumTest, CancellationAndEquality) {
    ExactSum s;
    s.addProduct(1e16, 1e16);
    s.addProduct(1, 1);
    s.addProduct(-1e16, 1e16);
    EXPECT_EQ(s.sign(), 1);
    EXPECT_EQ(s.approx(), 1.0);
    s.addProduct(-1, 1);
    EXPECT_EQ(s.sign(), 0);
    EXPECT_TRUE(s == ExactSum());

    // Same value built two ways, including GMP-range products.
    ExactSum a, b;
    a.addProduct(1e300, 1e300);
    a.addProduct(3, 0.1);
    b.addProduct(0.1, 3);
    b.addProduct(1e300, 1e300);
    EXPECT_TRUE(a == b);
    b.addProduct(1e-300, 1e-300);
    EXPECT_FALSE(a == b);
    EXPECT_EQ(b.sign(), 1);
    ExactSum c = b;
    c.add(a, -1);
    EXPECT_EQ(c.sign(), 1);
    c.addProduct(-1e-300, 1e-300);
    EXPECT_EQ(c.sign(), 0);
    c.add(c, 1);  // self-add
    EXPECT_EQ(c.sign(), 0);
}

TEST(ExactSumTest, ManyTermsStayShortAndExact) {
    std::mt19937_64 rng(7);
    ExactSum s;
    mpq_t ref, t, u;
    mpq_inits(ref, t, u, nullptr);
    std::uniform_real_distribution<double> d(-1e6, 1e6);
    for (int i = 0; i < 100000; ++i) {
        double x = d(rng), y = d(rng);
        s.addProduct(x, y);
        mpq_set_d(t, x), mpq_set_d(u, y), mpq_mul(t, t, u), mpq_add(ref, ref, t);
    }
    EXPECT_LT(s.size(), 40u);
    EXPECT_EQ(s.sign(), mpq_sgn(ref));
    EXPECT_NEAR(s.approx(), mpq_get_d(ref), std::fabs(mpq_get_d(ref)) * 1e-15);
    mpq_clears(ref, t, u, nullptr);
}

TEST(ExactSumTest, TriangleAreas) {
    ExactSum sq, tris;
    Point p[4] = {{0, 0}, {1e-310, 0}, {1e-310, 3}, {0, 3}};
    for (int i = 0; i < 4; ++i) sq.addCross(p[i], p[(i + 1) % 4]);
    tris.addTriangle(p[0], p[1], p[2]);
    tris.addTriangle(p[0], p[2], p[3]);
    EXPECT_EQ(sq.sign(), 1);
    EXPECT_TRUE(sq == tris);
}

// orientExplained() runs orient()'s stages and says which decided: the filter for plain
// input, expansions for near-degenerate points, rationals for extreme exponents.
TEST(OrientExplained, EachStageDecidesItsInputs) {
    using flood::orientExplained;
    using flood::Stage;
    auto r = orientExplained({0, 0}, {1, 0}, {0, 1});
    EXPECT_EQ(r.stage, Stage::Filter);
    EXPECT_EQ(r.sign, 1);
    EXPECT_EQ(r.det, 1.0);
    // Exactly collinear, and off the line by one ulp: beyond the filter's error bound.
    r = orientExplained({0.5, 0.5}, {12, 12}, {24, 24});
    EXPECT_EQ(r.stage, Stage::Expansion);
    EXPECT_EQ(r.sign, 0);
    r = orientExplained({std::nextafter(0.5, 1.0), 0.5}, {12, 12}, {24, 24});
    EXPECT_EQ(r.stage, Stage::Expansion);
    EXPECT_EQ(r.sign, orient({std::nextafter(0.5, 1.0), 0.5}, {12, 12}, {24, 24}));
    EXPECT_EQ(r.sign, -1);  // (0.5+u, 0.5) lies below the diagonal: a clockwise turn
    // Tiny products underflow and huge ones overflow: only rationals are exact there.
    r = orientExplained({1e-300, 0}, {0, 1e-300}, {0, 0});
    EXPECT_EQ(r.stage, Stage::Rationals);
    EXPECT_EQ(r.sign, 1);
    r = orientExplained({1e300, 1e300}, {-1e300, 1e300}, {0, -1e300});
    EXPECT_EQ(r.stage, Stage::Rationals);
    EXPECT_EQ(r.sign, 1);
    EXPECT_FALSE(std::isfinite(r.det));  // the floating-point value is no use here
    EXPECT_STREQ(flood::stageName(Stage::Rationals), "rationals");
}

// Same sign as orient() everywhere, without counting as the machine's work.
TEST(OrientExplained, AgreesWithOrientAndCountsNoWork) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 20000; ++i) {
        Point a{u(rng), u(rng)}, b{u(rng), u(rng)};
        double t = u(rng);
        Point c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};  // near the line: every stage
        if (i % 3 == 0) c = {u(rng) * std::ldexp(1.0, -600), u(rng) * std::ldexp(1.0, 600)};
        flood::work() = {};
        auto r = flood::orientExplained(a, b, c);
        EXPECT_EQ(flood::work().orientCalls, 0u);
        ASSERT_EQ(r.sign, orient(a, b, c)) << i;
    }
}

TEST(InsideExplained, AgreesWithInsideAndReportsTheDeepestStage) {
    Point l{0, 0}, r{4, 0}, nr{4, 4}, nl{0, 4};
    auto in = flood::insideExplained({2, 2}, l, r, nr, nl);
    EXPECT_TRUE(in.inside);
    EXPECT_EQ(in.stage, flood::Stage::Filter);
    EXPECT_GT(in.orients, 0);
    // On the diagonal edge of a skewed quadrangle: collinear, so an exact stage decides.
    Point nl2{0.5, 0.5 * 3}, s{0.25, 0.75};
    auto on = flood::insideExplained(s, l, r, nr, nl2);
    EXPECT_EQ(on.inside, inside(s, l, r, nr, nl2));
    EXPECT_FALSE(on.inside);
    EXPECT_EQ(on.stage, flood::Stage::Expansion);
}
