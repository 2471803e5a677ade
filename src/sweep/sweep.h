/* sweep.h - `waterworld sweep`: one scene evaluated over a grid (or a seeded random sample) of
 * --set values, one row of wave statistics per point, optionally a thumbnail per point and a
 * contact sheet.
 *
 *   ww_sweep_opts o = ww_default_sweep_opts();
 *   o.scene_path = "scenes/demo.yaml"; o.vary = specs; o.nvary = 2; o.out_dir = "out/sweep"; ...
 *   ww_sweep *s = NULL;
 *   ww_sweep_new(&o, &s, &err);        // parses the axes, reads the scene, loads the first point:
 *                                      // bad --vary, an unknown key or a scene that cannot be
 *                                      // read fail here, before any work (exit 2)
 *   ww_sweep_run(s, stdout, &err);     // every point (or only o.point): rows in point order
 *   ww_sweep_emit_jobs(s, stdout, &err); // or: one shell command line per point
 *   ww_sweep_free(s);
 *
 * Points. A grid is the cartesian product of the axes, the first axis slowest; an axis is
 * KEY=A:B:N (N evenly spaced values from A to B inclusive; N = 1 gives A) or KEY=v1,v2,... (words
 * or numbers; commas inside [], {} or quotes do not split, so a YAML flow list can be one value).
 * With o.random = N the sweep has N points instead, axis values drawn uniformly in [A, B] (A:B
 * is enough there) or uniformly from the list; point i's draws come from its own PCG stream
 * (core/rng.h, WW_RNG_SWEEP) seeded from SplitMix64 of (seed, i), so any point can be computed
 * alone and the same seed always gives the same rows.
 *
 * A point is the scene loaded with the base sets, then one KEY=VALUE per axis, through the normal
 * loader. A point that fails to load is a row with status "error" and the loader's message (its
 * place names the axis as --vary[N]); one whose load warned (fold: warn) has status "warn".
 *
 * Output. Without out_dir: CSV on the given stream. With out_dir: OUT/sweep.csv and
 * OUT/sweep.jsonl, each written atomically. With o.point >= 0 only that point is computed and
 * its JSON line goes to the stream, or to OUT/points/point_NNNNN.jsonl (with its CSV row in
 * point_NNNNN.csv and the sweep's OUT/points/sweep.job: the point count, the CSV header and the
 * points' command, for `waterworld join OUT`); the JSON line is the same bytes as that point's
 * line of a full sweep.jsonl, so `cat OUT/points/point_*.jsonl` is it.
 * With o.jobs > 1, points are computed by that many forked worker processes (point i on worker
 * i mod jobs) and the rows gathered through pipes in point order: the same bytes as jobs = 1.
 * With o.thumbs, each point's frame o.thumb_frame is rendered at thumb_w x thumb_h in a child
 * process of its own (own GL context, like bench) into OUT/thumbs/point_NNNNN.png, and a full
 * sweep composes OUT/contact_sheet.png (render/contact.h).
 */
#ifndef WW_SWEEP_H
#define WW_SWEEP_H

#include <stdint.h>
#include <stdio.h>

#include "core/error.h"
#include "gfx/backend.h"
#include "scene/scene.h"

#define WW_SWEEP_MAX_AXES 16
#define WW_SWEEP_MAX_ITEMS 1024      /* values in one list axis */
#define WW_SWEEP_MAX_POINTS 1000000  /* a larger grid is refused */
#define WW_SWEEP_MAX_JOBS 256
#define WW_SWEEP_VALUE_MAX 256       /* bytes of one value's text, with its terminator */
#define WW_SWEEP_JOB_MAGIC "waterworld sweep job 1" /* first line of OUT/points/sweep.job */

typedef struct ww_sweep_opts {
    const char *scene_path;
    const ww_set *sets;          /* base --set values, applied before the point's own */
    int nsets;
    const char *const *vary;     /* "KEY=A:B:N" or "KEY=v1,v2,..." as given */
    int nvary;
    long long random;            /* > 0: that many random points instead of the grid */
    uint64_t seed;               /* for random points */
    int jobs;                    /* worker processes (0 or 1: in this process) */
    long long point;             /* >= 0: compute only this point; -1: all */
    const char *out_dir;         /* NULL: CSV (or the point's JSON line) on the stream */
    int thumbs;                  /* render a thumbnail per point (needs out_dir) */
    int thumb_w, thumb_h;        /* px (0: 160 x 90) */
    int64_t thumb_frame;         /* frame rendered for a thumbnail */
    ww_backend_kind backend;     /* for thumbnails */
    const char *exe;             /* the program named in --emit-jobs lines (NULL: "waterworld") */
    int quiet;                   /* no summary on stderr */
} ww_sweep_opts;

typedef struct ww_sweep ww_sweep;

ww_sweep_opts ww_default_sweep_opts(void);
/* bad axes, counts or options are WW_E_USAGE; a scene that cannot be read or parsed, and a key
 * that the first point shows to be unknown, are the loader's own codes */
ww_result ww_sweep_new(const ww_sweep_opts *o, ww_sweep **out, ww_error *err);
void ww_sweep_free(ww_sweep *s);

long long ww_sweep_points(const ww_sweep *s);  /* points of the whole sweep */
int ww_sweep_axes(const ww_sweep *s);
const char *ww_sweep_axis_key(const ww_sweep *s, int axis);
/* the text of each axis's value at point i, as it is set: vals[axis] */
void ww_sweep_values(const ww_sweep *s, long long i, char vals[][WW_SWEEP_VALUE_MAX]);

/* compute the rows and write them (CSV to `to` without out_dir, or the point's JSON line);
 * points that fail to load are rows, not failures; a failure here is I/O, GL or a worker lost */
ww_result ww_sweep_run(ww_sweep *s, FILE *to, ww_error *err);
/* one shell-quoted command line per point: `EXE sweep SCENE <the same axes and sets> --point I`
 * (with -o and the thumbnail options when given) */
ww_result ww_sweep_emit_jobs(const ww_sweep *s, FILE *to, ww_error *err);

#endif
