// common.glsl - prepended to every program after the #version line (program.c): the sky
// gradient, shared by the sky pass and by the water's reflection so the two meet seamlessly.

uniform vec3 u_sky_zenith;   // sky colour straight up, linear RGB
uniform vec3 u_sky_horizon;  // sky colour at the horizon, linear RGB
uniform vec3 u_sun_dir;      // unit vector toward the sun, world
uniform vec3 u_sun_color;    // sun radiance at the ground, linear RGB

const float WW_PI = 3.14159265358979;

// ---- point and spot lights (lights[]): set by geometry.c for the geometry and the water ------
#define WW_NLIGHTS_MAX 8
// WW_LIGHTS 0: the scene has no lights and the loops over them are not built. llvmpipe runs a
// loop's body once even when its count is 0 (all lanes masked): a quarter of the lake's prepass
#ifndef WW_LIGHTS
#define WW_LIGHTS 1
#endif
uniform int u_nlights;
// WW_NLIGHTS: the scene's count of lights, built in by the programs that light (geometry.c,
// water.c, sky.c) as u_nlights would be: a loop of fixed count unrolls into direct uniform
// reads, where a uniform count made llvmpipe gather every light's uniforms lane by lane (a
// ninth of the reef's wreck view with its one lantern)
#ifndef WW_NLIGHTS
#define WW_NLIGHTS u_nlights
#endif
uniform vec3 u_light_pos[WW_NLIGHTS_MAX];   // camera-relative, m
uniform vec3 u_light_dir[WW_NLIGHTS_MAX];   // spot axis, unit
uniform vec3 u_light_color[WW_NLIGHTS_MAX]; // colour x intensity x flicker of this frame
uniform vec4 u_light_param[WW_NLIGHTS_MAX]; // (range m, cos outer, cos inner, 1 spot / 0 point)
const float WW_SUN_RADIUS = 0.00925; // angular radius of the drawn disc, rad (0.53 deg)
const float WW_SUN_RADIANCE = 20.0;  // disc radiance per unit of sun colour

// soft glow of sunlight scattered in the air around the sun; the sky and the fog both carry it,
// so distant water fades into exactly the sky above the horizon
vec3 ww_sun_glow(vec3 d) {
    float c = max(dot(d, u_sun_dir), 0.0);
    c *= c; c *= c; c *= c; c *= c; c *= c; c *= c; // c^64 by squaring: pow() is exp2(log2()) in software
    return u_sun_color * 0.5 * c;
}

// WW_CLOUDS 0 (gfx/sky.c, per scene): sky.clouds.cover is 0, and the clouds' noise, which every
// sky pixel would work out to find no cloud (llvmpipe runs both arms of the test), is left out
#ifndef WW_CLOUDS
#define WW_CLOUDS 1
#endif

// Preetham's sky (sky.model preetham, and under the dome), set by gfx/sky.c per frame
uniform vec3 u_perez[5];      // Perez coefficients A..E, each for (Y, x, y)
uniform vec3 u_perez_zenith;  // zenith (Y kcd/m^2, x, y) over F(0, theta_sun)
uniform vec3 u_perez_sun;     // the sun the fit is evaluated for (held at least 1 deg high)
uniform vec2 u_sky_mode;      // (1: Preetham's sky, its share against the twilight palette)
uniform vec4 u_sky_clouds;    // (cover 0..1, 0 none; drift x, z in noise units; -)

vec3 ww_sky_physical(vec3 d); // below, after the noise it draws the clouds with
vec3 ww_sky_physical_clear(vec3 d);
vec3 ww_sky_clouds_over(vec3 c, vec3 d, float a);
float ww_acos(float x);
float ww_sky_cloud(vec3 d);

// the sky seen along unit direction d, without the sun disc: a gradient from the horizon to the
// zenith, the horizon colour slightly darkened below the horizon, and the glow; by day (the
// preetham and dome models) Preetham's sky instead of the gradient. Evaluated per pixel; with
// WW_SKY_MAP the pixels take it from the sky map instead (ww_sky below)
vec3 ww_sky_exact(vec3 d) {
    if (u_sky_mode.x > 0.5 && u_sky_mode.y >= 1.0) return ww_sky_physical(d) + ww_sun_glow(d);
    vec3 c;
    if (d.y >= 0.0)
        c = mix(u_sky_horizon, u_sky_zenith, sqrt(d.y));
    else
        c = u_sky_horizon * (1.0 - 0.25 * smoothstep(0.0, 0.3, -d.y));
    if (u_sky_mode.x > 0.5 && u_sky_mode.y > 0.0) c = mix(c, ww_sky_physical(d), u_sky_mode.y);
    return c + ww_sun_glow(d);
}

