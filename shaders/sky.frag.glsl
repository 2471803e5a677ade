#version 330 core
// sky.frag.glsl - the gradient sky and the sun disc behind everything, one view ray per pixel.

uniform mat4 u_inv_view_proj; // inverse of projection * camera rotation (camera at the origin)

in vec2 v_ndc;
out vec4 o_color;

void main() {
    // the camera sits at the origin, so a point on the far plane is a point along the ray
    vec4 p = u_inv_view_proj * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(p.xyz / p.w);
    o_color = vec4(ww_sky(d) + ww_sun_disc(d), 1.0);
}
