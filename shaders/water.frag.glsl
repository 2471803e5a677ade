#version 330 core
// water.frag.glsl - water shading. Per-pixel analytic normal of the wave field and ripples
// (gerstner.glsl: ww_partials, components filtered by the pixel footprint), then:
//   reflection  the planar reflection pass's texture by projective texture mapping from the
//               fragment's window position (seed 002; the mirror camera of pass_reflection.c
//               images the water plane where the main camera does, so no flip), else the sky
//               function, or the sky cubemap (seed 004)
//   refraction  the prepass's colour by the same mapping, depth-aware (seed 000): the water's
//               thickness along the view ray from both depths linearised, taken along the
//               refracted ray, drives Beer-Lambert transmittance per channel
//               exp(-(absorption + murk) d) toward the lit water colour (red is absorbed
//               fastest, so what lies deeper is darker and bluer, never brighter) and shrinks
//               the distortion at the shore; without a prepass the lit deep-water colour
//   Fresnel     bias + scale (1 - v.n)^power (seed 000) or Schlick F0 + (1 - F0)(1 - v.n)^5
//   DuDv        seed 002's distortion map generated here instead of read from a file: two
//               layers of value noise drifting apart, seeded by world position only; the noise
//               gradient is the DuDv vector and, as a normal-map perturbation, specular detail
//   foam        where the Gerstner surface folds: the Jacobian of the horizontal map
//               J = (1 + dDx/dx)(1 + dDz/dz) - dDx/dz dDz/dx falls toward 0 (Tessendorf,
//               "Simulating Ocean Water", 2001), a soft coverage from J with a wide ramp (no
//               hard threshold), broken by two octaves of noise into patches whose edges stay
//               soft. Foam outlives the fold that made it: the coverage a point had at a few
//               past instants, each faded by exp(-age / life), is combined with today's as
//               independent chances, 1 - prod(1 - c_j e^(-age_j / life)), so foam gathers
//               where folding lasts and trails behind a passing crest, fading as it ages. The
//               waves are a function of time, so the past is evaluated, not stored: a frame
//               still depends on the state alone (--frames A:B stays exact)
//   detail      with the DuDv, fine normal-only ripples (short fixed sines, as capillary
//               waves) near the camera, each faded by the pixel footprint so nothing shimmers
//               far away
//   reflection  about a normal bent toward the viewer where the interpolated normal faces away
//   direction   (wave backs seen edge-on), then clamped above the horizon: a reflected ray from
//               above the water never sees the sky below it (seed 004's cubemap is dark there)
//   under water the surface from below: Snell's window (transmitted sky within the critical
//               angle asin(1 / 1.333) = 48.6 deg), total internal reflection of the water below
//               outside it, then the below-water exp2 fog
//   alpha blend seed 004's mode: alpha from Fresnel and the opacity at normal incidence
// Improvements on the seeds: seed 002's DuDv texture and seed 000's normal/DuDv maps are
// procedural and fade with the pixel footprint (no shimmer far away); seed 002 uses one constant
// distortion everywhere, which pulls objects above the water into the refraction at the shore:
// here a distorted lookup that lands in front of the water falls back to the undistorted one.

uniform vec3 u_water_color; // deep-water scattering colour, linear RGB
uniform vec3 u_ambient;     // sky ambient, linear RGB
uniform vec3 u_fog_color;   // linear RGB (the CPU substitutes the horizon colour when asked)
uniform float u_fog_density; // 1/m
uniform float u_pixel_angle; // angle one pixel spans, rad

