// Triangles and edges of the polygon, straight from the static vertex buffer.
layout(location = 0) in vec2 aPos;
void main() {
    gl_Position = screenToClip(worldToScreen(aPos));
}
