/* bench.h - speed and memory figures (measured and printed, never asserted).
 *
 *   ww_bench_render(&opts, stdout, &err);   // per backend, scene and size: ms per frame split
 *                                           // into simulate / render / read back / encode, the
 *                                           // backend's fill floor, peak RSS, state size
 *   ww_bench_sim(&opts, stdout, &err);      // steps per second of the simulation alone
 */
#ifndef WW_BENCH_H
#define WW_BENCH_H

#include <stdio.h>

#include "core/error.h"

typedef struct ww_bench_opts {
    int frames;             /* frames per configuration (0: 20) */
    int json;               /* one JSON object per line instead of a table */
    const char *scenes[4];  /* NULL-terminated; default minimal + demo */
} ww_bench_opts;

ww_result ww_bench_render(const ww_bench_opts *o, FILE *to, ww_error *err);
ww_result ww_bench_sim(const ww_bench_opts *o, FILE *to, ww_error *err);

#endif
