#version 330 core
// water_probe.frag.glsl - writes the probe's point and normal, unrounded, into two RGBA32F
// targets (gfx/water_probe.c reads them back).

flat in vec3 v_pos;
flat in vec3 v_normal;
layout(location = 0) out vec4 o_pos;
layout(location = 1) out vec4 o_normal;

void main() {
    o_pos = vec4(v_pos, 0.0);
    o_normal = vec4(v_normal, 0.0);
}
