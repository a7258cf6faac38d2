#version 330 core
uniform vec4 uColor;  // one colour per draw: water, the current step, fill, edges
out vec4 fragColor;
void main() {
    fragColor = uColor;
}
