/* test_waves.c - the accuracy oracles of every wave family: sincos against libm, dispersion,
 * analytic partials, normals and velocities against finite differences, batch against scalar,
 * far points against a long double evaluation, the exact height query (Gerstner inversion against
 * a brute-force search, hard cases), ripples, and the wave statistics against closed forms.
 * Scenes are built from ww_scene_defaults() with fields set directly (no YAML).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "core/rng.h"
#include "core/atan.h"
#include "core/exp.h"
#include "core/sincos.h"
#include "sim/ripples.h"
#include "scene/spectrum.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/wave_stats.h"
#include "sim/water.h"
#include "sim/waves.h"
#include "test.h"

/* ww_sincos against libm: fdlibm's kernels after a 3-part Cody-Waite reduction, |x| <= 1e5 */
#define SINCOS_TOL 1e-15
/* ww_sincosf against libm in double, |x| <= 1e3: a couple of float ulps of 1 */
#define SINCOSF_TOL 2e-7
/* ww_exp against libm's exp, |x| <= 708: fdlibm's kernel, within one unit in the last place of
 * the true value, so at most two of libm's (itself within one) */
#define EXP_ULPS 2.0
/* ww_atan and ww_atan2 against libm, in ulps of the true value's magnitude: Cephes's rational
 * (2.6e-18 relative on its interval) plus the reduction's and the sum's roundings, and for
 * atan2 the quotient's and the added pi's; libm itself is within one */
#define ATAN_ULPS 2.0
#define ATAN2_ULPS 3.0
/* a wave one period later: the phases' rounding (a few ulps of 2 pi) times k A */
#define DISPERSION_TOL 1e-12
/* central differences with step FD_STEP against analytic partials (dimensionless): truncation
 * FD_STEP^2 k^3 A / 6 and rounding 1e-16 |x| / FD_STEP, both below it for k <= 2 pi / 0.5 m */
#define PARTIAL_FD_TOL 1e-7
#define FD_STEP 1e-5
/* the unit normal from finite-difference partials against the analytic one */
#define NORMAL_FD_TOL 1e-7
/* particle velocity against a central difference in time of the displaced point, m/s */
#define VELOCITY_FD_TOL 1e-7
/* the same model evaluated two equivalent ways (steep sines e = 1 against sines), m */
#define SAME_MODEL_TOL 1e-14
/* relative evaluation at 1e5 m against long double from the raw parameters, m: the double
 * phase of the origin at t (omega t ~ 1e6 rad rounds to ~1e-10 rad) times k A */
#define FAR_POINT_TOL 1e-9

/* the query's bound at fold margin >= 0.1: residual below this within QUERY_MAX_IT evaluations */
#define QUERY_RESIDUAL_TOL 1e-6
#define QUERY_MAX_IT 8
/* what the query reports against the same quantity recomputed from its rest point: rounding */
#define QUERY_CONSISTENCY_TOL 1e-12
/* the world normal against central differences of the queried height (tolerance 1e-13 m, step
 * QUERY_FD_STEP): the height's error over the step (1e-8) plus the truncation k^3 A step^2 / 6 */
#define QUERY_NORMAL_FD_TOL 1e-7
#define QUERY_FD_STEP 1e-5
/* ripple gradient and dh/dt against central differences (step FD_STEP; k up to 6 rad/m) */
#define RIPPLE_FD_TOL 1e-8
/* a far query's surface point against long double evaluation from the raw parameters, m */
#define QUERY_FAR_TOL 1e-9
/* a warm-started query against the cold one on a steep sea (sim/water.h ww_water_at_warm): both
 * stop within 1e-9 m of the rest point, so heights differ by at most the slope times 2e-9 m */
#define WARM_COLD_HEIGHT_TOL 1e-8
#define WARM_COLD_NORMAL_TOL 1e-7   /* |n_warm - n_cold| */
#define WARM_COLD_VELOCITY_TOL 1e-7 /* m/s */

/* statistics in closed form against the same numbers computed directly: rounding */
#define STATS_EXACT_TOL 1e-12
/* the steep-sine variance against trapezoidal quadrature of h^2 on 4096 points, m^2 per A^2 */
#define STEEP_VARIANCE_TOL 1e-12
/* the steep-sine slope bound against a scan of 1e6 phases: near the maximum the scan misses
 * f'' (pi / 1e6)^2 / 2, about 1e-11 relative */
#define STEEP_SLOPE_SCAN_TOL 1e-9
/* sampled extremes of a single wave on an n = 64 grid: the phases sampled leave gaps of at most
 * 2 pi / 64, so the sampled extreme of a smooth profile misses the true one by at most
 * (1 - cos(pi / 64)) ~ 1.2e-3 of its size (for the fold margin) or f'' (pi / 64)^2 / 2 (slope) */
#define STATS_SAMPLE_REL_TOL 0.0125
/* the spectrum's peak period against 2 pi / (0.877 g / U): 0.877 is (0.8 beta)^(1/4) rounded */
#define PM_PEAK_REL_TOL 1e-3
/* Hs of a Pierson-Moskowitz sea against 0.21 U^2 / g (5%: 0.21 is rounded and the
 * sampled range leaves out the far tails) */
#define PM_HS_REL_TOL 0.05

/* ---- scenes ---- */

static ww_scene *new_scene(ww_wave_model model) {
    ww_scene *sc = malloc(sizeof *sc);
    ww_scene_defaults(sc);
    sc->wave_model = model;
    return sc;
}

/* mean of ((sin phi + 1) / 2)^e over a period by the trapezoidal rule on 4096 points (exact to
 * rounding for a periodic integrand this smooth): the oracle for the steep-sine mean */
static double steep_mean_quad(double e) {
    const int n = 4096;
    double sum = 0.0;
    for (int i = 0; i < n; i++) sum += pow(0.5 * (sin(WW_TAU * i / n) + 1.0), e);
    return sum / n;
}

static ww_wave *add_wave(ww_scene *sc, double dir_deg, double L, double A, double Q, double e) {
    ww_wave *w = &sc->waves[sc->nwaves++];
    *w = (ww_wave){.direction = ww_m_rad(dir_deg), .wavelength = L, .amplitude = A,
                   .steepness = Q, .exponent = e, .phase = 0.1 * sc->nwaves};
    ww_wave_derive(w, 0.0);
    w->mean = steep_mean_quad(e);
    return w;
}

/* n components, wavelengths log-uniform in [lo, hi], headings all round, Q in [0.4, 1], then
 * the amplitudes scaled so that sum Q k A = fold_sum (for sines: sum k A = fold_sum) */
static void random_sea(ww_scene *sc, int n, double lo, double hi, double fold_sum, double e,
                       uint64_t seed) {
    ww_rng r;
    ww_rng_seed(&r, seed, WW_RNG_WAVES);
    sc->nwaves = 0;
    double sum = 0.0;
    for (int i = 0; i < n; i++) {
        double L = lo * pow(hi / lo, ww_rng_uniform(&r));
        double A = L * (0.2 + ww_rng_uniform(&r)) / 100.0;
        double Q = 0.4 + 0.6 * ww_rng_uniform(&r);
        ww_wave *w = add_wave(sc, 360.0 * ww_rng_uniform(&r), L, A, Q, e);
        w->phase = WW_TAU * ww_rng_uniform(&r);
        sum += (sc->wave_model == WW_WAVES_GERSTNER ? Q : 1.0) * w->k * A;
    }
    for (int i = 0; i < n; i++) sc->waves[i].amplitude *= fold_sum / sum;
}

/* the families the tests sweep: model and steep-sine exponent */
typedef struct family {
    const char *name;
    ww_wave_model model;
    double e;
} family;

static const family FAMILIES[] = {
    {"gerstner", WW_WAVES_GERSTNER, 1.0},   {"sines", WW_WAVES_SINES, 1.0},
    {"steep e=1", WW_WAVES_STEEP_SINES, 1.0}, {"steep e=2", WW_WAVES_STEEP_SINES, 2.0},
    {"steep e=5.5", WW_WAVES_STEEP_SINES, 5.5},
};
#define NFAMILIES (int)(sizeof FAMILIES / sizeof FAMILIES[0])

static ww_scene *family_sea(const family *f, int n, uint64_t seed) {
    ww_scene *sc = new_scene(f->model);
    random_sea(sc, n, 0.5, 40.0, 0.6, f->e, seed);
    return sc;
}

/* ---- sincos ---- */

TEST(waves_sincos_matches_libm) {
    ww_rng r;
    ww_rng_seed(&r, 7, 0);
    double worst = 0.0, worstf = 0.0;
    for (int i = 0; i < 200000; i++) {
        double u = 2.0 * ww_rng_uniform(&r) - 1.0;
        double x = i % 3 == 0 ? u * 1e5 : i % 3 == 1 ? u * 10.0 : u * 1e-4;
        double s, c;
        ww_sincos(x, &s, &c);
        worst = fmax(worst, fmax(fabs(s - sin(x)), fabs(c - cos(x))));
        float xf = (float)(u * 1e3), sf, cf;
        ww_sincosf(xf, &sf, &cf);
        worstf = fmax(worstf, fmax(fabs(sf - sin((double)xf)), fabs(cf - cos((double)xf))));
    }
    /* quadrant edges: the multiples of pi/2 and their neighbours */
    for (int k = -2000; k <= 2000; k++) {
        double x = k * (WW_PI / 2.0), s, c;
        for (int d = 0; d < 3; d++) {
            double y = d == 0 ? x : nextafter(x, d == 1 ? -INFINITY : INFINITY);
            ww_sincos(y, &s, &c);
            worst = fmax(worst, fmax(fabs(s - sin(y)), fabs(c - cos(y))));
        }
    }
    double s, c;
    ww_sincos(0.0, &s, &c);
    ENSURE(s == 0.0 && c == 1.0);
    ENSURE_NEAR(worst, 0.0, SINCOS_TOL);
    ENSURE_NEAR(worstf, 0.0, SINCOSF_TOL);
    printf("    sincos max |error| vs libm: double %.3g, float %.3g\n", worst, worstf);
}

