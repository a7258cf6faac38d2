// groupsApart() (core/geometry/boxes_apart.h): boxes of different groups never meet, checked
// pair by pair on random boxes where touching and overlap are common; rows and grids of boxes
// apart are cut into single boxes; touching, overlapping and pinwheel layouts stay together.
#include <gtest/gtest.h>

#include <cstdint>

#include "geometry/boxes_apart.h"

using namespace flood;

namespace {

Box box(double x0, double y0, double x1, double y1) {
    Box b;
    b.add({x0, y0}), b.add({x1, y1});
    return b;
}

bool meet(const Box& a, const Box& b) {
    return !(a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0);
}

// Groups numbered from 0 in the order of their first box.
void expectNumberedInOrder(const std::vector<Index>& group, size_t count) {
    Index next = 0;
    for (Index g : group) {
        ASSERT_LE(g, next);
        if (g == next) ++next;
    }
    EXPECT_EQ(next, count);
}

}  // namespace

TEST(BoxesApart, BoxesOfDifferentGroupsNeverMeet) {
    uint64_t s = 7;
    auto rnd = [&](int n) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return int((s >> 33) % uint64_t(n));
    };
    size_t split = 0;
    for (int round = 0; round < 300; ++round) {
        const int n = 1 + rnd(60), span = 10 + rnd(200);
        std::vector<Box> boxes;
        for (int k = 0; k < n; ++k) {
            const int x = rnd(span), y = rnd(span);
            boxes.push_back(box(x, y, x + rnd(8), y + rnd(8)));  // some are segments or points
        }
        size_t count = 0;
        const std::vector<Index> group = groupsApart(boxes, count);
        ASSERT_EQ(group.size(), boxes.size());
        expectNumberedInOrder(group, count);
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b)
                if (group[a] != group[b]) {
                    ASSERT_FALSE(meet(boxes[a], boxes[b])) << round;
                }
        split += count > 1;
    }
    EXPECT_GT(split, 200u);
}

TEST(BoxesApart, RowsAndGridsAreCutIntoSingleBoxes) {
    std::vector<Box> row, grid;
    for (int k = 0; k < 1000; ++k) row.push_back(box(4 * k, k % 3, 4 * k + 3, k % 3 + 3));
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j) grid.push_back(box(2 * i, 2 * j, 2 * i + 1, 2 * j + 1));
    size_t count = 0;
    groupsApart(row, count);
    EXPECT_EQ(count, row.size());
    groupsApart(grid, count);
    EXPECT_EQ(count, grid.size());
}

TEST(BoxesApart, TouchingOverlappingAndPinwheelBoxesStayTogether) {
    size_t count = 0;
    // Along a line, at a corner: closed boxes meet.
    groupsApart({box(0, 0, 1, 1), box(1, 0, 2, 1), box(2, 1, 3, 2)}, count);
    EXPECT_EQ(count, 1u);
    // Four boxes around a fifth, each overlapping the next in x or y: no line cuts them,
    // though the first and third do not meet.
    std::vector<Box> pinwheel{box(0, 0, 2, 1), box(2.5, 0, 3, 2), box(1, 2.5, 3, 3),
                              box(0, 1, 0.5, 3), box(1, 1.2, 2, 2)};
    std::vector<Index> g = groupsApart(pinwheel, count);
    EXPECT_EQ(count, 1u);
    // A box apart from those five is cut off them.
    pinwheel.push_back(box(10, 10, 11, 11));
    g = groupsApart(pinwheel, count);
    EXPECT_EQ(count, 2u);
    EXPECT_EQ(g[5], 1u);
}

TEST(BoxesApart, EmptyBoxesAreGroupsOfTheirOwn) {
    size_t count = 0;
    std::vector<Index> g = groupsApart({Box{}, box(0, 0, 1, 1), Box{}, box(0.5, 0.5, 2, 2)}, count);
    EXPECT_EQ(count, 3u);
    EXPECT_EQ(g, (std::vector<Index>{0, 1, 2, 1}));
    groupsApart({}, count);
    EXPECT_EQ(count, 0u);
}
