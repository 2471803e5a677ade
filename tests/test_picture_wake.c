/* test_picture_wake.c - the boat's wake (gfx/wake.h): the stern's trail in the state; the
 * ribbon's rows along the hull (outside its waterline by the bow wave's band) and behind it
 * (half width (length + L) tan 19.47 deg at a path length L behind the stern: the wedge from the
 * stem), no fold in a turn, none without a boat under way or with wake 0; and the rendered wake:
 * foam behind the boat on both sides of its path, brighter than the water at midday, nothing
 * changed outside the ribbon, a bow wave beside the hull's forward half on both sides, and arms
 * whose foam runs on along the wedge rather than in dashes with water between.
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

#define WAKE_CAMERA "{t: 0, position: [30, 14, 12], look_at: [8, 0, 0]}"
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
    "    - " WAKE_CAMERA "\n"
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
/* the bow wave: points every BOW_STEP m along the band beside the hull's forward half, at
 * least this share of them with foam within a pixel */
#define BOW_STEP 0.1
#define BOW_SHARE_MIN 0.8
/* the arms: cuts across each side's outer part (ARM_CUT_POINTS + 1 points from ARM_CUT_FROM of
 * the half width to just past the edge) every ARM_STEP m of path from ARM_FROM to ARM_TO m
 * behind the stern; at least ARM_SHARE_MIN of them cross foam, and no run of bare cuts is longer
 * than ARM_GAP_MAX m of path (the dashes the arms were drawn in left 0.75-1 m) */
#define ARM_STEP 0.25
#define ARM_FROM 1.0
#define ARM_TO 10.0
#define ARM_CUT_FROM 0.55
#define ARM_CUT_POINTS 24
#define ARM_SHARE_MIN 0.9
/* one frame apart, at least this share of the points in the arms' bands with foam in either
 * frame have it in both; TRAVEL_ACROSS + 1 points across a band; ARM_GROW, the band's widening
 * per m behind the stern (geometry.frag.glsl's WAKE_ARM_GROW) */
#define TRAVEL_SHARE_MIN 0.85
#define TRAVEL_BAND 0.8 /* of the band from its outer edge in: the lace starts at 0.9 */
#define TRAVEL_ACROSS 8
#define ARM_GROW 0.03
#define ARM_GAP_MAX 0.5
/* the view from above: height m, and how far behind the boat's middle */
#define ABOVE 14.0
#define ABOVE_BACK 5.0

static ww_scene *load(const char *text) { return ww_test_scene_text("wake.yaml", text); }

