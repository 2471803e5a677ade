/* camera.c - keyframe interpolation of the camera path (see camera.h). Tangents follow the
 * finite-difference (Catmull-Rom) rule for non-uniform key times: m_i = (p_{i+1} - p_{i-1}) /
 * (t_{i+1} - t_{i-1}), one-sided at the ends, then cubic Hermite on each segment.
 */
#include "sim/camera.h"

#include <math.h>
#include <stddef.h>

#include "core/mathx.h"

void ww_camera_dir(double yaw, double pitch, double fwd[3]) {
    fwd[0] = sin(yaw) * cos(pitch);
    fwd[1] = sin(pitch);
    fwd[2] = -cos(yaw) * cos(pitch);
}

/* the keys' yaw and pitch, unwrapped so consecutive keys differ by at most pi in yaw */
typedef struct {
    double yaw[WW_MAX_KEYS];
    double pitch[WW_MAX_KEYS];
} keyset;

/* what every channel of segment i at u shares: the keys its tangents read, their spans, and
 * the cubic Hermite weights of p0, m0, p1 and m1 */
typedef struct segment {
    int i, a0, b1;       /* the tangent at key i reads keys a0 and i + 1, that at i + 1 keys i
                          * and b1 */
    int linear;          /* WW_INTERP_LINEAR: lerp p0 to p1 */
    double u, h;         /* the local parameter and the segment's length, s */
    double span0, span1; /* t[i + 1] - t[a0], t[b1] - t[i] */
    double w[4];
} segment;

static segment segment_at(const ww_scene *sc, int i, double u, double h) {
    int n = sc->ncam;
    segment g = {.i = i, .a0 = i > 0 ? i - 1 : i, .b1 = i + 2 < n ? i + 2 : i + 1,
                 .linear = sc->interp == WW_INTERP_LINEAR, .u = u, .h = h};
    g.span0 = sc->cam[i + 1].t - sc->cam[g.a0].t;
    g.span1 = sc->cam[g.b1].t - sc->cam[i].t;
    double u2 = u * u, u3 = u2 * u;
    g.w[0] = 2 * u3 - 3 * u2 + 1;
    g.w[1] = u3 - 2 * u2 + u;
    g.w[2] = -2 * u3 + 3 * u2;
    g.w[3] = u3 - u2;
    return g;
}

/* one channel on the segment from its values at keys a0, i, i + 1 and b1: the finite-difference
 * tangents (each key's neighbours differ, as n >= 2), then cubic Hermite */
static double segment_value(const segment *g, double va, double v0, double v1, double vb) {
    if (g->linear) return ww_m_lerp(v0, v1, g->u);
    double m0 = (v1 - va) / g->span0 * g->h, m1 = (vb - v0) / g->span1 * g->h;
    return g->w[0] * v0 + g->w[1] * m0 + g->w[2] * v1 + g->w[3] * m1;
}

/* component c of a point of the keys (position or look_at, offset in ww_camera_key) */
static double segment_point(const ww_scene *sc, const segment *g, size_t offset, int c) {
#define KEY_POINT(k) ((const double *)(const void *)((const char *)&sc->cam[k] + offset))[c]
    return segment_value(g, KEY_POINT(g->a0), KEY_POINT(g->i), KEY_POINT(g->i + 1),
                         KEY_POINT(g->b1));
#undef KEY_POINT
}

static double key_fov(const ww_scene *sc, int k) {
    return sc->cam[k].fov > 0.0 ? sc->cam[k].fov : sc->fov;
}

static void key_angles(const ww_camera_key *k, double *yaw, double *pitch) {
    if (!k->has_look_at) {
        *yaw = k->yaw;
        *pitch = k->pitch;
        return;
    }
    double d[3];
    ww_m_sub3(k->look_at, k->position, d);
    ww_m_normalize3(d);
    *yaw = atan2(d[0], -d[2]);
    *pitch = asin(ww_m_clamp(d[1], -1.0, 1.0));
}

