// Reading the caller's own points, with no copy into flood::Point rings first: any point type
// with members x and y (a struct, glm::dvec2, ...) or with [0] and [1] (std::array<double, 2>,
// double[2], ...), or one taught to Flood by specialising PointAccess, as earcut.hpp's
// mapbox::util::nth is specialised. A ring is any range of such points (std::vector, a C array,
// flood::Span over a pointer and a count); a polygon is a range of rings, outer ring first.
// The points go straight into the Polygon's one vertex array: the copy the machine needs, not
// one more (flood_api.h: triangulateView, triangulatePartsView).
#pragma once
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>

#include "flood/geometry/polygon.h"

namespace flood {

// A pointer and a count as a range, for points (or rings) the caller keeps in an array.
template <typename T>
struct Span {
    T* data = nullptr;
    size_t size = 0;
    T* begin() const { return data; }
    T* end() const { return data + size; }
};

namespace detail {
template <typename P, typename = void>
struct HasXY : std::false_type {};
template <typename P>
struct HasXY<
    P, std::void_t<decltype(std::declval<const P&>().x), decltype(std::declval<const P&>().y)>>
    : std::true_type {};
}  // namespace detail

// How Flood reads a point's coordinates. Specialise it for a type that has neither x/y
// members nor [0]/[1]: struct PointAccess<MyPt> { static double x(const MyPt&); static
// double y(const MyPt&); };
template <typename P, typename = void>
struct PointAccess {
    static double x(const P& p) {
        if constexpr (detail::HasXY<P>::value) return double(p.x);
        else return double(p[0]);
    }
    static double y(const P& p) {
        if constexpr (detail::HasXY<P>::value) return double(p.y);
        else return double(p[1]);
    }
};

// Appends one ring of the caller's points to `polygon` (a new part when `outer`). A closed
// ring (more than 3 points, the last equal to the first, as OGR, GEOS and WKT store rings)
// loses its closing point, as makePolygon() drops it.
template <typename RingRange>
void addRingOf(Polygon& polygon, const RingRange& ring, bool outer) {
    polygon.pointsDistinct = false;  // the new ring may touch the others
    if (outer) polygon.parts.push_back({Index(polygon.rings.size()), 0});
    const size_t first = polygon.vertices.size();
    for (const auto& p : ring) {
        using P = std::decay_t<decltype(p)>;
        polygon.vertices.push_back({PointAccess<P>::x(p), PointAccess<P>::y(p)});
    }
    size_t count = polygon.vertices.size() - first;
    if (count > 3 && polygon.vertices.back() == polygon.vertices[first]) {
        polygon.vertices.pop_back();
        --count;
    }
    polygon.rings.push_back({Index(first), Index(count)});
    polygon.parts.back().ringCount++;
}

// A MultiPolygon given as a range of parts, each a range of rings (outer ring, then holes),
// as a Polygon; vertices numbered through all rings in order, parts without rings skipped.
template <typename PartsRange>
Polygon makePolygonOf(const PartsRange& parts) {
    Polygon polygon;
    for (const auto& rings : parts) {
        bool outer = true;
        for (const auto& ring : rings) {
            addRingOf(polygon, ring, outer);
            outer = false;
        }
    }
    return polygon;
}

}  // namespace flood
