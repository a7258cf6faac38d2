// The only file pair with OpenGL calls. Geometry is batched on the CPU into one vertex buffer
// per layer and drawn with one call per layer, in layer order, under ImGui.
// Coordinates are screen pixels in ImGui's logical units (origin top-left, y down).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model.h"
#include "palette.h"

namespace flood::view {

enum class Layer : uint8_t { Fill, Water, Triangles, Lines, Markers, Count };

class Renderer {
public:
    Renderer() = default;
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Needs a current GL 3.3 core context with a loaded glad. Compile errors go to `error`
    // with the shader log.
    bool init(std::string* error);

    void clear();  // empties every layer; call once per frame before adding geometry
    // The Fill layer is filled even-odd (stencil), so holes need no triangulation and even
    // self-intersecting input shows something sensible.
    void addRing(const std::vector<Vec2>& ring);
    void setFillColor(Rgba c) { fillColor_ = c; }
    void addTriangle(Layer layer, Vec2 a, Vec2 b, Vec2 c, Rgba color);
    void addLine(Layer layer, Vec2 a, Vec2 b, float width, Rgba color);
    void addArrow(Layer layer, Vec2 a, Vec2 b, float width, float head, Rgba color);
    void addDisc(Layer layer, Vec2 c, float radius, Rgba color);
    void addCircle(Layer layer, Vec2 c, float radius, float width, Rgba color);

    // Clears the framebuffer and draws the layers clipped to `clip` (logical pixels).
    // `windowSize` is the logical size, `framebuffer` the pixel size (they differ on hi-DPI).
    void render(Vec2 windowSize, int framebufferW, int framebufferH, const Rect& clip,
                Rgba background);

    // Reads the back buffer (call before the swap): RGBA, top row first, alpha 255.
    bool readPixels(int width, int height, std::vector<uint8_t>& rgba) const;

private:
    struct Vertex {
        float x, y;
        uint8_t r, g, b, a;
    };
    void push(Layer layer, Vec2 p, Rgba c);
    std::array<std::vector<Vertex>, size_t(Layer::Count)> layers_;
    std::vector<Vertex> ringFans_;  // triangle fans of every ring, for the stencil pass
    std::array<uint32_t, size_t(Layer::Count)> vbo_{}, vao_{};
    uint32_t program_ = 0;
    int uViewSize_ = -1;
    Rgba fillColor_ = palette::kPolygonFill;
    float bbox_[4] = {0, 0, 0, 0};  // bounding box of the rings, for the stencil cover quad
};

// ImGui's OpenGL half lives here too, because it issues GL calls.
bool imguiGlInit();
void imguiGlNewFrame();
void imguiGlRender();  // draws ImGui's draw data over the canvas
void imguiGlShutdown();

// Writes RGBA pixels (top row first) as a PNG. Returns false with a reason in `error`.
bool writePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
              std::string* error);

}  // namespace flood::view