// the same without the clouds (what the sky map holds)
vec3 ww_sky_exact_clear(vec3 d) {
    if (u_sky_mode.x > 0.5 && u_sky_mode.y >= 1.0) return ww_sky_physical_clear(d) + ww_sun_glow(d);
    vec3 c;
    if (d.y >= 0.0)
        c = mix(u_sky_horizon, u_sky_zenith, sqrt(d.y));
    else
        c = u_sky_horizon * (1.0 - 0.25 * smoothstep(0.0, 0.3, -d.y));
    if (u_sky_mode.x > 0.5 && u_sky_mode.y > 0.0)
        c = mix(c, ww_sky_physical_clear(d), u_sky_mode.y);
    return c + ww_sun_glow(d);
}

// the clouds of cover a over the clear sky m along d, as ww_sky_exact draws them: over Preetham's
// sky (its share u_sky_mode.y), under the glow. Exact by day (share 1); in the twilight fade the
// clouds blend over the gradient's share too (the map keeps one clear colour)
vec3 ww_sky_with_clouds(vec3 m, vec3 d, float a) {
#if !WW_CLOUDS
    return m;
#endif
    if (a <= 0.0 || d.y <= 0.0 || u_sky_mode.x < 0.5) return m;
    vec3 g = ww_sun_glow(d), c = m - g;
    return mix(c, ww_sky_clouds_over(c, d, a), min(u_sky_mode.y, 1.0)) + g;
}

// ---- the sky map (WW_SKY_MAP, gfx/pass_skymap.c) ---------------------------------------------
// Preetham's sky costs an exp per Perez term and its clouds four octaves of hashed noise a
// pixel; the sky pass, the reflection, the water's reflected and refracted rays and the objects'
// sky reflections would each pay them. Instead the skymap pass evaluates the clear sky
// (ww_sky_exact_clear) and the cloud cover (ww_sky_cloud) once a frame (the clouds drift) for
// every direction of a latitude-longitude map (size: scene/plan.h, WW_SKY_MAP_WIDTH), which the
// pixels sample bilinearly. The rows are spaced by the square root of the elevation,
// t = sign(e) sqrt(|e| / (pi / 2)), so the haze band of the last degrees above the horizon
// (exp(-40 elevation)) gets a row every few hundredths of a degree there; the columns wrap
// (GL_REPEAT) where the azimuth does. The clear sky is smooth and loses nothing to the map; the
// clouds' edges are sharp (a smoothstep of the noise) and a texel spans ~0.7 deg, so the sky
// pass, which shows them directly, still evaluates the cover per pixel (ww_sky_sharp) and only
// the reflected and refracted views take it from the map. The sun disc stays analytic.
#ifndef WW_SKY_MAP
#define WW_SKY_MAP 0
#endif
#if WW_SKY_MAP
uniform sampler2D u_sky_map; // RGBA16F: (clear sky radiance, cloud cover)

vec2 ww_sky_map_uv(vec3 d) {
    float e = 0.5 * WW_PI - ww_acos(clamp(d.y, -1.0, 1.0)); // elevation
    float t = sqrt(abs(e) * (2.0 / WW_PI));
    return vec2(atan(d.z, d.x) * (0.5 / WW_PI) + 0.5, 0.5 + 0.5 * (e < 0.0 ? -t : t));
}

vec3 ww_sky(vec3 d) {
    vec4 m = texture(u_sky_map, ww_sky_map_uv(d));
    return ww_sky_with_clouds(m.rgb, d, m.a);
}
// the sky seen directly: the clouds' edges per pixel
vec3 ww_sky_sharp(vec3 d, float cover) {
    return ww_sky_with_clouds(texture(u_sky_map, ww_sky_map_uv(d)).rgb, d, cover);
}
#else
vec3 ww_sky(vec3 d) { return ww_sky_exact(d); }
vec3 ww_sky_sharp(vec3 d, float cover) { return ww_sky_exact(d); }
#endif

