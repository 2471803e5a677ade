/* boat.h - seed 000's arcade boat, bobbing and tilting on the surface, pushing cubes, and its seat camera.
 * (Issue 4; the owner of this file documents its model, formulas and sources here.) */
#ifndef WW_BOAT_H
#define WW_BOAT_H

#include "sim/state.h"

void ww_boat_reset(const ww_scene *sc, ww_state *st);
void ww_boat_step(const ww_scene *sc, ww_state *st);
/* WW_EV_BOAT and WW_EV_CAMERA_MODE */
void ww_boat_event(const ww_scene *sc, ww_state *st, const ww_event *ev);
/* after the camera path: in boat mode, put the camera in the seat (st->cam_pos, cam_fwd) */
void ww_boat_camera(const ww_scene *sc, ww_state *st);

#endif