uniform vec4 u_fresnel;     // (0 bias + scale, 1 Schlick; bias or F0; scale; power)
uniform float u_specular;   // sun highlight strength
uniform vec2 u_distort;     // (strength, screen fraction; pattern cells per metre)
uniform vec4 u_dudv_m[2];   // per layer, the mat2 (column-major) from rest offset (m) to cells
uniform vec2 u_dudv_o[2];   // per layer: the centre's cells plus the drift, wrapped (CPU, double)
// WW_DUDV_TEXTURE 1 (water.look.detail: texture): the noise's gradient per cell over its whole
// period, made once by water.c (tiled, mipmapped), read instead of evaluating ww_noise
#ifndef WW_DUDV_TEXTURE
#define WW_DUDV_TEXTURE 0
#endif
#if WW_DUDV_TEXTURE
uniform sampler2D u_dudv_grad;
#endif
uniform vec4 u_cam_axes;    // camera right and forward, horizontal parts (x, z, x, z), unit
uniform vec2 u_inv_size;    // 1 / the main target's size, 1/px
uniform vec2 u_clip_range;  // near, far clip, m
// The switches below are #defines, set per build of the program (gfx/water.c: water_prog):
// llvmpipe computes both arms of a branch for every pixel, so a switch tested per pixel costs
// the code it turns off. Per frame: WW_UNDERWATER (the camera is below the surface),
// WW_REFLECT_TEX (u_reflection holds this frame's mirrored scene), WW_REFRACT_TEX (u_scene_color
// and u_scene_depth hold the prepass), WW_DISTORT (the DuDv distorts them). Per scene:
// WW_SKY_CUBE (the sky is u_sky_cube times u_sky_intensity), WW_ALPHA_BLEND (seed 004's blend),
// WW_FOAM (foam on), WW_FRESNEL_SCHLICK (Schlick's Fresnel, else bias + scale (1 - c)^power),
// WW_REFRACT_EDGES (the prepass is smaller than the frame and u_scene_depth_full holds its
// depth at the frame's size), WW_REFLECT_DEPTH (the reflection pass mirrors objects, and
// u_reflection_depth and u_reflection_near hold their image's depth and nearest depths).
// Per pass: WW_WATER_RESOLVE (drawn over the screen from the G-buffer, not with the mesh).
#ifndef WW_UNDERWATER
#define WW_UNDERWATER 0
#endif
#ifndef WW_WATER_RESOLVE
#define WW_WATER_RESOLVE 0
#endif
#ifndef WW_REFLECT_TEX
#define WW_REFLECT_TEX 0
#endif
#ifndef WW_REFRACT_TEX
#define WW_REFRACT_TEX 0
#endif
#ifndef WW_REFLECT_DEPTH
#define WW_REFLECT_DEPTH 0
#endif
#ifndef WW_DISTORT
#define WW_DISTORT 0
#endif
#ifndef WW_SKY_CUBE
#define WW_SKY_CUBE 0
#endif
#ifndef WW_ALPHA_BLEND
#define WW_ALPHA_BLEND 0
#endif
#ifndef WW_FOAM
#define WW_FOAM 0
#endif
#ifndef WW_FRESNEL_SCHLICK
#define WW_FRESNEL_SCHLICK 0
#endif
#ifndef WW_REFRACT_EDGES
#define WW_REFRACT_EDGES 0
#endif
uniform sampler2D u_reflection;
#if WW_REFLECT_DEPTH
// the mirror image's least window depth (as this camera sees it) over each 2^(k+1)-texel square
// of u_reflection, level k (pass_reflection.c), of u_near_levels levels
uniform sampler2D u_reflection_near;
uniform int u_near_levels;
uniform sampler2D u_reflection_depth; // the mirror image's window depth, read nearest
uniform vec2 u_mirror; // the mirror plane's height relative to the camera (m), the camera's
                       // forward direction's y
#endif
uniform sampler2D u_scene_color;
uniform sampler2D u_scene_depth;
#if WW_REFRACT_EDGES
uniform sampler2D u_scene_depth_full; // the prepass's depth at the frame's size
#endif
uniform samplerCube u_sky_cube;
uniform float u_sky_intensity;
uniform float u_murk;       // extinction, 1/m
uniform float u_foam;       // amount (WW_FOAM)
uniform vec3 u_fog_below_color;
uniform float u_fog_below_density; // 1/m
uniform float u_alpha;      // opacity at normal incidence (WW_ALPHA_BLEND)
const int NDETAIL = 6; // water.c: WATER_NDETAIL
// normal-only detail (water.c): short sines of a light breeze that only the shading sees (the
// physics never feels them): (k Dx, k Dz 1/m, slope amplitude A k, phase at the mesh centre rad)
uniform vec4 u_detail[NDETAIL];
// their fixed part (water.c from waveblock.c's table): (direction x, z; wavelength m; slope
// amplitude A k), constants the detail's loop folds in
const vec4 DETAIL_WAVE[NDETAIL] = WW_DETAIL_WAVES;
// foam's memory (water.c): the components that fold or steepen the surface most, re-evaluated
// at FOAM_TAPS past instants. WW_FOAM_MEMORY 1 (water.c, per scene) builds it in: only where
// the waves can fold enough for aged foam to show, since its code slows the whole shader on
// software rasterisers even where it is not run
#ifndef WW_FOAM_MEMORY
#define WW_FOAM_MEMORY 0
#endif
const int FOAM_WAVES = 4;  // water.c: WATER_FOAM_WAVES
const int FOAM_TAPS = 4;
uniform vec4 u_foam_wave[FOAM_WAVES];  // (k Dx, k Dz 1/m, fold strength Q A k, slope A k)
uniform vec4 u_foam_phase[FOAM_WAVES]; // (phase at the centre now rad, omega rad/s, exponent e, 0)
uniform vec2 u_foam_step[FOAM_WAVES];  // (cos, sin) of omega times the taps' spacing
// (components in use, 0: no memory; life s; spacing of the taps s; longest of their wavelengths m)
uniform vec4 u_foam_memory;
// WW_FOAM_N: u_foam_memory.x built in (water.c, per scene), so the loop over the components
// unrolls into direct reads of their uniforms rather than gathers lane by lane (llvmpipe)
#ifndef WW_FOAM_N
#define WW_FOAM_N int(u_foam_memory.x)
#endif

#if WW_WATER_RESOLVE
// shaded over the screen from the G-buffer the mesh wrote (gfx/water.c), where the stencil marks
// the water's pixels: its inputs are read, not interpolated
uniform sampler2D u_water_pos;  // surface point relative to the camera (m), window depth
uniform sampler2D u_water_rest; // rest offset (m), the tag of the frame that wrote it
uniform float u_water_tag;      // this frame's tag
vec2 v_local;
vec3 v_pos;
float frag_z;
#else
in vec2 v_local;
in vec3 v_pos;
#define frag_z gl_FragCoord.z
#endif
out vec4 o_color;

