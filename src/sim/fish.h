/* fish.h - fish: wander or swim to targets, avoid, bank, bite, fight, get caught, respawn.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_FISH_H
#define WW_FISH_H

#include "sim/state.h"

void ww_fish_reset(const ww_scene *sc, ww_state *st);
void ww_fish_step(const ww_scene *sc, ww_state *st);

#endif
