/* fish.c - placeholder until its system lands (issue 4, in progress). */
#include "sim/fish.h"

void ww_fish_reset(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_fish_step(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
