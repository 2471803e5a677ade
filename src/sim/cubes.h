/* cubes.h - floating cubes: buoyancy, drag, tilt, press and release (seed 000).
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_CUBES_H
#define WW_CUBES_H

#include "sim/state.h"

/* step 0 (called by ww_state_reset when sc->cubes.on) */
void ww_cubes_reset(const ww_scene *sc, ww_state *st);
/* one step (when sc->cubes.on) */
void ww_cubes_step(const ww_scene *sc, ww_state *st);
/* WW_EV_PRESS */
void ww_cubes_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

#endif
