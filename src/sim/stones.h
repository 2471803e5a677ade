/* stones.h - thrown stones: flight, swept crossing of the surface, skipping or sinking, thuds
 * against cubes and the boat. A pool of WW_MAX_STONES slots in the state (fields_stones.h); a
 * throw takes a free slot, or the oldest stone's when none is free.
 *
 *   ww_stones_reset(sc, st);            // step 0: every slot free
 *   ww_stones_event(sc, st, ev);        // a WW_EV_THROW event (sim/step.c)
 *   ww_stones_step(sc, st);             // each step, after the cubes
 *
 * The throw event (compile_stones.c fills it):
 *   v[0] speed, m/s        v[1] downward angle, rad (seed 000: d = f cos a + (0, -sin a, 0))
 *   v[2] spin, rad/s       v[3..5] start position, m     v[6] heading, rad (0 = +x, pi/2 = +z)
 *   v[7] the charge 0..1 it was mapped from, -1 for an explicit throw
 *   flags & WW_THROW_FROM: start at v[3..5] along v[6]; else at st->cam_pos along the camera's
 *   heading (the camera as the step has it when the event is applied: the previous step's)
 *
 * Model (stones.c):
 * - flight: gravity, exact parabola per step; with drag C_d > 0 the quadratic air drag
 *   a = -(rho_air C_d pi a^2 / 2M) |v| v is integrated by classical RK4.
 * - swept contact: the path inside a step (the cubic Hermite through both ends: exactly the
 *   parabola without drag) is sampled at spacing <= 1/8 of the shortest wave
 *   and tested for f = y - h(x, z) changing sign against the exact surface of the waves
 *   (ww_water_height, frozen at the step's time; ripples are left out, see surface() in
 *   stones.c); the crossing time is found by Illinois regula falsi to 1e-13 of the
 *   step. Chords between samples are tested against cubes (slabs of the box grown by the stone's
 *   radius) and the boat (sphere grown likewise). The earliest contact is handled and the rest of
 *   the step continues from it (at most WW_STONE_CONTACTS_PER_STEP contacts).
 * - skip or sink: Clanet, Hersen & Bocquet (2004) and Bocquet (2003): the water pushes on the
 *   immersed part of the tilted disc with F = 1/2 rho C V_t^2 S; for a disc of radius a with
 *   attack angle alpha entering to depth h, S ~ 2 a h / sin(alpha) and the push is a spring
 *   F = kappa h, kappa = rho C a V^2 cos^2(beta) sin(alpha + beta) / sin(alpha) (the flat plate's
 *   normal force grows with the angle alpha + beta between plate and flow). The stone rebounds
 *   if its deepest point, from 1/2 kappa h^2 - M g h = 1/2 M (V sin beta)^2, stays above the
 *   disc's full immersion 2 a sin(alpha). Taking the stone's face along its path (alpha = beta,
 *   the throw the paper's magic angle describes), this is
 *       V^2 > V_min^2 = 4 a g / (sin(beta) (2 lambda cos^3(beta) - 1)),  lambda = 4 rho C a^3 / M
 *   which is infinite at beta = 0 (no lift), least near 23 deg and infinite again at
 *   beta_max = acos((2 lambda)^(-1/3)) whatever the speed (as for ricocheting spheres, whose limit
 *   18 deg / sqrt(specific gravity) Nagahiro & Hayakawa 2005 quote). The
 *   defaults give lambda = 1.408: beta_max = 44.9 deg, V_min = 1.8 m/s at 23 deg.
 *   beta is the angle between the stone's velocity and the surface's tangent plane.
 * - a skip: v' = -e_n v_N + c_t v_T about the surface normal (seed 000), at most max_bounces;
 *   a stone ripple and a stone_skip event. Otherwise it sinks: a full splash at splash_full or
 *   faster, else a tiny one; it then relaxes to the sinking speed (time constant
 *   WW_STONE_SINK_TAU) and its slot is freed on the seabed.
 * - a thud: impulse J = (1 + e) m_red v_rel.n on the cube (mass density size^3, no spin) or the
 *   boat (objects.boat.mass), a tiny ripple under it and a stone_thud event.
 */
#ifndef WW_STONES_H
#define WW_STONES_H

#include "sim/state.h"

#define WW_STONE_CONTACTS_PER_STEP 8
#define WW_STONE_SINK_TAU 0.25   /* s: a sinking stone's velocity relaxes with this time constant */

void ww_stones_reset(const ww_scene *sc, ww_state *st);
void ww_stones_step(const ww_scene *sc, ww_state *st);
/* WW_EV_THROW */
void ww_stones_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

/* the criterion alone (pure): the lowest speed that skips at incidence beta (rad), INFINITY
 * where none does (at and above beta_max, too) */
double ww_stone_min_speed(const ww_stones_desc *d, double beta);

#endif
