#version 330 core
in vec4 vColor;
flat in vec3 vShape;
out vec4 fragColor;
void main() {
    vec2 q = (gl_PointCoord * 2.0 - 1.0) * vShape.z;  // logical pixels from the centre, y down
    float r = vShape.y;
    if (vShape.x > 1.5) {
        // Finger: a triangle with its tip at the top centre (the vertex), 1.2 r wide at 1.6 r.
        if (abs(q.x) > 0.375 * (q.y + vShape.z)) discard;
    } else if (vShape.x > 0.5) {
        if (abs(length(q) - r) > vShape.z - r) discard;  // ring
    } else if (length(q) > r) {
        discard;  // disc
    }
    fragColor = vColor;
}
