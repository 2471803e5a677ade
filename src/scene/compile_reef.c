/* compile_reef.c - objects.chest, objects.bubbles and objects.models (scene/desc_reef.h), and the
 * `chest` script action. Defaults follow seed 000 for the chest (first spawn and interval about
 * five minutes, a 15 s lifetime) and measured bubble rise speeds for the emitters (see
 * sim/bubbles.h).
 */
#include <stdio.h>
#include <string.h>

#include "scene/compile_impl.h"

static const rule R_CHEST_FIRST = CLOSED(0, 1e9, "s");
static const rule R_CHEST_EVERY = OPEN_LO(0, 1e9, "s");
static const rule R_CHEST_TTL = OPEN_LO(0, 1e9, "s");
static const rule R_CHEST_RADIUS = CLOSED(0, 1e4, "m");
static const rule R_CHEST_REACH = OPEN_LO(0, 1e3, "m");
static const rule R_CHEST_SIZE = OPEN_LO(0, 100, "m");
static const rule R_PLACE = FINITE("m");
static const rule R_BUBBLE_RATE = OPEN_LO(0, 1000, "1/s");
static const rule R_BUBBLE_SPEED = OPEN_LO(0, 100, "m/s");
static const rule R_BUBBLE_WOBBLE = CLOSED(0, 10, "m");
static const rule R_BUBBLE_FREQUENCY = CLOSED(0, 100, "Hz");
static const rule R_BUBBLE_SIZE = OPEN_LO(0, 1, "m");
static const rule R_BUBBLE_COUNT = WHOLE(1, WW_MAX_BUBBLES_PER_EMITTER, "");

static const char *const NEAR_WORDS[] = {[WW_CHEST_NEAR_AUTO] = "auto",
                                         [WW_CHEST_NEAR_BOAT] = "boat",
                                         [WW_CHEST_NEAR_CAMERA] = "camera", NULL};

/* seed 000: the first chest about five minutes in, then every five minutes, 15 s to find it */
void ww_chest_defaults(ww_chest_desc *d) {
    *d = (ww_chest_desc){.first = 300.0,
                         .every = 300.0,
                         .ttl = 15.0,
                         .radius = 12.0,
                         .near = WW_CHEST_NEAR_AUTO,
                         .reach = 2.0,
                         .size = {0.9, 0.6, 0.6}};
}

static ww_result compile_chest(ctx *c, const section *objects) {
    static const char *const keys[] = {"first", "every", "ttl", "radius", "near", "reach", "size",
                                       NULL};
    ww_chest_desc *d = &c->sc->chest;
    int on = d->on; /* a chest event read earlier keeps it on */
    ww_chest_defaults(d);
    d->on = on;
    section s;
    TRY(wwc_open_section(c, objects, "chest", keys, &s));
    if (!s.map) return WW_OK;
    d->on = 1;
    TRY(wwc_get_number(c, &s, "first", &R_CHEST_FIRST, OPTIONAL, &d->first));
    TRY(wwc_get_number(c, &s, "every", &R_CHEST_EVERY, OPTIONAL, &d->every));
    TRY(wwc_get_number(c, &s, "ttl", &R_CHEST_TTL, OPTIONAL, &d->ttl));
    TRY(wwc_get_number(c, &s, "radius", &R_CHEST_RADIUS, OPTIONAL, &d->radius));
    int near = (int)d->near;
    TRY(wwc_get_word(c, &s, "near", NEAR_WORDS, &near));
    d->near = (ww_chest_near)near;
    TRY(wwc_get_number(c, &s, "reach", &R_CHEST_REACH, OPTIONAL, &d->reach));
    TRY(wwc_get_vec(c, &s, "size", 3, &R_CHEST_SIZE, OPTIONAL, d->size));

    /* objects.boat is read before this section (compile_objects) */
    if (d->near == WW_CHEST_NEAR_BOAT && !c->sc->boat.on)
        return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(s.map, "near"),
                        "%s.near is boat, but the scene has no boat: expected near: camera, or "
                        "an objects.boat section",
                        s.what);

    /* a new chest replaces the old one, so a lifetime past the interval would be cut short */
    if (d->ttl > d->every) {
        const ww_node *n = ww_node_find(s.map, "ttl");
        return wwc_fail(c, WW_E_INCONSISTENT, n ? n : s.map,
                        "%s.ttl = %g s is longer than %s.every = %g s: expected ttl <= every (the "
                        "next chest would replace this one before it expires)",
                        s.what, d->ttl, s.what, d->every);
    }
    return WW_OK;
}

