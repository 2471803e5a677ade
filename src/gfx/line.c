/* line.c - the fishing line and its rod as ribbons facing the camera (line.h) */
#include "gfx/line.h"

#include <math.h>

#include "core/mathx.h"
#include "sim/rod.h"
#include "sim/water.h"

/* the line's sag at its middle, as a fraction of its straight length: behind a lure in flight
 * the line pays out nearly straight; from a floating lure it hangs slack, down onto the water,
 * where it lies; a fish pulls it straight */
#define SAG_FLYING 0.03
#define SAG_SLACK 0.25
#define SAG_TAUT 0.004
#define LINE_CLEARANCE 0.004 /* m: a line lying on the water rests this far over its surface */
/* the rod: its length, how steeply it rises to the tip along the cast, its width at the butt
 * and at the tip (m) */
#define ROD_LENGTH 1.4
#define ROD_PITCH 35.0 /* deg */
#define ROD_BUTT_WIDTH 0.02
#define ROD_TIP_WIDTH 0.006
#define REEL_AT 0.2        /* the reel's place along the rod from the butt: the line leaves it */
#define GUIDE_HEIGHT 0.006 /* m: the guides hold the line this far over the rod's top */

/* the rod's tip and the level direction it points along: where the camera holds it, or where
 * the cast left; 0 when no line is out */
static int rod_pose(const ww_scene *sc, const ww_state *st, double tip[3], double f[3]) {
    if (!sc->rod.on || (int)st->lure_state[0] == WW_LURE_IDLE) return 0;
    if (st->rod_held[0] != 0.0) {
        ww_rod_held_tip(sc, st, tip, f);
    } else {
        for (int k = 0; k < 3; k++) tip[k] = st->rod_tip[k], f[k] = st->rod_dir[k];
    }
    return 1;
}

int ww_line_tip(const ww_scene *sc, const ww_state *st, double tip[3]) {
    double f[3];
    return rod_pose(sc, st, tip, f);
}

int ww_line_points(const ww_scene *sc, const ww_state *st, double (*p)[3]) {
    double tip[3];
    if (!(sc->rod.line_width > 0.0) || !ww_line_tip(sc, st, tip)) return 0;
    const double *lure = st->lure_pos;
    double end[3] = {lure[0], lure[1] + 0.5 * WW_LURE_SIZE, lure[2]}; /* the stem's top */
    double d[3] = {end[0] - tip[0], end[1] - tip[1], end[2] - tip[2]};
    int state = (int)st->lure_state[0];
    double sag = (state == WW_LURE_FLYING   ? SAG_FLYING
                  : state == WW_LURE_HOOKED ? SAG_TAUT
                                            : SAG_SLACK) *
                 ww_m_len3(d);
    for (int i = 0; i <= WW_LINE_SEGMENTS; i++) {
        double u = (double)i / WW_LINE_SEGMENTS;
        for (int k = 0; k < 3; k++) p[i][k] = tip[k] + u * d[k];
        p[i][1] -= 4.0 * u * (1.0 - u) * sag;
        if (i == 0 || i == WW_LINE_SEGMENTS) continue;
        ww_water_sample w;
        ww_water_at(sc, st, p[i][0], p[i][2], 0.0, &w);
        if (p[i][1] < w.height + LINE_CLEARANCE) p[i][1] = w.height + LINE_CLEARANCE;
    }
    return WW_LINE_SEGMENTS + 1;
}

int ww_line_rod_points(const ww_scene *sc, const ww_state *st, double (*p)[3], double *width) {
    double tip[3], f[3];
    if (!(sc->rod.line_width > 0.0) || !rod_pose(sc, st, tip, f)) return 0;
    double c = cos(ww_m_rad(ROD_PITCH)), s = sin(ww_m_rad(ROD_PITCH));
    double dir[3] = {c * f[0], s, c * f[2]};
    for (int i = 0; i <= WW_ROD_SEGMENTS; i++) {
        double u = (double)i / WW_ROD_SEGMENTS; /* 0 the butt, 1 the tip */
        for (int k = 0; k < 3; k++) p[i][k] = tip[k] - (1.0 - u) * ROD_LENGTH * dir[k];
        width[i] = ROD_BUTT_WIDTH + u * (ROD_TIP_WIDTH - ROD_BUTT_WIDTH);
    }
    return WW_ROD_SEGMENTS + 1;
}

/* the ribbon along points p[0 .. n-1] of widths w (m), facing the eye: vertices from vert (8
 * floats each, numbered from base), two triangles a segment into index; returns the indices */
