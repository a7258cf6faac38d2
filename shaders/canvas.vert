#version 330 core
// Canvas geometry arrives in screen pixels (origin top-left, y down), already transformed by
// the model's camera on the CPU so picking and drawing share one transform.
layout(location = 0) in vec2 aPos;
layout(location = 1) in vec4 aColor;
uniform vec2 uViewSize;
out vec4 vColor;
void main() {
    gl_Position = vec4(aPos.x / uViewSize.x * 2.0 - 1.0, 1.0 - aPos.y / uViewSize.y * 2.0, 0.0, 1.0);
    vColor = aColor;
}
