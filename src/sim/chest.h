/* chest.h - the treasure chest: spawn, lifetime, collection by the camera, prizes.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_CHEST_H
#define WW_CHEST_H

#include "sim/state.h"

void ww_chest_reset(const ww_scene *sc, ww_state *st);
void ww_chest_step(const ww_scene *sc, ww_state *st);
/* WW_EV_CHEST */
void ww_chest_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

#endif
