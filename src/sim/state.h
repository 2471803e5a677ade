/* state.h - everything a step changes (the "data" of MuJoCo's model/data pair).
 *
 *   ww_state *st = ww_state_new(sc);     // sim/step.h: one allocation, sized from the scene's
 *                                        // counts, reset to step 0 at t = start
 *   ww_step(sc, st); ...                 // sim/step.h
 *   uint64_t h = ww_state_hash(sc, st);
 *   ww_state_free(st);
 *
 * Each array is declared once in WW_STATE_FIELDS (MuJoCo's mjxmacro.h): the table drives sizing,
 * reset, hashing and trace output. X(type, name, count, system, comment), `system` the name
 * of the system that owns it (scene.h's WW_SYSTEM_LIST; "events" for the outbox). `count` may use `sc->...`.
 * `type` is double for physics and int32_t for modes, flags, indices and counters (the trace
 * prints both as the same numbers; the NaN guard skips the integers).
 * The arrays live in the same block as the header; the field pointers point into it, so
 * ww_state_copy() (not memcpy) makes a snapshot. The hash covers step and array bytes only.
 */
#ifndef WW_STATE_H
#define WW_STATE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene/scene.h"

/* values per warm start of a surface query (ww_water_at_warm, sim/water.h): the fields of the
 * systems that keep one per sample point are counted in these */
#define WW_WARM_STRIDE 4

#include "sim/fields_boat.h"
#include "sim/fields_cubes.h"
#include "sim/fields_fishing.h"
#include "sim/fields_floaters.h"
#include "sim/fields_reef.h"
#include "sim/fields_stones.h"

#define WW_MAX_STEP_EVENTS 64  /* the outbox of sim/events.h */
#define WW_SIM_EVENT_STRIDE 8

#define WW_STATE_FIELDS(X)                                                                        \
    X(double, time_of_day, 1, "clock", "clock, hours 0..24 (1)")                                    \
    X(double, clock_anchor, 2, "clock", "clock was set to [0] hours at simulated time [1] s (2)")   \
    X(double, sun_dir, 3, "clock", "unit vector toward the sun, world (3)")                         \
    X(double, sun_color, 3, "clock", "sun radiance at the ground, linear RGB (3)")                  \
    X(double, sky_zenith, 3, "clock", "sky colour straight up, linear RGB (3)")                     \
    X(double, sky_horizon, 3, "clock", "sky colour at the horizon, linear RGB (3)")                 \
    X(double, ambient, 3, "clock", "sky ambient light, linear RGB (3)")                             \
    X(double, cam_pos, 3, "camera", "camera position, m (3)")                                       \
    X(double, cam_fwd, 3, "camera", "camera forward, unit (3)")                                     \
    X(double, cam_fov, 1, "camera", "camera vertical field of view, rad (1)")                       \
    X(double, wave_phase, sc->nwaves, "waves", "per-wave phase at the world origin, wrapped to [0, 2pi), rad (nwaves)") \
    X(double, ripple, sc->ripples_on ? 4 * sc->ripples.max : 0, "ripples", "ripple pool: x, z, t0, A0 per entry; A0 = 0 is free (4 max)") \
    X(int32_t, ripple_slots, sc->ripples_on ? 1 : 0, "ripples", "slots of the pool in use: one past its last live entry, so a query reads no more (1)") \
    X(int32_t, event_count, ww_scene_has_objects(sc) ? 1 : 0, "events", "events in the step's outbox (1)") \
    X(int32_t, events_dropped, ww_scene_has_objects(sc) ? 1 : 0, "events", "events a full outbox could not hold, since step 0 (1)") \
    X(double, events, ww_scene_has_objects(sc) ? WW_MAX_STEP_EVENTS * WW_SIM_EVENT_STRIDE : 0, "events", "the step's outbox, sim/events.h") \
    WW_FIELDS_CUBES(X)                                                                           \
    WW_FIELDS_STONES(X)                                                                          \
    WW_FIELDS_FISHING(X)                                                                         \
    WW_FIELDS_REEF(X)                                                                            \
    WW_FIELDS_BOAT(X)                                                                            \
    WW_FIELDS_FLOATERS(X)

#define WW_STATE_COUNT_FIELD(type, name, count, sys, comment) +1
enum { WW_STATE_NFIELDS = 0 WW_STATE_FIELDS(WW_STATE_COUNT_FIELD) };
#undef WW_STATE_COUNT_FIELD

typedef struct ww_state {
    int64_t step;          /* steps taken since t = start */
    double t;              /* start + step dt, s */
    int event_next;        /* index of the next script event to apply */
    int nruns;             /* of runs, below */
    size_t bytes;          /* size of the whole block */
#define WW_STATE_DECL(type, name, count, sys, comment) type *name;
    WW_STATE_FIELDS(WW_STATE_DECL)
#undef WW_STATE_DECL
    /* the NaN guard's runs of adjacent double fields (padding included), as offsets and counts
     * in doubles from the header: found once when the fields are bound, so a step's check walks
     * a few runs instead of every field. The outbox, read only to its live events, is in none */
    struct {
        uint32_t start, count;
    } runs[WW_STATE_NFIELDS];
    /* the arrays follow in the same allocation */
} ww_state;

/* the block for this scene's counts, every array zero (not a step-0 state: ww_state_new in
 * sim/step.h resets it); NULL when out of memory */
ww_state *ww_state_alloc(const ww_scene *sc);
void ww_state_free(ww_state *st);
/* zero every array (used by reset) */
void ww_state_clear(ww_state *st);
/* dst must come from ww_state_new() on the same scene */
void ww_state_copy(ww_state *dst, const ww_state *src);
uint64_t ww_state_hash(const ww_scene *sc, const ww_state *st);
/* one JSON object (no newline): t, step, camera, sun and every field */
void ww_state_write_json(const ww_scene *sc, const ww_state *st, FILE *to);
/* where the arrays start in the block (a checkpoint stores the bytes from here to st->bytes:
 * the header before them holds pointers, which are the process's own and are bound again on
 * load by ww_state_alloc) */
size_t ww_state_arrays_offset(void);
/* 0 when every value is finite; otherwise fills err naming the field, index and step */
ww_result ww_state_check(const ww_scene *sc, const ww_state *st, ww_error *err);

#endif
