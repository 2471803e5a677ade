#version 330 core
// hud.frag.glsl - the HUD's colour, alpha-blended over the final image.

in vec4 v_color;
out vec4 o_color;

void main() { o_color = v_color; }
