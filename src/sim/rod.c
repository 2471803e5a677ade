/* rod.c - the rod and lure: the cast from the camera (or a given place), the exact flight under
 * gravity and exponential drag, a swept landing on the exact surface, floating, the active
 * window and reeling in. Model and formulas in rod.h (seed 000 section 3.4; the exact flight
 * update replaces the seed's first-order one).
 */
#include "sim/rod.h"

#include <math.h>

#include "core/mathx.h"
#include "sim/events.h"
#include "sim/ripples.h"
#include "sim/water.h"

#define SWEEP_MAX_SAMPLES 4096 /* a chord cap for absurd speeds: still a finite step */
#define BISECT_ITERATIONS 60   /* halves the crossing's time bracket down to dt 2^-60 */
#define SERIES_KS 1e-3         /* below this k s the drag terms use their Taylor series */

void ww_rod_charge_map(const ww_rod_desc *rod, double charge, double *angle, double *speed) {
    double c = ww_m_clamp(charge, 0.0, 1.0);
    *angle = rod->angle[0] + (1.0 - c) * (rod->angle[1] - rod->angle[0]);
    *speed = rod->speed[0] + c * (rod->speed[1] - rod->speed[0]);
}

void ww_rod_flight(const double p0[3], const double v0[3], const double g[3], double k, double s,
                   double p[3], double v[3]) {
    /* phi1 = (1 - e^(-ks)) / k and phi2 = (s - phi1) / k, by series where they cancel */
    double ks = k * s, e, phi1, phi2;
    if (ks < SERIES_KS) {
        e = exp(-ks);
        phi1 = s * (1.0 - ks / 2.0 + ks * ks / 6.0 - ks * ks * ks / 24.0);
        phi2 = s * s * (0.5 - ks / 6.0 + ks * ks / 24.0 - ks * ks * ks / 120.0);
    } else {
        e = exp(-ks);
        phi1 = -expm1(-ks) / k;
        phi2 = (s - phi1) / k;
    }
    for (int i = 0; i < 3; i++) {
        double pi = p0[i] + v0[i] * phi1 + g[i] * phi2;
        v[i] = v0[i] * e + g[i] * phi1;
        p[i] = pi;
    }
}

void ww_rod_reset(const ww_scene *sc, ww_state *st) {
    (void)sc;
    st->lure_state[0] = WW_LURE_IDLE;
    st->rod_fish[0] = -1.0;
    st->rod_casts[0] = 0.0;
    st->rod_held[0] = 0.0;
    for (int i = 0; i < 3; i++) {
        st->rod_tip[i] = st->cam_pos[i];
        st->rod_dir[i] = i == 0 ? 1.0 : 0.0;
        st->lure_pos[i] = st->cam_pos[i];
        st->lure_vel[i] = 0.0;
    }
}

void ww_rod_reel(const ww_scene *sc, ww_state *st) {
    if (st->lure_state[0] == WW_LURE_IDLE) return;
    ww_emit(sc, st, WW_SE_REEL, 0, st->lure_pos, st->rod_line_time[0], 0.0);
    st->lure_state[0] = WW_LURE_IDLE;
    st->rod_active_left[0] = 0.0;
    for (int i = 0; i < 3; i++) st->lure_vel[i] = 0.0;
}

void ww_rod_held_tip(const ww_scene *sc, const ww_state *st, double tip[3], double f[3]) {
    const ww_rod_desc *rod = &sc->rod;
    f[0] = 1.0, f[1] = 0.0, f[2] = 0.0;
    double h = hypot(st->cam_fwd[0], st->cam_fwd[2]);
    if (h > 1e-9) {
        f[0] = st->cam_fwd[0] / h;
        f[2] = st->cam_fwd[2] / h;
    }
    double right[3] = {-f[2], 0.0, f[0]};
    for (int i = 0; i < 3; i++)
        tip[i] = st->cam_pos[i] + rod->offset[0] * f[i] + rod->offset[1] * right[i];
    tip[1] += rod->offset[2];
}

void ww_rod_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    const ww_rod_desc *rod = &sc->rod;
    double angle = ev->v[1], speed = ev->v[0];
    if (ev->flags & WW_CAST_CHARGE) ww_rod_charge_map(rod, ev->v[2], &angle, &speed);

    /* where from, and the flat forward direction f */
    double start[3], f[3] = {1.0, 0.0, 0.0};
    if (ev->flags & WW_CAST_FROM) {
        f[0] = cos(ev->v[6]);
        f[2] = sin(ev->v[6]);
        for (int i = 0; i < 3; i++) start[i] = ev->v[3 + i];
    } else {
        ww_rod_held_tip(sc, st, start, f);
    }

    /* a new cast reels the old line in first (a hooked fish gets away, sim/fish.c) */
    ww_rod_reel(sc, st);
    for (int i = 0; i < 3; i++) {
        st->lure_pos[i] = start[i];
        st->lure_vel[i] = speed * cos(angle) * f[i];
    }
    st->lure_vel[1] = speed * sin(angle);
    st->lure_state[0] = WW_LURE_FLYING;
    st->rod_line_time[0] = 0.0;
    st->rod_active_left[0] = rod->window;
    st->rod_fish[0] = -1.0;
    st->rod_casts[0] += 1.0;
    /* where the line leaves and which way the rod points: a place given, or the rod the camera
     * holds (the renderer keeps its tip at the camera's offset as the camera moves) */
    st->rod_held[0] = ev->flags & WW_CAST_FROM ? 0.0 : 1.0;
    for (int i = 0; i < 3; i++) st->rod_tip[i] = start[i], st->rod_dir[i] = f[i];
    ww_emit(sc, st, WW_SE_ROD_CAST, 0, start, speed, 0.0);
}

