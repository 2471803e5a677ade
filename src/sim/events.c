/* events.c - the step's event outbox (events.h). */
#include "sim/events.h"

#include <string.h>

static const char *const names[WW_SE_COUNT] = {
    [WW_SE_NONE] = "none",
#define WW_SE_NAME(id, name, magnitude) [WW_SE_##id] = name,
    WW_SIM_EVENTS(WW_SE_NAME)
#undef WW_SE_NAME
};

const char *ww_sim_event_name(ww_sim_event_kind k) {
    return k >= 0 && k < WW_SE_COUNT ? names[k] : "unknown";
}

void ww_emit(const ww_scene *sc, ww_state *st, ww_sim_event_kind kind, int object,
             const double pos[3], double magnitude, double aux) {
    if (!ww_scene_has_objects(sc)) return;
    int n = (int)st->event_count[0];
    if (n >= WW_MAX_STEP_EVENTS) {
        st->events_dropped[0] += 1.0;
        return;
    }
    double *e = st->events + n * WW_SIM_EVENT_STRIDE;
    e[0] = (double)kind;
    e[1] = (double)object;
    e[2] = pos ? pos[0] : 0.0;
    e[3] = pos ? pos[1] : 0.0;
    e[4] = pos ? pos[2] : 0.0;
    e[5] = magnitude;
    e[6] = aux;
    e[7] = 0.0;
    st->event_count[0] = (double)(n + 1);
}

void ww_events_clear(const ww_scene *sc, ww_state *st) {
    if (!ww_scene_has_objects(sc)) return;
    int n = (int)st->event_count[0];
    memset(st->events, 0, (size_t)n * WW_SIM_EVENT_STRIDE * sizeof *st->events);
    st->event_count[0] = 0.0;
}

int ww_events_count(const ww_scene *sc, const ww_state *st) {
    return ww_scene_has_objects(sc) ? (int)st->event_count[0] : 0;
}
