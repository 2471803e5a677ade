/* rng.h - PCG32 random streams (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient
 * Statistically Good Algorithms for Random Number Generation"), one stream per system so that
 * adding fish never moves where a stone lands. Seeded from the scene seed and a system id.
 */
#ifndef WW_RNG_H
#define WW_RNG_H

#include <stdint.h>

typedef struct ww_rng {
    uint64_t state; /* generator state */
    uint64_t inc;   /* stream selector, always odd */
} ww_rng;

/* stream ids: fixed forever, so a new system never shifts another's draws */
enum {
    WW_RNG_WAVES = 1, WW_RNG_RIPPLES, WW_RNG_STONES, WW_RNG_FISH, WW_RNG_CHEST, WW_RNG_BUBBLES,
    WW_RNG_SWEEP, /* the points of `sweep --random` */
    WW_RNG_CUBES, WW_RNG_BOAT, WW_RNG_ROD,
    WW_RNG_BENCH, /* the sample boxes of `bench sim`'s columns table */
    WW_RNG_SPLASH /* the drops a splash throws (gfx/splash.h): the picture only */
};

void ww_rng_seed(ww_rng *r, uint64_t seed, uint64_t stream);
uint32_t ww_rng_u32(ww_rng *r);
double ww_rng_uniform(ww_rng *r); /* [0, 1), 53 bits */

/* a counter-based draw for the simulation: uniform in [0, 1) from (seed, stream, a, b) alone,
 * e.g. a = step, b = object * 16 + k. No generator state lives in ww_state, so a --frames slice
 * draws exactly what a full run draws, and one system's draws never move another's. The bits
 * come from SplitMix64's finaliser (Steele, Lea & Flood 2014) over the four words. */
double ww_rng_draw(uint64_t seed, uint64_t stream, uint64_t a, uint64_t b);
/* the draws of one (seed, stream, a), a system's in a step, share the first three of the four
 * mixes: ww_rng_prefix works them out once, and ww_rng_draw_at(prefix, b) is then
 * ww_rng_draw(seed, stream, a, b) to the bit for one mix */
uint64_t ww_rng_prefix(uint64_t seed, uint64_t stream, uint64_t a);
double ww_rng_draw_at(uint64_t prefix, uint64_t b);

#endif
