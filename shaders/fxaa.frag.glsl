#version 330 core
// fxaa.frag.glsl - FXAA, written from the algorithm of Lottes, "FXAA 3.11" (NVIDIA, 2011), its
// PC quality path: (1) local contrast of the luma cross, early out below the thresholds;
// (2) subpixel amount from the 3x3 low-pass against the centre; (3) edge direction from the
// 3x3 second differences, and which side of the pixel the edge lies on; (4) search along the
// edge both ways for its ends (luma leaving the edge's average by a quarter of the gradient),
// in growing steps; (5) the pixel's offset across the edge from its place in the span, or the
// subpixel amount when larger; one bilinear fetch at the offset position.
// Luma is the gamma-encoded RGB's, which the tone mapping writes into alpha (pass_tonemap.c):
// each of the up to 19 taps fetches it instead of computing it (seed 000 reads the alpha-less
// LDR image and computes it per tap).

uniform sampler2D u_ldr;  // tone-mapped sRGB8 image, bilinear

out vec4 o_color;

const float EDGE_THRESHOLD = 0.166;     // FXAA 3.11 quality default: minimum contrast / max luma
const float EDGE_THRESHOLD_MIN = 0.0833; //  and absolute minimum (skips dark noise)
const float SUBPIX = 0.75;              // amount of subpixel aliasing removal
// the step ladder of FXAA 3.11's quality preset 12 (5 steps reaching 20.5 px each way) rather
// than preset 39's 12 steps: on llvmpipe the waves keep most 8-pixel groups searching, and the
// long ladder cost 44 ms of a 1280x720 demo frame against 24 ms for this one (bench render);
// the ends of long, nearly axis-aligned edges are found less far, so they blend less
const int SEARCH_STEPS = 5;
const float STEP[5] = float[5](1.0, 1.5, 2.0, 4.0, 12.0);

float luma_at(vec2 uv) { return textureLod(u_ldr, uv, 0.0).a; }
float luma_px(ivec2 p) {
    return texelFetch(u_ldr, clamp(p, ivec2(0), textureSize(u_ldr, 0) - 1), 0).a;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec2 rcp = 1.0 / vec2(textureSize(u_ldr, 0));
    vec2 uv = gl_FragCoord.xy * rcp;
    vec4 rgbM = texelFetch(u_ldr, px, 0);

    // (1) local contrast of the cross
    float M = rgbM.a;
    float N = luma_px(px + ivec2(0, 1)), S = luma_px(px + ivec2(0, -1));
    float E = luma_px(px + ivec2(1, 0)), W = luma_px(px + ivec2(-1, 0));
    float hi = max(max(max(N, S), max(E, W)), M);
    float lo = min(min(min(N, S), min(E, W)), M);
    float range = hi - lo;
#ifdef WW_FXAA_MARK
    // the marking draw (pass_fxaa.c) writes depth where there is an edge, and nothing else; a
    // pixel without one keeps the copy of the tone-mapped image already in the target. The
    // shading draw runs only where this one wrote, so it needs no test of its own.
    if (range < max(EDGE_THRESHOLD_MIN, hi * EDGE_THRESHOLD)) discard;
    o_color = vec4(0.0);
    return;
#endif
    float NW = luma_px(px + ivec2(-1, 1)), NE = luma_px(px + ivec2(1, 1));
    float SW = luma_px(px + ivec2(-1, -1)), SE = luma_px(px + ivec2(1, -1));

    // (2) subpixel: the 3x3 tent low-pass against the centre, relative to the contrast
    float lp = (2.0 * (N + S + E + W) + (NW + NE + SW + SE)) / 12.0;
    float sc = clamp(abs(lp - M) / range, 0.0, 1.0);
    float sf = (-2.0 * sc + 3.0) * sc * sc;
    float subpix = sf * sf * SUBPIX;

    // (3) edge direction: horizontal edges have large vertical second differences
    float eh = abs(NW + SW - 2.0 * W) + 2.0 * abs(N + S - 2.0 * M) + abs(NE + SE - 2.0 * E);
    float ev = abs(NW + NE - 2.0 * N) + 2.0 * abs(W + E - 2.0 * M) + abs(SW + SE - 2.0 * S);
    bool horz = eh >= ev;
    float l1 = horz ? S : W; // the two neighbours across the edge
    float l2 = horz ? N : E;
    float g1 = l1 - M, g2 = l2 - M;
    bool side1 = abs(g1) >= abs(g2); // the edge lies toward neighbour 1
    float gradient = max(abs(g1), abs(g2));
    float step_len = horz ? rcp.y : rcp.x;
    float lumaLocal = 0.5 * (M + (side1 ? l1 : l2)); // average luma on the edge
    if (side1) step_len = -step_len;

    // (4) search along the edge from the point halfway to the chosen neighbour
    vec2 pos = uv;
    if (horz) pos.y += 0.5 * step_len; else pos.x += 0.5 * step_len;
    vec2 along = horz ? vec2(rcp.x, 0.0) : vec2(0.0, rcp.y);
    float gscaled = 0.25 * gradient;
    vec2 pn = pos - along, pp = pos + along;
    float en = luma_at(pn) - lumaLocal, ep = luma_at(pp) - lumaLocal;
    bool dn = abs(en) >= gscaled, dp = abs(ep) >= gscaled;
    for (int i = 1; i < SEARCH_STEPS && !(dn && dp); i++) {
        if (!dn) { pn -= along * STEP[i]; en = luma_at(pn) - lumaLocal; dn = abs(en) >= gscaled; }
        if (!dp) { pp += along * STEP[i]; ep = luma_at(pp) - lumaLocal; dp = abs(ep) >= gscaled; }
    }

    // (5) offset across the edge: pixels near the closer end move most; only when the luma
    // at that end turns the way the centre does (the span really ends there)
    float distN = horz ? uv.x - pn.x : uv.y - pn.y;
    float distP = horz ? pp.x - uv.x : pp.y - uv.y;
    bool nearN = distN < distP;
    float dist = min(distN, distP);
    float span = distN + distP;
    bool centreBelow = M - lumaLocal < 0.0;
    bool good = ((nearN ? en : ep) < 0.0) != centreBelow;
    float offset = good ? 0.5 - dist / span : 0.0;
    offset = max(offset, subpix);
    vec2 q = uv;
    if (horz) q.y += offset * step_len; else q.x += offset * step_len;
    o_color = vec4(textureLod(u_ldr, q, 0.0).rgb, 1.0);
}