/* height of the lure above the surface under it */
static double clearance(const ww_scene *sc, const ww_state *st, const double p[3]) {
    ww_water_sample w;
    ww_water_at(sc, st, p[0], p[2], 0.0, &w);
    return p[1] - w.height;
}

static void land(const ww_scene *sc, ww_state *st, const double p[3], const double v[3]) {
    const ww_rod_desc *rod = &sc->rod;
    /* the splash first: the lure floats on the surface it made */
    ww_ripples_add(sc, st, p[0], p[2], rod->splash);
    ww_water_sample w;
    ww_water_at(sc, st, p[0], p[2], 0.0, &w);
    double speed = ww_m_len3(v);
    st->lure_pos[0] = p[0];
    st->lure_pos[1] = w.height + rod->float_height;
    st->lure_pos[2] = p[2];
    st->lure_vel[0] = v[0];
    st->lure_vel[1] = 0.0;
    st->lure_vel[2] = v[2];
    st->lure_state[0] = WW_LURE_FLOATING;
    st->rod_active_left[0] = rod->window;
    ww_emit(sc, st, WW_SE_LURE_LAND, 0, st->lure_pos, speed, 0.0);
}

/* one flight step: the exact arc, swept against the surface */
static void fly(const ww_scene *sc, ww_state *st) {
    const ww_rod_desc *rod = &sc->rod;
    double dt = sc->dt, g[3] = {0.0, -rod->gravity * WW_G, 0.0};
    double p0[3], v0[3], p1[3], v1[3];
    for (int i = 0; i < 3; i++) {
        p0[i] = st->lure_pos[i];
        v0[i] = st->lure_vel[i];
    }
    /* cast from under the surface: it floats up where it is */
    if (clearance(sc, st, p0) <= 0.0) {
        land(sc, st, p0, v0);
        return;
    }
    ww_rod_flight(p0, v0, g, rod->drag, dt, p1, v1);
    double chord[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    double n = ceil(ww_m_len3(chord) / WW_LURE_SWEEP_STEP);
    int samples = n < 1.0 ? 1 : n > SWEEP_MAX_SAMPLES ? SWEEP_MAX_SAMPLES : (int)n;

    /* the first sub-interval whose end is at or under the surface, then bisection on time */
    double s_lo = 0.0, p[3], v[3];
    for (int j = 1; j <= samples; j++) {
        double s_hi = dt * (double)j / (double)samples;
        ww_rod_flight(p0, v0, g, rod->drag, s_hi, p, v);
        if (clearance(sc, st, p) > 0.0) {
            s_lo = s_hi;
            continue;
        }
        for (int it = 0; it < BISECT_ITERATIONS && s_hi - s_lo > 0.0; it++) {
            double s = 0.5 * (s_lo + s_hi);
            ww_rod_flight(p0, v0, g, rod->drag, s, p, v);
            if (clearance(sc, st, p) > 0.0) s_lo = s;
            else s_hi = s;
        }
        ww_rod_flight(p0, v0, g, rod->drag, s_hi, p, v);
        land(sc, st, p, v);
        return;
    }
    for (int i = 0; i < 3; i++) {
        st->lure_pos[i] = p1[i];
        st->lure_vel[i] = v1[i];
    }
}

/* floating: the horizontal velocity relaxes to the water's, the height follows the surface */
static void drift(const ww_scene *sc, ww_state *st) {
    const ww_rod_desc *rod = &sc->rod;
    ww_water_sample w;
    ww_water_at(sc, st, st->lure_pos[0], st->lure_pos[2], 0.0, &w);
    double a = exp(-rod->float_drag * sc->dt);
    for (int i = 0; i < 3; i += 2) {
        st->lure_vel[i] = w.velocity[i] + (st->lure_vel[i] - w.velocity[i]) * a;
        st->lure_pos[i] += st->lure_vel[i] * sc->dt;
    }
    ww_water_at(sc, st, st->lure_pos[0], st->lure_pos[2], 0.0, &w);
    st->lure_pos[1] = w.height + rod->float_height;
    st->lure_vel[1] = 0.0;
}

void ww_rod_step(const ww_scene *sc, ww_state *st) {
    int state = (int)st->lure_state[0];
    if (state == WW_LURE_IDLE) return;
    st->rod_line_time[0] += sc->dt;
    switch (state) {
    case WW_LURE_FLYING:
        fly(sc, st);
        /* a line that never came down (cast far above the water) runs out */
        if (st->lure_state[0] == WW_LURE_FLYING && st->rod_line_time[0] > sc->rod.window)
            ww_rod_reel(sc, st);
        break;
    case WW_LURE_FLOATING:
        drift(sc, st);
        st->rod_active_left[0] -= sc->dt;
        if (st->rod_active_left[0] <= 0.0) ww_rod_reel(sc, st);
        break;
    case WW_LURE_HOOKED: drift(sc, st); break; /* the fish holds it until the catch */
    default: break;
    }
}
