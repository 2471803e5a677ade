/* ripples.h - seed 000's damped radial ripples (scene.h: ww_ripple_desc), a bounded pool in the
 * state: each entry is (x, z, t0, A0); A0 = 0 marks a free slot.
 *
 *   h(r, age) = A0 e^(-alpha r) e^(-beta age) sin(kr (r - v age)) W(r, age)
 *
 * r is the distance to the centre softened near it (r = sqrt(d^2 + r0^2), so the surface has a
 * gradient at the centre), W the causal front of scene.h. Height, gradient and dh/dt are
 * analytic. The shader draws the same pool (shaders/gerstner.glsl).
 */
#ifndef WW_RIPPLES_H
#define WW_RIPPLES_H

#include "core/exp.h"
#include "core/lanes.h"
#include "core/sincos.h"
#include "sim/state.h"

#define WW_RIPPLE_STRIDE 4 /* doubles per pool entry: x, z, t0, A0 */
/* a point whose squared distance exceeds the front's squared radius by this factor is beyond
 * it whatever the rounding of the root (a few ulps), so W = 0 there without computing r */
#define WW_RIPPLE_FRONT_MARGIN (1.0 + 1e-12)

/* one entry's term at a point inside its front: at softened distance r from its centre, of age
 * age, amplitude amp, u = (v age - r) / lambda + 1 > 0 the place in the front (W = 1 from u = 1
 * on). Sets its height h and its derivatives along r and age. Branch-free and without libm
 * (ww_exp, ww_sincos), so the one-point sum (ripples.c) and the lanes' (sim/water.c, vectorised)
 * make the same bits; inlined into the lanes' clones (core/lanes.h). */
WW_LANE_STEP void ww_ripple_term(const ww_ripple_desc *d, double amp, double age, double r,
                                  double u, double lambda, double *h, double *dhdr,
                                  double *dhda) {
    double kr = d->wavenumber, v = d->speed;
    /* causal front: W = u^2 (3 - 2u) below u = 1, C1 there */
    double w = u < 1.0 ? u * u * (3.0 - 2.0 * u) : 1.0;
    double dw = u < 1.0 ? 6.0 * u * (1.0 - u) : 0.0;
    double env = amp * ww_exp(-d->radial_decay * r - d->time_decay * age);
    double s, c;
    ww_sincos(kr * (r - v * age), &s, &c);
    *h = env * s * w;
    /* dh/dr and dh/dage of env sin(psi) W */
    *dhdr = env * (-d->radial_decay * s * w + kr * c * w - s * dw / lambda);
    *dhda = env * (-d->time_decay * s * w - kr * v * c * w + s * dw * v / lambda);
}

/* add a ripple at (x, z) now (st->t); a full pool replaces its oldest entry. No-op when the
 * scene has no ripple pool. */
void ww_ripples_add(const ww_scene *sc, ww_state *st, double x, double z, double amplitude);
/* free the entries older than the lifetime */
void ww_ripples_prune(const ww_scene *sc, ww_state *st);
/* live entries in the pool */
int ww_ripples_count(const ww_scene *sc, const ww_state *st);

/* the sum of the pool's ripples at world (x, z) and time t: height (m, relative to the rest
 * level), and when not NULL the gradient (dh/dx, dh/dz) and dh/dt (m/s) */
double ww_ripples_height(const ww_scene *sc, const double *pool, double t, double x, double z,
                         double grad[2], double *dhdt);
/* the same over the pool's first nslots entries only (st->ripple_slots: the later ones are free;
 * a height query scans no more than that) */
double ww_ripples_height_n(const ww_scene *sc, const double *pool, int nslots, double t, double x,
                           double z, double grad[2], double *dhdt);

/* the entries of the pool's first nslots whose front can reach some point of the rectangle
 * lo..hi (x, z) at time t, copied in order to out (room for nslots entries); returns their
 * count. ww_ripples_height_n over them gives the same bits at every point of the rectangle as
 * over the whole pool: an entry left out is one it passes at each of those points. */
int ww_ripples_reaching(const ww_scene *sc, const double *pool, int nslots, double t,
                        const double lo[2], const double hi[2], double *out);

#endif
