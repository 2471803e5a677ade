/* bench.h - speed and memory figures (measured and printed, never asserted).
 *
 *   ww_bench_render(&opts, stdout, &err);   // per backend, scene and size: ms per frame split
 *                                           // into simulate / render / read back / encode, the
 *                                           // backend's fill floor, peak RSS, state size
 *   ww_bench_quality(&qopts, stdout, &err); // each render quality knob against ms per frame
 *                                           // and the error of the final frame against a
 *                                           // reference with every knob at its best (a table
 *                                           // and DIR/quality.png; bench_quality.c)
 *   ww_bench_sim(&opts, stdout, &err);      // the simulation alone (bench_sim.c): steps per
 *                                           // second and simulated s per wall s per scene; the
 *                                           // error of named metrics against dt next to the
 *                                           // speed (a table and DIR/sim.png); the simulation's
 *                                           // share of a frame of scenes/demo.yaml
 *   ww_bench_compare(&copts, stdout, &err); // ms to compare a 1280x720 PNG pair, ours next to
 *                                           // ImageMagick's compare (bench_compare.c)
 */
#ifndef WW_BENCH_H
#define WW_BENCH_H

#include <stdio.h>

#include "core/error.h"
#include "render/job.h"
#include "scene/scene.h"

typedef struct ww_bench_opts {
    int frames;             /* frames per configuration (0: 20) */
    int json;               /* one JSON object per line instead of a table */
    const char *scenes[4];  /* NULL-terminated; default minimal + demo (sim: see bench_sim.c) */
    const char *out_dir;    /* sim: folder for sim.png (default out/bench) */
    int tiny;               /* sim: a seconds-long run for the tests (no render share) */
    int width, height;      /* render: one size instead of 256x144 and 1280x720 (0: both) */
    const ww_set *sets;     /* render: scene overrides for every scene (--set), NULL: none */
    int nsets;
} ww_bench_opts;

ww_result ww_bench_render(const ww_bench_opts *o, FILE *to, ww_error *err);

/* ---- bench quality (bench_quality.c) -------------------------------------------------------- */

#define WW_QUALITY_MAX_VALUES 8
#define WW_QUALITY_MAX_KNOBS 10
#define WW_QUALITY_MAX_ROWS (WW_QUALITY_MAX_VALUES * WW_QUALITY_MAX_KNOBS)

/* one quality knob: a value of the compiled scene that trades speed for image error */
typedef struct ww_quality_knob {
    const char *name;        /* as written in the scene, e.g. "render.reflection.scale" */
    ww_pass_id pass;         /* the pass it tunes (WW_PASS_MAIN for knobs of the main pass) */
    int nvalues;
    double value[WW_QUALITY_MAX_VALUES]; /* cheapest first; the last is the reference's */
    /* set the knob; feature_on: also switch on the feature it belongs to (only asked when this
     * build has its pass) */
    void (*set)(ww_scene *sc, double v, int feature_on);
    double (*get)(const ww_scene *sc); /* its value in a scene as loaded: the default marked */
} ww_quality_knob;

/* the eight quality knobs: reflection.scale, shadows.size, shadows.technique, bloom.passes,
 * god_rays.samples, msaa, grid, water.look.caustics.method */
const ww_quality_knob *ww_quality_knobs(int *n);

typedef enum ww_quality_effect {
    WW_QUALITY_MEASURED = 0, /* rendered with the knob's pass in the plan */
    WW_QUALITY_NOT_BUILT,    /* this build has no pass for it: renders the same */
    WW_QUALITY_NOT_PLANNED   /* the scene does not plan its pass (e.g. shadows without casters) */
} ww_quality_effect;

