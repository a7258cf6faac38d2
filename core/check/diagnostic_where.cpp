#include "check/diagnostic_where.h"

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
