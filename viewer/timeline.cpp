#include "timeline.h"

#include <cmath>

namespace flood::view {

// [SECTION] breakpoints
bool Breakpoints::any() const {
    return forbidden || vertex != kNone || triangle >= 0 ||
           std::any_of(actions.begin(), actions.end(), [](bool b) { return b; });
}

bool hits(const Breakpoints& b, const Event& e) {
    if (b.actions[size_t(e.action)]) return true;
    if (b.forbidden && (e.action == Action::Forbidden || e.reason != Forbidden::None)) return true;
    if (b.vertex != kNone) {
        const Fingers &x = e.before, &y = e.after;
        if ((y.left == b.vertex && x.left != b.vertex) ||
            (y.right == b.vertex && x.right != b.vertex) ||
            (y.nextLeft == b.vertex && x.nextLeft != b.vertex) ||
            (y.nextRight == b.vertex && x.nextRight != b.vertex))
            return true;
    }
    if (b.triangle >= 0 && e.triangleCount > 0 && uint64_t(b.triangle) >= e.firstTriangle &&
        uint64_t(b.triangle) < uint64_t(e.firstTriangle) + e.triangleCount)
        return true;
    return false;
}

// [SECTION] the strip
uint32_t TimelineView::eventAt(double x, double width, uint32_t events) const {
    if (events == 0) return 0;
    double i = std::floor(first + x / perEvent(width, events));  // the mark x falls in
    return uint32_t(std::clamp(i, 0.0, double(events - 1)));
}

void TimelineView::zoomAt(double x, double width, double factor, uint32_t events) {
    if (events == 0 || width <= 0 || factor <= 0) return;
    double at = first + x / perEvent(width, events);
    // Zoomed in: never fewer than 8 events across; zoomed out: the whole log.
    span = std::clamp(visible(events) / factor, std::min(8.0, double(events)), double(events));
    first = at - x / perEvent(width, events);
    clamp(events);
}

void TimelineView::pan(double dx, double width, uint32_t events) {
    if (events == 0 || width <= 0) return;
    first -= dx / perEvent(width, events);
    clamp(events);
}

void TimelineView::clamp(uint32_t events) {
    if (span >= double(events)) span = 0;  // all of it: follow the log's length
    first = std::clamp(first, 0.0, std::max(0.0, double(events) - visible(events)));
}

}  // namespace flood::view
