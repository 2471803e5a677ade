/* mathx.h - small double-precision helpers for the simulation (ww_m_: pure, no scene or state).
 * The renderer uses cglm for float matrices; the simulation stays in double.
 */
#ifndef WW_MATHX_H
#define WW_MATHX_H

#include <math.h>

#define WW_PI 3.14159265358979323846
#define WW_TAU 6.28318530717958647692
#define WW_G 9.80665 /* standard gravity, m/s^2 */

static inline double ww_m_clamp(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }
static inline double ww_m_lerp(double a, double b, double u) { return a + (b - a) * u; }
static inline double ww_m_rad(double deg) { return deg * (WW_PI / 180.0); }
static inline double ww_m_deg(double rad) { return rad * (180.0 / WW_PI); }
static inline double ww_m_smoothstep(double e0, double e1, double x) {
    double u = ww_m_clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return u * u * (3.0 - 2.0 * u);
}
/* x wrapped into [0, 2pi) */
static inline double ww_m_wrap_tau(double x) {
    double r = fmod(x, WW_TAU);
    return r < 0.0 ? r + WW_TAU : r;
}

static inline double ww_m_dot3(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline double ww_m_len3(const double a[3]) { return sqrt(ww_m_dot3(a, a)); }
static inline void ww_m_normalize3(double a[3]) {
    double l = ww_m_len3(a);
    if (l > 0.0) { a[0] /= l; a[1] /= l; a[2] /= l; }
}
static inline void ww_m_sub3(const double a[3], const double b[3], double out[3]) {
    out[0] = a[0] - b[0]; out[1] = a[1] - b[1]; out[2] = a[2] - b[2];
}
static inline void ww_m_cross3(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

#endif
