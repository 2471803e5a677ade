// common.glsl - prepended to every program after the #version line (program.c): the sky
// gradient, shared by the sky pass and by the water's reflection so the two meet seamlessly.

uniform vec3 u_sky_zenith;   // sky colour straight up, linear RGB
uniform vec3 u_sky_horizon;  // sky colour at the horizon, linear RGB
uniform vec3 u_sun_dir;      // unit vector toward the sun, world
uniform vec3 u_sun_color;    // sun radiance at the ground, linear RGB

const float WW_PI = 3.14159265358979;
const float WW_SUN_RADIUS = 0.00925; // angular radius of the drawn disc, rad (0.53 deg)
const float WW_SUN_RADIANCE = 20.0;  // disc radiance per unit of sun colour

// soft glow of sunlight scattered in the air around the sun; the sky and the fog both carry it,
// so distant water fades into exactly the sky above the horizon
vec3 ww_sun_glow(vec3 d) {
    float c = max(dot(d, u_sun_dir), 0.0);
    c *= c; c *= c; c *= c; c *= c; c *= c; c *= c; // c^64 by squaring: pow() is exp2(log2()) in software
    return u_sun_color * 0.5 * c;
}

// the sky seen along unit direction d, without the sun disc: a gradient from the horizon to the
// zenith, the horizon colour slightly darkened below the horizon, and the glow
vec3 ww_sky(vec3 d) {
    vec3 c;
    if (d.y >= 0.0)
        c = mix(u_sky_horizon, u_sky_zenith, sqrt(d.y));
    else
        c = u_sky_horizon * (1.0 - 0.25 * smoothstep(0.0, 0.3, -d.y));
    return c + ww_sun_glow(d);
}

// the sun disc with a smooth edge; |d - sun| is the angle between them for small angles
vec3 ww_sun_disc(vec3 d) {
    float a = length(d - u_sun_dir);
    return u_sun_color * WW_SUN_RADIANCE *
           (1.0 - smoothstep(0.8 * WW_SUN_RADIUS, 1.2 * WW_SUN_RADIUS, a));
}
