/* test_fish_species.c - objects.fish.species: each species is its own school (its fish stay in
 * their region, cruise at their speed), the count is the species' sum, scenes without species
 * keep every fish alike; and the rendered feature scene: three species whose fish differ in
 * colour (mean hue of each fish's pixels) and silhouette (its mask's height against its
 * length: a deep-bodied fish is several times taller for its length than a slim one), every
 * fish drawn.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "io/image.h"
#include "io/writers.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* a fish stays within its school's region: homing starts at 0.8 R, so it may overshoot R a
 * little while it turns back (fraction of R) */
#define SCHOOL_OVERSHOOT 1.3
/* the mean hue of any two species' fish differs by at least this, degrees */
#define SPECIES_HUE_MIN 40.0
/* a deep-bodied fish's mask is at least this many times taller for its width than a slim
 * fish's, and a long fish's at most this fraction of a slim fish's (medians over each species) */
#define DEEP_OVER_SLIM_MIN 1.6
#define LONG_OVER_SLIM_MAX 0.75
/* a pixel differs from the open water behind it by more than this (largest channel, 8-bit) */
#define FISH_PIXEL_DIFF 18
/* a fish counts as drawn with at least this many pixels in its window */
#define FISH_MIN_PIXELS 12

static ww_scene *load(const char *text) { return ww_test_scene_text("species.yaml", text); }

static void run(const ww_scene *sc, ww_state *st, int steps) {
    ww_error err = {0};
    for (int n = 0; n < steps; n++) {
        ww_result r = ww_step(sc, st, &err);
        ENSURE_MSG(r == WW_OK, "step %d: %s", n, err.msg);
        if (r != WW_OK) return;
    }
}

