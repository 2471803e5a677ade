/* rng.c - PCG32 (XSH-RR output, 64-bit LCG state); see rng.h for the citation. */
#include "core/rng.h"

void ww_rng_seed(ww_rng *r, uint64_t seed, uint64_t stream) {
    r->state = 0u;
    r->inc = (stream << 1u) | 1u;
    ww_rng_u32(r);
    r->state += seed;
    ww_rng_u32(r);
}

uint32_t ww_rng_u32(ww_rng *r) {
    uint64_t old = r->state;
    r->state = old * 6364136223846793005ULL + r->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
}

double ww_rng_uniform(ww_rng *r) {
    uint64_t hi = ww_rng_u32(r) >> 5, lo = ww_rng_u32(r) >> 6; /* 27 + 26 bits */
    return ((double)hi * 67108864.0 + (double)lo) * (1.0 / 9007199254740992.0);
}

/* SplitMix64's output function: a bijective 64-bit mixer */
static uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

#define GOLDEN 0x9e3779b97f4a7c15ULL /* 2^64 / phi, SplitMix64's increment */

uint64_t ww_rng_prefix(uint64_t seed, uint64_t stream, uint64_t a) {
    uint64_t h = mix64(seed + GOLDEN);
    h = mix64(h ^ (stream + 2 * GOLDEN));
    return mix64(h ^ (a + 3 * GOLDEN));
}

double ww_rng_draw_at(uint64_t prefix, uint64_t b) {
    uint64_t h = mix64(prefix ^ (b + 4 * GOLDEN));
    return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

double ww_rng_draw(uint64_t seed, uint64_t stream, uint64_t a, uint64_t b) {
    return ww_rng_draw_at(ww_rng_prefix(seed, stream, a), b);
}
