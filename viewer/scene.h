// What the canvas shows at the current step, as world-space primitives with colours. Built
// from the model alone (no GL, no ImGui) so the canvas, the SVG export and the tests agree.
#pragma once
#include <string>
#include <vector>

#include "model.h"
#include "palette.h"

namespace flood::view {

struct Scene {
    struct Tri {
        Point a, b, c;
        Rgba color;
    };
    struct Line {
        Point a, b;
        Rgba color;
        float width = 1;  // screen pixels (before UI scale)
        bool arrow = false;
    };
    enum class Shape : uint8_t { Disc, Ring, Finger };
    struct Marker {
        Point p;
        Rgba color;
        float radius = 3;  // screen pixels (before UI scale)
        Shape shape = Shape::Disc;
        bool thin = false;  // one of many alike (vertex classes, gorges): thinned by screen density
    };
    // What a label is, in the order the canvas places them (first placed, first served).
    enum class LabelKind : uint8_t {
        Named,   // a vertex or triangle the step's sentence names: large, always shown
        Finger,  // L, R, NL, NR: always shown
        Ghost,   // a finger before the step, where it moved: dropped when no room is left
        Gorge,   // a pending or held gorge: dropped when no room is left, folded when crowded
        Number   // a triangle's number (the whole scene only; the canvas draws its own)
    };
    struct Label {
        Point p;
        std::string text;
        Rgba color;
        // Screen offset (before UI scale) in the SVG; on the canvas its signs choose the side
        // the label would rather go (dx < 0: left of the point, dy < 0: above it).
        float dx = 0, dy = 0;
        double minArea = 0;    // hide when the owner's screen area (px²) is below this
        double worldArea = 0;  // area of the owning triangle in world units², 0 = always
        bool folds = false;    // one of many alike (gorge labels): hidden when crowded
        LabelKind kind = LabelKind::Number;
        Index vertex = kNone;       // the vertex it names (Named, Finger, Ghost)
        uint32_t triangle = kNone;  // the triangle it names (Named)
    };
    std::vector<std::vector<Point>> rings;  // filled even-odd: holes stay open
    std::vector<Tri> water;                 // flooded triangles
    std::vector<Tri> current;               // triangles cut by the current event
    std::vector<Line> lines;                // edges, chain, water level, bridges, jumps
    std::vector<Marker> markers;            // vertex classes, fingers, culprits
    std::vector<Label> labels;
    Point waterA, waterB;  // the water level across the gorge
    bool hasWater = false;
};

struct SceneOptions {
    bool vertexClasses = true;
    bool triangleNumbers = true;
    bool triangleEdges = true;
    bool jumps = true;
    bool bridges = true;
    bool dormant = true;
    bool vertexNumbers = true;
    bool gorgeFocus = false;  // "current gorge only": dim everything outside the active gorge
    // The step as a transition: the chain and the fingers before it, faint, under those after.
    bool ghost = true;
    // Only what changes with the step: no rings, triangles, boundary, bridges or vertex
    // classes (the canvas keeps those in GPU buffers, see canvas_geometry.h).
    bool perStepOnly = false;
};

Scene buildScene(const Model& model, const SceneOptions& options = {});
// The labels and rings of what the sentence of event `e` names (flood/teach/narrate.h): each
// vertex once, "35 sag", with its first role; its triangles, "triangle 18", all of them up to
// kNamedTriangles, else the first and the last. buildScene adds them at the current event.
constexpr uint32_t kNamedTriangles = 6;
void addNamedLabels(Scene& scene, const Model& model, const Event& e);
Rgba vertexClassColor(VertexClass c);  // the legend's colours

// Writes the scene as a standalone SVG of the given pixel width, the polygon fitted.
void writeSceneSvg(std::ostream& out, const Scene& scene, const Polygon& polygon, int width);
// The same through `camera` (its viewport is the canvas, clipped as on screen) on a page of
// width x height, with an optional caption line below the canvas. Triangles are <polygon>
// elements of class "water" or "current" (cut by the current event).
struct CaptionLine {  // export.h's captionOf: "Step N  Action" and the narration
    std::string head, text;
    Rgba headColor;
};
void writeSceneSvg(std::ostream& out, const Scene& scene, const Camera& camera, int width,
                   int height, const CaptionLine* caption = nullptr);

}  // namespace flood::view