TEST(wake_trail_and_wedge_on_a_straight_run_and_in_a_turn) {
    ww_scene *sc = load(WAKE_SCENE);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ww_wake_row row[WW_WAKE_MAX_ROWS];
    int stern = -1;
    ENSURE_EQ_INT(ww_wake_rows(sc, st, row, &stern), 0); /* not under way yet */
    int64_t every = (int64_t)floor(WW_BOAT_WAKE_EVERY / sc->dt + 0.5);
    /* each trail sample is the stern at its step */
    for (int64_t step = every; step <= 3 * every; step += every) {
        if (!ww_test_run_to(sc, st, step)) break;
        int k = ((int)st->boat_wake_next[0] + WW_BOAT_WAKE - 1) % WW_BOAT_WAKE;
        const double *w = st->boat_wake + 4 * k;
        double h = st->boat_heading[0], L = 0.5 * sc->boat.length;
        ENSURE_NEAR(w[0], st->boat_pos[0] - L * cos(h), STERN_TOL);
        ENSURE_NEAR(w[1], st->boat_pos[2] - L * sin(h), STERN_TOL);
        ENSURE_NEAR(w[2], st->t, 0.0);
        ENSURE_NEAR(w[3], st->boat_odometer[0], 0.0);
    }
    if (!ww_test_run_to(sc, st, STRAIGHT_FRAME * sc->steps_per_frame)) return;
    int n = ww_wake_rows(sc, st, row, &stern);
    ENSURE_MSG(n > stern + 10, "%d rows of wake after 4.5 s under way", n - stern - 1);
    ENSURE_EQ_INT(stern, WW_WAKE_HULL_ROWS);
    double spread = tan(ww_m_rad(WW_WAKE_KELVIN_DEG)), len = sc->boat.length;
    double h = st->boat_heading[0];
    /* the first row lies ahead of the stem and starts the foam from nothing; the rows on the
     * hull run back to the stern along the heading, each wider than the hull there */
    double stem[2] = {st->boat_pos[0] + 0.5 * len * cos(h), st->boat_pos[2] + 0.5 * len * sin(h)};
    ENSURE_NEAR(hypot(row[0].p[0] - stem[0], row[0].p[1] - stem[1]), WW_WAKE_STEM_AHEAD,
                STERN_TOL);
    ENSURE_NEAR(row[0].strength, 0.0, 0.0);
    ENSURE_NEAR(row[1].p[0], stem[0], STERN_TOL);
    ENSURE_NEAR(row[1].p[1], stem[1], STERN_TOL);
    double least_margin = INFINITY;
    for (int i = 1; i <= stern; i++) {
        double ahead = row[i].odo - row[stern].odo;
        least_margin = fmin(least_margin, row[i].half - ww_wake_hull_half(sc, ahead));
        ENSURE_NEAR(row[i].half, fmax(ww_wake_hull_half(sc, ahead) + WW_WAKE_BAND,
                                      (len - ahead) * spread), WEDGE_TOL);
        ENSURE(row[i].age == 0.0 && row[i].strength > 0.0);
    }
    ENSURE_NEAR(row[stern].p[0], st->boat_pos[0] - 0.5 * len * cos(h), STERN_TOL);
    /* behind the stern: the wedge from the stem */
    for (int i = stern + 1; i < n; i++) {
        ENSURE(row[i].age > row[i - 1].age && row[i].age <= WW_WAKE_LIFE);
        ENSURE(row[i].odo < row[i - 1].odo);
        ENSURE_NEAR(row[i].half, (len + row[stern].odo - row[i].odo) * spread, WEDGE_TOL);
    }
    /* the path behind the stern is as long as the boat went since */
    double speed = fabs(st->boat_speed[0]);
    ENSURE_NEAR((row[stern].odo - row[stern + 1].odo) / (speed * row[stern + 1].age), 1.0,
                ODOMETER_REL_TOL);
    printf("  straight: %d rows on the hull, the ribbon %.2f m or more outside its waterline; "
           "%d behind over %.2f s, %.1f m of path, half width %.2f to %.2f m\n",
           stern, least_margin, n - stern - 1, row[n - 1].age, row[stern].odo - row[n - 1].odo,
           row[stern].half, row[n - 1].half);

    /* in the turn the inner edge runs on along the path: it never doubles back over itself */
    if (!ww_test_run_to(sc, st, TURN_FRAME * sc->steps_per_frame)) return;
    n = ww_wake_rows(sc, st, row, &stern);
    int folds = 0;
    for (int i = 1; i + 1 < n; i++) {
        double d[2] = {row[i - 1].p[0] - row[i + 1].p[0], row[i - 1].p[1] - row[i + 1].p[1]};
        for (int side = -1; side <= 1; side += 2) {
            double e[2][2];
            for (int k = 0; k < 2; k++) {
                int j = i + k;
                const double *a = row[j > 0 ? j - 1 : 0].p, *b = row[j + 1 < n ? j + 1 : n - 1].p;
                double t[2] = {a[0] - b[0], a[1] - b[1]}, l = hypot(t[0], t[1]);
                e[k][0] = row[j].p[0] - side * row[j].half * t[1] / l;
                e[k][1] = row[j].p[1] + side * row[j].half * t[0] / l;
            }
            folds += (e[0][0] - e[1][0]) * d[0] + (e[0][1] - e[1][1]) * d[1] <= 0.0;
        }
    }
    printf("  turning: %d rows, %d edge segments running backward\n", n, folds);
    ENSURE_MSG(n > stern + 10 && folds == 0,
               "%d of the ribbon's edge segments fold back in the turn", folds);
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
    if (ww_test_run_to(sc, st, STRAIGHT_FRAME * sc->steps_per_frame))
        ENSURE_EQ_INT(ww_wake_rows(sc, st, row, &stern), 0);
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

/* the point on the water beside the straight path: `ahead` m ahead of the stern (negative:
 * behind), `out` m out to `side` (-1, 1), projected into the frame (scaled to its size) */
static void beside(const ww_scene *sc, const ww_state *st, double ahead, int side, double out,
                   const ww_test_pic *pic, double px[2]) {
    double h = st->boat_heading[0], c = cos(h), s = sin(h), len = sc->boat.length;
    double x = st->boat_pos[0] + (ahead - 0.5 * len) * c - side * out * s;
    double z = st->boat_pos[2] + (ahead - 0.5 * len) * s + side * out * c;
    ww_water_sample ws;
    ww_water_at(sc, st, x, z, 0.0, &ws);
    double w[3] = {x, ws.height, z};
    ww_test_project(sc, st, w, px);
    px[0] *= (double)pic->w / sc->width;
    px[1] *= (double)pic->h / sc->height;
}

TEST_IMAGE(picture_wake_foam_behind_the_boat_on_both_sides) {
    REQUIRE_GL();
    ww_test_pic with, none;
    if (!ww_test_render_with_without("wake", WAKE_SCENE, STRAIGHT_FRAME, "640x360",
                                     "--set objects.boat.wake=0", &with, &none))
        return;
    ww_scene *sc = load(WAKE_SCENE);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    if (ww_test_run_to(sc, st, STRAIGHT_FRAME * sc->steps_per_frame)) {
        ww_wake_row row[WW_WAKE_MAX_ROWS];
        int stern = 0, n = ww_wake_rows(sc, st, row, &stern);
        /* the ribbon's two halves projected, each a polygon: an edge, then the path back */
        static double side_poly[2][2 * WW_WAKE_MAX_ROWS][2];
        for (int i = 0; i < n; i++) {
            const double *a = row[i < n - 1 ? i + 1 : n - 1].p, *b = row[i > 0 ? i - 1 : 0].p;
            double t[2] = {b[0] - a[0], b[1] - a[1]}, l = hypot(t[0], t[1]);
            for (int s = 0; s < 2; s++) {
                double sg = s ? 1.0 : -1.0, w[3], c[3];
                w[0] = row[i].p[0] - sg * row[i].half * t[1] / l;
                w[2] = row[i].p[1] + sg * row[i].half * t[0] / l;
                c[0] = row[i].p[0], c[2] = row[i].p[1];
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
        (void)stern;
        long count[2] = {0, 0}, changed = 0, outside = 0;
        double gain = 0.0;
        for (int y = 0; y < with.h; y++)
            for (int x = 0; x < with.w; x++) {
                if (!ww_test_moved_near(&with, &none, x, y, 0, WAKE_LEVELS)) continue;
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

/* the run seen from above at a frame: the camera ABOVE m over the path, ABOVE_BACK m behind the
 * boat's middle then, looking down the path's line. Renders it with and without the wake (tag
 * names the renders) and leaves the scene with that camera and its state at the frame; 0 when
 * any of it failed (checked) */
typedef struct above_view {
    ww_scene *sc;
    ww_state *st;
    ww_test_pic with, none;
} above_view;

static void above_free(above_view *v) {
    ww_image_free(&v->with.im);
    ww_image_free(&v->none.im);
    if (v->st) ww_state_free(v->st);
    ww_scene_free(v->sc);
    memset(v, 0, sizeof *v);
}

static int above(int frame, const char *tag, above_view *v) {
    memset(v, 0, sizeof *v);
    /* where the boat is at the frame, for the camera over it */
    ww_scene *sc = load(WAKE_SCENE);
    if (!sc) return 0;
    ww_state *st = ww_state_new(sc);
    int ok = ww_test_run_to(sc, st, frame * sc->steps_per_frame);
    double bx = st->boat_pos[0] - ABOVE_BACK, bz = st->boat_pos[2];
    ww_state_free(st);
    ww_scene_free(sc);
    if (!ok) return 0;
    char text[2048], cam[160];
    snprintf(cam, sizeof cam, "{t: 0, position: [%.3f, %.1f, %.3f], look_at: [%.3f, 0, %.3f]}",
             bx, ABOVE, bz, bx + 1.0, bz);
    const char *at = strstr(WAKE_SCENE, WAKE_CAMERA);
    ENSURE(at != NULL);
    if (!at) return 0;
    snprintf(text, sizeof text, "%.*s%s%s", (int)(at - WAKE_SCENE), WAKE_SCENE, cam,
             at + strlen(WAKE_CAMERA));
    v->sc = load(text);
    if (!v->sc) return 0;
    v->st = ww_state_new(v->sc);
    if (ww_test_render_with_without(tag, text, frame, "640x360", "--set objects.boat.wake=0",
                                    &v->with, &v->none) &&
        ww_test_run_to(v->sc, v->st, frame * v->sc->steps_per_frame))
        return 1;
    above_free(v);
    return 0;
}

/* the arms' cuts (below): for each side, ARM_FROM to ARM_TO m behind the stern every ARM_STEP,
 * ARM_CUT_POINTS + 1 points across from ARM_CUT_FROM of the half width to just past the edge;
 * whether each has foam within a pixel, in that order; returns the count */
enum { ARM_CUTS = 37 }; /* (ARM_TO - ARM_FROM) / ARM_STEP + 1 */
static int arm_points(const above_view *v, int side, unsigned char *foam) {
    int n = 0;
    for (int c = 0; c < ARM_CUTS; c++) {
        double back = ARM_FROM + c * ARM_STEP;
        double half = (v->sc->boat.length + back) * tan(ww_m_rad(WW_WAKE_KELVIN_DEG));
        for (int k = 0; k <= ARM_CUT_POINTS; k++) {
            double px[2], out = half * (ARM_CUT_FROM + (1.02 - ARM_CUT_FROM) * k / ARM_CUT_POINTS);
            beside(v->sc, v->st, -back, side, out, &v->with, px);
            foam[n++] = (unsigned char)ww_test_moved_near(&v->with, &v->none, px[0], px[1], 1, WAKE_LEVELS);
        }
    }
    return n;
}

/* seen from above the boat, where neither side of the hull hides the water beside it: a bow
 * wave beside the hull's forward half on both sides, and arms whose foam runs on along the
 * wedge rather than in dashes with bare water between */
TEST_IMAGE(picture_wake_bow_wave_and_unbroken_arms_from_above) {
    REQUIRE_GL();
    above_view v;
    if (above(STRAIGHT_FRAME, "wake_above", &v)) {
        ww_scene *sc = v.sc;
        ww_state *st = v.st;
        const ww_test_pic with = v.with, none = v.none;
        double len = sc->boat.length;
        /* the bow wave: foam in the band beside the hull's forward half, on each side; points
         * every BOW_STEP m along the middle of the band */
        for (int side = -1; side <= 1; side += 2) {
            int seen = 0, points = 0;
            for (double a = 0.5 * len; a <= len; a += BOW_STEP) {
                double px[2];
                beside(sc, st, a, side, ww_wake_hull_half(sc, a) + 0.5 * WW_WAKE_BAND, &with, px);
                seen += ww_test_moved_near(&with, &none, px[0], px[1], 1, WAKE_LEVELS);
                points++;
            }
            printf("  the bow wave on side %+d: foam at %d of %d points beside the forward half\n",
                   side, seen, points);
            ENSURE_MSG(seen >= BOW_SHARE_MIN * points, "a bow wave at %d of %d points", seen,
                       points);
        }

        /* the arms: across the outer part of each side (ARM_CUT_FROM of the half width out to
         * the edge, clear of the wash, where the arms lie) every ARM_STEP m of path from
         * ARM_FROM to ARM_TO behind the stern, foam somewhere on the cut (dashes leave cuts of
         * bare water) */
        for (int side = -1; side <= 1; side += 2) {
            unsigned char foam[ARM_CUTS * (ARM_CUT_POINTS + 1)];
            arm_points(&v, side, foam);
            int seen = 0, gap = 0, longest = 0;
            for (int c = 0; c < ARM_CUTS; c++) {
                int hit = 0;
                for (int k = 0; k <= ARM_CUT_POINTS; k++) hit |= foam[c * (ARM_CUT_POINTS + 1) + k];
                seen += hit;
                gap = hit ? 0 : gap + 1;
                longest = gap > longest ? gap : longest;
            }
            printf("  the arm on side %+d: foam on %d of %d cuts across it, %.0f to %.0f m behind "
                   "the stern; the longest stretch without, %.2f m\n", side, seen, ARM_CUTS,
                   ARM_FROM, ARM_TO, longest * ARM_STEP);
            ENSURE_MSG(seen >= ARM_SHARE_MIN * ARM_CUTS,
                       "the arm on side %+d has foam on %d of %d cuts", side, seen, ARM_CUTS);
            ENSURE_MSG(longest * ARM_STEP <= ARM_GAP_MAX,
                       "the arm on side %+d: %.2f m without foam", side, longest * ARM_STEP);
        }
        above_free(&v);
    }
}

/* the arms' breaking crests are a pattern that travels with the boat (Kelvin's is steady in the
 * boat's frame): seen from above at the same place relative to the boat one frame apart, the
 * foam in the arms' bands lies at the same points, where foam drawn fixed to the water under a
 * band moving out across it boiled from frame to frame. The points: across each band (from
 * TRAVEL_BAND of its width, WW_WAKE_BAND + ARM_GROW m per m behind the stern, in from the
 * ribbon's edge, to the edge) at TRAVEL_ACROSS + 1 points, every ARM_STEP m of path from
 * ARM_FROM to ARM_TO */
static int band_points(const above_view *v, int side, unsigned char *foam) {
    int n = 0;
    for (int c = 0; c < ARM_CUTS; c++) {
        double back = ARM_FROM + c * ARM_STEP, band = WW_WAKE_BAND + ARM_GROW * back;
        double half = (v->sc->boat.length + back) * tan(ww_m_rad(WW_WAKE_KELVIN_DEG));
        for (int k = 0; k <= TRAVEL_ACROSS; k++) {
            double px[2];
            beside(v->sc, v->st, -back, side,
                   half - TRAVEL_BAND * band * (1.0 - (double)k / TRAVEL_ACROSS), &v->with, px);
            foam[n++] = (unsigned char)ww_test_moved_near(&v->with, &v->none, px[0], px[1], 1, WAKE_LEVELS);
        }
    }
    return n;
}

TEST_IMAGE(picture_wake_arms_travel_with_the_boat) {
    REQUIRE_GL();
    above_view a, b;
    if (!above(STRAIGHT_FRAME, "wake_travel_a", &a)) return;
    if (above(STRAIGHT_FRAME + 1, "wake_travel_b", &b)) {
        int both = 0, either = 0;
        for (int side = -1; side <= 1; side += 2) {
            unsigned char fa[ARM_CUTS * (TRAVEL_ACROSS + 1)], fb[ARM_CUTS * (TRAVEL_ACROSS + 1)];
            int n = band_points(&a, side, fa);
            band_points(&b, side, fb);
            for (int i = 0; i < n; i++) both += fa[i] && fb[i], either += fa[i] || fb[i];
        }
        double share = either ? (double)both / either : 0.0;
        printf("  the arms' foam one frame apart, at the same places relative to the boat: %d "
               "points in both of %d in either (%.2f)\n", both, either, share);
        ENSURE_MSG(either > 0 && share >= TRAVEL_SHARE_MIN,
                   "the arms' foam at %d of %d points in both frames", both, either);
        above_free(&b);
    }
    above_free(&a);
}
