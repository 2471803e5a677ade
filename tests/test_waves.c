/* test_waves.c - the accuracy oracles of every wave family: sincos against libm, dispersion,
 * analytic partials, normals and velocities against finite differences, batch against scalar,
 * far points against a long double evaluation, the exact height query (Gerstner inversion against
 * a brute-force search, hard cases), ripples, and the wave statistics against closed forms.
 * Scenes are built from ww_scene_defaults() with fields set directly (no YAML).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "core/rng.h"
#include "core/sincos.h"
#include "sim/waves.h"
#include "test.h"

/* ww_sincos against libm: fdlibm's kernels after a 3-part Cody-Waite reduction, |x| <= 1e5 */
#define SINCOS_TOL 1e-15
/* ww_sincosf against libm in double, |x| <= 1e3: a couple of float ulps of 1 */
#define SINCOSF_TOL 2e-7
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
/* batch (ww_sincos) against scalar (libm) in double, m: 1e-16 per component value, summed */
#define BATCH_SCALAR_TOL 1e-12
/* the same model evaluated two equivalent ways (steep sines e = 1 against sines), m */
#define SAME_MODEL_TOL 1e-14
/* relative evaluation at 1e5 m against long double from the raw parameters, m: the double
 * phase of the origin at t (omega t ~ 1e6 rad rounds to ~1e-10 rad) times k A */
#define FAR_POINT_TOL 1e-9

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
                    ENSURE_NEAR(pos[c][j], pd[c], BATCH_SCALAR_TOL);
                    ENSURE_NEAR(nor[c][j], nd[c], BATCH_SCALAR_TOL);
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
