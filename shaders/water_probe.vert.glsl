#version 330 core
// water_probe.vert.glsl - the GPU probe of the wave field (gfx/water_probe.c): one point per rest
// point, displaced by ww_displace (the water vertex shader's function) and with the normal of
// ww_partials (the water fragment shader's), both built with the fade off (WW_FADE 0). Each
// point lands on its own pixel of the probe's targets: point i at (i % width, i / width).

layout(location = 0) in vec2 a_rest; // rest point relative to the camera (x, z), m

uniform float u_level;  // water level - camera y, m
uniform ivec2 u_size;   // target size, px

flat out vec3 v_pos;    // displaced surface point relative to the camera, m
flat out vec3 v_normal; // unit, up

void main() {
    v_pos = vec3(a_rest.x, u_level, a_rest.y) + ww_displace(a_rest, 0.0);
    vec3 dpdx, dpdz;
    float removed;
    ww_partials(a_rest, ww_footprint_round(0.0), dpdx, dpdz, removed);
    v_normal = normalize(cross(dpdz, dpdx));
    ivec2 px = ivec2(gl_VertexID % u_size.x, gl_VertexID / u_size.x);
    gl_Position = vec4((vec2(px) + 0.5) / vec2(u_size) * 2.0 - 1.0, 0.0, 1.0);
}
