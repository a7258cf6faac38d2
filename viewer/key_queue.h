// Key presses in the order the platform reported them. ImGui folds a frame's presses of a
// key into one, so a slow frame lost taps; the platform (platform_glfw.cpp) queues each press
// here instead and the shortcuts apply every one.
#pragma once
#include <vector>

namespace flood::view {

struct KeyPress {
    int key = 0;  // the platform's key code
    bool shift = false, ctrl = false, repeat = false;
};

class KeyQueue {
public:
    // A platform key event: action 0 release, 1 press, 2 auto-repeat (GLFW's numbering).
    void push(int key, int action, bool shift, bool ctrl) {
        if (action == 1 || action == 2) presses_.push_back({key, shift, ctrl, action == 2});
    }
    // Every press since the last call, oldest first.
    std::vector<KeyPress> take() {
        std::vector<KeyPress> out;
        out.swap(presses_);
        return out;
    }

private:
    std::vector<KeyPress> presses_;
};

}  // namespace flood::view
