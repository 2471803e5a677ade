/* sim_out.c - the step's event outbox as JSON lines, state fields looked up by name and the
 * system owning each field, all driven by the X-macro tables of sim/state.h and sim/fields_*.h
 * (so a system's new fields are found without any change here).
 */
#include "render/sim_out.h"

#include <math.h>
#include <string.h>

#include "core/numfmt.h"
#include "sim/events.h"

int ww_sim_events_write(const ww_scene *sc, const ww_state *st, FILE *to) {
    int n = ww_events_count(sc, st);
    for (int i = 0; i < n; i++) {
        const double *e = st->events + i * WW_SIM_EVENT_STRIDE;
        fprintf(to, "{\"step\":%lld,\"t\":", (long long)st->step);
        ww_num_json(to, st->t);
        fprintf(to, ",\"kind\":\"%s\",\"object\":%d,\"pos\":[",
                ww_sim_event_name((ww_sim_event_kind)(int)e[0]), (int)e[1]);
        ww_num_json(to, e[2]);
        fputc(',', to);
        ww_num_json(to, e[3]);
        fputc(',', to);
        ww_num_json(to, e[4]);
        fputs("],\"magnitude\":", to);
        ww_num_json(to, e[5]);
        fputs(",\"aux\":", to);
        ww_num_json(to, e[6]);
        fputs("}\n", to);
    }
    return n;
}

const double *ww_state_field(const ww_scene *sc, const ww_state *st, const char *name,
                             long long *count) {
#define WW_FIELD_BY_NAME(type, fname, n, sys, comment)                                                 \
    if (strcmp(name, #fname) == 0) {                                                              \
        const double *p_ = _Generic(st->fname, double *: (const double *)(const void *)st->fname, \
                                    default: NULL);                                               \
        *count = p_ ? (long long)(n) : 0;                                                         \
        return p_;                                                                                \
    }
    WW_STATE_FIELDS(WW_FIELD_BY_NAME)
#undef WW_FIELD_BY_NAME
    *count = 0;
    return NULL;
}
