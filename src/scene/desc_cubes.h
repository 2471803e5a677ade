/* desc_cubes.h - objects.cubes: floating boxes with Archimedes or spring buoyancy (seed 000).
 * Read by compile_cubes.c; simulated by sim/cubes.c (the model and its formulas are there).
 * Other systems read position and size. Every setting is per cube; ww_cube_default() holds the
 * file format's defaults (zero is a real value for several of them, so they are explicit); a
 * desc written by hand with only position, size and density gets the identity orientation, the
 * default columns and no drag.
 */
#ifndef WW_DESC_CUBES_H
#define WW_DESC_CUBES_H

#define WW_MAX_CUBES 64
#define WW_CUBE_MAX_COLUMNS 8  /* buoyancy columns per side of the box */
#define WW_CUBE_DEFAULT_COLUMNS 4

/* exact surface queries per side of a box of n x n buoyancy columns (sim/boxwater.h): the
 * columns' own centres up to 2 x 2, then the 2 x 2 Gauss-Legendre nodes up to 4 x 4 columns and
 * the 3 x 3 nodes above, the surface interpolated from them to the columns */
static inline int ww_box_nodes_per_side(int n) {
    return n <= 2 ? n : n <= 4 ? 2 : 3;
}
#define WW_BOX_MAX_NODES 9 /* nodes of a box at most: 3 x 3 */

typedef enum ww_cube_buoyancy {
    WW_CUBE_ARCHIMEDES = 0, /* submerged volume of the box against the exact surface */
    WW_CUBE_SPRING          /* seed 000's spring-damper toward a target height */
} ww_cube_buoyancy;

typedef struct ww_cube_desc {
    double position[3];  /* start, m */
    double rotation[4];  /* start orientation, unit quaternion w x y z; all 0: identity */
    double size;         /* edge length, m */
    double density;      /* kg/m^3 (water 1000) */
    ww_cube_buoyancy buoyancy;
    int columns;         /* buoyancy columns per side (archimedes), 1..WW_CUBE_MAX_COLUMNS;
                          * 0: WW_CUBE_DEFAULT_COLUMNS */
    /* water drag, scaled by the submerged fraction, relative to the water's velocity */
    double drag_linear;    /* 1/s: dv/dt = -b (v - u) when fully submerged */
    double drag_quadratic; /* drag coefficient Cd of a face: F = 1/2 rho Cd s^2 |v - u| (v - u) */
    double drag_angular;   /* 1/s: dw/dt = -b_w w when fully submerged */
    /* buoyancy: spring (seed 000): v += k (y_surface + offset - y) dt, v *= e^(-c dt) */
    double spring_stiffness; /* k, 1/s^2 */
    double spring_damping;   /* c, 1/s */
    double spring_offset;    /* centre above the surface at rest, m */
    /* press (seed 000): v_y -= a dt while held; on release v_y += J0 + J1 min(held, Tmax) */
    double press_accel;    /* a, m/s^2 */
    double press_j0;       /* J0, m/s */
    double press_j1;       /* J1, m/s per s held */
    double press_max_hold; /* Tmax, s */
    double nudge;          /* ripple slope force: F = -nudge rho g V_sub grad(h_ripple) */
} ww_cube_desc;

typedef struct ww_cubes_desc {
    int on;              /* the scene has cubes */
    int count;
    ww_cube_desc cube[WW_MAX_CUBES];
} ww_cubes_desc;

/* the file format's defaults for one cube at the origin: a 1 m box of density 500 */
static inline ww_cube_desc ww_cube_default(void) {
    return (ww_cube_desc){.rotation = {1.0, 0.0, 0.0, 0.0},
                          .size = 1.0,
                          .density = 500.0,
                          .buoyancy = WW_CUBE_ARCHIMEDES,
                          .columns = WW_CUBE_DEFAULT_COLUMNS,
                          .drag_linear = 0.8,
                          .drag_quadratic = 1.05, /* a flat plate face-on ~1.1-1.2, cube 1.05 */
                          .drag_angular = 1.5,
                          .spring_stiffness = 20.0,
                          .spring_damping = 2.0,
                          .spring_offset = 0.0,
                          .press_accel = 8.0,
                          .press_j0 = 1.0,
                          .press_j1 = 2.0,
                          .press_max_hold = 1.5,
                          .nudge = 1.0};
}

#endif
