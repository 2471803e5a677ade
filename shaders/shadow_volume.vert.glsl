#version 330 core
// shadow_volume.vert.glsl - stencil shadow volumes (gfx/stencil_shadows.c): corners come
// camera-relative from the CPU, the extruded ones at infinity (w = 0) away from the sun.

layout(location = 0) in vec4 a_pos;

uniform mat4 u_view_proj; // camera-relative world -> clip
uniform vec4 u_clip;      // keep a.x + b.y + c.z + d w >= 0 (the prepass's water plane), when enabled

void main() {
    gl_ClipDistance[0] = dot(a_pos, u_clip);
    gl_Position = u_view_proj * a_pos;
}
