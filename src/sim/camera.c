/* camera.c - keyframe interpolation of the camera path (see camera.h). Tangents follow the
 * finite-difference (Catmull-Rom) rule for non-uniform key times: m_i = (p_{i+1} - p_{i-1}) /
 * (t_{i+1} - t_{i-1}), one-sided at the ends, then cubic Hermite on each segment.
 */
#include "sim/camera.h"

#include <math.h>

#include "core/mathx.h"

void ww_camera_dir(double yaw, double pitch, double fwd[3]) {
    fwd[0] = sin(yaw) * cos(pitch);
    fwd[1] = sin(pitch);
    fwd[2] = -cos(yaw) * cos(pitch);
}

/* the value of channel c of key i: position, look-at, yaw/pitch (unwrapped) or fov */
typedef struct {
    const ww_scene *sc;
    double yaw[WW_MAX_KEYS]; /* unwrapped so consecutive keys differ by at most pi */
    double pitch[WW_MAX_KEYS];
} keyset;

enum { CH_POS = 0, CH_TARGET = 3, CH_YAW = 6, CH_PITCH = 7, CH_FOV = 8 };

static double key_value(const keyset *ks, int i, int ch) {
    const ww_camera_key *k = &ks->sc->cam[i];
    if (ch < CH_TARGET) return k->position[ch];
    if (ch < CH_YAW) return k->look_at[ch - CH_TARGET];
    if (ch == CH_YAW) return ks->yaw[i];
    if (ch == CH_PITCH) return ks->pitch[i];
    return k->fov > 0.0 ? k->fov : ks->sc->fov;
}

/* derivative per second at key i */
static double key_slope(const keyset *ks, int i, int ch) {
    int n = ks->sc->ncam, a = i > 0 ? i - 1 : i, b = i < n - 1 ? i + 1 : i;
    if (a == b) return 0.0;
    return (key_value(ks, b, ch) - key_value(ks, a, ch)) / (ks->sc->cam[b].t - ks->sc->cam[a].t);
}

static double channel_at(const keyset *ks, int i, double u, double h, int ch) {
    double p0 = key_value(ks, i, ch), p1 = key_value(ks, i + 1, ch);
    if (ks->sc->interp == WW_INTERP_LINEAR) return ww_m_lerp(p0, p1, u);
    double m0 = key_slope(ks, i, ch) * h, m1 = key_slope(ks, i + 1, ch) * h;
    double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 +
           (u3 - u2) * m1;
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
    ks.sc = sc;
    int n = sc->ncam, i;
    double u, h;
    WW_ASSERT(n >= 1);
    find_segment(sc, t, &i, &u, &h);
    int lo = i > 0 ? i - 1 : 0, hi = i + 2 < n ? i + 2 : n - 1;

    if (n == 1) {
        key_angles_near(sc, 0, 0, &ks);
        for (int c = 0; c < 3; c++) pos[c] = key_value(&ks, 0, CH_POS + c);
        ww_camera_dir(ks.yaw[0], ks.pitch[0], fwd);
        *fov = key_value(&ks, 0, CH_FOV);
        return;
    }
    for (int c = 0; c < 3; c++) pos[c] = channel_at(&ks, i, u, h, CH_POS + c);
    *fov = channel_at(&ks, i, u, h, CH_FOV);

    /* target interpolation needs every key of the path to aim at a point (camera.h); then the
     * keys' angles are not needed */
    int all_targets = 1;
    for (int k = 0; k < n && all_targets; k++) all_targets &= sc->cam[k].has_look_at;
    double target[3], d[3];
    if (all_targets) {
        for (int c = 0; c < 3; c++) target[c] = channel_at(&ks, i, u, h, CH_TARGET + c);
        ww_m_sub3(target, pos, d);
        if (ww_m_len3(d) > 1e-9) {
            ww_m_normalize3(d);
            for (int c = 0; c < 3; c++) fwd[c] = d[c];
            return;
        }
    }
    key_angles_near(sc, lo, hi, &ks);
    double pitch = ww_m_clamp(channel_at(&ks, i, u, h, CH_PITCH), ww_m_rad(-89.9), ww_m_rad(89.9));
    ww_camera_dir(channel_at(&ks, i, u, h, CH_YAW), pitch, fwd);
}

void ww_camera_update(const ww_scene *sc, ww_state *st) {
    ww_camera_eval(sc, st->t, st->cam_pos, st->cam_fwd, st->cam_fov);
}
