/* compile_impl.h - the loader's shared layer (private to src/scene/compile*.c): the context, the
 * section being read, the one-line range rules and the getters every section's compile function
 * is written with. compile.c holds the getters and the world's sections (time, render, sky, fog,
 * water, camera, script); each system of the scripted world reads its own `objects.*` section and
 * script actions in its own compile_<system>.c.
 *
 *   static const rule R_DENSITY = OPEN_LO(0, 1e5, "kg/m^3");
 *   section s;
 *   TRY(wwc_open_section(c, objects, "cubes", keys, &s));
 *   TRY(wwc_get_number(c, &s, "density", &R_DENSITY, OPTIONAL, &desc->density));
 */
#ifndef WW_COMPILE_IMPL_H
#define WW_COMPILE_IMPL_H

#include <float.h>

#include "scene/scene.h"
#include "scene/tree.h"

#define TRY(x)                                                                                  \
    do {                                                                                        \
        ww_result r_ = (x);                                                                     \
        if (r_ != WW_OK) return r_;                                                             \
    } while (0)

typedef struct rule {
    double lo, hi;
    unsigned char lo_open, hi_open; /* 1: the end itself is excluded */
    unsigned char integer;          /* 1: whole numbers only */
    const char *unit;               /* for messages */
} rule;

#define CLOSED(lo, hi, unit) {lo, hi, 0, 0, 0, unit}  /* [lo, hi] */
#define OPEN_LO(lo, hi, unit) {lo, hi, 1, 0, 0, unit} /* (lo, hi] */
#define WHOLE(lo, hi, unit) {lo, hi, 0, 0, 1, unit}   /* whole numbers in [lo, hi] */
#define FINITE(unit) CLOSED(-DBL_MAX, DBL_MAX, unit)  /* any finite number */

typedef struct ctx {
    ww_scene *sc;
    const char *file;     /* for errors with no node to point at */
    ww_error *err;
} ctx;

/* a mapping being read, and its dotted name for messages */
typedef struct section {
    const ww_node *map;   /* NULL when absent: every value keeps its default */
    char what[96];        /* "render.tonemap", "camera.path[2]"; "" at the top level */
} section;

typedef enum need { OPTIONAL = 0, REQUIRED } need;

