// The model's camera (model.h) for geometry in world coordinates minus the geometry's
// origin: screen = viewport centre + (p - centre) * scale, y down, in logical pixels.
// Prepended to the world-space vertex shaders after the #version line.
uniform vec2 uCenter;     // camera centre, minus the origin
uniform float uScale;     // pixels per world unit
uniform vec4 uViewport;   // x, y, w, h of the canvas
uniform vec2 uViewSize;   // the window, logical pixels
vec2 worldToScreen(vec2 p) {
    return vec2(uViewport.x + uViewport.z * 0.5 + (p.x - uCenter.x) * uScale,
                uViewport.y + uViewport.w * 0.5 - (p.y - uCenter.y) * uScale);
}
vec4 screenToClip(vec2 s) {
    return vec4(s.x / uViewSize.x * 2.0 - 1.0, 1.0 - s.y / uViewSize.y * 2.0, 0.0, 1.0);
}