static ww_result compile_emitter(ctx *c, const ww_node *item, int i, ww_emitter_desc *e) {
    static const char *const keys[] = {"at", "rate", "speed", "wobble", "frequency", "size",
                                       "count", NULL};
    section s;
    TRY(wwc_open_item(c, item, "objects.bubbles", i, keys, &s));
    *e = (ww_emitter_desc){.rate = 2.0,
                           .speed = 0.25,
                           .wobble = 0.03,
                           .frequency = 2.0,
                           .size = 0.01,
                           .count = 16};
    double count = e->count;
    TRY(wwc_get_vec(c, &s, "at", 3, &R_PLACE, REQUIRED, e->at));
    TRY(wwc_get_number(c, &s, "rate", &R_BUBBLE_RATE, OPTIONAL, &e->rate));
    TRY(wwc_get_number(c, &s, "speed", &R_BUBBLE_SPEED, OPTIONAL, &e->speed));
    TRY(wwc_get_number(c, &s, "wobble", &R_BUBBLE_WOBBLE, OPTIONAL, &e->wobble));
    TRY(wwc_get_number(c, &s, "frequency", &R_BUBBLE_FREQUENCY, OPTIONAL, &e->frequency));
    TRY(wwc_get_number(c, &s, "size", &R_BUBBLE_SIZE, OPTIONAL, &e->size));
    TRY(wwc_get_number(c, &s, "count", &R_BUBBLE_COUNT, OPTIONAL, &count));
    e->count = (int)count;

    /* a vent above the rest level would release bubbles into the air */
    if (!(e->at[1] < c->sc->water_level))
        return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(s.map, "at"),
                        "%s.at[1] = %g is not below the water level %g: expected an emitter under "
                        "water",
                        s.what, e->at[1], c->sc->water_level);
    return WW_OK;
}

static ww_result compile_bubbles(ctx *c, const section *objects) {
    ww_bubbles_desc *d = &c->sc->bubbles;
    const ww_node *list;
    *d = (ww_bubbles_desc){0};
    TRY(wwc_get_list(c, objects, "bubbles", WW_MAX_EMITTERS, &list));
    int i = 0, total = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++) {
        TRY(compile_emitter(c, item, i, &d->emitter[i]));
        d->emitter[i].first = total;
        total += d->emitter[i].count;
    }
    d->count = i;
    d->total = total;
    d->on = i > 0;
    return WW_OK;
}

static ww_result compile_model(ctx *c, const ww_node *item, int i, ww_model_desc *m) {
    static const char *const keys[] = {"name", "min", "max", NULL};
    static const char *const axes[] = {"x", "y", "z"};
    section s;
    const ww_node *name;
    TRY(wwc_open_item(c, item, "objects.models", i, keys, &s));
    *m = (ww_model_desc){0};
    TRY(wwc_lookup(c, &s, "name", OPTIONAL, &name));
    if (name) {
        if (name->kind != WW_NODE_SCALAR || ww_node_is_null(name))
            return wwc_fail(c, WW_E_TYPE, name, "%s.name: expected a word", s.what);
        if (name->len >= sizeof m->name)
            return wwc_fail(c, WW_E_RANGE, name, "%s.name is %zu characters: expected at most %zu",
                            s.what, name->len, sizeof m->name - 1);
        snprintf(m->name, sizeof m->name, "%s", name->text);
    }
    TRY(wwc_get_vec(c, &s, "min", 3, &R_PLACE, REQUIRED, m->min));
    TRY(wwc_get_vec(c, &s, "max", 3, &R_PLACE, REQUIRED, m->max));
    for (int a = 0; a < 3; a++)
        if (!(m->min[a] < m->max[a]))
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(s.map, "max"),
                            "%s: max.%s = %g is not above min.%s = %g: expected min < max on "
                            "every axis",
                            s.what, axes[a], m->max[a], axes[a], m->min[a]);
    return WW_OK;
}

static ww_result compile_models(ctx *c, const section *objects) {
    ww_models_desc *d = &c->sc->models;
    const ww_node *list;
    *d = (ww_models_desc){0};
    TRY(wwc_get_list(c, objects, "models", WW_MAX_MODELS, &list));
    int i = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++)
        TRY(compile_model(c, item, i, &d->model[i]));
    d->count = i;
    return WW_OK;
}

ww_result wwc_reef(ctx *c, const section *objects) {
    TRY(compile_chest(c, objects));
    TRY(compile_bubbles(c, objects));
    return compile_models(c, objects);
}

/* chest: {at: [x, z]} forces a spawn there; chest: {} (or nothing) forces one by the random
 * rule. ev->flags bit 0: at given; ev->v[0], v[1]: x, z (sim/chest.h) */
ww_result wwc_action_chest(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    static const char *const keys[] = {"at", NULL};
    c->sc->chest.on = 1;
    if (ww_node_is_null(value)) return WW_OK;
    section a;
    TRY(wwc_open_section(c, s, "chest", keys, &a));
    if (ww_node_find(a.map, "at")) {
        TRY(wwc_get_vec(c, &a, "at", 2, &R_PLACE, REQUIRED, ev->v));
        ev->flags |= 1;
    }
    return WW_OK;
}
