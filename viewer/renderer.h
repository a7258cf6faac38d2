// The only file pair with OpenGL calls. Two kinds of geometry, both drawn under ImGui:
// - world space (canvas_vertices.h, built by canvas_geometry.h): the polygon, its triangles, edges and markers live in
//   buffers uploaded once per trace, the per-step overlay in buffers uploaded when the step
//   changes, and the camera is a uniform, so a frame issues a dozen draw calls and uploads
//   nothing. A step's triangles are a prefix of the flood-order buffer: one draw call.
// - screen space: small extras batched on the CPU every frame into one vertex buffer per
//   layer (arrowheads), in ImGui's logical pixels (origin top-left, y down).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "canvas_vertices.h"
#include "geometry.h"
#include "palette.h"

namespace flood::view {

enum class Layer : uint8_t { Lines, Markers, Count };

// The camera and how much of the static geometry the current step shows.
struct WorldView {
    Point center;  // camera centre minus the geometry's origin
    double scale = 1;
    Rect viewport;
    uint32_t waterEnd = 0, currentEnd = 0;  // triangles [0, waterEnd) flooded, then current
    uint32_t edgeEnd = 0;                   // triangles whose edges are drawn
    uint32_t bridgeCount = 0;               // a prefix of CanvasGeometry::bridges
    bool classes = true;                    // vertex markers (as thinned by setMarkers)
    bool thinBoundary = false;              // 1-pixel boundary (dense: cheaper, same look)
    float uiScale = 1;
};

class Renderer {
public:
    Renderer() = default;
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Needs a current GL 3.3 core context with a loaded glad. Compile errors go to `error`
    // with the shader log.
    bool init(std::string* error);

    // World-space buffers: the trace's once when it is opened, the overlay when the step changes.
    void setGeometry(const CanvasGeometry& g);
    // The thin boundary drawn instead of every edge (pixelBoundary: decimated for the current
    // camera); empty: every edge.
    void setPixelBoundary(const std::vector<uint32_t>& lines);
    // The overlay's lines (CanvasOverlay::lines); its markers come from setMarkers.
    void setOverlay(const std::vector<SegmentVertex>& lines);
    // The markers thinned for the current camera (thinMarkers): the vertices' and the overlay's.
    void setMarkers(const std::vector<MarkerVertex>& vertices,
                    const std::vector<MarkerVertex>& overlay);

    void clear();  // empties every screen-space layer; call once per frame before adding
    void addTriangle(Layer layer, Vec2 a, Vec2 b, Vec2 c, Rgba color);
    void addLine(Layer layer, Vec2 a, Vec2 b, float width, Rgba color);
    void addDisc(Layer layer, Vec2 c, float radius, Rgba color);
    void addCircle(Layer layer, Vec2 c, float radius, float width, Rgba color);

    // Clears the framebuffer and draws the world, then the screen-space layers, clipped to
    // `clip` (logical pixels). The polygon is filled even-odd (stencil), so holes need no
    // triangulation and even self-intersecting input shows something sensible.
    // `windowSize` is the logical size, `framebuffer` the pixel size (they differ on hi-DPI).
    void render(Vec2 windowSize, int framebufferW, int framebufferH, const Rect& clip,
                Rgba background, const WorldView& view);

    void finish();  // waits for the GPU (llvmpipe: the rasteriser threads); benchmarks only
    // Reads the back buffer (call before the swap): RGBA, top row first, alpha 255.
    bool readPixels(int width, int height, std::vector<uint8_t>& rgba) const;

private:
    struct Vertex {
        float x, y;
        uint8_t r, g, b, a;
    };
    struct Program {
        uint32_t id = 0;
        int center = -1, scale = -1, viewport = -1, viewSize = -1, color = -1, uiScale = -1,
            pixelRatio = -1;
    };
    // World buffers; each VAO binds one buffer (and its element buffer) for one kind of draw.
    enum Buffer {
        Positions,
        Triangles,
        Edges,
        Fans,
        Cover,
        Boundary,
        BoundaryEdges,
        PixelBoundary,
        Bridges,
        Classes,
        Regular,
        OverlayLines,
        OverlayMarkers,
        BufferCount
    };
    void push(Layer layer, Vec2 p, Rgba c);
    void drawWorld(const WorldView& view, Vec2 windowSize, float pixelRatio);
    void useWorld(const Program& p, const WorldView& view, Vec2 windowSize);
    std::array<std::vector<Vertex>, size_t(Layer::Count)> layers_;
    std::array<uint32_t, size_t(Layer::Count)> vbo_{}, vao_{};
    std::array<uint32_t, BufferCount> buf_{}, wvao_{};
    std::array<size_t, BufferCount> count_{};  // indices, instances or vertices in each
    Program screen_, world_, segment_, marker_;
    bool dryIsUncut_ = false;
};

// ImGui's OpenGL half lives here too, because it issues GL calls.
bool imguiGlInit();
void imguiGlNewFrame();
void imguiGlRender();  // draws ImGui's draw data over the canvas
void imguiGlShutdown();

// Writes RGBA pixels (top row first) as a PNG, atomically. Returns false with the line to show
// in `error`: "error: PATH: cannot write: REASON".
bool writePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba,
              std::string* error);

// Reads `buffer` (a GL read-buffer name: GL_BACK, GL_COLOR_ATTACHMENT0) as RGBA rows, top row
// first, alpha opaque. False when GL reports an error.
bool readFramebuffer(unsigned buffer, int width, int height, std::vector<uint8_t>& rgba);

}  // namespace flood::view
