// Thick lines, one instance per segment: the quad's six corners come from gl_VertexID, so
// a segment costs one instance record and its width stays in pixels at any zoom.
layout(location = 0) in vec4 aEnds;   // a.x, a.y, b.x, b.y
layout(location = 1) in vec4 aColor;
layout(location = 2) in float aWidth;  // pixels before UI scale
uniform float uUiScale;
out vec4 vColor;
const vec2 kCorner[6] = vec2[6](vec2(0, -1), vec2(1, -1), vec2(1, 1),
                                vec2(0, -1), vec2(1, 1), vec2(0, 1));
void main() {
    vec2 c = kCorner[gl_VertexID];
    vec2 a = worldToScreen(aEnds.xy), b = worldToScreen(aEnds.zw);
    vec2 d = b - a;
    float len = length(d);
    vec2 n = len > 1e-6 ? vec2(-d.y, d.x) / len : vec2(0.0);  // zero length: draws nothing
    gl_Position = screenToClip(mix(a, b, c.x) + n * (c.y * aWidth * uUiScale * 0.5));
    vColor = aColor;
}
