#version 330 core
// floor.frag.glsl - the fill floor of `waterworld bench`: one constant colour per pixel, the
// cheapest full-screen pass a backend can run.

out vec4 o_color;

void main() { o_color = vec4(0.25, 0.5, 0.75, 1.0); }
