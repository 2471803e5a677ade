/* test_picture_wake.c - the boat's wake (gfx/wake.h): the stern's trail in the state, the
 * ribbon's wedge (its half width beam / 2 + L tan 19.47 deg at a path length L behind the stern),
 * no fold in a turn, none without a boat under way or with wake 0; and the rendered wake: foam
 * behind the boat on both sides of its path, brighter than the water at midday, and nothing
 * changed outside the ribbon.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/wake.h"
#include "io/image.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "test.h"

/* a straight run at full throttle for 5 s, then a turn to starboard, at midday, seen from ahead
 * and above, where the whole wake lies in the frame */
static const char *WAKE_SCENE =
    "seed: 3\n"
    "time: {dt: 1/120, fps: 30, duration: 10}\n"
    "render: {size: [640, 360]}\n"
    "sky: {time_of_day: 11}\n"
    "water:\n"
    "  waves:\n"
    "    model: gerstner\n"
    "    list:\n"
    "      - {direction: 30, wavelength: 24, amplitude: 0.25, steepness: 0.5}\n"
    "      - {direction: -20, wavelength: 9, amplitude: 0.08, steepness: 0.4}\n"
    "objects:\n"
    "  boat: {position: [0, 0.25, 0], heading: 0}\n"
    "camera:\n"
    "  path:\n"
    "    - {t: 0, position: [30, 14, 12], look_at: [8, 0, 0]}\n"
    "script:\n"
    "  - {t: 0.2, boat: {throttle: 1, steer: 0, until: 5}}\n"
    "  - {t: 5, boat: {throttle: 1, steer: 0.35, until: 10}}\n";

#define STRAIGHT_FRAME 140 /* t = 4.67 s: straight, 4.5 s under way */
#define TURN_FRAME 240     /* t = 8 s: 3 s into the turn */

/* the trail's stern against the stern recomputed, m: the same operations */
#define STERN_TOL 1e-12
/* the wedge's half width against its formula on a straight run, m: rounding */
#define WEDGE_TOL 1e-9
/* the odometer against speed times time on the straight run at full speed (the boat still
 * accelerates a little): relative */
#define ODOMETER_REL_TOL 0.05
/* the rendered wake: pixels whose largest channel moved by more than this (8-bit) */
#define WAKE_LEVELS 8
/* ... at least this many on each side of the path, and at most this share of them further than
 * OUTSIDE_PX from the projected ribbon (bloom and FXAA spread a little) */
#define WAKE_MIN_PIXELS 150
#define OUTSIDE_PX 4.0
#define OUTSIDE_SHARE_MAX 0.01
/* midday foam is brighter than the water it covers: mean luma gain of the changed pixels */
#define FOAM_GAIN_MIN 10.0

static ww_scene *load(const char *text) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load_string("wake.yaml", text, strlen(text), NULL, 0, &sc, &err);
    ENSURE_MSG(r == WW_OK, "%s", err.msg);
    return r == WW_OK ? sc : NULL;
}

static int run_to(const ww_scene *sc, ww_state *st, int64_t step) {
    ww_error err = {0};
    ww_result r = ww_sim_advance_to(sc, st, step, &err);
    ENSURE_MSG(r == WW_OK, "step %lld: %s", (long long)st->step, err.msg);
    return r == WW_OK;
}

