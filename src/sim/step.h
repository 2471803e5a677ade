/* step.h - advancing the world by one fixed step: ww_step(const ww_scene*, ww_state*).
 *
 *   ww_state *st = ww_state_new(sc);            // reset: step 0, t = start, step-0 events applied
 *   for (...) if (ww_step(sc, st, &err)) ...    // WW_E_NAN names system, index and step
 *   ww_sim_advance_to(sc, st, n, &err);          // step until st->step == n (n >= st->step)
 *
 * Order inside a step: time, script events due at this step, sky clock, camera, waves; then the
 * NaN guard over every state field. No allocation, no I/O, no wall clock.
 */
#ifndef WW_STEP_H
#define WW_STEP_H

#include "core/error.h"
#include "scene/scene.h"
#include "sim/state.h"

/* a state for the scene at step 0 (ww_state_alloc, then ww_state_reset); NULL when out of
 * memory. Free it with ww_state_free. */
ww_state *ww_state_new(const ww_scene *sc);
/* back to step 0 at t = start: every system's reset, then the step-0 events and update */
void ww_state_reset(const ww_scene *sc, ww_state *st);
ww_result ww_step(const ww_scene *sc, ww_state *st, ww_error *err);
ww_result ww_sim_advance_to(const ww_scene *sc, ww_state *st, int64_t step, ww_error *err);

/* calls around each part of a step, for a breakdown of its time by system (`bench sim`; the
 * role of MuJoCo's per-stage timers): enter(ctx, id) before, leave(ctx, id) after each system's
 * hook or script event (id: its ww_system) and the step's own work (id WW_SYS_COUNT: clearing
 * the outbox, the NaN guard). They see the step run, never change it */
typedef struct ww_step_probe {
    void (*enter)(void *ctx, int id);
    void (*leave)(void *ctx, int id);
    void *ctx;
} ww_step_probe;

/* ww_step with probe's calls around its parts: the same state to the bit */
ww_result ww_step_probed(const ww_scene *sc, ww_state *st, const ww_step_probe *probe,
                         ww_error *err);

#endif
