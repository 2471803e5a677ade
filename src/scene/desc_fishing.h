/* desc_fishing.h - objects.rod and objects.fish: the rod and lure, and fish that wander, bite,
 * fight and are caught (seed 000), or swim to targets (seed 003). Read by compile_fishing.c;
 * simulated by sim/rod.c and sim/fish.c. */
#ifndef WW_DESC_FISHING_H
#define WW_DESC_FISHING_H

#define WW_MAX_FISH 128

typedef struct ww_rod_desc {
    int on;      /* casts can happen (a rod section or a cast event) */
} ww_rod_desc;

typedef struct ww_fish_desc {
    int on;      /* the scene has fish */
    int count;
} ww_fish_desc;

#endif