/* the segment [i, i + 1] holding t, its local parameter u and length h; holds outside the path */
static void find_segment(const ww_scene *sc, double t, int *i, double *u, double *h) {
    int n = sc->ncam;
    *i = 0;
    *u = 0.0;
    *h = 1.0;
    if (n == 1 || t <= sc->cam[0].t) return;
    if (t >= sc->cam[n - 1].t) {
        *i = n - 2;
        *u = 1.0;
        *h = sc->cam[n - 1].t - sc->cam[n - 2].t;
        return;
    }
    /* binary search: cam[lo].t <= t < cam[hi].t */
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (t >= sc->cam[mid].t) lo = mid; else hi = mid;
    }
    *i = lo;
    *h = sc->cam[lo + 1].t - sc->cam[lo].t;
    *u = (t - sc->cam[lo].t) / *h;
}

/* the angles of keys lo .. hi (those the segment's Hermite tangents read), the yaw unwrapped so
 * neighbours differ by at most pi: only the segment's neighbourhood, so a step costs the same
 * whatever the path's length */
static void key_angles_near(const ww_scene *sc, int lo, int hi, keyset *ks) {
    for (int k = lo; k <= hi; k++) {
        key_angles(&sc->cam[k], &ks->yaw[k], &ks->pitch[k]);
        if (k > lo) {
            while (ks->yaw[k] - ks->yaw[k - 1] > WW_PI) ks->yaw[k] -= WW_TAU;
            while (ks->yaw[k] - ks->yaw[k - 1] < -WW_PI) ks->yaw[k] += WW_TAU;
        }
    }
}

void ww_camera_eval(const ww_scene *sc, double t, double pos[3], double fwd[3], double *fov) {
    keyset ks; /* the angles are filled where they are read (key_angles_near) */
    int n = sc->ncam, i;
    double u, h;
    WW_ASSERT(n >= 1);
    find_segment(sc, t, &i, &u, &h);
    int lo = i > 0 ? i - 1 : 0, hi = i + 2 < n ? i + 2 : n - 1;

    if (n == 1) {
        key_angles_near(sc, 0, 0, &ks);
        for (int c = 0; c < 3; c++) pos[c] = sc->cam[0].position[c];
        ww_camera_dir(ks.yaw[0], ks.pitch[0], fwd);
        *fov = key_fov(sc, 0);
        return;
    }
    segment g = segment_at(sc, i, u, h);
    for (int c = 0; c < 3; c++)
        pos[c] = segment_point(sc, &g, offsetof(ww_camera_key, position), c);
    *fov = segment_value(&g, key_fov(sc, g.a0), key_fov(sc, i), key_fov(sc, i + 1),
                         key_fov(sc, g.b1));

    /* target interpolation needs every key of the path to aim at a point (camera.h); then the
     * keys' angles are not needed */
    int all_targets = 1;
    for (int k = 0; k < n && all_targets; k++) all_targets &= sc->cam[k].has_look_at;
    double target[3], d[3];
    if (all_targets) {
        for (int c = 0; c < 3; c++)
            target[c] = segment_point(sc, &g, offsetof(ww_camera_key, look_at), c);
        ww_m_sub3(target, pos, d);
        if (ww_m_len3(d) > 1e-9) {
            ww_m_normalize3(d);
            for (int c = 0; c < 3; c++) fwd[c] = d[c];
            return;
        }
    }
    key_angles_near(sc, lo, hi, &ks);
    double pitch = segment_value(&g, ks.pitch[g.a0], ks.pitch[i], ks.pitch[i + 1], ks.pitch[g.b1]);
    pitch = ww_m_clamp(pitch, ww_m_rad(-89.9), ww_m_rad(89.9));
    ww_camera_dir(segment_value(&g, ks.yaw[g.a0], ks.yaw[i], ks.yaw[i + 1], ks.yaw[g.b1]), pitch,
                  fwd);
}

void ww_camera_update(const ww_scene *sc, ww_state *st) {
    ww_camera_eval(sc, st->t, st->cam_pos, st->cam_fwd, st->cam_fov);
}
