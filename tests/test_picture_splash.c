/* test_picture_splash.c - the spray a splash throws (gfx/splash.h): drops from each young ripple
 * in the pool, as many as its amplitude calls for, rising and falling on ballistic paths, all
 * above the surface they were thrown from and gone once they fall back, the same drops however
 * they are asked for, none with water.ripples.spray 0; and on a rendered frame, the drops seen
 * where they are projected and nothing changed away from them (they have no mirror image).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/splash.h"
#include "io/image.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "test.h"

/* calm water, a ripple of 5 cm at t = 1 s four metres ahead of a camera 1.2 m up */
static const char *SPLASH_SCENE =
    "seed: 5\n"
    "time: {dt: 1/120, fps: 30, duration: 3}\n"
    "render: {size: [640, 360]}\n"
    "sky: {time_of_day: 11}\n"
    "water:\n"
    "  waves:\n"
    "    model: gerstner\n"
    "    list:\n"
    "      - {direction: 30, wavelength: 20, amplitude: 0.05, steepness: 0.3}\n"
    "  ripples: {amplitude: 0.03}\n"
    "camera:\n"
    "  path:\n"
    "    - {t: 0, position: [0, 1.2, 0], look_at: [0, 0.15, -4]}\n"
    "script:\n"
    "  - {t: 1, ripple: {at: [0, -4], amplitude: 0.05}}\n";

#define SPLASH_T 1.0
#define SPLASH_AMP 0.05
#define SHOT_FRAME 36 /* t = 1.2 s: 0.2 s after the splash, its crown near the top */

/* a drop's height over the surface it was thrown from, m: it is drawn only above it */
#define ABOVE_TOL 0.0
/* the rendered drops: a pixel within DROP_PX of a drop's projected centre moved by more than
 * DROP_LEVELS (8-bit), for at least DROP_SEEN_MIN of the drops; and of the pixels that moved,
 * at most OUTSIDE_SHARE_MAX are further than OUTSIDE_PX from every drop (bloom and FXAA spread
 * a little) */
#define DROP_LEVELS 8
#define DROP_PX 1
#define DROP_SEEN_MIN 0.8
#define OUTSIDE_PX 4.0
#define OUTSIDE_SHARE_MAX 0.01

static ww_scene *load(const char *text) { return ww_test_scene_text("splash.yaml", text); }

TEST(splash_drops_rise_and_fall_back_from_each_young_ripple) {
    ww_scene *sc = load(SPLASH_SCENE);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    int cap = ww_splash_capacity(sc);
    ENSURE(cap > 0);
    ww_splash_drop *d = malloc((size_t)cap * sizeof *d), *again = malloc((size_t)cap * sizeof *d);
    if (!d || !again) return;
    int64_t splash_step = (int64_t)llround(SPLASH_T / sc->dt);
    int expect = (int)lround(WW_SPLASH_DROPS * SPLASH_AMP / WW_SPLASH_A_REF);
    if (ww_test_run_to(sc, st, splash_step - 1)) ENSURE_EQ_INT(ww_splash_drops(sc, st, d, cap), 0);
    /* through the flight: all of them at first, then fewer as they fall back; every drop
     * above the surface over the splash, within the crown's height */
    double rise = fmin(WW_SPLASH_RISE * SPLASH_AMP, WW_SPLASH_RISE_MAX);
    int first = -1, last = -1, highest = 0;
    double top = 0.0;
    for (int64_t step = splash_step + 1; step <= splash_step + 120 && ww_test_run_to(sc, st, step); step++) {
        int n = ww_splash_drops(sc, st, d, cap);
        if (first < 0) first = n;
        if (n > 0) last = (int)(step - splash_step);
        ww_water_sample ws;
        ww_water_at(sc, st, 0.0, -4.0, 0.0, &ws);
        for (int k = 0; k < n; k++) {
            double over = d[k].p[1] - ws.height;
            ENSURE_MSG(over >= -ABOVE_TOL, "a drop %.4f m under the surface at step %lld", over,
                       (long long)step);
            top = fmax(top, over);
            highest = n > highest ? n : highest;
        }
        /* the same drops when asked again */
        int m = ww_splash_drops(sc, st, again, cap);
        ENSURE_EQ_INT(m, n);
        ENSURE(memcmp(d, again, (size_t)n * sizeof *d) == 0);
    }
    double flight = 2.0 * sqrt(2.0 * WW_G * rise) / WW_G;
    printf("  a splash of %.2f m: %d drops, the crown %.3f m high (at most %.3f), the last back "
           "down %d steps after (the flight %.3f s)\n",
           SPLASH_AMP, first, top, rise, last, flight);
    ENSURE_EQ_INT(first, expect);
    ENSURE(top <= rise && top > 0.5 * rise);
    ENSURE(last > 0 && last * sc->dt <= flight);
    free(d);
    free(again);
    ww_state_free(st);
    ww_scene_free(sc);

    /* spray 0 throws none */
    char text[2048];
    snprintf(text, sizeof text, "%s", SPLASH_SCENE);
    char *a = strstr(text, "ripples: {amplitude: 0.03}");
    ENSURE(a != NULL);
    if (!a) return;
    memcpy(a, "ripples: {spray: 0      }", strlen("ripples: {amplitude: 0.03}"));
    sc = load(text);
    if (!sc) return;
    ENSURE_EQ_INT(ww_splash_capacity(sc), 0);
    ww_scene_free(sc);
}

