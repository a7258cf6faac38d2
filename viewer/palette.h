// Colours of the viewer, shared by the canvas, the SVG export and the screenshot test, so a
// pixel check can ask "is this the water colour?" without duplicating numbers.
#pragma once
#include <cstdint>

#include "events.h"

namespace flood::view {

struct Rgba {
    uint8_t r = 0, g = 0, b = 0, a = 255;
};

namespace palette {
constexpr Rgba kBackground{30, 32, 38, 255};
constexpr Rgba kPolygonFill{72, 78, 70, 255};     // dry land: the not yet flooded interior
constexpr Rgba kTriangle{120, 126, 110, 255};     // a triangle already cut (seen through water)
constexpr Rgba kWater{40, 110, 190, 255};         // flooded triangles (opaque so tests can probe)
constexpr Rgba kCurrent{250, 200, 60, 255};       // triangles cut by the current event
constexpr Rgba kTriangleEdge{20, 50, 90, 255};
constexpr Rgba kBoundary{235, 235, 235, 255};
constexpr Rgba kWaterLevel{120, 210, 255, 255};
constexpr Rgba kChain{255, 120, 40, 255};
constexpr Rgba kLeft{255, 60, 200, 255};          // the Left end of the active chain
constexpr Rgba kRight{60, 230, 90, 255};          // the Right end
constexpr Rgba kNextLeft{255, 150, 230, 255};     // finger markers: lighter shades of L / R
constexpr Rgba kNextRight{160, 255, 170, 255};
constexpr Rgba kJump{200, 160, 255, 255};
constexpr Rgba kBridge{0, 215, 175, 255};        // teal: far from the just-cut yellow
constexpr Rgba kDormant{255, 255, 255, 255};
constexpr Rgba kCulprit{255, 40, 40, 255};
constexpr Rgba kHover{255, 255, 255, 255};
constexpr Rgba kVertexNumber{200, 200, 200, 255};
constexpr Rgba kTreePath{255, 244, 140, 255};     // the current event's path in the Fig. 9 tree

// Vertex classes of §3 (Fig. 1).
constexpr Rgba kRegular{170, 170, 170, 255};
constexpr Rgba kBottom{60, 200, 255, 255};
constexpr Rgba kSag{40, 120, 255, 255};
constexpr Rgba kTop{255, 170, 40, 255};
constexpr Rgba kCeiling{255, 90, 60, 255};

// One colour per action for the timeline, the event list and the state machine.
inline Rgba action(Action a) {
    switch (a) {
        case Action::Start: return {200, 200, 200, 255};
        case Action::Raise: return {80, 160, 255, 255};
        case Action::Bridge: return {255, 220, 80, 255};
        case Action::Spill: return {80, 220, 120, 255};
        case Action::Jump: return {190, 120, 255, 255};
        case Action::Fill: return {60, 220, 220, 255};
        case Action::Forbidden: return {255, 50, 50, 255};
        default: return {128, 128, 128, 255};
    }
}
}  // namespace palette

}  // namespace flood::view
