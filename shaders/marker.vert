// Vertex markers as point sprites: one vertex each, the shape cut in marker.frag.
layout(location = 0) in vec2 aPos;
layout(location = 1) in vec4 aColor;
layout(location = 2) in float aRadius;  // pixels before UI scale
layout(location = 3) in float aShape;   // Scene::Shape: 0 disc, 1 ring, 2 finger
uniform float uUiScale;
uniform float uPixelRatio;  // framebuffer pixels per logical pixel (hi-DPI)
out vec4 vColor;
flat out vec3 vShape;  // shape, radius, half-size of the sprite (logical pixels)
void main() {
    float r = aRadius * uUiScale, ring = uUiScale;  // rings are 2 px (UI-scaled) wide
    float h = aShape > 1.5 ? 0.8 * r : (aShape > 0.5 ? r + ring : r);
    vec2 s = worldToScreen(aPos);
    if (aShape > 1.5) s.y += 0.8 * r;  // the finger hangs below the vertex, tip on it
    gl_Position = screenToClip(s);
    gl_PointSize = 2.0 * h * uPixelRatio;
    vColor = aColor;
    vShape = vec3(aShape, r, h);
}
