/* lanes.h - WW_LANES marks a function over blocks of lanes (arrays of 8 doubles whose loops GCC
 * vectorises): it is built twice, for AVX2 and for the baseline x86-64, and the loader picks the
 * one the CPU runs (GCC's target_clones, an ifunc). AVX2 without FMA, so every operation rounds as
 * the baseline's does and the answers are the same to the bit; with FMA, GCC's vectoriser fuses a
 * multiply into an add-subtract (vfmaddsub) even under -ffp-contract=off, which moved the lake's
 * state hash. The lake's simulation: 13.4 -> 9.1 us a step on the 2-core machine, same hash.
 */
#ifndef WW_LANES_H
#define WW_LANES_H

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(WW_NO_CLONES)
#define WW_LANES __attribute__((target_clones("avx2", "default")))
#else
#define WW_LANES
#endif
/* a step of a WW_LANES function, inlined into it and so built for each of its targets (a call
 * across the clones' boundary would go through the loader's choice and could not be inlined) */
#if defined(__GNUC__)
#define WW_LANE_STEP static inline __attribute__((always_inline))
#else
#define WW_LANE_STEP static inline
#endif

#endif
