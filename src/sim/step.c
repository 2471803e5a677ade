/* step.c - the fixed-step driver: t = start + n dt with an integer n; each step runs the table
 * of systems (sim/systems.h) stage by stage: begin (wave phases, so every system reads the
 * surface at the step's own time), the script events due, the objects, then the view (sky
 * clock, camera path, boat seat, collision). Systems read the camera of the step before (the
 * final one: seat and collision included), and at step 0 the path's first pose.
 */
#include "sim/step.h"

#include "sim/events.h"
#include "sim/systems.h"

/* the probe's calls around a part of the step (none without a probe) */
#define PROBED(probe, id, work)                                                                   \
    do {                                                                                          \
        if (probe) probe->enter(probe->ctx, (int)(id));                                           \
        work;                                                                                     \
        if (probe) probe->leave(probe->ctx, (int)(id));                                           \
    } while (0)

/* the stage's hook of every row the scene runs, in table order */
#define RUN_STAGE(hook, probe)                                                                    \
    do {                                                                                          \
        for (int i_ = 0; i_ < nrows; i_++)                                                        \
            if (rows[i_].hook && ww_system_runs(sc, &rows[i_]))                                   \
                PROBED(probe, rows[i_].id, rows[i_].hook(sc, st));                                \
    } while (0)

/* apply every event due at or before the current step, each to the system that takes it (the
 * compiler turns on the system a script event needs) */
static void apply_events(const ww_scene *sc, ww_state *st, const ww_step_probe *probe) {
    while (st->event_next < sc->nevents && sc->events[st->event_next].step <= st->step) {
        const ww_event *ev = &sc->events[st->event_next++];
        const ww_system_row *r = ww_system_taking(ev->kind);
        WW_ASSERT(r && r->event);
        PROBED(probe, r->id, r->event(sc, st, ev));
    }
}

static void update_systems(const ww_scene *sc, ww_state *st, const ww_step_probe *probe) {
    int nrows;
    const ww_system_row *rows = ww_systems(&nrows);
    PROBED(probe, WW_SYS_COUNT, ww_events_clear(sc, st));
    RUN_STAGE(begin, probe);
    apply_events(sc, st, probe);
    RUN_STAGE(step, probe);
    RUN_STAGE(view, probe);
}

/* each system's step-0 state, before the step-0 events and updates */
static void reset_systems(const ww_scene *sc, ww_state *st) {
    int nrows;
    const ww_system_row *rows = ww_systems(&nrows);
    const ww_step_probe *none = NULL;
    RUN_STAGE(begin, none);
    RUN_STAGE(reset, none);
}

ww_state *ww_state_new(const ww_scene *sc) {
    ww_state *st = ww_state_alloc(sc);
    if (st) ww_state_reset(sc, st);
    return st;
}

void ww_state_reset(const ww_scene *sc, ww_state *st) {
    ww_state_clear(st);
    st->step = 0;
    st->t = sc->start;
    st->event_next = 0;
    st->clock_anchor[0] = sc->time_of_day;
    st->clock_anchor[1] = sc->start;
    reset_systems(sc, st);
    update_systems(sc, st, NULL);
}

ww_result ww_step_probed(const ww_scene *sc, ww_state *st, const ww_step_probe *probe,
                         ww_error *err) {
    st->step++;
    st->t = sc->start + (double)st->step * sc->dt;
    update_systems(sc, st, probe);
    ww_result r;
    PROBED(probe, WW_SYS_COUNT, r = ww_state_check(sc, st, err));
    return r;
}

ww_result ww_step(const ww_scene *sc, ww_state *st, ww_error *err) {
    return ww_step_probed(sc, st, NULL, err);
}

ww_result ww_sim_advance_to(const ww_scene *sc, ww_state *st, int64_t step, ww_error *err) {
    WW_ASSERT(step >= st->step);
    while (st->step < step) {
        ww_result r = ww_step(sc, st, err);
        if (r != WW_OK) return r;
    }
    return WW_OK;
}
