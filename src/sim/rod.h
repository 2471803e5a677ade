/* rod.h - the rod and its lure: cast, flight with drag, floating, the active window, reeling.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_ROD_H
#define WW_ROD_H

#include "sim/state.h"

void ww_rod_reset(const ww_scene *sc, ww_state *st);
void ww_rod_step(const ww_scene *sc, ww_state *st);
/* WW_EV_CAST */
void ww_rod_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

#endif
