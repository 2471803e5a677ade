/* chest.c - the treasure chest: schedule, spawn on the seabed near the boat or the camera,
 * lifetime, collection within reach of the camera (model and departures from seed 000 in
 * chest.h). */
#include "sim/chest.h"

#include <math.h>

#include "core/mathx.h"
#include "core/rng.h"
#include "sim/camera.h"
#include "sim/events.h"

#define CHEST_TIME_EPS 1e-9 /* s: a time is reached on the step that comes within eps of it */

void ww_chest_place(double cx, double cz, double r, double u1, double u2, double out[2]) {
    double rho = r * sqrt(ww_m_clamp(u1, 0.0, 1.0)), th = WW_TAU * u2;
    double dx = rho * cos(th), dz = rho * sin(th);

    /* |(cos, sin)| may round to 1 + ulp: keep the edge on the disc */
    double d = sqrt(dx * dx + dz * dz);
    if (d > r && d > 0.0) {
        dx *= r / d;
        dz *= r / d;
    }
    out[0] = cx + dx;
    out[1] = cz + dz;
}

double ww_chest_distance(const double size[3], const double base[3], const double p[3]) {
    double lo[3] = {base[0] - 0.5 * size[0], base[1], base[2] - 0.5 * size[2]};
    double hi[3] = {base[0] + 0.5 * size[0], base[1] + size[1], base[2] + 0.5 * size[2]};
    double s = 0.0;
    for (int a = 0; a < 3; a++) {
        double d = p[a] < lo[a] ? lo[a] - p[a] : p[a] > hi[a] ? p[a] - hi[a] : 0.0;
        s += d * d;
    }
    return sqrt(s);
}

/* the previous step's camera; at step 0 (no camera yet) the path's first point */
static void camera_now(const ww_scene *sc, const ww_state *st, double p[3]) {
    if (st->step > 0) {
        for (int a = 0; a < 3; a++) p[a] = st->cam_pos[a];
        return;
    }
    double fwd[3], fov;
    ww_camera_eval(sc, st->t, p, fwd, &fov);
}

/* what the chest spawns around, XZ */
static void anchor(const ww_scene *sc, const ww_state *st, double out[2]) {
    int boat = sc->chest.near == WW_CHEST_NEAR_BOAT ||
               (sc->chest.near == WW_CHEST_NEAR_AUTO && sc->boat.on);
    if (boat && sc->boat.on) {
        out[0] = st->boat_pos[0];
        out[1] = st->boat_pos[2];
        return;
    }
    double p[3];
    camera_now(sc, st, p);
    out[0] = p[0];
    out[1] = p[2];
}

/* a new chest with its base centre at (x, z) on the seabed, replacing any present one */
static void spawn(const ww_scene *sc, ww_state *st, double x, double z) {
    if (st->chest_state[0] != 0.0) ww_emit(sc, st, WW_SE_CHEST_EXPIRE, 0, st->chest_pos, 0.0, 0.0);
    st->chest_pos[0] = x;
    st->chest_pos[1] = sc->water_level - sc->water_depth;
    st->chest_pos[2] = z;
    st->chest_state[0] = 1.0;
    st->chest_t0[0] = st->t;
    ww_emit(sc, st, WW_SE_CHEST_SPAWN, 0, st->chest_pos, sc->chest.ttl, 0.0);
}

/* the random rule: uniform over the disc around the anchor; draws k = 0, 1 of this step, or
 * 2, 3 for a scripted spawn (so a scripted and a scheduled spawn on one step differ) */
static void spawn_random(const ww_scene *sc, ww_state *st, uint64_t k) {
    double a[2], xz[2];
    anchor(sc, st, a);
    double u1 = ww_rng_draw(sc->seed, WW_RNG_CHEST, (uint64_t)st->step, k);
    double u2 = ww_rng_draw(sc->seed, WW_RNG_CHEST, (uint64_t)st->step, k + 1);
    ww_chest_place(a[0], a[1], sc->chest.radius, u1, u2, xz);
    spawn(sc, st, xz[0], xz[1]);
}

void ww_chest_reset(const ww_scene *sc, ww_state *st) {
    WW_ASSERT(sc->chest.every > 0.0);
    st->chest_state[0] = 0.0;
    st->prizes[0] = 0.0;
    st->chest_t0[0] = 0.0;
    st->chest_next[0] = sc->chest.first;
}

void ww_chest_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    if (ev->flags & WW_CHEST_AT)
        spawn(sc, st, ev->v[0], ev->v[1]);
    else
        spawn_random(sc, st, 2);
}

void ww_chest_step(const ww_scene *sc, ww_state *st) {
    const ww_chest_desc *d = &sc->chest;

    /* lifetime */
    if (st->chest_state[0] != 0.0 && st->t >= st->chest_t0[0] + d->ttl - CHEST_TIME_EPS) {
        st->chest_state[0] = 0.0;
        ww_emit(sc, st, WW_SE_CHEST_EXPIRE, 0, st->chest_pos, 0.0, 0.0);
    }

    /* the schedule: first + k every; a run that starts late skips the spawns it missed */
    if (st->t >= st->chest_next[0] - CHEST_TIME_EPS) {
        spawn_random(sc, st, 0);
        double k = floor((st->t + CHEST_TIME_EPS - d->first) / d->every) + 1.0;
        st->chest_next[0] = d->first + k * d->every;
    }

    /* collection: the camera within reach of the box (not at step 0: no camera yet) */
    if (st->chest_state[0] != 0.0 && st->step > 0 &&
        ww_chest_distance(d->size, st->chest_pos, st->cam_pos) <= d->reach) {
        st->chest_state[0] = 0.0;
        st->prizes[0] += 1.0;
        ww_emit(sc, st, WW_SE_CHEST_COLLECT, 0, st->chest_pos, st->prizes[0], 0.0);
    }
}