TEST(waves_exp_matches_libm) {
    ww_rng r;
    ww_rng_seed(&r, 11, 0);
    double worst = 0.0, worst_x = 0.0;
    for (int i = 0; i < 300000; i++) {
        double u = 2.0 * ww_rng_uniform(&r) - 1.0;
        double x = i % 3 == 0 ? u * 708.0 : i % 3 == 1 ? u * 2.0 : u * 1e-9;
        double e = exp(x), ulp = nextafter(e, INFINITY) - e;
        double d = fabs(ww_exp(x) - e) / ulp;
        if (d > worst) worst = d, worst_x = x;
    }
    /* the reduction's edges: the multiples of ln 2 / 2 and their neighbours */
    for (int k = -2040; k <= 2040; k++) {
        double x = k * (0.5 * M_LN2);
        for (int d = 0; d < 3; d++) {
            double y = d == 0 ? x : nextafter(x, d == 1 ? -INFINITY : INFINITY);
            double e = exp(y), q = fabs(ww_exp(y) - e) / (nextafter(e, INFINITY) - e);
            if (q > worst) worst = q, worst_x = y;
        }
    }
    printf("    exp max error vs libm: %.2f ulp (at x = %.6g)\n", worst, worst_x);
    ENSURE(ww_exp(0.0) == 1.0);
    ENSURE(worst <= EXP_ULPS);
    /* past the clamp: finite and positive, never 0, inf or NaN */
    ENSURE(ww_exp(-1000.0) == ww_exp(-708.0) && ww_exp(-708.0) > 0.0);
    ENSURE(isfinite(ww_exp(1000.0)));
    /* the clamp (tests on the bits): everything past +-708 is +-708, the ends and what lies
     * just inside are themselves, and a NaN stays a NaN (the NaN guard must see it) */
    static const double beyond[] = {708.0000000000001, 709.0, 1e300, DBL_MAX, INFINITY};
    for (size_t k = 0; k < sizeof beyond / sizeof beyond[0]; k++) {
        ENSURE(ww_exp(beyond[k]) == ww_exp(708.0));
        ENSURE(ww_exp(-beyond[k]) == ww_exp(-708.0));
    }
    ENSURE(ww_exp(nextafter(708.0, 0.0)) < ww_exp(708.0));
    ENSURE(ww_exp(nextafter(-708.0, 0.0)) > ww_exp(-708.0));
    ENSURE(ww_exp(-0.0) == 1.0 && ww_exp(DBL_TRUE_MIN) == 1.0);
    ENSURE(isnan(ww_exp(NAN)) && isnan(ww_exp(-NAN)));
}

/* |a - b| in ulps of b (b's own spacing; at 0 the smallest normal's) */
static double ulps_off(double a, double b) {
    double m = fmax(fabs(b), 0x1p-1022);
    return fabs(a - b) / (nextafter(m, INFINITY) - m);
}

TEST(waves_atan_matches_libm) {
    ww_rng r;
    ww_rng_seed(&r, 13, 0);
    double worst = 0.0, worst_x = 0.0, worst2 = 0.0, worst_y = 0.0, worst_x2 = 0.0;
    for (int i = 0; i < 300000; i++) {
        double u = 2.0 * ww_rng_uniform(&r) - 1.0, v = 2.0 * ww_rng_uniform(&r) - 1.0;
        /* every reduction: |x| below 0.66, up to tan(3 pi/8), beyond; tiny and huge */
        double x = i % 4 == 0 ? u * 0.66 : i % 4 == 1 ? u * 2.5 : i % 4 == 2 ? u * 1e6 : u * 1e-9;
        double q = ulps_off(ww_atan(x), atan(x));
        if (q > worst) worst = q, worst_x = x;
        /* atan2 over every quadrant, magnitudes apart by up to 1e6 either way */
        double y = v * pow(10.0, 6.0 * ww_rng_uniform(&r) - 3.0);
        q = ulps_off(ww_atan2(y, x), atan2(y, x));
        if (q > worst2) worst2 = q, worst_y = y, worst_x2 = x;
    }
    /* the reductions' edges and their neighbours */
    const double edges[] = {0.66, 2.41421356237309504880, 1.0};
    for (int e = 0; e < 3; e++)
        for (int d = -2; d <= 2; d++) {
            double x = edges[e];
            for (int k = 0; k < abs(d); k++) x = nextafter(x, d < 0 ? 0.0 : INFINITY);
            for (int sg = -1; sg <= 1; sg += 2) {
                double q = ulps_off(ww_atan(sg * x), atan(sg * x));
                if (q > worst) worst = q, worst_x = sg * x;
            }
        }
    printf("    atan max error vs libm: %.2f ulp (at x = %.6g); atan2 %.2f ulp (at %.6g, %.6g)\n",
           worst, worst_x, worst2, worst_y, worst_x2);
    ENSURE(worst <= ATAN_ULPS);
    ENSURE(worst2 <= ATAN2_ULPS);
    /* the special values the header lists */
    ENSURE(ww_atan(0.0) == 0.0 && !signbit(ww_atan(0.0)) && signbit(ww_atan(-0.0)));
    ENSURE(ww_atan(INFINITY) == atan(INFINITY) && ww_atan(-INFINITY) == atan(-INFINITY));
    ENSURE(isnan(ww_atan(NAN)) && isnan(ww_atan2(NAN, 1.0)) && isnan(ww_atan2(1.0, NAN)));
    ENSURE(isnan(ww_atan2(NAN, 0.0)) && isnan(ww_atan2(NAN, -0.0)) && isnan(ww_atan2(0.0, NAN)));
    const double zs[][2] = {{0.0, 0.0}, {-0.0, 0.0}, {0.0, -0.0}, {-0.0, -0.0}, {0.0, -1.0},
                            {-0.0, -1.0}, {1.0, 0.0}, {-1.0, -0.0}, {0.0, 1.0}};
    for (int k = 0; k < 9; k++) {
        double a = ww_atan2(zs[k][0], zs[k][1]), b = atan2(zs[k][0], zs[k][1]);
        ENSURE(a == b && signbit(a) == signbit(b));
    }
    /* a heading round trip: the angle of (cos t, sin t) is t, within the sine and cosine's own
     * error (SINCOS_TOL, far above atan2's) */
    for (int k = -100; k <= 100; k++) {
        double t = k * (WW_PI / 100.5), s, c;
        ww_sincos(t, &s, &c);
        ENSURE_NEAR(ww_atan2(s, c), t, 2.0 * SINCOS_TOL);
    }
}

/* ww_atan and ww_atan2 pick their reduction and quadrant with masks, so that loops calling them
 * vectorise; these are the same choices made with branches (Cephes's atan.c and the quadrants as
 * libm), around the same rational (ww_atan_reduced): the oracle the masks must agree with */
