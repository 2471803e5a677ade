#version 330 core
// shafts.frag.glsl - light shafts as a post-process (Mitchell, "Volumetric Light Scattering as a
// Post-Process", GPU Gems 3 ch. 13; seed 000): every pixel marches `samples` steps toward the
// light's screen position, summing an occlusion mask with a decaying weight:
//   delta = (uv - light) * density / samples;  L = exposure * sum_i decay^i * weight * mask(uv_i)
// Above water the mask is the sky (depth 1 in the main pass's depth) glowing with the sun's
// colour by its angle to the sun; geometry and water block it. Under water the light is the sun
// refracted through the surface (Snell's window): the mask is the surface seen from below (rays
// going up), as bright as the main pass drew it, weighted by the angle to the refracted sun and
// by a caustic pattern where the view ray meets the rest plane of the surface, so the light
// comes down in separate shafts (where the waves focus it) that drift with time; a uniformly
// bright surface would only blur into a haze.
// The mask is drawn first into its own texture (MASK defined), then marched over: one
// bilinear fetch per sample instead of a depth fetch, a view ray and exponentials; then the
// march's jitter is smoothed (SMOOTH defined).
// Seed 000 marches the whole way to the light; here the march is at most MARCH_MAX of the
// screen, so a light far off screen (the refracted sun seen while looking level under water)
// still gives parallel shafts coming down instead of a few samples spread over the screen.
// The mask is known on screen only. A march that leaves the screen (toward a light beyond it)
// counts the samples beyond as the mean of its samples on it: the sum is scaled by its whole
// weight over its weight on screen, at most OFF_SCREEN_MAX times. Counting nothing there faded
// the shafts toward the edge on the light's side (under water, looking level, the top rows had
// a tenth of the light of the rows below), so they seemed to start in mid-water.

uniform sampler2D u_mask;   // the occlusion mask at this pass's size (bilinear), MASK undefined
uniform sampler2D u_depth;  // main pass depth (nearest)
uniform sampler2D u_hdr;    // main pass colour (nearest)
uniform vec2 u_light_uv;    // the light's position on screen, texture coordinates
uniform vec3 u_light_dir;   // unit vector toward the light, world
uniform vec3 u_light_color; // its radiance, linear RGB
uniform vec3 u_ray00, u_ray_dx, u_ray_dy; // view ray at uv (0,0) and per unit of uv, world
uniform int u_samples;
uniform float u_decay, u_density, u_weight, u_exposure; // exposure includes the fades
uniform int u_underwater;
uniform vec2 u_inv_size;    // 1 / the target's size
uniform float u_surface_up; // under water: height of the surface over the camera, m
uniform vec2 u_cam_xz;      // camera x, z wrapped to the pattern's period, m
uniform vec3 u_phase;       // the pattern's three phases at this time, rad

out vec4 o_color;

const float MARCH_MAX = 0.75;       // longest march, in screen widths
const float OFF_SCREEN_MAX = 8.0;   // most a march's sum is scaled for its samples off screen:
                                    // near the edge the few samples left on screen are the raw
                                    // mask, and more than this draws its blobs along the edge
const float SUN_CORE = 400.0;       // glow exp((cos - 1) k): k = 2 / sigma^2, sigma 4 deg
const float SUN_HALO = 40.0;        //   and a halo of sigma 13 deg
const float HALO_SHARE = 0.15;
const float WINDOW_GLOW = 6.0;      // under water: the refracted sun smeared by the waves, 33 deg
const float SURFACE_MAX = 8.0;      // bright surface pixels clamped so the sun glint cannot burn
const vec3 LUMA = vec3(0.2126, 0.7152, 0.0722);
// caustic pattern: three crossed sine trains, wavenumbers 2 pi n / 64 m so it tiles every
// 64 m (pass_shafts.c wraps the camera to that period); sharpened by a power
const vec3 CAUSTIC_K = vec3(21.0, 27.0, 17.0) * (6.28318530718 / 64.0);
const float CAUSTIC_SHARP = 4.0;

float caustic(vec2 p) {
    float v = sin(CAUSTIC_K.x * p.x + u_phase.x + sin(CAUSTIC_K.z * p.y))
            + sin(CAUSTIC_K.y * p.y + u_phase.y + sin(CAUSTIC_K.x * p.x))
            + sin(CAUSTIC_K.z * (p.x + p.y) + u_phase.z);
    float c = 0.5 + v / 6.0;
    c *= c;
    return CAUSTIC_SHARP * c * c; // c^4, mean ~ 1 / CAUSTIC_SHARP before the factor
}

