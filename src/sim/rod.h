/* rod.h - the rod and its lure (seed 000 section 3.4): cast, flight with drag, landing on the
 * exact surface, floating, the active window, reeling in.
 *
 * Call order (sim/step.c): ww_rod_reset at step 0; per step ww_rod_event for each due WW_EV_CAST,
 * then ww_rod_step (before the fish, which bite the floating lure and call ww_rod_reel after a
 * catch).
 *
 * Cast (seed 000): a charge c in [0, 1] maps to an elevation and a speed,
 *   alpha = alpha_min + (1 - c)(alpha_max - alpha_min),   s = s_min + c (s_max - s_min),
 * so a longer hold is flatter and faster; v0 = s (f cos alpha + up sin alpha) with f the camera's
 * forward flattened to XZ, from the camera plus rod.offset (forward, right, up).
 *
 * Flight: dv/dt = g' - k v (g' = rod.gravity g, down; k = rod.drag), integrated by its exact
 * solution over each step (seed 000's v <- (v + g' dt) e^(-k dt) is first-order in dt; the exact
 * update has no step error, so a cast lands where it would at any dt):
 *   v(s) = v0 e^(-ks) + g' (1 - e^(-ks)) / k
 *   p(s) = p0 + v0 (1 - e^(-ks)) / k + g' (s - (1 - e^(-ks)) / k) / k
 * Landing is swept: the step's arc is sampled at most WW_LURE_SWEEP_STEP metres apart against the
 * exact surface (ww_water_at at st->t) and the first sign change is bisected, so a fast lure
 * cannot pass through a crest. On landing: a ripple of rod.splash, a lure_land event, the lure
 * floats rod.float_height above the surface; its horizontal velocity relaxes to the water's at
 * rate rod.float_drag. The lure is active for rod.window seconds; a fish (sim/fish.h) may bite it
 * once per cast (rod_fish), which holds it until the catch. Reeling (end of the window, after a
 * catch, a new cast, or a lure still flying after rod.window) emits `reel` with the seconds the
 * line was out, and the lure goes idle.
 *
 * WW_EV_CAST payload (scene/compile_fishing.c fills it):
 *   flags & WW_CAST_CHARGE: v[2] charge 0..1, mapped as above; else v[0] speed m/s, v[1] elevation
 *                           rad (up positive)
 *   flags & WW_CAST_FROM:   v[3..5] start position m, v[6] heading rad (0 = +x, pi/2 = +z);
 *                           else from the camera (st->cam_pos, st->cam_fwd) plus rod.offset
 */
#ifndef WW_ROD_H
#define WW_ROD_H

#include "sim/state.h"

#define WW_LURE_SWEEP_STEP 0.05 /* m: the longest chord of a flight step tested against the surface */

enum { WW_LURE_IDLE = 0, WW_LURE_FLYING, WW_LURE_FLOATING, WW_LURE_HOOKED };

void ww_rod_reset(const ww_scene *sc, ww_state *st);
void ww_rod_step(const ww_scene *sc, ww_state *st);
/* WW_EV_CAST */
void ww_rod_event(const ww_scene *sc, ww_state *st, const ww_event *ev);
/* reel the line in: a `reel` event, the lure idle (the fish after a catch) */
void ww_rod_reel(const ww_scene *sc, ww_state *st);

/* pure: the tip of the rod the camera holds, rod.offset (forward, right, up) from the camera,
 * where a cast without `from` starts; f: the camera's forward direction made level (unit) */
void ww_rod_held_tip(const ww_scene *sc, const ww_state *st, double tip[3], double f[3]);
/* pure: the cast's elevation (rad) and speed (m/s) for a charge in [0, 1] */
void ww_rod_charge_map(const ww_rod_desc *rod, double charge, double *angle, double *speed);
/* pure: the exact flight from (p0, v0) after s seconds under gravity g (3) and drag k */
void ww_rod_flight(const double p0[3], const double v0[3], const double g[3], double k, double s,
                   double p[3], double v[3]);

#endif
