// Colours of the viewer, shared by the canvas, the SVG export and the screenshot test, so a
// pixel check can ask "is this the water colour?" without duplicating numbers.
// Two themes: dark (the default, for screens) and light (projectors, printed handouts). The
// k* colours are the current theme's, so every drawer and exporter follows setTheme().
#pragma once
#include <cstdint>
#include <cstring>
#include <iterator>
#include <utility>

#include "flood/machine/events.h"

namespace flood::view {

struct Rgba {
    uint8_t r = 0, g = 0, b = 0, a = 255;
};

enum class Theme : uint8_t { Dark, Light };

namespace palette {
// Every colour of a theme; the k* colours below are the current theme's copy.
struct Colours {
    Rgba background, polygonFill, triangle, water, current, triangleEdge, boundary, waterLevel,
        chain, left, right, nextLeft, nextRight, jump, bridge, dormant, culprit, hover,
        vertexNumber, regular, bottom, sag, top, ceiling, ok, treePath;
};
// Both themes in one table, a row per Colours field in its order: {dark, light}. Light:
// paper-white ground, sand for dry land, mid-blue water, and every line, marker and label
// dark enough to read on white (and on a washed-out projector).
constexpr Rgba kThemes[][2] = {
    {{30, 32, 38}, {250, 250, 246}},     // background
    {{72, 78, 70}, {226, 218, 196}},     // polygonFill
    {{120, 126, 110}, {196, 190, 168}},  // triangle
    {{40, 110, 190}, {110, 170, 230}},   // water
    {{250, 200, 60}, {245, 185, 30}},    // current
    {{20, 50, 90}, {30, 60, 110}},       // triangleEdge
    {{235, 235, 235}, {25, 25, 30}},     // boundary
    {{120, 210, 255}, {0, 80, 190}},     // waterLevel
    {{255, 120, 40}, {215, 85, 0}},      // chain
    {{255, 60, 200}, {190, 0, 140}},     // left
    {{60, 230, 90}, {0, 140, 45}},       // right
    {{255, 150, 230}, {225, 90, 190}},   // nextLeft
    {{160, 255, 170}, {40, 180, 80}},    // nextRight
    {{200, 160, 255}, {110, 50, 200}},   // jump
    {{0, 215, 175}, {0, 140, 120}},      // bridge
    {{255, 255, 255}, {40, 40, 40}},     // dormant
    {{255, 40, 40}, {215, 0, 0}},        // culprit
    {{255, 255, 255}, {0, 0, 0}},        // hover
    {{200, 200, 200}, {60, 60, 60}},     // vertexNumber
    {{170, 170, 170}, {110, 110, 110}},  // regular
    {{60, 200, 255}, {0, 130, 200}},     // bottom
    {{40, 120, 255}, {20, 70, 200}},     // sag
    {{255, 170, 40}, {200, 115, 0}},     // top
    {{255, 90, 60}, {200, 45, 25}},      // ceiling
    {{153, 230, 153}, {20, 130, 40}},    // ok
    {{255, 244, 140}, {185, 95, 0}},     // treePath
};
static_assert(sizeof(Colours) == sizeof(kThemes) / 2, "a colour without its row");
template <size_t... Field>
constexpr Colours themeColumn(int theme, std::index_sequence<Field...>) {
    return Colours{kThemes[Field][theme]...};
}
constexpr Colours kDark = themeColumn(0, std::make_index_sequence<std::size(kThemes)>{});
constexpr Colours kLight = themeColumn(1, std::make_index_sequence<std::size(kThemes)>{});

inline Rgba kBackground = kDark.background;
inline Rgba kPolygonFill = kDark.polygonFill;  // dry land: the not yet flooded interior
inline Rgba kTriangle = kDark.triangle;        // a triangle already cut (seen through water)
inline Rgba kWater = kDark.water;              // flooded triangles (opaque so tests can probe)
inline Rgba kCurrent = kDark.current;          // triangles cut by the current event
inline Rgba kTriangleEdge = kDark.triangleEdge;
inline Rgba kBoundary = kDark.boundary;
inline Rgba kWaterLevel = kDark.waterLevel;
inline Rgba kChain = kDark.chain;
inline Rgba kLeft = kDark.left;          // the Left end of the active chain
inline Rgba kRight = kDark.right;        // the Right end
inline Rgba kNextLeft = kDark.nextLeft;  // finger markers: lighter shades of L / R
inline Rgba kNextRight = kDark.nextRight;
inline Rgba kJump = kDark.jump;
inline Rgba kBridge = kDark.bridge;  // teal: far from the just-cut yellow
inline Rgba kDormant = kDark.dormant;
inline Rgba kCulprit = kDark.culprit;
inline Rgba kHover = kDark.hover;
inline Rgba kVertexNumber = kDark.vertexNumber;

// Vertex classes of §3 (Fig. 1).
inline Rgba kRegular = kDark.regular;
inline Rgba kBottom = kDark.bottom;
inline Rgba kSag = kDark.sag;
inline Rgba kTop = kDark.top;
inline Rgba kCeiling = kDark.ceiling;

inline Rgba kOk = kDark.ok;              // a passed check in the verdict and the invariant lane
inline Rgba kTreePath = kDark.treePath;  // the current event's path in the Fig. 9 tree

namespace detail {
inline Theme g_theme = Theme::Dark;
}  // namespace detail

inline Theme theme() { return detail::g_theme; }
inline void setTheme(Theme t) {
    const Colours& c = t == Theme::Light ? kLight : kDark;
    struct Slot {
        Rgba* colour;
        Rgba Colours::*field;
    };
    const Slot slots[] = {{&kBackground, &Colours::background},
                          {&kPolygonFill, &Colours::polygonFill},
                          {&kTriangle, &Colours::triangle},
                          {&kWater, &Colours::water},
                          {&kCurrent, &Colours::current},
                          {&kTriangleEdge, &Colours::triangleEdge},
                          {&kBoundary, &Colours::boundary},
                          {&kWaterLevel, &Colours::waterLevel},
                          {&kChain, &Colours::chain},
                          {&kLeft, &Colours::left},
                          {&kRight, &Colours::right},
                          {&kNextLeft, &Colours::nextLeft},
                          {&kNextRight, &Colours::nextRight},
                          {&kJump, &Colours::jump},
                          {&kBridge, &Colours::bridge},
                          {&kDormant, &Colours::dormant},
                          {&kCulprit, &Colours::culprit},
                          {&kHover, &Colours::hover},
                          {&kVertexNumber, &Colours::vertexNumber},
                          {&kRegular, &Colours::regular},
                          {&kBottom, &Colours::bottom},
                          {&kSag, &Colours::sag},
                          {&kTop, &Colours::top},
                          {&kCeiling, &Colours::ceiling},
                          {&kOk, &Colours::ok},
                          {&kTreePath, &Colours::treePath}};
    static_assert(sizeof(Colours) == sizeof(slots) / sizeof(slots[0]) * sizeof(Rgba),
                  "a colour without a slot");
    for (const Slot& s : slots) *s.colour = c.*s.field;
    detail::g_theme = t;
}
inline const char* themeName(Theme t) { return t == Theme::Light ? "light" : "dark"; }
// "light" or "dark"; false (and `out` untouched) for anything else.
inline bool parseTheme(const char* text, Theme& out) {
    if (std::strcmp(text, "light") == 0) return out = Theme::Light, true;
    if (std::strcmp(text, "dark") == 0) return out = Theme::Dark, true;
    return false;
}

// One colour per action for the timeline, the event list and the state machine; the light
// theme's are darker so they read as text on white.
inline Rgba action(Action a) {
    const bool light = detail::g_theme == Theme::Light;
    switch (a) {
        case Action::Start: return light ? Rgba{90, 90, 90, 255} : Rgba{200, 200, 200, 255};
        case Action::Raise: return light ? Rgba{20, 95, 205, 255} : Rgba{80, 160, 255, 255};
        case Action::Bridge: return light ? Rgba{170, 125, 0, 255} : Rgba{255, 220, 80, 255};
        case Action::Spill: return light ? Rgba{10, 140, 55, 255} : Rgba{80, 220, 120, 255};
        case Action::Jump: return light ? Rgba{125, 55, 205, 255} : Rgba{190, 120, 255, 255};
        case Action::Fill: return light ? Rgba{0, 135, 140, 255} : Rgba{60, 220, 220, 255};
        case Action::Forbidden: return light ? Rgba{210, 20, 20, 255} : Rgba{255, 50, 50, 255};
        default: return {128, 128, 128, 255};
    }
}

// The Fig. 9 tree (panel_decision.cpp): its boxes, labels and edges, each readable on the
// theme's panel (ImGui's dark or light window background). The yes/no answers on the edges
// are a green and a blue, never the forbidden red; the light theme's are dark enough to read
// on white at a contrast of 4:1 or more.
struct TreeColours {
    Rgba test, border, label,   // a test box not reached, its outline and label
        leafLabel,              // an action's or a forbidden state's label when not reached
        stop,                   // a forbidden state not reached (reached: kCulprit)
        edge,                   // an edge without an answer (after an action, a pass-through)
        testLit, testLitLabel,  // a test the current event ran
        actionLitLabel,         // the current event's action box (its fill: action())
        stopLitLabel,           // the forbidden state the event ended in
        yes, no;
};
constexpr TreeColours kDarkTree{{50, 54, 62, 255},    {100, 104, 112, 255}, {140, 144, 150, 255},
                                {220, 220, 220, 255}, {105, 28, 28, 255},   {78, 82, 90, 255},
                                {90, 86, 52, 255},    {250, 250, 250, 255}, {20, 20, 20, 255},
                                {250, 250, 250, 255}, {140, 220, 140, 255}, {150, 180, 230, 255}};
constexpr TreeColours kLightTree{{226, 228, 233, 255}, {150, 153, 160, 255}, {90, 93, 100, 255},
                                 {40, 40, 40, 255},    {238, 196, 196, 255}, {160, 163, 170, 255},
                                 {255, 232, 140, 255}, {25, 25, 25, 255},    {255, 255, 255, 255},
                                 {255, 255, 255, 255}, {0, 115, 35, 255},    {20, 75, 190, 255}};
inline const TreeColours& tree() {
    return detail::g_theme == Theme::Light ? kLightTree : kDarkTree;
}
}  // namespace palette

}  // namespace flood::view
