/* chest.c - placeholder until its system lands (issue 4, in progress). */
#include "sim/chest.h"

void ww_chest_reset(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_chest_step(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_chest_event(const ww_scene *sc, ww_state *st, const ww_event *ev) { (void)sc; (void)st; (void)ev; }
