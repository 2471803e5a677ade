#version 330 core
// sky.frag.glsl - the sky behind everything, one view ray per pixel: Preetham's sky with its
// clouds or the gradient (seed 000; both common.glsl's ww_sky), a
// cubemap skybox (seed 004; WW_SKY_CUBEMAP) or the procedural dome (seed 003; WW_SKY_DOME) or its
// picture (sky.image; WW_SKY_DOME_IMAGE, common.glsl), with the sun disc on top.
//
// Seed 004 draws a unit cube with gl_Position = pos.xyww and samples (x, y, -z); here a
// full-screen triangle on the far plane gives the same depth, and the cubemap is sampled along
// the world direction unflipped, so the face named +z is what the camera sees looking along +z.

uniform mat4 u_inv_view_proj; // inverse of projection * camera rotation (camera at the origin)
uniform float u_intensity;    // sky.intensity: radiance scale of the cubemap and the dome
uniform vec4 u_below;         // (fog colour under water, 1) when the camera is under water: what
                              // lies beyond everything drawn is water, fogged out completely.
                              // WW_SKY_BELOW (gfx/sky.c) builds that side in: one program each
uniform float u_below_density; // fog.below.density, 1/m (the lights' glow, WW_LIGHT_SCATTER)
#ifndef WW_SKY_BELOW
#define WW_SKY_BELOW 0
#endif
#ifdef WW_SKY_CUBEMAP
uniform samplerCube u_cubemap; // sRGB faces, decoded to linear by the sampler
#endif
#ifdef WW_SKY_DOME
uniform vec2 u_drift;          // cloud drift, noise units, wrapped to the noise period
#endif

in vec2 v_ndc;
out vec4 o_color;

void main() {
    // the camera sits at the origin, so a point on the far plane is a point along the ray
    vec4 p = u_inv_view_proj * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(p.xyz / p.w);
#if WW_SKY_BELOW
    vec3 c = u_below.rgb;
#if WW_LIGHT_SCATTER
    // the lights' glow along the ray, which the fog ends (common.glsl)
    c += ww_lights_scatter(vec3(0.0), d, 0.0, 1e4, u_below_density, gl_FragCoord.xy);
#endif
    o_color = vec4(c, 1.0);
#elif defined(WW_SKY_CUBEMAP)
    o_color = vec4(texture(u_cubemap, d).rgb * u_intensity + ww_sun_disc(d), 1.0);
#elif defined(WW_SKY_DOME) && WW_SKY_DOME_IMAGE
    o_color = vec4(ww_sky_dome_image(d) * u_intensity + ww_sun_disc(d), 1.0);
#elif defined(WW_SKY_DOME)
    vec4 dome = ww_sky_dome(d, u_drift);
    o_color = vec4(dome.rgb * u_intensity + ww_sun_disc(d) * (1.0 - dome.a), 1.0);
#else
    float cover = ww_sky_cloud(d);
    o_color = vec4(ww_sky_sharp(d, cover) + ww_sun_disc(d) * (1.0 - cover), 1.0);
#endif
}
