/* caustic_set.h - water.look.caustics.method texture: seed 003's looped set of caustic textures,
 * computed on the CPU from the scene's own wave field (no GL here; gfx/geometry.c uploads it).
 *
 *   ww_caustic_set cs;
 *   ww_caustic_set_make(sc, &cs, &err);   // once, when the renderer is made; allocates
 *   ... cs.texel: frames x size x size intensities, mean 1, row-major, frame after frame ...
 *   ww_caustic_set_frame(&cs, t, &i0, &i1, &w);  // the two frames to blend at time t
 *   ww_caustic_set_free(&cs);
 */
#ifndef WW_GFX_CAUSTIC_SET_H
#define WW_GFX_CAUSTIC_SET_H

#include "core/error.h"
#include "scene/scene.h"

#define WW_CAUSTIC_SET_SIZE 128    /* texels along each side of a frame */
#define WW_CAUSTIC_SET_FRAMES 32   /* frames over one loop (seed 003 has 32) */
#define WW_CAUSTIC_SET_PATCH 16.0  /* m: a frame tiles the seabed every this many metres */
#define WW_CAUSTIC_SET_PERIOD 4.0  /* s: the set loops in time every this many seconds */

typedef struct ww_caustic_set {
    int size, frames;   /* WW_CAUSTIC_SET_SIZE, WW_CAUSTIC_SET_FRAMES */
    double patch;       /* m, the side of the periodic patch a frame covers */
    double period;      /* s, the loop */
    double depth;       /* m, the depth below the surface the frames were focused at */
    int ncomp;          /* sines the set was computed from (after snapping and fading) */
    float *texel;       /* frames x size x size irradiance over the flat-water one (mean 1) */
} ww_caustic_set;

ww_result ww_caustic_set_make(const ww_scene *sc, ww_caustic_set *cs, ww_error *err);
/* the frames to blend at time t (s): i0, i1 = i0 + 1 (looped) and the weight of i1 */
void ww_caustic_set_frame(const ww_caustic_set *cs, double t, int *i0, int *i1, double *w);
void ww_caustic_set_free(ww_caustic_set *cs);

#endif
