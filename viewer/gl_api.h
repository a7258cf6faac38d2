// The OpenGL API the viewer draws with: OpenGL 3.3 core through glad's loader on the desktop
// (generated at build time, viewer/CMakeLists.txt); WebGL 2 on the web, which is OpenGL ES 3.0
// and whose functions Emscripten links directly, so there is nothing to load.
#pragma once
#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#else
#include <glad/gl.h>
#endif

namespace flood::view {

// Loads the GL functions of the current context; false if they cannot be had.
template <typename GetProc>
bool loadGL(GetProc getProcAddress) {
#ifdef __EMSCRIPTEN__
    (void)getProcAddress;
    return true;
#else
    return gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress)) != 0;
#endif
}

}  // namespace flood::view
