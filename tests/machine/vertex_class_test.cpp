// The vertex classes (flood/machine/vertex_class.h) orient each ring by the machine's own rule
// (ring_area.h's ringOrientation), so that on a ring that is not simple too they are the
// classes the machine sees: the vertex it starts from is a bottom.
#include <gtest/gtest.h>

#include <vector>

#include "flood/machine/flood.h"
#include "flood/machine/vertex_class.h"

using namespace flood;

namespace {

struct FirstEvent : Listener {
    Event first;
    bool seen = false;
    void onEvent(const Event& e) override {
        if (!seen) first = e, seen = true;
    }
};

}  // namespace

TEST(VertexClass, FollowsTheMachinesOrientationOnAFigureEight) {
    // A figure eight whose small lower loop turns the other way from the whole: the area's sign
    // says clockwise, the turn at the lowest vertex (the machine's rule) counter-clockwise.
    const std::vector<Point> eight = {{0, 0}, {2, 0}, {-2, 4}, {2, 4}};
    // The same figure turned so that its lowest vertex is lowest along each axis direction.
    const struct {
        Up up;
        Point (*turn)(Point);
    } ups[] = {{Up::PlusY, [](Point p) { return p; }},
               {Up::MinusY,
                [](Point p) {
                    return Point{-p.x, -p.y};
                }},
               {Up::PlusX,
                [](Point p) {
                    return Point{p.y, -p.x};
                }},
               {Up::MinusX, [](Point p) {
                    return Point{-p.y, p.x};
                }}};
    for (const auto& u : ups) {
        std::vector<Point> ring;
        for (Point p : eight) ring.push_back(u.turn(p));
        Polygon polygon;
        polygon.addRing(ring, true);
        FirstEvent start;
        triangulate(polygon, &start, Options{u.up});
        ASSERT_TRUE(start.seen && start.first.action == Action::Start) << upName(u.up);
        ASSERT_EQ(start.first.bottom, 0u) << upName(u.up);
        EXPECT_EQ(classifyVertices(polygon, u.up)[0], VertexClass::Bottom) << upName(u.up);
    }
}
