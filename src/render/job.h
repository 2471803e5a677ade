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

/* png: sRGB8 (RGBA8 with alpha); exr: linear half or float RGBA; y4m: one YUV4MPEG2 stream (4:4:4
 * or 4:2:0, see y4m_chroma) into a file or stdout; raw: packed RGB8 frames, one stream; none:
 * render and read back only */
typedef enum ww_out_format { WW_OUT_PNG = 0, WW_OUT_EXR, WW_OUT_NONE, WW_OUT_Y4M, WW_OUT_RAW } ww_out_format;

typedef enum ww_exr_compression { WW_EXR_ZIP = 0, WW_EXR_NONE, WW_EXR_PIZ } ww_exr_compression;

/* progress on stderr: auto shows it when stderr is a terminal */
typedef enum ww_progress { WW_PROGRESS_AUTO = 0, WW_PROGRESS_OFF, WW_PROGRESS_ON } ww_progress;

typedef struct ww_job_opts {
    const char *out_dir;      /* folder for frame_XXXXX.EXT; created. y4m/raw: the stream's file,
                               * "-" for stdout */
    ww_out_format format;
    int64_t first, last;      /* frame slice [first, last) */
    int width, height;        /* render size (the scene's unless --size) */
    ww_backend_kind backend;
    int quiet;                /* no summary line and no progress on stderr */
    ww_timing time_passes;    /* bench: per-pass timing (WW_TIMING_OFF: none) */

    /* frames out */
    int alpha;                /* png: RGBA8, alpha from the HDR target (--alpha) */
    int exr_float;            /* exr: 32-bit float channels instead of half (--exr-float) */
    ww_exr_compression exr_compression; /* --exr-compression none|zip|piz */
    int y4m_420;              /* y4m: 4:2:0 chroma (C420jpeg) instead of 4:4:4 (--y4m-420) */
    int threads;              /* encoder threads; 0: one per core beyond the render thread, >= 1 */
    int resume;               /* skip frames whose file is already complete (--resume) */
    ww_progress progress;
    const char *stats_path;   /* --stats FILE.jsonl: one line per frame with its timings; NULL: none */
    const char *audio_path;   /* --audio FILE.wav: the sound track of the slice; NULL: none */
    const struct ww_checkpoint *from; /* --from-checkpoint: start from its state (and sound), at
                               * or before the first frame's step (render/checkpoint.h); NULL:
                               * from step 0 */
} ww_job_opts;

typedef struct ww_job_stats {
    int64_t frames;           /* frames rendered */
    double prefix_s;          /* stepping the prefix before the first frame */
    double sim_s, render_s, readback_s, encode_s; /* totals over the rendered frames, s */
    double first_render_s;    /* render time of the first frame alone (shader JIT, caches), s */
    double setup_s;           /* backend + renderer creation, s */
    char backend[64];         /* e.g. "egl/surfaceless" */
    char renderer[128];       /* GL_RENDERER */
    char gl_version[128];     /* GL_VERSION (names the Mesa release on Mesa) */
    long peak_rss_kib;        /* process peak resident set after the job */
    size_t state_bytes;       /* size of the ww_state block */
    ww_pass_times passes;     /* with time_passes: ms per pass summed over the frames after the
                               * first (all frames when only one is rendered) */
    int64_t skipped;          /* --resume: frames already complete on disk, not written again */
    double wall_s;            /* the whole job, setup included, s */
    double encode_wait_s;     /* the render thread waiting for a free queue slot, s */
    double loop_s;            /* first frame started to last frame written (the frames' fps) */
} ww_job_stats;

ww_job_opts ww_default_job_opts(void);
/* parse "png" | "exr" | "y4m" | "raw" | "none"; -1 when none of them */
int ww_out_format_parse(const char *s);
const char *ww_out_format_ext(ww_out_format f);
/* WW_E_INTERRUPTED when SIGINT/SIGTERM arrived: the frames in flight were finished, nothing
 * partial is on disk (the handlers are installed for the job's length and restored after) */
ww_result ww_job_run(const ww_scene *sc, const ww_job_opts *o, ww_job_stats *stats, ww_error *err);
double ww_now_seconds(void); /* monotonic clock, for timing only (never the simulation) */

#endif
