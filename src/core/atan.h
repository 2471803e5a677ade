/* atan.h - arctangent and the quadrant-correct atan2, deterministic (no libm: the same operations
 * in the same order on every machine and libm version, as sincos.h and exp.h) and branch-free
 * (so that GCC at -O2 vectorises the loops calling them: the fish's steering), for the
 * simulation's per-step headings and angles.
 *
 *   double a = ww_atan(x);          in [-pi/2, pi/2]
 *   double b = ww_atan2(y, x);      in [-pi, pi], the angle of (x, y)
 *
 * Method (Moshier, Cephes Math Library, atan.c, 1984-1998): |x| is reduced to [0, 0.66] by
 * atan x = pi/2 + atan(-1/x) above tan(3 pi/8) and atan x = pi/4 + atan((x - 1) / (x + 1))
 * above 0.66; there atan t = t + t^3 P(t^2) / Q(t^2), Cephes's degree 4/5 rational minimax
 * (peak relative error 2.6e-18 on the interval), and the part of pi/2 or pi/4 that their
 * doubles drop (6.1e-17, 3.1e-17) is added back to the small term before the large one.
 * atan2 takes atan(y / x) and for x < 0 adds pi with the sign of y.
 * Accuracy: within one ulp of libm's atan and atan2 over 300,000 random arguments in every
 * reduction and quadrant (test waves_atan_matches_libm).
 * Special values: NaN in, NaN out; atan(+-0) = +-0, atan(+-inf) = +-pi/2; atan2(+-0, +0) = +-0,
 * atan2(+-0, -0) = +-pi as libm; atan2 of two infinities is NaN (libm: an odd multiple of pi/4).
 */
#ifndef WW_ATAN_H
#define WW_ATAN_H

#include <stdint.h>

#include "core/select.h"
#include "core/sincos.h" /* ww_sc_bits, ww_sc_double */

#define WW_ATAN_PIO2 1.57079632679489661923
#define WW_ATAN_PIO4 7.85398163397448309616e-1
#define WW_ATAN_PI 3.14159265358979323846
/* pi/2 less its double: what the reduction above tan(3 pi/8) adds back */
#define WW_ATAN_MOREBITS 6.123233995736765886130e-17

/* base + atan t, t in [-0.66, 0.66] reduced from |x| (0, pi/4 or pi/2 with the part of it that
 * its double drops, more): Cephes's rational, the small terms summed before the large one */
static inline double ww_atan_reduced(double t, double base, double more) {
    double z = t * t;
    double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z -
                 7.500855792314704667340e1) * z - 1.228866684490136173410e2) * z -
               6.485021904942025371773e1;
    double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z +
                 4.328810604912902668951e2) * z + 4.853903996359136964868e2) * z +
               1.945506571482613964425e2;
    return base + ((t + t * z * (p / q)) + more);
}

/* Branch-free: both reductions are worked out and the one |x| calls for is picked by tests on
 * its bits (for a double >= 0 the order of its bits as integers is the order of its values), so
 * the loops that call it vectorise; the operations on the value picked are those of the
 * reduction alone, so the result is the same to the bit as with branches */
static inline double ww_atan(double x) {
    const int64_t far_bits = 0x4003504f333f9de6; /* tan(3 pi/8) = 2.41421356237309504880 */
    const int64_t mid_bits = 0x3fe51eb851eb851f; /* 0.66 */
    uint64_t ux = ww_sc_bits(x), sign = ux & 0x8000000000000000u;
    int64_t ua = (int64_t)(ux & ~sign); /* a NaN's bits lie above every number's: far */
    double a = ww_sc_double((uint64_t)ua);
    double t_far = -1.0 / a, t_mid = (a - 1.0) / (a + 1.0);
    uint64_t far = ww_mask(ua > far_bits), mid = ww_mask(ua > mid_bits) & ~far;
    double t = ww_pick(far, t_far, ww_pick(mid, t_mid, a));
    double base = ww_pick(far, WW_ATAN_PIO2, ww_pick(mid, WW_ATAN_PIO4, 0.0));
    double more = ww_pick(far, WW_ATAN_MOREBITS, ww_pick(mid, 0.5 * WW_ATAN_MOREBITS, 0.0));
    double r = ww_atan_reduced(t, base, more);
    return ww_sc_double(ww_sc_bits(r) ^ sign); /* -r for x < 0 */
}

/* Branch-free as ww_atan: atan(y / x) is worked out whatever x, and the quadrant's pi (a - pi as
 * a + (-pi), the same operation) or the answer for x = 0 picked by tests on the bits */
static inline double ww_atan2(double y, double x) {
    const uint64_t signbit = 0x8000000000000000u;
    const int64_t inf_bits = 0x7ff0000000000000;
    uint64_t ux = ww_sc_bits(x), uy = ww_sc_bits(y);
    uint64_t ysign = uy & signbit;
    int64_t ax = (int64_t)(ux & ~signbit), ay = (int64_t)(uy & ~signbit);
    double pi_y = ww_sc_double(ww_sc_bits(WW_ATAN_PI) | ysign); /* pi with the sign of y */
    double half_pi_y = ww_sc_double(ww_sc_bits(WW_ATAN_PIO2) | ysign);
    double a = ww_atan(y / x);
    /* x < 0 (or NaN, whose a is NaN either way): a + pi with the sign of y */
    double off_axis = ww_pick(ww_mask(((ux & signbit) == 0) & (ax <= inf_bits)), a, a + pi_y);
    /* x = +-0: +-pi/2 for y != 0; for y = +-0 the sign of x picks 0 or pi, the sign of y the
     * side, as libm; a NaN y stays itself */
    double at_zero_y = ww_pick(ww_mask((ux & signbit) != 0), pi_y, y);
    double on_axis = ww_pick(ww_mask(ay == 0), at_zero_y,
                             ww_pick(ww_mask(ay > inf_bits), y, half_pi_y));
    return ww_pick(ww_mask(ax == 0), on_axis, off_axis);
}

#endif
