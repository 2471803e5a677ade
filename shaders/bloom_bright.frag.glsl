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

void main() {
    // the output texel's footprint in source texels and its four quarter points
    vec2 centre = gl_FragCoord.xy * u_ratio;
    vec2 q = 0.25 * u_ratio;
    vec3 s = bright(ivec2(floor(centre + vec2(-q.x, -q.y))))
           + bright(ivec2(floor(centre + vec2( q.x, -q.y))))
           + bright(ivec2(floor(centre + vec2(-q.x,  q.y))))
           + bright(ivec2(floor(centre + vec2( q.x,  q.y))));
    o_color = vec4(0.25 * s, 1.0);
}
