#version 330 core
// hud.vert.glsl - the HUD's triangles in pixels (origin top left, y down) to clip space through
// a pixel-space orthographic projection; each vertex carries its colour with alpha.

layout(location = 0) in vec2 a_pos;   // px
layout(location = 1) in vec4 a_color; // linear 0..1 display colour, alpha

uniform vec2 u_size; // target size, px

out vec4 v_color;

void main() {
    v_color = a_color;
    gl_Position = vec4(2.0 * a_pos.x / u_size.x - 1.0, 1.0 - 2.0 * a_pos.y / u_size.y, 0.0, 1.0);
}
