/* floater_stats.h - how the floating objects of a scene respond to its sea (sweep rows): the scene
 * is simulated over its duration and, after the first quarter (the objects settle), each frame is
 * sampled. Heave RMS: root mean square of a body's height about its own mean; tilt/pitch RMS:
 * root mean square of its angle. Cubes: the tilt is the angle between the vertical and the nearest
 * of the box's three axes (a cube that turns onto another face is upright again), averaged over the
 * cubes; boat: its pitch. NaN where the scene has no such object.
 */
#ifndef WW_FLOATER_STATS_H
#define WW_FLOATER_STATS_H

#include "core/error.h"
#include "scene/scene.h"

typedef struct ww_floater_stats {
    double cube_heave_rms;  /* m, mean over the cubes */
    double cube_tilt_rms;   /* rad, mean over the cubes */
    double boat_heave_rms;  /* m */
    double boat_pitch_rms;  /* rad */
    int samples;            /* frames sampled */
} ww_floater_stats;

/* simulate sc and measure; WW_E_NAN (with err) when the simulation fails */
ww_result ww_floater_stats_compute(const ww_scene *sc, ww_floater_stats *out, ww_error *err);

#endif
