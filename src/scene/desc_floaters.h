/* desc_floaters.h - objects.models[].float: any model floats like a cube (seed 001's buoyant
 * game objects). Read by compile_floaters.c; simulated by sim/floaters.c.
 *
 *   objects:
 *     models:
 *       - {name: barrel, mesh: box, scale: [0.6, 0.9, 0.6], position: [2, 0, -4],
 *          float: {density: 450, columns: 4, drag: {linear: 0.8, quadratic: 1.05, angular: 1.5},
 *                  nudge: 1}}
 *
 * The body is the model's box: its mesh's bounds (the unit box of a procedural mesh, an OBJ's
 * own bounds) times its scale, in the model's own frame. It floats by the cubes' Archimedes
 * model (sim/cubes.c) generalised from a cube to that box; children and lights parented to it
 * ride along. A floating model is a root of the scene graph (no parent).
 */
#ifndef WW_DESC_FLOATERS_H
#define WW_DESC_FLOATERS_H

#include "scene/desc_reef.h"

#define WW_MAX_FLOATERS 16

typedef struct ww_floater_desc {
    int model;             /* index in objects.models */
    double density;        /* kg/m^3 (water 1000) */
    int columns;           /* buoyancy columns per side, 1..WW_CUBE_MAX_COLUMNS */
    double drag_linear;    /* 1/s, as a cube's */
    double drag_quadratic; /* Cd, on the area V^(2/3) */
    double drag_angular;   /* 1/s */
    double nudge;          /* ripple slope force, as a cube's */
    double extent[3];      /* the box's edges along the model's axes, m (bounds x scale) */
    double offset[3];      /* the box's centre from the model's origin, model axes, m */
    double position[3];    /* start: the box's centre in the world, m */
    double rotation[4];    /* start orientation, unit quaternion w x y z (the model's rotation) */
} ww_floater_desc;

typedef struct ww_floaters_desc {
    int on;                /* some model floats */
    int count;
    ww_floater_desc floater[WW_MAX_FLOATERS];
    int plus_one[WW_MAX_MODELS]; /* per objects.models index: its floater + 1, 0 static */
} ww_floaters_desc;

#endif
