/* render_jobs.h - `render --jobs N`: one run's frames rendered by N processes of this binary.
 *
 * The frames [first, last) are cut into N slices (render/slices.h); slice I is rendered by a
 * child `EXE render WORDS -o DIR --slice I/N --quiet`, with LP_NUM_THREADS set to cores / N
 * (at least 1) unless the environment sets it. Once every child has exited 0, the slices'
 * sound track and stats are joined (`join`), moved to the paths the command named, and the
 * slices' parts under DIR/slices/ removed: DIR then holds the frames and sound track of a
 * one-process run, byte for byte (the stats carry each slice's summary line).
 *
 * Why: llvmpipe bins each pass on the calling thread while its rasterising threads wait for
 * it, so one process leaves cores idle part of every frame; N processes of fewer threads each
 * keep them busy (docs/speed.md, "Processes against llvmpipe's threads").
 */
#ifndef WW_RENDER_JOBS_H
#define WW_RENDER_JOBS_H

#include <stdint.h>

#include "core/error.h"
#include "render/job.h"

#define WW_RENDER_MAX_JOBS 64

typedef struct ww_render_jobs {
    int jobs;                  /* processes, >= 2 */
    const char *exe;           /* this binary */
    char **words;              /* what each child repeats after "render": the scene and the
                                * options that shape the frames (not -o, --jobs, --golden and
                                * its thresholds, --audio, --stats, --progress, --quiet,
                                * --resume) */
    int nwords;
    const char *dir;           /* the frames' folder */
    const char *audio_path;    /* the joined sound track's path, NULL for none */
    const char *stats_path;    /* the joined stats' path, NULL for none */
    int resume;                /* --resume: keep complete slices and frames */
    int quiet;
    ww_progress progress;
    int64_t first, last;       /* the run's frames */
    ww_out_format format;
} ww_render_jobs;

typedef struct ww_render_jobs_stats {
    int jobs;                  /* processes run (at most one a frame) */
    int threads;               /* LP_NUM_THREADS given to each, 0 when the environment set it */
    double wall_s;
} ww_render_jobs_stats;

/* the children, then the join; a child's failure is reported naming its slice and its exit
 * code (its own message is on stderr before it), and the parts are kept for --resume */
ww_result ww_render_jobs_run(const ww_render_jobs *o, ww_render_jobs_stats *st, ww_error *err);

#endif
