/* test_spectrum.c - the wave spectra and the components sampled from them (scene/spectrum.h):
 * closed forms and the published Pierson-Moskowitz figures, band energies, the global steepness,
 * and the seeded draws.
 *
 * Wind speed: Pierson-Moskowitz is written for U at 19.5 m above the sea (Pierson and Moskowitz
 * 1964), so Hs ~ 0.21 U^2 / g and wp ~ 0.877 g / U hold for that U; JONSWAP takes U at 10 m.
 */
#include <math.h>
#include <string.h>

#include "core/mathx.h"
#include "scene/scene.h"
#include "scene/spectrum.h"
#include "test.h"

/* adaptive Simpson is asked for 1e-10 of the whole; this allows rounding on top */
#define SPECTRUM_INTEGRAL_REL_TOL 1e-8
/* the discrete variance within 3% of the continuous spectrum's integral */
#define SPECTRUM_VARIANCE_REL_TOL 0.03
/* Hs within 5% as the component count goes from 16 to 256 */
#define SPECTRUM_HS_COUNT_REL_TOL 0.05
/* within 5% of the published PM figures 0.21 U^2 / g and 0.877 g / U (rounded to 2 and
 * 3 digits: 2 sqrt(alpha / beta) = 0.2092, (4 beta / 5)^(1/4) = 0.8772) */
#define PM_PUBLISHED_REL_TOL 0.05
/* a grid search for the peak resolves it to its spacing, 1e-4 relative */
#define PEAK_GRID_REL_TOL 2e-4
/* sum Q k A against the requested steepness: rounding of a sum of at most 256 terms */
#define STEEPNESS_SUM_TOL 1e-12
/* a component's frequency inside its band, up to the rounding of the band edges */
#define BAND_EDGE_REL_TOL 1e-12
/* the formula evaluated two ways, rounding only */
#define FORMULA_REL_TOL 1e-12

static ww_spectrum_desc pm(double wind, double lo, double hi, int count) {
    ww_scene sc;
    ww_scene_defaults(&sc);
    ww_spectrum_desc d = sc.spectrum;
    d.kind = WW_SPECTRUM_PM;
    d.wind_speed = wind;
    d.wavelength[0] = lo;
    d.wavelength[1] = hi;
    d.count = count;
    return d;
}

static ww_spectrum_desc jonswap(double wind, double fetch, double gamma, double lo, double hi,
                                int count) {
    ww_spectrum_desc d = pm(wind, lo, hi, count);
    d.kind = WW_SPECTRUM_JONSWAP;
    d.fetch = fetch;
    d.gamma = gamma;
    return d;
}

/* deep-water frequency of a wavelength, rad/s */
static double omega_of(double wavelength) { return sqrt(WW_TAU * WW_G / wavelength); }

/* int S dw of Pierson-Moskowitz in closed form: d/dw exp(-beta w0^4 w^-4) = 4 beta w0^4 w^-5
 * exp(...), so int_a^b = alpha g^2 / (4 beta w0^4) [exp(-beta (w0/b)^4) - exp(-beta (w0/a)^4)] */
static double pm_integral(double wind, double a, double b) {
    const double alpha = 8.1e-3, beta = 0.74;
    double w0 = WW_G / wind;
    double ea = exp(-beta * pow(w0 / a, 4.0)), eb = exp(-beta * pow(w0 / b, 4.0));
    return alpha * WW_G * WW_G / (4.0 * beta * pow(w0, 4.0)) * (eb - ea);
}

/* the trapezoid rule on 200000 log-spaced points: a second integrator, independent of the
 * library's adaptive Simpson */
static double trapezoid_log(const ww_spectrum_desc *d, double a, double b) {
    const int n = 200000;
    double sum = 0.0, prev_w = a, prev_f = ww_spectrum_density(d, a);
    for (int i = 1; i <= n; i++) {
        double w = a * pow(b / a, (double)i / n), f = ww_spectrum_density(d, w);
        sum += 0.5 * (f + prev_f) * (w - prev_w);
        prev_w = w;
        prev_f = f;
    }
    return sum;
}

/* variance of the sampled components, m^2 */
static double variance(const ww_wave *w, int n) {
    double m0 = 0.0;
    for (int i = 0; i < n; i++) m0 += 0.5 * w[i].amplitude * w[i].amplitude;
    return m0;
}

/* the grid point of largest density over [a, b], 1e-4 apart in log w */
static double grid_peak(const ww_spectrum_desc *d, double a, double b) {
    double best = a, best_s = -1.0;
    for (double w = a; w <= b; w *= 1.0001) {
        double s = ww_spectrum_density(d, w);
        if (s > best_s) {
            best_s = s;
            best = w;
        }
    }
    return best;
}

