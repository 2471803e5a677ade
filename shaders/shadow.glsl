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

const vec2 WW_POISSON[12] = vec2[](
    vec2(-0.326, -0.406), vec2(-0.840, -0.074), vec2(-0.696, 0.457), vec2(-0.203, 0.621),
    vec2(0.962, -0.195), vec2(0.473, -0.480), vec2(0.519, 0.767), vec2(0.185, -0.893),
    vec2(0.507, 0.064), vec2(0.896, 0.412), vec2(-0.322, -0.933), vec2(-0.792, -0.598));

// fraction of sunlight reaching camera-relative point p with unit normal n (1 lit, 0 shadow).
// The point moves 1.5 texels along its normal first (normal-offset shadows, Holbein 2011), so
// lit faces do not shadow themselves; the map's polygon offset handles the rest.
float ww_shadow(vec3 p, vec3 n) {
    if (u_shadow_on != 1) return u_shadow_on == 0 ? 1.0 : 0.0;
    vec4 c = u_sun_view_proj * vec4(p + n * (1.5 * u_shadow_filter.z), 1.0);
    vec3 s = c.xyz / c.w * 0.5 + 0.5;
    if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
    float r = u_shadow_filter.x * u_shadow_filter.y;
    if (r <= 0.0) return texture(u_shadow_map, s);
    float lit = 0.0;
    for (int i = 0; i < 12; i++) lit += texture(u_shadow_map, vec3(s.xy + WW_POISSON[i] * r, s.z));
    return lit * (1.0 / 12.0);
}
