/* collide.c - placeholder until its system lands (issue 4, in progress). */
#include "sim/collide.h"

void ww_camera_collide(const ww_scene *sc, ww_state *st) { (void)sc; (void)st; }
