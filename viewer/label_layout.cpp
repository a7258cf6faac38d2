#include "label_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flood::view {

bool overlap(const Rect& a, const Rect& b, double gap) {
    return a.x < b.x + b.w + gap && b.x < a.x + a.w + gap && a.y < b.y + b.h + gap &&
           b.y < a.y + a.h + gap;
}

namespace {

double overlapArea(const Rect& a, const Rect& b) {
    double w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
    double h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return w > 0 && h > 0 ? w * h : 0;
}

bool inside(const Rect& box, const Rect& area) {
    return box.x >= area.x && box.y >= area.y && box.x + box.w <= area.x + area.w &&
           box.y + box.h <= area.y + area.h;
}

// The point of `box` nearest `p`.
Vec2 nearestOn(const Rect& box, Vec2 p) {
    return {std::clamp(p.x, box.x, box.x + box.w), std::clamp(p.y, box.y, box.y + box.h)};
}

}  // namespace

std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& labels, const Rect& area,
                                     const std::vector<Rect>& obstacles, double gap, double step,
                                     double reach) {
    std::vector<PlacedLabel> placed;
    placed.reserve(labels.size());
    const double dot = 5;  // an anchor's marker: a label does not cover it
    constexpr double kPi = 3.14159265358979323846;
    for (const LabelRequest& l : labels) {
        const Vec2 a = l.anchor;
        // How crowded a place is: 0 when free, else the area it overlaps (out of the area
        // counts whole).
        auto cost = [&](const Rect& box) {
            double c = inside(box, area) ? 0 : box.w * box.h;
            for (const Rect& o : obstacles) c += overlap(box, o, gap) ? overlapArea(box, o) + 1 : 0;
            for (const PlacedLabel& p : placed)
                c += overlap(box, p.box, gap) ? overlapArea(box, p.box) + 1 : 0;
            for (const LabelRequest& other : labels)
                if (overlap(box, {other.anchor.x - dot, other.anchor.y - dot, 2 * dot, 2 * dot}))
                    c += 4 * dot * dot;
            return c;
        };
        PlacedLabel best;
        double bestCost = std::numeric_limits<double>::infinity();
        auto consider = [&](const Rect& box) {
            double c = cost(box);
            if (c < bestCost) {
                bestCost = c;
                best.box = box;
            }
            return c == 0;
        };
        // Beside the point first: right and above, right and below, left and above, left and
        // below (the usual places of a map label).
        const double d = 7;
        bool done = l.preferred && consider({a.x + l.offset.x, a.y + l.offset.y, l.w, l.h});
        for (Rect box :
             {Rect{a.x + d, a.y - d - l.h, l.w, l.h}, Rect{a.x + d, a.y + d, l.w, l.h},
              Rect{a.x - d - l.w, a.y - d - l.h, l.w, l.h}, Rect{a.x - d - l.w, a.y + d, l.w, l.h}})
            if (done || (done = consider(box))) break;
        const bool beside = done;  // no leader needed
        // Then further out, ring by ring, 16 directions each.
        for (double r = d + step; !done && r <= reach; r += step)
            for (int k = 0; k < 16 && !done; ++k) {
                const double t = (k * 2 + 1) * kPi / 16 - kPi / 2;
                const double cx = a.x + std::cos(t) * (r + l.w / 2),
                             cy = a.y + std::sin(t) * (r + l.h / 2);
                done = consider({cx - l.w / 2, cy - l.h / 2, l.w, l.h});
            }
        best.overlaps = !done;
        const Vec2 to = nearestOn(best.box, a);
        best.from = a, best.to = to;
        best.leader = !beside && std::hypot(to.x - a.x, to.y - a.y) > d * 1.5 + 1;
        placed.push_back(best);
    }
    return placed;
}

std::vector<PointGroup> groupCoincident(const std::vector<Point>& points) {
    std::vector<PointGroup> groups;
    for (size_t i = 0; i < points.size(); ++i) {
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&](const PointGroup& g) { return g.at == points[i]; });
        if (it == groups.end()) groups.push_back({points[i], {i}});
        else it->members.push_back(i);
    }
    return groups;
}

}  // namespace flood::view
