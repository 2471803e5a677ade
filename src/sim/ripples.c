/* ripples.c - the ripple pool of ripples.h: add, prune, and the analytic height, gradient and
 * time derivative of the sum.
 */
#include "sim/ripples.h"

#include <math.h>

#include "core/mathx.h"

/* a rectangle whose nearest squared distance exceeds the front's squared radius by this factor
 * has every point beyond it by far more than WW_RIPPLE_FRONT_MARGIN and the rounding of each
 * point's r^2 */
#define RECT_MARGIN (1.0 + 1e-9)

void ww_ripples_add(const ww_scene *sc, ww_state *st, double x, double z, double amplitude) {
    if (!sc->ripples_on || sc->ripples.max <= 0 || !(amplitude > 0.0)) return;
    double *pool = st->ripple;
    int slot = 0;
    for (int i = 0; i < sc->ripples.max; i++) {
        const double *e = pool + i * WW_RIPPLE_STRIDE;
        if (e[3] == 0.0) { /* a free slot */
            slot = i;
            break;
        }
        if (e[2] < pool[slot * WW_RIPPLE_STRIDE + 2]) slot = i; /* else the oldest */
    }
    double *e = pool + slot * WW_RIPPLE_STRIDE;
    if (slot >= st->ripple_slots[0]) st->ripple_slots[0] = slot + 1;
    e[0] = x;
    e[1] = z;
    e[2] = st->t;
    e[3] = amplitude;
}

void ww_ripples_prune(const ww_scene *sc, ww_state *st) {
    if (!sc->ripples_on) return;
    /* the slots from ripple_slots on are free (ww_ripples_add and this keep it so) */
    int top = 0;
    for (int i = 0; i < st->ripple_slots[0]; i++) {
        double *e = st->ripple + i * WW_RIPPLE_STRIDE;
        if (e[3] != 0.0 && st->t - e[2] > sc->ripples.lifetime)
            e[0] = e[1] = e[2] = e[3] = 0.0;
        if (e[3] != 0.0) top = i + 1;
    }
    st->ripple_slots[0] = top;
}

int ww_ripples_count(const ww_scene *sc, const ww_state *st) {
    int n = 0;
    if (!sc->ripples_on) return 0;
    for (int i = 0; i < sc->ripples.max; i++) n += st->ripple[i * WW_RIPPLE_STRIDE + 3] != 0.0;
    return n;
}

double ww_ripples_height(const ww_scene *sc, const double *pool, double t, double x, double z,
                         double grad[2], double *dhdt) {
    return ww_ripples_height_n(sc, pool, sc->ripples.max, t, x, z, grad, dhdt);
}

double ww_ripples_height_n(const ww_scene *sc, const double *pool, int nslots, double t, double x,
                           double z, double grad[2], double *dhdt) {
    double h = 0.0, gx = 0.0, gz = 0.0, ht = 0.0;
    if (sc->ripples_on && pool) {
        const ww_ripple_desc *d = &sc->ripples;
        double kr = d->wavenumber, v = d->speed;
        double lambda = WW_TAU / kr;   /* width of the front, m */
        double r0 = 1.0 / kr;          /* softening of the distance at the centre, m */
        int n = nslots < d->max ? nslots : d->max;
        for (int i = 0; i < n; i++) {
            const double *e = pool + i * WW_RIPPLE_STRIDE;
            double age = t - e[2];
            if (e[3] == 0.0 || age < 0.0) continue;
            double dx = x - e[0], dz = z - e[1], r2 = dx * dx + dz * dz + r0 * r0;
            /* causal front: W = 1 behind r = v age, 0 one wavelength ahead, C1 between. A point
             * surely beyond the front (by far more than rounding) is passed without the root */
            double front = v * age + lambda;
            if (front <= 0.0 || r2 > WW_RIPPLE_FRONT_MARGIN * front * front) continue;
            double r = sqrt(r2);
            double u = (v * age - r) / lambda + 1.0;
            if (u <= 0.0) continue;
            double th, dhdr, dhda;
            ww_ripple_term(d, e[3], age, r, u, lambda, &th, &dhdr, &dhda);
            h += th;
            /* the chain rule through r(x, z) */
            gx += dhdr * dx / r;
            gz += dhdr * dz / r;
            ht += dhda;
        }
    }
    if (grad) {
        grad[0] = gx;
        grad[1] = gz;
    }
    if (dhdt) *dhdt = ht;
    return h;
}

int ww_ripples_reaching(const ww_scene *sc, const double *pool, int nslots, double t,
                        const double lo[2], const double hi[2], double *out) {
    if (!sc->ripples_on || !pool) return 0;
    const ww_ripple_desc *d = &sc->ripples;
    double lambda = WW_TAU / d->wavenumber, r0 = 1.0 / d->wavenumber;
    int n = nslots < d->max ? nslots : d->max, kept = 0;
    for (int i = 0; i < n; i++) {
        const double *e = pool + i * WW_RIPPLE_STRIDE;
        double age = t - e[2];
        if (e[3] == 0.0 || age < 0.0) continue;
        double front = d->speed * age + lambda;
        if (front <= 0.0) continue;
        /* the rectangle's nearest point to the centre: every point's r^2 is at least this (a
         * gap is 0 where the centre lies between the sides) */
        double gx = e[0] < lo[0] ? lo[0] - e[0] : e[0] > hi[0] ? e[0] - hi[0] : 0.0;
        double gz = e[1] < lo[1] ? lo[1] - e[1] : e[1] > hi[1] ? e[1] - hi[1] : 0.0;
        double reach = RECT_MARGIN * WW_RIPPLE_FRONT_MARGIN * front * front;
        if (gx * gx + gz * gz + r0 * r0 > reach) continue;
        for (int k = 0; k < WW_RIPPLE_STRIDE; k++) out[kept * WW_RIPPLE_STRIDE + k] = e[k];
        kept++;
    }
    return kept;
}
