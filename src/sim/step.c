/* step.c - the fixed-step driver: t = start + n dt with an integer n, script events applied on
 * the first step at or after their time, then each system present in the scene, in seed 000's
 * order: cubes, stones, rod and lure, fish, chest, bubbles, boat (which pushes the cubes); then
 * the sky clock and the camera (path, boat seat, collision). The wave phases are taken first, so
 * every system reads the surface at the step's own time; systems read the camera of the step
 * before (the final one: seat and collision included), and at step 0 the path's first pose.
 */
#include "sim/step.h"

#include "sim/boat.h"
#include "sim/bubbles.h"
#include "sim/camera.h"
#include "sim/chest.h"
#include "sim/collide.h"
#include "sim/cubes.h"
#include "sim/events.h"
#include "sim/fish.h"
#include "sim/ripples.h"
#include "sim/rod.h"
#include "sim/sky.h"
#include "sim/stones.h"
#include "sim/waves.h"

/* apply every event due at or before the current step */
static void apply_events(const ww_scene *sc, ww_state *st) {
    while (st->event_next < sc->nevents && sc->events[st->event_next].step <= st->step) {
        const ww_event *ev = &sc->events[st->event_next++];
        switch (ev->kind) {
        case WW_EV_TIME_OF_DAY:
            st->clock_anchor[0] = ev->value;
            st->clock_anchor[1] = st->t;
            break;
        case WW_EV_RIPPLE: ww_ripples_add(sc, st, ev->at[0], ev->at[1], ev->value); break;
        case WW_EV_THROW: ww_stones_event(sc, st, ev); break;
        case WW_EV_CAST: ww_rod_event(sc, st, ev); break;
        case WW_EV_BOAT:
        case WW_EV_CAMERA_MODE: ww_boat_event(sc, st, ev); break;
        case WW_EV_PRESS: ww_cubes_event(sc, st, ev); break;
        case WW_EV_CHEST: ww_chest_event(sc, st, ev); break;
        }
    }
}

static void update_systems(const ww_scene *sc, ww_state *st) {
    ww_waves_phases(sc, st->t, st->wave_phase);
    ww_events_clear(sc, st);
    ww_ripples_prune(sc, st);
    apply_events(sc, st);
    if (sc->cubes.on) ww_cubes_step(sc, st);
    if (sc->stones.on) ww_stones_step(sc, st);
    if (sc->rod.on) ww_rod_step(sc, st);
    if (sc->fish.on) ww_fish_step(sc, st);
    if (sc->chest.on) ww_chest_step(sc, st);
    if (sc->bubbles.on) ww_bubbles_step(sc, st);
    if (sc->boat.on) ww_boat_step(sc, st);
    ww_sky_update(sc, st);
    ww_camera_update(sc, st);
    if (sc->boat.on) ww_boat_camera(sc, st);
    if (sc->camera_collide) ww_camera_collide(sc, st);
}

/* each system's step-0 state, before the step-0 events and updates */
static void reset_systems(const ww_scene *sc, ww_state *st) {
    ww_waves_phases(sc, st->t, st->wave_phase);
    ww_camera_update(sc, st); /* a throw or cast at step 0 starts from the path's first pose */
    if (sc->cubes.on) ww_cubes_reset(sc, st);
    if (sc->stones.on) ww_stones_reset(sc, st);
    if (sc->rod.on) ww_rod_reset(sc, st);
    if (sc->fish.on) ww_fish_reset(sc, st);
    if (sc->chest.on) ww_chest_reset(sc, st);
    if (sc->bubbles.on) ww_bubbles_reset(sc, st);
    if (sc->boat.on) ww_boat_reset(sc, st);
}

void ww_state_reset(const ww_scene *sc, ww_state *st) {
    ww_state_clear(st);
    st->step = 0;
    st->t = sc->start;
    st->event_next = 0;
    st->clock_anchor[0] = sc->time_of_day;
    st->clock_anchor[1] = sc->start;
    reset_systems(sc, st);
    update_systems(sc, st);
}

ww_result ww_step(const ww_scene *sc, ww_state *st, ww_error *err) {
    st->step++;
    st->t = sc->start + (double)st->step * sc->dt;
    update_systems(sc, st);
    return ww_state_check(sc, st, err);
}

ww_result ww_sim_advance_to(const ww_scene *sc, ww_state *st, int64_t step, ww_error *err) {
    WW_ASSERT(step >= st->step);
    while (st->step < step) {
        ww_result r = ww_step(sc, st, err);
        if (r != WW_OK) return r;
    }
    return WW_OK;
}
