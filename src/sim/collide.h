/* collide.h - camera collision (seed 003): the camera stops at the surface of solid objects.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_COLLIDE_H
#define WW_COLLIDE_H

#include "sim/state.h"

/* after the camera (and the boat seat): keep st->cam_pos out of solid objects, emitting
 * WW_SE_CAMERA_BLOCKED when it had to move it (when sc->camera_collide) */
void ww_camera_collide(const ww_scene *sc, ww_state *st);

#endif
