#version 330 core
// tonemap.frag.glsl - HDR to display: exposure, a tone curve, gamma encoding; alpha is 1.

uniform sampler2D u_hdr;  // linear HDR colour, same size as the output
uniform float u_exposure; // E
uniform float u_gamma;    // display gamma
uniform int u_op;         // 0: exponential, 1: ACES (Narkowicz fit)

out vec4 o_color;

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve"
vec3 aces(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
    vec3 hdr = max(texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb, vec3(0.0));
    vec3 x = u_exposure * hdr;
    vec3 c = u_op == 1 ? aces(x) : vec3(1.0) - exp(-x); // exp: 1 - e^(-E c), seed 000
    o_color = vec4(pow(c, vec3(1.0 / u_gamma)), 1.0);
}
