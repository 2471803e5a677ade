/* systems.h - the simulation's systems as one table: each row names a system (scene.h's
 * ww_system) and gives what it does when the state is reset and in each stage of a step, which
 * script events it takes and which simulation events it emits. ww_step (sim/step.c) runs the
 * rows of the systems the scene has (sc->system_on, decided once when the scene was compiled)
 * in the table's order, stage by stage:
 *
 *   begin   first in every step and at reset, before anything reads the world (wave phases at
 *           the step's own time, expired ripples out)
 *   events  the script events due by this step, each to the row that takes its kind
 *   step    the objects, in seed 000's order: cubes, stones, rod and lure, fish, chest, bubbles,
 *           boat (which pushes the cubes)
 *   view    once every object has moved: the sky clock, the camera path, the boat's seat, then
 *           camera collision
 *
 * Reset runs the rows' reset hooks in table order, then a whole step-0 update. The camera's
 * reset takes the path's first pose before the objects reset, so that a throw or a cast at step 0
 * starts from it. Rows marked `always` run in every scene: their work is empty when the scene
 * has nothing for them (no wave components, no ripples).
 *
 * Adding a system: its sim file, its scene section (desc + compile), its line in scene.h's
 * WW_SYSTEM_LIST (name and when a scene has it), its state fields (a fields header and one line
 * in state.h's table), and one row here.
 */
#ifndef WW_SYSTEMS_H
#define WW_SYSTEMS_H

#include <stdint.h>

#include "scene/scene.h"
#include "sim/state.h"

typedef void (*ww_system_fn)(const ww_scene *sc, ww_state *st);
typedef void (*ww_system_event_fn)(const ww_scene *sc, ww_state *st, const ww_event *ev);

typedef struct ww_system_row {
    ww_system id;
    int always;              /* runs whatever sc->system_on says (see above) */
    ww_system_fn begin;      /* stage hooks; NULL: nothing in that stage */
    ww_system_fn reset;
    ww_system_fn step;
    ww_system_fn view;
    ww_system_event_fn event;
    uint32_t takes;          /* bit 1 << ww_event_kind per script event kind it takes */
    uint32_t emits;          /* bit 1 << ww_sim_event_kind per simulation event it emits */
} ww_system_row;

/* the table, in the order its rows run; *n rows */
const ww_system_row *ww_systems(int *n);
/* the row that takes script event kind k, or NULL */
const ww_system_row *ww_system_taking(ww_event_kind k);
/* whether the scene runs row r */
static inline int ww_system_runs(const ww_scene *sc, const ww_system_row *r) {
    return r->always || sc->system_on[r->id];
}

#endif
