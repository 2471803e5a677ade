/* compile_fish_species.c - objects.fish.species (scene/desc_fish_species.h): a list of species,
 * each with its body plan, count, length, colour, speed and school region. The fish count is the
 * species' sum (objects.fish.count may not be given with them); a species' speed, centre and
 * radius default to objects.fish's, its length and colour to its shape's.
 *
 *   species:
 *     - {shape: slim, count: 10, color: [0.16, 0.32, 0.42], center: [0, -5, -10], radius: 4}
 *     - {shape: deep, count: 6, length: 0.22}
 */
#include <math.h>

#include "scene/compile_impl.h"

static const rule R_SPECIES_COUNT = WHOLE(1, WW_MAX_FISH, "");
static const rule R_SPECIES_LENGTH = CLOSED(0.02, 10, "m");
static const rule R_SPECIES_COLOR = CLOSED(0, 1, "");
static const rule R_SPECIES_SPEED = OPEN_LO(0, 100, "m/s");
static const rule R_SPECIES_PLACE = FINITE("m");
static const rule R_SPECIES_RADIUS = OPEN_LO(0, 1e5, "m");

static const char *const SHAPE_WORDS[] = {[WW_FISH_SLIM] = "slim", [WW_FISH_DEEP] = "deep",
                                          [WW_FISH_LONG] = "long", NULL};

/* each shape's defaults: a mackerel's length and its blue-green back; a butterflyfish's length
 * and yellow; a long red fish (a cornetfish or a red snapper's colour) */
static const double SHAPE_LENGTH[WW_FISH_SHAPES] = {0.38, 0.22, 0.7};
static const double SHAPE_COLOR[WW_FISH_SHAPES][3] = {
    {0.10, 0.28, 0.36}, {1.0, 0.62, 0.02}, {0.75, 0.10, 0.06}};

static ww_result compile_one(ctx *c, const ww_node *item, int k, ww_fish_species *sp) {
    static const char *const keys[] = {"shape", "count", "length", "color", "speed",
                                       "center", "radius", NULL};
    section s;
    TRY(wwc_open_item(c, item, "objects.fish.species", k, keys, &s));
    int shape = 0;
    const ww_node *word;
    TRY(wwc_lookup(c, &s, "shape", REQUIRED, &word));
    TRY(wwc_get_word(c, &s, "shape", SHAPE_WORDS, &shape));
    sp->shape = (ww_fish_shape)shape;
    double count = 0.0;
    TRY(wwc_get_number(c, &s, "count", &R_SPECIES_COUNT, REQUIRED, &count));
    sp->count = (int)count;
    sp->length = SHAPE_LENGTH[shape];
    for (int a = 0; a < 3; a++) sp->color[a] = SHAPE_COLOR[shape][a];
    TRY(wwc_get_number(c, &s, "length", &R_SPECIES_LENGTH, OPTIONAL, &sp->length));
    TRY(wwc_get_vec(c, &s, "color", 3, &R_SPECIES_COLOR, OPTIONAL, sp->color));
    /* NAN: objects.fish's, filled in once it is read (wwc_fish_species_resolve) */
    sp->speed = sp->radius = NAN;
    sp->center[0] = sp->center[1] = sp->center[2] = NAN;
    TRY(wwc_get_number(c, &s, "speed", &R_SPECIES_SPEED, OPTIONAL, &sp->speed));
    TRY(wwc_get_vec(c, &s, "center", 3, &R_SPECIES_PLACE, OPTIONAL, sp->center));
    return wwc_get_number(c, &s, "radius", &R_SPECIES_RADIUS, OPTIONAL, &sp->radius);
}

ww_result wwc_fish_species(ctx *c, const section *fish, ww_fish_desc *f) {
    const ww_node *list;
    TRY(wwc_get_list(c, fish, "species", WW_MAX_SPECIES, &list));
    f->nspecies = 0;
    if (!list || list->n == 0) return WW_OK;
    const ww_node *count = ww_node_find(fish->map, "count");
    if (count)
        return wwc_fail(c, WW_E_INCONSISTENT, count,
                        "%s: both count and species: expected one (the count is the species' sum)",
                        fish->what);
    int k = 0, total = 0;
    for (const ww_node *item = list->first; item; item = item->next, k++) {
        ww_fish_species *sp = &f->species[k];
        TRY(compile_one(c, item, k, sp));
        if (total + sp->count > WW_MAX_FISH)
            return wwc_fail(c, WW_E_RANGE, ww_node_find(item, "count"),
                            "%s.species: %d fish in all: expected at most %d", fish->what,
                            total + sp->count, WW_MAX_FISH);
        sp->first = total;
        for (int i = 0; i < sp->count; i++) f->species_of[total + i] = (unsigned char)k;
        total += sp->count;
    }
    f->nspecies = k;
    f->count = total;
    return WW_OK;
}

ww_result wwc_fish_species_resolve(ctx *c, const section *fish, ww_fish_desc *f) {
    double floor = c->sc->water_level - c->sc->water_depth;
    for (int k = 0; k < f->nspecies; k++) {
        ww_fish_species *sp = &f->species[k];
        if (isnan(sp->speed)) sp->speed = f->speed;
        if (isnan(sp->radius)) sp->radius = f->radius;
        if (isnan(sp->center[0]))
            for (int a = 0; a < 3; a++) sp->center[a] = f->center[a];
        const ww_node *item = ww_node_at(ww_node_find(fish->map, "species"), k);
        if (sp->speed > f->max_speed)
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(item, "speed"),
                            "%s.species[%d]: speed %g m/s is above max_speed %g m/s", fish->what,
                            k, sp->speed, f->max_speed);
        if (!(sp->center[1] < c->sc->water_level && sp->center[1] > floor))
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(item, "center"),
                            "%s.species[%d]: center y %g m is not in the water (seabed %g m, "
                            "level %g m)",
                            fish->what, k, sp->center[1], floor, c->sc->water_level);
    }
    return WW_OK;
}
