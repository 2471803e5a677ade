/* test_picture_line.c - the fishing line and the rod that holds it (gfx/line.h): where the line
 * runs (from the rod's tip to the top of the lure, slack and lying on the water from a floating
 * lure, straight under a fish, never under the surface), the ribbons' width and coverage, and
 * the rendered line: seen along its whole length in the frame, from the rod to the lure, and
 * nothing else in the picture changed by it.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/line.h"
#include "io/image.h"
#include "io/writers.h"
#include "sim/rod.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "test.h"

#define FISHING "scenes/fishing.yaml"

/* the line's ends are the tip and the lure's stem to rounding, m */
#define END_TOL 1e-12
/* a line under a fish is straight: its points lie this close to the chord, as a fraction of the
 * chord's length */
#define TAUT_BEND_MAX 0.005
/* a slack line lies on the water: some of its points rest within this of the surface, m */
#define ON_WATER_TOL 0.01
/* a ribbon is 2 pixels wide or its width, to float rounding (relative) */
#define RIBBON_WIDTH_TOL 1e-5
/* the rendered line is seen where a pixel within SEEN_RADIUS px of the projected line differs by
 * at least SEEN_LEVELS from the frame without it; along at least SEEN_SHARE of its length in the
 * frame (a line that broke into dashes would miss about half) */
#define SEEN_LEVELS 3
#define SEEN_RADIUS 1.5
#define SEEN_SHARE 0.9
/* nothing else changes: pixels further than AWAY_PX from the line and the rod (their drawn half
 * width added) that differ by more than AWAY_LEVELS, at most this share of the frame (bloom and
 * FXAA spread a strand's light a little) */
#define AWAY_PX 6.0
#define AWAY_LEVELS 2
#define AWAY_SHARE_MAX 0.001

static ww_scene *load_file(const char *path) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load(path, NULL, 0, &sc, &err);
    ENSURE_MSG(r == WW_OK, "%s", err.msg);
    return r == WW_OK ? sc : NULL;
}

static double dist_to_chord(const double p[3], const double a[3], const double b[3]) {
    double ab[3], ap[3], c[3];
    ww_m_sub3(b, a, ab);
    ww_m_sub3(p, a, ap);
    ww_m_cross3(ab, ap, c);
    return ww_m_len3(c) / ww_m_len3(ab);
}