const float SPEC_POWER = 600.0;   // Blinn-Phong exponent of a calm surface
const float ETA_WATER = 1.333;    // refractive index of water over air's
const int NOISE_MASK = 255;       // the noise lattice repeats every 256 cells (water.c wraps)
const float LAYER_WEIGHT0 = 0.6;  // the two DuDv layers' shares
const float LAYER_WEIGHT1 = 0.4;
const float DETAIL_SLOPE = 0.06;  // normal-map slope per unit DuDv (seed 002's specular detail)
const float WAVE_DISTORT = 1.0;   // lookup offset per unit of the wave normal's horizontal part
const float SHORE_DEPTH = 1.0;    // m of water along the ray over which distortion grows in
const float NO_FOLD = 0.1;        // the DuDv offset's most, in DuDv cells on screen along the view
const float EDGE = 0.002;         // keep projective lookups off the texture border
const float REFLECT_BEHIND = 0.1; // m: a mirror image this much farther in front of the water
                                  // point than it may lie is not seen from it at all (the fade)
const float OUTLINE_LO = 0.01;    // the prepass's bilinear depth misses the full-size depth by
const float OUTLINE_HI = 0.03;    // ... this share of it and more: an outline runs there
const float SAME_SIDE = 0.25;     // a texel within this share of its neighbours' depth spread
                                  // from the full-size depth lies on the same side of the outline
const float FOLD_J_FULL = 0.2;    // Jacobian at which the fold foam is whole ...
const float FOLD_J_NONE = 0.9;    // ... and where it starts: a wide ramp, soft edges
const float STEEP_LO = 0.1;       // 1 - n.y where slope foam starts ...
const float STEEP_HI = 0.6;       // ... and is whole (a wide ramp, soft edges)
const float FOAM_OCTAVE = 3.0;    // the second noise octave's cells per first's
const float FOAM_GROW = 0.7;      // noise level the coverage lifts the patches by
const float FOAM_SOFT = 0.6;      // width of a patch's edge, in the noise's [0, 1] range
const float FOAM_CELLS = 2.0;     // foam noise cells per DuDv cell; this and FOAM_OCTAVE
                                  // whole, so the offset wrapped at the lattice period
                                  // (water.c) wraps the foam's lattice too
const float LACE_WIDTH = 0.35;    // the aged foam's lines: the noise's range near its ridges
const float LACE_MEAN = 0.2;      // the lace's share of the surface, seen from afar
const float FOAM_AGE_CELLS = 0.5; // cells per DuDv cell of the noise dithering the taps' ages
const float FOAM_ALBEDO = 0.85;
const float FOAM_MIN = 0.01;      // coverage under which no foam is drawn (nor its noise paid)
// pure water's absorption per metre, red first (Pope and Fry, "Absorption spectrum (380-700 nm)
// of pure water", 1997, at about 600, 550 and 450 nm; geometry.c's WATER_EXTINCTION, which dims
// the sunlight reaching what lies under water, uses the same)
const vec3 ABSORB = vec3(0.45, 0.09, 0.07);
const float NORMAL_FOOTPRINT = 2.0; // the shading's footprint in pixels (see main)
const float BENT_MIN = 0.05;      // smallest n.v the reflection's normal may have
const float HORIZON_MIN = 0.01;   // smallest elevation of a reflected ray (its sine) ...
const float HORIZON_COS = 0.99995; // ... and that elevation's cosine

// integer hash of a lattice point (PCG output permutation), in [0, 1]: positions only, no time
float ww_hash(ivec2 c) {
    uvec2 q = uvec2(c & NOISE_MASK);
    uint h = q.x + q.y * 256u;
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return float(h) * (1.0 / 4294967295.0);
}

// value noise in [-1, 1] with its analytic gradient (Quilez, "value noise derivatives"):
// (n, dn/dx, dn/dy) in cells
vec3 ww_noise(vec2 x) {
    vec2 i = floor(x), f = x - i;
    vec2 u = f * f * (3.0 - 2.0 * f), du = 6.0 * f * (1.0 - f);
    ivec2 c = ivec2(i);
    float a = ww_hash(c), b = ww_hash(c + ivec2(1, 0));
    float d = ww_hash(c + ivec2(0, 1)), e = ww_hash(c + ivec2(1, 1));
    float k = a - b - d + e;
    float n = a + (b - a) * u.x + (d - a) * u.y + k * u.x * u.y;
    vec2 g = du * vec2(b - a + k * u.y, d - a + k * u.x);
    return 2.0 * vec3(n - 0.5, g);
}

// foam coverage of a surface with partials dpdx, dpdz: a smooth ramp of the fold (J falls from 1
// as the crest steepens and folds), or, for the families that move no water sideways and never
// fold, of the slope
float ww_foam_cover(vec3 dpdx, vec3 dpdz) {
    float jac = dpdx.x * dpdz.z - dpdx.z * dpdz.x;
    float fold = 1.0 - smoothstep(FOLD_J_FULL, FOLD_J_NONE, jac);
    float ny = normalize(cross(dpdz, dpdx)).y;
    return max(fold, smoothstep(STEEP_LO, STEEP_HI, 1.0 - ny));
}

