// The filtered ring orientation (flood/geometry/ring_area.h) against exact arithmetic: the same sign
// on every ring, also where doubles alone cannot tell, and error bounds that hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "flood/geometry/predicates.h"
#include "flood/geometry/ring_area.h"

namespace {

using namespace flood;

int exactSign(const Polygon& p) {
    ExactSum s;
    const Ring& r = p.rings[0];
    for (Index i = 0; i < r.count; ++i)
        s.addCross(p.vertices[r.first + i], p.vertices[r.first + (i + 1) % r.count]);
    return s.sign();
}

Polygon ring(const std::vector<Point>& pts) {
    Polygon p;
    p.addRing(pts, true);
    return p;
}

// The term count and its limit (2^50) are 64-bit on every platform. Issue 29: `size_t(1) << 50`
// is undefined where size_t is 32 bits (wasm32, 32-bit Windows), and a 32-bit count would wrap
// after 2^32 terms. Checked here with the types spelled out, as a 32-bit build would see them.
TEST(RingArea, TermLimitIsSixtyFourBitsEverywhere) {
    static_assert(std::is_same_v<decltype(AreaEstimate::kMaxTerms), const uint64_t>);
    static_assert(std::is_same_v<decltype(AreaEstimate{}.terms()), uint64_t>);
    static_assert(AreaEstimate::kMaxTerms == 1125899906842624ull, "2^50");
    static_assert(AreaEstimate::kMaxTerms > uint64_t(UINT32_MAX), "beyond any 32-bit count");
    AreaEstimate a;
    a.addTriangle({0, 0}, {1, 0}, {0, 1});
    EXPECT_EQ(a.terms(), 3u);
    EXPECT_TRUE(a.finite());
    EXPECT_EQ(a.sign(), 1);
}

TEST(RingArea, SignMatchesExactArithmetic) {
    uint64_t state = 7;
    auto rnd = [&] {  // xorshift: the same rings everywhere
        state ^= state << 13, state ^= state >> 7, state ^= state << 17;
        return double(state >> 11) / double(uint64_t(1) << 53);
    };
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<Point> pts;
        const int n = 3 + trial % 20;
        const double scale = std::ldexp(1.0, (trial % 9) * 120 - 500), shift = trial % 3 ? 1e6 : 0;
        for (int i = 0; i < n; ++i) pts.push_back({shift + rnd() * scale, shift + rnd() * scale});
        Polygon p = ring(pts);
        EXPECT_EQ(ringAreaSign(p, 0, Index(n)), exactSign(p)) << trial;
    }
}

TEST(RingArea, DecidesWhatDoublesCannot) {
    // Collinear points (zero area) far from the origin, and a sliver whose area is below the
    // rounding error of its products: the estimate declines, the exact sum decides.
    const double big = 0x1p40;
    Polygon flat = ring({{big, big}, {big + 1, big + 1}, {big + 2, big + 2}});
    EXPECT_EQ(ringAreaSign(flat, 0, 3), 0);
    Polygon sliver =
        ring({{big, big}, {big + 2, big + 2}, {big + 1, std::nextafter(big + 1, 1e300)}});
    EXPECT_EQ(ringAreaSign(sliver, 0, 3), exactSign(sliver));
    EXPECT_NE(ringAreaSign(sliver, 0, 3), 0);
    AreaEstimate e;
    for (int i = 0; i < 3; ++i) e.addCross(sliver.vertices[i], sliver.vertices[(i + 1) % 3]);
    EXPECT_EQ(e.sign(), 0);  // too close to tell in doubles
    // Tiny coordinates whose products underflow.
    Polygon tiny = ring({{0, 0}, {0x1p-1000, 0}, {0, 0x1p-1000}});
    EXPECT_EQ(ringAreaSign(tiny, 0, 3), 1);
}

TEST(RingArea, BoundCoversTheError) {
    uint64_t state = 11;
    auto rnd = [&] {
        state ^= state << 13, state ^= state >> 7, state ^= state << 17;
        return double(state >> 11) / double(uint64_t(1) << 53) - 0.5;
    };
    for (int trial = 0; trial < 200; ++trial) {
        AreaEstimate e;
        ExactSum exact;
        for (int i = 0; i < 1000; ++i) {
            Point a{rnd() * 1e3, rnd() * 1e-3}, b{rnd() * 1e7, rnd()}, c{rnd(), rnd() * 1e5};
            e.addTriangle(a, b, c);
            exact.addTriangle(a, b, c);
        }
        ExactSum diff = exact;
        ExactSum approx;
        approx.addProduct(e.value(), 1);
        diff.add(approx, -1);
        EXPECT_LE(std::fabs(diff.approx()), e.bound()) << trial;
    }
}

}  // namespace

// The machine's orientation is the turn at the lowest vertex: the area's sign on a simple
// ring, not on a figure eight whose small lower loop turns the other way from the whole.
TEST(RingArea, OrientationIsTheTurnAtTheLowestVertex) {
    const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_EQ(ringOrientation(square.data(), 4), 1);
    const std::vector<Point> reversed(square.rbegin(), square.rend());
    EXPECT_EQ(ringOrientation(reversed.data(), 4), -1);
    const std::vector<Point> eight = {{0, 0}, {2, 0}, {-2, 4}, {2, 4}};
    EXPECT_EQ(ringOrientation(eight.data(), 4), 1);
    EXPECT_EQ(ringAreaSign(eight.data(), 4), -1);
    const std::vector<Point> flatBottom = {{1, 0}, {0, 0}, {2, 0}, {1, 1}};  // a spike at (0, 0)
    EXPECT_EQ(ringOrientation(flatBottom.data(), 4), ringAreaSign(flatBottom.data(), 4));
}
