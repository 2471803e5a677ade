/* select.h - a select of doubles by a mask on their bits, for the branch-free functions whose
 * loops GCC at -O2 vectorises (core/atan.h, the fish's steering):
 *
 *   double r = ww_pick(ww_mask(x < lo), lo, x);     x < lo ? lo : x
 *
 * GCC keeps these selects (a blend in a vectorised loop), where chained floating-point tests
 * and ternaries become branches again (jump threading, and under -ftrapping-math no if-conversion
 * of a comparison or a multiplication behind a branch). The value picked is bit for bit the one
 * selected, so a select of two results of the same operations gives the same bits as a branch.
 */
#ifndef WW_SELECT_H
#define WW_SELECT_H

#include <stdint.h>

#include "core/sincos.h" /* ww_sc_bits, ww_sc_double */

/* all ones where c holds, else all zeros */
static inline uint64_t ww_mask(int c) { return (uint64_t)0 - (uint64_t)(c != 0); }
/* yes where mask is all ones, no where it is all zeros */
static inline double ww_pick(uint64_t mask, double yes, double no) {
    return ww_sc_double((ww_sc_bits(yes) & mask) | (ww_sc_bits(no) & ~mask));
}

#endif