TEST(line_runs_from_the_tip_to_the_lure_and_never_under_the_water) {
    ww_scene *sc = load_file(FISHING);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    int seen[4] = {0}, lying = 0;
    double worst_under = 0.0, worst_bend = 0.0;
    /* every other frame of the scene's three casts: held from the camera, then from a place */
    for (int64_t step = 0; step < 30 * 30 * sc->steps_per_frame; step += 2 * sc->steps_per_frame) {
        if (!ww_test_run_to(sc, st, step)) break;
        double p[WW_LINE_SEGMENTS + 1][3], tip[3];
        int n = ww_line_points(sc, st, p), state = (int)st->lure_state[0];
        ENSURE_EQ_INT(n > 0, state != WW_LURE_IDLE);
        if (n == 0) continue;
        seen[state]++;
        ENSURE(ww_line_tip(sc, st, tip));
        if (st->rod_held[0] != 0.0) {
            double held[3], f[3];
            ww_rod_held_tip(sc, st, held, f);
            for (int k = 0; k < 3; k++) ENSURE_NEAR(tip[k], held[k], END_TOL);
        } else {
            static const double from[3] = {-6, 1, -9}; /* the third cast's `from` */
            for (int k = 0; k < 3; k++) ENSURE_NEAR(tip[k], from[k], END_TOL);
        }
        const double *l = st->lure_pos;
        for (int k = 0; k < 3; k++) {
            ENSURE_NEAR(p[0][k], tip[k], END_TOL);
            ENSURE_NEAR(p[n - 1][k], l[k] + (k == 1 ? 0.5 * WW_LURE_SIZE : 0.0), END_TOL);
        }
        int on_water = 0;
        for (int i = 1; i < n - 1; i++) {
            ww_water_sample w;
            ww_water_at(sc, st, p[i][0], p[i][2], 0.0, &w);
            worst_under = fmax(worst_under, w.height - p[i][1]);
            on_water += p[i][1] - w.height < ON_WATER_TOL;
            double chord[3];
            ww_m_sub3(p[n - 1], p[0], chord);
            if (state == WW_LURE_HOOKED)
                worst_bend = fmax(worst_bend,
                                  dist_to_chord(p[i], p[0], p[n - 1]) / ww_m_len3(chord));
        }
        lying += state == WW_LURE_FLOATING && on_water > 0;
    }
    printf("  frames with a line: flying %d, floating %d (lying on the water %d), hooked %d; "
           "deepest under the surface %.3g m, straightest bend %.3g\n",
           seen[WW_LURE_FLYING], seen[WW_LURE_FLOATING], lying, seen[WW_LURE_HOOKED], worst_under,
           worst_bend);
    ENSURE(seen[WW_LURE_FLYING] > 0 && seen[WW_LURE_FLOATING] > 0 && seen[WW_LURE_HOOKED] > 0);
    ENSURE_MSG(worst_under <= 0.0, "a point of the line %.3g m under the water", worst_under);
    ENSURE_MSG(lying == seen[WW_LURE_FLOATING], "a slack line off the water in %d frames",
               seen[WW_LURE_FLOATING] - lying);
    ENSURE_MSG(worst_bend <= TAUT_BEND_MAX, "a line under a fish bends by %.3g of its length",
               worst_bend);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(line_ribbons_are_two_pixels_wide_or_their_width) {
    ww_scene *sc = load_file(FISHING);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    if (!ww_test_run_to(sc, st, 50 * sc->steps_per_frame)) return; /* the first cast in flight */
    ww_line_eye eye = {.pixel_angle = 2.0 * tan(0.5 * st->cam_fov[0]) / sc->height,
                       .near = sc->near_clip};
    for (int k = 0; k < 3; k++) eye.pos[k] = st->cam_pos[k], eye.fwd[k] = st->cam_fwd[k];
    static float vert[8 * WW_LINE_MAX_VERTS];
    static uint32_t index[WW_LINE_MAX_INDEX];
    double p[WW_ROD_SEGMENTS + 1][3], width[WW_ROD_SEGMENTS + 1];
    for (int which = 0; which < 2; which++) {
        int nvert, nindex = ww_line_build(sc, st, &eye, (ww_strand)which, vert, index, &nvert);
        ENSURE_MSG(nindex > 0, "strand %d: nothing built", which);
        /* two triangles a segment of each polyline: the rod; the line and its run up the rod */
        int polylines = which == WW_STRAND_ROD ? 1 : 2;
        ENSURE_EQ_INT(nindex, 3 * nvert - 6 * polylines);
        int n = which == WW_STRAND_ROD ? ww_line_rod_points(sc, st, p, width) : nvert / 2;
        for (int i = 0; i < nvert / 2; i++) {
            const float *a = vert + 16 * i, *b = a + 8;
            double gap = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                              (a[2] - b[2]) * (a[2] - b[2]));
            double mid[3] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
            double px = fmax(ww_m_dot3(mid, eye.fwd), eye.near) * eye.pixel_angle;
            double w = which == WW_STRAND_ROD && i < n ? width[i] : sc->rod.line_width;
            ENSURE_NEAR(gap / fmax(w, 2.0 * px), 1.0, RIBBON_WIDTH_TOL);
            ENSURE_NEAR(a[7] / (w / px), 1.0, RIBBON_WIDTH_TOL);
            ENSURE(a[6] == -1.0f && b[6] == 1.0f);
        }
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

/* ---- the rendered line ------------------------------------------------------------------- */

/* the largest channel difference of a and b within r px of (x, y) */
static int diff_near(const ww_test_pic *a, const ww_test_pic *b, double x, double y, double r) {
    int most = 0;
    for (int j = (int)floor(y - r); j <= (int)ceil(y + r); j++)
        for (int i = (int)floor(x - r); i <= (int)ceil(x + r); i++) {
            if (i < 0 || j < 0 || i >= a->w || j >= a->h) continue;
            if (hypot(i + 0.5 - x, j + 0.5 - y) > r) continue;
            const unsigned char *p = ww_test_pixel(&a->im, i, j), *q = ww_test_pixel(&b->im, i, j);
            for (int c = 0; c < 3; c++) most = abs(p[c] - q[c]) > most ? abs(p[c] - q[c]) : most;
        }
    return most;
}

/* a strand projected: samples about a pixel apart with the drawn half width there, px */
typedef struct sample {
    double x, y, half;
} sample;

static int strand_samples(const ww_scene *sc, const ww_state *st, const double (*p)[3],
                          const double *width, double line_width, int n, sample *out, int cap) {
    double pixel_angle = 2.0 * tan(0.5 * st->cam_fov[0]) / sc->height;
    int m = 0;
    for (int i = 0; i + 1 < n; i++) {
        double a[2], b[2];
        ww_test_project(sc, st, p[i], a);
        ww_test_project(sc, st, p[i + 1], b);
        double d[3];
        ww_m_sub3(p[i], st->cam_pos, d);
        double z = ww_m_dot3(d, st->cam_fwd);
        if (z <= sc->near_clip) continue; /* behind the camera: the rod's butt */
        double w = width ? width[i] : line_width;
        double half = fmax(0.5 * w / (z * pixel_angle), 1.0);
        int k = (int)ceil(hypot(b[0] - a[0], b[1] - a[1]));
        for (int j = 0; j < k && m < cap; j++) {
            double u = (double)j / k;
            out[m++] = (sample){a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), half};
        }
    }
    return m;
}

TEST_IMAGE(picture_line_seen_from_the_rod_to_the_lure) {
    REQUIRE_GL();
    ww_scene *sc = load_file(FISHING);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    /* the first cast in flight, floating, and under a fish */
    static const int frames[] = {50, 70, 120};
    enum { CAP = 20000 };
    sample *line = malloc(CAP * sizeof *line), *rod = malloc(CAP * sizeof *rod);
    for (int f = 0; f < 3 && line && rod; f++) {
        ww_test_pic with = {0}, none = {0};
        char args[64];
        snprintf(args, sizeof args, "--set objects.rod.line_width=0");
        if (!ww_test_render_pic(FISHING, frames[f], "1280x720", NULL, "line", &with) ||
            !ww_test_render_pic(FISHING, frames[f], "1280x720", args, "none", &none) ||
            !ww_test_run_to(sc, st, frames[f] * sc->steps_per_frame))
            break;
        double p[WW_LINE_SEGMENTS + 1][3], rp[WW_ROD_SEGMENTS + 1][3], rw[WW_ROD_SEGMENTS + 1];
        int n = ww_line_points(sc, st, p), nr = ww_line_rod_points(sc, st, rp, rw);
        ENSURE_MSG(n > 0 && nr > 0, "frame %d: no line or no rod out", frames[f]);
        int ml = strand_samples(sc, st, (const double(*)[3])p, NULL, sc->rod.line_width, n, line,
                                CAP);
        int mr = strand_samples(sc, st, (const double(*)[3])rp, rw, 0.0, nr, rod, CAP);
        int in_frame = 0, seen = 0;
        for (int i = 0; i < ml; i++) {
            const sample *s = &line[i];
            if (s->x < 2 || s->y < 2 || s->x > with.w - 2 || s->y > with.h - 2) continue;
            in_frame++;
            seen += diff_near(&with, &none, s->x, s->y, SEEN_RADIUS) >= SEEN_LEVELS;
        }
        /* every pixel that changed away from both strands */
        long away = 0;
        for (int y = 0; y < with.h; y++)
            for (int x = 0; x < with.w; x++) {
                if (!ww_test_moved_near(&with, &none, x, y, 0, AWAY_LEVELS)) continue;
                int near = 0;
                for (int i = 0; i < ml + mr && !near; i++) {
                    const sample *s = i < ml ? &line[i] : &rod[i - ml];
                    near = hypot(x + 0.5 - s->x, y + 0.5 - s->y) <= s->half + AWAY_PX;
                }
                away += !near;
            }
        double share = in_frame ? (double)seen / in_frame : 0.0;
        double away_share = (double)away / ((double)with.w * with.h);
        printf("  frame %d: the line seen along %d of %d px in the frame (%.3f); %ld pixels "
               "changed away from it (%.5f of the frame)\n",
               frames[f], seen, in_frame, share, away, away_share);
        ENSURE_MSG(in_frame > 100, "frame %d: only %d px of the line in the frame", frames[f],
                   in_frame);
        ENSURE_MSG(share >= SEEN_SHARE, "frame %d: the line seen along %.3f of its length",
                   frames[f], share);
        ENSURE_MSG(away_share <= AWAY_SHARE_MAX, "frame %d: %.5f of the frame changed away from "
                   "the line and the rod", frames[f], away_share);
        ww_image_free(&with.im);
        ww_image_free(&none.im);
    }
    free(line);
    free(rod);
    ww_state_free(st);
    ww_scene_free(sc);
}
