/* desc_fish_species.h - objects.fish.species: fish of several kinds, each its own school
 * (seed 003's "fishes of various species"). Read by compile_fish_species.c; the fish of species
 * k are consecutive (fish first .. first + count - 1); sim/fish.c gives each school its own
 * region, speed and body length, gfx/geometry.c its own mesh, size, colour and pattern.
 *
 *   objects:
 *     fish:
 *       species:
 *         - {shape: slim, count: 8, length: 0.35, color: [0.15, 0.3, 0.45], center: [0, -4, -8]}
 *         - {shape: deep, count: 5, center: [3, -5, -10], radius: 3}
 *         - {shape: long, count: 3, speed: 0.5}
 */
#ifndef WW_DESC_FISH_SPECIES_H
#define WW_DESC_FISH_SPECIES_H

#define WW_MAX_SPECIES 8

/* body plans: each a procedural mesh (gfx/meshgen.c) and a colour pattern (the fragment shader) */
typedef enum ww_fish_shape {
    WW_FISH_SLIM = 0, /* mackerel-like: fusiform, forked tail; dark wavy bars over a silver belly */
    WW_FISH_DEEP,     /* angelfish / butterflyfish-like: a tall disc with high fins; dark bands */
    WW_FISH_LONG,     /* a long slender reddish fish: undulating body, long dorsal fin; pale belly */
    WW_FISH_SHAPES
} ww_fish_shape;

typedef struct ww_fish_species {
    ww_fish_shape shape;
    int count;             /* fish of this species */
    int first;             /* the index of its first fish */
    double length;         /* body length, nose to tail, m */
    double color[3];       /* linear RGB of the body (the pattern darkens and lightens it) */
    double speed;          /* cruising speed, m/s (<= objects.fish.max_speed) */
    double center[3];      /* the middle of its school's region, m */
    double radius;         /* the region's horizontal radius, m */
} ww_fish_species;

#endif
