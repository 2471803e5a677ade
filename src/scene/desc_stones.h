/* desc_stones.h - objects.stones: thrown stones that skip (Clanet, Hersen & Bocquet 2004) or
 * sink. Read by compile_stones.c; simulated by sim/stones.c, whose header states the model.
 * ww_stones_defaults() gives every value of an absent key (a scene with only `throw` events). */
#ifndef WW_DESC_STONES_H
#define WW_DESC_STONES_H

#define WW_MAX_STONES 32

/* a throw event's ww_event.flags (the payload is in sim/stones.h) */
#define WW_THROW_FROM 1   /* from v[3..5] with heading v[6]; else from the camera */

typedef struct ww_stones_desc {
    int on;               /* stones can be thrown (a stones section or a throw event) */
    double mass;          /* kg */
    double radius;        /* disc radius a, m: collision sphere and the skip criterion */
    double drag;          /* quadratic air drag coefficient C_d on the area pi a^2; 0: none */
    double lift;          /* hydrodynamic force coefficient C of the skip criterion */
    double e_n;           /* restitution of the normal velocity at a skip, 0..1 */
    double c_t;           /* kept fraction of the tangential velocity at a skip, 0..1 */
    double restitution;   /* of a thud against a cube or the boat, 0..1 */
    int max_bounces;      /* skips one stone may make */
    double splash_full;   /* m/s: a sinking stone this fast or faster makes a full splash */
    double sink_speed;    /* terminal sinking speed in water, m/s */
    double ripple;        /* ripple amplitude A0 of a skip or a full splash, m */
    double ripple_tiny;   /* of a tiny splash or a thud, m */
    double throw_angle[2];/* [flattest, steepest] downward angle of a charge throw, rad */
    double throw_speed[2];/* [slowest, fastest] speed of a charge throw, m/s */
    double throw_spin;    /* spin of a charge throw (and an explicit one with none), rad/s */
} ww_stones_desc;

/* every default; on = 0 */
void ww_stones_defaults(ww_stones_desc *d);

#endif
