#version 330 core
// mirror_near.frag.glsl - one level of the reflection's nearest-depth pyramid (pass_reflection.c):
// each texel the least window depth of the 2 x 2 texels under it in u_src (the reflection's
// depth, or the level below), and of the leftover third row or column where that level's size
// is odd. A colour lookup that mixes texels of the reflection's mip level L covers at most the
// 2 x 2 texels of level L + 1 around it, so their least depth is the nearest surface in it.

uniform sampler2D u_src; // window depth, read at its base level

out vec4 o_depth;

float at(ivec2 q, ivec2 last) { return texelFetch(u_src, min(q, last), 0).r; }

void main() {
    ivec2 size = textureSize(u_src, 0), last = size - 1;
    ivec2 a = 2 * ivec2(gl_FragCoord.xy);
    float d = min(min(at(a, last), at(a + ivec2(1, 0), last)),
                  min(at(a + ivec2(0, 1), last), at(a + ivec2(1, 1), last)));
    // the last texel of a row or column also takes the one an odd size leaves over (min of a
    // texel read twice where it is not odd: the same value)
    ivec2 c = ivec2(a.x + 2 == last.x ? a.x + 2 : a.x + 1, a.y + 2 == last.y ? a.y + 2 : a.y + 1);
    d = min(d, min(min(at(ivec2(c.x, a.y), last), at(ivec2(c.x, a.y + 1), last)),
                   min(min(at(ivec2(a.x, c.y), last), at(ivec2(a.x + 1, c.y), last)),
                       at(c, last))));
    o_depth = vec4(d);
}