#if WW_FOAM_MEMORY
// what the recent past left at rest offset p: the coverage u_foam_wave's components gave it at
// the FOAM_TAPS ages (j + xi) dt, each faded by exp(-age / life), combined as independent chances
// 1 - prod(1 - c_j e^(-age_j / life)). The phases at age a are phi + omega a: one sine and cosine
// per component, then a rotation by omega dt per tap (u_foam_step). Each component is faded by
// the pixel's longest footprint (1 / inv_long) in every direction: one resolved only across the
// view (its crests running away from the camera) would sweep its past foam over a whole wedge of
// the far water.
float ww_foam_aged(vec2 p, float xi, float inv_long) {
    vec3 dx[FOAM_TAPS], dz[FOAM_TAPS];
    for (int j = 0; j < FOAM_TAPS; j++) {
        dx[j] = vec3(1.0, 0.0, 0.0);
        dz[j] = vec3(0.0, 0.0, 1.0);
    }
    float dt = u_foam_memory.z;
    for (int i = 0; i < WW_FOAM_N; i++) {
        vec4 w = u_foam_wave[i], ph = u_foam_phase[i];
        float k = length(w.xy);
        vec2 dir = w.xy / k;
        float f = ww_wave_fade(2.0 * WW_PI / k, inv_long);
        float phi = ph.x + dot(w.xy, p) + ph.y * xi * dt;
        float s = sin(phi), c = cos(phi);
        for (int j = 0; j < FOAM_TAPS; j++) {
            float qs = f * w.z * s;
            // steep sines: d/dphi of 2 A (u^e - mean), u = (sin + 1) / 2, is A e u^(e - 1) cos
            float ac = f * w.w * c * (ph.z > 1.0 ? ph.z * pow(0.5 * (s + 1.0), ph.z - 1.0) : 1.0);
            dx[j] += vec3(-qs * dir.x * dir.x, ac * dir.x, -qs * dir.x * dir.y);
            dz[j] += vec3(-qs * dir.x * dir.y, ac * dir.y, -qs * dir.y * dir.y);
            vec2 r = u_foam_step[i];
            float s1 = s * r.x + c * r.y;
            c = c * r.x - s * r.y;
            s = s1;
        }
    }
    float life = u_foam_memory.y, fade = exp(-xi * dt / life), step = exp(-dt / life);
    float clear = 1.0;
    for (int j = 0; j < FOAM_TAPS; j++) {
        clear *= 1.0 - fade * ww_foam_cover(dx[j], dz[j]);
        fade *= step;
    }
    return 1.0 - clear;
}
#endif

float ww_fresnel(float c) {
    float m = 1.0 - clamp(c, 0.0, 1.0);
#if WW_FRESNEL_SCHLICK
    float m2 = m * m;
    return u_fresnel.y + (1.0 - u_fresnel.y) * (m2 * m2 * m);
#else
    return clamp(u_fresnel.y + u_fresnel.z * pow(m, u_fresnel.w), 0.0, 1.0);
#endif
}

// the sky along d: the cubemap when the sky is one, the dome's picture, else the gradient
vec3 ww_sky_any(vec3 d) {
#if WW_SKY_DOME_IMAGE
    return u_sky_intensity * ww_sky_dome_image(d); // the dome's picture (common.glsl)
#endif
#if WW_SKY_CUBE
    return u_sky_intensity * texture(u_sky_cube, d).rgb;
#else
    return ww_sky(d);
#endif
}

// eye-space depth of a window depth (perspective, default depth range), m
float ww_linear_depth(float z) {
    float n = u_clip_range.x, f = u_clip_range.y;
    return 2.0 * n * f / (f + n - (2.0 * z - 1.0) * (f - n));
}

#if WW_REFRACT_EDGES
// The prepass's window depth at uv, at the frame's size (read nearest, a pixel's own), so the
// shore's fade, the check for what lies in front and the water's thickness change where the
// frame's pixels put an outline, not along the smaller prepass's texels
float ww_scene_window_depth(vec2 uv) {
    ivec2 full = textureSize(u_scene_depth_full, 0);
    return texelFetch(u_scene_depth_full, min(ivec2(uv * vec2(full)), full - 1), 0).r;
}

// The prepass's colour at uv (with its coverage: from below, what rises above the water over
// nothing), where the prepass is smaller than the frame; df, zf: the window and eye depth there
// (ww_scene_window_depth). Read bilinear, an outline between a submerged object and what lies
// behind it, or between what floats and the sky seen from below, steps along the prepass's
// texels (2-pixel stairs at half size). A window depth is affine across the screen on any
// plane, so the bilinear mix of the four texels' depths around uv equals the full-size depth
// wherever they lie on one face, and misses it where an outline runs between them. There the
// colour is instead that of the nearest texel on the same side as the full-size depth
// ("nearest-depth upsampling"), so the outline falls where the frame's own pixels put it;
// elsewhere it is the bilinear colour, to the bit.
vec4 ww_refracted_color(vec2 uv, float df, float zf) {
    vec4 c = texture(u_scene_color, uv);
    ivec2 half_ = textureSize(u_scene_depth, 0);
    vec2 t = uv * vec2(half_) - 0.5, fr = fract(t);
    ivec2 lo = clamp(ivec2(floor(t)), ivec2(0), half_ - 1), hi = min(lo + 1, half_ - 1);
    ivec2 p1 = ivec2(hi.x, lo.y), p2 = ivec2(lo.x, hi.y);
    vec4 d = vec4(texelFetch(u_scene_depth, lo, 0).r, texelFetch(u_scene_depth, p1, 0).r,
                  texelFetch(u_scene_depth, p2, 0).r, texelFetch(u_scene_depth, hi, 0).r);
    vec4 w = vec4((1.0 - fr.x) * (1.0 - fr.y), fr.x * (1.0 - fr.y), (1.0 - fr.x) * fr.y, fr.x * fr.y);
    float edge = smoothstep(OUTLINE_LO, OUTLINE_HI, abs(ww_linear_depth(dot(w, d)) - zf) / zf);
    // the texels on the full-size depth's side: within SAME_SIDE of the depths' spread of the
    // nearest in depth; of those, the one nearest to uv
    vec4 dz = abs(d - df);
    float near = min(min(dz.x, dz.y), min(dz.z, dz.w));
    float spread = max(max(d.x, d.y), max(d.z, d.w)) - min(min(d.x, d.y), min(d.z, d.w));
    w = (w + 1e-6) * step(dz, vec4(near + SAME_SIDE * spread));
    float wm = max(max(w.x, w.y), max(w.z, w.w));
    ivec2 pick = w.x == wm ? lo : w.y == wm ? p1 : w.z == wm ? p2 : hi;
    return mix(c, texelFetch(u_scene_color, pick, 0), edge);
}
#else
float ww_scene_window_depth(vec2 uv) { return texture(u_scene_depth, uv).r; }
#endif

