/* desc_cubes.h - objects.cubes: floating boxes with Archimedes or spring buoyancy (seed 000).
 * Read by compile_cubes.c; simulated by sim/cubes.c. Other systems read position and size. */
#ifndef WW_DESC_CUBES_H
#define WW_DESC_CUBES_H

#define WW_MAX_CUBES 64

typedef struct ww_cube_desc {
    double position[3];  /* start, m */
    double size;         /* edge length, m */
    double density;      /* kg/m^3 (water 1000) */
} ww_cube_desc;

typedef struct ww_cubes_desc {
    int on;              /* the scene has cubes */
    int count;
    ww_cube_desc cube[WW_MAX_CUBES];
} ww_cubes_desc;

#endif
