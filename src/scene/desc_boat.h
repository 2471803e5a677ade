/* desc_boat.h - objects.boat: seed 000's arcade boat and its seat camera. Read by
 * compile_boat.c; simulated by sim/boat.c. */
#ifndef WW_DESC_BOAT_H
#define WW_DESC_BOAT_H

typedef struct ww_boat_desc {
    int on;      /* the scene has a boat */
} ww_boat_desc;

#endif
