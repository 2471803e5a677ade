/* wake.h - the boat's wake as a ribbon lying on the water, from just ahead of the stem back
 * along the hull and behind the stern, built on the CPU each frame from the boat's pose and the
 * stern's trail in the state (sim/fields_boat.h: boat_wake, every WW_BOAT_WAKE_EVERY s);
 * gfx/geometry.c draws it blended in the main pass after the water (geometry.frag.glsl mode 5).
 * No GL here: the tests check the shape without a context.
 *
 * A boat under way leaves three things on the water:
 * - the bow wave: the water its stem and forward sections push aside breaks along the hull's
 *   sides, and leaves the hull at the shoulders;
 * - the Kelvin wedge: the divergent waves, whose crests break along two arms at
 *   asin(1/3) = 19.47 degrees each side of the path from the bow, whatever the speed in deep
 *   water (Kelvin 1887; Lighthill, "Waves in Fluids", 1978, sec. 3.10); the crests slant back
 *   at 54.7 degrees to the path along the arms (ibid.);
 * - the wash: water churned behind the transom, foam in streaks along the path that spreads
 *   slowly, breaks into a lace and dies out in a few seconds.
 *
 * The ribbon's rows: WW_WAKE_HULL_ROWS along the hull as it lies now (the first a little ahead
 * of the stem, where the foam starts), then the stern and its trail back. A row's half width is
 * the larger of the hull's waterline half-breadth plus the bow wave's band (WW_WAKE_BAND)
 * and the wedge's, (the path length back from the stem) tan 19.47 deg, so its edges are the
 * bow wave where that hugs the hull and the wedge's arms from where they leave it; in a turn
 * it is at most a share of the radius, so the ribbon never folds. Each row carries the foam's
 * strength there (the boat's speed when it passed: none below WAKE_SPEED_MIN; 0 on the row
 * ahead of the stem; the trail's ends fade out), the time since the stern passed it, and the
 * odometer then, a coordinate fixed to the water along the path, so the wash and the lace stay
 * where they were made as the boat moves on. The shader makes the wash, the bow wave and the
 * arms from these (geometry.frag.glsl); the last two travel with the boat, as Kelvin's pattern
 * does: their crests are drawn in the boat's frame, from the path length behind the stern.
 *
 * Vertex layout (8 floats, the geometry meshes'): position camera-relative m (at the rest level:
 * the vertex shader puts it on the surface), (strength, age s, odometer m), (s -1 .. 1 across,
 * the half width m); WW_WAKE_ACROSS points across each row. The draw's instance carries the
 * stern's odometer and the transom's half-breadth (ww_wake_build's `stern`) and the time. */
#ifndef WW_GFX_WAKE_H
#define WW_GFX_WAKE_H

#include <stdint.h>

#include "gfx/line.h"
#include "scene/scene.h"
#include "sim/state.h"

#define WW_WAKE_LIFE 7.0 /* s: the trail drawn, from the stern back */
#define WW_WAKE_KELVIN_DEG 19.47
#define WW_WAKE_ACROSS 13    /* points across the ribbon: it follows waves a metre or two long */
#define WW_WAKE_HULL_ROWS 8  /* rows ahead of the stern: one ahead of the stem, seven on the hull */
#define WW_WAKE_STEM_AHEAD 0.3 /* m: the first row's distance ahead of the stem */
#define WW_WAKE_BAND 0.3 /* m: the bow wave's band beside the hull (geometry.frag.glsl's
                          * WAKE_ARM_BAND): the ribbon reaches this far past the waterline */
#define WW_WAKE_MAX_ROWS (WW_WAKE_HULL_ROWS + WW_BOAT_WAKE + 1)
#define WW_WAKE_MAX_VERTS (WW_WAKE_ACROSS * WW_WAKE_MAX_ROWS)
#define WW_WAKE_MAX_INDEX (6 * (WW_WAKE_ACROSS - 1) * (WW_WAKE_MAX_ROWS - 1))

typedef struct ww_wake_row {
    double p[2];     /* world x, z of the row's middle */
    double half;     /* half width, m */
    double age;      /* s since the stern passed here (0 ahead of the stern) */
    double odo;      /* the odometer there, m: ahead of the stern, the stern's plus the distance */
    double strength; /* the foam's strength, 0 .. objects.boat.wake */
} ww_wake_row;

/* the wake's rows from ahead of the stem back (at most WW_WAKE_MAX_ROWS); *stern is the stern's
 * row. 0 when no wake is drawn (no boat, wake 0, or the stern has not moved) */
int ww_wake_rows(const ww_scene *sc, const ww_state *st, ww_wake_row *row, int *stern);

/* the hull's waterline half-breadth, m, at a distance ahead of the stern, m (0 .. length) */
double ww_wake_hull_half(const ww_scene *sc, double ahead);

/* the ribbon on the water: vertices (8 floats each, at most WW_WAKE_MAX_VERTS) and
 * triangles (at most WW_WAKE_MAX_INDEX indices); returns the index count (0: nothing to draw).
 * stern: the stern's odometer m and the transom's half-breadth m, for the draw's instance */
int ww_wake_build(const ww_scene *sc, const ww_state *st, const ww_line_eye *eye, float *vert,
                  uint32_t *index, int *nvert, double stern[2]);

#endif
