#include "renderer.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <stb_image_write.h>  // implementation lives in Debian's libstb, not here
#include "gl_api.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>

#include "flood/io/output.h"  // atomic files
#include "shaders.h"          // generated from shaders/ by embed_shaders.cmake

namespace flood::view {

namespace {

#ifdef __EMSCRIPTEN__
// WebGL 2 speaks GLSL ES 3.00, which wants default precisions; the shaders are the same.
const char* const kVersion = "#version 300 es\nprecision highp float;\nprecision highp int;\n";
#else
const char* const kVersion = "#version 330 core\n";
#endif

// Compiles `parts` joined (glShaderSource takes a list: the version line, shared code, body).
GLuint compile(GLenum type, std::initializer_list<const char*> parts, const char* name,
               std::string* error) {
    GLuint s = glCreateShader(type);
    std::vector<const char*> src;
    for (const char* part : parts) {
        // A shader file's own version line becomes this platform's (kVersion).
        static const char kFileVersion[] = "#version 330 core\n";
        if (std::strncmp(part, kFileVersion, sizeof kFileVersion - 1) == 0)
            src.push_back(kVersion), part += sizeof kFileVersion - 1;
        src.push_back(part);
    }
    glShaderSource(s, GLsizei(src.size()), src.data(), nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        if (error) *error = std::string("shader ") + name + " failed to compile:\n" + log;
        glDeleteShader(s);
        return 0;
    }
    return s;
}

GLuint link(GLuint vs, GLuint fs, const char* name, std::string* error) {
    if (!vs || !fs) {
        glDeleteShader(vs), glDeleteShader(fs);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        if (error) *error = std::string("shader program ") + name + " failed to link:\n" + log;
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

// A world-space program: the vertex shader gets the camera (shaders/camera.glsl) prepended.
GLuint worldProgram(const char* vert, const char* frag, const char* name, std::string* error) {
    return link(compile(GL_VERTEX_SHADER, {kVersion, kShader_camera_glsl, vert}, name, error),
                compile(GL_FRAGMENT_SHADER, {frag}, name, error), name, error);
}

void upload(GLenum target, uint32_t buffer, const void* data, size_t bytes) {
    glBindBuffer(target, buffer);
    glBufferData(target, GLsizeiptr(bytes), bytes ? data : nullptr, GL_STATIC_DRAW);
}

void setColor(int location, Rgba c) {
    glUniform4f(location, c.r / 255.f, c.g / 255.f, c.b / 255.f, c.a / 255.f);
}

// Instanced attributes of SegmentVertex (segment.vert) and vertex attributes of
// MarkerVertex (marker.vert), for the VAO currently bound.
void segmentAttributes() {
    const GLsizei stride = sizeof(SegmentVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(SegmentVertex, ax)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                          reinterpret_cast<void*>(offsetof(SegmentVertex, color)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(SegmentVertex, width)));
    for (GLuint a : {0u, 1u, 2u}) glVertexAttribDivisor(a, 1);
}

void markerAttributes() {
    const GLsizei stride = sizeof(MarkerVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(MarkerVertex, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                          reinterpret_cast<void*>(offsetof(MarkerVertex, color)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(MarkerVertex, radius)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(MarkerVertex, shape)));
}

}  // namespace

Renderer::~Renderer() {
    // Only tear down if init() ran: the context may already be gone otherwise.
    if (!screen_.id) return;
    glDeleteBuffers(GLsizei(vbo_.size()), vbo_.data());
    glDeleteVertexArrays(GLsizei(vao_.size()), vao_.data());
    glDeleteBuffers(GLsizei(buf_.size()), buf_.data());
    glDeleteVertexArrays(GLsizei(wvao_.size()), wvao_.data());
    for (Program* p : {&screen_, &world_, &segment_, &marker_}) glDeleteProgram(p->id);
}

bool Renderer::init(std::string* error) {
    screen_.id =
        link(compile(GL_VERTEX_SHADER, {kShader_canvas_vert}, "shaders/canvas.vert", error),
             compile(GL_FRAGMENT_SHADER, {kShader_canvas_frag}, "shaders/canvas.frag", error),
             "canvas", error);
    world_.id = worldProgram(kShader_world_vert, kShader_solid_frag, "world + solid", error);
    segment_.id = worldProgram(kShader_segment_vert, kShader_canvas_frag, "segment", error);
    marker_.id = worldProgram(kShader_marker_vert, kShader_marker_frag, "marker", error);
    if (!screen_.id || !world_.id || !segment_.id || !marker_.id) return false;
    for (Program* p : {&screen_, &world_, &segment_, &marker_}) {
        p->center = glGetUniformLocation(p->id, "uCenter");
        p->scale = glGetUniformLocation(p->id, "uScale");
        p->viewport = glGetUniformLocation(p->id, "uViewport");
        p->viewSize = glGetUniformLocation(p->id, "uViewSize");
        p->color = glGetUniformLocation(p->id, "uColor");
        p->uiScale = glGetUniformLocation(p->id, "uUiScale");
        p->pixelRatio = glGetUniformLocation(p->id, "uPixelRatio");
    }
    glGenVertexArrays(GLsizei(vao_.size()), vao_.data());
    glGenBuffers(GLsizei(vbo_.size()), vbo_.data());
    for (size_t i = 0; i < vao_.size(); ++i) {
        glBindVertexArray(vao_[i]);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_[i]);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<void*>(offsetof(Vertex, x)));
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                              reinterpret_cast<void*>(offsetof(Vertex, r)));
    }

