/* wake.c - the boat's wake as a ribbon on the water (wake.h) */
#include "gfx/wake.h"

#include <math.h>

#include "core/mathx.h"
#include "gfx/meshgen.h"

#define WAKE_SPEED_MIN 0.5  /* m/s: slower, the hull leaves no wake worth drawing ... */
#define WAKE_SPEED_FULL 4.0 /* ... and from this speed its full one */
#define MIN_SPACING 0.05    /* m of path: a trail point closer to the last one is left out */
#define END_FADE 2.0        /* m of path: the trail's oldest end fades out over this */
#define TURN_FILL 0.8       /* the ribbon's half width is at most this share of the path's
                             * radius of turn, so its inner edge never folds over itself */

static double smooth01(double a, double b, double x) {
    double t = ww_m_clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double ww_wake_hull_half(const ww_scene *sc, double ahead) {
    return sc->boat.length * ww_meshgen_hull_waterline(ahead / sc->boat.length);
}

int ww_wake_rows(const ww_scene *sc, const ww_state *st, ww_wake_row *row, int *stern) {
    if (!sc->boat.on || !(sc->boat.wake > 0.0)) return 0;
    double c = cos(st->boat_heading[0]), s = sin(st->boat_heading[0]), len = sc->boat.length;
    double sx = st->boat_pos[0] - 0.5 * len * c, sz = st->boat_pos[2] - 0.5 * len * s;
    double spread = tan(ww_m_rad(WW_WAKE_KELVIN_DEG)), odo0 = st->boat_odometer[0];
    double speed = fabs(st->boat_speed[0]);
    double now = sc->boat.wake * smooth01(WAKE_SPEED_MIN, WAKE_SPEED_FULL, speed);

    /* along the hull as it lies now, from ahead of the stem to the stern: the bow wave hugs
     * the hull until the wedge from the stem runs outside it */
    int n = 0;
    for (int j = 0; j <= WW_WAKE_HULL_ROWS; j++) {
        double a = j == 0 ? len + WW_WAKE_STEM_AHEAD
                          : len * (1.0 - (double)(j - 1) / (WW_WAKE_HULL_ROWS - 1));
        if (j == WW_WAKE_HULL_ROWS) a = 0.0; /* the stern */
        ww_wake_row *r = &row[n++];
        r->p[0] = sx + a * c;
        r->p[1] = sz + a * s;
        r->age = 0.0;
        r->odo = odo0 + a;
        r->half = j == 0 ? 0.5 * WW_WAKE_BAND
                         : fmax(ww_wake_hull_half(sc, a) + WW_WAKE_BAND, (len - a) * spread);
        r->strength = j == 0 ? 0.0 : now;
    }
    *stern = n - 1;

    /* the stern's trail back */
    int next = (int)st->boat_wake_next[0];
    for (int k = 1; k <= WW_BOAT_WAKE; k++) {
        const double *w = st->boat_wake + 4 * ((next - k + WW_BOAT_WAKE) % WW_BOAT_WAKE);
        double age = st->t - w[2];
        if (!(age >= 0.0 && age <= WW_WAKE_LIFE)) break;
        const ww_wake_row *last = &row[n - 1];
        if (last->odo - w[3] < MIN_SPACING) continue; /* the hull barely moved since */
        ww_wake_row *r = &row[n++];
        r->p[0] = w[0];
        r->p[1] = w[1];
        r->age = age;
        r->odo = w[3];
        r->half = fmax(ww_wake_hull_half(sc, 0.0) + WW_WAKE_BAND, (len + odo0 - w[3]) * spread);
        /* the boat's speed when its stern passed here */
        double v = (last->odo - w[3]) / fmax(age - last->age, 1e-9);
        r->strength = sc->boat.wake * smooth01(WAKE_SPEED_MIN, WAKE_SPEED_FULL, v) *
                      (1.0 - smooth01(0.6 * WW_WAKE_LIFE, WW_WAKE_LIFE, age));
    }
    if (n == *stern + 1) return 0;
    for (int i = *stern + 1; i < n; i++) {
        row[i].strength *= smooth01(0.0, END_FADE, row[i].odo - row[n - 1].odo);
        if (i == n - 1) continue;
        /* the radius of the turn through this point: the shorter segment over the angle */
        const double *p0 = row[i - 1].p, *p1 = row[i].p, *p2 = row[i + 1].p;
        double a[2] = {p1[0] - p2[0], p1[1] - p2[1]}, b[2] = {p0[0] - p1[0], p0[1] - p1[1]};
        double la = hypot(a[0], a[1]), lb = hypot(b[0], b[1]);
        double turn = atan2(fabs(a[0] * b[1] - a[1] * b[0]), a[0] * b[0] + a[1] * b[1]);
        if (turn > 1e-9) row[i].half = fmin(row[i].half, TURN_FILL * fmin(la, lb) / turn);
    }
    return n;
}

int ww_wake_build(const ww_scene *sc, const ww_state *st, const ww_line_eye *eye, float *vert,
                  uint32_t *index, int *nvert, double stern[2]) {
    ww_wake_row row[WW_WAKE_MAX_ROWS];
    *nvert = 0;
    int s0 = 0, n = ww_wake_rows(sc, st, row, &s0);
    if (n == 0) return 0;
    stern[0] = row[s0].odo;
    stern[1] = ww_wake_hull_half(sc, 0.0);
    for (int i = 0; i < n; i++) {
        /* across the path, level: from the older neighbour toward the newer */
        const double *a = row[i < n - 1 ? i + 1 : n - 1].p, *b = row[i > 0 ? i - 1 : 0].p;
        double d[2] = {b[0] - a[0], b[1] - a[1]}, l = hypot(d[0], d[1]);
        double across[2] = {l > 0.0 ? -d[1] / l : 0.0, l > 0.0 ? d[0] / l : 1.0};
        /* a row of points across, at the rest level: the vertex shader puts each on the
         * surface over it (geometry.vert.glsl), so the ribbon follows the waves across too */
        for (int j = 0; j < WW_WAKE_ACROSS; j++) {
            double s = -1.0 + 2.0 * j / (WW_WAKE_ACROSS - 1);
            double x = row[i].p[0] + s * row[i].half * across[0];
            double z = row[i].p[1] + s * row[i].half * across[1];
            float *v = vert + 8 * (WW_WAKE_ACROSS * i + j);
            v[0] = (float)(x - eye->pos[0]);
            v[1] = (float)(sc->water_level - eye->pos[1]);
            v[2] = (float)(z - eye->pos[2]);
            v[3] = (float)row[i].strength;
            v[4] = (float)row[i].age;
            v[5] = (float)row[i].odo;
            v[6] = (float)s;
            v[7] = (float)row[i].half;
        }
    }
    int m = 0;
    for (int i = 0; i + 1 < n; i++)
        for (int j = 0; j + 1 < WW_WAKE_ACROSS; j++) {
            uint32_t v0 = (uint32_t)(WW_WAKE_ACROSS * i + j), v1 = v0 + WW_WAKE_ACROSS;
            uint32_t tri[6] = {v0, v0 + 1, v1, v0 + 1, v1 + 1, v1};
            for (int k = 0; k < 6; k++) index[m++] = tri[k];
        }
    *nvert = WW_WAKE_ACROSS * n;
    return m;
}
