/* prefix.c - long stretches of stepping with a progress line (prefix.h). */
#include "render/prefix.h"

#include <stdio.h>

#include "render/job.h"
#include "sim/step.h"

/* steps between looks at the clock and the stop flag (a lake step is ~10 us) */
#define CHUNK 1024

void ww_steps_progress_begin(ww_steps_progress *p, int on, const char *what, int64_t from, int64_t to) {
    *p = (ww_steps_progress){.on = on && to > from, .what = what, .from = from, .to = to};
    p->t0 = p->last = ww_now_seconds();
}

void ww_steps_progress_show(ww_steps_progress *p, int64_t step, int final) {
    if (!p->on) return;
    double now = ww_now_seconds();
    if (!final && now - p->last < WW_STEPS_PROGRESS_PERIOD_S) return;
    p->last = now;
    double el = now - p->t0, done = (double)(step - p->from), total = (double)(p->to - p->from);
    double rate = el > 0 ? done / el : 0.0;
    long eta = rate > 0 ? (long)((total - done) / rate + 0.5) : 0;
    int n = fprintf(stderr, "\r%s: step %lld/%lld (%.1f%%)  %.0f steps/s  ETA %ld:%02ld:%02ld ",
                    p->what, (long long)(step - p->from), (long long)(p->to - p->from),
                    total > 0 ? 100.0 * done / total : 100.0, rate, eta / 3600, eta / 60 % 60,
                    eta % 60);
    if (n > p->width) p->width = n;
    fflush(stderr);
}

void ww_steps_progress_end(ww_steps_progress *p, int64_t step) {
    if (!p->on) return;
    /* the last count always, so a log of a stretch shorter than the period still holds it */
    ww_steps_progress_show(p, step, 1);
    fprintf(stderr, "\r%*s\r", p->width, "");
    fflush(stderr);
    p->width = 0;
}

ww_result ww_prefix_advance(const ww_scene *sc, ww_state *st, int64_t step, ww_step_hook hook,
                            void *ctx, ww_steps_progress *p, const volatile sig_atomic_t *stop,
                            ww_error *err) {
    while (st->step < step) {
        if (stop && *stop) return WW_OK;
        int64_t end = step - st->step > CHUNK ? st->step + CHUNK : step;
        if (!hook) {
            ww_result r = ww_sim_advance_to(sc, st, end, err);
            if (r) return r;
        }
        while (hook && st->step < end) {
            ww_result r = ww_step(sc, st, err);
            if (r) return r;
            hook(ctx, sc, st);
        }
        if (p) ww_steps_progress_show(p, st->step, 0);
    }
    return WW_OK;
}
