/* sincos.h - sine and cosine together, branch-free so that GCC at -O2 vectorises the loops that
 * call them (the batch wave evaluation, sim/waves.c), and deterministic (no libm, no data-dependent
 * branches, the same operations in the same order everywhere).
 *
 *   double s, c; ww_sincos(x, &s, &c);      float sf, cf; ww_sincosf(xf, &sf, &cf);
 *
 * Method (Cody and Waite, "Software Manual for the Elementary Functions", 1980): n = nearest
 * integer to x 2/pi (the 1.5 * 2^52 rounding trick), r = x - n pi/2 with pi/2 split into three
 * parts so that n * part is exact for the first two; then sin and cos of r in [-pi/4, pi/4] by
 * polynomials, and the quadrant n mod 4 picks and negates them with bit selects.
 * Double polynomials: the minimax coefficients of fdlibm's __kernel_sin and __kernel_cos
 * (Sun Microsystems, 1993), with its compensated 1 - r^2/2. Float polynomials: Cephes sinf/cosf
 * (Moshier, 1989).
 * Accuracy: absolute error <= 1e-15 (double) for |x| <= 2^20 pi/2 ~ 1.6e6, where n * pi/2's first
 * parts stay exact; <= 2e-7 (float) for |x| <= 2^10 pi/2 ~ 1.6e3. Beyond, the error grows with
 * |x| (the reduction loses bits) but stays finite; callers keep phases wrapped so |x| is small.
 */
#ifndef WW_SINCOS_H
#define WW_SINCOS_H

#include <stdint.h>
#include <string.h>

static inline uint64_t ww_sc_bits(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}
static inline double ww_sc_double(uint64_t u) {
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}
static inline uint32_t ww_sc_bitsf(float x) {
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}
static inline float ww_sc_float(uint32_t u) {
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

static inline void ww_sincos(double x, double *s, double *c) {
    /* n = round(x 2/pi): adding 1.5 * 2^52 leaves n in the low mantissa bits */
    const double magic = 0x1.8p52;
    double t = x * 0x1.45f306dc9c883p-1 + magic;
    uint64_t q = ww_sc_bits(t);
    double n = t - magic;
    /* r = x - n pi/2, pi/2 = p1 + p2 + p3 with 33-bit p1 and p2 (fdlibm's pio2_1, pio2_2) */
    double r = x - n * 0x1.921fb544p0;
    r = r - n * 0x1.0b4611a6p-34;
    r = r - n * 0x1.3198a2e037073p-69;

    /* sin r = r + r^3 (S1 + z S2 + ... + z^5 S6), z = r^2 (fdlibm __kernel_sin) */
    const double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                 S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                 S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
    double z = r * r;
    double ps = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    double sr = r + (z * r) * (S1 + z * ps);
    /* cos r = 1 - z/2 + z^2 (C1 + ... + z^5 C6), with the rounding of 1 - z/2 carried
     * (fdlibm __kernel_cos) */
    const double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                 C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                 C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
    double pc = C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))));
    double hz = 0.5 * z, w = 1.0 - hz;
    double cr = w + (((1.0 - w) - hz) + (z * z) * pc);

    /* quadrant: odd n swaps sin and cos; n = 2, 3 (mod 4) negate sin; n = 1, 2 negate cos */
    uint64_t swap = (uint64_t)0 - (q & 1u);
    uint64_t sb = ww_sc_bits(sr), cb = ww_sc_bits(cr);
    uint64_t so = (sb & ~swap) | (cb & swap);
    uint64_t co = (cb & ~swap) | (sb & swap);
    so ^= (q & 2u) << 62;
    co ^= ((q + 1u) & 2u) << 62;
    *s = ww_sc_double(so);
    *c = ww_sc_double(co);
}

static inline void ww_sincosf(float x, float *s, float *c) {
    /* n = round(x 2/pi) by the 1.5 * 2^23 trick; pi/2 = p1 + p2 + p3 with 12-bit p1 and p2 */
    const float magic = 0x1.8p23f;
    float t = x * 0x1.45f306p-1f + magic;
    uint32_t q = ww_sc_bitsf(t);
    float n = t - magic;
    float r = x - n * 0x1.922p0f;
    r = r - n * -0x1.2aep-18f;
    r = r - n * -0x1.de973ep-31f;

    /* Cephes sinf and cosf polynomials on [-pi/4, pi/4] */
    float z = r * r;
    float sr = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
    float cr = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f)
                   * z * z - 0.5f * z + 1.0f;

    uint32_t swap = (uint32_t)0 - (q & 1u);
    uint32_t sb = ww_sc_bitsf(sr), cb = ww_sc_bitsf(cr);
    uint32_t so = (sb & ~swap) | (cb & swap);
    uint32_t co = (cb & ~swap) | (sb & swap);
    so ^= (q & 2u) << 30;
    co ^= ((q + 1u) & 2u) << 30;
    *s = ww_sc_float(so);
    *c = ww_sc_float(co);
}

#endif