TEST(fish_species_each_school_keeps_to_its_region) {
    ww_scene *sc = load("time: {dt: 1/60, fps: 30, duration: 60}\nwater: {depth: 20}\n"
                        "objects:\n  fish:\n    species:\n"
                        "      - {shape: slim, count: 10, center: [-12, -5, 0], radius: 3}\n"
                        "      - {shape: deep, count: 6, center: [0, -8, -10], radius: 2, "
                        "speed: 0.4}\n"
                        "      - {shape: long, count: 4, center: [12, -4, 0], radius: 4}\n");
    if (!sc) return;
    ENSURE_EQ_INT(sc->fish.count, 20);
    ENSURE_EQ_INT(sc->fish.nspecies, 3);
    ENSURE_EQ_INT(sc->fish.species[2].first, 16);
    ww_state *st = ww_state_new(sc);
    double worst = 0.0;
    for (int n = 0; n < 60 * 60; n += 30) {
        run(sc, st, 30);
        for (int k = 0; k < 3; k++) {
            const ww_fish_species *sp = &sc->fish.species[k];
            for (int i = sp->first; i < sp->first + sp->count; i++) {
                const double *p = st->fish_pos + 3 * i;
                double r = hypot(p[0] - sp->center[0], p[2] - sp->center[2]) / sp->radius;
                worst = fmax(worst, r);
            }
        }
    }
    ENSURE_MSG(worst < SCHOOL_OVERSHOOT, "a fish strayed %.2f radii from its school", worst);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(fish_species_absent_keeps_one_kind) {
    ww_scene *sc = load("time: {dt: 1/60, fps: 30, duration: 1}\nobjects:\n  fish: {count: 5}\n");
    if (!sc) return;
    ENSURE_EQ_INT(sc->fish.nspecies, 0);
    ENSURE_EQ_INT(sc->fish.count, 5);
    ww_scene_free(sc);
}

/* ---- the rendered feature scene --------------------------------------------------------- */

#define FEATURE "scenes/features/fish_species.yaml"

static double hue_of(const double c[3]) {
    double mx = fmax(c[0], fmax(c[1], c[2])), mn = fmin(c[0], fmin(c[1], c[2])), d = mx - mn;
    if (d <= 0.0) return 0.0;
    double h = mx == c[0] ? fmod((c[1] - c[2]) / d, 6.0) : mx == c[1] ? (c[2] - c[0]) / d + 2.0
                                                                        : (c[0] - c[1]) / d + 4.0;
    h *= 60.0;
    return h < 0.0 ? h + 360.0 : h;
}

static double hue_gap(double a, double b) {
    double d = fabs(a - b);
    return d > 180.0 ? 360.0 - d : d;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

TEST_IMAGE(fish_species_rendered_colour_shape_and_count) {
    REQUIRE_GL();
    char dir[512];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("fs"));
    ENSURE(ww_test_render(FEATURE, NULL, dir) == 0);
    char path[600];
    snprintf(path, sizeof path, "%s/frame_00000.png", dir);
    ww_image im = {0};
    ww_error err = {0};
    ENSURE_MSG(ww_read_png(path, &im, &err) == WW_OK, "%s: %s", path, err.msg);
    ww_scene *sc = NULL;
    ENSURE_MSG(ww_scene_load(FEATURE, NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc || !im.u8) return;
    ww_state *st = ww_state_new(sc); /* frame 0: the state after reset */
    const unsigned char *bg = ww_test_pixel(&im, 2, im.height / 2); /* open water */

    double hue[3] = {0, 0, 0}, aspect[3][WW_MAX_FISH];
    int drawn[3] = {0, 0, 0};
    for (int k = 0; k < sc->fish.nspecies; k++) {
        const ww_fish_species *sp = &sc->fish.species[k];
        double sum[3] = {0, 0, 0};
        for (int i = sp->first; i < sp->first + sp->count; i++) {
            /* the window: the fish's length around its centre, in pixels */
            double c[2], tip[3], ct[2];
            ww_test_project(sc, st, st->fish_pos + 3 * i, c);
            for (int a = 0; a < 3; a++) tip[a] = st->fish_pos[3 * i + a];
            tip[1] += 0.6 * sp->length;
            ww_test_project(sc, st, tip, ct);
            int half = (int)ceil(fabs(c[1] - ct[1]));
            int x0 = (int)c[0] - half, x1 = (int)c[0] + half, y0 = (int)c[1] - half,
                y1 = (int)c[1] + half, n = 0, lo[2] = {1 << 20, 1 << 20}, hi[2] = {-1, -1};
            for (int y = y0 < 0 ? 0 : y0; y <= y1 && y < im.height; y++)
                for (int x = x0 < 0 ? 0 : x0; x <= x1 && x < im.width; x++) {
                    const unsigned char *p = ww_test_pixel(&im, x, y);
                    int d = 0;
                    for (int ch = 0; ch < 3; ch++) d = abs(p[ch] - bg[ch]) > d ? abs(p[ch] - bg[ch]) : d;
                    if (d <= FISH_PIXEL_DIFF) continue;
                    n++;
                    for (int ch = 0; ch < 3; ch++) sum[ch] += p[ch];
                    lo[0] = x < lo[0] ? x : lo[0], hi[0] = x > hi[0] ? x : hi[0];
                    lo[1] = y < lo[1] ? y : lo[1], hi[1] = y > hi[1] ? y : hi[1];
                }
            if (n < FISH_MIN_PIXELS) continue;
            aspect[k][drawn[k]++] = (double)(hi[1] - lo[1] + 1) / (hi[0] - lo[0] + 1);
        }
        hue[k] = hue_of(sum);
        ENSURE_MSG(drawn[k] == sp->count, "species %d: %d of %d fish drawn", k, drawn[k],
                   sp->count);
        if (drawn[k] == 0) aspect[k][drawn[k]++] = 0.0;
        qsort(aspect[k], (size_t)drawn[k], sizeof aspect[k][0], cmp_double);
    }
    double med[3];
    for (int k = 0; k < 3; k++) med[k] = aspect[k][drawn[k] / 2];
    fprintf(stderr, "hues %.0f %.0f %.0f deg; median height/width %.2f %.2f %.2f; drawn %d %d %d\n",
            hue[0], hue[1], hue[2], med[0], med[1], med[2], drawn[0], drawn[1], drawn[2]);
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++)
            ENSURE_MSG(hue_gap(hue[a], hue[b]) > SPECIES_HUE_MIN, "species %d and %d: hues %.0f, %.0f",
                       a, b, hue[a], hue[b]);
    ENSURE(med[1] > DEEP_OVER_SLIM_MIN * med[0]);
    ENSURE(med[2] < LONG_OVER_SLIM_MAX * med[0]);
    ww_image_free(&im);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST_IMAGE(fish_species_golden) {
    REQUIRE_GL();
    char dir[512], actual[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden"));
    ENSURE(ww_test_render(FEATURE, NULL, dir) == 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden("golden/features/fish_species.png", actual);
}