TEST(spectrum_pm_integral_matches_closed_form) {
    static const double winds[] = {3.0, 8.0, 20.0, 40.0};
    for (int i = 0; i < 4; i++) {
        ww_spectrum_desc d = pm(winds[i], 1.0, 300.0, 32);
        double a = omega_of(1000.0), b = omega_of(0.5);
        double want = pm_integral(winds[i], a, b);
        double got = ww_spectrum_integral(&d, a, b);
        ENSURE_NEAR(got / want, 1.0, SPECTRUM_INTEGRAL_REL_TOL);
        /* a narrow piece off the peak as well */
        double p = ww_spectrum_peak(&d);
        ENSURE_NEAR(ww_spectrum_integral(&d, 1.5 * p, 1.6 * p) / pm_integral(winds[i], 1.5 * p, 1.6 * p),
                    1.0, SPECTRUM_INTEGRAL_REL_TOL);
    }
    /* an empty or reversed range holds nothing */
    ww_spectrum_desc d = pm(10.0, 1.0, 300.0, 32);
    ENSURE(ww_spectrum_integral(&d, 2.0, 2.0) == 0.0);
    ENSURE(ww_spectrum_integral(&d, 3.0, 2.0) == 0.0);
    ENSURE(ww_spectrum_density(&d, 0.0) == 0.0);
}

TEST(spectrum_variance_matches_continuous_integral) {
    static ww_wave w[WW_MAX_WAVES];
    /* PM against its closed form, JONSWAP against the trapezoid rule */
    ww_spectrum_desc ds[] = {pm(8.0, 1.0, 300.0, 32), pm(15.0, 2.0, 100.0, 16),
                             jonswap(10.0, 1e5, 3.3, 1.0, 300.0, 32),
                             jonswap(20.0, 3e4, 7.0, 0.5, 200.0, 24)};
    for (int i = 0; i < 4; i++) {
        const ww_spectrum_desc *d = &ds[i];
        ww_spectrum_sample(d, 7, w);
        double a = omega_of(d->wavelength[1]), b = omega_of(d->wavelength[0]);
        double want = d->kind == WW_SPECTRUM_PM ? pm_integral(d->wind_speed, a, b)
                                                : trapezoid_log(d, a, b);
        ENSURE_NEAR(variance(w, d->count) / want, 1.0, SPECTRUM_VARIANCE_REL_TOL);
    }
}

TEST(spectrum_hs_stable_as_count_grows) {
    static ww_wave w[WW_MAX_WAVES];
    ww_spectrum_desc ds[] = {pm(10.0, 1.0, 300.0, 256), jonswap(12.0, 5e4, 3.3, 1.0, 300.0, 256)};
    for (int k = 0; k < 2; k++) {
        ww_spectrum_sample(&ds[k], 3, w);
        double hs256 = 4.0 * sqrt(variance(w, 256));
        for (int count = 16; count < 256; count *= 2) {
            ww_spectrum_desc d = ds[k];
            d.count = count;
            ww_spectrum_sample(&d, 3, w);
            ENSURE_NEAR(4.0 * sqrt(variance(w, count)) / hs256, 1.0, SPECTRUM_HS_COUNT_REL_TOL);
        }
    }
}

TEST(spectrum_pm_hs_and_peak_follow_wind_speed) {
    static ww_wave w[WW_MAX_WAVES];
    static const double winds[] = {5.0, 10.0, 15.0, 25.0};
    for (int i = 0; i < 4; i++) {
        double u = winds[i];
        /* wavelengths 0.05 m .. 20 km hold all but ~1e-5 of the energy at these winds */
        ww_spectrum_desc d = pm(u, 0.05, 20000.0, 256);
        ww_spectrum_sample(&d, 11, w);
        double hs = 4.0 * sqrt(variance(w, d.count));
        ENSURE_NEAR(hs / (0.21 * u * u / WW_G), 1.0, PM_PUBLISHED_REL_TOL);

        /* the peak: the formula, a grid search of the density, and the published figure */
        double wp = ww_spectrum_peak(&d);
        double a = omega_of(d.wavelength[1]), b = omega_of(d.wavelength[0]);
        ENSURE_NEAR(grid_peak(&d, a, b) / wp, 1.0, PEAK_GRID_REL_TOL);
        ENSURE_NEAR(wp / (0.877 * WW_G / u), 1.0, PM_PUBLISHED_REL_TOL);

        /* and the sampled components: the band of most energy per unit frequency holds it */
        double best = 0.0, best_w = 0.0;
        for (int j = 0; j < d.count; j++) {
            double e0 = a * pow(b / a, (double)j / d.count);
            double e1 = a * pow(b / a, (double)(j + 1) / d.count);
            double density = 0.5 * w[j].amplitude * w[j].amplitude / (e1 - e0);
            if (density > best) {
                best = density;
                best_w = w[j].omega;
            }
        }
        ENSURE_NEAR(best_w / (0.877 * WW_G / u), 1.0, PM_PUBLISHED_REL_TOL);
    }
}

