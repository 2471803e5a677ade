/* compile_fishing.c - objects.rod, objects.fish and the `cast` action: defaults (seed 000's rod
 * and fish, seed 003's targets), ranges, and the event payload documented in sim/rod.h.
 *
 *   objects:
 *     rod: {angle: [10, 40], speed: [6, 16], drag: 0.3, window: 10, bite_radius: 2}
 *     fish: {count: 12, center: [0, -2, 0], radius: 15, mode: wander}
 *   script:
 *     - {t: 2.5, cast: {charge: 0.6}}
 *     - {t: 9.0, cast: {speed: 12, angle: 25, from: [0, 1.5, 0], heading: 90}}
 */
#include <math.h>

#include "core/mathx.h"
#include "scene/compile_impl.h"

static const rule R_CAST_ANGLE = CLOSED(-89, 89, "deg");
static const rule R_CAST_SPEED = OPEN_LO(0, 1000, "m/s");
static const rule R_CHARGE = CLOSED(0, 1, "");
static const rule R_GRAVITY = OPEN_LO(0, 10, "g"); /* without gravity a lure never lands */
static const rule R_RATE = CLOSED(0, 100, "1/s");
static const rule R_OFFSET = CLOSED(-10, 10, "m");
static const rule R_WINDOW = OPEN_LO(0, 1e4, "s");
static const rule R_RADIUS = CLOSED(0, 1e3, "m");
static const rule R_SMALL_HEIGHT = CLOSED(0, 10, "m");
static const rule R_LINE_WIDTH = CLOSED(0, 0.05, "m");
static const rule R_LINE_COLOR = CLOSED(0, 1, "");
static const rule R_PLACE = FINITE("m");
static const rule R_COUNT = WHOLE(1, WW_MAX_FISH, "");
static const rule R_REGION = OPEN_LO(0, 1e5, "m");
static const rule R_FISH_SPEED = OPEN_LO(0, 100, "m/s");
static const rule R_TURN_RATE = OPEN_LO(0, 3600, "deg/s");
static const rule R_TURN = CLOSED(0, 180, "deg");
static const rule R_JITTER = CLOSED(0, 3600, "deg/sqrt(s)");
static const rule R_PER_SECOND = CLOSED(0, 100, "1/s");
static const rule R_SWIM = CLOSED(0, 1e3, "");
static const rule R_BANK = CLOSED(0, 89, "deg");
static const rule R_LENGTH = OPEN_LO(0, 100, "m");
static const rule R_DURATION = OPEN_LO(0, 1e5, "s");
static const rule R_WIGGLE = CLOSED(0, 1e3, "");
static const rule R_REACH = OPEN_LO(0, 1e3, "m");

void ww_rod_defaults(ww_rod_desc *r) {
    *r = (ww_rod_desc){.on = 0,
                       .angle = {ww_m_rad(10.0), ww_m_rad(40.0)},
                       .speed = {6.0, 16.0},
                       .gravity = 1.0,
                       .drag = 0.3,
                       .offset = {0.5, 0.3, -0.2},
                       .window = 10.0,
                       .bite_radius = 2.0,
                       .attract = 6.0,
                       .float_height = 0.02,
                       .float_drag = 5.0,
                       .hook_depth = 0.4,
                       .splash = 0.03,
                       .line_width = 0.003,
                       .line_color = {0.85, 0.85, 0.8}};
}

void ww_fish_defaults(ww_fish_desc *f) {
    *f = (ww_fish_desc){.on = 0,
                        .count = 12,
                        .mode = WW_FISH_WANDER,
                        .center = {0.0, -2.0, 0.0},
                        .radius = 15.0,
                        .spread = 1.0,
                        .margin = 0.3,
                        .speed = 1.2,
                        .max_speed = 3.0,
                        .response = 2.0,
                        .turn_rate = ww_m_rad(120.0),
                        .jitter = ww_m_rad(40.0),
                        .big_turn = ww_m_rad(90.0),
                        .big_turn_rate = 0.15,
                        .avoid = 4.0,
                        .separation = 0.8,
                        .swim = {0.15, 3.0},
                        .max_bank = ww_m_rad(35.0),
                        .length = 0.5,
                        .fight = {1.5, 4.0},
                        .wiggle = {ww_m_rad(20.0), 3.0},
                        .respawn = 6.0,
                        .reach = 0.5};
}

