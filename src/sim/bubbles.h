/* bubbles.h - air bubbles (seed 003): emitters, rising with wobble, respawn.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_BUBBLES_H
#define WW_BUBBLES_H

#include "sim/state.h"

void ww_bubbles_reset(const ww_scene *sc, ww_state *st);
void ww_bubbles_step(const ww_scene *sc, ww_state *st);

#endif
