/* bubbles.c - bubble emitters: releases at a rate into fixed pools, rise with a zigzag wobble in
 * closed form, burst at the exact surface (model and sources in bubbles.h). */
#include "sim/bubbles.h"

#include <math.h>

#include "core/exp.h"
#include "core/lanes.h"
#include "core/mathx.h"
#include "core/rng.h"
#include "core/sincos.h"
#include "sim/water.h"

#define BUBBLE_TIME_EPS 1e-9 /* s: a release is due on the step that comes within eps of it */
#define BUBBLE_SPEED_SPREAD 0.2 /* each bubble rises at speed (0.9 + 0.2 u) */

/* draws of bubble slot b: k = 0 phase, 1 plane, 2 speed, 3 radius; the emitter's stagger is
 * drawn past the last slot */
enum { DRAW_PHASE = 0, DRAW_PLANE, DRAW_SPEED, DRAW_RADIUS };

static double draw(const ww_scene *sc, int64_t step, int object, int k) {
    return ww_rng_draw(sc->seed, WW_RNG_BUBBLES, (uint64_t)step, (uint64_t)object * 16u + (uint64_t)k);
}

/* the wobble and the place below use ww_exp and ww_sincos: branch-free (the pools' loops
 * vectorise) and the same on every libm */
WW_LANE_STEP double wobble(double amplitude, double frequency, double phase, double age) {
    double w = WW_TAU * frequency * age, s, c;
    ww_sincos(w + phase, &s, &c);
    return amplitude * (1.0 - ww_exp(-w)) * s;
}

double ww_bubble_wobble(double amplitude, double frequency, double phase, double age) {
    return wobble(amplitude, frequency, phase, age);
}

/* where a bubble of emitter e released at t0 (its wobble's phase, its plane's heading and its
 * rise speed given) is at t */
WW_LANE_STEP void bubble_place(const ww_emitter_desc *e, double t, double t0, double phase,
                               double heading, double speed, double *x, double *y, double *z) {
    double age = t - t0, s = wobble(e->wobble, e->frequency, phase, age), sh, ch;
    ww_sincos(heading, &sh, &ch);
    *x = e->at[0] + s * ch;
    *y = e->at[1] + speed * age;
    *z = e->at[2] + s * sh;
}

/* place bubble b at age t - t0 */
static void place(const ww_emitter_desc *e, ww_state *st, int b) {
    double *p = st->bubble_pos + 3 * b;
    bubble_place(e, st->t, st->bubble_t0[b], st->bubble_wobble[2 * b],
                 st->bubble_wobble[2 * b + 1], st->bubble_speed[b], p, p + 1, p + 2);
}

/* place every rising bubble of emitter e: its pool in blocks of 8 slots, each block's places
 * worked out together (a slot past the pool repeats the block's first) and kept for the slots
 * that rise */
static WW_LANES void rise(const ww_emitter_desc *e, ww_state *st) {
    enum { B = 8 };
    for (int j0 = 0; j0 < e->count; j0 += B) {
        int m = e->count - j0 < B ? e->count - j0 : B;
        double t0[B], phase[B], heading[B], speed[B], x[B], y[B], z[B];
        for (int j = 0; j < B; j++) {
            int b = e->first + j0 + (j < m ? j : 0);
            t0[j] = st->bubble_t0[b];
            phase[j] = st->bubble_wobble[2 * b];
            heading[j] = st->bubble_wobble[2 * b + 1];
            speed[j] = st->bubble_speed[b];
        }
        for (int j = 0; j < B; j++)
            bubble_place(e, st->t, t0[j], phase[j], heading[j], speed[j], &x[j], &y[j], &z[j]);
        for (int j = 0; j < m; j++) {
            int b = e->first + j0 + j;
            if (st->bubble_on[b] == 0.0) continue;
            st->bubble_pos[3 * b] = x[j];
            st->bubble_pos[3 * b + 1] = y[j];
            st->bubble_pos[3 * b + 2] = z[j];
        }
    }
}

/* the bubble's top has reached the surface over it */
static int at_surface(const ww_scene *sc, const ww_state *st, int b, double floor_y) {
    const double *p = st->bubble_pos + 3 * b;
    double top = p[1] + st->bubble_radius[b];
    if (top < floor_y) return 0;
    ww_water_sample w;
    ww_water_at(sc, st, p[0], p[2], 0.0, &w);
    return top >= w.height;
}

/* release bubble b of emitter e at t0 with this step's draws; kept only when under water */
static void release(const ww_scene *sc, ww_state *st, const ww_emitter_desc *e, int b, double t0,
                    double floor_y) {
    st->bubble_t0[b] = t0;
    st->bubble_wobble[2 * b] = WW_TAU * draw(sc, st->step, b, DRAW_PHASE);
    st->bubble_wobble[2 * b + 1] = WW_TAU * draw(sc, st->step, b, DRAW_PLANE);
    st->bubble_speed[b] =
        e->speed * (1.0 - 0.5 * BUBBLE_SPEED_SPREAD + BUBBLE_SPEED_SPREAD * draw(sc, st->step, b, DRAW_SPEED));
    st->bubble_radius[b] = e->size * (0.5 + 0.5 * draw(sc, st->step, b, DRAW_RADIUS));
    place(e, st, b);
    st->bubble_on[b] = at_surface(sc, st, b, floor_y) ? 0.0 : 1.0;
}

/* a free slot of emitter e's pool, or -1 */
static int free_slot(const ww_emitter_desc *e, const ww_state *st) {
    for (int j = 0; j < e->count; j++)
        if (st->bubble_on[e->first + j] == 0.0) return e->first + j;
    return -1;
}

void ww_bubbles_reset(const ww_scene *sc, ww_state *st) {
    const ww_bubbles_desc *d = &sc->bubbles;
    double floor_y = ww_water_lowest(sc, st);
    for (int i = 0; i < d->count; i++) {
        const ww_emitter_desc *e = &d->emitter[i];
        double u = draw(sc, 0, d->total + i, 0), period = 1.0 / e->rate;

        /* warm: the pool holds the releases of the past, youngest first, while they are under
         * water (k = 0, -1, ...: at start - (j + u) / rate) */
        for (int j = 0; j < e->count; j++) {
            int b = e->first + j;
            st->bubble_on[b] = 0.0;
            release(sc, st, e, b, sc->start - ((double)j + u) * period, floor_y);
            if (st->bubble_on[b] == 0.0) break;
        }
        st->bubble_next[i] = sc->start + (1.0 - u) * period;
    }
}

void ww_bubbles_step(const ww_scene *sc, ww_state *st) {
    const ww_bubbles_desc *d = &sc->bubbles;
    double floor_y = ww_water_lowest(sc, st);
    for (int i = 0; i < d->count; i++) {
        const ww_emitter_desc *e = &d->emitter[i];

        /* rise; burst at the surface */
        rise(e, st);
        for (int j = 0; j < e->count; j++) {
            int b = e->first + j;
            if (st->bubble_on[b] != 0.0 && at_surface(sc, st, b, floor_y)) st->bubble_on[b] = 0.0;
        }

        /* releases due by now, into free slots; none free: skipped */
        double period = 1.0 / e->rate;
        while (st->t >= st->bubble_next[i] - BUBBLE_TIME_EPS) {
            int b = free_slot(e, st);
            if (b >= 0) release(sc, st, e, b, st->bubble_next[i], floor_y);
            st->bubble_next[i] += period;
        }
    }
}
