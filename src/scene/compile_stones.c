/* compile_stones.c - objects.stones (the stones' physics, every key optional) and the script's
 * `throw` action. Defaults reproduce Clanet, Hersen & Bocquet (Nature 2004): with the default
 * mass, radius and lift the lowest skipping speed is found near 23 deg of incidence and nothing
 * skips above 45 deg (the criterion and its derivation are in sim/stones.h).
 *
 *   objects: {stones: {mass: 0.1, radius: 0.04, e_n: 0.55, c_t: 0.85}}
 *   script:
 *     - {t: 1, throw: {charge: 0.8}}                              # from the camera
 *     - {t: 2, throw: {speed: 12, angle: 10, spin: 8, from: [0, 1.5, 0], heading: 90}}
 */
#include <math.h>

#include "core/mathx.h"
#include "scene/compile_impl.h"

static const rule R_MASS = OPEN_LO(0, 100, "kg");
static const rule R_RADIUS = OPEN_LO(0, 1, "m");
static const rule R_COEFF = CLOSED(0, 100, "");
static const rule R_FRACTION = CLOSED(0, 1, "");
static const rule R_BOUNCES = WHOLE(0, 1000, "");
static const rule R_SPEED = CLOSED(0, 1e3, "m/s");
static const rule R_THROW_SPEED = OPEN_LO(0, 1e3, "m/s");
static const rule R_RIPPLE = CLOSED(0, 10, "m");
static const rule R_DOWN_ANGLE = CLOSED(-89, 89, "deg");
static const rule R_SPIN = CLOSED(0, 1e3, "rev/s");
static const rule R_CHARGE = CLOSED(0, 1, "");
static const rule R_FROM = FINITE("m");

void ww_stones_defaults(ww_stones_desc *d) {
    *d = (ww_stones_desc){
        .on = 0,
        .mass = 0.1,
        .radius = 0.04,
        .drag = 0.0,
        /* lambda = 4 rho C a^3 / M = 1.408: no skip above 44.9 deg (sim/stones.h) */
        .lift = 0.55,
        .e_n = 0.55,
        .c_t = 0.85,
        .restitution = 0.3,
        .max_bounces = 40,
        .splash_full = 4.0,
        .sink_speed = 0.6,
        .ripple = 0.03,
        .ripple_tiny = 0.008,
        .throw_angle = {ww_m_rad(3.0), ww_m_rad(20.0)},
        .throw_speed = {6.0, 16.0},
        .throw_spin = 10.0 * WW_TAU,
    };
}

ww_result wwc_stones(ctx *c, const section *objects) {
    static const char *const keys[] = {"mass", "radius", "drag", "lift", "e_n", "c_t",
                                       "restitution", "max_bounces", "splash_full",
                                       "sink_speed", "ripple", "ripple_tiny", "throw_angle",
                                       "throw_speed", "throw_spin", NULL};
    ww_stones_desc *d = &c->sc->stones;
    ww_stones_defaults(d);
    section s;
    TRY(wwc_open_section(c, objects, "stones", keys, &s));
    if (!s.map) return WW_OK;
    d->on = 1;
    c->sc->ripples_on = 1;
    double bounces = d->max_bounces;
    double angle_deg[2] = {ww_m_deg(d->throw_angle[0]), ww_m_deg(d->throw_angle[1])};
    double spin = d->throw_spin / WW_TAU;
    TRY(wwc_get_number(c, &s, "mass", &R_MASS, OPTIONAL, &d->mass));
    TRY(wwc_get_number(c, &s, "radius", &R_RADIUS, OPTIONAL, &d->radius));
    TRY(wwc_get_number(c, &s, "drag", &R_COEFF, OPTIONAL, &d->drag));
    TRY(wwc_get_number(c, &s, "lift", &R_COEFF, OPTIONAL, &d->lift));
    TRY(wwc_get_number(c, &s, "e_n", &R_FRACTION, OPTIONAL, &d->e_n));
    TRY(wwc_get_number(c, &s, "c_t", &R_FRACTION, OPTIONAL, &d->c_t));
    TRY(wwc_get_number(c, &s, "restitution", &R_FRACTION, OPTIONAL, &d->restitution));
    TRY(wwc_get_number(c, &s, "max_bounces", &R_BOUNCES, OPTIONAL, &bounces));
    TRY(wwc_get_number(c, &s, "splash_full", &R_SPEED, OPTIONAL, &d->splash_full));
    TRY(wwc_get_number(c, &s, "sink_speed", &R_THROW_SPEED, OPTIONAL, &d->sink_speed));
    TRY(wwc_get_number(c, &s, "ripple", &R_RIPPLE, OPTIONAL, &d->ripple));
    TRY(wwc_get_number(c, &s, "ripple_tiny", &R_RIPPLE, OPTIONAL, &d->ripple_tiny));
    TRY(wwc_get_range(c, &s, "throw_angle", &R_DOWN_ANGLE, 1, angle_deg));
    TRY(wwc_get_range(c, &s, "throw_speed", &R_THROW_SPEED, 1, d->throw_speed));
    TRY(wwc_get_number(c, &s, "throw_spin", &R_SPIN, OPTIONAL, &spin));
    d->max_bounces = (int)bounces;
    d->throw_angle[0] = ww_m_rad(angle_deg[0]);
    d->throw_angle[1] = ww_m_rad(angle_deg[1]);
    d->throw_spin = spin * WW_TAU;
    return WW_OK;
}

