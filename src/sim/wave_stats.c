/* wave_stats.c - the statistics of a scene's wave field (wave_stats.h): closed-form moments of
 * each component's profile, and the slope and fold margin sampled over a grid of rest points at
 * several times.
 */
#include "sim/wave_stats.h"

#include <math.h>

#include "core/mathx.h"
#include "scene/spectrum.h"
#include "sim/waves.h"

#define DEFAULT_GRID 64
#define DEFAULT_TIMES 8

/* the Wallis integral M(e) = mean of sin^(2e) over a period = Gamma(e + 1/2) / (sqrt(pi)
 * Gamma(e + 1)) (Abramowitz and Stegun 6.1.1, 6.2.1), which is also the mean of
 * ((sin phi + 1) / 2)^e (with (sin phi + 1) / 2 = sin^2(phi / 2 + pi / 4)). Gamma of the
 * fractional part, then M(x) = M(x - 1) (x - 1/2) / x upwards, so no Gamma overflows. */
static double wallis(double e) {
    double e0 = e - floor(e);
    double m = tgamma(e0 + 0.5) / (sqrt(WW_PI) * tgamma(e0 + 1.0));
    int steps = (int)floor(e);
    for (int i = 1; i <= steps; i++) {
        double x = e0 + i;
        m *= (x - 0.5) / x;
    }
    return m;
}

/* the variance of one component's height: A^2 / 2 for a sine; for the steep sine
 * h = 2 A (u^e - mean), u^e having mean M(e) and second moment M(2 e), it is 4 A^2 (M(2e) - M(e)^2) */
static double component_variance(const ww_scene *sc, const ww_wave *w) {
    double A = w->amplitude;
    if (sc->wave_model != WW_WAVES_STEEP_SINES) return 0.5 * A * A;
    double m1 = wallis(w->exponent);
    return 4.0 * A * A * (wallis(2.0 * w->exponent) - m1 * m1);
}

/* max |dh/dphi| / A: 1 for a sine; for the steep sine |e u^(e-1) cos phi| = 2 e s^(2e-1) c with
 * s = sin(theta), c = cos(theta), theta = phi / 2 + pi / 4, largest where tan^2 theta = 2e - 1 */
static double slope_factor(const ww_scene *sc, const ww_wave *w) {
    if (sc->wave_model != WW_WAVES_STEEP_SINES) return 1.0;
    double e = w->exponent, s2 = (2.0 * e - 1.0) / (2.0 * e), c2 = 1.0 / (2.0 * e);
    return 2.0 * e * pow(s2, e - 0.5) * sqrt(c2);
}

/* Gerstner Q as the model uses it (waves.h): sines and steep sines move no water sideways */
static double model_q(const ww_scene *sc, const ww_wave *w) {
    return (sc->wave_model == WW_WAVES_GERSTNER || sc->wave_model == WW_WAVES_SPECTRUM)
               ? w->steepness
               : 0.0;
}

void ww_wave_stats_compute(const ww_scene *sc, int n, int ntimes, ww_wave_stats *out) {
    if (n <= 0) n = DEFAULT_GRID;
    if (ntimes <= 0) ntimes = DEFAULT_TIMES;
    int nw = sc->wave_model == WW_WAVES_FLAT ? 0 : sc->nwaves;
    *out = (ww_wave_stats){.count = nw, .fold_margin = 1.0};
    if (nw == 0) return;

    /* moments, energy weights and the bounds, component by component */
    double m0 = 0.0, lsum = 0.0, top = -1.0, bound = 0.0, fold = 0.0, lmax = 0.0, tmax = 0.0;
    int peak = 0;
    for (int i = 0; i < nw; i++) {
        const ww_wave *w = &sc->waves[i];
        double v = component_variance(sc, w);
        m0 += v;
        lsum += v * w->wavelength;
        if (v > top) {
            top = v;
            peak = i;
        }
        bound += w->k * w->amplitude * slope_factor(sc, w);
        fold += model_q(sc, w) * w->k * w->amplitude;
        lmax = fmax(lmax, w->wavelength);
        tmax = fmax(tmax, WW_TAU / w->omega);
    }
    out->m0 = m0;
    out->hs = 4.0 * sqrt(m0);
    out->peak_period = sc->wave_model == WW_WAVES_SPECTRUM
                           ? WW_TAU / ww_spectrum_peak(&sc->spectrum)
                           : WW_TAU / sc->waves[peak].omega;
    out->mean_wavelength = m0 > 0.0 ? lsum / m0 : 0.0;
    out->fold_sum = fold;
    /* |grad h| = |J^-T grad_a Y| <= |grad_a Y| / (1 - sum Q k A): J = I + M with M symmetric and
     * |M| <= sum Q k A, and |grad_a Y| <= sum k A h'max. No bound where the sea can fold. */
    out->slope_bound = fold < 1.0 ? bound / (1.0 - fold) : INFINITY;
    out->total_amplitude = ww_waves_total_amplitude(sc);

    /* the sample: an n x n grid of rest points over one longest wavelength, at ntimes times over
     * one longest period */
    double phase[WW_MAX_WAVES], slope = 0.0, margin = INFINITY;
    for (int tj = 0; tj < ntimes; tj++) {
        ww_waves_phases(sc, tmax * tj / ntimes, phase);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                ww_wave_point p;
                ww_waves_point(sc, phase, lmax * i / n, lmax * j / n, 0.0, &p);
                /* the horizontal Jacobian [dX/dx dX/dz; dZ/dx dZ/dz] and grad h = J^-T grad_a Y */
                double jxx = p.dpdx[0], jxz = p.dpdz[0], jzx = p.dpdx[2], jzz = p.dpdz[2];
                double det = jxx * jzz - jxz * jzx;
                margin = fmin(margin, det);
                if (det <= 0.0) continue; /* folded: no height field there */
                double yx = p.dpdx[1], yz = p.dpdz[1];
                double hx = (jzz * yx - jzx * yz) / det, hz = (jxx * yz - jxz * yx) / det;
                slope = fmax(slope, hypot(hx, hz));
            }
        }
    }
    out->max_slope = slope;
    out->fold_margin = margin;
    out->samples = n * n * ntimes;
}