TEST(wake_trail_and_wedge_on_a_straight_run_and_in_a_turn) {
    ww_scene *sc = load(WAKE_SCENE);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    double p[WW_BOAT_WAKE + 1][2], half[WW_BOAT_WAKE + 1], age[WW_BOAT_WAKE + 1],
        odo[WW_BOAT_WAKE + 1];
    ENSURE_EQ_INT(ww_wake_points(sc, st, p, half, age, odo), 0); /* not under way yet */
    int64_t every = (int64_t)floor(WW_BOAT_WAKE_EVERY / sc->dt + 0.5);
    /* each trail sample is the stern at its step */
    for (int64_t step = every; step <= 3 * every; step += every) {
        if (!run_to(sc, st, step)) break;
        int k = ((int)st->boat_wake_next[0] + WW_BOAT_WAKE - 1) % WW_BOAT_WAKE;
        const double *w = st->boat_wake + 4 * k;
        double h = st->boat_heading[0], L = 0.5 * sc->boat.length;
        ENSURE_NEAR(w[0], st->boat_pos[0] - L * cos(h), STERN_TOL);
        ENSURE_NEAR(w[1], st->boat_pos[2] - L * sin(h), STERN_TOL);
        ENSURE_NEAR(w[2], st->t, 0.0);
        ENSURE_NEAR(w[3], st->boat_odometer[0], 0.0);
    }
    if (!run_to(sc, st, STRAIGHT_FRAME * sc->steps_per_frame)) return;
    int n = ww_wake_points(sc, st, p, half, age, odo);
    ENSURE_MSG(n > 10, "%d points of wake after 4.5 s under way", n);
    double spread = tan(ww_m_rad(WW_WAKE_KELVIN_DEG));
    for (int i = 1; i < n; i++) {
        ENSURE(age[i] > age[i - 1] && age[i] <= WW_WAKE_LIFE);
        ENSURE_NEAR(half[i], 0.5 * sc->boat.beam + spread * (odo[0] - odo[i]), WEDGE_TOL);
    }
    /* the path behind the stern is as long as the boat went since */
    double speed = fabs(st->boat_speed[0]);
    ENSURE_NEAR((odo[0] - odo[1]) / (speed * (age[1] - age[0])), 1.0, ODOMETER_REL_TOL);
    printf("  straight: %d points over %.2f s, %.1f m of path, half width %.2f to %.2f m\n", n,
           age[n - 1], odo[0] - odo[n - 1], half[0], half[n - 1]);

    /* in the turn the inner edge runs on along the path: it never doubles back over itself */
    if (!run_to(sc, st, TURN_FRAME * sc->steps_per_frame)) return;
    n = ww_wake_points(sc, st, p, half, age, odo);
    int folds = 0;
    for (int i = 1; i + 1 < n; i++) {
        double d[2] = {p[i - 1][0] - p[i + 1][0], p[i - 1][1] - p[i + 1][1]};
        for (int side = -1; side <= 1; side += 2) {
            double e[2][2];
            for (int k = 0; k < 2; k++) {
                int j = i + k;
                double t[2] = {p[j > 0 ? j - 1 : 0][0] - p[j + 1 < n ? j + 1 : n - 1][0],
                               p[j > 0 ? j - 1 : 0][1] - p[j + 1 < n ? j + 1 : n - 1][1]};
                double l = hypot(t[0], t[1]);
                e[k][0] = p[j][0] - side * half[j] * t[1] / l;
                e[k][1] = p[j][1] + side * half[j] * t[0] / l;
            }
            folds += (e[0][0] - e[1][0]) * d[0] + (e[0][1] - e[1][1]) * d[1] <= 0.0;
        }
    }
    printf("  turning: %d points, %d edge segments running backward\n", n, folds);
    ENSURE_MSG(n > 10 && folds == 0, "%d of the ribbon's edge segments fold back in the turn",
               folds);
    ww_state_free(st);
    ww_scene_free(sc);

    /* wake 0 draws none */
    char text[2048];
    snprintf(text, sizeof text, "%s", WAKE_SCENE);
    char *b = strstr(text, "heading: 0}");
    if (b) memcpy(b, "wake: 0   }", 11);
    sc = load(text);
    if (!sc) return;
    st = ww_state_new(sc);
    if (run_to(sc, st, STRAIGHT_FRAME * sc->steps_per_frame))
        ENSURE_EQ_INT(ww_wake_points(sc, st, p, half, age, odo), 0);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* ---- the rendered wake --------------------------------------------------------------------- */

/* whether pixel (x, y) lies in the polygon of n points (even-odd rule) */
static int inside(const double (*poly)[2], int n, double x, double y) {
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((poly[i][1] > y) != (poly[j][1] > y) &&
            x < (poly[j][0] - poly[i][0]) * (y - poly[i][1]) / (poly[j][1] - poly[i][1]) +
                    poly[i][0])
            in = !in;
    return in;
}

/* the distance from (x, y) to the polygon's outline */
static double outline_distance(const double (*poly)[2], int n, double x, double y) {
    double best = INFINITY;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        double ax = poly[j][0], ay = poly[j][1], bx = poly[i][0] - ax, by = poly[i][1] - ay;
        double t = ww_m_clamp(((x - ax) * bx + (y - ay) * by) / fmax(bx * bx + by * by, 1e-12),
                              0.0, 1.0);
        best = fmin(best, hypot(x - ax - t * bx, y - ay - t * by));
    }
    return best;
}

