/* test_picture_caustics.c - caustics measured on rendered frames: a statistic of the light the
 * caustics add to the seabed (the frame with caustics on minus the same frame with them off),
 * against thresholds named for what they allow. Each test prints its figures.
 *   plaid      the analytic caustics 10 m down, seen straight from above, are a web: the power
 *              spectrum of their pattern has no isolated peak standing far above the rest
 *   texture    water.look.caustics.method texture (scenes/features/caustics_texture.yaml): the
 *              caustics show, move, loop over the set's period, and light the seabed as brightly
 *              on average as the analytic method
 *   objects    both methods light the fish and the cubes' submerged sides, not the seabed alone
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/caustic_set.h"
#include "io/image.h"
#include "io/writers.h"
#include "test.h"

/* Hann-windowed power spectrum of the caustics' light 10 m down, straight from above: its
 * largest bin over the median of the bins as far from 0 (the other directions of the same
 * wavelength). The plaid of the two detail sines that outlast the sun's blur measured 8.5e5 (a
 * few beat frequencies hold nearly all the power); with the water's DuDv ripples focusing too,
 * 106 */
#define PLAID_PEAK_MEDIAN_MAX 2000.0
#define PLAID_N 256            /* the frame, square, px */
#define PLAID_LOW_BINS 3       /* bins this close to 0 (the mean and the gradient) are left out */
#define TEX_VISIBLE_MIN 6.0    /* mean 8-bit levels the texture caustics move the seabed, at least */
#define TEX_ANIMATED_MIN 2.0   /* ... by which frames 0 and 15 differ, at least */
#define TEX_LOOP_CORR_MIN 0.95 /* correlation of the caustics' light in frames 0 and 120 (one
                                * loop, 4 s), at least: the pattern comes back. Not a difference:
                                * the column of water over the camera, which the waves move,
                                * scales all the sunlight on the seabed a little from frame to
                                * frame, caustics or not, and shifts the point a pixel's sun ray
                                * left the surface from a little (the fish move too): 0.969 */
#define TEX_MEAN_MAX 7.0       /* 8-bit levels between the seabed's mean luminance with the
                                * texture caustics and with the analytic ones, at most. The set
                                * moves light without making any (mean 1), but the tone curve
                                * clips its brightest lines: 3.4 levels under caustics off; the
                                * analytic 1 / |det J| at one preimage brightens on average:
                                * 2.6 levels over */
#define WW_TEST_PI 3.14159265358979323846
#define TEX_W 320
#define TEX_H 180
#define SEABED_TOP 0.4         /* the seabed fills the frame below this share of its height */
#define OBJECT_LEVELS 2.0      /* 8-bit levels the caustics must move a pixel of an object ... */
#define OBJECT_PIXELS_MIN 150  /* ... in this many pixels at least (fish and cubes under water) */
#define OBJECT_W 640           /* the objects are small: a larger frame */
#define OBJECT_H 360

typedef struct img {
    ww_image im;
    int ok;
} img;

static img render_at(const char *scene, int frame, const char *args, const char *tag, int w, int h) {
    img r = {0};
    char dir[512], c[4096], path[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(tag));
    snprintf(c, sizeof c, "%s render %s --frames %d:%d --size %dx%d -o %s --quiet %s", ww_test_bin(),
             scene, frame, frame + 1, w, h, dir, args ? args : "");
    int rc = ww_test_run(c, NULL, NULL);
    ENSURE_MSG(rc == 0, "%s: exit %d", c, rc);
    if (rc != 0) return r;
    snprintf(path, sizeof path, "%s/frame_%05d.png", dir, frame);
    ww_error err = {0};
    r.ok = ww_read_png(path, &r.im, &err) == WW_OK && r.im.u8 && r.im.width == w && r.im.height == h &&
           r.im.channels >= 3;
    ENSURE_MSG(r.ok, "%s: %s", path, err.msg);
    return r;
}