static double atan_branches(double x) {
    double a = fabs(x), base = 0.0, more = 0.0, t = a;
    if (a > 2.41421356237309504880) {
        base = WW_ATAN_PIO2;
        more = WW_ATAN_MOREBITS;
        t = -1.0 / a;
    } else if (a > 0.66) {
        base = WW_ATAN_PIO4;
        more = 0.5 * WW_ATAN_MOREBITS;
        t = (a - 1.0) / (a + 1.0);
    }
    double r = ww_atan_reduced(t, base, more);
    return signbit(x) ? -r : r;
}
static double atan2_branches(double y, double x) {
    if (x == 0.0) {
        if (y > 0.0) return WW_ATAN_PIO2;
        if (y < 0.0) return -WW_ATAN_PIO2;
        if (y == 0.0 && signbit(x)) return signbit(y) ? -WW_ATAN_PI : WW_ATAN_PI;
        return y;
    }
    double a = atan_branches(y / x);
    if (x > 0.0) return a;
    return signbit(y) ? a - WW_ATAN_PI : a + WW_ATAN_PI;
}
/* the same bits, or both NaN */
static int same_bits(double a, double b) {
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

TEST(waves_atan_masks_are_the_branches_to_the_bit) {
    ww_rng r;
    ww_rng_seed(&r, 29, 0);
    int bad = 0;
    for (int i = 0; i < 300000 && bad < 5; i++) {
        /* magnitudes from 1e-300 to 1e300, every sign, and each reduction's edge region */
        double u = 2.0 * ww_rng_uniform(&r) - 1.0, v = 2.0 * ww_rng_uniform(&r) - 1.0;
        double x = i % 3 == 0 ? u * pow(10.0, 600.0 * ww_rng_uniform(&r) - 300.0)
                              : u * (i % 3 == 1 ? 0.66 : 2.41421356237309504880) *
                                    (1.0 + 1e-3 * v);
        double y = v * pow(10.0, 12.0 * ww_rng_uniform(&r) - 6.0) * fabs(x);
        if (!same_bits(ww_atan(x), atan_branches(x)) ||
            !same_bits(ww_atan2(y, x), atan2_branches(y, x))) {
            printf("    differ at x = %.17g, y = %.17g\n", x, y);
            bad++;
        }
    }
    ENSURE(bad == 0);
    /* the edges, their neighbours, and the special values, every pair of them for atan2 */
    double sp[32];
    int n = 0;
    const double edges[] = {0.66, 2.41421356237309504880};
    for (int e = 0; e < 2; e++)
        for (int d = -1; d <= 1; d++)
            sp[n++] = nextafter(edges[e], d < 0 ? 0.0 : d > 0 ? 9.0 : edges[e]);
    const double others[] = {0.0, 5e-324, 1.0, 1e300, INFINITY, NAN};
    for (int k = 0; k < 6; k++) sp[n++] = others[k];
    for (int k = 0, m = n; k < m; k++) sp[n++] = -sp[k];
    for (int a = 0; a < n; a++) {
        ENSURE(same_bits(ww_atan(sp[a]), atan_branches(sp[a])));
        for (int b = 0; b < n; b++)
            ENSURE(same_bits(ww_atan2(sp[a], sp[b]), atan2_branches(sp[a], sp[b])));
    }
}

/* ---- the field ---- */

TEST(waves_dispersion_period) {
    /* deep water: omega^2 = g k, so a wave of length L repeats after T = sqrt(2 pi L / g) */
    const double Ls[] = {0.3, 7.0, 120.0};
    for (int m = 0; m < 2; m++) {
        for (int l = 0; l < 3; l++) {
            ww_scene *sc = new_scene(m ? WW_WAVES_SINES : WW_WAVES_GERSTNER);
            add_wave(sc, 25, Ls[l], 0.01 * Ls[l], 0.7, 1.0);
            double T = sqrt(WW_TAU * Ls[l] / WW_G), t0 = 3.3, ph0[1], ph1[1], ph2[1];
            ww_waves_phases(sc, t0, ph0);
            ww_waves_phases(sc, t0 + T, ph1);
            ww_waves_phases(sc, t0 + 0.5 * T, ph2);
            for (int i = 0; i < 16; i++) {
                double x = -3.0 + 0.61 * i, z = 1.0 - 0.37 * i, a[3], b[3], h[3];
                ww_waves_eval(sc, ph0, x, z, a, NULL);
                ww_waves_eval(sc, ph1, x, z, b, NULL);
                ww_waves_eval(sc, ph2, x, z, h, NULL);
                for (int c = 0; c < 3; c++) ENSURE_NEAR(a[c], b[c], DISPERSION_TOL);
                /* half a period later the surface is the mirror image (so T is not a multiple
                 * of the true period either) */
                ENSURE_NEAR(h[1], -a[1], DISPERSION_TOL);
                ENSURE_NEAR(h[0] - x, -(a[0] - x), DISPERSION_TOL);
            }
            free(sc);
        }
    }
}

TEST(waves_partials_normals_velocity_match_finite_differences) {
    for (int fi = 0; fi < NFAMILIES; fi++) {
        const family *f = &FAMILIES[fi];
        ww_scene *sc = family_sea(f, 6, 11 + (uint64_t)fi);
        sc->water_level = 0.4;
        double t = 2.75, ph[6], phm[6], php[6], h = FD_STEP;
        ww_waves_phases(sc, t, ph);
        ww_waves_phases(sc, t - h, phm);
        ww_waves_phases(sc, t + h, php);
        double worst = 0.0;
        for (int i = 0; i < 40; i++) {
            double x = -9.0 + 0.53 * i, z = 4.0 - 0.29 * i;
            ww_wave_point p, x0, x1, z0, z1, t0, t1;
            ww_waves_point(sc, ph, x, z, 0.0, &p);
            ww_waves_point(sc, ph, x - h, z, 0.0, &x0);
            ww_waves_point(sc, ph, x + h, z, 0.0, &x1);
            ww_waves_point(sc, ph, x, z - h, 0.0, &z0);
            ww_waves_point(sc, ph, x, z + h, 0.0, &z1);
            ww_waves_point(sc, phm, x, z, 0.0, &t0);
            ww_waves_point(sc, php, x, z, 0.0, &t1);
            double fx[3], fz[3], fn[3];
            for (int c = 0; c < 3; c++) {
                fx[c] = (x1.p[c] - x0.p[c]) / (2 * h);
                fz[c] = (z1.p[c] - z0.p[c]) / (2 * h);
                double fv = (t1.p[c] - t0.p[c]) / (2 * h);
                ENSURE_NEAR(p.dpdx[c], fx[c], PARTIAL_FD_TOL);
                ENSURE_NEAR(p.dpdz[c], fz[c], PARTIAL_FD_TOL);
                ENSURE_NEAR(p.vel[c], fv, VELOCITY_FD_TOL);
                worst = fmax(worst, fabs(p.dpdx[c] - fx[c]));
            }
            fn[0] = fz[1] * fx[2] - fz[2] * fx[1];
            fn[1] = fz[2] * fx[0] - fz[0] * fx[2];
            fn[2] = fz[0] * fx[1] - fz[1] * fx[0];
            ww_m_normalize3(fn);
            for (int c = 0; c < 3; c++) ENSURE_NEAR(p.normal[c], fn[c], NORMAL_FD_TOL);
            ENSURE(p.normal[1] > 0.0);
            /* ww_waves_eval gives the same point and normal */
            double e3[3], n3[3];
            ww_waves_eval(sc, ph, x, z, e3, n3);
            for (int c = 0; c < 3; c++) ENSURE(e3[c] == p.p[c] && n3[c] == p.normal[c]);
            /* sines and steep sines move no water sideways */
            if (f->model != WW_WAVES_GERSTNER) ENSURE(p.p[0] == x && p.p[2] == z);
        }
        if (ww_test_failed_now()) printf("    family %s: worst dP/dx error %.3g\n", f->name, worst);
        free(sc);
    }
}

TEST(waves_steep_profile_is_seed_001s_shape) {
    /* e = 1 is the plain sine; e = 2 is 2 A (((s + 1) / 2)^2 - 3/8), its mean sin^4 = 3/8 */
    ww_scene *a = new_scene(WW_WAVES_SINES), *b = new_scene(WW_WAVES_STEEP_SINES);
    ww_scene *c = new_scene(WW_WAVES_STEEP_SINES);
    add_wave(a, 40, 9, 0.2, 0, 1);
    add_wave(b, 40, 9, 0.2, 0, 1);
    add_wave(c, 40, 9, 0.2, 0, 2);
    ENSURE_NEAR(c->waves[0].mean, 0.375, SAME_MODEL_TOL);
    double ph[1];
    ww_waves_phases(a, 1.5, ph);
    for (int i = 0; i < 20; i++) {
        double x = 0.7 * i, z = -0.3 * i, pa[3], pb[3], pc[3];
        ww_waves_eval(a, ph, x, z, pa, NULL);
        ww_waves_eval(b, ph, x, z, pb, NULL);
        ww_waves_eval(c, ph, x, z, pc, NULL);
        ENSURE_NEAR(pa[1], pb[1], SAME_MODEL_TOL);
        const ww_wave *w = &c->waves[0];
        double s = sin(w->k * (w->dir[0] * x + w->dir[1] * z) + ph[0]), u = 0.5 * (s + 1.0);
        ENSURE_NEAR(pc[1], 2 * 0.2 * (u * u - 0.375), SAME_MODEL_TOL);
    }
    /* the surface of a steep sine rests at the water level on average */
    double mean = 0.0;
    for (int i = 0; i < 1000; i++) {
        double p[3];
        ww_waves_eval(c, ph, 9.0 * i / 1000.0 / cos(ww_m_rad(40)), 0.0, p, NULL);
        mean += p[1] / 1000.0;
    }
    ENSURE_NEAR(mean, 0.0, SAME_MODEL_TOL);
    free(a);
    free(b);
    free(c);
}

TEST(waves_flat_model_has_no_components) {
    ww_scene *sc = new_scene(WW_WAVES_FLAT);
    add_wave(sc, 0, 5, 0.3, 0.5, 1);
    sc->water_level = -2.0;
    double ph[1] = {0.0};
    ww_wave_point p;
    ww_waves_point(sc, ph, 3, 4, 0.0, &p);
    ENSURE(p.p[0] == 3 && p.p[1] == -2.0 && p.p[2] == 4 && p.normal[1] == 1.0);
    ENSURE(p.vel[0] == 0 && p.vel[1] == 0 && p.vel[2] == 0);
    ENSURE(ww_waves_total_amplitude(sc) == 0.0);
    free(sc);
}

TEST(waves_total_amplitude_bounds_the_surface) {
    for (int fi = 0; fi < NFAMILIES; fi++) {
        ww_scene *sc = family_sea(&FAMILIES[fi], 5, 3 + (uint64_t)fi);
        double total = ww_waves_total_amplitude(sc), top = 0.0, ph[5];
        ww_waves_phases(sc, 0.0, ph);
        for (int i = 0; i < 4000; i++) {
            double p[3];
            ww_waves_eval(sc, ph, 0.37 * i, -0.11 * i, p, NULL);
            top = fmax(top, fabs(p[1]));
        }
        ENSURE(top <= total);
        ENSURE(top > 0.3 * total); /* and it is not a loose bound */
        free(sc);
    }
}

TEST(waves_min_wavelength_skips_short_components) {
    ww_scene *all = new_scene(WW_WAVES_GERSTNER), *lng = new_scene(WW_WAVES_GERSTNER);
    random_sea(all, 12, 0.5, 50, 0.5, 1.0, 5);
    double ph[12], phl[12];
    ww_waves_phases(all, 4.0, ph);
    lng->nwaves = 0;
    for (int i = 0; i < all->nwaves; i++)
        if (all->waves[i].wavelength >= 6.0) {
            phl[lng->nwaves] = ph[i];
            lng->waves[lng->nwaves++] = all->waves[i];
        }
    ENSURE(lng->nwaves > 0 && lng->nwaves < all->nwaves);
    for (int i = 0; i < 10; i++) {
        ww_wave_point a, b;
        ww_waves_point(all, ph, 1.3 * i, 0.4 * i, 6.0, &a);
        ww_waves_point(lng, phl, 1.3 * i, 0.4 * i, 0.0, &b);
        for (int c = 0; c < 3; c++) {
            ENSURE(a.p[c] == b.p[c] && a.normal[c] == b.normal[c] && a.vel[c] == b.vel[c]);
        }
    }
    free(all);
    free(lng);
}

TEST(waves_batch_matches_scalar) {
    enum { N = 203 }; /* three blocks and a short one */
    static double x[N], z[N], X[N], Y[N], Z[N], nx[N], ny[N], nz[N];
    static float xf[N], zf[N], Xf[N], Yf[N], Zf[N], nxf[N], nyf[N], nzf[N];
    const int counts[] = {1, 8, 256};
    for (int fi = 0; fi < NFAMILIES; fi++) {
        for (int ci = 0; ci < 3; ci++) {
            ww_scene *sc = family_sea(&FAMILIES[fi], counts[ci], 100 + (uint64_t)(fi * 3 + ci));
            sc->water_level = 0.25;
            double ph[WW_MAX_WAVES], worst = 0.0, worstf = 0.0, worstfy = 0.0, worstfn = 0.0;
            ww_waves_phases(sc, 1e3, ph);
            for (int j = 0; j < N; j++) {
                x[j] = -40.0 + 80.0 * j / N;
                z[j] = 30.0 * sin(0.1 * j);
                xf[j] = (float)x[j];
                zf[j] = (float)z[j];
            }
            ww_waves_eval_batch(sc, ph, N, x, z, X, Y, Z, nx, ny, nz);
            ww_waves_eval_batch_f(sc, ph, N, xf, zf, Xf, Yf, Zf, nxf, nyf, nzf);
            double *pos[3] = {X, Y, Z}, *nor[3] = {nx, ny, nz};
            float *posf[3] = {Xf, Yf, Zf}, *norf[3] = {nxf, nyf, nzf};
            for (int j = 0; j < N; j++) {
                double p[3], n[3];
                ww_waves_eval(sc, ph, (double)xf[j], (double)zf[j], p, n);
                double pd[3], nd[3];
                ww_waves_eval(sc, ph, x[j], z[j], pd, nd);
                for (int c = 0; c < 3; c++) {
                    /* the same operations in the same order, one lane per point: equal bits */
                    ENSURE_MSG(pos[c][j] == pd[c] && nor[c][j] == nd[c],
                               "%s point %d: batch (%.17g, %.17g) scalar (%.17g, %.17g)",
                               FAMILIES[fi].name, j, pos[c][j], nor[c][j], pd[c], nd[c]);
                    worst = fmax(worst, fabs(pos[c][j] - pd[c]));
                    worstf = fmax(worstf, fabs((double)posf[c][j] - p[c]));
                    worstfn = fmax(worstfn, fabs((double)norf[c][j] - n[c]));
                }
                worstfy = fmax(worstfy, fabs((double)Yf[j] - p[1]));
            }
            /* without normals the points are the same */
            ww_waves_eval_batch(sc, ph, N, x, z, nx, ny, nz, NULL, NULL, NULL);
            for (int j = 0; j < N; j++) ENSURE(nx[j] == X[j] && ny[j] == Y[j] && nz[j] == Z[j]);
            /* float: each component's phase rounds to a float ulp of |phase| + k (|x| + |z|)
             * (70 m here), times its slope (e k A for the steep profile); each of the count
             * float sums rounds by half an ulp of what it holds (positions up to 40 m) */
            double bound = 0.0, total = ww_waves_total_amplitude(sc);
            for (int i = 0; i < sc->nwaves; i++) {
                const ww_wave *w = &sc->waves[i];
                bound += 2.0 * FAMILIES[fi].e * w->amplitude * (WW_TAU + w->k * 70.0) * 0x1p-24;
            }
            bound += counts[ci] * (40.0 + total) * 0x1p-24;
            ENSURE_MSG(worstf <= bound, "%s %d components: float error %.3g > bound %.3g",
                       FAMILIES[fi].name, counts[ci], worstf, bound);
            if (ci == 2 || ww_test_failed_now())
                printf("    %-12s %3d components: batch-scalar %.2g m; float-double: height "
                       "%.2g m (%.2g of the total amplitude), position %.2g m, normal %.2g\n",
                       FAMILIES[fi].name, counts[ci], worst, worstfy, worstfy / total, worstf,
                       worstfn);
            free(sc);
        }
    }
}

TEST(waves_far_point_relative_matches_long_double) {
    /* at |x| = 1e5 m and t = 1e6 s: phases moved to a reference near the point, positions
     * relative, against every phase summed in long double from the raw parameters */
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    random_sea(sc, 16, 0.01, 1000.0, 0.5, 1.0, 77);
    double t = 1e6, ph[16], pha[16];
    ww_waves_phases(sc, t, ph);
    const double far[][2] = {{1e5, 0.0}, {-1e5, 1e5}, {73211.4, -99999.9}};
    for (int f = 0; f < 3; f++) {
        double rx = round(far[f][0]), rz = round(far[f][1]);
        ww_waves_phases_at(sc, ph, rx, rz, pha);
        for (int i = 0; i < sc->nwaves; i++) ENSURE(pha[i] >= 0.0 && pha[i] < WW_TAU);
        for (int j = 0; j < 5; j++) {
            double x = far[f][0] + 0.3 * j, z = far[f][1] - 0.2 * j, p[3];
            ww_waves_eval(sc, pha, x - rx, z - rz, p, NULL);
            long double Y = 0.0L, X = (long double)x;
            for (int i = 0; i < sc->nwaves; i++) {
                const ww_wave *w = &sc->waves[i];
                long double phi = (long double)w->k * ((long double)w->dir[0] * x +
                                                       (long double)w->dir[1] * z) -
                                  (long double)w->omega * t + (long double)w->phase;
                Y += (long double)w->amplitude * sinl(phi);
                X += (long double)(w->steepness * w->amplitude) * (long double)w->dir[0] *
                     cosl(phi);
            }
            ENSURE_NEAR(p[1], (double)Y, FAR_POINT_TOL);
            ENSURE_NEAR(p[0] + rx, (double)X, FAR_POINT_TOL);
        }
    }
    free(sc);
}

/* ---- the exact surface query ---- */

/* |X(rest) - x| recomputed from the reported rest point */
static double true_residual(const ww_scene *sc, const double *ph, double x, double z,
                            const ww_water_sample *o) {
    ww_wave_point p;
    ww_waves_point(sc, ph, o->rest[0], o->rest[1], 0.0, &p);
    return hypot(p.p[0] - x, p.p[2] - z);
}

TEST(water_inversion_converges_within_8_at_fold_margin_0_1) {
    /* fold margins 0.5, 0.2, 0.1 (sum Q k A = 0.5, 0.8, 0.9): every query reaches 1e-6 m */
    const double sums[] = {0.5, 0.8, 0.9};
    const int counts[] = {1, 2, 3, 8, 64};
    const ww_query_opts opts = {.tolerance = QUERY_RESIDUAL_TOL, .max_iterations = QUERY_MAX_IT};
    for (int si = 0; si < 3; si++) {
        long total = 0, queries = 0;
        int worst_it = 0;
        double worst_res = 0.0;
        for (int ci = 0; ci < 5; ci++) {
            for (int seed = 0; seed < 6; seed++) {
                ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
                random_sea(sc, counts[ci], 0.5, 40.0, sums[si], 1.0, 500 + (uint64_t)(seed * 7 + ci));
                double ph[WW_MAX_WAVES], t = 1.7 * seed;
                ww_waves_phases(sc, t, ph);
                ww_field f = {.sc = sc, .phase = ph, .t = t};
                for (int j = 0; j < 300; j++) {
                    double x = 40.0 * (j % 20) / 20.0 - 13.0, z = 40.0 * (j / 20) / 15.0 + 2.0;
                    ww_water_sample o;
                    int ok = ww_water_height(&f, x, z, &opts, &o);
                    ENSURE_MSG(ok && o.converged && o.iterations <= QUERY_MAX_IT,
                               "sum %.1f n %d seed %d at (%g, %g): residual %.3g after %d",
                               sums[si], counts[ci], seed, x, z, o.residual, o.iterations);
                    ENSURE_NEAR(true_residual(sc, ph, x, z, &o), 0.0, QUERY_RESIDUAL_TOL);
                    total += o.iterations;
                    queries++;
                    worst_it = o.iterations > worst_it ? o.iterations : worst_it;
                    worst_res = fmax(worst_res, o.residual);
                }
                free(sc);
            }
        }
        printf("    fold margin %.1f: %ld queries, mean %.2f evaluations, max %d, max residual "
               "%.2g m\n", 1.0 - sums[si], queries, (double)total / (double)queries, worst_it,
               worst_res);
    }
}

TEST(water_warm_start_agrees_with_cold_query_over_many_steps) {
    /* a 1 m box's 4 x 4 columns swept along a turning path over a steep sea (fold margin 0.1,
     * eight components) for 1200 steps of 1/120 s: each column's warm-started query (its warm
     * start carried from step to step as a system keeps it in its state) against the cold
     * query of the same point: the same height, normal and velocity within the tolerances,
     * converged, in fewer evaluations */
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    random_sea(sc, 8, 0.5, 40.0, 0.9, 1.0, 4242);
    ww_state *st = ww_state_new(sc);
    enum { SIDE = 4, NPTS = SIDE * SIDE, STEPS = 1200 };
    double warm[NPTS][WW_WARM_STRIDE] = {{0.0}};
    double dh = 0.0, dn = 0.0, dv = 0.0, worst_res = 0.0;
    long ev_warm = 0, ev_cold = 0;
    int all_converged = 1;
    for (int n = 0; n < STEPS; n++) {
        st->t = n / 120.0;
        ww_waves_phases(sc, st->t, st->wave_phase);
        double heading = 0.3 * st->t, cx = 2.0 + 1.5 * st->t, cz = -1.0 + sin(0.7 * st->t);
        double cs = cos(heading), sn = sin(heading);
        for (int p = 0; p < NPTS; p++) {
            double u = (p / SIDE + 0.5) / SIDE - 0.5, v = (p % SIDE + 0.5) / SIDE - 0.5;
            double x = cx + u * cs - v * sn, z = cz + u * sn + v * cs;
            ww_water_sample w, c;
            all_converged &= ww_water_at_warm(sc, st, x, z, 0.0, warm[p], &w);
            all_converged &= ww_water_at(sc, st, x, z, 0.0, &c);
            dh = fmax(dh, fabs(w.height - c.height));
            for (int k = 0; k < 3; k++) {
                dn = fmax(dn, fabs(w.normal[k] - c.normal[k]));
                dv = fmax(dv, fabs(w.velocity[k] - c.velocity[k]));
            }
            worst_res = fmax(worst_res, w.residual);
            ev_warm += w.iterations;
            ev_cold += c.iterations;
        }
    }
    printf("    %d queries: max |dh| %.2g m, |dn| %.2g, |dv| %.2g m/s; warm residual <= %.2g m; "
           "evaluations warm %.2f, cold %.2f a query\n",
           NPTS * STEPS, dh, dn, dv, worst_res, (double)ev_warm / (NPTS * STEPS),
           (double)ev_cold / (NPTS * STEPS));
    ENSURE(all_converged);
    ENSURE_NEAR(dh, 0.0, WARM_COLD_HEIGHT_TOL);
    ENSURE_NEAR(dn, 0.0, WARM_COLD_NORMAL_TOL);
    ENSURE_NEAR(dv, 0.0, WARM_COLD_VELOCITY_TOL);
    ENSURE(ev_warm < ev_cold);
    ww_state_free(st);
    free(sc);
}

TEST(water_steep_and_folding_seas_report_honestly) {
    /* margins 0.05 and 0 and a folding sea (sum 1.2): finite answers, the residual and the
     * converged flag true to the reported rest point, within the iteration cap */
    const double sums[] = {0.95, 1.0, 1.2};
    const int caps[] = {8, 32};
    for (int si = 0; si < 3; si++) {
        for (int ki = 0; ki < 2; ki++) {
            const ww_query_opts opts = {.tolerance = QUERY_RESIDUAL_TOL, .max_iterations = caps[ki]};
            int missed = 0, queries = 0, worst_it = 0;
            long total = 0;
            double worst = 0.0;
            for (int seed = 0; seed < 8; seed++) {
                ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
                random_sea(sc, 1 + seed % 4, 0.5, 40.0, sums[si], 1.0, 900 + (uint64_t)seed);
                double ph[WW_MAX_WAVES], total_amp = ww_waves_total_amplitude(sc);
                ww_waves_phases(sc, 0.3 * seed, ph);
                ww_field f = {.sc = sc, .phase = ph, .t = 0.3 * seed};
                for (int j = 0; j < 250; j++) {
                    double x = 0.173 * j - 20.0, z = 11.0 * sin(0.05 * j);
                    ww_water_sample o;
                    int ok = ww_water_height(&f, x, z, &opts, &o);
                    ENSURE(isfinite(o.height) && isfinite(o.residual));
                    ENSURE(fabs(o.height) <= total_amp);
                    ENSURE_NEAR(hypot(o.normal[0], hypot(o.normal[1], o.normal[2])), 1.0,
                                QUERY_CONSISTENCY_TOL);
                    ENSURE(o.normal[1] >= 0.0);
                    for (int c = 0; c < 3; c++) ENSURE(isfinite(o.velocity[c]));
                    ENSURE(o.iterations >= 1 && o.iterations <= caps[ki]);
                    ENSURE(ok == o.converged && o.converged == (o.residual <= QUERY_RESIDUAL_TOL));
                    ENSURE_NEAR(true_residual(sc, ph, x, z, &o), o.residual, QUERY_CONSISTENCY_TOL);
                    missed += !o.converged;
                    queries++;
                    total += o.iterations;
                    worst_it = o.iterations > worst_it ? o.iterations : worst_it;
                    if (!o.converged) worst = fmax(worst, o.residual);
                }
                free(sc);
            }
            printf("    sum Q k A %.2f, cap %2d: %d/%d not converged (worst residual %.2g m), "
                   "mean %.2f evaluations, max %d\n", sums[si], caps[ki], missed, queries, worst,
                   (double)total / queries, worst_it);
            /* below the fold the query still converges (more slowly) */
            if (sums[si] < 1.0 && caps[ki] == 32) ENSURE_EQ_INT(missed, 0);
        }
    }
    /* a cap that cannot be met is reported as such */
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    add_wave(sc, 30, 10, 0.5, 1.0, 1.0);
    double ph[1];
    ww_waves_phases(sc, 0.0, ph);
    ww_field f = {.sc = sc, .phase = ph};
    ww_water_sample o;
    const ww_query_opts one = {.max_iterations = 1};
    ENSURE_EQ_INT(ww_water_height(&f, 1.0, 2.0, &one, &o), 0);
    ENSURE(o.iterations == 1 && !o.converged && o.residual > WW_QUERY_TOLERANCE);
    ENSURE_NEAR(true_residual(sc, ph, 1.0, 2.0, &o), o.residual, QUERY_CONSISTENCY_TOL);
    free(sc);
}

TEST(water_inversion_agrees_with_brute_force_grid) {
    /* the rest point minimising |a + D(a) - x| over a fine grid around x (the root is within
     * sum Q A of x, and unique below the fold) against the query's */
    for (int seed = 0; seed < 2; seed++) {
        ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
        random_sea(sc, 4, 1.0, 30.0, 0.9, 1.0, 1200 + (uint64_t)seed);
        double ph[4], R = 0.0;
        for (int i = 0; i < sc->nwaves; i++) R += sc->waves[i].steepness * sc->waves[i].amplitude;
        ww_waves_phases(sc, 2.0, ph);
        ww_field f = {.sc = sc, .phase = ph, .t = 2.0};
        const int n = 500;
        double h = 2.0 * R / n; /* grid step, m */
        for (int q = 0; q < 3; q++) {
            double x = 3.1 * q - 2.0, z = 1.7 * q + 0.5, bx = x, bz = z, bres = INFINITY;
            for (int i = 0; i <= n; i++) {
                for (int j = 0; j <= n; j++) {
                    double ax = x - R + h * i, az = z - R + h * j, p[3];
                    ww_waves_eval(sc, ph, ax, az, p, NULL);
                    double r = hypot(p[0] - x, p[2] - z);
                    if (r < bres) {
                        bres = r;
                        bx = ax;
                        bz = az;
                    }
                }
            }
            ww_water_sample o;
            ENSURE(ww_water_height(&f, x, z, NULL, &o));
            /* |F| grows at least (1 - sum) |a - a*| and at most (1 + sum) |a - a*|: the grid's
             * best is within h (1 + sum) / (1 - sum) of the root */
            double grid_tol = h * 1.9 / 0.1;
            ENSURE_NEAR(o.rest[0], bx, grid_tol);
            ENSURE_NEAR(o.rest[1], bz, grid_tol);
            ENSURE(o.residual <= bres); /* and it is closer than any grid point */
        }
        free(sc);
    }
}

static void ripple_setup(ww_scene *sc) {
    sc->ripples_on = 1;
    sc->ripples = (ww_ripple_desc){.amplitude = 0.05, .lifetime = 10.0, .max = 4,
                                   .radial_decay = 0.1, .time_decay = 0.3, .wavenumber = 6.0,
                                   .speed = 1.2};
}

TEST(water_lanes_match_one_point_queries_to_the_bit) {
    /* ww_water_at_warm_n against ww_water_at_warm point by point: 13 points (a full lane block
     * and a padded one) of a turning 1.2 m box over a steep sea (fold margin 0.1, eight
     * components) with two ripples, and one point past the far-from-origin reference, for 600
     * steps of 1/120 s with their warm starts carried: the same height, velocity and warm start
     * to the bit, with every component and with those shorter than 5 m ignored (the lanes do
     * the one-point query's arithmetic; the points that leave the common path go through it) */
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    random_sea(sc, 8, 0.5, 40.0, 0.9, 1.0, 5151);
    ripple_setup(sc);
    ww_state *st = ww_state_new(sc);
    st->t = 0.2;
    ww_ripples_add(sc, st, 2.5, -0.5, 0.04);
    st->t = 1.1;
    ww_ripples_add(sc, st, 3.5, -1.5, 0.03);
    enum { NPTS = 13, STEPS = 600 };
    double wa[NPTS * WW_WARM_STRIDE] = {0.0}, wb[NPTS * WW_WARM_STRIDE] = {0.0};
    double wc[NPTS * WW_WARM_STRIDE] = {0.0}, wd[NPTS * WW_WARM_STRIDE] = {0.0};
    long differ = 0;
    for (int n = 0; n < STEPS; n++) {
        st->t = 1.5 + n / 120.0;
        ww_waves_phases(sc, st->t, st->wave_phase);
        double heading = 0.4 * st->t, cx = 2.0 + 1.5 * st->t, cz = -1.0 + sin(0.7 * st->t);
        double cs = cos(heading), sn = sin(heading), x[NPTS], z[NPTS], h[NPTS], v[3 * NPTS];
        for (int p = 0; p < NPTS; p++) {
            double u = 1.2 * ((p / 4 + 0.5) / 4 - 0.5), w = 1.2 * ((p % 4 + 0.5) / 4 - 0.5);
            x[p] = cx + u * cs - w * sn;
            z[p] = cz + u * sn + w * cs;
        }
        x[NPTS - 1] += 2000.0; /* far from the origin: the one-point path */
        ww_water_at_warm_n(sc, st, NPTS, x, z, 0.0, wa, h, v);
        for (int p = 0; p < NPTS; p++) {
            ww_water_sample o;
            ww_water_at_warm(sc, st, x[p], z[p], 0.0, wb + WW_WARM_STRIDE * p, &o);
            differ += memcmp(&o.height, &h[p], sizeof(double)) != 0;
            differ += memcmp(o.velocity, &v[3 * p], 3 * sizeof(double)) != 0;
        }
        differ += memcmp(wa, wb, sizeof wa) != 0;
        /* the boat's way: components shorter than 5 m ignored, no velocity wanted */
        double h5[NPTS];
        ww_water_at_warm_n(sc, st, NPTS, x, z, 5.0, wc, h5, NULL);
        for (int p = 0; p < NPTS; p++) {
            ww_water_sample o;
            ww_water_at_warm(sc, st, x[p], z[p], 5.0, wd + WW_WARM_STRIDE * p, &o);
            differ += memcmp(&o.height, &h5[p], sizeof(double)) != 0;
        }
        differ += memcmp(wc, wd, sizeof wc) != 0;
    }
    printf("    %d points x %d steps: %ld answers differ from the one-point query's bits\n", NPTS,
           STEPS, differ);
    ENSURE(differ == 0);
    ww_state_free(st);
    free(sc);
}

TEST(water_query_matches_surface_point_and_finite_differences) {
    /* every family with two ripples: the reported height, normal and velocity are the surface
     * at the reported rest point plus the ripples; the normal is the finite-difference normal
     * of the queried height field */
    for (int fi = 0; fi < NFAMILIES; fi++) {
        ww_scene *sc = family_sea(&FAMILIES[fi], 5, 40 + (uint64_t)fi);
        sc->water_level = 0.3;
        ripple_setup(sc);
        ww_state *st = ww_state_new(sc);
        st->t = 1.0;
        ww_ripples_add(sc, st, 1.0, -1.0, 0.04);
        st->t = 2.5;
        ww_ripples_add(sc, st, -2.0, 0.5, 0.03);
        double t = 4.0, ph[5], phm[5], php[5];
        ww_waves_phases(sc, t, ph);
        ww_waves_phases(sc, t - FD_STEP, phm);
        ww_waves_phases(sc, t + FD_STEP, php);
        ww_field f = {.sc = sc, .phase = ph, .t = t, .ripples = st->ripple};
        const ww_query_opts opts = {.tolerance = 1e-13};
        for (int j = 0; j < 12; j++) {
            double x = -3.0 + 0.55 * j, z = 1.5 - 0.35 * j;
            ww_water_sample o, xm, xp, zm, zp;
            ENSURE(ww_water_height(&f, x, z, &opts, &o));
            ww_wave_point p;
            ww_waves_point(sc, ph, o.rest[0], o.rest[1], 0.0, &p);
            double rg[2], rdt, rh = ww_ripples_height(sc, st->ripple, t, x, z, rg, &rdt);
            ENSURE(rh != 0.0);
            ENSURE_NEAR(o.height, p.p[1] + rh, QUERY_CONSISTENCY_TOL);
            ENSURE_NEAR(o.velocity[0], p.vel[0], QUERY_CONSISTENCY_TOL);
            ENSURE_NEAR(o.velocity[1], p.vel[1] + rdt, QUERY_CONSISTENCY_TOL);
            ENSURE_NEAR(o.velocity[2], p.vel[2], QUERY_CONSISTENCY_TOL);
            if (FAMILIES[fi].model != WW_WAVES_GERSTNER)
                ENSURE(o.rest[0] == x && o.rest[1] == z && o.iterations == 1);
            double h = QUERY_FD_STEP;
            ww_water_height(&f, x - h, z, &opts, &xm);
            ww_water_height(&f, x + h, z, &opts, &xp);
            ww_water_height(&f, x, z - h, &opts, &zm);
            ww_water_height(&f, x, z + h, &opts, &zp);
            double n[3] = {-(xp.height - xm.height) / (2 * h), 1.0,
                           -(zp.height - zm.height) / (2 * h)};
            ww_m_normalize3(n);
            for (int c = 0; c < 3; c++) ENSURE_NEAR(o.normal[c], n[c], QUERY_NORMAL_FD_TOL);
            /* without sideways motion the surface velocity is dh/dt at the world point */
            if (FAMILIES[fi].model != WW_WAVES_GERSTNER) {
                ww_field fm = f, fp = f;
                fm.phase = phm;
                fm.t = t - FD_STEP;
                fp.phase = php;
                fp.t = t + FD_STEP;
                ww_water_sample tm, tp;
                ww_water_height(&fm, x, z, &opts, &tm);
                ww_water_height(&fp, x, z, &opts, &tp);
                ENSURE_NEAR(o.velocity[1], (tp.height - tm.height) / (2 * FD_STEP), VELOCITY_FD_TOL);
            }
        }
        ww_state_free(st);
        free(sc);
    }
}

TEST(water_query_min_wavelength_ignores_short_components) {
    ww_scene *all = new_scene(WW_WAVES_GERSTNER), *lng = new_scene(WW_WAVES_GERSTNER);
    random_sea(all, 10, 0.5, 50, 0.7, 1.0, 21);
    double ph[10], phl[10];
    ww_waves_phases(all, 3.0, ph);
    lng->nwaves = 0;
    for (int i = 0; i < all->nwaves; i++)
        if (all->waves[i].wavelength >= 5.0) {
            phl[lng->nwaves] = ph[i];
            lng->waves[lng->nwaves++] = all->waves[i];
        }
    ENSURE(lng->nwaves > 0 && lng->nwaves < all->nwaves);
    ww_field fa = {.sc = all, .phase = ph, .t = 3.0}, fl = {.sc = lng, .phase = phl, .t = 3.0};
    const ww_query_opts skip = {.min_wavelength = 5.0};
    for (int j = 0; j < 10; j++) {
        ww_water_sample a, b, c;
        ENSURE(ww_water_height(&fa, 1.1 * j, -0.7 * j, &skip, &a));
        ENSURE(ww_water_height(&fl, 1.1 * j, -0.7 * j, NULL, &b));
        ENSURE(ww_water_height(&fa, 1.1 * j, -0.7 * j, NULL, &c));
        ENSURE(a.height == b.height && a.normal[1] == b.normal[1] && a.velocity[1] == b.velocity[1]);
        ENSURE(a.height != c.height);
    }
    free(all);
    free(lng);
}

TEST(water_query_hard_cases) {
    /* 1 and 256 components, wavelengths 0.01 m and 1000 m together, t = 1e6 s, the folding limit:
     * finite, bounded answers whose converged flag is true to the residual */
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    for (int kind = 0; kind < 4; kind++) {
        sc->nwaves = 0;
        if (kind == 0) add_wave(sc, 10, 7.0, 0.5, 0.8, 1.0);
        if (kind == 1) random_sea(sc, 256, 0.3, 300.0, 0.9, 1.0, 31);
        if (kind == 2) {
            add_wave(sc, 20, 0.01, 0.01 / WW_TAU * 0.3, 1.0, 1.0);
            add_wave(sc, 200, 1000.0, 1000.0 / WW_TAU * 0.5, 1.0, 1.0);
        }
        if (kind == 3) add_wave(sc, 45, 5.0, 5.0 / WW_TAU, 1.0, 1.0); /* Q k A = 1: cusps */
        double ph[WW_MAX_WAVES], amp = ww_waves_total_amplitude(sc);
        const double times[] = {0.0, 1e6};
        for (int ti = 0; ti < 2; ti++) {
            ww_waves_phases(sc, times[ti], ph);
            ww_field f = {.sc = sc, .phase = ph, .t = times[ti]};
            int missed = 0, most = 0;
            for (int j = 0; j < 200; j++) {
                double x = 0.0137 * j * (kind == 2 ? 10.0 : 1.0) - 1.0, z = 0.021 * j;
                ww_water_sample o;
                ww_water_height(&f, x, z, NULL, &o);
                ENSURE(isfinite(o.height) && fabs(o.height) <= amp);
                ENSURE(isfinite(o.normal[0]) && isfinite(o.normal[1]) && isfinite(o.normal[2]));
                ENSURE(o.converged == (o.residual <= WW_QUERY_TOLERANCE));
                ENSURE_NEAR(true_residual(sc, ph, x, z, &o), o.residual, QUERY_CONSISTENCY_TOL);
                if (kind < 3) ENSURE(o.converged);
                missed += !o.converged;
                most = o.iterations > most ? o.iterations : most;
            }
            printf("    hard case %d at t = %g: %d/200 not converged to 1e-9 m, max %d evaluations\n",
                   kind, times[ti], missed, most);
        }
    }
    free(sc);
}

TEST(water_query_far_from_origin) {
    /* |x| = 1e5 m at t = 1e6 s: the reported point lies on the surface computed in long double
     * from the raw parameters */
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    random_sea(sc, 12, 0.5, 200.0, 0.8, 1.0, 61);
    double t = 1e6, ph[12];
    ww_waves_phases(sc, t, ph);
    ww_field f = {.sc = sc, .phase = ph, .t = t};
    const double at[][2] = {{1e5, 3.25}, {-1e5, 1e5}, {512.5, -99999.75}};
    for (int q = 0; q < 3; q++) {
        ww_water_sample o;
        ENSURE(ww_water_height(&f, at[q][0], at[q][1], NULL, &o));
        long double X = o.rest[0], Y = 0.0L, Z = o.rest[1];
        for (int i = 0; i < sc->nwaves; i++) {
            const ww_wave *w = &sc->waves[i];
            long double phi = (long double)w->k * ((long double)w->dir[0] * o.rest[0] +
                                                   (long double)w->dir[1] * o.rest[1]) -
                              (long double)w->omega * t + (long double)w->phase;
            long double qa = (long double)(w->steepness * w->amplitude);
            X += qa * (long double)w->dir[0] * cosl(phi);
            Z += qa * (long double)w->dir[1] * cosl(phi);
            Y += (long double)w->amplitude * sinl(phi);
        }
        ENSURE_NEAR((double)(X - at[q][0]), 0.0, QUERY_FAR_TOL);
        ENSURE_NEAR((double)(Z - at[q][1]), 0.0, QUERY_FAR_TOL);
        ENSURE_NEAR(o.height, (double)Y, QUERY_FAR_TOL);
    }
    free(sc);
}

/* ---- ripples ---- */

TEST(ripples_gradient_and_rate_match_finite_differences) {
    ww_scene *sc = new_scene(WW_WAVES_FLAT);
    ripple_setup(sc);
    ww_state *st = ww_state_new(sc);
    st->t = 0.5;
    ww_ripples_add(sc, st, 0.0, 0.0, 0.05);
    st->t = 1.0;
    ww_ripples_add(sc, st, 1.5, -0.5, 0.02);
    double t = 3.0, h = FD_STEP;
    int inside = 0;
    for (int j = 0; j < 60; j++) {
        /* points behind, inside and ahead of the fronts (v age = 3 m and 2.4 m) */
        double x = -6.0 + 0.2 * j, z = 0.3 - 0.05 * j, g[2], dt;
        double v = ww_ripples_height(sc, st->ripple, t, x, z, g, &dt);
        double gx = (ww_ripples_height(sc, st->ripple, t, x + h, z, NULL, NULL) -
                     ww_ripples_height(sc, st->ripple, t, x - h, z, NULL, NULL)) / (2 * h);
        double gz = (ww_ripples_height(sc, st->ripple, t, x, z + h, NULL, NULL) -
                     ww_ripples_height(sc, st->ripple, t, x, z - h, NULL, NULL)) / (2 * h);
        double gt = (ww_ripples_height(sc, st->ripple, t + h, x, z, NULL, NULL) -
                     ww_ripples_height(sc, st->ripple, t - h, x, z, NULL, NULL)) / (2 * h);
        ENSURE_NEAR(g[0], gx, RIPPLE_FD_TOL);
        ENSURE_NEAR(g[1], gz, RIPPLE_FD_TOL);
        ENSURE_NEAR(dt, gt, RIPPLE_FD_TOL);
        inside += v != 0.0;
    }
    ENSURE(inside > 10 && inside < 60); /* the front is crossed */
    ww_state_free(st);
    free(sc);
}

TEST(ripples_pool_replaces_oldest_and_prunes) {
    ww_scene *sc = new_scene(WW_WAVES_FLAT);
    ripple_setup(sc);
    ww_state *st = ww_state_new(sc);
    for (int i = 0; i < 6; i++) {
        st->t = i;
        ww_ripples_add(sc, st, i, 0.0, 0.01);
    }
    ENSURE_EQ_INT(ww_ripples_count(sc, st), 4);
    /* the two oldest (t0 = 0, 1) were replaced */
    for (int i = 0; i < 4; i++) ENSURE(st->ripple[i * WW_RIPPLE_STRIDE + 2] >= 2.0);
    st->t = 13.5; /* ages 11.5, 10.5, 9.5, 8.5 against a lifetime of 10 */
    ww_ripples_prune(sc, st);
    ENSURE_EQ_INT(ww_ripples_count(sc, st), 2);
    ww_ripples_add(sc, st, 0.0, 0.0, 0.0); /* no amplitude: nothing added */
    ENSURE_EQ_INT(ww_ripples_count(sc, st), 2);
    /* a ripple has no effect before it starts */
    double g[2], dt;
    ENSURE(ww_ripples_height(sc, st->ripple, 1.0, 4.0, 0.0, g, &dt) == 0.0 && g[0] == 0.0);
    ww_state_free(st);
    free(sc);
}

/* the pool's ripple_slots: every slot from it on is free after each add and prune, so that
 * prune (and every query) reads only the slots below it; prune leaves the pool as a prune of
 * every slot would. Random adds at random times into a pool of 4 with a lifetime of 10 s */
TEST(ripples_slots_cover_every_live_ripple) {
    ww_scene *sc = new_scene(WW_WAVES_FLAT);
    ripple_setup(sc);
    ww_state *st = ww_state_new(sc);
    ww_rng r;
    ww_rng_seed(&r, 3, 0);
    int max = sc->ripples.max, bad = 0, live_seen = 0;
    double t = 0.0;
    for (int i = 0; i < 400; i++) {
        t += 12.0 * ww_rng_uniform(&r) * ww_rng_uniform(&r);
        st->t = t;
        if (ww_rng_uniform(&r) < 0.5) {
            ww_ripples_add(sc, st, ww_rng_uniform(&r), ww_rng_uniform(&r), 0.01);
        } else {
            /* the reference: every slot whose ripple has outlived the lifetime freed */
            double want[16 * WW_RIPPLE_STRIDE];
            memcpy(want, st->ripple, sizeof(double) * (size_t)(max * WW_RIPPLE_STRIDE));
            for (int s = 0; s < max; s++) {
                double *e = want + s * WW_RIPPLE_STRIDE;
                if (e[3] != 0.0 && t - e[2] > sc->ripples.lifetime) e[0] = e[1] = e[2] = e[3] = 0.0;
            }
            ww_ripples_prune(sc, st);
            bad += memcmp(want, st->ripple, sizeof(double) * (size_t)(max * WW_RIPPLE_STRIDE)) != 0;
            int top = 0;
            for (int s = 0; s < max; s++) top = want[s * WW_RIPPLE_STRIDE + 3] != 0.0 ? s + 1 : top;
            bad += st->ripple_slots[0] != top;
        }
        for (int s = st->ripple_slots[0]; s < max; s++)
            bad += st->ripple[s * WW_RIPPLE_STRIDE + 3] != 0.0;
        live_seen += ww_ripples_count(sc, st) > 0 && ww_ripples_count(sc, st) < max;
    }
    ENSURE_EQ_INT(bad, 0);
    ENSURE(live_seen > 50);
    ww_state_free(st);
    free(sc);
}

/* ---- statistics ---- */

TEST(wave_stats_single_sine) {
    ww_scene *sc = new_scene(WW_WAVES_SINES);
    add_wave(sc, 30, 12.0, 0.4, 0.0, 1.0);
    ww_wave_stats st;
    ww_wave_stats_compute(sc, 0, 0, &st);
    const ww_wave *w = &sc->waves[0];
    ENSURE_EQ_INT(st.count, 1);
    ENSURE_EQ_INT(st.samples, 64 * 64 * 8);
    ENSURE_NEAR(st.m0, 0.4 * 0.4 / 2, STATS_EXACT_TOL);
    ENSURE_NEAR(st.hs, 4.0 * sqrt(0.4 * 0.4 / 2), STATS_EXACT_TOL);
    ENSURE_NEAR(st.peak_period, sqrt(WW_TAU * 12.0 / WW_G), STATS_EXACT_TOL);
    ENSURE_NEAR(st.mean_wavelength, 12.0, STATS_EXACT_TOL);
    ENSURE(st.fold_margin == 1.0 && st.fold_sum == 0.0);
    ENSURE_NEAR(st.slope_bound, w->k * 0.4, STATS_EXACT_TOL);
    ENSURE(st.max_slope <= st.slope_bound);
    ENSURE_NEAR(st.max_slope / st.slope_bound, 1.0, STATS_SAMPLE_REL_TOL);
    ENSURE_NEAR(st.total_amplitude, 0.4, STATS_EXACT_TOL);
    free(sc);
}

TEST(wave_stats_sea_of_sines_adds_variances) {
    ww_scene *sc = new_scene(WW_WAVES_SINES);
    random_sea(sc, 9, 1.0, 30.0, 0.5, 1.0, 8);
    ww_wave_stats st;
    ww_wave_stats_compute(sc, 16, 2, &st);
    double m0 = 0.0, lw = 0.0, top = 0.0, tp = 0.0;
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        m0 += w->amplitude * w->amplitude / 2;
        lw += w->amplitude * w->amplitude / 2 * w->wavelength;
        if (w->amplitude > top) {
            top = w->amplitude;
            tp = WW_TAU / w->omega;
        }
    }
    ENSURE_EQ_INT(st.samples, 16 * 16 * 2);
    ENSURE_NEAR(st.hs, 4.0 * sqrt(m0), STATS_EXACT_TOL);
    ENSURE_NEAR(st.mean_wavelength, lw / m0, STATS_EXACT_TOL);
    ENSURE_NEAR(st.peak_period, tp, STATS_EXACT_TOL);
    ENSURE(st.max_slope <= st.slope_bound && st.max_slope > 0.0);
    free(sc);
}