    glGenBuffers(GLsizei(buf_.size()), buf_.data());
    glGenVertexArrays(GLsizei(wvao_.size()), wvao_.data());
    // Triangles, edges and fans index the shared positions; the cover quad has its own.
    for (Buffer b : {Triangles, Edges, Fans, Cover, BoundaryEdges, PixelBoundary}) {
        glBindVertexArray(wvao_[b]);
        glBindBuffer(GL_ARRAY_BUFFER, buf_[b == Cover ? Cover : Positions]);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
        if (b != Cover) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf_[b]);
    }
    for (Buffer b : {Boundary, Bridges, OverlayLines}) {
        glBindVertexArray(wvao_[b]);
        glBindBuffer(GL_ARRAY_BUFFER, buf_[b]);
        segmentAttributes();
    }
    for (Buffer b : {Classes, OverlayMarkers}) {
        glBindVertexArray(wvao_[b]);
        glBindBuffer(GL_ARRAY_BUFFER, buf_[b]);
        markerAttributes();
    }
    glBindVertexArray(0);
    return true;
}

void Renderer::setGeometry(const CanvasGeometry& g) {
    if (!screen_.id) return;
    auto put = [&](Buffer b, GLenum target, const auto& v, size_t count) {
        // An element buffer is VAO state: bind it through its own VAO.
        glBindVertexArray(target == GL_ELEMENT_ARRAY_BUFFER ? wvao_[b] : 0);
        upload(target, buf_[b], v.data(), v.size() * sizeof(v[0]));
        count_[b] = count;
    };
    put(Positions, GL_ARRAY_BUFFER, g.positions, g.positions.size() / 2);
    put(Triangles, GL_ELEMENT_ARRAY_BUFFER, g.triangles, g.triangles.size());
    put(Edges, GL_ELEMENT_ARRAY_BUFFER, g.edges, g.edges.size());
    put(Fans, GL_ELEMENT_ARRAY_BUFFER, g.fans, g.fans.size());
    const float* b = g.bbox;
    std::vector<float> cover{b[0], b[1], b[2], b[1], b[2], b[3],
                             b[0], b[1], b[2], b[3], b[0], b[3]};
    put(Cover, GL_ARRAY_BUFFER, cover, g.fans.empty() ? 0 : 6);
    put(Boundary, GL_ARRAY_BUFFER, g.boundary, g.boundary.size());
    put(Bridges, GL_ARRAY_BUFFER, g.bridges, g.bridges.size());
    put(BoundaryEdges, GL_ELEMENT_ARRAY_BUFFER, g.boundaryEdges, g.boundaryEdges.size());
    count_[PixelBoundary] = 0;  // the last geometry's, for its camera: the canvas sets it again
    dryIsUncut_ = g.dryIsUncut;
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::setPixelBoundary(const std::vector<uint32_t>& lines) {
    if (!screen_.id) return;
    glBindVertexArray(wvao_[PixelBoundary]);  // an element buffer is VAO state
    upload(GL_ELEMENT_ARRAY_BUFFER, buf_[PixelBoundary], lines.data(),
           lines.size() * sizeof(lines[0]));
    count_[PixelBoundary] = lines.size();
    glBindVertexArray(0);
}

void Renderer::setOverlay(const std::vector<SegmentVertex>& lines) {
    if (!screen_.id) return;
    upload(GL_ARRAY_BUFFER, buf_[OverlayLines], lines.data(), lines.size() * sizeof(lines[0]));
    count_[OverlayLines] = lines.size();
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::setMarkers(const std::vector<MarkerVertex>& vertices,
                          const std::vector<MarkerVertex>& overlay) {
    if (!screen_.id) return;
    upload(GL_ARRAY_BUFFER, buf_[Classes], vertices.data(), vertices.size() * sizeof(vertices[0]));
    count_[Classes] = vertices.size();
    upload(GL_ARRAY_BUFFER, buf_[OverlayMarkers], overlay.data(),
           overlay.size() * sizeof(overlay[0]));
    count_[OverlayMarkers] = overlay.size();
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::clear() {
    for (auto& l : layers_) l.clear();
}

void Renderer::push(Layer layer, Vec2 p, Rgba c) {
    layers_[size_t(layer)].push_back({float(p.x), float(p.y), c.r, c.g, c.b, c.a});
}

void Renderer::addTriangle(Layer layer, Vec2 a, Vec2 b, Vec2 c, Rgba color) {
    push(layer, a, color), push(layer, b, color), push(layer, c, color);
}

void Renderer::addLine(Layer layer, Vec2 a, Vec2 b, float width, Rgba color) {
    double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (len < 1e-9) return;
    double nx = -dy / len * width / 2, ny = dx / len * width / 2;
    Vec2 p0{a.x + nx, a.y + ny}, p1{b.x + nx, b.y + ny}, p2{b.x - nx, b.y - ny},
        p3{a.x - nx, a.y - ny};
    addTriangle(layer, p0, p1, p2, color);
    addTriangle(layer, p0, p2, p3, color);
}

void Renderer::addDisc(Layer layer, Vec2 c, float radius, Rgba color) {
    const int n = 20;
    for (int i = 0; i < n; ++i) {
        double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n;
        addTriangle(layer, c, {c.x + radius * std::cos(a0), c.y + radius * std::sin(a0)},
                    {c.x + radius * std::cos(a1), c.y + radius * std::sin(a1)}, color);
    }
}

void Renderer::addCircle(Layer layer, Vec2 c, float radius, float width, Rgba color) {
    const int n = 24;
    for (int i = 0; i < n; ++i) {
        double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n;
        addLine(layer, {c.x + radius * std::cos(a0), c.y + radius * std::sin(a0)},
                {c.x + radius * std::cos(a1), c.y + radius * std::sin(a1)}, width, color);
    }
}

void Renderer::useWorld(const Program& p, const WorldView& v, Vec2 windowSize) {
    glUseProgram(p.id);
    glUniform2f(p.center, float(v.center.x), float(v.center.y));
    glUniform1f(p.scale, float(v.scale));
    glUniform4f(p.viewport, float(v.viewport.x), float(v.viewport.y), float(v.viewport.w),
                float(v.viewport.h));
    glUniform2f(p.viewSize, float(windowSize.x), float(windowSize.y));
    glUniform1f(p.uiScale, v.uiScale);
}

void Renderer::drawWorld(const WorldView& v, Vec2 windowSize, float pixelRatio) {
    auto elements = [&](Buffer b, GLenum mode, size_t first, size_t end) {
        end = std::min(end, count_[b]);
        if (first >= end) return;
        glBindVertexArray(wvao_[b]);
        glDrawElements(mode, GLsizei(end - first), GL_UNSIGNED_INT,
                       reinterpret_cast<void*>(first * sizeof(uint32_t)));
    };
    auto segments = [&](Buffer b, size_t count) {
        count = std::min(count, count_[b]);
        if (!count) return;
        glBindVertexArray(wvao_[b]);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(count));
    };
    auto markers = [&](Buffer b) {
        if (!count_[b]) return;
        glBindVertexArray(wvao_[b]);
        glDrawArrays(GL_POINTS, 0, GLsizei(count_[b]));
    };

    // Dry land: the triangles not cut yet when they tile the polygon (half the vertices of
    // the alternative); otherwise fans into the stencil with INVERT (even-odd), then the
    // cover quad through it.
    useWorld(world_, v, windowSize);
    if (dryIsUncut_) {
        setColor(world_.color, palette::kPolygonFill);
        elements(Triangles, GL_TRIANGLES, 3 * size_t(v.currentEnd), count_[Triangles]);
    } else if (count_[Fans]) {
        glEnable(GL_STENCIL_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
        elements(Fans, GL_TRIANGLES, 0, count_[Fans]);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilFunc(GL_NOTEQUAL, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        setColor(world_.color, palette::kPolygonFill);
        glBindVertexArray(wvao_[Cover]);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(count_[Cover]));
        glDisable(GL_STENCIL_TEST);
    }
    // Water, then the triangles of the current step: two ranges of the flood-order buffer.
    setColor(world_.color, palette::kWater);
    elements(Triangles, GL_TRIANGLES, 0, 3 * size_t(v.waterEnd));
    setColor(world_.color, palette::kCurrent);
    elements(Triangles, GL_TRIANGLES, 3 * size_t(v.waterEnd), 3 * size_t(v.currentEnd));
    setColor(world_.color, palette::kTriangleEdge);
    elements(Edges, GL_LINES, 0, 6 * size_t(v.edgeEnd));

    if (v.thinBoundary) {
        setColor(world_.color, palette::kBoundary);
        const Buffer b = count_[PixelBoundary] ? PixelBoundary : BoundaryEdges;
        elements(b, GL_LINES, 0, count_[b]);
    }

    useWorld(segment_, v, windowSize);
    if (!v.thinBoundary) segments(Boundary, count_[Boundary]);
    segments(Bridges, v.bridgeCount);
    segments(OverlayLines, count_[OverlayLines]);

    useWorld(marker_, v, windowSize);
    glUniform1f(marker_.pixelRatio, pixelRatio);
#ifndef __EMSCRIPTEN__  // GL ES (WebGL) always takes gl_PointSize from the shader
    glEnable(GL_PROGRAM_POINT_SIZE);
#endif
    if (v.classes) markers(Classes);
    markers(OverlayMarkers);
#ifndef __EMSCRIPTEN__
    glDisable(GL_PROGRAM_POINT_SIZE);
#endif
}

void Renderer::render(Vec2 windowSize, int fbW, int fbH, const Rect& clip, Rgba bg,
                      const WorldView& view) {
    glViewport(0, 0, fbW, fbH);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(bg.r / 255.f, bg.g / 255.f, bg.b / 255.f, 1.f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (!screen_.id || windowSize.x <= 0 || windowSize.y <= 0) return;

    double sx = fbW / windowSize.x, sy = fbH / windowSize.y;
    glEnable(GL_SCISSOR_TEST);
    glScissor(GLint(clip.x * sx), GLint(fbH - (clip.y + clip.h) * sy), GLsizei(clip.w * sx),
              GLsizei(clip.h * sy));
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    drawWorld(view, windowSize, float(sx));

    glUseProgram(screen_.id);
    glUniform2f(screen_.viewSize, float(windowSize.x), float(windowSize.y));
    for (size_t i = 0; i < layers_.size(); ++i) {
        const auto& verts = layers_[i];
        if (verts.empty()) continue;
        glBindVertexArray(vao_[i]);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_[i]);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(Vertex)), verts.data(),
                     GL_STREAM_DRAW);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(verts.size()));
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::finish() { glFinish(); }

bool readFramebuffer(unsigned buffer, int width, int height, std::vector<uint8_t>& rgba) {
    if (width <= 0 || height <= 0) return false;
    std::vector<uint8_t> raw(size_t(width) * height * 4);
    glReadBuffer(buffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    if (glGetError() != GL_NO_ERROR) return false;
    // GL's rows start at the bottom; PNG's and GIF's at the top. The buffer's alpha is not ours.
    rgba.resize(raw.size());
    size_t row = size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(raw.data() + (height - 1 - y) * row, row, rgba.data() + y * row);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    return true;
}

bool Renderer::readPixels(int width, int height, std::vector<uint8_t>& rgba) const {
    return readFramebuffer(GL_BACK, width, height, rgba);
}

bool imguiGlInit() {
#ifdef __EMSCRIPTEN__
    return ImGui_ImplOpenGL3_Init("#version 300 es");
#else
    return ImGui_ImplOpenGL3_Init("#version 330 core");
#endif
}
void imguiGlNewFrame() { ImGui_ImplOpenGL3_NewFrame(); }
void imguiGlRender() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }
void imguiGlShutdown() { ImGui_ImplOpenGL3_Shutdown(); }

bool writePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
              std::string* error) {
    if (width <= 0 || height <= 0 || rgba.size() < size_t(width) * height * 4) {
        if (error) *error = "error: " + path + ": cannot write: no pixels to write";
        return false;
    }
    // Through the CLI's atomic output: a failed write leaves no half a PNG behind.
    Output out(path);
    auto write = [](void* context, void* data, int size) {
        static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
    };
    if (!stbi_write_png_to_func(write, &out.stream(), width, height, 4, rgba.data(), width * 4)) {
        if (error) *error = "error: " + path + ": cannot write: the PNG encoder failed";
        return false;
    }
    std::string reason;
    if (out.commit(&reason) != Status::Ok) {
        if (error) *error = reason;
        return false;
    }
    return true;
}

}  // namespace flood::view