// the sun disc with a smooth edge; |d - sun| is the angle between them for small angles
vec3 ww_sun_disc(vec3 d) {
    float a = length(d - u_sun_dir);
    return u_sun_color * WW_SUN_RADIANCE *
           (1.0 - smoothstep(0.8 * WW_SUN_RADIUS, 1.2 * WW_SUN_RADIUS, a));
}

// ---- procedural skydome (sky.model dome) ------------------------------------------------------
// Seed 003 maps a painted texture onto a hemisphere around the camera; here the dome is
// procedural so no file is needed: the time-of-day gradient above, a scattering-like band of
// haze along the horizon (brighter toward the sun, after the forward lobe of Mie scattering) and
// clouds on a plane above the camera, drifting with the simulated time. The noise hashes integer
// lattice points (no sin() hashes), so it is the same on every driver.

const int WW_DOME_PERIOD = 256;          // the cloud noise repeats every this many units
const float WW_DOME_CLOUD_SCALE = 1.6;   // noise units per unit of the cloud plane
const float WW_DOME_CLOUD_HEIGHT = 0.12; // keeps the plane's projection finite at the horizon
const float WW_DOME_BAND = 9.0;          // sharpness of the horizon band (1/elevation)

// a hash of an integer lattice point in [0, 1) (after Jarzynski and Olano, "Hash Functions for
// GPU Rendering", JCGT 2020, pcg2d), periodic with WW_DOME_PERIOD
float ww_hash2(ivec2 p) {
    uvec2 v = uvec2(p & (WW_DOME_PERIOD - 1)) * 1664525u + 1013904223u;
    v.x += v.y * 1664525u; v.y += v.x * 1664525u;
    v ^= v >> 16u;
    v.x += v.y * 1664525u; v.y += v.x * 1664525u;
    v ^= v >> 16u;
    return float(v.x >> 8u) * (1.0 / 16777216.0);
}

