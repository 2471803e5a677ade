/* job.c - the render loop of job.h: backend, renderer from the plan, state, frame slice,
 * read-back and atomic frame files, with per-phase timings for bench.
 */
#include "tools/job.h"

#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "gfx/renderer.h"
#include "io/image.h"
#include "io/writers.h"
#include "scene/plan.h"
#include "sim/state.h"
#include "sim/step.h"
#include "tools/audio.h"

double ww_now_seconds(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

ww_job_opts ww_default_job_opts(void) {
    return (ww_job_opts){.out_dir = "out", .format = WW_OUT_PNG, .first = 0, .last = -1,
                         .backend = WW_BACKEND_AUTO};
}

int ww_out_format_parse(const char *s) {
    if (strcmp(s, "png") == 0) return WW_OUT_PNG;
    if (strcmp(s, "exr") == 0) return WW_OUT_EXR;
    if (strcmp(s, "none") == 0) return WW_OUT_NONE;
    if (strcmp(s, "y4m") == 0) return WW_OUT_Y4M;
    if (strcmp(s, "raw") == 0) return WW_OUT_RAW;
    return -1;
}

const char *ww_out_format_ext(ww_out_format f) {
    switch (f) {
    case WW_OUT_PNG: return "png";
    case WW_OUT_EXR: return "exr";
    case WW_OUT_Y4M: return "y4m";
    case WW_OUT_RAW: return "rgb";
    case WW_OUT_NONE: break;
    }
    return "";
}

typedef struct job {
    ww_backend *backend;
    ww_renderer *renderer;
    ww_state *st;
    ww_image ldr, hdr;
    ww_audio *audio;      /* --audio: fed after every step of the slice */
} job;

static void job_close(job *j) {
    ww_audio_free(j->audio);
    ww_image_free(&j->ldr);
    ww_image_free(&j->hdr);
    ww_state_free(j->st);
    if (j->renderer) ww_renderer_free(j->renderer);
    if (j->backend) ww_backend_close(j->backend);
}

/* step to `step`; with a sound track, one step at a time so that it hears every step's events */
static ww_result advance(const ww_scene *sc, job *j, int64_t step, ww_error *err) {
    if (!j->audio) return ww_sim_advance_to(sc, j->st, step, err);
    while (j->st->step < step) {
        ww_result r = ww_step(sc, j->st, err);
        if (r) return r;
        ww_audio_step(j->audio, sc, j->st);
    }
    return WW_OK;
}

/* read back and write frame f in the job's format */
static ww_result emit_frame(const ww_scene *sc, const ww_job_opts *o, job *j, int64_t f,
                            ww_job_stats *s, ww_error *err) {
    double t0 = ww_now_seconds();
    ww_result r = o->format == WW_OUT_EXR ? ww_renderer_read_hdr(j->renderer, &j->hdr, err)
                                          : ww_renderer_read_ldr(j->renderer, &j->ldr, err);
    if (r) return r;
    double t1 = ww_now_seconds();
    s->readback_s += t1 - t0;
    if (o->format == WW_OUT_NONE) return WW_OK;

    char path[1024];
    snprintf(path, sizeof path, "%s/frame_%05lld.%s", o->out_dir, (long long)f,
             ww_out_format_ext(o->format));
    if (o->format == WW_OUT_PNG) {
        r = ww_write_png(path, &j->ldr, err);
    } else {
        ww_exr_meta meta = {.frame = (int)f, .time = j->st->t, .scene = sc->name,
                            .renderer = s->renderer};
        r = ww_write_exr(path, &j->hdr, &meta, err);
    }
    s->encode_s += ww_now_seconds() - t1;
    return r;
}

ww_result ww_job_run(const ww_scene *sc, const ww_job_opts *o, ww_job_stats *s, ww_error *err) {
    memset(s, 0, sizeof *s);
    double job_t0 = ww_now_seconds();
    job j = {0};
    ww_result r = WW_OK;
    WW_ASSERT(o->first >= 0 && o->last > o->first);
    if (o->format == WW_OUT_Y4M || o->format == WW_OUT_RAW)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--format %s is not built yet",
                            ww_out_format_ext(o->format));

    /* the GL side: backend, then passes from the plan */
    double t0 = ww_now_seconds();
    ww_plan plan;
    ww_plan_build(sc, o->width, o->height, &plan);
    if ((r = ww_backend_open(o->backend, &j.backend, err))) goto done;
    snprintf(s->backend, sizeof s->backend, "%s", ww_backend_describe(j.backend));
    snprintf(s->renderer, sizeof s->renderer, "%s", ww_backend_renderer(j.backend));
    snprintf(s->gl_version, sizeof s->gl_version, "%s", ww_backend_version(j.backend));
    if ((r = ww_renderer_new(ww_backend_gl(j.backend), sc, &plan, &j.renderer, err))) goto done;
    if (ww_image_alloc(&j.ldr, o->width, o->height, 3, WW_PIX_U8) ||
        ww_image_alloc(&j.hdr, o->width, o->height, 4, WW_PIX_F32) || !(j.st = ww_state_new(sc))) {
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for %dx%d frames", o->width,
                         o->height);
        goto done;
    }
    s->state_bytes = j.st->bytes;
    s->setup_s = ww_now_seconds() - t0;
    if (o->time_passes != WW_TIMING_OFF) ww_renderer_time_passes(j.renderer, o->time_passes);

    /* the output folder only once everything that can fail before the first frame has not */
    if (o->format != WW_OUT_NONE && (r = ww_make_dirs(o->out_dir, err))) goto done;

    /* the prefix is stepped, not rendered */
    t0 = ww_now_seconds();
    if ((r = ww_sim_advance_to(sc, j.st, o->first * sc->steps_per_frame, err))) goto done;
    s->prefix_s = ww_now_seconds() - t0;
    if (o->audio_path && (r = ww_audio_new(sc, o->first * sc->steps_per_frame,
                                           o->last * sc->steps_per_frame, &j.audio, err)))
        goto done;

    for (int64_t f = o->first; f < o->last; f++) {
        double a = ww_now_seconds();
        if ((r = advance(sc, &j, f * sc->steps_per_frame, err))) goto done;
        double b = ww_now_seconds();
        if ((r = ww_render_frame(j.renderer, sc, j.st, err))) goto done;
        ww_renderer_finish(j.renderer);
        double c = ww_now_seconds();
        s->sim_s += b - a;
        s->render_s += c - b;
        if (f == o->first) s->first_render_s = c - b;
        /* the first frame's pass times carry shader compilation: dropped, as bench does */
        if (o->time_passes != WW_TIMING_OFF && f == o->first && o->last - o->first > 1)
            ww_renderer_pass_times(j.renderer, &s->passes);
        if ((r = emit_frame(sc, o, &j, f, s, err))) goto done;
        s->frames++;
    }

    if (o->time_passes != WW_TIMING_OFF) ww_renderer_pass_times(j.renderer, &s->passes);
    /* the track runs to the end of the slice's last frame */
    if (j.audio) {
        if ((r = advance(sc, &j, o->last * sc->steps_per_frame, err))) goto done;
        if ((r = ww_audio_write(j.audio, o->audio_path, err))) goto done;
    }

done:
    job_close(&j);
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) == 0) s->peak_rss_kib = ru.ru_maxrss;
    s->wall_s = ww_now_seconds() - job_t0;
    return r;
}
