/* compile_cubes.c - objects.cubes (a list of floating boxes, each with its own buoyancy model,
 * drag, spring and press settings; defaults in ww_cube_default) and the script action
 * `press: {cube: i, hold: seconds}`. The model is in sim/cubes.c.
 *
 *   objects:
 *     cubes:
 *       - {position: [0, 0, -6], size: 1, density: 500}
 *       - {position: [3, 0, -6], size: 0.6, density: 800, rotation: [0, 30, 0],
 *          buoyancy: spring, spring: {stiffness: 30, damping: 2}}
 *   script:
 *     - {t: 2, press: {cube: 0, hold: 1.2}}
 */
#include <math.h>

#include "core/mathx.h"
#include "scene/compile_impl.h"

static const rule R_CUBE_POSITION = FINITE("m");
static const rule R_CUBE_ANGLE = FINITE("deg");
static const rule R_CUBE_SIZE = CLOSED(0.01, 100, "m");
static const rule R_CUBE_DENSITY = CLOSED(1, 1e5, "kg/m^3");
static const rule R_CUBE_COLUMNS = WHOLE(1, WW_CUBE_MAX_COLUMNS, "");
static const rule R_DRAG_RATE = CLOSED(0, 1e3, "1/s");
static const rule R_DRAG_CD = CLOSED(0, 100, "");
static const rule R_STIFFNESS = CLOSED(0, 1e6, "1/s^2");
static const rule R_DAMPING = CLOSED(0, 1e3, "1/s");
static const rule R_OFFSET = CLOSED(-100, 100, "m");
static const rule R_PRESS_ACCEL = CLOSED(0, 1e3, "m/s^2");
static const rule R_IMPULSE = CLOSED(0, 100, "m/s");
static const rule R_IMPULSE_RATE = CLOSED(0, 100, "m/s per s");
static const rule R_MAX_HOLD = CLOSED(0, 1e4, "s");
static const rule R_NUDGE = CLOSED(0, 100, "");
static const rule R_PRESS_CUBE = WHOLE(0, WW_MAX_CUBES - 1, "");
static const rule R_HOLD = OPEN_LO(0, 1e4, "s");

static const char *const BUOYANCY_WORDS[] = {[WW_CUBE_ARCHIMEDES] = "archimedes",
                                             [WW_CUBE_SPRING] = "spring", NULL};

/* rotation: [x, y, z] degrees about the world axes, applied x first, then y, then z */
static void quat_from_degrees(const double deg[3], double q[4]) {
    double r[4] = {1.0, 0.0, 0.0, 0.0};
    for (int a = 0; a < 3; a++) {
        double h = 0.5 * ww_m_rad(deg[a]), c = cos(h), s = sin(h);
        double e[4] = {c, 0.0, 0.0, 0.0};
        e[1 + a] = s;
        /* r <- e r */
        double w = e[0] * r[0] - e[1] * r[1] - e[2] * r[2] - e[3] * r[3];
        double x = e[0] * r[1] + e[1] * r[0] + e[2] * r[3] - e[3] * r[2];
        double y = e[0] * r[2] - e[1] * r[3] + e[2] * r[0] + e[3] * r[1];
        double z = e[0] * r[3] + e[1] * r[2] - e[2] * r[1] + e[3] * r[0];
        r[0] = w, r[1] = x, r[2] = y, r[3] = z;
    }
    for (int i = 0; i < 4; i++) q[i] = r[i];
}

