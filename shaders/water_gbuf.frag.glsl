#version 330 core
// water_gbuf.frag.glsl - the water mesh's G-buffer (gfx/water.c): what water.frag.glsl's
// resolve build reads instead of its interpolated inputs, so that the water is shaded once a
// pixel rather than once for every thin far triangle crossing a block of pixels. The tag marks
// the values as this frame's (the resolve tells them from another frame's by it).

in vec2 v_local; // rest offset, m
in vec3 v_pos;   // displaced surface point relative to the camera, m

uniform float u_water_tag; // this frame's, 1 .. 2^24 - 1

layout(location = 0) out vec4 o_pos;  // water_pos: v_pos, window depth
layout(location = 1) out vec4 o_rest; // water_rest: v_local, tag

void main() {
    o_pos = vec4(v_pos, gl_FragCoord.z);
    o_rest = vec4(v_local, u_water_tag, 0.0);
}