static ww_result compile_rod(ctx *c, const section *objects) {
    static const char *const keys[] = {"angle",  "speed",       "gravity", "drag",
                                       "offset", "window",      "bite_radius", "attract",
                                       "float_height", "float_drag", "hook_depth", "splash",
                                       "line_width", "line_color", NULL};
    ww_rod_desc *r = &c->sc->rod;
    section s;
    TRY(wwc_open_section(c, objects, "rod", keys, &s));
    if (!s.map) return WW_OK;
    r->on = 1;
    /* the file gives [flattest, steepest] in degrees */
    double a[2] = {ww_m_deg(r->angle[0]), ww_m_deg(r->angle[1])};
    TRY(wwc_get_range(c, &s, "angle", &R_CAST_ANGLE, 1, a));
    r->angle[0] = ww_m_rad(a[0]);
    r->angle[1] = ww_m_rad(a[1]);
    TRY(wwc_get_range(c, &s, "speed", &R_CAST_SPEED, 1, r->speed));
    TRY(wwc_get_number(c, &s, "gravity", &R_GRAVITY, OPTIONAL, &r->gravity));
    TRY(wwc_get_number(c, &s, "drag", &R_RATE, OPTIONAL, &r->drag));
    TRY(wwc_get_vec(c, &s, "offset", 3, &R_OFFSET, OPTIONAL, r->offset));
    TRY(wwc_get_number(c, &s, "window", &R_WINDOW, OPTIONAL, &r->window));
    TRY(wwc_get_number(c, &s, "bite_radius", &R_RADIUS, OPTIONAL, &r->bite_radius));
    TRY(wwc_get_number(c, &s, "attract", &R_RADIUS, OPTIONAL, &r->attract));
    TRY(wwc_get_number(c, &s, "float_height", &R_SMALL_HEIGHT, OPTIONAL, &r->float_height));
    TRY(wwc_get_number(c, &s, "float_drag", &R_RATE, OPTIONAL, &r->float_drag));
    TRY(wwc_get_number(c, &s, "hook_depth", &R_SMALL_HEIGHT, OPTIONAL, &r->hook_depth));
    TRY(wwc_get_number(c, &s, "splash", &R_SMALL_HEIGHT, OPTIONAL, &r->splash));
    TRY(wwc_get_number(c, &s, "line_width", &R_LINE_WIDTH, OPTIONAL, &r->line_width));
    TRY(wwc_get_vec(c, &s, "line_color", 3, &R_LINE_COLOR, OPTIONAL, r->line_color));
    return WW_OK;
}

/* positions: a list of [x, y, z], one per fish from fish 0 */
static ww_result compile_positions(ctx *c, const section *s, ww_fish_desc *f) {
    const ww_node *list;
    TRY(wwc_get_list(c, s, "positions", WW_MAX_FISH, &list));
    if (!list) return WW_OK;
    int i = 0;
    for (const ww_node *e = list->first; e; e = e->next, i++) {
        char name[160];
        snprintf(name, sizeof name, "%s.positions[%d]", wwc_where(s), i);
        if (e->kind != WW_NODE_SEQ || e->n != 3)
            return wwc_fail(c, WW_E_TYPE, e, "%s: expected a list of 3 numbers", name);
        int k = 0;
        for (const ww_node *v = e->first; v; v = v->next, k++) {
            char item[176];
            snprintf(item, sizeof item, "%s[%d]", name, k);
            TRY(wwc_check_number(c, v, item, &R_PLACE, &f->positions[i][k]));
        }
    }
    if (i > f->count)
        return wwc_fail(c, WW_E_INCONSISTENT, list,
                        "%s.positions: %d positions for %d fish", wwc_where(s), i, f->count);
    f->npositions = i;
    return WW_OK;
}

