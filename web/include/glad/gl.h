// The web build's <glad/gl.h>: WebGL 2 is OpenGL ES 3.0, whose functions Emscripten links
// directly; nothing to load. The desktop build generates the real glad (viewer/CMakeLists.txt).
#pragma once
#include <GLES3/gl3.h>
#define GLAD_GL_VERSION_3_3 1
typedef void (*GLADapiproc)(void);
typedef GLADapiproc (*GLADloadfunc)(const char* name);
static inline int gladLoadGL(GLADloadfunc) { return 1; }