TEST(wave_stats_single_gerstner_fold_margin) {
    const double dirs[] = {0.0, 30.0, 117.0};
    for (int d = 0; d < 3; d++) {
        ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
        add_wave(sc, dirs[d], 8.0, 0.5, 0.9, 1.0);
        const ww_wave *w = &sc->waves[0];
        double qka = 0.9 * w->k * 0.5, ka = w->k * 0.5;
        ww_wave_stats st;
        ww_wave_stats_compute(sc, 0, 0, &st);
        ENSURE_NEAR(st.fold_sum, qka, STATS_EXACT_TOL);
        ENSURE_NEAR(st.fold_sum, ww_waves_fold_sum(sc), STATS_EXACT_TOL);
        /* J = 1 - Q k A sin(phi): the margin 1 - Q k A, sampled */
        ENSURE(st.fold_margin >= 1.0 - qka - STATS_EXACT_TOL);
        ENSURE_NEAR(st.fold_margin, 1.0 - qka, STATS_SAMPLE_REL_TOL * qka);
        /* slope k A cos / (1 - Q k A sin), its largest value found by a fine scan */
        double top = 0.0;
        for (int i = 0; i < 100000; i++) {
            double ph = WW_TAU * i / 100000;
            top = fmax(top, fabs(ka * cos(ph) / (1.0 - qka * sin(ph))));
        }
        ENSURE(st.max_slope <= top * (1.0 + STATS_EXACT_TOL) && st.max_slope <= st.slope_bound);
        ENSURE_NEAR(st.max_slope / top, 1.0, STATS_SAMPLE_REL_TOL);
        ENSURE_NEAR(st.slope_bound, ka / (1.0 - qka), STATS_EXACT_TOL);
        if (ww_test_failed_now())
            printf("    direction %g: margin %.6f (1 - QkA = %.6f), slope %.6f of %.6f\n", dirs[d],
                   st.fold_margin, 1.0 - qka, st.max_slope, top);
        free(sc);
    }
}