static int ribbon(const ww_line_eye *eye, const double (*p)[3], const double *w, int n,
                  float *vert, int base, uint32_t *index) {
    for (int i = 0; i < n; i++) {
        const double *a = p[i > 0 ? i - 1 : 0], *b = p[i < n - 1 ? i + 1 : n - 1];
        double t[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double e[3] = {p[i][0] - eye->pos[0], p[i][1] - eye->pos[1], p[i][2] - eye->pos[2]};
        double across[3];
        ww_m_cross3(t, e, across);
        if (!(ww_m_len3(across) > 1e-12)) { /* seen end on: any direction across it */
            double up[3] = {0.0, 1.0, 0.0};
            ww_m_cross3(t, up, across);
            if (!(ww_m_len3(across) > 1e-12)) across[0] = 1.0, across[1] = across[2] = 0.0;
        }
        ww_m_normalize3(across);
        double depth = fmax(ww_m_dot3(e, eye->fwd), eye->near);
        double px = depth * eye->pixel_angle;
        double half = fmax(0.5 * w[i], px); /* at least 2 pixels across */
        for (int side = 0; side < 2; side++) {
            float *v = vert + 8 * (2 * i + side);
            double s = side ? 1.0 : -1.0;
            for (int k = 0; k < 3; k++) {
                v[k] = (float)(e[k] + s * half * across[k]);
                v[3 + k] = (float)across[k];
            }
            v[6] = (float)s;
            v[7] = (float)(w[i] / px);
        }
    }
    int m = 0;
    for (int i = 0; i + 1 < n; i++) {
        uint32_t v0 = (uint32_t)(base + 2 * i);
        uint32_t tri[6] = {v0, v0 + 1, v0 + 2, v0 + 1, v0 + 3, v0 + 2};
        for (int k = 0; k < 6; k++) index[m++] = tri[k];
    }
    return m;
}

int ww_line_build(const ww_scene *sc, const ww_state *st, const ww_line_eye *eye,
                  ww_strand which, float *vert, uint32_t *index, int *nvert) {
    *nvert = 0;
    if (which == WW_STRAND_LINE) {
        double p[WW_LINE_SEGMENTS + 1][3], w[WW_LINE_SEGMENTS + 1];
        int n = ww_line_points(sc, st, p);
        if (n == 0) return 0;
        for (int i = 0; i < n; i++) w[i] = sc->rod.line_width;
        int m = ribbon(eye, (const double(*)[3])p, w, n, vert, 0, index);
        *nvert = 2 * n;
        /* from the reel up the rod's top to the tip, lying on the guides */
        double r[WW_ROD_SEGMENTS + 1][3], rw[WW_ROD_SEGMENTS + 1];
        int nr = ww_line_rod_points(sc, st, r, rw);
        if (nr > 0) {
            double up[3], axis[3];
            ww_m_sub3(r[nr - 1], r[0], axis);
            ww_m_normalize3(axis);
            /* the rod's top: the vertical less its part along the rod */
            for (int k = 0; k < 3; k++) up[k] = (k == 1) - axis[1] * axis[k];
            ww_m_normalize3(up);
            int first = (int)(REEL_AT * (nr - 1));
            double q[WW_ROD_SEGMENTS + 1][3];
            for (int i = first; i < nr; i++)
                for (int k = 0; k < 3; k++)
                    q[i - first][k] = r[i][k] + (0.5 * rw[i] + GUIDE_HEIGHT) * up[k];
            for (int k = 0; k < 3; k++) q[nr - 1 - first][k] = r[nr - 1][k]; /* through the tip */
            m += ribbon(eye, (const double(*)[3])q, w, nr - first, vert + 8 * *nvert, *nvert,
                        index + m);
            *nvert += 2 * (nr - first);
        }
        /* the leader, from a lure on the water down to the hook (a hooked fish's mouth) */
        int state = (int)st->lure_state[0];
        if (state == WW_LURE_FLOATING || state == WW_LURE_HOOKED) {
            const double *l = st->lure_pos;
            double q[2][3] = {{l[0], l[1], l[2]}, {l[0], l[1] - sc->rod.hook_depth, l[2]}};
            m += ribbon(eye, (const double(*)[3])q, w, 2, vert + 8 * *nvert, *nvert, index + m);
            *nvert += 4;
        }
        return m;
    }
    double p[WW_ROD_SEGMENTS + 1][3], w[WW_ROD_SEGMENTS + 1];
    int n = ww_line_rod_points(sc, st, p, w);
    if (n == 0) return 0;
    *nvert = 2 * n;
    return ribbon(eye, (const double(*)[3])p, w, n, vert, 0, index);
}
