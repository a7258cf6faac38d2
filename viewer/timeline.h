// The timeline: the breakpoints an event may hit, and the strip that shows the log zoomed
// and panned.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>

#include "flood/machine/events.h"

namespace flood::view {

// Breakpoints: stop when an event matches any enabled condition.
struct Breakpoints {
    std::array<bool, size_t(Action::Count)> actions{};  // on these action kinds
    bool forbidden = false;                             // on a Forbidden event
    Index vertex = kNone;   // when this vertex becomes Left, Right, NextLeft or NextRight
    int64_t triangle = -1;  // when this triangle number is cut
    bool any() const;
};
bool hits(const Breakpoints& b, const Event& e);

// The timeline strip: which events a strip `width` pixels wide shows, zoomed and panned.
// Event i is the mark [x(i), x(i + 1)); hovering it names step i + 1 (the state after it),
// and a click there lands on that same step.
struct TimelineView {
    double first = 0;  // event index (fractional) at the strip's left edge
    double span = 0;   // events across the strip; 0: the whole log
    double visible(uint32_t events) const { return span > 0 ? span : double(events); }
    double perEvent(double width, uint32_t events) const {
        return width / std::max(1.0, visible(events));
    }
    double xOfStep(uint32_t step, double width, uint32_t events) const {
        return (step - first) * perEvent(width, events);
    }
    // The event whose mark is under x (clamped to the log), and the step a click there means.
    uint32_t eventAt(double x, double width, uint32_t events) const;
    uint32_t stepAt(double x, double width, uint32_t events) const {
        return events == 0 ? 0 : eventAt(x, width, events) + 1;
    }
    // Wheel: zoom by `factor` (> 1 magnifies) keeping the event under x in place; drag: pan.
    void zoomAt(double x, double width, double factor, uint32_t events);
    void pan(double dx, double width, uint32_t events);

private:
    void clamp(uint32_t events);
};

}  // namespace flood::view
