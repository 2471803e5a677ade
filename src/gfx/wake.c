/* wake.c - the boat's wake as a ribbon on the water (wake.h) */
#include "gfx/wake.h"

#include <math.h>

#include "core/mathx.h"

#define WAKE_SPEED_MIN 0.5  /* m/s: slower, the hull leaves no wake worth drawing ... */
#define WAKE_SPEED_FULL 4.0 /* ... and from this speed its full one */
#define WASH_LIFE 1.2       /* s: the wash's foam fades by e in this */
#define ARM_LIFE 3.0        /* s: the arms' breaking crests, likewise */
#define MIN_SPACING 0.05    /* m of path: a trail point closer to the last one is left out */
#define END_FADE 2.0        /* m of path: the trail's oldest end fades out over this */
#define TURN_FILL 0.8       /* the ribbon's half width is at most this share of the path's
                             * radius of turn, so its inner edge never folds over itself */

static double smooth01(double a, double b, double x) {
    double t = ww_m_clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

int ww_wake_points(const ww_scene *sc, const ww_state *st, double (*p)[2], double *half,
                   double *age, double *odo) {
    if (!sc->boat.on || !(sc->boat.wake > 0.0)) return 0;
    double c = cos(st->boat_heading[0]), s = sin(st->boat_heading[0]);
    p[0][0] = st->boat_pos[0] - 0.5 * sc->boat.length * c;
    p[0][1] = st->boat_pos[2] - 0.5 * sc->boat.length * s;
    age[0] = 0.0;
    odo[0] = st->boat_odometer[0];
    int n = 1, next = (int)st->boat_wake_next[0];
    for (int k = 1; k <= WW_BOAT_WAKE; k++) {
        const double *w = st->boat_wake + 4 * ((next - k + WW_BOAT_WAKE) % WW_BOAT_WAKE);
        double a = st->t - w[2];
        if (!(a >= 0.0 && a <= WW_WAKE_LIFE)) break;
        if (odo[n - 1] - w[3] < MIN_SPACING) continue; /* the hull barely moved since */
        p[n][0] = w[0];
        p[n][1] = w[1];
        age[n] = a;
        odo[n++] = w[3];
    }
    if (n < 2) return 0;
    double spread = tan(ww_m_rad(WW_WAKE_KELVIN_DEG));
    for (int i = 0; i < n; i++) {
        half[i] = 0.5 * sc->boat.beam + spread * (odo[0] - odo[i]);
        if (i == 0 || i == n - 1) continue;
        /* the radius of the turn through this point: the shorter segment over the angle */
        double a[2] = {p[i][0] - p[i + 1][0], p[i][1] - p[i + 1][1]};
        double b[2] = {p[i - 1][0] - p[i][0], p[i - 1][1] - p[i][1]};
        double la = hypot(a[0], a[1]), lb = hypot(b[0], b[1]);
        double turn = atan2(fabs(a[0] * b[1] - a[1] * b[0]), a[0] * b[0] + a[1] * b[1]);
        if (turn > 1e-9) half[i] = fmin(half[i], TURN_FILL * fmin(la, lb) / turn);
    }
    return n;
}

int ww_wake_build(const ww_scene *sc, const ww_state *st, const ww_line_eye *eye, float *vert,
                  uint32_t *index, int *nvert) {
    double p[WW_BOAT_WAKE + 1][2], half[WW_BOAT_WAKE + 1], age[WW_BOAT_WAKE + 1],
        odo[WW_BOAT_WAKE + 1];
    *nvert = 0;
    int n = ww_wake_points(sc, st, p, half, age, odo);
    if (n == 0) return 0;
    for (int i = 0; i < n; i++) {
        /* the boat's speed when its stern passed here, and what is left of the foam */
        double speed = i == 0 ? fabs(st->boat_speed[0])
                              : (odo[i - 1] - odo[i]) / fmax(age[i] - age[i - 1], 1e-9);
        double strength = sc->boat.wake * smooth01(WAKE_SPEED_MIN, WAKE_SPEED_FULL, speed);
        double end = (1.0 - smooth01(0.6 * WW_WAKE_LIFE, WW_WAKE_LIFE, age[i])) *
                     smooth01(0.0, END_FADE, odo[i] - odo[n - 1]);
        double wash = strength * exp(-age[i] / WASH_LIFE) * end;
        double arm = strength * exp(-age[i] / ARM_LIFE) * end;
        /* across the path, level: from the older neighbour toward the newer */
        const double *a = p[i < n - 1 ? i + 1 : n - 1], *b = p[i > 0 ? i - 1 : 0];
        double d[2] = {b[0] - a[0], b[1] - a[1]}, l = hypot(d[0], d[1]);
        double across[2] = {l > 0.0 ? -d[1] / l : 0.0, l > 0.0 ? d[0] / l : 1.0};
        /* a row of points across, at the rest level: the vertex shader puts each on the
         * surface over it (geometry.vert.glsl), so the ribbon follows the waves across too */
        for (int j = 0; j < WW_WAKE_ACROSS; j++) {
            double s = -1.0 + 2.0 * j / (WW_WAKE_ACROSS - 1);
            double x = p[i][0] + s * half[i] * across[0], z = p[i][1] + s * half[i] * across[1];
            float *v = vert + 8 * (WW_WAKE_ACROSS * i + j);
            v[0] = (float)(x - eye->pos[0]);
            v[1] = (float)(sc->water_level - eye->pos[1]);
            v[2] = (float)(z - eye->pos[2]);
            v[3] = (float)wash;
            v[4] = (float)arm;
            v[5] = (float)odo[i];
            v[6] = (float)s;
            v[7] = (float)half[i];
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
