/* atan.h - arctangent and the quadrant-correct atan2, deterministic (no libm: the same operations
 * in the same order on every machine and libm version, as sincos.h and exp.h), for the
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

#include <math.h>

#define WW_ATAN_PIO2 1.57079632679489661923
#define WW_ATAN_PIO4 7.85398163397448309616e-1
#define WW_ATAN_PI 3.14159265358979323846
/* pi/2 less its double: what the reduction above tan(3 pi/8) adds back */
#define WW_ATAN_MOREBITS 6.123233995736765886130e-17

static inline double ww_atan(double x) {
    double a = fabs(x), base = 0.0, more = 0.0, t = a;
    if (a > 2.41421356237309504880) { /* tan(3 pi/8) */
        base = WW_ATAN_PIO2;
        more = WW_ATAN_MOREBITS;
        t = -1.0 / a;
    } else if (a > 0.66) {
        base = WW_ATAN_PIO4;
        more = 0.5 * WW_ATAN_MOREBITS;
        t = (a - 1.0) / (a + 1.0);
    }
    double z = t * t;
    double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z -
                 7.500855792314704667340e1) * z - 1.228866684490136173410e2) * z -
               6.485021904942025371773e1;
    double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z +
                 4.328810604912902668951e2) * z + 4.853903996359136964868e2) * z +
               1.945506571482613964425e2;
    double r = base + ((t + t * z * (p / q)) + more);
    return signbit(x) ? -r : r;
}

static inline double ww_atan2(double y, double x) {
    if (x == 0.0) {
        if (y > 0.0) return WW_ATAN_PIO2;
        if (y < 0.0) return -WW_ATAN_PIO2;
        /* both zero: the sign of x picks 0 or pi, the sign of y the side, as libm */
        if (y == 0.0 && signbit(x)) return signbit(y) ? -WW_ATAN_PI : WW_ATAN_PI;
        return y; /* +-0, or NaN */
    }
    double a = ww_atan(y / x);
    if (x > 0.0) return a;
    return signbit(y) ? a - WW_ATAN_PI : a + WW_ATAN_PI;
}

#endif
