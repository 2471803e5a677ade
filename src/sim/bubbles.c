/* bubbles.c - placeholder until its system lands (issue 4, in progress). */
#include "sim/bubbles.h"

void ww_bubbles_reset(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
void ww_bubbles_step(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
