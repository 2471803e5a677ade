/* desc_boat.h - objects.boat: seed 000's arcade boat and its seat camera. Read by
 * compile_boat.c; simulated by sim/boat.c (which states the model). Other systems read the
 * collision radius.
 *
 * Seed 000 gives the structure of the model and one number, the coasting drag 1.2 1/s; the other
 * defaults are ours, chosen for a small open motorboat (4 m x 1.6 m) on a lake, and are listed
 * here so a scene can restate them. ww_boat_defaults() fills them: zero is a real value for
 * several of them (slip, ride height), so there is no "zero means default".
 */
#ifndef WW_DESC_BOAT_H
#define WW_DESC_BOAT_H

#include "core/mathx.h"

typedef struct ww_boat_desc {
    int on;              /* the scene has a boat */
    double position[3];  /* start, m: y is the hull centre's start height (it then floats) */
    double heading;      /* start, rad (0 = +x, 90 deg = +z, as wave directions) */
    double radius;       /* collision sphere and cube-pushing circle, m */
    double mass;         /* kg: what a stone's impulse moves */
    double length;       /* hull length, m: bow and stern sample the surface at +-length/2;
                          * waves shorter than this are not followed */
    double beam;         /* hull width, m: port and starboard sample at +-beam/2 */
    double acceleration; /* engine acceleration at full throttle, m/s^2 */
    double drag;         /* k of v <- v e^(-k dt) (seed 000: 1.2), 1/s */
    double max_speed;    /* forward speed cap, m/s */
    double reverse_speed;/* reverse speed cap, m/s (<= max_speed) */
    double turn_rate;    /* heading rate at full steer, rad/s */
    double slip;         /* outward side slip at full steer, m/s per m/s of forward speed */
    double ride_height;  /* hull centre above the surface under it, m */
    double bob_time;     /* time constant of following the surface (height, pitch, roll), s */
    double seat[3];      /* seat camera in the hull frame: forward, up, starboard, m */
    double look_time;    /* time constant of the seat view easing back to the heading, s */
    double look_pitch;   /* seat view below (-) or above (+) the hull's bow line, rad */
    double wake;         /* the wake's strength as drawn (0: none; gfx/wake.h) */
} ww_boat_desc;

/* the file format's defaults (on stays 0) */
static inline void ww_boat_defaults(ww_boat_desc *b) {
    *b = (ww_boat_desc){
        .position = {0.0, 0.25, 0.0},
        .heading = 0.0,
        .radius = 2.0,
        .mass = 250.0,        /* a 4 m aluminium skiff with its driver */
        .length = 4.0,
        .beam = 1.6,
        .acceleration = 6.0,  /* terminal speed acceleration / drag = 5 m/s (18 km/h) */
        .drag = 1.2,          /* seed 000 */
        .max_speed = 8.0,     /* a cap above the terminal speed: reached with more acceleration */
        .reverse_speed = 2.0, /* binds in reverse: the reduced reverse speed of seed 000 */
        .turn_rate = ww_m_rad(45.0),
        .slip = 0.1,
        .ride_height = 0.25,
        .bob_time = 0.15,     /* seed 000's per-frame lambda ~ 0.1 at 60 fps: tau = 0.16 s */
        .seat = {1.2, 1.0, 0.0},
        .look_time = 0.5,
        .look_pitch = ww_m_rad(-8.0),
        .wake = 1.0,
    };
}

#endif