/* throw: {charge} or {speed, angle[, spin]}, optionally {from, heading}; the payload is
 * documented in sim/stones.h. A charge is mapped here, as seed 000 maps the hold time:
 *   angle = angle_min + (1 - charge) (angle_max - angle_min),
 *   speed = speed_min + charge (speed_max - speed_min)   (longer hold: flatter and faster) */
ww_result wwc_action_throw(ctx *c, const section *event, const ww_node *value, ww_event *ev) {
    static const char *const keys[] = {"charge", "speed", "angle", "spin", "from", "heading",
                                       NULL};
    ww_stones_desc *d = &c->sc->stones;
    section s;
    TRY(wwc_open_section(c, event, "throw", keys, &s));
    if (!s.map)
        return wwc_fail(c, WW_E_MISSING, value, "%s.throw: expected {charge} or {speed, angle}",
                        event->what);
    const ww_node *charge = ww_node_find(s.map, "charge");
    const ww_node *speed = ww_node_find(s.map, "speed");
    const ww_node *angle = ww_node_find(s.map, "angle");
    const ww_node *from = ww_node_find(s.map, "from");
    const ww_node *heading = ww_node_find(s.map, "heading");
    double spin = d->throw_spin / WW_TAU;

    if (charge && (speed || angle))
        return wwc_fail(c, WW_E_INCONSISTENT, speed ? speed->key : angle->key,
                        "%s has charge and %s: expected a charge or an explicit speed and angle",
                        wwc_where(&s), speed ? "speed" : "angle");
    if (charge) {
        double q = 0.0;
        TRY(wwc_get_number(c, &s, "charge", &R_CHARGE, REQUIRED, &q));
        ev->v[0] = ww_m_lerp(d->throw_speed[0], d->throw_speed[1], q);
        ev->v[1] = ww_m_lerp(d->throw_angle[0], d->throw_angle[1], 1.0 - q);
        ev->v[7] = q;
    } else {
        if (!speed)
            return wwc_fail(c, WW_E_MISSING, s.map,
                            "%s is missing 'charge' or 'speed': expected {charge} or {speed, "
                            "angle}",
                            wwc_where(&s));
        TRY(wwc_get_number(c, &s, "speed", &R_THROW_SPEED, REQUIRED, &ev->v[0]));
        TRY(wwc_get_angle(c, &s, "angle", &R_DOWN_ANGLE, REQUIRED, &ev->v[1]));
        ev->v[7] = -1.0;
    }
    TRY(wwc_get_number(c, &s, "spin", &R_SPIN, OPTIONAL, &spin));
    ev->v[2] = spin * WW_TAU;

    if (heading && !from)
        return wwc_fail(c, WW_E_INCONSISTENT, heading->key,
                        "%s has a heading but no 'from': a throw from the camera takes the "
                        "camera's heading",
                        wwc_where(&s));
    if (from) {
        TRY(wwc_get_vec(c, &s, "from", 3, &R_FROM, REQUIRED, &ev->v[3]));
        ev->v[6] = 0.0;
        TRY(wwc_get_heading(c, &s, "heading", OPTIONAL, &ev->v[6]));
        ev->flags |= WW_THROW_FROM;
    }
    d->on = 1;
    c->sc->ripples_on = 1;
    return WW_OK;
}