TEST_IMAGE(picture_wake_foam_behind_the_boat_on_both_sides) {
    REQUIRE_GL();
    char path[600];
    snprintf(path, sizeof path, "%s/wake.yaml", ww_test_tmpdir("wake_scene"));
    ENSURE(ww_test_write_text(path, WAKE_SCENE) == 0);
    ww_test_pic with = {0}, none = {0};
    if (!ww_test_render_pic(path, STRAIGHT_FRAME, "640x360", NULL, "wake_on", &with) ||
        !ww_test_render_pic(path, STRAIGHT_FRAME, "640x360", "--set objects.boat.wake=0",
                            "wake_off", &none))
        return;
    ww_scene *sc = load(WAKE_SCENE);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    if (run_to(sc, st, STRAIGHT_FRAME * sc->steps_per_frame)) {
        double p[WW_BOAT_WAKE + 1][2], half[WW_BOAT_WAKE + 1], age[WW_BOAT_WAKE + 1],
            odo[WW_BOAT_WAKE + 1];
        int n = ww_wake_points(sc, st, p, half, age, odo);
        /* the ribbon's two halves projected, each a polygon: an edge, then the path back */
        static double side_poly[2][2 * (WW_BOAT_WAKE + 1)][2];
        for (int i = 0; i < n; i++) {
            const double *a = p[i < n - 1 ? i + 1 : n - 1], *b = p[i > 0 ? i - 1 : 0];
            double t[2] = {b[0] - a[0], b[1] - a[1]}, l = hypot(t[0], t[1]);
            for (int s = 0; s < 2; s++) {
                double sg = s ? 1.0 : -1.0, w[3], c[3];
                w[0] = p[i][0] - sg * half[i] * t[1] / l;
                w[2] = p[i][1] + sg * half[i] * t[0] / l;
                c[0] = p[i][0], c[2] = p[i][1];
                ww_water_sample ws;
                ww_water_at(sc, st, w[0], w[2], 0.0, &ws);
                w[1] = ws.height;
                ww_water_at(sc, st, c[0], c[2], 0.0, &ws);
                c[1] = ws.height;
                ww_test_project(sc, st, w, side_poly[s][i]);
                ww_test_project(sc, st, c, side_poly[s][2 * n - 1 - i]);
            }
        }
        /* the frame's size, not the scene's: project then scale */
        double sx = (double)with.w / sc->width, sy = (double)with.h / sc->height;
        for (int s = 0; s < 2; s++)
            for (int i = 0; i < 2 * n; i++) side_poly[s][i][0] *= sx, side_poly[s][i][1] *= sy;
        long count[2] = {0, 0}, changed = 0, outside = 0;
        double gain = 0.0;
        for (int y = 0; y < with.h; y++)
            for (int x = 0; x < with.w; x++) {
                const unsigned char *a = ww_test_pixel(&with.im, x, y);
                const unsigned char *b = ww_test_pixel(&none.im, x, y);
                int d = 0;
                for (int c = 0; c < 3; c++) d = abs(a[c] - b[c]) > d ? abs(a[c] - b[c]) : d;
                if (d <= WAKE_LEVELS) continue;
                changed++;
                gain += ww_test_pic_luma(&with, x, y) - ww_test_pic_luma(&none, x, y);
                double px = x + 0.5, py = y + 0.5;
                int s = inside((const double(*)[2])side_poly[0], 2 * n, px, py) ? 0
                        : inside((const double(*)[2])side_poly[1], 2 * n, px, py) ? 1
                                                                                   : -1;
                if (s >= 0) {
                    count[s]++;
                    continue;
                }
                const double(*s0)[2] = (const double(*)[2])side_poly[0];
                const double(*s1)[2] = (const double(*)[2])side_poly[1];
                double near = fmin(outline_distance(s0, 2 * n, px, py),
                                   outline_distance(s1, 2 * n, px, py));
                outside += near > OUTSIDE_PX;
            }
        gain = changed ? gain / changed : 0.0;
        printf("  %ld pixels of foam: %ld and %ld on the two sides of the path, %ld further than "
               "%.0f px outside the ribbon; mean luma gain %.1f\n",
               changed, count[0], count[1], outside, OUTSIDE_PX, gain);
        ENSURE_MSG(count[0] >= WAKE_MIN_PIXELS && count[1] >= WAKE_MIN_PIXELS,
                   "the wake's sides: %ld and %ld pixels", count[0], count[1]);
        ENSURE_MSG(outside <= OUTSIDE_SHARE_MAX * changed, "%ld pixels changed outside the wake",
                   outside);
        ENSURE_MSG(gain >= FOAM_GAIN_MIN, "the foam brightens the water by %.1f levels", gain);
    }
    ww_image_free(&with.im);
    ww_image_free(&none.im);
    ww_state_free(st);
    ww_scene_free(sc);
}
