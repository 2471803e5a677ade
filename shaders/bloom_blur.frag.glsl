#version 330 core
// bloom_blur.frag.glsl - one direction of the separable Gaussian: render.bloom.passes rounds of
// a 9-tap binomial kernel merged into one, read with 2 WW_BLOOM_FETCHES - 1 bilinear fetches,
// each pair of neighbouring taps merged into one fetch between them at the offset weighted by
// their weights (Rakos, "Efficient Gaussian blur with linear sampling", 2010). Weights and
// offsets come from pass_bloom.c (ww_bloom_kernel).

uniform sampler2D u_src;  // linear filtering on
uniform vec2 u_dir;       // one texel along the blur direction, in texture coordinates
uniform float u_weight[WW_BLOOM_FETCHES]; // WW_BLOOM_FETCHES: built in by pass_bloom.c
uniform float u_offset[WW_BLOOM_FETCHES];

out vec4 o_color;

void main() {
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_src, 0));
    vec3 s = u_weight[0] * texture(u_src, uv).rgb;
    for (int i = 1; i < WW_BLOOM_FETCHES; i++) {
        vec2 d = u_offset[i] * u_dir;
        s += u_weight[i] * (texture(u_src, uv + d).rgb + texture(u_src, uv - d).rgb);
    }
    o_color = vec4(s, 1.0);
}