static ww_result compile_cube(ctx *c, const ww_node *item, int i, ww_cube_desc *d) {
    static const char *const keys[] = {"position", "rotation", "size",   "density", "buoyancy",
                                       "columns",  "drag",     "spring", "press",   "nudge",
                                       NULL};
    static const char *const drag_keys[] = {"linear", "quadratic", "angular", NULL};
    static const char *const spring_keys[] = {"stiffness", "damping", "offset", NULL};
    static const char *const press_keys[] = {"acceleration", "j0", "j1", "max_hold", NULL};
    section s, sub;
    TRY(wwc_open_item(c, item, "objects.cubes", i, keys, &s));
    *d = ww_cube_default();
    TRY(wwc_get_vec(c, &s, "position", 3, &R_CUBE_POSITION, REQUIRED, d->position));
    double deg[3] = {0.0, 0.0, 0.0};
    TRY(wwc_get_vec(c, &s, "rotation", 3, &R_CUBE_ANGLE, OPTIONAL, deg));
    quat_from_degrees(deg, d->rotation);
    TRY(wwc_get_number(c, &s, "size", &R_CUBE_SIZE, OPTIONAL, &d->size));
    TRY(wwc_get_number(c, &s, "density", &R_CUBE_DENSITY, OPTIONAL, &d->density));
    int model = (int)d->buoyancy;
    TRY(wwc_get_word(c, &s, "buoyancy", BUOYANCY_WORDS, &model));
    d->buoyancy = (ww_cube_buoyancy)model;
    double columns = d->columns;
    TRY(wwc_get_number(c, &s, "columns", &R_CUBE_COLUMNS, OPTIONAL, &columns));
    d->columns = (int)columns;
    TRY(wwc_get_number(c, &s, "nudge", &R_NUDGE, OPTIONAL, &d->nudge));

    TRY(wwc_open_section(c, &s, "drag", drag_keys, &sub));
    TRY(wwc_get_number(c, &sub, "linear", &R_DRAG_RATE, OPTIONAL, &d->drag_linear));
    TRY(wwc_get_number(c, &sub, "quadratic", &R_DRAG_CD, OPTIONAL, &d->drag_quadratic));
    TRY(wwc_get_number(c, &sub, "angular", &R_DRAG_RATE, OPTIONAL, &d->drag_angular));

    /* the spring's rest offset defaults to where Archimedes floats the box: the centre is
     * H/2 - (rho / 1000) H above the surface */
    d->spring_offset = d->size * (0.5 - d->density / 1000.0);
    TRY(wwc_open_section(c, &s, "spring", spring_keys, &sub));
    TRY(wwc_get_number(c, &sub, "stiffness", &R_STIFFNESS, OPTIONAL, &d->spring_stiffness));
    TRY(wwc_get_number(c, &sub, "damping", &R_DAMPING, OPTIONAL, &d->spring_damping));
    TRY(wwc_get_number(c, &sub, "offset", &R_OFFSET, OPTIONAL, &d->spring_offset));

    TRY(wwc_open_section(c, &s, "press", press_keys, &sub));
    TRY(wwc_get_number(c, &sub, "acceleration", &R_PRESS_ACCEL, OPTIONAL, &d->press_accel));
    TRY(wwc_get_number(c, &sub, "j0", &R_IMPULSE, OPTIONAL, &d->press_j0));
    TRY(wwc_get_number(c, &sub, "j1", &R_IMPULSE_RATE, OPTIONAL, &d->press_j1));
    return wwc_get_number(c, &sub, "max_hold", &R_MAX_HOLD, OPTIONAL, &d->press_max_hold);
}

ww_result wwc_cubes(ctx *c, const section *objects) {
    ww_cubes_desc *cd = &c->sc->cubes;
    const ww_node *list;
    TRY(wwc_get_list(c, objects, "cubes", WW_MAX_CUBES, &list));
    /* cubes: [] is no cubes, as when the key is absent (--set objects.cubes=[] removes them) */
    if (!list || list->n == 0) return WW_OK;
    int n = 0;
    for (const ww_node *item = list->first; item; item = item->next, n++)
        TRY(compile_cube(c, item, n, &cd->cube[n]));
    cd->count = n;
    cd->on = 1;
    return WW_OK;
}

/* press: {cube: i, hold: s}: ev->index = i, ev->v[0] = hold (sim/cubes.h). The release splashes,
 * so the ripple pool is turned on; the cube index is checked against the list in
 * wwc_check_cubes once the whole scene is read. */
ww_result wwc_action_press(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    static const char *const keys[] = {"cube", "hold", NULL};
    (void)value;
    section p;
    double cube = 0.0;
    TRY(wwc_open_section(c, s, "press", keys, &p));
    TRY(wwc_get_number(c, &p, "cube", &R_PRESS_CUBE, REQUIRED, &cube));
    TRY(wwc_get_number(c, &p, "hold", &R_HOLD, REQUIRED, &ev->v[0]));
    ev->index = (int)cube;
    c->sc->ripples_on = 1;
    return WW_OK;
}
