#include "gorge_focus.h"

#include <algorithm>
#include <cmath>

namespace flood::view {

std::vector<Point> activeGorgeOutline(const Model& model) {
    const Polygon& poly = model.polygon();
    const ReplayState& s = model.state();
    const Fingers& f = s.fingers;
    std::vector<Index> ids;
    auto add = [&](Index v) {
        if (v != kNone && v < poly.vertices.size() && (ids.empty() || ids.back() != v))
            ids.push_back(v);
    };
    if (s.chain.empty() && f.left == kNone) return {};
    add(f.nextLeft);
    add(f.left);
    for (Index v : s.chain) add(v);
    add(f.right);
    add(f.nextRight);
    std::vector<Point> out;
    for (Index v : ids) out.push_back(poly.vertices[v]);
    return out;
}

std::vector<Rect> outsideOf(const std::vector<Vec2>& outline, const Rect& area, double rowHeight) {
    std::vector<Rect> out;
    if (area.w <= 0 || area.h <= 0 || rowHeight <= 0) return out;
    const size_t rows = size_t(std::ceil(area.h / rowHeight));
    std::vector<std::vector<double>> crossings(rows);
    // Row i samples y = area.y + (i + 0.5) * rowHeight; an edge crosses the rows whose sample
    // lies in [low end, high end): half-open, so a vertex between two edges counts once.
    for (size_t k = 0; k < outline.size(); ++k) {
        Vec2 a = outline[k], b = outline[(k + 1) % outline.size()];
        if (a.y == b.y || !std::isfinite(a.y) || !std::isfinite(b.y)) continue;
        double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
        double first = std::ceil((lo - area.y) / rowHeight - 0.5);
        double last = std::ceil((hi - area.y) / rowHeight - 0.5) - 1;
        if (last < 0 || first > double(rows) - 1) continue;
        for (size_t i = size_t(std::max(first, 0.0)); i <= size_t(std::min(last, double(rows) - 1));
             ++i) {
            double y = area.y + (double(i) + 0.5) * rowHeight;
            crossings[i].push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
        }
    }
    const double right = area.x + area.w;
    for (size_t i = 0; i < rows; ++i) {
        std::vector<double>& xs = crossings[i];
        std::sort(xs.begin(), xs.end());
        double top = area.y + double(i) * rowHeight, h = std::min(rowHeight, area.y + area.h - top);
        // Outside: before the first crossing, between the 2nd and 3rd, ..., after the last.
        double from = area.x;
        for (size_t k = 0; k <= xs.size(); k += 2) {
            double to = k < xs.size() ? std::clamp(xs[k], area.x, right) : right;
            if (to > from) out.push_back({from, top, to - from, h});
            if (k + 1 < xs.size()) from = std::clamp(xs[k + 1], area.x, right);
        }
    }
    return out;
}

}  // namespace flood::view
