/* spectrum.c - the Pierson-Moskowitz and JONSWAP wave spectra, their band energies by adaptive
 * Simpson integration, and the Gerstner components sampled from them at load (formulas and
 * sources in spectrum.h).
 */
#include "scene/spectrum.h"

#include <math.h>

#include "core/mathx.h"
#include "core/rng.h"

#define PM_ALPHA 8.1e-3       /* Phillips constant of Pierson-Moskowitz (1964) */
#define PM_BETA 0.74
#define JONSWAP_SIGMA_LO 0.07 /* peak width below wp (Hasselmann et al. 1973) */
#define JONSWAP_SIGMA_HI 0.09 /* and above */
#define EXP_UNDERFLOW 745.0   /* exp(-x) is 0 in double beyond this */

#define SIMPSON_REL_TOL 1e-10 /* relative to the whole integral (spectrum.h) */
#define SIMPSON_PANELS 32     /* log-spaced panels before adapting, so no narrow peak is missed */
#define SIMPSON_MAX_DEPTH 40  /* halvings of a panel; a panel at this depth is 2^-40 of it */

/* JONSWAP's alpha and peak frequency from the wind speed and the fetch (Hasselmann et al. 1973) */
static double jonswap_alpha(const ww_spectrum_desc *d) {
    return 0.076 * pow(d->wind_speed * d->wind_speed / (d->fetch * WW_G), 0.22);
}

static double jonswap_peak(const ww_spectrum_desc *d) {
    return 22.0 * cbrt(WW_G * WW_G / (d->wind_speed * d->fetch));
}

double ww_spectrum_density(const ww_spectrum_desc *d, double omega) {
    if (!(omega > 0.0)) return 0.0;
    double g2w5 = WW_G * WW_G / (omega * omega * omega * omega * omega);
    if (d->kind == WW_SPECTRUM_PM) {
        /* Pierson-Moskowitz (1964): alpha g^2 w^-5 exp(-beta (w0 / w)^4), w0 = g / U */
        double q = WW_G / (d->wind_speed * omega);
        double x = PM_BETA * q * q * q * q;
        return x > EXP_UNDERFLOW ? 0.0 : PM_ALPHA * g2w5 * exp(-x);
    }
    /* JONSWAP (Hasselmann et al. 1973): the PM shape around wp times the peak enhancement
     * gamma^r, r = exp(-(w - wp)^2 / (2 sigma^2 wp^2)) */
    double wp = jonswap_peak(d);
    double q = wp / omega;
    double x = 1.25 * q * q * q * q;
    if (x > EXP_UNDERFLOW) return 0.0;
    double sigma = omega <= wp ? JONSWAP_SIGMA_LO : JONSWAP_SIGMA_HI;
    double u = (omega - wp) / (sigma * wp);
    double r = exp(-0.5 * u * u);
    return jonswap_alpha(d) * g2w5 * exp(-x) * pow(d->gamma, r);
}

double ww_spectrum_peak(const ww_spectrum_desc *d) {
    /* PM: dS/dw = 0 where 5 w^4 = 4 beta w0^4; JONSWAP: both factors peak at wp */
    if (d->kind == WW_SPECTRUM_PM) return pow(0.8 * PM_BETA, 0.25) * WW_G / d->wind_speed;
    return jonswap_peak(d);
}

/* Simpson's rule on [a, b] with the midpoint m: (b - a) / 6 (fa + 4 fm + fb) */
static double simpson(double a, double b, double fa, double fm, double fb) {
    return (b - a) / 6.0 * (fa + 4.0 * fm + fb);
}

/* adaptive Simpson (Kuncir 1962; Lyness 1969): halve until the two halves agree with the whole
 * to 15 eps, then add the Richardson correction (S2 - S1) / 15 */
static double adapt(const ww_spectrum_desc *d, double a, double b, double fa, double fm,
                    double fb, double whole, double eps, int depth) {
    double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    double flm = ww_spectrum_density(d, lm), frm = ww_spectrum_density(d, rm);
    double left = simpson(a, m, fa, flm, fm), right = simpson(m, b, fm, frm, fb);
    double diff = left + right - whole;
    if (depth >= SIMPSON_MAX_DEPTH || fabs(diff) <= 15.0 * eps)
        return left + right + diff / 15.0;
    return adapt(d, a, m, fa, flm, fm, left, 0.5 * eps, depth + 1) +
           adapt(d, m, b, fm, frm, fb, right, 0.5 * eps, depth + 1);
}

