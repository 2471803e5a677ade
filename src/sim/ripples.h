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

#include "sim/state.h"

#define WW_RIPPLE_STRIDE 4 /* doubles per pool entry: x, z, t0, A0 */

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
