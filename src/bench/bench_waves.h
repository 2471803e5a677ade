/* bench_waves.h - `waterworld bench waves`: the wave field's speed against its error (printed,
 * never asserted), in three parts and one figure:
 *   (a) CPU evaluations per second per family and component count, double and float batches,
 *       the float error against double, and the cost of the libm sincos calls the sum needs;
 *   (b) exact height queries (sim/water.h): iterations against residual and time per query,
 *       for seas of fold margin 0.5, 0.2 and 0.05;
 *   (c) GPU ms per frame at 1280x720 against component count, with and without the distance
 *       fade (WW_WATER_FADE=0), each configuration in a child process as `bench render` does;
 *       skipped with a note when no GL backend opens.
 * The figure (DIR/waves.png): GPU ms and CPU ns per point against component count.
 *
 *   ww_bench_waves_opts o = {.json = 0, .out_dir = "out/bench"};
 *   ww_bench_waves(&o, stdout, &err);
 */
#ifndef WW_BENCH_WAVES_H
#define WW_BENCH_WAVES_H

#include <stdio.h>

#include "core/error.h"

typedef struct ww_bench_waves_opts {
    int json;             /* one JSON object per line instead of the tables */
    const char *out_dir;  /* folder for waves.png; NULL: out/bench */
    int tiny;             /* a configuration that runs in about a second (tests) */
} ww_bench_waves_opts;

ww_result ww_bench_waves(const ww_bench_waves_opts *o, FILE *to, ww_error *err);

#endif
