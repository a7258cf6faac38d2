#include "platform_glfw.h"

#include "gl_api.h"  // before GLFW, so GLFW does not pull in a GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cstdlib>

#ifdef __EMSCRIPTEN__
// The page (cmake/web.cmake): Emscripten's GLFW is 3.2.1, without content scales; the canvas
// is sized here to the page in device pixels, and the loop yields to the browser each frame.
#include <emscripten.h>
#include <emscripten/html5.h>

// Resolves at the next animation frame, or, when `idle`, at the next one after an input event
// or `timeout` seconds, whichever comes first (the desktop's glfwWaitEventsTimeout). The page's
// own "flood-wake" event (a message from the shrink's worker) is an input too.
// clang-format off
EM_ASYNC_JS(void, flood_web_next_frame, (int idle, double timeout), {
    if (idle) {
        await new Promise(resolve => {
            const events = ["keydown", "keyup", "pointerdown", "pointerup", "pointermove",
                            "wheel", "resize", "drop", "flood-wake"];
            let timer;
            const done = () => {
                clearTimeout(timer);
                for (const e of events) window.removeEventListener(e, done, true);
                resolve();
            };
            timer = setTimeout(done, timeout * 1000);
            for (const e of events) window.addEventListener(e, done, true);
        });
    }
    await new Promise(resolve => requestAnimationFrame(resolve));
});

// Copy: Emscripten's glfwSetClipboardString is a stub; the text goes to the browser's
// clipboard (asynchronous; a refusal, e.g. a page without focus, is said on the console).
EM_JS(void, flood_web_copy, (const char* text), {
    const s = UTF8ToString(text);
    Module["floodCopied"] = s;
    if (navigator.clipboard && navigator.clipboard.writeText)
        navigator.clipboard.writeText(s).catch(
            e => console.warn("flood-viewer: the browser refused the copy: " + e));
    else  // browsers give the clipboard only to https:// pages and http://localhost
        console.warn("flood-viewer: no clipboard for this page (served over plain http?)");
});
// clang-format on
#endif

namespace flood::view::platform {
#ifdef __EMSCRIPTEN__
namespace {
std::string g_clipboard;  // ImGui's paste inside the page reads the last copy back
void setClipboard(void*, const char* text) {
    g_clipboard = text ? text : "";
    flood_web_copy(g_clipboard.c_str());
}
const char* getClipboard(void*) { return g_clipboard.c_str(); }
}  // namespace
#endif

const int kKeyF = GLFW_KEY_F;
const int kKeyF1 = GLFW_KEY_F1;
const int kKeyF8 = GLFW_KEY_F8;
const int kKeyLeft = GLFW_KEY_LEFT, kKeyRight = GLFW_KEY_RIGHT;
const int kKeyF11 = GLFW_KEY_F11, kKeyTab = GLFW_KEY_TAB;
// '+' shares its key with '=' on most layouts; Ctrl+= is what a user presses for Ctrl++.
const int kKeyPlus[2] = {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD};
const int kKeyMinus[2] = {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT};
const int kKeyZero[2] = {GLFW_KEY_0, GLFW_KEY_KP_0};

namespace {
GLFWwindow* g_window = nullptr;
std::vector<std::string> g_dropped;
std::string g_glfwError;

void onError(int, const char* description) { g_glfwError = description ? description : "?"; }

KeyQueue g_keys;
GLFWkeyfun g_imguiKey = nullptr;  // ImGui's key callback: ours chains to it

void onKey(GLFWwindow* w, int key, int scancode, int action, int mods) {
    if (g_imguiKey) g_imguiKey(w, key, scancode, action, mods);
    g_keys.push(key, action, mods & GLFW_MOD_SHIFT, mods & GLFW_MOD_CONTROL);
}

void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) g_dropped.emplace_back(paths[i]);
}

bool g_scaleChanged = false;
float g_scale = 1;
void onContentScale(GLFWwindow*, float x, float) {
    g_scale = x;
    g_scaleChanged = true;
}

int g_windowed[4] = {0, 0, 0, 0};  // x, y, w, h before fullscreen

// The monitor holding the window's centre; the primary one if none does.
GLFWmonitor* monitorOfWindow() {
    int x = 0, y = 0, w = 0, h = 0, count = 0;
    glfwGetWindowPos(g_window, &x, &y);
    glfwGetWindowSize(g_window, &w, &h);
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    for (int i = 0; i < count; ++i) {
        int mx = 0, my = 0;
        glfwGetMonitorPos(monitors[i], &mx, &my);
        const GLFWvidmode* mode = glfwGetVideoMode(monitors[i]);
        if (mode && x + w / 2 >= mx && x + w / 2 < mx + mode->width && y + h / 2 >= my &&
            y + h / 2 < my + mode->height)
            return monitors[i];
    }
    return glfwGetPrimaryMonitor();
}
}  // namespace

bool displayNamed() {
#ifdef __EMSCRIPTEN__
    return true;  // the page's canvas
#endif
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

bool initialize(std::string* error) {
    glfwSetErrorCallback(onError);
    if (!displayNamed()) {
        if (error) *error = "no display: neither DISPLAY nor WAYLAND_DISPLAY is set";
        return false;
    }
    if (!glfwInit()) {
        if (error) *error = "no display: GLFW could not initialise (" + g_glfwError + ")";
        return false;
    }
    return true;
}

void terminate() { glfwTerminate(); }

bool createWindow(const WindowOptions& o, std::string* error) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);  // the even-odd polygon fill needs a stencil
    glfwWindowHint(GLFW_VISIBLE, o.hidden ? GLFW_FALSE : GLFW_TRUE);
