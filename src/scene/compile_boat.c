/* compile_boat.c - objects.boat (seed 000's arcade boat, desc_boat.h) and the script actions
 * `boat: {throttle, steer, until}` and `camera: free | boat` (their payload: sim/boat.h).
 * A boat section, a boat action or `camera: boat` puts a boat in the scene; without a section
 * it has every default of ww_boat_defaults().
 */
#include "scene/compile_impl.h"

#include "core/mathx.h"

static const rule R_POSITION = FINITE("m");
static const rule R_SIZE = OPEN_LO(0, 1e3, "m");
static const rule R_MASS = OPEN_LO(0, 1e7, "kg");
static const rule R_WAKE = CLOSED(0, 4, "");
static const rule R_ACCELERATION = CLOSED(0, 1e3, "m/s^2");
static const rule R_DRAG = CLOSED(0, 1e3, "1/s");
static const rule R_SPEED = CLOSED(0, 1e3, "m/s");
static const rule R_TURN_RATE = CLOSED(0, 3600, "deg/s");
static const rule R_SLIP = CLOSED(0, 10, "");
static const rule R_RIDE_HEIGHT = CLOSED(-1e2, 1e2, "m");
static const rule R_TIME_CONSTANT = CLOSED(0, 1e3, "s");
static const rule R_SEAT = CLOSED(-1e2, 1e2, "m");
static const rule R_LOOK_PITCH = CLOSED(-89, 89, "deg");
static const rule R_INPUT = CLOSED(-1, 1, "");
static const rule R_UNTIL = CLOSED(0, WW_TIME_MAX, "s");

/* the words of `camera:`, indexed by ev->index */
static const char *const CAMERA_WORDS[] = {"free", "boat", NULL};

ww_result wwc_boat(ctx *c, const section *objects) {
    static const char *const keys[] = {
        "position",  "heading",       "radius",    "mass",   "length", "beam", "acceleration",
        "drag",      "max_speed",     "reverse_speed", "turn_rate", "slip", "ride_height",
        "bob_time",  "seat",          "look_time", "look_pitch",  "wake", NULL};
    ww_boat_desc *b = &c->sc->boat;
    section s;
    TRY(wwc_open_section(c, objects, "boat", keys, &s));
    ww_boat_defaults(b); /* a boat action without a section gets these */
    if (!s.map) return WW_OK;
    b->on = 1;
    TRY(wwc_get_vec(c, &s, "position", 3, &R_POSITION, OPTIONAL, b->position));
    TRY(wwc_get_heading(c, &s, "heading", OPTIONAL, &b->heading));
    TRY(wwc_get_number(c, &s, "radius", &R_SIZE, OPTIONAL, &b->radius));
    TRY(wwc_get_number(c, &s, "mass", &R_MASS, OPTIONAL, &b->mass));
    TRY(wwc_get_number(c, &s, "length", &R_SIZE, OPTIONAL, &b->length));
    TRY(wwc_get_number(c, &s, "beam", &R_SIZE, OPTIONAL, &b->beam));
    TRY(wwc_get_number(c, &s, "acceleration", &R_ACCELERATION, OPTIONAL, &b->acceleration));
    TRY(wwc_get_number(c, &s, "drag", &R_DRAG, OPTIONAL, &b->drag));
    TRY(wwc_get_number(c, &s, "max_speed", &R_SPEED, OPTIONAL, &b->max_speed));
    TRY(wwc_get_number(c, &s, "reverse_speed", &R_SPEED, OPTIONAL, &b->reverse_speed));
    TRY(wwc_get_angle(c, &s, "turn_rate", &R_TURN_RATE, OPTIONAL, &b->turn_rate));
    TRY(wwc_get_number(c, &s, "slip", &R_SLIP, OPTIONAL, &b->slip));
    TRY(wwc_get_number(c, &s, "ride_height", &R_RIDE_HEIGHT, OPTIONAL, &b->ride_height));
    TRY(wwc_get_number(c, &s, "bob_time", &R_TIME_CONSTANT, OPTIONAL, &b->bob_time));
    TRY(wwc_get_vec(c, &s, "seat", 3, &R_SEAT, OPTIONAL, b->seat));
    TRY(wwc_get_number(c, &s, "look_time", &R_TIME_CONSTANT, OPTIONAL, &b->look_time));
    TRY(wwc_get_angle(c, &s, "look_pitch", &R_LOOK_PITCH, OPTIONAL, &b->look_pitch));
    TRY(wwc_get_number(c, &s, "wake", &R_WAKE, OPTIONAL, &b->wake));

    /* seed 000: reverse is the reduced speed */
    if (b->reverse_speed > b->max_speed) {
        const ww_node *n = NULL;
        TRY(wwc_lookup(c, &s, "reverse_speed", OPTIONAL, &n));
        if (!n) TRY(wwc_lookup(c, &s, "max_speed", OPTIONAL, &n));
        return wwc_fail(c, WW_E_INCONSISTENT, n,
                        "%s: reverse_speed = %g m/s is above max_speed = %g m/s: expected the "
                        "reverse speed to be the reduced one",
                        s.what, b->reverse_speed, b->max_speed);
    }
    return WW_OK;
}

/* {throttle: -1..1, steer: -1..1, until: t}: v[0] throttle, v[1] steer, v[2] until (flags 1
 * when given; without it the inputs hold until the next boat action) */
ww_result wwc_action_boat(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    static const char *const keys[] = {"throttle", "steer", "until", NULL};
    section a;
    (void)value;
    TRY(wwc_open_section(c, s, "boat", keys, &a));
    if (!a.map) return WW_OK; /* not reached: the action is present */
    TRY(wwc_get_number(c, &a, "throttle", &R_INPUT, OPTIONAL, &ev->v[0]));
    TRY(wwc_get_number(c, &a, "steer", &R_INPUT, OPTIONAL, &ev->v[1]));
    const ww_node *until = NULL;
    TRY(wwc_lookup(c, &a, "until", OPTIONAL, &until));
    if (until) {
        TRY(wwc_get_number(c, &a, "until", &R_UNTIL, REQUIRED, &ev->v[2]));
        if (!(ev->v[2] > ev->t))
            return wwc_fail(c, WW_E_INCONSISTENT, until,
                            "%s.until = %g s is not after the event's t = %g s: expected the "
                            "inputs to end after they start",
                            a.what, ev->v[2], ev->t);
        ev->flags = 1;
    }
    c->sc->boat.on = 1;
    return WW_OK;
}

/* free | boat: ev->index 0 (the camera path) or 1 (the boat's seat); `boat` puts a boat in */
ww_result wwc_action_camera(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    int mode = 0;
    (void)value;
    TRY(wwc_get_word(c, s, "camera", CAMERA_WORDS, &mode));
    ev->index = mode;
    if (mode == 1) c->sc->boat.on = 1;
    return WW_OK;
}
