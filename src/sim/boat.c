/* boat.c - placeholder until its system lands (issue 4, in progress). */
#include "sim/boat.h"

void ww_boat_reset(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_boat_step(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_boat_event(const ww_scene *sc, ww_state *st, const ww_event *ev) { (void)sc; (void)st; (void)ev; }
void ww_boat_camera(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
