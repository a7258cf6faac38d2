// Screen geometry, shared by the model and the window layer (platform_glfw.*, renderer.*),
// which need no more of the model than this. Screen coordinates are ImGui's logical pixels:
// origin top-left, y down.
#pragma once

namespace flood::view {

struct Vec2 {
    double x = 0, y = 0;
};

struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
    bool contains(Vec2 p) const { return p.x >= x && p.y >= y && p.x < x + w && p.y < y + h; }
};

}  // namespace flood::view
