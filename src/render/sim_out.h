/* sim_out.h - what the simulation tools read out of a state beyond the trace: the step's events as
 * JSON lines (`simulate --events`) and a state field by name (bench sim's metrics).
 *
 *   ww_step(sc, st, &err);
 *   ww_sim_events_write(sc, st, file);          // one line per event in the outbox
 *   long long n; const double *y = ww_state_field(sc, st, "cube_pos", &n);   // NULL: no such
 *
 * Nothing here allocates or writes the state.
 */
#ifndef WW_SIM_OUT_H
#define WW_SIM_OUT_H

#include <stdio.h>

#include "sim/state.h"

/* one JSON object per line for each event in the step's outbox:
 *   {"step":S,"t":T,"kind":"stone_skip","object":I,"pos":[x,y,z],"magnitude":M,"aux":A}
 * numbers as %.17g (non-finite: null); returns the number of lines written */
int ww_sim_events_write(const ww_scene *sc, const ww_state *st, FILE *to);

/* the array of the state field `name` (WW_STATE_FIELDS) and its length in *count; NULL when no
 * field has that name or it is an integer column (a mode, flag or counter: read it from the
 * state). A field of a system the scene lacks has *count 0. */
const double *ww_state_field(const ww_scene *sc, const ww_state *st, const char *name,
                             long long *count);


#endif
