/* cubes.h - floating cubes: buoyancy, drag, tilt, press and release (seed 000).
 *
 *   ww_cubes_reset(sc, st);          // step 0: the described poses, at rest (ww_state_reset)
 *   ww_cubes_event(sc, st, ev);      // WW_EV_PRESS (step.c's dispatch)
 *   ww_cubes_step(sc, st);           // one step, st->t - dt -> st->t (nothing at step 0)
 *
 * The model (sim/cubes.c has the formulas and sources):
 *   archimedes  buoyancy rho_w g V_sub from the box's submerged volume against the exact surface
 *               (ww_water_at), integrated over columns x columns prisms along the box axis
 *               nearest the vertical; the torque of the buoyancy about the centre, at the
 *               centre of buoyancy, tilts the box toward the surface slope (and turns a box
 *               with a negative metacentric height over).
 *   spring      seed 000: v_y += k (y_surface + offset - y) dt, v_y *= e^(-c dt); the up axis
 *               is pulled toward the surface normal by the same spring.
 * Water drag (linear and quadratic, relative to the water's velocity, scaled by the submerged
 * fraction), the ripple slope force, press and release. The Archimedes heave is advanced by
 * the implicit midpoint rule with the discrete gradient of the buoyancy's exact piecewise-linear
 * potential, so stiff buoyancy cannot gain energy at any dt; the spring's heave by the exact
 * solution of its damped oscillator.
 *
 * WW_EV_PRESS payload: ev->index = cube, ev->v[0] = hold (s). A new press restarts the hold.
 * Emits WW_SE_CUBE_PRESS (magnitude: hold s) and WW_SE_CUBE_RELEASE (magnitude: the release
 * impulse m (J0 + J1 min(held, Tmax)), N s), and a ripple at the release.
 */
#ifndef WW_CUBES_H
#define WW_CUBES_H

#include "sim/boxwater.h"
#include "sim/state.h"

#define WW_WATER_RHO 1000.0 /* kg/m^3 */

/* step 0 (called by ww_state_reset when sc->cubes.on) */
void ww_cubes_reset(const ww_scene *sc, ww_state *st);
/* one step (when sc->cubes.on) */
void ww_cubes_step(const ww_scene *sc, ww_state *st);
/* WW_EV_PRESS */
void ww_cubes_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

/* what the water does to cube i at its pose in st, at st->t (Archimedes columns, sim/boxwater.h) */
typedef ww_box_water ww_cube_water;

void ww_cubes_water(const ww_scene *sc, const ww_state *st, int i, ww_cube_water *out);

#endif
