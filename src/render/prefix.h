/* prefix.h - stepping a long stretch of simulation with a progress line on stderr ("simulating
 * the prefix: steps done / total, steps per second, ETA"), for `render` (the steps before a
 * slice's first frame) and `simulate` (the whole run).
 *
 *   ww_steps_progress p;
 *   ww_steps_progress_begin(&p, on, "simulating the prefix", from_step, to_step);
 *   ww_prefix_advance(sc, st, to_step, hook, ctx, &p, &stop_flag, &err);  // or steps of your own
 *   ww_steps_progress_show(&p, st->step, 0);                              // and this
 *   ww_steps_progress_end(&p, st->step);          // the last count, then clears the line
 *
 * The line is rewritten at most every WW_STEPS_PROGRESS_PERIOD_S, like the frame progress of a
 * render (render/job.c), and only when `on` (stderr a terminal, or --progress; never --quiet).
 */
#ifndef WW_PREFIX_H
#define WW_PREFIX_H

#include <signal.h>
#include <stdint.h>

#include "core/error.h"
#include "scene/scene.h"
#include "sim/state.h"

#define WW_STEPS_PROGRESS_PERIOD_S 0.25

typedef struct ww_steps_progress {
    int on;
    const char *what;
    int64_t from, to;          /* steps: the stretch shown */
    double t0, last;           /* wall clock, s */
    int width;                 /* characters of the last line, to clear it */
} ww_steps_progress;

void ww_steps_progress_begin(ww_steps_progress *p, int on, const char *what, int64_t from, int64_t to);
/* the line for st->step == step (final: whatever the time since the last) */
void ww_steps_progress_show(ww_steps_progress *p, int64_t step, int final);
/* the line for `step` whatever the time (a stretch shorter than the period still shows its
 * count in a log), then cleared */
void ww_steps_progress_end(ww_steps_progress *p, int64_t step);

/* called after each step (e.g. the sound track hearing it) */
typedef void (*ww_step_hook)(void *ctx, const ww_scene *sc, const ww_state *st);

/* step st to `step`, the hook after each step (NULL: none), the progress line as it goes (p may
 * be NULL); stops early, returning WW_OK with st->step < step, once *stop is nonzero (a signal
 * handler's flag; NULL: never) */
ww_result ww_prefix_advance(const ww_scene *sc, ww_state *st, int64_t step, ww_step_hook hook,
                            void *ctx, ww_steps_progress *p, const volatile sig_atomic_t *stop,
                            ww_error *err);

#endif
