/* exp.h - e^x, branch-free so that GCC at -O2 vectorises the loops that call it (the ripple sums
 * of a lane block, sim/water.c), and deterministic (no libm: the same operations in the same
 * order on every machine and libm version).
 *
 *   double y = ww_exp(x);
 *
 * Method (fdlibm's e_exp.c, Sun Microsystems, 1993): k = nearest integer to x / ln 2 (the
 * 1.5 * 2^52 rounding trick of sincos.h), r = x - k ln 2 with ln 2 split in two parts so that
 * k times the first is exact, then e^r on [-ln2/2, ln2/2] from a degree-5 minimax polynomial R
 * of r^2 in the rational form e^r = 1 + r + r c / (2 - c), c = r - r^2 R(r^2) (the coefficients
 * are fdlibm's P1..P5), and the result scaled by 2^k built in the exponent bits.
 * Accuracy: within 1 ulp of e^x for |x| <= 708; x is clamped to [-708, 708] first, so below
 * -708 the answer is e^-708 (3.3e-308) instead of a subnormal or 0, and above 708 e^708.
 */
#ifndef WW_EXP_H
#define WW_EXP_H

#include "core/select.h"
#include "core/sincos.h" /* ww_sc_bits, ww_sc_double */

#define WW_EXP_ARG_MAX 708.0

static inline double ww_exp(double x) {
    /* x into [-708, 708], a NaN left a NaN, by tests on its bits as integers: |x| beyond 708
     * and at most infinity takes 708 with x's sign. A select on the bits (core/select.h), so
     * that a loop calling this vectorises */
    const int64_t max_bits = 0x40862000, inf_bits = 0x7ff00000; /* high words of 708 and inf */
    uint64_t u = ww_sc_bits(x), sign = u & 0x8000000000000000u;
    int64_t mag = (int64_t)(u ^ sign);
    double limit = ww_sc_double(sign | ((uint64_t)max_bits << 32)); /* 708 with x's sign */
    x = ww_pick(ww_mask((mag > (max_bits << 32)) & (mag <= (inf_bits << 32))), limit, x);
    /* k = round(x / ln 2): adding 1.5 * 2^52 leaves k in the low mantissa bits */
    const double magic = 0x1.8p52;
    double t = x * 1.44269504088896338700e+00 + magic;
    uint64_t q = ww_sc_bits(t);
    double k = t - magic;
    /* ln 2 = LN2_HI + LN2_LO, LN2_HI with 32 trailing zero bits: k LN2_HI is exact */
    double hi = x - k * 6.93147180369123816490e-01;
    double lo = k * 1.90821492927058770002e-10;
    double r = hi - lo;
    const double P1 = 1.66666666666666019037e-01, P2 = -2.77777777770155933842e-03,
                 P3 = 6.61375632143793436117e-05, P4 = -1.65339022054652515390e-06,
                 P5 = 4.13813679705723846039e-08;
    double z = r * r;
    double c = r - z * (P1 + z * (P2 + z * (P3 + z * (P4 + z * P5))));
    double y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    /* 2^k: k + 1023 in [2, 2044] in the exponent field (the low 12 bits of q + 1023 are those
     * of k + 1023, the magic's own bits lying above them) */
    double scale = ww_sc_double((q + 1023u) << 52);
    return y * scale;
}

#endif
