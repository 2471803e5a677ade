/* camera.h - the scripted camera: keyframes with a position and a look-at point (or yaw and
 * pitch), interpolated in time by a time-aware Catmull-Rom spline (C1 through every key) or
 * linearly. When every key has a look-at point the target itself is interpolated, so a camera
 * that keeps one target in view does so between keys too; otherwise yaw and pitch are
 * interpolated (yaw the short way round). Before the first key and after the last the camera holds.
 */
#ifndef WW_CAMERA_H
#define WW_CAMERA_H

#include "scene/scene.h"
#include "sim/state.h"

/* camera position, forward and field of view at st->t */
void ww_camera_update(const ww_scene *sc, ww_state *st);

/* pure: the camera at time t (fov in rad) */
void ww_camera_eval(const ww_scene *sc, double t, double pos[3], double fwd[3], double *fov);

/* pure: forward unit vector from yaw (0 = -z, positive toward +x) and pitch (up), rad */
void ww_camera_dir(double yaw, double pitch, double fwd[3]);

#endif