TEST(wave_stats_steep_sines_closed_form) {
    const double es[] = {1.0, 2.0, 5.5};
    for (int k = 0; k < 3; k++) {
        ww_scene *sc = new_scene(WW_WAVES_STEEP_SINES);
        add_wave(sc, 50, 6.0, 0.3, 0.0, es[k]);
        const ww_wave *w = &sc->waves[0];
        /* the profile's variance and largest |dh/dphi| by quadrature over a period */
        const int n = 4096;
        double s1 = 0.0, s2 = 0.0, dmax = 0.0;
        for (int i = 0; i < n; i++) {
            double ph = WW_TAU * i / n, u = 0.5 * (sin(ph) + 1.0);
            double h = 2.0 * 0.3 * (pow(u, es[k]) - w->mean);
            s1 += h / n;
            s2 += h * h / n;
        }
        for (int i = 0; i < 1000000; i++) {
            double ph = WW_TAU * i / 1000000, u = 0.5 * (sin(ph) + 1.0);
            dmax = fmax(dmax, fabs(0.3 * es[k] * pow(u, es[k] - 1.0) * cos(ph)));
        }
        ww_wave_stats st;
        ww_wave_stats_compute(sc, 0, 0, &st);
        ENSURE_NEAR(st.m0, s2 - s1 * s1, STEEP_VARIANCE_TOL);
        if (es[k] == 1.0) ENSURE_NEAR(st.m0, 0.3 * 0.3 / 2, STATS_EXACT_TOL);
        ENSURE_NEAR(st.slope_bound / (w->k * dmax), 1.0, STEEP_SLOPE_SCAN_TOL);
        ENSURE(st.max_slope <= st.slope_bound && st.fold_margin == 1.0);
        ENSURE_NEAR(st.max_slope / st.slope_bound, 1.0, STATS_SAMPLE_REL_TOL);
        /* the largest excursion: 2 A (1 - mean) above the level */
        ENSURE_NEAR(st.total_amplitude, 2.0 * 0.3 * (1.0 - w->mean), STATS_EXACT_TOL);
        free(sc);
    }
}