vec3 mask(vec2 uv) {
    vec3 d = normalize(u_ray00 + uv.x * u_ray_dx + uv.y * u_ray_dy);
    float c = dot(d, u_light_dir);
    if (u_underwater == 0) {
        if (texture(u_depth, uv).r < 1.0) return vec3(0.0); // geometry and water block
        return u_light_color * (exp((c - 1.0) * SUN_CORE) + HALO_SHARE * exp((c - 1.0) * SUN_HALO));
    }
    if (d.y <= 0.0) return vec3(0.0);
    vec3 s = texture(u_hdr, uv).rgb;
    float l = dot(s, LUMA);
    s *= min(l, SURFACE_MAX) / max(l, 1e-4);
    vec2 hit = u_cam_xz + d.xz * (u_surface_up / d.y);
    return s * exp((c - 1.0) * WINDOW_GLOW) * caustic(hit);
}

#ifdef MASK
// first step: the mask once per texel of the target
void main() { o_color = vec4(mask(gl_FragCoord.xy * u_inv_size), 1.0); }
#elif defined(SMOOTH)
// last step: the march's jitter (below) leaves grain whose pattern repeats every few texels, and
// the tone mapping's bilinear upsampling draws each texel as a soft diamond, so the grain shows
// as a lattice where the shafts are bright and change fast (under water at the frame's edge,
// where half a step decides whether a sample is on screen). The jitter is made to average out
// over a texel's neighbours (interleaved gradient noise), so a 3 x 3 tent, [1 2 1] / 4 each way,
// takes it away and leaves the shafts, many texels wide, as they were: four bilinear fetches
// half a texel off each way (u_mask holds the march here)
void main() {
    vec2 uv = gl_FragCoord.xy * u_inv_size, h = 0.5 * u_inv_size;
    vec3 s = texture(u_mask, uv + vec2(-h.x, -h.y)).rgb + texture(u_mask, uv + vec2(h.x, -h.y)).rgb
           + texture(u_mask, uv + vec2(-h.x, h.y)).rgb + texture(u_mask, uv + vec2(h.x, h.y)).rgb;
    o_color = vec4(0.25 * s, 1.0);
}
#else
// second step: the march over the mask, one bilinear fetch per sample

// interleaved gradient noise (Jimenez, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare", SIGGRAPH 2014): a per-pixel value in [0, 1) whose neighbours differ, so
// the jitter it drives looks like fine grain, not structure
float ign(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

void main() {
    vec2 uv = gl_FragCoord.xy * u_inv_size;
    vec2 delta = uv - u_light_uv;
    float len = length(delta) * u_density;
    delta *= (len > MARCH_MAX ? MARCH_MAX / len : 1.0) * u_density / float(u_samples);
    // the march starts a jittered fraction of a step out: with every pixel of a row sampling
    // the mask at the same fractions of the step, the samples of neighbouring rows fall on the
    // mask's features in step and out of step in turn, and the sum shows as horizontal bands
    // where the march runs along the columns (light above the screen). The jitter trades the
    // bands for grain a quarter as strong, which the bilinear upsampling then softens; the
    // weights follow the jittered distance so the mean is unchanged.
    float j = ign(gl_FragCoord.xy);
    uv -= delta * j;
    // the first sample is taken on screen: the jitter can put it past the edge, and the rows
    // along the edge would then have none there at all
    float w = u_weight * pow(u_decay, j), w_on = w;
    vec3 sum = w * texture(u_mask, clamp(uv, vec2(0.0), vec2(1.0))).rgb;
    uv -= delta;
    w *= u_decay;
    // the rest run on screen for a count of steps (the screen is convex: once off, a march
    // stays off), then leave it; the weight they would have had beyond is summed in closed form
    vec2 room = mix(vec2(1.0) - uv, uv, step(0.0, delta)) / abs(delta);
    vec2 fits = mix(floor(room) + 1.0, vec2(1e9), equal(delta, vec2(0.0)));
    fits = mix(fits, vec2(0.0), lessThan(room, vec2(0.0)));
    int n = u_samples - 1, m = int(min(float(n), min(fits.x, fits.y)));
    for (int i = 0; i < m; i++) {
        sum += w * texture(u_mask, uv).rgb;
        w_on += w;
        uv -= delta;
        w *= u_decay;
    }
    // the r steps past the edge: their weights sum to w (1 - decay^r) / (1 - decay)
    float r = float(n - m);
    float tail = r > 0.0 ? (u_decay < 1.0 ? (1.0 - pow(u_decay, r)) / (1.0 - u_decay) : r) : 0.0;
    float w_all = w_on + w * tail;
    o_color = vec4(u_exposure * sum * min(w_all / max(w_on, 1e-6), OFF_SCREEN_MAX), 1.0);
}
#endif