#if WW_REFLECT_DEPTH
// The least window depth of the mirror image among the texels of u_reflection that a trilinear
// lookup at uv mixes into its colour: the nearest surface the filtered colour holds. Levels L and
// L + 1 are mixed at a level of detail in [L, L + 1), and the 2 x 2 texels of level L + 1 around
// uv cover both footprints; u_reflection_near's level L is the least depth of each of them.
// g: the lookup's derivatives across the screen (dFdx, dFdy of uv)
float ww_mirror_nearest(vec2 uv, vec4 g) {
    vec2 size = vec2(textureSize(u_reflection, 0));
    vec2 gx = g.xy * size, gy = g.zw * size;
    float lod = 0.5 * log2(max(max(dot(gx, gx), dot(gy, gy)), 1e-20));
    int level = clamp(int(floor(lod)), 0, u_near_levels - 1);
    ivec2 n = textureSize(u_reflection_near, level), top = n - 1;
    ivec2 lo = ivec2(floor(uv * vec2(n) - 0.5));
    ivec2 a = clamp(lo, ivec2(0), top), b = clamp(lo + 1, ivec2(0), top);
    return min(min(texelFetch(u_reflection_near, a, level).r,
                   texelFetch(u_reflection_near, ivec2(b.x, a.y), level).r),
               min(texelFetch(u_reflection_near, ivec2(a.x, b.y), level).r,
                   texelFetch(u_reflection_near, b, level).r));
}
#endif

#if WW_WATER_RESOLVE
// This pixel's inputs from the G-buffer. Pixels are shaded in 2x2 blocks, and derivatives (which
// choose the reflection's and the sky's mip levels) are differences across a block; a pixel of
// the block that is not water this frame runs only for them, and holds another frame's values
// or none. So a value this frame did not write is zeroed, then replaced by its neighbour's
// along the row (0 + the difference: exact), else along the column: a water pixel's derivative
// toward it is 0, no other frame's value reaches the picture, and a frame draws the same
// whatever was drawn before it.
void read_gbuffer() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(u_water_pos, px, 0), b = texelFetch(u_water_rest, px, 0);
    float stale = b.z == u_water_tag ? 0.0 : 1.0;
    a *= 1.0 - stale;
    b *= 1.0 - stale;
    // the neighbour across the row is at +dFdx from the left pixel, -dFdx from the right one
    float sx = (px.x & 1) == 0 ? 1.0 : -1.0, sy = (px.y & 1) == 0 ? 1.0 : -1.0;
    vec4 da = dFdx(a), db = dFdx(b);
    float take = stale * (1.0 - (stale + sx * dFdx(stale))); // stale, its neighbour is not
    a += take * sx * da;
    b += take * sx * db;
    stale -= take;
    da = dFdy(a);
    db = dFdy(b);
    take = stale * (1.0 - (stale + sy * dFdy(stale)));
    a += take * sy * da;
    b += take * sy * db;
    v_pos = a.xyz;
    frag_z = a.w;
    v_local = b.xy;
}
#endif

