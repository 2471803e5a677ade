/* desc_boat.h - objects.boat: seed 000's arcade boat and its seat camera. Read by
 * compile_boat.c; simulated by sim/boat.c. Other systems read the collision radius. */
#ifndef WW_DESC_BOAT_H
#define WW_DESC_BOAT_H

typedef struct ww_boat_desc {
    int on;              /* the scene has a boat */
    double position[3];  /* start, m */
    double heading;      /* start, rad (0 = +x, 90 deg = +z, as wave directions) */
    double radius;       /* collision sphere and cube-pushing circle, m */
} ww_boat_desc;

#endif
