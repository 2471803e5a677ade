/* desc_fishing.h - objects.rod and objects.fish: the rod and lure, and fish that wander, bite,
 * fight and are caught (seed 000), or swim to targets (seed 003). Read by compile_fishing.c;
 * simulated by sim/rod.c and sim/fish.c (their headers give the model and formulas).
 * Angles are radians here (degrees in the file); headings 0 = +x, 90 deg = +z. */
#ifndef WW_DESC_FISHING_H
#define WW_DESC_FISHING_H

#include "scene/desc_fish_species.h"

#define WW_MAX_FISH 128

/* ww_event.flags of a cast (WW_EV_CAST; the whole payload is in sim/rod.h) */
#define WW_CAST_CHARGE 1 /* v[2] holds a charge; else v[0] speed and v[1] elevation */
#define WW_CAST_FROM 2   /* v[3..5] start and v[6] heading; else from the camera */

typedef struct ww_rod_desc {
    int on;              /* casts can happen (a rod section or a cast event) */
    double angle[2];     /* elevation of a cast at charge 1 and at charge 0, rad (seed 000's
                          * alpha_min, alpha_max: a longer hold is flatter) */
    double speed[2];     /* speed at charge 0 and at charge 1, m/s (s_min, s_max) */
    double gravity;      /* the lure's gravity as a fraction of g (seed 000's scaled g') */
    double drag;         /* exponential drag rate k, 1/s: dv/dt = g' - k v */
    double offset[3];    /* lure start from the camera: forward, right, up, m */
    double window;       /* seconds a floating lure stays active before it is reeled in */
    double bite_radius;  /* a fish whose centre is this close to a floating lure in XZ bites, m */
    double attract;      /* fish this close in XZ turn toward a floating lure, m (0: none) */
    double float_height; /* the floating lure's height above the surface, m */
    double float_drag;   /* rate at which a floating lure takes the water's velocity, 1/s */
    double hook_depth;   /* the hook hangs this far under the lure, m */
    double splash;       /* amplitude of the ripple where the lure lands, m */
    double line_width;   /* the line as drawn, m (0: none; gfx/line.h) */
    double line_color[3]; /* its albedo, linear RGB */
} ww_rod_desc;

typedef enum ww_fish_mode { WW_FISH_WANDER = 0, WW_FISH_TARGETS } ww_fish_mode;

typedef struct ww_fish_desc {
    int on;              /* the scene has fish */
    int count;
    ww_fish_mode mode;
    double center[3];    /* the middle of the fish's region, m */
    double radius;       /* horizontal radius of the region, m */
    double spread;       /* cruising depths are drawn within center.y +- spread, m */
    double margin;       /* kept this far under the surface and above the seabed, m */
    int npositions;      /* fish 0..npositions-1 start at positions[] (else drawn) */
    double positions[WW_MAX_FISH][3];
    double speed;        /* cruising speed, m/s (seed 000's v_swim) */
    double max_speed;    /* speed when fleeing, and the cap of every velocity, m/s */
    double response;     /* rate a of the first-order velocity filter, 1/s */
    double turn_rate;    /* largest yaw rate, rad/s */
    double jitter;       /* wander: random walk of the heading goal, rad/sqrt(s) */
    double big_turn;     /* wander: largest occasional turn of the goal, rad */
    double big_turn_rate;/* wander: occasional turns per second */
    double avoid;        /* steer away from boat, cubes and camera closer than this, m */
    double separation;   /* fish keep this far apart, m */
    double swim[2];      /* vertical swim: amplitude m, period s */
    double max_bank;     /* largest bank angle, rad */
    double length;       /* body length, m: the mouth is half of it ahead of the centre */
    double fight[2];     /* a fight lasts a duration drawn in [lo, hi], s */
    double wiggle[2];    /* while fighting: yaw amplitude rad, frequency Hz */
    double respawn;      /* a caught fish reappears after this, s */
    double reach;        /* targets: a target within this is reached, m */
    int nspecies;        /* species (desc_fish_species.h); 0: every fish alike, as without */
    ww_fish_species species[WW_MAX_SPECIES];
    unsigned char species_of[WW_MAX_FISH]; /* each fish's species (with nspecies > 0) */
} ww_fish_desc;

/* the file format's defaults (on stays 0); compile_fishing.c */
void ww_rod_defaults(ww_rod_desc *r);
void ww_fish_defaults(ww_fish_desc *f);

#endif
