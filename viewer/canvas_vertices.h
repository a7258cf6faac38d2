// The GPU's view of the canvas: the vertex layouts the renderer's shaders read and the world
// geometry uploaded once per trace (canvas_geometry.h builds them from the model). Kept apart
// from the model so the renderer sees only these arrays.
#pragma once
#include <cstdint>
#include <vector>

#include "flood/geometry/polygon.h"  // Point
#include "palette.h"

namespace flood::view {

struct SegmentVertex {  // one instance of the thick-line shader
    float ax, ay, bx, by;
    Rgba color;
    float width;  // screen pixels before UI scale
};

struct MarkerVertex {  // one point sprite
    float x, y;
    Rgba color;
    float radius;  // screen pixels before UI scale
    float shape;   // Scene::Shape
};

struct CanvasGeometry {
    Point origin;                     // subtracted from every position
    std::vector<float> positions;     // x, y per polygon vertex
    std::vector<uint32_t> triangles;  // 3 indices per triangle, flood order
    std::vector<uint32_t> edges;      // 6 per triangle: its edges as GL_LINES
    std::vector<uint32_t> fans;       // 3 per fan triangle of each ring (even-odd fill)
    float bbox[4] = {0, 0, 0, 0};     // x0, y0, x1, y1 of the rings
    std::vector<SegmentVertex> boundary;
    std::vector<uint32_t> boundaryEdges;  // 2 per edge: the boundary as thin GL_LINES
    std::vector<SegmentVertex> bridges;   // every Bridge, in event order
    std::vector<MarkerVertex> classes;    // bottoms, sags, tops and ceilings
    std::vector<MarkerVertex> regular;    // the other vertices (most of a big polygon)
    bool dryIsUncut = false;              // the triangles tile the polygon: the untriangulated rest
                                          // is their suffix, no stencil fill needed
};

}  // namespace flood::view