static ww_result compile_fish(ctx *c, const section *objects) {
    static const char *const keys[] = {
        "count",  "center",    "radius",     "mode",     "spread",    "margin",   "positions",
        "speed",  "max_speed", "response",   "turn_rate", "jitter",   "big_turn", "big_turn_rate",
        "avoid",  "separation", "swim",      "max_bank", "length",    "fight",    "wiggle",
        "respawn", "reach",    "species", NULL};
    static const char *const modes[] = {"wander", "targets", NULL};
    ww_fish_desc *f = &c->sc->fish;
    section s;
    TRY(wwc_open_section(c, objects, "fish", keys, &s));
    if (!s.map) return WW_OK;
    f->on = 1;
    double count = f->count;
    TRY(wwc_get_number(c, &s, "count", &R_COUNT, OPTIONAL, &count));
    f->count = (int)count;
    TRY(wwc_fish_species(c, &s, f)); /* sets the count when given */
    TRY(wwc_get_vec(c, &s, "center", 3, &R_PLACE, OPTIONAL, f->center));
    TRY(wwc_get_number(c, &s, "radius", &R_REGION, OPTIONAL, &f->radius));
    int mode = (int)f->mode;
    TRY(wwc_get_word(c, &s, "mode", modes, &mode));
    f->mode = (ww_fish_mode)mode;
    TRY(wwc_get_number(c, &s, "spread", &R_SMALL_HEIGHT, OPTIONAL, &f->spread));
    TRY(wwc_get_number(c, &s, "margin", &R_SMALL_HEIGHT, OPTIONAL, &f->margin));
    TRY(compile_positions(c, &s, f));
    TRY(wwc_get_number(c, &s, "speed", &R_FISH_SPEED, OPTIONAL, &f->speed));
    TRY(wwc_get_number(c, &s, "max_speed", &R_FISH_SPEED, OPTIONAL, &f->max_speed));
    TRY(wwc_get_number(c, &s, "response", &R_RATE, OPTIONAL, &f->response));
    TRY(wwc_get_angle(c, &s, "turn_rate", &R_TURN_RATE, OPTIONAL, &f->turn_rate));
    TRY(wwc_get_angle(c, &s, "jitter", &R_JITTER, OPTIONAL, &f->jitter));
    TRY(wwc_get_angle(c, &s, "big_turn", &R_TURN, OPTIONAL, &f->big_turn));
    TRY(wwc_get_number(c, &s, "big_turn_rate", &R_PER_SECOND, OPTIONAL, &f->big_turn_rate));
    TRY(wwc_get_number(c, &s, "avoid", &R_RADIUS, OPTIONAL, &f->avoid));
    TRY(wwc_get_number(c, &s, "separation", &R_RADIUS, OPTIONAL, &f->separation));
    TRY(wwc_get_vec(c, &s, "swim", 2, &R_SWIM, OPTIONAL, f->swim));
    TRY(wwc_get_angle(c, &s, "max_bank", &R_BANK, OPTIONAL, &f->max_bank));
    TRY(wwc_get_number(c, &s, "length", &R_LENGTH, OPTIONAL, &f->length));
    TRY(wwc_get_range(c, &s, "fight", &R_DURATION, 1, f->fight));
    double w[2] = {ww_m_deg(f->wiggle[0]), f->wiggle[1]};
    TRY(wwc_get_vec(c, &s, "wiggle", 2, &R_WIGGLE, OPTIONAL, w));
    f->wiggle[0] = ww_m_rad(w[0]);
    f->wiggle[1] = w[1];
    TRY(wwc_get_number(c, &s, "respawn", &R_DURATION, OPTIONAL, &f->respawn));
    TRY(wwc_get_number(c, &s, "reach", &R_REACH, OPTIONAL, &f->reach));

    /* values fine alone, wrong together */
    const ww_node *at = s.map;
    const ww_node *max_speed = ww_node_find(s.map, "max_speed");
    if (f->max_speed < f->speed)
        return wwc_fail(c, WW_E_INCONSISTENT, max_speed ? max_speed : at, "%s: max_speed %g m/s is below speed %g m/s",
                        s.what, f->max_speed, f->speed);
    double floor = c->sc->water_level - c->sc->water_depth;
    const ww_node *center = ww_node_find(s.map, "center");
    if (!(f->center[1] < c->sc->water_level && f->center[1] > floor))
        return wwc_fail(c, WW_E_INCONSISTENT, center ? center : at,
                        "%s: center y %g m is not in the water (seabed %g m, level %g m)", s.what,
                        f->center[1], floor, c->sc->water_level);
    if (2.0 * f->margin >= c->sc->water_depth)
        return wwc_fail(c, WW_E_INCONSISTENT, at,
                        "%s: margin %g m leaves no room in water %g m deep", s.what, f->margin,
                        c->sc->water_depth);
    return wwc_fish_species_resolve(c, &s, f);
}

ww_result wwc_fishing(ctx *c, const section *objects) {
    ww_rod_defaults(&c->sc->rod);
    ww_fish_defaults(&c->sc->fish);
    TRY(compile_rod(c, objects));
    TRY(compile_fish(c, objects));
    if (c->sc->rod.on) c->sc->ripples_on = 1; /* the lure's splash */
    return WW_OK;
}

/* the payload is documented in sim/rod.h (WW_CAST_*) */
ww_result wwc_action_cast(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    static const char *const keys[] = {"charge", "speed", "angle", "from", "heading", NULL};
    section a;
    TRY(wwc_open_section(c, s, "cast", keys, &a));
    if (!a.map) return wwc_fail(c, WW_E_TYPE, value, "%s.cast: expected a mapping", s->what);
    const ww_node *charge = ww_node_find(a.map, "charge");
    const ww_node *speed = ww_node_find(a.map, "speed");
    const ww_node *angle = ww_node_find(a.map, "angle");
    if (charge && (speed || angle))
        return wwc_fail(c, WW_E_INCONSISTENT, speed ? speed : angle,
                        "%s: give charge, or speed and angle, not both", a.what);
    if (charge) {
        ev->flags |= WW_CAST_CHARGE;
        TRY(wwc_get_number(c, &a, "charge", &R_CHARGE, REQUIRED, &ev->v[2]));
    } else {
        if (!speed && !angle)
            return wwc_fail(c, WW_E_MISSING, a.map, "%s: expected charge, or speed and angle",
                            a.what);
        TRY(wwc_get_number(c, &a, "speed", &R_CAST_SPEED, REQUIRED, &ev->v[0]));
        TRY(wwc_get_angle(c, &a, "angle", &R_CAST_ANGLE, REQUIRED, &ev->v[1]));
    }
    if (ww_node_find(a.map, "from") || ww_node_find(a.map, "heading")) {
        ev->flags |= WW_CAST_FROM;
        TRY(wwc_get_vec(c, &a, "from", 3, &R_PLACE, REQUIRED, &ev->v[3]));
        TRY(wwc_get_heading(c, &a, "heading", REQUIRED, &ev->v[6]));
    }
    c->sc->rod.on = 1;
    c->sc->ripples_on = 1;
    return WW_OK;
}
