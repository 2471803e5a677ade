#version 330 core
// shadow_volume.frag.glsl - the volume's faces: nothing while they count into the stencil (colour
// writes off), a translucent tint when render.shadows is volumes_visible.

uniform vec4 u_tint; // premultiplied colour, cover

out vec4 o_color;

void main() { o_color = u_tint; }