static double luma(const img *a, int x, int y) {
    const unsigned char *p = ww_test_pixel(&a->im, x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/* the caustics' share of the luminance, on minus off, over rows y0.. of frames w x h; NULL when
 * a render failed */
static double *caustic_light(const char *scene, int frame, const char *args, const char *tag,
                             int w, int h, int y0) {
    char on_tag[96], off_tag[96], off_args[1024];
    snprintf(on_tag, sizeof on_tag, "%s_on", tag);
    snprintf(off_tag, sizeof off_tag, "%s_off", tag);
    snprintf(off_args, sizeof off_args, "%s --set water.look.caustics=false", args ? args : "");
    img on = render_at(scene, frame, args, on_tag, w, h);
    img off = render_at(scene, frame, off_args, off_tag, w, h);
    double *d = NULL;
    if (on.ok && off.ok && (d = malloc((size_t)w * (size_t)(h - y0) * sizeof *d)))
        for (int y = y0; y < h; y++)
            for (int x = 0; x < w; x++) d[(size_t)(y - y0) * w + x] = luma(&on, x, y) - luma(&off, x, y);
    ww_image_free(&on.im);
    ww_image_free(&off.im);
    return d;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the 2D DFT power of n x n real d (Hann-windowed, mean removed), by rows then columns */
static double *power_spectrum(const double *d, int n) {
    double *re = calloc((size_t)n * n, sizeof *re), *im = calloc((size_t)n * n, sizeof *im);
    double *tr = calloc((size_t)n * n, sizeof *tr), *ti = calloc((size_t)n * n, sizeof *ti);
    double *cs = malloc((size_t)n * sizeof *cs), *sn = malloc((size_t)n * sizeof *sn);
    double *p = malloc((size_t)n * n * sizeof *p);
    if (!re || !im || !tr || !ti || !cs || !sn || !p) {
        free(p);
        p = NULL;
        goto done;
    }
    double mean = 0.0;
    for (int i = 0; i < n * n; i++) mean += d[i];
    mean /= (double)n * n;
    for (int k = 0; k < n; k++) {
        cs[k] = cos(2.0 * WW_TEST_PI * k / n);
        sn[k] = sin(2.0 * WW_TEST_PI * k / n);
    }
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            double wx = 0.5 - 0.5 * cs[x], wy = 0.5 - 0.5 * cs[y];
            re[y * n + x] = (d[y * n + x] - mean) * wx * wy;
        }
    /* rows */
    for (int y = 0; y < n; y++)
        for (int u = 0; u < n; u++) {
            double a = 0.0, b = 0.0;
            for (int x = 0; x < n; x++) {
                int k = (u * x) % n;
                a += re[y * n + x] * cs[k];
                b -= re[y * n + x] * sn[k];
            }
            tr[y * n + u] = a;
            ti[y * n + u] = b;
        }
    /* columns */
    for (int u = 0; u < n; u++)
        for (int v = 0; v < n; v++) {
            double a = 0.0, b = 0.0;
            for (int y = 0; y < n; y++) {
                int k = (v * y) % n;
                a += tr[y * n + u] * cs[k] + ti[y * n + u] * sn[k];
                b += ti[y * n + u] * cs[k] - tr[y * n + u] * sn[k];
            }
            p[v * n + u] = a * a + b * b;
        }
done:
    free(re);
    free(im);
    free(tr);
    free(ti);
    free(cs);
    free(sn);
    return p;
}

/* the largest ratio of a bin to the median of its ring (bins at the same distance from 0,
 * rounded; frequencies wrapped), over rings PLAID_LOW_BINS + 1 .. n / 2: an isolated peak stands
 * far above the other directions of its wavelength, where a web's power spreads over them */
static double peak_over_ring_median(const double *p, int n) {
    int rings = n / 2 + 1;
    double *b = malloc((size_t)n * n * sizeof *b), *med = calloc((size_t)rings, sizeof *med);
    long *cnt = calloc((size_t)rings, sizeof *cnt);
    double most = INFINITY;
    if (!b || !med || !cnt) goto done;
    most = 0.0;
    for (int r = PLAID_LOW_BINS + 1; r < rings; r++) {
        long m = 0;
        for (int v = 0; v < n; v++)
            for (int u = 0; u < n; u++) {
                int fu = u <= n / 2 ? u : n - u, fv = v <= n / 2 ? v : n - v;
                if ((int)lround(sqrt((double)(fu * fu + fv * fv))) == r) b[m++] = p[v * n + u];
            }
        qsort(b, (size_t)m, sizeof *b, cmp_double);
        double md = b[m / 2];
        if (md > 0.0 && b[m - 1] / md > most) most = b[m - 1] / md;
    }
done:
    free(b);
    free(med);
    free(cnt);
    return most;
}

/* the analytic caustics 10 m down under the reef's swells (tests/data/caustics_down.yaml),
 * looking straight down from 9 m above the seabed */
TEST_IMAGE(picture_caustics_analytic_web_not_plaid) {
    REQUIRE_GL();
    double *d = caustic_light("tests/data/caustics_down.yaml", 0, NULL, "pc_plaid", PLAID_N,
                              PLAID_N, 0);
    ENSURE(d != NULL);
    if (!d) return;
    double rms = 0.0;
    for (int i = 0; i < PLAID_N * PLAID_N; i++) rms += d[i] * d[i];
    rms = sqrt(rms / ((double)PLAID_N * PLAID_N));
    double *p = power_spectrum(d, PLAID_N);
    ENSURE(p != NULL);
    double r = p ? peak_over_ring_median(p, PLAID_N) : INFINITY;
    printf("  caustics 10 m down: RMS %.2f levels; spectrum peak / its ring's median %.3g\n", rms, r);
    ENSURE_MSG(rms > 1.0, "the caustics barely show (RMS %.2f levels)", rms);
    ENSURE_MSG(r <= ww_test_tol(PLAID_PEAK_MEDIAN_MAX), "a plaid: spectrum peak / median %.3g > %.3g",
               r, ww_test_tol(PLAID_PEAK_MEDIAN_MAX));
    free(p);
    free(d);
}

/* mean |a - b| over n values */
static double mean_abs_diff(const double *a, const double *b, long n) {
    double s = 0.0;
    for (long i = 0; i < n; i++) s += fabs(a[i] - (b ? b[i] : 0.0));
    return s / (double)n;
}

/* the correlation coefficient of a and b over n values */
static double correlation(const double *a, const double *b, long n) {
    double ma = 0.0, mb = 0.0, ab = 0.0, aa = 0.0, bb = 0.0;
    for (long i = 0; i < n; i++) {
        ma += a[i];
        mb += b[i];
    }
    ma /= (double)n;
    mb /= (double)n;
    for (long i = 0; i < n; i++) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return aa > 0.0 && bb > 0.0 ? ab / sqrt(aa * bb) : 0.0;
}

/* the texture caustics show, move from frame to frame, and come back after the set's loop */
TEST_IMAGE(picture_caustics_texture_seen_animated_looping) {
    REQUIRE_GL();
    const char *scene = "scenes/features/caustics_texture.yaml";
    int y0 = (int)(TEX_H * SEABED_TOP);
    int loop = (int)lround(WW_CAUSTIC_SET_PERIOD * 30.0); /* the scene's 30 frames per second */
    double *d0 = caustic_light(scene, 0, NULL, "pc_tex0", TEX_W, TEX_H, y0);
    double *d15 = caustic_light(scene, 15, NULL, "pc_tex15", TEX_W, TEX_H, y0);
    double *dl = caustic_light(scene, loop, NULL, "pc_texloop", TEX_W, TEX_H, y0);
    ENSURE(d0 && d15 && dl);
    if (d0 && d15 && dl) {
        long n = (long)TEX_W * (TEX_H - y0);
        double seen = mean_abs_diff(d0, NULL, n), moved = mean_abs_diff(d0, d15, n);
        double looped = correlation(d0, dl, n), c15 = correlation(d0, d15, n);
        printf("  texture caustics move the seabed by %.2f levels; frames 0 and 15 differ by %.2f "
               "(correlation %.3f), 0 and %d correlate %.4f (mean difference %.2f)\n", seen, moved,
               c15, loop, looped, mean_abs_diff(d0, dl, n));
        ENSURE_MSG(seen >= ww_test_tol(TEX_VISIBLE_MIN), "unseen: %.2f", seen);
        ENSURE_MSG(moved >= ww_test_tol(TEX_ANIMATED_MIN), "still: %.2f", moved);
        ENSURE_MSG(looped >= TEX_LOOP_CORR_MIN, "no loop: correlation %.4f", looped);
    }
    free(d0);
    free(d15);
    free(dl);
}

/* the mean luminance of the seabed's rows, frame 0 of scene with args */
static double seabed_mean(const char *scene, const char *args, const char *tag, double *sd) {
    img a = render_at(scene, 0, args, tag, TEX_W, TEX_H);
    double s = 0.0, s2 = 0.0;
    long n = 0;
    if (a.ok)
        for (int y = (int)(TEX_H * SEABED_TOP); y < TEX_H; y++)
            for (int x = 0; x < TEX_W; x++, n++) {
                double l = luma(&a, x, y);
                s += l;
                s2 += l * l;
            }
    ww_image_free(&a.im);
    double m = n ? s / (double)n : 0.0;
    *sd = n ? sqrt(fmax(s2 / (double)n - m * m, 0.0)) : 0.0;
    return m;
}

/* the texture caustics light the seabed as brightly on average as the analytic ones */
TEST_IMAGE(picture_caustics_texture_as_bright_as_analytic) {
    REQUIRE_GL();
    const char *scene = "scenes/features/caustics_texture.yaml";
    double sdt, sda, sdo;
    double t = seabed_mean(scene, NULL, "pc_mean_tex", &sdt);
    double a = seabed_mean(scene, "--set water.look.caustics.method=analytic", "pc_mean_ana", &sda);
    double o = seabed_mean(scene, "--set water.look.caustics=false", "pc_mean_off", &sdo);
    printf("  seabed mean luma: texture %.2f (sd %.2f), analytic %.2f (sd %.2f), off %.2f (sd %.2f)\n",
           t, sdt, a, sda, o, sdo);
    ENSURE_MSG(fabs(t - a) <= ww_test_tol(TEX_MEAN_MAX), "texture %.2f vs analytic %.2f", t, a);
}

/* the set in numbers: mean 1 (the light is moved, not made), frames differ, the loop closes */
TEST_PROC(picture_caustics_texture_set_mean_one) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load("scenes/features/caustics_texture.yaml", NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return;
    ww_caustic_set cs;
    ENSURE(ww_caustic_set_make(sc, &cs, &err) == WW_OK);
    size_t per = (size_t)cs.size * cs.size;
    double lo = 1e9, hi = 0.0;
    for (int f = 0; f < cs.frames; f++) {
        double m = 0.0;
        for (size_t i = 0; i < per; i++) m += cs.texel[per * f + i];
        m /= (double)per;
        lo = fmin(lo, m);
        hi = fmax(hi, m);
    }
    double sd = 0.0;
    for (size_t i = 0; i < per; i++) sd += (cs.texel[i] - 1.0) * (cs.texel[i] - 1.0);
    sd = sqrt(sd / (double)per);
    printf("  set: %d frames of %dx%d from %d sines; frame means %.6f .. %.6f; contrast (sd) %.3f\n",
           cs.frames, cs.size, cs.size, cs.ncomp, lo, hi, sd);
    ENSURE_NEAR(lo, 1.0, 1e-4);
    ENSURE_NEAR(hi, 1.0, 1e-4);
    ENSURE(sd > 0.1);
    int i0, i1;
    double w;
    ww_caustic_set_frame(&cs, 2.0 + cs.period, &i0, &i1, &w);
    ENSURE_EQ_INT(i0, cs.frames / 2);
    ENSURE_EQ_INT(i1, cs.frames / 2 + 1);
    ENSURE_NEAR(w, 0.0, 1e-9);
    ww_caustic_set_free(&cs);
    ww_scene_free(sc);
}

/* the caustics light the objects under water too (fish, the cubes' submerged sides), with
 * either method: without a seabed only they can change when the caustics go off (the fog
 * behind them takes no sunlight) */
TEST_IMAGE(picture_caustics_on_objects_both_methods) {
    REQUIRE_GL();
    static const char *const method[2] = {"analytic", "texture"};
    for (int m = 0; m < 2; m++) {
        char args[256], tag[64];
        snprintf(args, sizeof args, "--set render.seabed=false --set water.look.caustics.method=%s",
                 method[m]);
        snprintf(tag, sizeof tag, "pc_objects_%s", method[m]);
        double *d = caustic_light("scenes/features/caustics_texture.yaml", 0, args, tag, OBJECT_W,
                                  OBJECT_H, 0);
        ENSURE(d != NULL);
        if (!d) continue;
        long lit = 0;
        for (long i = 0; i < (long)OBJECT_W * OBJECT_H; i++) lit += fabs(d[i]) > OBJECT_LEVELS;
        printf("  %s: %ld pixels of objects changed by caustics\n", method[m], lit);
        ENSURE_MSG(lit >= OBJECT_PIXELS_MIN, "%s: caustics changed only %ld pixels of objects",
                   method[m], lit);
        free(d);
    }
}
