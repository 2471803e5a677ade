// shadow.glsl - the sun's shadow map (gfx/pass_shadow.c) read with percentage-closer filtering
// (Reeves, Salesin & Cook, "Rendering Antialiased Shadows with Depth Maps", SIGGRAPH 1987) over
// a fixed 12-tap Poisson disc, each tap a hardware 2x2 compare (sampler2DShadow, linear).
// Included by the geometry shader; the water may include it too: set u_shadow_on = 0 when the
// frame has no shadow pass (r->shared.shadow_map == 0), otherwise bind the map to a texture unit
// and set the rest from r->shared.sun_view_proj and the map's size.

uniform sampler2DShadow u_shadow_map;
uniform int u_shadow_on;          // 0: everything lit; 2: in a stencilled shadow, nothing lit
uniform mat4 u_sun_view_proj;     // camera-relative world -> the map's clip space
uniform vec3 u_shadow_filter;     // (texel size in map uv, kernel radius in texels, texel in m)
uniform vec4 u_shadow_water;      // (u, level): u toward the sun under water (refracted, unit;
                                  // u.y 0: no water, no warp), level the rest level's
                                  // camera-relative height

const vec2 WW_POISSON[12] = vec2[](
    vec2(-0.326, -0.406), vec2(-0.840, -0.074), vec2(-0.696, 0.457), vec2(-0.203, 0.621),
    vec2(0.962, -0.195), vec2(0.473, -0.480), vec2(0.519, 0.767), vec2(0.185, -0.893),
    vec2(0.507, 0.064), vec2(0.896, 0.412), vec2(-0.322, -0.933), vec2(-0.792, -0.598));

// Sunlight under water comes down the refracted ray, steeper than the sun's ray in air. A point p
// under water is lit through the surface point s = p + u L, L = (level - p.y) / u.y, and s by
// the sun along its air direction a; the map (orthographic along a) sees p at s - a L instead:
// s's texel, L farther from the sun. Casters (the shadow pass) and receivers (the lookup) are
// warped alike, so a point under water is shadowed by what lies on its own bent ray (a fish
// beside it, a hull at the surface, a cube above the water), and everything above the water is
// unchanged. Without it a shadow 10 m down with the sun 57 deg high landed 2 m too far out.
vec3 ww_shadow_warp(vec3 p) {
    if (u_shadow_water.y <= 0.0 || p.y >= u_shadow_water.w) return p;
    float l = (u_shadow_water.w - p.y) / u_shadow_water.y;
    return p + (u_shadow_water.xyz - u_sun_dir) * l;
}

// The projected shadows (stencil_shadows.c) flatten their casters onto the seabed along u. A
// caster point above the water reaches the surface along a first: it moves along the surface's
// level lines to where a projection along u from its own height lands as the bent ray does.
vec3 ww_shadow_unbend(vec3 p) {
    if (u_shadow_water.y <= 0.0 || p.y <= u_shadow_water.w) return p;
    float h = p.y - u_shadow_water.w;
    return p + (u_shadow_water.xyz / u_shadow_water.y - u_sun_dir / max(u_sun_dir.y, 1e-3)) * h;
}

// fraction of sunlight reaching camera-relative point p with unit normal n (1 lit, 0 shadow).
// The point moves 1.5 texels along its normal first (normal-offset shadows, Holbein 2011), so
// lit faces do not shadow themselves; the map's polygon offset handles the rest.
float ww_shadow(vec3 p, vec3 n) {
    vec4 c = u_sun_view_proj * vec4(ww_shadow_warp(p + n * (1.5 * u_shadow_filter.z)), 1.0);
    vec3 s = c.xyz / c.w * 0.5 + 0.5;
    bool inside = all(greaterThanEqual(s, vec3(0.0))) && all(lessThanEqual(s, vec3(1.0)));
    float r = u_shadow_filter.x * u_shadow_filter.y;
    // the taps' count, not a branch, says whether there are any: llvmpipe runs both arms of a
    // branch for every pixel, but leaves a loop once no pixel of its block has a pass left, so
    // a frame with the stencilled shadows or none pays one masked pass instead of twelve taps
    int taps = u_shadow_on == 1 && inside ? (r > 0.0 ? 12 : 1) : 0;
    float lit = 0.0;
    for (int i = 0; i < taps; i++)
        lit += textureLod(u_shadow_map, vec3(s.xy + WW_POISSON[i] * r, s.z), 0.0);
    if (taps == 0) return u_shadow_on == 2 ? 0.0 : 1.0;
    return lit / float(taps);
}
