/* boat.h - seed 000's arcade boat made analog: throttle and steering, bobbing and tilting on
 * the exact surface, pushing cubes, and its seat camera.
 *
 * Call order (sim/step.c, only when sc->boat.on):
 *   ww_boat_reset(sc, st);      // step 0: the desc's pose, engine off, camera free
 *   per step: ww_boat_event(sc, st, ev) for each due action; ww_boat_step(sc, st) after the
 *   other objects (it moves the cubes it touches); ww_boat_camera(sc, st) after the camera path.
 * The boat owns no memory; everything it keeps is in the state (fields_boat.h).
 *
 * Script payload (compile_boat.c):
 *   WW_EV_BOAT         v[0] throttle -1..1, v[1] steer -1..1 (+ turns to starboard: the heading
 *                      grows, from +x toward +z), v[2] until (s, when flags & 1; otherwise the
 *                      inputs hold until the next boat action). The inputs take effect from the
 *                      action's step and end on the first step at or after `until`.
 *   WW_EV_CAMERA_MODE  index 0: the camera path (free), 1: the boat's seat.
 * Events: boat_start when the throttle becomes non-zero (magnitude: throttle), boat_stop when it
 * returns to zero (magnitude: speed, m/s).
 *
 * The model (the formulas are in boat.c; desc_boat.h lists the parameters):
 *   forward speed  dv/dt = a u - k v, integrated exactly over the step (seed 000's
 *                  v <- v + a u dt; v <- v e^(-k dt), which is the same in the limit dt -> 0),
 *                  then capped to [-reverse_speed, max_speed]; terminal speed a u / k.
 *   heading        dh/dt = turn_rate * steer (seed 000's yaw += w dt, made analog).
 *   side slip      an outward lateral velocity -slip * steer * v along the starboard vector.
 *   position       the step's exact displacement for a constant turn rate (the chord of the arc)
 *                  at the step's mean speed: a steady turn is an exact circle of radius
 *                  sqrt(1 + (slip steer)^2) |v| / (turn_rate |steer|).
 *   bobbing        height, pitch and roll follow the surface under the hull through a first-
 *                  order lag of time constant bob_time (seed 000's y += (y_t - y) lambda, made
 *                  independent of the step): height = surface under the centre + ride_height;
 *                  pitch from bow and stern samples, roll from port and starboard (seed 001).
 *   cubes          circles in XZ: a cube whose centre is nearer than radius + size/2 is moved
 *                  out to that distance and given the boat's velocity along the normal.
 *   seat camera    the seat offset in the tilted hull frame; the view's heading eases back to the
 *                  boat's heading with time constant look_time (it starts from the path camera's
 *                  heading when the mode switches, so the switch does not jump the view).
 */
#ifndef WW_BOAT_H
#define WW_BOAT_H

#include "sim/state.h"

void ww_boat_reset(const ww_scene *sc, ww_state *st);
void ww_boat_step(const ww_scene *sc, ww_state *st);
/* WW_EV_BOAT and WW_EV_CAMERA_MODE (ignored when the scene has no boat: `camera: free`) */
void ww_boat_event(const ww_scene *sc, ww_state *st, const ww_event *ev);
/* after the camera path: in boat mode, put the camera in the seat (st->cam_pos, cam_fwd) */
void ww_boat_camera(const ww_scene *sc, ww_state *st);

/* pure: the hull frame (forward, up, starboard; unit vectors, world) for a heading, pitch (bow
 * up +) and roll (starboard down +), rad */
void ww_boat_frame(double heading, double pitch, double roll, double fwd[3], double up[3],
                   double stbd[3]);

#endif