typedef struct ww_quality_row {
    int knob;                /* index in the knob list */
    double value;
    int is_default;          /* the scene's value as loaded */
    int is_reference;        /* the value every other knob holds (the knob's best) */
    ww_quality_effect effect;
    double ms;               /* render + glFinish, the least of the timed renders */
    double pass_ms;          /* the pass the knob tunes, the least (0: not planned) */
    double psnr;             /* dB of the final RGB8 frame against the reference (INFINITY: same) */
    int max_diff;            /* largest channel difference, 8-bit levels */
    int front;               /* no other value of the knob has both as cheap a pass and as close
                              * a frame, and is better in one of them */
    int knee;                /* the value with the cheapest pass within WW_QUALITY_GOOD_DB of
                              * the reference */
} ww_quality_row;

/* PSNR from which two frames count as alike (the knee): 40 dB, an RMS error of 2.6 levels */
#define WW_QUALITY_GOOD_DB 40.0

typedef struct ww_quality_opts {
    const char *scene;       /* default scenes/lake.yaml */
    int width, height;       /* default 640x360 */
    int64_t frame;           /* the frame rendered (default 0) */
    int repeats;             /* timed renders per configuration (0: 5), after one untimed */
    const char *out_dir;     /* folder for quality.png (default out/bench); NULL in tests: none */
    int json;                /* one JSON object per row */
    int no_figure;           /* do not write the figure */
    const char *knob;        /* only this knob (its name), NULL: all of them */
    ww_backend_kind backend;
} ww_quality_opts;

/* the render.quality presets, measured whole: the scene as written with the preset set */
#define WW_QUALITY_PRESETS 3
/* the pseudo-knob that asks for them alone (--knob) */
#define WW_QUALITY_PRESET_KNOB "render.quality"
typedef struct ww_quality_preset {
    const char *name;        /* final, preview, draft */
    double ms;               /* render + glFinish, the least of the timed renders */
    double psnr;             /* dB against the reference (INFINITY: the same frame) */
    int max_diff;
    double psnr_final;       /* dB against the scene's frame at final */
} ww_quality_preset;

typedef struct ww_quality_result {
    char device[64], renderer[128];
    double reference_ms;     /* the reference configuration */
    int nrows;
    ww_quality_row rows[WW_QUALITY_MAX_ROWS];
    int npresets;            /* 0 when --knob named a knob */
    ww_quality_preset presets[WW_QUALITY_PRESETS];
} ww_quality_result;

/* render the reference, each value of each knob (the others at their best) and each preset;
 * fills res */
ww_result ww_bench_quality_measure(const ww_quality_opts *o, const ww_quality_knob *knobs,
                                   int nknobs, ww_quality_result *res, ww_error *err);
/* measure the knobs, print the table (or JSON lines) and write DIR/quality.png */
ww_result ww_bench_quality(const ww_quality_opts *o, FILE *to, ww_error *err);
ww_result ww_bench_sim(const ww_bench_opts *o, FILE *to, ww_error *err);
/* [frames] bench output (bench_output.c): fps of none, png, exr, y4m at 1280x720 (tiny: 256x144),
 * png/none against the 0.85 target, peak RSS of a 30- and a 300-frame PNG run */
ww_result ww_bench_output(const ww_bench_opts *o, FILE *to, ww_error *err);
/* render `frames` frames of one scene at width x height in a child process (auto backend, no
 * files kept); its job stats, or WW_E_BACKEND with the child's message */
ww_result ww_bench_render_once(const char *scene, int width, int height, int frames,
                               ww_job_stats *stats, ww_error *err);

/* ---- bench compare (bench_compare.c) -------------------------------------------------------- */

typedef struct ww_bench_compare_opts {
    const char *scene;       /* default scenes/demo.yaml: frames 0 and 1 are the pair */
    int width, height;       /* default 1280x720 */
    int repeats;             /* timed runs of each (0: 7); best and median reported */
    int json;                /* one JSON object instead of a table */
} ww_bench_compare_opts;

/* render the pair, then time our compare (load + metrics, metrics alone, the identical fast
 * path, the CLI as a process) and ImageMagick's `compare -metric RMSE` by fork/exec */
ww_result ww_bench_compare(const ww_bench_compare_opts *o, FILE *to, ww_error *err);

#endif
