/* step.c - the fixed-step driver: t = start + n dt with an integer n, script events applied on
 * the first step at or after their time, then each system present in the scene.
 */
#include "sim/step.h"

#include "sim/camera.h"
#include "sim/ripples.h"
#include "sim/sky.h"
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
        case WW_EV_RIPPLE:
            ww_ripples_add(sc, st, ev->at[0], ev->at[1], ev->value);
            break;
        }
    }
}

static void update_systems(const ww_scene *sc, ww_state *st) {
    ww_ripples_prune(sc, st);
    apply_events(sc, st);
    ww_sky_update(sc, st);
    ww_camera_update(sc, st);
    ww_waves_phases(sc, st->t, st->wave_phase);
}

void ww_state_reset(const ww_scene *sc, ww_state *st) {
    ww_state_clear(st);
    st->step = 0;
    st->t = sc->start;
    st->event_next = 0;
    st->clock_anchor[0] = sc->time_of_day;
    st->clock_anchor[1] = sc->start;
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
