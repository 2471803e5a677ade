/* desc_cubes.h - objects.cubes: floating boxes with Archimedes or spring buoyancy (seed 000).
 * Read by compile_cubes.c; simulated by sim/cubes.c. */
#ifndef WW_DESC_CUBES_H
#define WW_DESC_CUBES_H

#define WW_MAX_CUBES 64

typedef struct ww_cubes_desc {
    int on;      /* the scene has cubes */
    int count;
} ww_cubes_desc;

#endif
