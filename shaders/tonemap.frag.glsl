#version 330 core
// tonemap.frag.glsl - HDR to display (seed 000's composite): the main pass's colour plus the
// blurred bloom times its strength plus the light shafts, both upsampled bilinearly from their
// smaller targets; then exposure, a tone curve and gamma encoding; alpha is 1, or with FXAA after
// it (u_luma_alpha) the luma FXAA reads, so FXAA fetches it instead of computing it per tap.
// The colour is dithered before the RGBA8 target rounds it (WW_DITHER).

uniform sampler2D u_hdr;    // linear HDR colour, same size as the output
uniform sampler2D u_bloom;  // blurred bright light (bilinear), when WW_BLOOM
uniform sampler2D u_shafts; // light shafts (bilinear), when WW_SHAFTS
// #defines (gfx/pass_tonemap.c): WW_BLOOM, WW_SHAFTS (those passes' images are there to add),
// WW_ACES (the ACES curve, else exponential), WW_LUMA_ALPHA (alpha carries FXAA's luma),
// WW_DITHER (render.tonemap.dither)
#ifndef WW_BLOOM
#define WW_BLOOM 0
#endif
#ifndef WW_SHAFTS
#define WW_SHAFTS 0
#endif
#ifndef WW_ACES
#define WW_ACES 0
#endif
#ifndef WW_LUMA_ALPHA
#define WW_LUMA_ALPHA 0
#endif
#ifndef WW_DITHER
#define WW_DITHER 0
#endif
uniform float u_bloom_strength;
uniform float u_exposure; // E
uniform float u_gamma;    // display gamma

out vec4 o_color;

const float HDR_MAX = 65000.0; // a half float's overflow must not reach the curve as inf
const vec3 LUMA = vec3(0.2126, 0.7152, 0.0722);
const float HUE_KEEP = 0.5;    // aces: share of the luminance-only curve (hue-preserving)

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve"
vec3 aces(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

#if WW_DITHER
// ordered dither (Bayer, 8 x 8) over one level of the 8-bit target, the same offset for all
// three channels. A smooth gradient darker than a few levels a band (the night sky, a dim haze)
// rounds to flat bands a level apart, which the eye picks out as contours and a moving camera
// sweeps across the frame; with each pixel's rounding threshold moved by its place in the
// matrix, a value between two levels rounds up on the share of the pixels its fraction gives,
// so the bands become a fine pattern that averages to the gradient. A value on a level, and so
// a flat region, is left alone. Ordered rather than random: a frame of random grain (two uniform
// draws a pixel) grew the lake's PNG frames 2.2 times, this pattern, whose rows repeat every 8
// pixels, 1.5 times. The index interleaves the bits of x ^ y and x (Bayer 1973)
float dither(ivec2 p) {
    uint x = uint(p.x) & 7u, z = x ^ (uint(p.y) & 7u);
    uint b = ((z & 1u) << 5u) | ((x & 1u) << 4u) | ((z & 2u) << 2u) | ((x & 2u) << 1u) |
             ((z & 4u) >> 1u) | ((x & 4u) >> 2u);
    return (float(b) + 0.5) * (1.0 / 64.0) - 0.5;
}
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 hdr = clamp(texelFetch(u_hdr, px, 0).rgb, 0.0, HDR_MAX);
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_hdr, 0));
#if WW_BLOOM
    hdr += u_bloom_strength * max(texture(u_bloom, uv).rgb, vec3(0.0));
#endif
#if WW_SHAFTS
    hdr += max(texture(u_shafts, uv).rgb, vec3(0.0));
#endif
    vec3 x = u_exposure * hdr;
#if WW_ACES
    // ACES (Narkowicz's fit), half hue-preserving:
    // the curve per channel pushes bright colours toward white (a sunset sky turns grey);
    // the curve on the luminance, scaling the colour, keeps their hue and saturation but
    // lets a saturated highlight leave the gamut. Half of each keeps the colour and still
    // lands in [0, 1] (both do)
    float l = dot(x, LUMA);
    vec3 hue = l > 1e-6 ? x * (aces(vec3(l)).r / l) : vec3(0.0);
    vec3 c = mix(aces(x), clamp(hue, 0.0, 1.0), HUE_KEEP);
#else
    vec3 c = vec3(1.0) - exp(-x); // exp: 1 - e^(-E c), seed 000
#endif
    vec3 g = pow(c, vec3(1.0 / u_gamma));
#if WW_DITHER
    g += dither(px) * (1.0 / 255.0);
#endif
#if WW_LUMA_ALPHA
    // the luma of the colour as the RGBA8 target will hold it (rounded to 8 bits), as FXAA
    // computed it from the stored image before
    vec3 g8 = floor(clamp(g, 0.0, 1.0) * 255.0 + 0.5) * (1.0 / 255.0);
    o_color = vec4(g, dot(g8, vec3(0.299, 0.587, 0.114)));
#else
    o_color = vec4(g, 1.0);
#endif
}
