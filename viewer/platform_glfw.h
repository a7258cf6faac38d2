// The only file pair that talks to GLFW: window and GL context, content scale, input through
// ImGui's GLFW backend, drag-and-drop, and hidden windows for screenshots.
#pragma once
#include <string>
#include <vector>

#include "geometry.h"   // Vec2
#include "key_queue.h"  // KeyPress

namespace flood::view::platform {

struct WindowOptions {
    int width = 1280, height = 800;
    bool hidden = false;  // screenshot mode: render off screen, never shown
    std::string title = "flood-viewer";
};

// True when the environment names a display (DISPLAY or WAYLAND_DISPLAY).
bool displayNamed();
// glfwInit; false with a reason when there is no usable display.
bool initialize(std::string* error);
void terminate();

// Creates the window with a GL 3.3 core context, loads GL with glad and starts ImGui's GLFW
// backend (the ImGui context must exist). Returns false with a reason.
bool createWindow(const WindowOptions& options, std::string* error);
void destroyWindow();

bool shouldClose();
void requestClose();
// In the page both yield to the browser until its next frame (ASYNCIFY): a function that
// calls them must be listed, with them, in web/asyncify-only.txt.
void pollEvents();
void waitEvents(double timeoutSeconds);  // idle without spinning when nothing plays
void newFrame();                         // ImGui's platform half of a frame
void swapBuffers();
double time();

Vec2 windowSize();  // logical pixels (ImGui's units)
void framebufferSize(int* w, int* h);
float contentScale();  // 1 on a 96-dpi screen, 2 on most hi-DPI ones
void setTitle(const std::string& title);
std::vector<std::string> takeDroppedPaths();  // files dropped on the window since last call
// Key presses and repeats since the last call, every one in order (key_queue.h).
std::vector<KeyPress> takeKeyPresses();

// Wakes waitEvents() from any thread (a background flood is ready: viewer/edit.h).
void wake();

// The settings and recent files were written: in the page, their folder is copied to the
// browser's storage (IndexedDB, web/pre.js) so that a reload finds them. A no-op elsewhere.
void persistConfig();

// ImGui 1.86 has no ImGuiKey for letters or function keys; its GLFW backend fills
// io.KeysDown by GLFW key code, so these index io.KeysDown directly.
extern const int kKeyF;
extern const int kKeyF1;
extern const int kKeyF8;  // next finding (Shift: previous)
extern const int kKeyLeft, kKeyRight;

// Presenter mode (panel_caption.cpp).
extern const int kKeyF11, kKeyTab;
extern const int kKeyPlus[2], kKeyMinus[2], kKeyZero[2];  // main row and keypad
// F11: the window covers the monitor it is on at that monitor's video mode; again (or
// destroyWindow) gives back the window where and as large as it was.
void toggleFullscreen();
bool fullscreen();
// True once after the window's content scale changed (moved to another monitor, DPI
// changed), with the new scale.
bool takeContentScaleChange(float* scale);

}  // namespace flood::view::platform
