#include "find.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace flood::view {

FindTarget findTarget(const Trace& trace, const std::string& query) {
    FindTarget f;
    std::string q;
    for (char c : query)
        if (!std::isspace(static_cast<unsigned char>(c)))
            q += char(std::tolower(static_cast<unsigned char>(c)));
    if (q.empty()) return f.message = "type v<vertex>, t<triangle>, s<step> or r<ring>", f;
    f.kind = q[0];
    if (std::string("vtsr").find(f.kind) == std::string::npos)
        return f.message =
                   "'" + query + "': start with v (vertex), t (triangle), s (step) or r (ring)",
               f;
    if (q.size() == 1 || q.size() > 12 || q.find_first_not_of("0123456789", 1) != std::string::npos)
        return f.message = "'" + query + "': a number must follow '" + std::string(1, f.kind) + "'",
               f;
    f.index = std::stoull(q.substr(1));
    const Polygon& P = trace.polygon;
    const auto& V = P.vertices;
    auto outOfRange = [&](const char* what, size_t count) {
        f.message = std::string("no ") + what + " " + std::to_string(f.index) + ": there are " +
                    std::to_string(count) + (count ? " (0-" + std::to_string(count - 1) + ")" : "");
        return f;
    };
    auto at = [&](Point p) {
        f.hasCenter = true, f.center = p, f.x0 = f.x1 = p.x, f.y0 = f.y1 = p.y;
    };
    switch (f.kind) {
        case 'v': {
            if (f.index >= V.size()) return outOfRange("vertex", V.size());
            Index v = Index(f.index);
            at(V[v]);
            f.vertices = {v};
            // Its first event: the first step it is a finger or the event's subject.
            for (const Event& e : trace.events)
                for (Index u : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight,
                                e.bottom, e.sag})  // sag, top and culprit share storage
                    if (u == v && f.seekTo == kNone) f.seekTo = e.step + 1;
            Index r = P.ringOf(v);
            f.message = "vertex " + std::to_string(v) + ": ring " + std::to_string(r) + " vertex " +
                        std::to_string(v - P.rings[r].first);
            break;
        }
        case 't': {
            if (f.index >= trace.triangles.size())
                return outOfRange("triangle", trace.triangles.size());
            const Triangle& t = trace.triangles[f.index];
            if (t[0] >= V.size() || t[1] >= V.size() || t[2] >= V.size())
                return f.message =
                           "triangle " + std::to_string(f.index) + " has a vertex out of range",
                       f;
            at({(V[t[0]].x + V[t[1]].x + V[t[2]].x) / 3, (V[t[0]].y + V[t[1]].y + V[t[2]].y) / 3});
            for (Index v : t)
                f.x0 = std::min(f.x0, V[v].x), f.x1 = std::max(f.x1, V[v].x),
                f.y0 = std::min(f.y0, V[v].y), f.y1 = std::max(f.y1, V[v].y);
            for (const Event& e : trace.events)
                if (e.triangleCount && f.index >= e.firstTriangle &&
                    f.index < uint64_t(e.firstTriangle) + e.triangleCount) {
                    f.seekTo = e.step + 1;
                    break;
                }
            f.message = "triangle " + std::to_string(f.index);
            break;
        }
        case 's': {
            if (f.index > trace.events.size())
                return f.message = "no step " + std::to_string(f.index) + ": there are " +
                                   std::to_string(trace.events.size()) + " steps",
                       f;
            f.seekTo = uint32_t(f.index);
            f.message = "step " + std::to_string(f.index);
            if (f.index == 0) return f.ok = true, f.message += " (before anything)", f;
            const Event& e = trace.events[f.index - 1];
            Index v = e.water != kNone ? e.water : e.after.left;
            if (v == kNone || v >= V.size()) v = e.before.left;
            if (v != kNone && v < V.size()) at(V[v]);
            else return f.ok = true, f;  // nothing to centre on: seek only
            // Framed with its fingers: where the water is and where it goes next.
            f.vertices = {v};
            for (Index u : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
                if (u != kNone && u < V.size() &&
                    std::find(f.vertices.begin(), f.vertices.end(), u) == f.vertices.end())
                    f.vertices.push_back(u);
            break;
        }
        case 'r': {
            if (f.index >= P.rings.size()) return outOfRange("ring", P.rings.size());
            const Ring& r = P.rings[f.index];
            if (r.count == 0) return f.message = "ring " + std::to_string(f.index) + " is empty", f;
            at(V[r.first]);
            for (Index i = 0; i < r.count; ++i) {
                Point p = V[r.first + i];
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
                f.x0 = std::min(f.x0, p.x), f.x1 = std::max(f.x1, p.x);
                f.y0 = std::min(f.y0, p.y), f.y1 = std::max(f.y1, p.y);
            }
            f.center = {(f.x0 + f.x1) / 2, (f.y0 + f.y1) / 2};
            f.message =
                "ring " + std::to_string(f.index) + ": " + std::to_string(r.count) + " vertices";
            break;
        }
    }
    f.ok = true;
    return f;
}

}  // namespace flood::view
