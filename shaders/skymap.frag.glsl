#version 330 core
// skymap.frag.glsl - the sky map (gfx/pass_skymap.c; common.glsl's WW_SKY_MAP): each texel the
// exact clear sky (ww_sky_exact_clear) and the cloud cover along the direction its centre stands
// for, the inverse of common.glsl's ww_sky_map_uv: azimuth 2 pi (u - 1/2), elevation
// sign(t) t^2 pi / 2 with t = 2 v - 1.

in vec2 v_ndc;
out vec4 o_color;

void main() {
    vec2 uv = 0.5 * v_ndc + 0.5;
    float az = (uv.x - 0.5) * (2.0 * WW_PI), t = 2.0 * uv.y - 1.0;
    float e = (t < 0.0 ? -t * t : t * t) * (0.5 * WW_PI);
    vec3 d = vec3(cos(e) * cos(az), sin(e), cos(e) * sin(az));
    o_color = vec4(ww_sky_exact_clear(d), ww_sky_cloud(d));
}
