#version 330 core
// reflection_sky.frag.glsl - the sky of the planar reflection pass (pass_reflection.c): the
// gradient (common.glsl), the cubemap or the dome's picture along each pixel's mirrored ray, without the sun disc:
// the water's sun glitter is the disc's reflection, spread by the waves (water.frag.glsl), and
// a second, mirror-sharp disc in the texture would count it twice.

uniform mat4 u_inv_view_proj; // inverse of projection * camera rotation * the mirror's flip of y
uniform int u_cube;           // 1: the sky is u_sky_cube
uniform samplerCube u_sky_cube;
uniform float u_sky_intensity;

in vec2 v_ndc;
out vec4 o_color;

void main() {
    vec4 p = u_inv_view_proj * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(p.xyz / p.w);
#if WW_SKY_DOME_IMAGE
    vec3 c = u_sky_intensity * ww_sky_dome_image(d); // the dome's picture (common.glsl)
#else
    vec3 c = u_cube != 0 ? u_sky_intensity * texture(u_sky_cube, d).rgb : ww_sky(d);
#endif
    o_color = vec4(c, 1.0);
}