double ww_spectrum_integral(const ww_spectrum_desc *d, double w0, double w1) {
    if (!(w1 > w0) || !(w0 > 0.0)) return 0.0;
    /* panels equal in log w (the spectrum spans decades); a coarse pass sets the tolerance */
    double edge[SIMPSON_PANELS + 1], f[2 * SIMPSON_PANELS + 1], coarse[SIMPSON_PANELS];
    double ratio = w1 / w0, total = 0.0;
    for (int i = 0; i <= SIMPSON_PANELS; i++)
        edge[i] = i == SIMPSON_PANELS ? w1 : w0 * pow(ratio, (double)i / SIMPSON_PANELS);
    for (int i = 0; i <= SIMPSON_PANELS; i++) f[2 * i] = ww_spectrum_density(d, edge[i]);
    for (int i = 0; i < SIMPSON_PANELS; i++) {
        f[2 * i + 1] = ww_spectrum_density(d, 0.5 * (edge[i] + edge[i + 1]));
        coarse[i] = simpson(edge[i], edge[i + 1], f[2 * i], f[2 * i + 1], f[2 * i + 2]);
        total += coarse[i];
    }
    if (!(total > 0.0)) return 0.0;
    double eps = SIMPSON_REL_TOL * total / SIMPSON_PANELS, sum = 0.0;
    for (int i = 0; i < SIMPSON_PANELS; i++)
        sum += adapt(d, edge[i], edge[i + 1], f[2 * i], f[2 * i + 1], f[2 * i + 2], coarse[i], eps,
                     0);
    return sum;
}

/* a standard normal deviate (Box and Muller 1958), from two uniforms */
static double normal_deviate(ww_rng *r) {
    double u1 = 1.0 - ww_rng_uniform(r); /* (0, 1]: the log is finite */
    double u2 = ww_rng_uniform(r);
    return sqrt(-2.0 * log(u1)) * cos(WW_TAU * u2);
}

void ww_spectrum_sample(const ww_spectrum_desc *d, uint64_t seed, ww_wave *out) {
    WW_ASSERT(d->count >= 1 && d->count <= WW_MAX_WAVES);
    WW_ASSERT(d->wavelength[0] > 0.0 && d->wavelength[1] > d->wavelength[0]);
    ww_rng rng;
    ww_rng_seed(&rng, seed, WW_RNG_WAVES);

    /* deep water w = sqrt(2 pi g / L): the longest wave has the lowest frequency */
    double wlo = sqrt(WW_TAU * WW_G / d->wavelength[1]);
    double whi = sqrt(WW_TAU * WW_G / d->wavelength[0]);
    double ratio = whi / wlo, sum_ka = 0.0;
    for (int i = 0; i < d->count; i++) {
        double e0 = wlo * pow(ratio, (double)i / d->count);
        double e1 = i + 1 == d->count ? whi : wlo * pow(ratio, (double)(i + 1) / d->count);

        /* the band's energy: variance A^2 / 2 = int S dw over the band */
        double energy = ww_spectrum_integral(d, e0, e1);

        /* draws in a fixed order: frequency in the band (log-uniform), heading, phase */
        double omega = e0 * pow(e1 / e0, ww_rng_uniform(&rng));
        double heading = d->direction + d->spread * normal_deviate(&rng);
        double phase = WW_TAU * ww_rng_uniform(&rng);

        ww_wave *w = &out[i];
        *w = (ww_wave){.direction = heading,
                       .wavelength = WW_TAU * WW_G / (omega * omega),
                       .amplitude = sqrt(2.0 * energy),
                       .exponent = 1.0,
                       .phase = phase};
        ww_wave_derive(w, 0.0);
        sum_ka += w->k * w->amplitude;
    }

    /* one Q for all components: sum Q k A = steepness, below 1 so the surface cannot fold */
    double q = sum_ka > 0.0 ? d->steepness / sum_ka : 0.0;
    for (int i = 0; i < d->count; i++) out[i].steepness = q;
}
