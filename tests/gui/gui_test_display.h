// The display check the GUI tests share: they draw in a real (hidden) window, so they need X or
// Wayland — Xvfb in CI, where a missing display is a broken set-up, not a reason to skip.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

inline bool hasDisplay() {
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

inline bool inCi() {
    const char* ci = std::getenv("CI");
    return ci && std::string(ci) == "true";
}

// For a test's main(): 0 to go on; else the exit code — 77 (ctest's skip) without a display,
// 1 in CI.
inline int displayOrSkip() {
    if (hasDisplay()) return 0;
    if (inCi()) {
        std::fprintf(stderr, "FAIL: no display in CI: run the tests under xvfb-run -a\n");
        return 1;
    }
    std::printf("SKIP: no display (run under xvfb-run -a)\n");
    return 77;
}