// value noise with smoothstep weights, in [0, 1)
float ww_value_noise(vec2 x) {
    vec2 i = floor(x), f = x - i;
    vec2 u = f * f * (3.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float a = ww_hash2(c), b = ww_hash2(c + ivec2(1, 0));
    float d = ww_hash2(c + ivec2(0, 1)), e = ww_hash2(c + ivec2(1, 1));
    return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

// four octaves; the octave scales are whole, so the sum keeps the period
float ww_fbm(vec2 x) {
    float s = 0.0, w = 0.5;
    for (int o = 0; o < 4; o++) {
        s += w * ww_value_noise(x);
        x *= 2.0;
        w *= 0.5;
    }
    return s;
}

// the dome along unit direction d, without the sun disc; drift: the clouds' offset in noise
// units (wrapped to the period by the caller, in double). Returns (colour, cloud cover).
vec4 ww_sky_dome(vec3 d, vec2 drift) {
    vec3 c = ww_sky(d);
    if (d.y <= 0.0) return vec4(c, 0.0);
    // scattering-like horizon band: haze whiter than the horizon colour, lifted toward the sun
    float mu = dot(d.xz, u_sun_dir.xz) / max(length(d.xz) * length(u_sun_dir.xz), 1e-6);
    float phase = 0.25 * (1.0 + mu) * (1.0 + mu);
    float band = exp(-WW_DOME_BAND * d.y);
    vec3 haze = mix(u_sky_horizon, vec3(dot(u_sky_horizon, vec3(0.3333))), 0.5) * 1.2 +
                u_sun_color * 0.12 * phase;
    c = mix(c, haze, 0.6 * band);
    // clouds on a plane above: where the ray meets it, in noise units
    vec2 p = d.xz / (d.y + WW_DOME_CLOUD_HEIGHT) * WW_DOME_CLOUD_SCALE + drift;
    float n = ww_fbm(p);
    float cover = smoothstep(0.47, 0.72, n) * smoothstep(0.0, 0.12, d.y);
    // lit tops toward the sun, darker thick cores; the sky's own light fills the shadows
    vec3 light = u_sun_color * (0.45 + 0.35 * phase) + 0.5 * (u_sky_zenith + u_sky_horizon);
    vec3 cloud = light * (1.0 - 0.4 * smoothstep(0.62, 0.85, n));
    return vec4(mix(c, cloud, cover), cover);
}

// ---- the dome's picture (sky.image) ---------------------------------------------------------
// Seed 003 paints its dome. WW_SKY_DOME_IMAGE 1 (gfx/sky.c, sky.model dome with sky.image) maps
// the picture by the classic dome projection (azimuthal equidistant, as a fisheye photograph of
// the whole sky): the image's centre is the zenith, the circle inscribed in it the horizon, the
// distance from the centre proportional to the zenith angle; the image's top is -z (north, ahead
// of a camera with no yaw), its right +x. Chosen over the upper half of an equirectangular map:
// no seam where the azimuth wraps (which breaks the mip selection along a line) and no pinch at
// the zenith, where an equirectangular map spends a whole row on one point; the texels spread
// evenly over the sky. Below the horizon the horizon's ring, darkened as the gradient is.
#ifndef WW_SKY_DOME_IMAGE
#define WW_SKY_DOME_IMAGE 0
#endif
#if WW_SKY_DOME_IMAGE
uniform sampler2D u_sky_dome_image; // sRGB, decoded to linear by the sampler

vec2 ww_dome_uv(vec3 d) {
    float h = length(d.xz);
    vec2 az = h > 1e-6 ? d.xz / h : vec2(0.0);
    float r = 0.5 * min(ww_acos(clamp(d.y, -1.0, 1.0)) / (0.5 * WW_PI), 1.0);
    return vec2(0.5) + r * az; // image x toward +x, image rows (t, top first) toward +z
}

vec3 ww_sky_dome_image(vec3 d) {
    vec3 c = texture(u_sky_dome_image, ww_dome_uv(d)).rgb;
    return d.y >= 0.0 ? c : c * (1.0 - 0.25 * smoothstep(0.0, 0.3, -d.y));
}
#endif

// ---- point and spot lights on a surface --------------------------------------------------------
// Light i's irradiance factor at p (camera-relative) and the unit vector l toward it: the smooth
// range window of Karis, "Real Shading in Unreal Engine 4" (SIGGRAPH 2013 course),
// (1 - (d/r)^4)^2 / (d^2 + 1), spots fading over the outer `softness` of their cone.
float ww_light_att(int i, vec3 p, out vec3 l) {
    vec3 d = u_light_pos[i] - p;
    float dist = length(d);
    l = d / max(dist, 1e-4);
    vec4 q = u_light_param[i];
    float x = dist / q.x, x2 = x * x;
    float win = clamp(1.0 - x2 * x2, 0.0, 1.0);
    float att = win * win / (dist * dist + 1.0);
    if (q.w > 0.5) att *= smoothstep(q.y, q.z, dot(-l, u_light_dir[i]));
    return att;
}

// the water lit by the lights, toward v (unit, toward the eye) at p with normal n (facing the
// eye): the body's diffuse light (albedo: the water colour) and the surface's normalised
// Blinn-Phong reflection (s + 8) / (8 pi) (n.h)^s with the Fresnel reflectance on h.v, so a
// lantern over the water draws its glitter path as the sun does. From above (below false):
// Schlick's (F0 0.02); the body also glows over a light under the surface (|n.l|: the water
// just beneath scatters what crosses it either way, less what the surface reflects back). From
// below (below true): the water side's, 1 past the critical angle asin(1 / 1.333) (total
// internal reflection), else Schlick's on the air side's angle, so a lantern under the water
// lights a pool on the underside of the surface above it.
vec3 ww_lights_water(vec3 p, vec3 n, vec3 v, vec3 albedo, float shininess, bool below) {
    vec3 c = vec3(0.0);
#if WW_LIGHTS
    float norm = (shininess + 8.0) / (8.0 * WW_PI);
    for (int i = 0; i < WW_NLIGHTS; i++) {
        vec3 l;
        float att = ww_light_att(i, p, l);
        float nl = dot(n, l);
        if (att <= 0.0 || (below && nl <= 0.0)) continue;
        if (nl <= 0.0) {
            // a light under the surface seen from above: what crosses into the body's glow
            if (below || l.y >= 0.0) continue;
            c += u_light_color[i] * att * (-nl) * 0.98 * albedo / WW_PI;
            continue;
        }
        vec3 h = normalize(l + v);
        float ch = clamp(dot(h, v), 0.0, 1.0), fr;
        if (below) {
            float s2 = 1.777689 * (1.0 - ch * ch); // sin^2 of the refracted angle, 1.333^2
            float m = s2 >= 1.0 ? 0.0 : 1.0 - sqrt(1.0 - s2), m2 = m * m;
            fr = s2 >= 1.0 ? 1.0 : 0.02 + 0.98 * m2 * m2 * m;
        } else {
            float m = 1.0 - ch, m2 = m * m;
            fr = 0.02 + 0.98 * m2 * m2 * m;
        }
        float spec = norm * pow(max(dot(n, h), 0.0), shininess) * fr;
        c += u_light_color[i] * att * nl * (albedo / WW_PI + spec);
    }
#endif
    return c;
}

// ---- the lights' glow in the water: single in-scattering along a view ray -----------------
// WW_LIGHT_SCATTER 1 (gfx/geometry.c, per scene: some light has lights[].scatter > 0) builds it
// in; without it the call folds to zero. Light i scattered once toward the eye by the water
// along the ray o + t d, t in [t0, t1] (under water), is
//   L = scatter_i rho C_i int att_i(x(t)) p(theta) T(t) dt,   T(t) = exp(-(rho (t - t0))^2),
// rho fog.below.density taken as the scattering coefficient, att the lights' own window and
// cone (ww_light_att: surfaces and water see the same light), T the exp2 fog's transmittance
// from where the ray enters the water, p Henyey-Greenstein's phase (water scatters forward).
// The ray is first clipped to the light's range sphere and, for a spot, to its cone
// (analytically: no step is spent outside), then integrated with WW_SCATTER_STEPS samples spaced
// equiangularly about the light (Kulla and Fajardo, "Importance Sampling Techniques for Path
// Tracing in Participating Media", EGSR 2012): t = t_c + H tan(a), so the 1 / (dist^2 + 1) of
// the falloff cancels against dt = H sec^2(a) da and each sample weighs (a1 - a0) / (N H); a
// smooth integrand remains, exact for a bare point light. The samples' start is dithered per
// pixel (interleaved gradient noise, Jimenez 2014: a fixed function of the pixel, deterministic)
// so the few steps leave no bands.
#ifndef WW_LIGHT_SCATTER
#define WW_LIGHT_SCATTER 0
#endif
const int WW_SCATTER_STEPS = 12;
const float WW_SCATTER_G = 0.45; // Henyey-Greenstein asymmetry: forward, as sea water's particles

#if WW_LIGHT_SCATTER
uniform float u_light_scatter[WW_NLIGHTS_MAX]; // lights[].scatter, 0: this light adds no glow
// the geometry's prepass (gfx/geometry.c): what lies under the water seen from above through it,
// so a ray from above glows along its part under the plane; in the other passes such a point is
// hidden by the opaque water or lies in the air inside a hull, and gets none
uniform bool u_scatter_through;

// the interval of t in which o + t d lies inside the forward nappe of light i's cone (cos c about
// axis a from the apex q): (x - q).a >= c |x - q| is q(t) = A t^2 + 2 B t + C >= 0 on the
// nappe's side; one interval at most (a line crosses a convex nappe once)
vec2 ww_cone_clip(vec3 co, vec3 d, vec3 a, float c, vec2 r) {
    float da = dot(d, a), ca = dot(co, a), c2 = c * c;
    float A = da * da - c2, B = da * ca - c2 * dot(d, co), C = ca * ca - c2 * dot(co, co);
    float disc = B * B - A * C;
    if (abs(A) < 1e-6) {
        // the ray runs along the cone's side: one crossing, inside on the axis' side
        if (abs(B) < 1e-9) return C >= 0.0 && ca >= 0.0 ? r : vec2(1.0, 0.0);
        float tx = -0.5 * C / B;
        return da > 0.0 ? vec2(max(r.x, tx), r.y) : vec2(r.x, min(r.y, tx));
    }
    if (disc < 0.0) return A > 0.0 && ca >= 0.0 ? r : vec2(1.0, 0.0);
    float s = sqrt(disc), ta = (-B - s) / A, tb = (-B + s) / A;
    vec2 i;
    if (A < 0.0) i = vec2(min(ta, tb), max(ta, tb));    // inside between the crossings
    else i = da > 0.0 ? vec2(max(ta, tb), 1e30) : vec2(-1e30, min(ta, tb)); // toward the nappe
    // the forward nappe only: (co + t d).a >= 0
    if (abs(da) > 1e-9) {
        float th = -ca / da;
        if (da > 0.0) i.x = max(i.x, th); else i.y = min(i.y, th);
    } else if (ca < 0.0) {
        return vec2(1.0, 0.0);
    }
    return vec2(max(i.x, r.x), min(i.y, r.y));
}

vec3 ww_lights_scatter(vec3 o, vec3 d, float t0, float t1, float rho, vec2 px) {
    vec3 sum = vec3(0.0);
    float xi = fract(52.9829189 * fract(dot(px, vec2(0.06711056, 0.00583715))));
    float g = WW_SCATTER_G, g2 = g * g;
    for (int i = 0; i < WW_NLIGHTS; i++) {
        float k = u_light_scatter[i];
        vec4 q = u_light_param[i];
        vec3 co = o - u_light_pos[i];
        // the range sphere |co + t d| <= range
        float b = dot(co, d), c = dot(co, co) - q.x * q.x, disc = b * b - c;
        float s = sqrt(max(disc, 0.0));
        vec2 r = vec2(max(t0, -b - s), min(t1, -b + s));
        if (q.w > 0.5) r = ww_cone_clip(co, d, u_light_dir[i], q.y, r);
        // the samples are a loop of per-pixel length, 0 where the ray misses the light's
        // volume: llvmpipe runs a branch's code for every pixel of a block, but a loop only
        // while one of them still goes round, so blocks that miss skip the march
        bool hit = k > 0.0 && disc > 0.0 && r.y > r.x;
        int steps = hit ? WW_SCATTER_STEPS : 0;
        // equiangular samples about the ray's closest approach t_c (the +1 of the falloff
        // widens H)
        float tc = -b, H = sqrt(max(dot(co, co) - b * b, 0.0) + 1.0);
        float a0 = atan((r.x - tc) / H), a1 = atan((r.y - tc) / H);
        float da = (a1 - a0) / float(WW_SCATTER_STEPS), f = 0.0;
        for (int j = 0; j < steps; j++) {
            float t = tc + H * tan(a0 + (float(j) + xi) * da);
            vec3 x = co + t * d; // from the light
            float dist = length(x), xr = dist / q.x, xr2 = xr * xr;
            float win = clamp(1.0 - xr2 * xr2, 0.0, 1.0);
            vec3 l = x / max(dist, 1e-4);
            float w = win * win;
            if (q.w > 0.5) w *= smoothstep(q.y, q.z, dot(l, u_light_dir[i]));
            // the phase: the light travels along l, the eye looks back along -d
            float m = 1.0 + g2 + 2.0 * g * dot(l, d);
            float ph = (1.0 - g2) / (4.0 * WW_PI * m * sqrt(m));
            float e = rho * (t - t0);
            f += w * ph * exp(-e * e);
        }
        if (hit) sum += u_light_color[i] * (k * rho * f * da / H);
    }
    return sum;
}
#endif

// the glow the lights add to the view ray from e to p (camera-relative), on its part under the
// water plane water_y; air_only: the ray stands for a path through the air (the reflection);
// px: the pixel (gl_FragCoord.xy), which dithers the samples
vec3 ww_lights_scatter_segment(vec3 e, vec3 p, float water_y, bool air_only, float rho, vec2 px) {
#if WW_LIGHT_SCATTER
    if (air_only || WW_NLIGHTS == 0) return vec3(0.0);
    float he = e.y - water_y, hp = p.y - water_y, len = length(p - e);
    vec3 d = (p - e) / max(len, 1e-6);
    // the part of [0, len] under the plane, empty when there is none; one call, not one per
    // case: llvmpipe would run every call's code for every pixel
    bool split = (he < 0.0) != (hp < 0.0);
    float cross = split ? len * he / (he - hp) : 0.0; // where the segment meets the plane
    vec2 t = vec2(0.0);
    if (he < 0.0) t = vec2(0.0, hp < 0.0 ? len : cross);
    else if (hp < 0.0 && u_scatter_through) t = vec2(cross, len);
    return ww_lights_scatter(e, d, t.x, t.y, rho, px);
#else
    return vec3(0.0);
#endif
}

// ---- Preetham's daylight sky and drifting clouds ---------------------------------------------
// Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight" (SIGGRAPH 1999): the
// luminance Y and chromaticity x, y of the sky along d follow the Perez distribution
// F(theta, gamma) = (1 + A e^(B / cos theta))(1 + C e^(D gamma) + E cos^2 gamma), theta the view's
// zenith angle, gamma its angle to the sun, scaled to the zenith values (coefficients from the
// turbidity on the CPU); then xyY -> XYZ -> linear sRGB (D65).

const float WW_PREETHAM_SCALE = 0.022; // HDR radiance per kcd/m^2 of sky luminance
const float WW_HAZE_BAND = 40.0;       // the last ~1.5 deg above the horizon fade into the haze
                                       // colour the fog takes, so far water meets the sky

vec3 ww_perez(float ct, float g, float cg) {
    return (1.0 + u_perez[0] * exp(u_perez[1] / ct)) *
           (1.0 + u_perez[2] * exp(u_perez[3] * g) + u_perez[4] * cg * cg);
}

// cloud cover along d in [0, 1]: fbm on a plane above the camera drifting with the simulated
// time (the dome's clouds), thresholded by sky.clouds.cover
float ww_sky_cloud(vec3 d) {
#if !WW_CLOUDS
    return 0.0;
#endif
    if (u_sky_clouds.x <= 0.0 || d.y <= 0.0) return 0.0;
    vec2 p = d.xz / (d.y + WW_DOME_CLOUD_HEIGHT) * WW_DOME_CLOUD_SCALE + u_sky_clouds.yz;
    float lo = 0.72 - 0.34 * u_sky_clouds.x;
    return smoothstep(lo, lo + 0.16, ww_fbm(p)) * smoothstep(0.0, 0.12, d.y);
}

// acos to 7e-5 rad (Abramowitz and Stegun 4.4.45): a square root and a cubic instead of the
// library call, which costs several times as much in software rasterisers
float ww_acos(float x) {
    float a = abs(x);
    float r = sqrt(1.0 - a) * (1.5707288 + a * (-0.2121144 + a * (0.0742610 - 0.0187293 * a)));
    return x < 0.0 ? WW_PI - r : r;
}

// the clouds of cover a (ww_sky_cloud) over the sky colour c along d (above the horizon): lit by
// the sun (brighter toward it, the forward lobe) and by the sky; thick cores darker
vec3 ww_sky_clouds_over(vec3 c, vec3 d, float a) {
    if (a <= 0.0) return c;
    float mu = dot(d, u_sun_dir);
    vec3 light = u_sun_color * (0.35 + 0.25 * (1.0 + mu)) + 0.6 * (u_sky_zenith + u_sky_horizon);
    return mix(c, light * (1.0 - 0.3 * a * a), a);
}

// Preetham's sky along d without its clouds
vec3 ww_sky_physical_clear(vec3 d) {
    vec3 e = normalize(vec3(d.x, max(d.y, 0.0), d.z)); // below the horizon: the horizon's
    float cg = clamp(dot(e, u_perez_sun), -1.0, 1.0);
    vec3 yxy = u_perez_zenith * ww_perez(max(e.y, 0.02), ww_acos(cg), cg);
    float Y = yxy.x * WW_PREETHAM_SCALE;
    vec3 xyz = vec3(yxy.y / yxy.z * Y, Y, (1.0 - yxy.y - yxy.z) / yxy.z * Y);
    vec3 c = max(mat3(3.2406, -0.9689, 0.0557, -1.5372, 1.8758, -0.2040, -0.4986, 0.0415, 1.0570) *
                     xyz, vec3(0.0));
    c = mix(c, u_sky_horizon, exp(-WW_HAZE_BAND * max(d.y, 0.0)));
    return d.y < 0.0 ? c * (1.0 - 0.25 * smoothstep(0.0, 0.3, -d.y)) : c;
}

vec3 ww_sky_physical(vec3 d) {
    vec3 c = ww_sky_physical_clear(d);
    return d.y < 0.0 ? c : ww_sky_clouds_over(c, d, ww_sky_cloud(d));
}
