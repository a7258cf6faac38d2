#include "renderer.h"

#include <glad/gl.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <stb_image_write.h>  // implementation lives in Debian's libstb, not here

#include <algorithm>
#include <cmath>

#include "shaders.h"  // generated from shaders/ by embed_shaders.cmake

namespace flood::view {

namespace {

GLuint compile(GLenum type, const char* source, const char* name, std::string* error) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
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

}  // namespace

Renderer::~Renderer() {
    // Only tear down if init() ran: the context may already be gone otherwise.
    if (!program_) return;
    glDeleteBuffers(GLsizei(vbo_.size()), vbo_.data());
    glDeleteVertexArrays(GLsizei(vao_.size()), vao_.data());
    glDeleteProgram(program_);
}

bool Renderer::init(std::string* error) {
    GLuint vs = compile(GL_VERTEX_SHADER, kShader_canvas_vert, "shaders/canvas.vert", error);
    GLuint fs = compile(GL_FRAGMENT_SHADER, kShader_canvas_frag, "shaders/canvas.frag", error);
    if (!vs || !fs) return false;
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(program_, sizeof log, nullptr, log);
        if (error) *error = std::string("shader program failed to link:\n") + log;
        glDeleteProgram(program_);
        program_ = 0;
        return false;
    }
    uViewSize_ = glGetUniformLocation(program_, "uViewSize");
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
    glBindVertexArray(0);
    return true;
}

void Renderer::clear() {
    for (auto& l : layers_) l.clear();
    ringFans_.clear();
    bbox_[0] = bbox_[1] = 1e30f;
    bbox_[2] = bbox_[3] = -1e30f;
}

void Renderer::push(Layer layer, Vec2 p, Rgba c) {
    layers_[size_t(layer)].push_back({float(p.x), float(p.y), c.r, c.g, c.b, c.a});
}

void Renderer::addRing(const std::vector<Vec2>& ring) {
    if (ring.size() < 3) return;
    auto put = [&](Vec2 p) {
        ringFans_.push_back({float(p.x), float(p.y), 0, 0, 0, 255});
        bbox_[0] = std::min(bbox_[0], float(p.x)), bbox_[1] = std::min(bbox_[1], float(p.y));
        bbox_[2] = std::max(bbox_[2], float(p.x)), bbox_[3] = std::max(bbox_[3], float(p.y));
    };
    for (size_t i = 1; i + 1 < ring.size(); ++i) put(ring[0]), put(ring[i]), put(ring[i + 1]);
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

void Renderer::addArrow(Layer layer, Vec2 a, Vec2 b, float width, float head, Rgba color) {
    double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if (len < 1e-9) return;
    double ux = dx / len, uy = dy / len;
    head = float(std::min<double>(head, len / 2));
    Vec2 base{b.x - ux * head, b.y - uy * head};
    addLine(layer, a, base, width, color);
    addTriangle(layer, b, {base.x - uy * head / 2, base.y + ux * head / 2},
                {base.x + uy * head / 2, base.y - ux * head / 2}, color);
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

void Renderer::render(Vec2 windowSize, int fbW, int fbH, const Rect& clip, Rgba bg) {
    glViewport(0, 0, fbW, fbH);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(bg.r / 255.f, bg.g / 255.f, bg.b / 255.f, 1.f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (!program_ || windowSize.x <= 0 || windowSize.y <= 0) return;

    double sx = fbW / windowSize.x, sy = fbH / windowSize.y;
    glEnable(GL_SCISSOR_TEST);
    glScissor(GLint(clip.x * sx), GLint(fbH - (clip.y + clip.h) * sy), GLsizei(clip.w * sx),
              GLsizei(clip.h * sy));
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(program_);
    glUniform2f(uViewSize_, float(windowSize.x), float(windowSize.y));

    // Fill layer: fans into the stencil with INVERT (even-odd), then one cover quad.
    auto& fill = layers_[size_t(Layer::Fill)];
    fill = ringFans_;
    size_t fans = fill.size();
    if (fans) {
        Rgba c = fillColor_;
        Vertex q[4] = {{bbox_[0], bbox_[1], c.r, c.g, c.b, c.a},
                       {bbox_[2], bbox_[1], c.r, c.g, c.b, c.a},
                       {bbox_[2], bbox_[3], c.r, c.g, c.b, c.a},
                       {bbox_[0], bbox_[3], c.r, c.g, c.b, c.a}};
        for (int i : {0, 1, 2, 0, 2, 3}) fill.push_back(q[i]);
    }
    for (size_t i = 0; i < layers_.size(); ++i) {
        const auto& verts = layers_[i];
        if (verts.empty()) continue;
        glBindVertexArray(vao_[i]);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_[i]);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(Vertex)), verts.data(),
                     GL_STREAM_DRAW);
        if (Layer(i) == Layer::Fill) {
            glEnable(GL_STENCIL_TEST);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glStencilFunc(GL_ALWAYS, 0, 0xff);
            glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(fans));
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glStencilFunc(GL_NOTEQUAL, 0, 0xff);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glDrawArrays(GL_TRIANGLES, GLint(fans), GLsizei(verts.size() - fans));
            glDisable(GL_STENCIL_TEST);
        } else {
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(verts.size()));
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
}

bool Renderer::readPixels(int width, int height, std::vector<uint8_t>& rgba) const {
    if (width <= 0 || height <= 0) return false;
    std::vector<uint8_t> raw(size_t(width) * height * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    if (glGetError() != GL_NO_ERROR) return false;
    // GL's rows start at the bottom; PNG's at the top. The back buffer's alpha is not ours.
    rgba.resize(raw.size());
    size_t row = size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(raw.data() + (height - 1 - y) * row, row, rgba.data() + y * row);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    return true;
}

bool imguiGlInit() { return ImGui_ImplOpenGL3_Init("#version 330 core"); }
void imguiGlNewFrame() { ImGui_ImplOpenGL3_NewFrame(); }
void imguiGlRender() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }
void imguiGlShutdown() { ImGui_ImplOpenGL3_Shutdown(); }

bool writePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
              std::string* error) {
    if (rgba.size() < size_t(width) * height * 4) {
        if (error) *error = "no pixels to write";
        return false;
    }
    if (!stbi_write_png(path.c_str(), width, height, 4, rgba.data(), width * 4)) {
        if (error) *error = "cannot write " + path;
        return false;
    }
    return true;
}

}  // namespace flood::view