void main() {
#if WW_WATER_RESOLVE
    read_gbuffer();
#endif
    float dist = length(v_pos);
    vec3 v = -v_pos / max(dist, 1e-6); // toward the camera

    // the pixel's footprint on the water: dist * pixel angle across the view, stretched by
    // 1 / sin(elevation) along it (grazing rays see long footprints)
    float hl = length(v.xz);
    vec2 along = hl > 1e-5 ? -v.xz / hl : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    float stretch = 1.0 / max(abs(v.y), 0.01);
    // the shading's footprint is NORMAL_FOOTPRINT pixels wide: a component is whole from 8
    // pixels per wavelength and gone at 4, so none is shaded near the Nyquist limit, where its
    // alias beats with its neighbours into moire, nor as a regular grating of 4-5 pixel stripes
    // (a few sines seen from 300 m up; the mesh keeps its own fade by its spacing)
    float pix = NORMAL_FOOTPRINT * dist * u_pixel_angle;

    // surface partials dP/dx, dP/dz at the rest point (gerstner.glsl: ww_partials). The geometry
    // fades waves by the mesh spacing; the normals fade each wave by the footprint along its
    // direction instead, so they keep close-up detail the mesh cannot carry and drop what a
    // pixel cannot show. The slope variance of what the fades removed widens the sun highlight
    // instead of vanishing.
    vec3 dpdx, dpdz;
    float removed;
    ww_partials(v_local, ww_footprint_make(along, across, stretch, pix), dpdx, dpdz, removed);
    vec3 n = normalize(cross(dpdz, dpdx));
    vec3 nw = n; // the waves' normal, without the detail

    // DuDv: the gradient of two drifting noise layers, per metre then per cell; each layer
    // fades out where a cell spans fewer than 4 footprints along the view (as the waves)
    vec2 dudv = vec2(0.0);
    float dudv_most = 1e9; // the DuDv's largest share of the lookup offset, DuDv units
#if WW_DISTORT
    {
        float cell = 1.0 / u_distort.y, inv_fp = 1.0 / max(pix * stretch, 1e-6);
        vec2 g = vec2(0.0);
        for (int j = 0; j < 2; j++) {
            mat2 m = mat2(u_dudv_m[j].xy, u_dudv_m[j].zw);
            float fade = ww_wave_fade(1.0 / length(m[0]), inv_fp); // a cell, m
            if (fade == 0.0) continue;
#if WW_DUDV_TEXTURE
            vec2 gn = texture(u_dudv_grad, (m * v_local + u_dudv_o[j]) * (1.0 / float(NOISE_MASK + 1))).xy;
#else
            vec2 gn = ww_noise(m * v_local + u_dudv_o[j]).yz;
#endif
            // the chain rule: d noise(M p + o) / dp = M^T grad noise
            g += (j == 0 ? LAYER_WEIGHT0 : LAYER_WEIGHT1) * fade * (transpose(m) * gn);
        }
        dudv = g * cell;
        // far off a cell spans few pixels: an offset larger than NO_FOLD of it turns faster
        // than the pixels under it and folds the refracted picture into torn slivers
        dudv_most = NO_FOLD * cell * inv_fp * u_inv_size.y / max(u_distort.x, 1e-6);
        // normal-map detail: the DuDv as the slope of a small height field (seed 002)
        n = normalize(n - DETAIL_SLOPE * vec3(dudv.x, 0.0, dudv.y));
    }
#endif
    // fine detail: slopes of short sines, each faded by the footprint along its direction as
    // the waves are; what the fade removes widens the sun highlight (LEAN mapping's variance,
    // Olano and Baker, "LEAN Mapping", 2010) so the far water keeps its sheen, not its shimmer.
    // Part of the normal-map detail, so only with the DuDv (seed 002), and never on flat water
    // (a mirror)
#if WW_WAVE_MODEL != WW_MODEL_FLAT && WW_DISTORT
    {
        ww_footprint fp = ww_footprint_make(along, across, stretch, pix);
        vec2 g = vec2(0.0);
        // a fixed count and no early exit, the wavelengths and directions constants: the loop
        // unrolls and folds them in, which costs less on llvmpipe than working out 2 pi / |k|
        // per pixel and stopping at the first one faded out (whose fade is 0 anyway)
        for (int j = 0; j < NDETAIL; j++) {
            vec4 w = DETAIL_WAVE[j];
            float f = ww_wave_fade_along(w.z, w.xy, fp);
            removed += 0.5 * (1.0 - f * f) * w.w * w.w;
            g += (f * w.w * cos(u_detail[j].w + dot(u_detail[j].xy, v_local))) * w.xy;
        }
        n = normalize(n - vec3(g.x, 0.0, g.y));
    }
#endif
    // the lookups' offset on screen: DuDv plus the waves' tilt, horizontal world directions
    // taken to screen x (camera right) and y (farther is higher)
    vec2 tilt = dudv * min(1.0, dudv_most / max(length(dudv), 1e-6)) + WAVE_DISTORT * nw.xz;
    vec2 off = u_distort.x * vec2(dot(tilt, u_cam_axes.xy), dot(tilt, u_cam_axes.zw));
    vec2 uv0 = gl_FragCoord.xy * u_inv_size;

    vec3 l = u_sun_dir;
    float sun_up = smoothstep(-0.02, 0.02, l.y); // the horizon hides the sun

    // the highlights' roughness: normalised Blinn-Phong whose exponent falls as the removed
    // slopes grow (Beckmann m^2 ~ slope variance; exponent n = 2 / m^2 - 2)
    float m2 = 2.0 / (SPEC_POWER + 2.0) + removed;
    float pw = 2.0 / m2 - 2.0;

#if WW_UNDERWATER
    {
        // from below: the normal facing the camera; Snell's window, else total internal
        // reflection of the water below (its fog colour)
        vec3 nd = -n;
        vec3 t = refract(-v, nd, ETA_WATER);
        vec3 below = u_fog_below_color;
        vec3 c;
        if (dot(t, t) == 0.0) {
            c = below;
        } else {
            // Fresnel on the air side's angle, the larger one: 1 at the window's edge
            float fr = ww_fresnel(max(dot(t, n), 0.0));
            vec3 air = ww_sky_any(t) + ww_sun_disc(t) * sun_up;
#if WW_REFRACT_TEX
            // what rises above the water (the prepass from below: a cube's top, a hull), over
            // the sky by its coverage (the prepass is cleared to nothing there, so its bilinear
            // colour is premultiplied), distorted as the view down through the surface is. It
            // stands where the camera's straight ray meets it, not where the bent one would: a
            // small shift for what floats, whose parts above the water are near the surface.
            // Where the prepass is smaller than the frame, its outline against the sky is put
            // where the frame's pixels lie by the full-size depth, as from above
            vec2 uva = clamp(uv0 + off, EDGE, 1.0 - EDGE);
#if WW_REFRACT_EDGES
            float da = ww_scene_window_depth(uva); // 1 where nothing rises above the water
            vec4 above = ww_refracted_color(uva, da, ww_linear_depth(da));
#else
            vec4 above = texture(u_scene_color, uva);
#endif
            air = above.rgb + (1.0 - above.a) * air;
#endif
            c = mix(air, below, fr);
        }
        // the lights below light the underside: the water under it and its mirror (total
        // internal reflection past the critical angle)
        c += ww_lights_water(v_pos, nd, v, u_water_color, pw, true);
        float k = u_fog_below_density * dist;
        c = mix(u_fog_below_color, c, exp(-k * k));
#if WW_LIGHT_SCATTER
        // the lights' glow in the water between the camera and the surface (common.glsl)
        c += ww_lights_scatter(vec3(0.0), -v, 0.0, dist, u_fog_below_density, gl_FragCoord.xy);
#endif
        o_color = vec4(c, 1.0);
        return;
    }
#else
    float ndv = max(dot(n, v), 0.0);
    float ndl = max(dot(n, l), 0.0);
    float fr = ww_fresnel(ndv);
    // the reflected ray: about the normal bent toward the viewer where it faces away (a wave's
    // back seen edge-on, which the pixel cannot see), then kept above the horizon
    vec3 nb = n;
    float nv = dot(n, v);
    if (nv < BENT_MIN) nb = normalize(n + (BENT_MIN - nv) * v);
    vec3 rdir = reflect(-v, nb);
    if (rdir.y < HORIZON_MIN) {
        vec2 hz = rdir.xz / max(length(rdir.xz), 1e-6);
        rdir = vec3(hz.x * HORIZON_COS, HORIZON_MIN, hz.y * HORIZON_COS);
    }

    // reflection: the mirrored scene, or the sky
#if WW_REFLECT_TEX
    // the pass draws its sky behind the mirrored geometry, so the texture is whole everywhere
    vec2 uvr = clamp(uv0 + off, EDGE, 1.0 - EDGE);
    vec3 refl = texture(u_reflection, uvr).rgb;
#if WW_REFLECT_DEPTH
    // Seen from a water point, a mirror image lies on the view ray carried on past the surface,
    // so only what the image holds beyond the point is reflected there. The texture is the
    // mirror image about the rest plane, read at an offset (DuDv, the waves' tilt), while the
    // water stands up to a wave's height off that plane: around what floats, a lookup could hand
    // a water point an image lying in front of it, the dark mirror image of a cube spread over
    // the water beyond the cube's far side. There the ray passes it by, and sees the sky along
    // the view ray mirrored by the plane, as the texture holds the sky where nothing is drawn.
    // The image about the water point's own height h lies 2 h above the texture's, which puts
    // the texture's up to 2 h |view y| nearer the camera than it should be: that much is
    // allowed. Where the lookup falls on the sky, the nearest surface among the texels the
    // colour was filtered from decides, so no rim of an image's colour is left along its
    // outline, at any mip level; where it falls on an image, that image does
    float zc = texture(u_reflection_depth, uvr).r;
    float zm = zc < 1.0 ? zc : ww_mirror_nearest(uvr, vec4(dFdx(uvr), dFdy(uvr)));
    float nearer = max(2.0 * (v_pos.y - u_mirror.x) * u_mirror.y, 0.0);
    float seen = zm < 1.0 ? clamp((ww_linear_depth(zm) - ww_linear_depth(frag_z) + nearer) /
                                  REFLECT_BEHIND + 1.0, 0.0, 1.0)
                          : 1.0; // the sky (the depth's clear value) lies beyond every point
    refl = mix(ww_sky_any(vec3(-v.x, v.y, -v.z)), refl, seen);
#endif
#else
    vec3 refl = ww_sky_any(rdir);
#endif

    // refraction: deep water lit by the sky and a little sun, or what lies below through murk
    vec3 deep = u_water_color * (u_ambient + 0.1 * sun_up * ndl * u_sun_color);
    vec3 refr = deep;
#if WW_REFRACT_TEX && !WW_ALPHA_BLEND
    {
        float zw = ww_linear_depth(frag_z), ray = dist / zw; // eye depth -> ray length
        float ds = ww_scene_window_depth(uv0), zs = ww_linear_depth(ds);
        float shore = 1.0 - exp(-max(zs - zw, 0.0) * ray / SHORE_DEPTH);
        vec2 uv = clamp(uv0 + off * shore, EDGE, 1.0 - EDGE);
        float dd = ww_scene_window_depth(uv), zd = ww_linear_depth(dd);
        if (zd < zw) {
            uv = uv0; // the distorted lookup found something in front of the water
        } else {
            zs = zd;
            ds = dd;
        }
#if WW_REFRACT_EDGES
        vec3 seen = ww_refracted_color(uv, ds, zs).rgb;
#else
        vec3 seen = texture(u_scene_color, uv).rgb;
#endif
        // the path through the water to what is seen: its depth below the surface over the
        // refracted ray's cosine (Snell), not the straight view ray, which grazes far longer
        float thick = max(zs - zw, 0.0) * ray;
        vec3 t = refract(-v, n, 1.0 / ETA_WATER);
        float path = thick * abs(v.y) / max(-t.y, 0.2);
        // Beer-Lambert per channel: absorbed red first, plus the murk's grey extinction
        vec3 tr = exp(-(ABSORB + u_murk) * path);
        refr = mix(deep, seen, tr);
    }
#endif
    vec3 c = mix(refr, refl, fr);

    // sun glitter: normalised Blinn-Phong whose roughness grows with the removed slopes
    // (Beckmann m^2 ~ slope variance; exponent n = 2 / m^2 - 2). No n.l factor: a mirror
    // reflects a low sun as brightly as a high one, which is what makes the path at sunset
    vec3 h = normalize(l + v);
    float spec = (pw + 8.0) / (8.0 * WW_PI) * pow(max(dot(n, h), 0.0), pw);
    vec3 sun = u_sun_color * (u_specular * spec * ww_fresnel(dot(h, v)) * sun_up);
    c += ww_lights_water(v_pos, n, v, u_water_color, pw, false); // lights[] (common.glsl)

    // foam: folding (J -> 0), steep, steeper-looking edge-on; broken up by noise
    float foam = 0.0;
    vec3 foam_lit = vec3(0.0);
#if WW_FOAM
    {
        // coverage now (fresh foam), then what the recent past left (aged foam): each tap's age
        // is dithered by a smooth noise (a fraction of the taps' spacing), so the crest's past
        // positions blend into a trail rather than stand as copies
        float fresh = ww_foam_cover(dpdx, dpdz), aged = 0.0;
#if WW_FOAM_MEMORY
        {
            float inv_long = 1.0 / max(pix * stretch, 1e-6);
            // far off, where every component foam remembers is faded out, there is none
            if (!ww_faded_out(u_foam_memory.w, inv_long)) {
                float xi = 0.5 + 0.5 * ww_noise(FOAM_AGE_CELLS * u_distort.y * v_local + u_dudv_o[1]).x;
                aged = ww_foam_aged(v_local, xi, inv_long);
            }
        }
#endif
        // texture-free noise breaks fresh foam into patches that grow with the coverage; the
        // patches' edges ramp over FOAM_SOFT of the noise's range (a smooth noise: several
        // pixels). Aged foam has broken up into a lace: the noise's ridges (its zero crossings),
        // thinner and fainter (its coverage squared) as it fades, so what little an old or a
        // slight fold left does not stand out as bright scribbles. Both fade with the footprint
        // toward their means, so no shimmer far away.
        if (max(fresh, aged) > FOAM_MIN) {
            float inv_fp = 1.0 / max(pix * stretch, 1e-6), cells = FOAM_CELLS * u_distort.y;
            vec2 q = cells * v_local + u_dudv_o[0] * FOAM_CELLS;
            float f1 = ww_wave_fade(1.0 / cells, inv_fp);
            float n1 = f1 * ww_noise(q).x;
            float n2 = ww_wave_fade(1.0 / (FOAM_OCTAVE * cells), inv_fp) *
                       ww_noise(FOAM_OCTAVE * q + vec2(37.0, 91.0)).x;
            float nz = 0.5 + 0.5 * (0.65 * n1 + 0.35 * n2);
            float patch = nz + FOAM_GROW * (fresh - 0.5);
            float f_fresh = sqrt(fresh) * smoothstep(0.5 - 0.5 * FOAM_SOFT, 0.5 + 0.5 * FOAM_SOFT, patch);
            float ridge = 1.0 - abs(0.65 * n1 + 0.35 * n2);
            float lace = aged * aged * smoothstep(1.0 - LACE_WIDTH * aged, 1.0, ridge);
            lace = mix(LACE_MEAN * aged * aged * aged, lace, f1);
            foam = u_foam * max(f_fresh, lace);
        }
        foam_lit = FOAM_ALBEDO * (u_ambient + u_sun_color * max(dot(nw, l), 0.0) * sun_up);
        c = mix(c, foam_lit, foam);
        sun *= 1.0 - foam;
    }
#endif

    float fog = exp(-(u_fog_density * dist) * (u_fog_density * dist));
    vec3 fogc = u_fog_color + ww_sun_glow(-v);
#if WW_ALPHA_BLEND
    {
        // seed 004's blend over what was drawn below: out = a C + (1 - a) below with
        // (1 - a) = (1 - F)(1 - alpha) the light let through, a C = F refl + (1 - F) alpha deep
        // foam is opaque
        float a = 1.0 - (1.0 - fr) * (1.0 - u_alpha);
        vec3 ca = (fr * refl + (1.0 - fr) * u_alpha * deep + sun) / a;
        ca = mix(ca, foam_lit, foam);
        a = mix(a, 1.0, foam);
        o_color = vec4(mix(fogc, ca, fog), mix(1.0, a, fog));
    }
#else
    // exp2 fog toward the fog colour lit by the sun glow along the view
    o_color = vec4(mix(fogc, c + sun, fog), 1.0);
#endif
#endif // WW_UNDERWATER
}
