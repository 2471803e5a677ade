/* stones.c - placeholder until its system lands (issue 4, in progress). */
#include "sim/stones.h"

void ww_stones_reset(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_stones_step(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_stones_event(const ww_scene *sc, ww_state *st, const ww_event *ev) { (void)sc; (void)st; (void)ev; }