#ifndef __EMSCRIPTEN__
    // Screenshots must be exactly the requested size, whatever the monitor's scale.
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, o.hidden ? GLFW_FALSE : GLFW_TRUE);
#endif
    g_window = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
    if (!g_window) {
        if (error) *error = "cannot create an OpenGL 3.3 core window: " + g_glfwError;
        return false;
    }
    glfwMakeContextCurrent(g_window);
    glfwSwapInterval(o.hidden ? 0 : 1);
    if (!loadGL(glfwGetProcAddress)) {
        if (error) *error = "cannot load OpenGL functions";
        return false;
    }
    glfwSetDropCallback(g_window, onDrop);
#ifndef __EMSCRIPTEN__
    glfwSetWindowContentScaleCallback(g_window, onContentScale);
#else
    (void)onContentScale;
    g_scale = float(emscripten_get_device_pixel_ratio());
    glfwSetWindowTitle(g_window, o.title.c_str());  // Emscripten's window leaves it unset
#endif
    ImGui_ImplGlfw_InitForOpenGL(g_window, true);
#ifdef __EMSCRIPTEN__
    ImGui::GetIO().SetClipboardTextFn = setClipboard;
    ImGui::GetIO().GetClipboardTextFn = getClipboard;
#endif
    g_imguiKey = glfwSetKeyCallback(g_window, onKey);
    return true;
}

void destroyWindow() {
    if (!g_window) return;
    if (fullscreen()) toggleFullscreen();  // the desktop gets its video mode back first
    ImGui_ImplGlfw_Shutdown();
    glfwDestroyWindow(g_window);
    g_window = nullptr;
}

bool shouldClose() { return glfwWindowShouldClose(g_window); }
void requestClose() { glfwSetWindowShouldClose(g_window, GLFW_TRUE); }
#ifdef __EMSCRIPTEN__
// The page's file picker (web/shell.html, Ctrl+O) writes the chosen file into the in-memory
// file system and opens it here, as a file dropped on the canvas.
extern "C" EMSCRIPTEN_KEEPALIVE void flood_web_open(const char* path) {
    g_dropped.emplace_back(path);
}

namespace {
// The canvas fills the page at the device's resolution; ImGui is scaled by the pixel ratio
// (contentScale), as on a hi-DPI monitor.
void followPage() {
    double cssW = 0, cssH = 0;
    emscripten_get_element_css_size("#canvas", &cssW, &cssH);
    const double ratio = emscripten_get_device_pixel_ratio();
    if (float(ratio) != g_scale) onContentScale(g_window, float(ratio), float(ratio));
    const int w = int(cssW * ratio + 0.5), h = int(cssH * ratio + 0.5);
    int nowW = 0, nowH = 0;
    glfwGetWindowSize(g_window, &nowW, &nowH);
    if (w > 0 && h > 0 && (w != nowW || h != nowH)) glfwSetWindowSize(g_window, w, h);
}
}  // namespace
void pollEvents() {
    flood_web_next_frame(0, 0);
    followPage();
}
void waitEvents(double timeout) {
    flood_web_next_frame(1, timeout);
    followPage();
}
#else
void pollEvents() { glfwPollEvents(); }
void waitEvents(double timeout) { glfwWaitEventsTimeout(timeout); }
#endif
void wake() { glfwPostEmptyEvent(); }
void persistConfig() {
#ifdef __EMSCRIPTEN__
    EM_ASM({
        if (Module["floodPersistConfig"]) Module["floodPersistConfig"]();
    });
#endif
}
void newFrame() { ImGui_ImplGlfw_NewFrame(); }
void swapBuffers() { glfwSwapBuffers(g_window); }
double time() { return glfwGetTime(); }

Vec2 windowSize() {
    int w = 0, h = 0;
    glfwGetWindowSize(g_window, &w, &h);
    return {double(w), double(h)};
}

void framebufferSize(int* w, int* h) { glfwGetFramebufferSize(g_window, w, h); }

float contentScale() {
#ifdef __EMSCRIPTEN__
    return g_scale > 0 ? g_scale : 1;
#else
    float x = 1, y = 1;
    glfwGetWindowContentScale(g_window, &x, &y);
    return x > 0 ? x : 1;
#endif
}

void setTitle(const std::string& title) { glfwSetWindowTitle(g_window, title.c_str()); }

std::vector<KeyPress> takeKeyPresses() { return g_keys.take(); }

bool fullscreen() { return g_window && glfwGetWindowMonitor(g_window) != nullptr; }

void toggleFullscreen() {
    if (!g_window) return;
    if (fullscreen()) {
        glfwSetWindowMonitor(g_window, nullptr, g_windowed[0], g_windowed[1], g_windowed[2],
                             g_windowed[3], 0);
        return;
    }
    GLFWmonitor* monitor = monitorOfWindow();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return;  // no monitor to cover (headless): stay windowed
    glfwGetWindowPos(g_window, &g_windowed[0], &g_windowed[1]);
    glfwGetWindowSize(g_window, &g_windowed[2], &g_windowed[3]);
    glfwSetWindowMonitor(g_window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

bool takeContentScaleChange(float* scale) {
    if (!g_scaleChanged) return false;
    g_scaleChanged = false;
    if (scale) *scale = g_scale;
    return true;
}

std::vector<std::string> takeDroppedPaths() {
    std::vector<std::string> out;
    out.swap(g_dropped);
    return out;
}

}  // namespace flood::view::platform