/* an error at a node (NULL: the file), formatted; returns code */
ww_result wwc_fail(ctx *c, ww_result code, const ww_node *at, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* "FILE:LINE:COL: warning: ..." appended to the scene's warnings (the CLI prints them) */
void wwc_warn(ctx *c, const ww_node *at, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

const char *wwc_nearest(const char *typed, const char *const *words);
const char *wwc_join_words(const char *const *words, char *buf, size_t size);
const char *wwc_where(const section *s);
const char *wwc_path_of(const section *s, const char *key, char *buf, size_t size);

/* every key of s is one of keys (NULL-terminated), else an unknown-key error with a suggestion */
ww_result wwc_check_keys(ctx *c, const section *s, const char *const *keys);
/* parent.key as a mapping with those keys (out->map NULL when absent) */
ww_result wwc_open_section(ctx *c, const section *parent, const char *key,
                           const char *const *keys, section *out);
/* item i of the list list_name as a mapping with those keys */
ww_result wwc_open_item(ctx *c, const ww_node *item, const char *list_name, int i,
                        const char *const *keys, section *out);
ww_result wwc_lookup(ctx *c, const section *s, const char *key, need nd, const ww_node **out);
ww_result wwc_check_number(ctx *c, const ww_node *n, const char *name, const rule *r,
                           double *out);
/* getters: *out keeps its value (the default) when the key is absent and nd is OPTIONAL */
ww_result wwc_get_number(ctx *c, const section *s, const char *key, const rule *r, need nd,
                         double *out);
/* degrees in the file, radians in *out; r is checked in degrees */
ww_result wwc_get_angle(ctx *c, const section *s, const char *key, const rule *r, need nd,
                        double *out);
ww_result wwc_get_vec(ctx *c, const section *s, const char *key, int len, const rule *r,
                      need nd, double *out);
/* a heading: degrees, or a non-zero [x, z] vector; radians in *out */
ww_result wwc_get_heading(ctx *c, const section *s, const char *key, need nd, double *out);
/* [lo, hi] with lo < hi (or <= with allow_equal) */
ww_result wwc_get_range(ctx *c, const section *s, const char *key, const rule *r,
                        int allow_equal, double out[2]);
/* one of words (NULL-terminated); *out its index */
ww_result wwc_get_word(ctx *c, const section *s, const char *key, const char *const *words,
                       int *out);
ww_result wwc_get_list(ctx *c, const section *s, const char *key, int max,
                       const ww_node **out);

/* a file name written at node n, resolved against the folder of the file n was written in
 * (absolute names stay), checked to be a readable regular file: an error at n otherwise */
ww_result wwc_resolve_path(ctx *c, const ww_node *n, char *out, size_t size);

/* ---- how the scene is drawn (compile_render.c) ------------------------------------------- */

ww_result wwc_render(ctx *c, const section *top);        /* render.* */
ww_result wwc_sky(ctx *c, const section *top);           /* sky.* */
ww_result wwc_fog(ctx *c, const section *top);           /* fog.above, fog.below */
ww_result wwc_water_look(ctx *c, const section *water);  /* water.look */
ww_result wwc_lights(ctx *c, const section *top);        /* lights */
/* each light's parent names the boat or a model (once objects are read) */
ww_result wwc_check_lights(ctx *c, const ww_node *root);

/* ---- what comes out besides the frames ------------------------------------------------- */

ww_result wwc_audio(ctx *c, const section *top);         /* audio.*: compile_audio.c */
ww_result wwc_golden(ctx *c, const section *top);        /* golden.*: compile_golden.c */

/* ---- the scripted world's sections (compile_<system>.c) ---------------------------------- */

/* objects.<key> of each system; `objects` may have map NULL (no objects section) */
ww_result wwc_cubes(ctx *c, const section *objects);     /* compile_cubes.c */
ww_result wwc_boat(ctx *c, const section *objects);      /* compile_boat.c */
ww_result wwc_stones(ctx *c, const section *objects);    /* compile_stones.c */
ww_result wwc_fishing(ctx *c, const section *objects);   /* compile_fishing.c: rod and fish */
/* objects.fish.species (compile_fish_species.c): read with the count, then their defaults from
 * objects.fish and cross-checks once the whole fish section is read */
ww_result wwc_fish_species(ctx *c, const section *fish, ww_fish_desc *f);
ww_result wwc_fish_species_resolve(ctx *c, const section *fish, ww_fish_desc *f);
ww_result wwc_reef(ctx *c, const section *objects);      /* compile_reef.c: chest, bubbles, models */
ww_result wwc_floaters(ctx *c, const section *objects);  /* compile_floaters.c: models[].float */

/* script actions: the event's mapping s (t already read) and the action's value node; each fills
 * ev->v / index / flags as its system's header documents. */
ww_result wwc_action_throw(ctx *c, const section *s, const ww_node *value, ww_event *ev);
ww_result wwc_action_cast(ctx *c, const section *s, const ww_node *value, ww_event *ev);
ww_result wwc_action_boat(ctx *c, const section *s, const ww_node *value, ww_event *ev);
ww_result wwc_action_camera(ctx *c, const section *s, const ww_node *value, ww_event *ev);
ww_result wwc_action_press(ctx *c, const section *s, const ww_node *value, ww_event *ev);
ww_result wwc_action_chest(ctx *c, const section *s, const ww_node *value, ww_event *ev);

/* the file an event was written in: the scene, or the --script file */
const char *wwc_event_file(const ctx *c, const ww_event *ev);

/* cross-checks once every section is read (e.g. press.cube < number of cubes) */
ww_result wwc_check_world(ctx *c);                        /* compile_objects.c */

#endif