TEST_IMAGE(picture_splash_drops_seen_where_they_are) {
    REQUIRE_GL();
    ww_test_pic with, none;
    if (!ww_test_render_with_without("splash", SPLASH_SCENE, SHOT_FRAME, "640x360",
                                     "--set water.ripples.spray=0", &with, &none))
        return;
    ww_scene *sc = load(SPLASH_SCENE);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    int cap = ww_splash_capacity(sc);
    ww_splash_drop *d = malloc((size_t)cap * sizeof *d);
    double(*at)[2] = malloc((size_t)cap * sizeof *at);
    if (d && at && ww_test_run_to(sc, st, SHOT_FRAME * sc->steps_per_frame)) {
        int n = ww_splash_drops(sc, st, d, cap);
        double sx = (double)with.w / sc->width, sy = (double)with.h / sc->height;
        for (int k = 0; k < n; k++) {
            ww_test_project(sc, st, d[k].p, at[k]);
            at[k][0] *= sx, at[k][1] *= sy;
        }
        int seen = 0;
        for (int k = 0; k < n; k++)
            seen += ww_test_moved_near(&with, &none, at[k][0], at[k][1], DROP_PX, DROP_LEVELS);
        long changed = 0, outside = 0;
        for (int y = 0; y < with.h; y++)
            for (int x = 0; x < with.w; x++) {
                if (!ww_test_moved_near(&with, &none, x, y, 0, DROP_LEVELS)) continue;
                changed++;
                double best = INFINITY;
                for (int i = 0; i < n; i++)
                    best = fmin(best, hypot(x + 0.5 - at[i][0], y + 0.5 - at[i][1]));
                outside += best > OUTSIDE_PX;
            }
        printf("  %d drops in the air, %d seen at their projected places; %ld pixels changed, "
               "%ld further than %.0f px from every drop\n",
               n, seen, changed, outside, OUTSIDE_PX);
        ENSURE_MSG(n > 0 && seen >= DROP_SEEN_MIN * n, "%d of %d drops seen", seen, n);
        ENSURE_MSG(outside <= OUTSIDE_SHARE_MAX * changed, "%ld pixels changed away from the drops",
                   outside);
    }
    free(d);
    free(at);
    ww_image_free(&with.im);
    ww_image_free(&none.im);
    ww_state_free(st);
    ww_scene_free(sc);
}