TEST(spectrum_jonswap_peaks_at_its_formula) {
    static const double cases[][3] = {{10.0, 1e5, 3.3}, {20.0, 2e4, 1.0}, {6.0, 5e5, 7.0}};
    for (int i = 0; i < 3; i++) {
        double u = cases[i][0], fetch = cases[i][1], gamma = cases[i][2];
        ww_spectrum_desc d = jonswap(u, fetch, gamma, 0.1, 5000.0, 32);
        /* Hasselmann et al. (1973): wp = 22 (g^2 / (U F))^(1/3) */
        double wp = 22.0 * pow(WW_G * WW_G / (u * fetch), 1.0 / 3.0);
        ENSURE_NEAR(ww_spectrum_peak(&d) / wp, 1.0, FORMULA_REL_TOL);
        ENSURE_NEAR(grid_peak(&d, omega_of(5000.0), omega_of(0.1)) / wp, 1.0, PEAK_GRID_REL_TOL);
        /* at the peak r = 1: S = alpha g^2 wp^-5 e^(-5/4) gamma */
        double alpha = 0.076 * pow(u * u / (fetch * WW_G), 0.22);
        double at_peak = alpha * WW_G * WW_G * pow(wp, -5.0) * exp(-1.25) * gamma;
        ENSURE_NEAR(ww_spectrum_density(&d, wp) / at_peak, 1.0, FORMULA_REL_TOL);
    }
}

TEST(spectrum_steepness_sum_is_exact) {
    static ww_wave w[WW_MAX_WAVES];
    static const double steep[] = {0.0, 0.3, 0.5, 0.95};
    static const int counts[] = {1, 7, 64, 256};
    for (int i = 0; i < 4; i++) {
        ww_spectrum_desc d = jonswap(9.0, 8e4, 3.3, 0.5, 400.0, counts[i]);
        d.steepness = steep[i];
        ww_spectrum_sample(&d, 5, w);
        double sum = 0.0;
        for (int j = 0; j < d.count; j++) {
            sum += w[j].steepness * w[j].k * w[j].amplitude;
            ENSURE(w[j].steepness == w[0].steepness); /* one Q for all */
        }
        ENSURE_NEAR(sum, steep[i], STEEPNESS_SUM_TOL);
    }
}

TEST(spectrum_components_in_bands_seeded) {
    static ww_wave w[WW_MAX_WAVES], v[WW_MAX_WAVES];
    ww_spectrum_desc d = pm(10.0, 1.0, 300.0, 256);
    d.direction = ww_m_rad(30.0);
    d.spread = ww_m_rad(20.0);
    ww_spectrum_sample(&d, 42, w);
    double a = omega_of(300.0), b = omega_of(1.0);
    double mean = 0.0, var = 0.0;
    for (int j = 0; j < d.count; j++) {
        double e0 = a * pow(b / a, (double)j / d.count);
        double e1 = a * pow(b / a, (double)(j + 1) / d.count);
        ENSURE_MSG(w[j].omega >= e0 * (1.0 - BAND_EDGE_REL_TOL) &&
                       w[j].omega <= e1 * (1.0 + BAND_EDGE_REL_TOL),
                   "component %d: w = %g outside its band [%g, %g]", j, w[j].omega, e0, e1);
        /* deep water and derived fields */
        ENSURE_NEAR(w[j].omega * w[j].omega / (WW_G * w[j].k), 1.0, FORMULA_REL_TOL);
        ENSURE_NEAR(w[j].dir[0], cos(w[j].direction), FORMULA_REL_TOL);
        ENSURE(w[j].phase >= 0.0 && w[j].phase < WW_TAU);
        ENSURE(w[j].exponent == 1.0 && w[j].amplitude >= 0.0);
        mean += w[j].direction / d.count;
    }
    for (int j = 0; j < d.count; j++) var += pow(w[j].direction - mean, 2.0) / (d.count - 1);

    /* headings ~ normal(30, 20 deg): the sample mean within 4 standard errors (20 / 16 deg),
     * the sample deviation within 4 of its standard errors (20 / sqrt(2 * 255) deg) */
    ENSURE_NEAR(mean, d.direction, 4.0 * d.spread / 16.0);
    ENSURE_NEAR(sqrt(var), d.spread, 4.0 * d.spread / sqrt(510.0));

    /* the same seed draws the same components; another seed moves frequencies, headings and
     * phases but not the band energies */
    ww_spectrum_sample(&d, 42, v);
    ENSURE(memcmp(w, v, sizeof(ww_wave) * (size_t)d.count) == 0);
    ww_spectrum_sample(&d, 43, v);
    int moved = 0;
    for (int j = 0; j < d.count; j++) {
        moved += v[j].phase != w[j].phase && v[j].direction != w[j].direction;
        ENSURE(v[j].amplitude == w[j].amplitude);
    }
    ENSURE_EQ_INT(moved, d.count);
}
