#version 330 core
// bloom_bright.frag.glsl - bloom's first step: the bright pass and the downsample to the bloom
// target in one. Each output texel averages four texels of the HDR image at the corners of its
// footprint (a 4-tap box: at half resolution exactly the 2x2 block it covers, so a one-pixel
// highlight cannot flicker in and out between texels), each tap through the bright pass first.
// Bright pass: a soft knee around the threshold on the exposure-scaled luminance, so what blooms
// follows the tone mapping (the quadratic knee of Jimenez, "Next Generation Post Processing in
// Call of Duty: Advanced Warfare", SIGGRAPH 2014). Seed 000 thresholds the HDR buffer hard.

uniform sampler2D u_hdr;    // main pass's linear HDR colour (nearest)
uniform vec2 u_ratio;       // source texels per output texel, x and y
uniform float u_exposure;   // the tone mapping's exposure E
uniform float u_threshold;  // exposed luminance where blooming starts
uniform float u_knee;       // half-width of the soft knee around it

out vec4 o_color;

const vec3 LUMA = vec3(0.2126, 0.7152, 0.0722); // Rec. 709 luminance of linear RGB
const float HDR_MAX = 65000.0;                  // guard against inf in half floats

vec3 bright(ivec2 p) {
    ivec2 size = textureSize(u_hdr, 0);
    vec3 c = clamp(texelFetch(u_hdr, clamp(p, ivec2(0), size - 1), 0).rgb, 0.0, HDR_MAX);
    float l = u_exposure * dot(c, LUMA);
    // soft = (l - t + k)^2 / 4k inside the knee, l - t above it; the share of c that blooms
    float soft = clamp(l - u_threshold + u_knee, 0.0, 2.0 * u_knee);
    soft = soft * soft / (4.0 * u_knee + 1e-5);
    float w = max(soft, l - u_threshold) / max(l, 1e-5);
    return c * w;
}

// WW_BLOOM_BLOCK (pass_bloom.c): source texels per output texel along each side, rounded. The
// output texel's footprint is split into that many points a side, one in each source texel:
// every texel is thresholded, then they are averaged, so no glint falls between the samples
#ifndef WW_BLOOM_BLOCK
#define WW_BLOOM_BLOCK 2
#endif

void main() {
    vec2 centre = gl_FragCoord.xy * u_ratio;
    vec3 s = vec3(0.0);
    for (int j = 0; j < WW_BLOOM_BLOCK; j++)
        for (int i = 0; i < WW_BLOOM_BLOCK; i++) {
            vec2 at = (vec2(i, j) + 0.5) * (1.0 / float(WW_BLOOM_BLOCK)) - 0.5;
            s += bright(ivec2(floor(centre + at * u_ratio)));
        }
    o_color = vec4(s * (1.0 / float(WW_BLOOM_BLOCK * WW_BLOOM_BLOCK)), 1.0);
}
