/* wake.h - the boat's wake as a ribbon lying on the water behind the stern, built on the CPU
 * each frame from the stern's trail in the state (sim/fields_boat.h: boat_wake, every
 * WW_BOAT_WAKE_EVERY s); gfx/geometry.c draws it blended in the main pass after the water
 * (geometry.frag.glsl mode 5). No GL here: the tests check the shape without a context.
 *
 * A boat under way leaves two things on the water: the churned wash behind its transom, foam in
 * streaks along the path that dies out in a few seconds, and the Kelvin wedge, the divergent
 * waves whose crests break along two arms at asin(1/3) = 19.47 degrees each side of the path
 * (Kelvin 1887; Lighthill, "Waves in Fluids", 1978, sec. 3.10), whatever the speed in deep water.
 * The ribbon runs from the stern back through the trail; at a point a path length L behind the
 * stern it is beam / 2 + L tan(19.47 deg) wide each side, so its edges are the wedge's arms. Each
 * point carries the wash's and the arms' strengths there (fading with the time since the stern
 * passed it, and with the boat's speed then: no wake below WAKE_SPEED_MIN) and the odometer
 * when the stern passed it, a coordinate fixed to the water along the path, so the foam's
 * streaks stay where they were made as the boat moves on.
 *
 * Vertex layout (8 floats, the geometry meshes'): position camera-relative m (at the rest level:
 * the vertex shader puts it on the surface), (the wash's strength, the arms' strength, the
 * odometer m), (s -1 .. 1 across, the half width m); WW_WAKE_ACROSS points across each point of
 * the trail. */
#ifndef WW_GFX_WAKE_H
#define WW_GFX_WAKE_H

#include <stdint.h>

#include "gfx/line.h"
#include "scene/scene.h"
#include "sim/state.h"

#define WW_WAKE_LIFE 7.0 /* s: the trail drawn, from the stern back */
#define WW_WAKE_KELVIN_DEG 19.47
#define WW_WAKE_ACROSS 13 /* points across the ribbon: it follows waves a metre or two long */
#define WW_WAKE_MAX_VERTS (WW_WAKE_ACROSS * (WW_BOAT_WAKE + 1))
#define WW_WAKE_MAX_INDEX (6 * (WW_WAKE_ACROSS - 1) * WW_BOAT_WAKE)

/* the points of the wake from the stern back (at most WW_BOAT_WAKE + 1): world x, z (p), half
 * width m (half), the time since the stern passed s (age), its odometer then m (odo); 0 when no
 * wake is drawn (no boat, wake 0, or it has not moved) */
int ww_wake_points(const ww_scene *sc, const ww_state *st, double (*p)[2], double *half,
                   double *age, double *odo);

/* the ribbon on the water: vertices (8 floats each, at most WW_WAKE_MAX_VERTS) and
 * triangles (at most WW_WAKE_MAX_INDEX indices); returns the index count (0: nothing to draw) */
int ww_wake_build(const ww_scene *sc, const ww_state *st, const ww_line_eye *eye, float *vert,
                  uint32_t *index, int *nvert);

#endif