TEST(wave_stats_folding_flat_and_spectrum) {
    ww_scene *sc = new_scene(WW_WAVES_GERSTNER);
    random_sea(sc, 5, 2.0, 20.0, 1.2, 1.0, 4);
    ww_wave_stats st;
    ww_wave_stats_compute(sc, 32, 4, &st);
    ENSURE_NEAR(st.fold_sum, 1.2, STATS_EXACT_TOL);
    ENSURE(st.fold_margin < 1.0 - 1.2 + 0.5 && isinf(st.slope_bound) && isfinite(st.max_slope));
    sc->wave_model = WW_WAVES_FLAT;
    ww_wave_stats_compute(sc, 0, 0, &st);
    ENSURE(st.count == 0 && st.hs == 0.0 && st.fold_margin == 1.0 && st.max_slope == 0.0);
    free(sc);

    /* Pierson-Moskowitz at U = 10 m/s: the peak of spectrum.h, Hs ~ 0.21 U^2 / g */
    sc = new_scene(WW_WAVES_SPECTRUM);
    sc->spectrum = (ww_spectrum_desc){.kind = WW_SPECTRUM_PM, .wind_speed = 10.0, .count = 128,
                                      .wavelength = {1.0, 2000.0}, .steepness = 0.5,
                                      .spread = 0.3, .fetch = 1e5, .gamma = 3.3};
    sc->nwaves = sc->spectrum.count;
    ww_spectrum_sample(&sc->spectrum, 5, sc->waves);
    ww_wave_stats_compute(sc, 16, 2, &st);
    ENSURE_NEAR(st.peak_period, WW_TAU / (0.877 * WW_G / 10.0), PM_PEAK_REL_TOL * st.peak_period);
    ENSURE_NEAR(st.hs / (0.21 * 100.0 / WW_G), 1.0, PM_HS_REL_TOL);
    ENSURE_NEAR(st.fold_sum, 0.5, STATS_EXACT_TOL);
    printf("    PM U = 10 m/s, 128 components: Hs %.4f m (0.21 U^2/g = %.4f), peak period %.4f s\n",
           st.hs, 0.21 * 100.0 / WW_G, st.peak_period);
    /* the spectrum's components are Gerstner waves: the query inverts them too */
    double ph[128];
    ww_waves_phases(sc, 10.0, ph);
    ww_field f = {.sc = sc, .phase = ph, .t = 10.0};
    const ww_query_opts opts = {.tolerance = QUERY_RESIDUAL_TOL, .max_iterations = QUERY_MAX_IT};
    for (int j = 0; j < 50; j++) {
        ww_water_sample o;
        ENSURE(ww_water_height(&f, 1.7 * j, -0.9 * j, &opts, &o));
        ENSURE(fabs(o.height) <= ww_waves_total_amplitude(sc));
    }
    free(sc);
}
