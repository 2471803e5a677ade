/* floaters.h - floating models (seed 001: "buoyancy support for game objects" that match the
 * water's height and tilt with its normal): any objects.models item with `float:` is a rigid box
 * (its mesh's bounds x scale) floating by the cubes' Archimedes model (sim/cubes.c), generalised
 * from a cube to a box with three edges.
 *
 *   ww_floaters_reset(sc, st);      // step 0: the model's place and rotation, at rest
 *   ww_floaters_step(sc, st);       // one step, st->t - dt -> st->t (nothing at step 0)
 *   ww_floater_pose(sc, st, j, m);  // floater j's model frame now (T R, no scale), column-major
 *
 * The state holds the box's centre, velocity, orientation and angular velocity; the model's
 * origin is the centre less the turned offset of the box in the model (an OBJ need not be
 * centred). Its children and lights are placed in that frame each frame (gfx/geometry.c), the
 * camera collides with the turned box (sim/collide.c). No events.
 */
#ifndef WW_FLOATERS_H
#define WW_FLOATERS_H

#include "sim/state.h"

void ww_floaters_reset(const ww_scene *sc, ww_state *st);
void ww_floaters_step(const ww_scene *sc, ww_state *st);

/* the frame (T R) of floater j's model now: where the model's origin and axes are */
void ww_floater_pose(const ww_scene *sc, const ww_state *st, int j, double m[16]);

/* model k to the camera: 1 it floats (its turned box now: centre c, half edges half, unit
 * quaternion q), -1 it rides a floating model (the floater's own box stops the camera), 0 static */
int ww_floater_box(const ww_scene *sc, const ww_state *st, int k, double c[3], double half[3],
                   double q[4]);

/* the floater model k floats as, or -1 (static); the floater its chain's root floats as */
static inline int ww_floater_of_model(const ww_scene *sc, int k) {
    return sc->floaters.on ? sc->floaters.plus_one[k] - 1 : -1;
}

#endif
