/* job.h - one render job: step the simulation, render the frames of a slice, read them back and
 * write them. Shared by `render` and `bench`, so what bench measures is what render does.
 *
 *   ww_job_opts o = ww_default_job_opts();  o.out_dir = "out/demo"; ...
 *   ww_job_stats s; ww_job_run(sc, &o, &s, &err);
 *
 * Frames [first, last) are rendered; the prefix [0, first) is stepped without rendering, so a
 * slice gives byte-identical frames to a full run.
 */
#ifndef WW_JOB_H
#define WW_JOB_H

#include <stdint.h>

#include "core/error.h"
#include "gfx/backend.h"
#include "gfx/renderer.h"
#include "scene/scene.h"

typedef enum ww_out_format { WW_OUT_PNG = 0, WW_OUT_EXR, WW_OUT_NONE } ww_out_format;

typedef struct ww_job_opts {
    const char *out_dir;      /* folder for frame_XXXXX.EXT; created */
    ww_out_format format;
    int64_t first, last;      /* frame slice [first, last) */
    int width, height;        /* render size (the scene's unless --size) */
    ww_backend_kind backend;
    int quiet;                /* no summary line on stderr */
    ww_timing time_passes;    /* bench: per-pass timing (WW_TIMING_OFF: none) */
} ww_job_opts;

typedef struct ww_job_stats {
    int64_t frames;           /* frames rendered */
    double prefix_s;          /* stepping the prefix before the first frame */
    double sim_s, render_s, readback_s, encode_s; /* totals over the rendered frames, s */
    double first_render_s;    /* render time of the first frame alone (shader JIT, caches), s */
    double setup_s;           /* backend + renderer creation, s */
    char backend[64];         /* e.g. "egl/surfaceless" */
    char renderer[128];       /* GL_RENDERER */
    long peak_rss_kib;        /* process peak resident set after the job */
    size_t state_bytes;       /* size of the ww_state block */
    ww_pass_times passes;     /* with time_passes: ms per pass summed over the frames after the
                               * first (all frames when only one is rendered) */
} ww_job_stats;

ww_job_opts ww_default_job_opts(void);
/* parse "png" | "exr" | "none"; -1 when none of them */
int ww_out_format_parse(const char *s);
const char *ww_out_format_ext(ww_out_format f);
ww_result ww_job_run(const ww_scene *sc, const ww_job_opts *o, ww_job_stats *stats, ww_error *err);
double ww_now_seconds(void); /* monotonic clock, for timing only (never the simulation) */

#endif
