#include "flood/check/diagnostic_where.h"

#include <cmath>

#include "io/io_util.h"

namespace flood {

Where whereOf(const Polygon& polygon, const Culprits& c) {
    Where w;
    if (!c.vertices.empty() && c.vertices.front() < polygon.vertices.size()) {
        Index v = c.vertices.front();
        w.ring = polygon.ringOf(v);
        w.vertex = v - polygon.rings[w.ring].first;
        w.text = "ring " + std::to_string(w.ring) + " vertex " + std::to_string(w.vertex) + " " +
                 io_detail::formatPoint(polygon.vertices[v]);
    } else if (!c.rings.empty() && c.rings.front() < polygon.rings.size()) {
        w.ring = c.rings.front();
        w.text = "ring " + std::to_string(w.ring);
    }
    return w;
}

bool diagnosticPoint(const Polygon& polygon, const Culprits& c, Point& p, bool anyVertex) {
    const auto& V = polygon.vertices;
    if (c.hasPoint) {
        p = {c.x, c.y};
        return true;
    }
    auto ends = [&](Index e, Point& a, Point& b) {
        if (e >= V.size()) return false;
        const Ring& r = polygon.rings[polygon.ringOf(e)];
        a = V[e], b = V[e + 1 == r.first + r.count ? r.first : e + 1];
        return true;
    };
    Point a, b, q, d;
    if (c.edges.size() >= 2 && ends(c.edges[0], a, b) && ends(c.edges[1], q, d)) {
        double den = (b.x - a.x) * (d.y - q.y) - (b.y - a.y) * (d.x - q.x);
        if (den == 0 || !std::isfinite(den)) {  // collinear overlap: the middle of the ends
            p = {(a.x + b.x + q.x + d.x) / 4, (a.y + b.y + q.y + d.y) / 4};
            return true;
        }
        double t = ((q.x - a.x) * (d.y - q.y) - (q.y - a.y) * (d.x - q.x)) / den;
        p = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        return true;
    }
    if (!anyVertex) return false;
    if (!c.vertices.empty() && c.vertices.front() < V.size()) {
        p = V[c.vertices.front()];
        return true;
    }
    if (!c.rings.empty() && c.rings.front() < polygon.rings.size() &&
        polygon.rings[c.rings.front()].count > 0) {
        p = V[polygon.rings[c.rings.front()].first];
        return true;
    }
    return false;
}

namespace {
// `s` without `prefix` + ":" and one space, if it starts so; else `s` unchanged.
std::string after(const std::string& s, const std::string& prefix) {
    if (prefix.empty() || s.compare(0, prefix.size(), prefix) != 0) return s;
    size_t i = prefix.size();
    if (s.compare(i, 2, ": ") == 0) return s.substr(i + 2);
    if (s.compare(i, 1, ":") == 0) return s.substr(i + 1);
    return s;
}
}  // namespace

std::string reasonOf(const std::string& message, const std::string& name, const Where& where) {
    return after(after(message, name), where.text);
}

}  // namespace flood
