/* stones.h - thrown stones: flight, swept crossing of the surface, skipping or sinking, collisions.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_STONES_H
#define WW_STONES_H

#include "sim/state.h"

void ww_stones_reset(const ww_scene *sc, ww_state *st);
void ww_stones_step(const ww_scene *sc, ww_state *st);
/* WW_EV_THROW */
void ww_stones_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

#endif
