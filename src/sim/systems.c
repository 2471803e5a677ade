/* systems.c - the table of the simulation's systems (model in systems.h). */
#include "sim/systems.h"

#include "sim/boat.h"
#include "sim/bubbles.h"
#include "sim/camera.h"
#include "sim/chest.h"
#include "sim/collide.h"
#include "sim/cubes.h"
#include "sim/events.h"
#include "sim/fish.h"
#include "sim/floaters.h"
#include "sim/ripples.h"
#include "sim/rod.h"
#include "sim/sky.h"
#include "sim/stones.h"
#include "sim/waves.h"

#define TAKES(k) (1u << (k))
#define EMITS(k) (1u << (k))

static void waves_begin(const ww_scene *sc, ww_state *st) {
    ww_waves_phases(sc, st->t, st->wave_phase);
}

static void clock_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    (void)sc;
    st->clock_anchor[0] = ev->value;
    st->clock_anchor[1] = st->t;
}

static void ripples_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    ww_ripples_add(sc, st, ev->at[0], ev->at[1], ev->value);
}

/* in the order the rows run (systems.h): the world's clock and camera first, so that the camera
 * resets before the objects; their view hooks then follow the objects' steps */
static const ww_system_row ROWS[] = {
    {.id = WW_SYS_WAVES, .always = 1, .begin = waves_begin},
    {.id = WW_SYS_RIPPLES, .always = 1, .begin = ww_ripples_prune, .event = ripples_event,
     .takes = TAKES(WW_EV_RIPPLE)},
    {.id = WW_SYS_CLOCK, .always = 1, .view = ww_sky_update, .event = clock_event,
     .takes = TAKES(WW_EV_TIME_OF_DAY)},
    {.id = WW_SYS_CAMERA, .always = 1, .reset = ww_camera_update, .view = ww_camera_update},
    {.id = WW_SYS_CUBES, .reset = ww_cubes_reset, .step = ww_cubes_step, .event = ww_cubes_event,
     .takes = TAKES(WW_EV_PRESS), .emits = EMITS(WW_SE_CUBE_PRESS) | EMITS(WW_SE_CUBE_RELEASE)},
    {.id = WW_SYS_FLOATERS, .reset = ww_floaters_reset, .step = ww_floaters_step},
    {.id = WW_SYS_STONES, .reset = ww_stones_reset, .step = ww_stones_step,
     .event = ww_stones_event, .takes = TAKES(WW_EV_THROW),
     .emits = EMITS(WW_SE_STONE_THROW) | EMITS(WW_SE_STONE_SKIP) | EMITS(WW_SE_STONE_SINK) |
              EMITS(WW_SE_STONE_THUD) | EMITS(WW_SE_SPLASH_FULL) | EMITS(WW_SE_SPLASH_TINY)},
    {.id = WW_SYS_ROD, .reset = ww_rod_reset, .step = ww_rod_step, .event = ww_rod_event,
     .takes = TAKES(WW_EV_CAST),
     .emits = EMITS(WW_SE_ROD_CAST) | EMITS(WW_SE_LURE_LAND) | EMITS(WW_SE_REEL)},
    {.id = WW_SYS_FISH, .reset = ww_fish_reset, .step = ww_fish_step,
     .emits = EMITS(WW_SE_BITE) | EMITS(WW_SE_CATCH) | EMITS(WW_SE_FISH_ESCAPE)},
    {.id = WW_SYS_CHEST, .reset = ww_chest_reset, .step = ww_chest_step, .event = ww_chest_event,
     .takes = TAKES(WW_EV_CHEST),
     .emits = EMITS(WW_SE_CHEST_SPAWN) | EMITS(WW_SE_CHEST_EXPIRE) | EMITS(WW_SE_CHEST_COLLECT)},
    {.id = WW_SYS_BUBBLES, .reset = ww_bubbles_reset, .step = ww_bubbles_step},
    {.id = WW_SYS_BOAT, .reset = ww_boat_reset, .step = ww_boat_step, .view = ww_boat_camera,
     .event = ww_boat_event, .takes = TAKES(WW_EV_BOAT) | TAKES(WW_EV_CAMERA_MODE),
     .emits = EMITS(WW_SE_BOAT_START) | EMITS(WW_SE_BOAT_STOP)},
    {.id = WW_SYS_COLLIDE, .view = ww_camera_collide, .emits = EMITS(WW_SE_CAMERA_BLOCKED)},
};
#define NROWS ((int)(sizeof ROWS / sizeof ROWS[0]))

const ww_system_row *ww_systems(int *n) {
    *n = NROWS;
    return ROWS;
}

const ww_system_row *ww_system_taking(ww_event_kind k) {
    for (int i = 0; i < NROWS; i++)
        if (ROWS[i].takes & TAKES(k)) return &ROWS[i];
    return NULL;
}
