/* bench.h - speed and memory figures (measured and printed, never asserted).
 *
 *   ww_bench_render(&opts, stdout, &err);   // per backend, scene and size: ms per frame split
 *                                           // into simulate / render / read back / encode, the
 *                                           // backend's fill floor, peak RSS, state size
 *   ww_bench_sim(&opts, stdout, &err);      // the simulation alone (bench_sim.c): steps per
 *                                           // second and simulated s per wall s per scene; the
 *                                           // error of named metrics against dt next to the
 *                                           // speed (a table and DIR/sim.png); the simulation's
 *                                           // share of a frame of scenes/demo.yaml
 */
#ifndef WW_BENCH_H
#define WW_BENCH_H

#include <stdio.h>

#include "core/error.h"
#include "tools/job.h"

typedef struct ww_bench_opts {
    int frames;             /* frames per configuration (0: 20) */
    int json;               /* one JSON object per line instead of a table */
    const char *scenes[4];  /* NULL-terminated; default minimal + demo (sim: see bench_sim.c) */
    const char *out_dir;    /* sim: folder for sim.png (default out/bench) */
    int tiny;               /* sim: a seconds-long run for the tests (no render share) */
} ww_bench_opts;

ww_result ww_bench_render(const ww_bench_opts *o, FILE *to, ww_error *err);
ww_result ww_bench_sim(const ww_bench_opts *o, FILE *to, ww_error *err);
/* render `frames` frames of one scene at width x height in a child process (auto backend, no
 * files kept); its job stats, or WW_E_BACKEND with the child's message */
ww_result ww_bench_render_once(const char *scene, int width, int height, int frames,
                               ww_job_stats *stats, ww_error *err);

#endif
