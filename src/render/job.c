/* job.c - the render loop of job.h, pipelined: the calling thread simulates, renders and reads
 * each frame back into a slot of a fixed pool; encoder threads take filled slots from a bounded
 * queue (io/queue.h), encode and write them atomically, and hand the slots back. Also --resume,
 * SIGINT/SIGTERM, the progress line and --stats.
 */
#include "render/job.h"

#include <dirent.h>
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "gfx/renderer.h"
#include "io/image.h"
#include "io/outpath.h"
#include "io/queue.h"
#include "io/stream.h"
#include "io/writers.h"
#include "io/y4m.h"
#include "render/audio.h"
#include "render/checkpoint.h"
#include "render/prefix.h"
#include "sim/state.h"
#include "sim/step.h"

#define MAX_THREADS 64
/* slots beyond one per encoder thread: one being filled by the render thread, one queued, so
 * neither side waits on the other while both keep pace */
#define EXTRA_SLOTS 2
/* the progress line is rewritten at most this often, s */
#define PROGRESS_PERIOD_S 0.25

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

/* ---- signals ---------------------------------------------------------------------------------
 * A signal handler takes no context, so the one flag it sets is the file's only static: written
 * by the handler (async-signal-safe: a store to a volatile sig_atomic_t), read by the render
 * loop between frames. SA_RESETHAND: a second Ctrl-C kills at once, as users expect. */
static volatile sig_atomic_t job_signal;

static void on_signal(int sig) { job_signal = sig; }

typedef struct job_signals {
    struct sigaction old_int, old_term, old_pipe;
} job_signals;

static void signals_install(job_signals *js) {
    job_signal = 0;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &js->old_int);
    /* a SIGINT ignored when we started (a background job of a script) stays ignored */
    if (js->old_int.sa_handler == SIG_IGN) sigaction(SIGINT, &js->old_int, NULL);
    sigaction(SIGTERM, &sa, &js->old_term);
    /* a closed pipe (ffmpeg gone) is a write error to report, not a silent death */
    struct sigaction ign;
    memset(&ign, 0, sizeof ign);
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    sigaction(SIGPIPE, &ign, &js->old_pipe);
}

static void signals_restore(const job_signals *js) {
    sigaction(SIGINT, &js->old_int, NULL);
    sigaction(SIGTERM, &js->old_term, NULL);
    sigaction(SIGPIPE, &js->old_pipe, NULL);
}

/* ---- the job ------------------------------------------------------------------------------- */

/* one frame in flight: filled by the render thread, emptied by an encoder thread */
typedef struct slot {
    int64_t frame;
    double t;                  /* simulated time of the frame, s */
    ww_image img;              /* LDR U8 (3 or 4 channels) or HDR F32 RGBA */
} slot;

/* --stats: one record per frame of the slice */
typedef struct frame_rec {
    double t, sim_ms, render_ms, readback_ms, encode_ms, wait_ms;
    size_t bytes;
    int written;
} frame_rec;

typedef struct job {
    const ww_scene *sc;
    const ww_job_opts *o;
    /* render thread only */
    ww_backend *backend;
    ww_renderer *renderer;
    ww_state *st;
    ww_audio *audio;           /* --audio: fed after every step of the slice */
    float *depth;              /* --alpha: depth read-back scratch */
    /* the pipeline */
    slot *slots;
    int nslots, nworkers, queues;
    int threads;               /* encoder threads started (nworkers drops to 0 once joined) */
    ww_queue free_q, work_q;
    pthread_t workers[MAX_THREADS];
    ww_stream stream;          /* y4m / raw */
    int stream_open;
    uint8_t *ybuf;             /* y4m: one frame, used by the single stream writer */
    char renderer_name[128];
    /* shared with the encoder threads */
    pthread_mutex_t lock;
    int lock_made;
    atomic_int failed;         /* an encoder failed: stop taking frames */
    atomic_llong written;      /* frames written */
    ww_result first_r;         /* under lock: the first encoder error */
    ww_error first_err;
    double encode_s;           /* under lock */
    frame_rec *recs;           /* --stats, indexed by frame - first; each written by one thread */
} job;

static int is_stream(ww_out_format f) { return f == WW_OUT_Y4M || f == WW_OUT_RAW; }

static void frame_path(const ww_job_opts *o, int64_t f, char *buf, size_t cap) {
    snprintf(buf, cap, "%s/frame_%05lld.%s", o->out_dir, (long long)f, ww_out_format_ext(o->format));
}

/* encode and write one slot; bytes written into *bytes */
static ww_result write_slot(job *j, const slot *s, size_t *bytes, ww_error *err) {
    const ww_job_opts *o = j->o;
    *bytes = 0;
    if (o->format == WW_OUT_NONE) return WW_OK;
    if (is_stream(o->format)) {
        /* one writer thread: frames reach the stream in order, whole */
        const void *data = s->img.u8;
        size_t n = (size_t)s->img.width * (size_t)s->img.height * 3;
        if (o->format == WW_OUT_Y4M) {
            ww_y4m_frame(&s->img, o->y4m_420, j->ybuf);
            data = j->ybuf;
            n = ww_y4m_frame_bytes(s->img.width, s->img.height, o->y4m_420);
        }
        if (fwrite(data, 1, n, j->stream.f) != n)
            return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot write frame %lld to %s: %s",
                                (long long)s->frame, j->stream.is_stdout ? "stdout" : o->out_dir,
                                strerror(errno));
        *bytes = n;
        return WW_OK;
    }
    unsigned char *data = NULL;
    size_t len = 0;
    ww_result r;
    if (o->format == WW_OUT_PNG) {
        r = ww_encode_png(&s->img, &data, &len, err);
    } else {
        ww_exr_meta meta = {.float32 = o->exr_float, .compression = (int)o->exr_compression,
                            .frame = (int)s->frame, .time = s->t, .scene = j->sc->name,
                            .renderer = j->renderer_name};
        r = ww_encode_exr(&s->img, &meta, &data, &len, err);
    }
    char path[1024];
    frame_path(o, s->frame, path, sizeof path);
    if (r == WW_OK) r = ww_write_file_atomic(path, data, len, err);
    free(data);
    *bytes = len;
    return r;
}

static void *encoder_main(void *arg) {
    job *j = arg;
    slot *s;
    while ((s = ww_queue_pop(&j->work_q)) != NULL) {
        /* after a failure the remaining slots go back unwritten */
        if (!atomic_load(&j->failed)) {
            ww_error e = {0};
            size_t bytes = 0;
            double t0 = ww_now_seconds();
            ww_result r = write_slot(j, s, &bytes, &e);
            double dt = ww_now_seconds() - t0;
            pthread_mutex_lock(&j->lock);
            if (r != WW_OK && !atomic_load(&j->failed)) {
                j->first_r = r;
                j->first_err = e;
                atomic_store(&j->failed, 1);
            }
            j->encode_s += dt;
            pthread_mutex_unlock(&j->lock);
            if (r == WW_OK) {
                if (j->recs) {
                    frame_rec *fr = &j->recs[s->frame - j->o->first];
                    fr->encode_ms = 1e3 * dt;
                    fr->bytes = bytes;
                    fr->written = 1;
                }
                atomic_fetch_add(&j->written, 1);
            }
        }
        ww_queue_push(&j->free_q, s);
    }
    return NULL;
}

/* encoder threads: --threads, else one per core beyond the render thread; one for a stream */
static int encoder_count(const ww_job_opts *o) {
    if (is_stream(o->format) || o->format == WW_OUT_NONE) return 1;
    if (o->threads > 0) return o->threads < MAX_THREADS ? o->threads : MAX_THREADS;
    long n = sysconf(_SC_NPROCESSORS_ONLN) - 1;
    return n < 1 ? 1 : n > MAX_THREADS ? MAX_THREADS : (int)n;
}

/* the slot pool (allocated once: memory stays flat however long the run), the queues, the
 * encoder threads */
static ww_result pipeline_start(job *j, ww_error *err) {
    const ww_job_opts *o = j->o;
    j->nworkers = j->threads = encoder_count(o);
    j->nslots = j->nworkers + EXTRA_SLOTS;
    int hdr = o->format == WW_OUT_EXR, ch = hdr || (o->alpha && o->format == WW_OUT_PNG) ? 4 : 3;
    j->slots = calloc((size_t)j->nslots, sizeof *j->slots);
    int bad = !j->slots || pthread_mutex_init(&j->lock, NULL) != 0;
    j->lock_made = !bad;
    for (int i = 0; !bad && i < j->nslots; i++)
        bad = ww_image_alloc(&j->slots[i].img, o->width, o->height, ch,
                             hdr ? WW_PIX_F32 : WW_PIX_U8) != 0;
    if (!bad && o->alpha) bad = !(j->depth = malloc((size_t)o->width * (size_t)o->height * sizeof(float)));
    if (!bad && o->format == WW_OUT_Y4M)
        bad = !(j->ybuf = malloc(ww_y4m_frame_bytes(o->width, o->height, o->y4m_420)));
    if (!bad && o->stats_path)
        bad = !(j->recs = calloc((size_t)(o->last - o->first), sizeof *j->recs));
    if (!bad) {
        bad = ww_queue_init(&j->free_q, (size_t)j->nslots) != 0;
        if (!bad && ww_queue_init(&j->work_q, (size_t)j->nslots) != 0) {
            ww_queue_free(&j->free_q);
            bad = 1;
        }
        j->queues = !bad;
    }
    if (bad)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for %d %dx%d frame slots",
                            j->nslots, o->width, o->height);
    for (int i = 0; i < j->nslots; i++) ww_queue_push(&j->free_q, &j->slots[i]);
    for (int i = 0; i < j->nworkers; i++) {
        if (pthread_create(&j->workers[i], NULL, encoder_main, j) != 0) {
            j->nworkers = i;
            return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot start encoder thread %d", i);
        }
    }
    return WW_OK;
}

/* no more frames: the encoders finish what is queued and end */
static void pipeline_stop(job *j) {
    if (!j->queues) return;
    ww_queue_close(&j->work_q);
    for (int i = 0; i < j->nworkers; i++) pthread_join(j->workers[i], NULL);
    j->nworkers = 0;
}

static void job_close(job *j) {
    pipeline_stop(j);
    if (j->stream_open) ww_stream_abort(&j->stream);
    if (j->queues) {
        ww_queue_free(&j->work_q);
        ww_queue_free(&j->free_q);
    }
    for (int i = 0; j->slots && i < j->nslots; i++) ww_image_free(&j->slots[i].img);
    free(j->slots);
    if (j->lock_made) pthread_mutex_destroy(&j->lock);
    free(j->recs);
    free(j->ybuf);
    free(j->depth);
    ww_audio_free(j->audio);
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

static void hear_step(void *audio, const ww_scene *sc, const ww_state *st) {
    ww_audio_step(audio, sc, st);
}

/* the prefix: from step 0, or from the checkpoint's state and sound, to the first frame's step,
 * with its progress line; a signal stops it (the loop then stops at once) */
static ww_result step_prefix(const ww_scene *sc, job *j, ww_error *err) {
    const ww_job_opts *o = j->o;
    ww_result r = WW_OK;
    WW_ASSERT(!o->from || o->from->step <= o->first * sc->steps_per_frame);
    if (o->from) {
        ww_state_copy(j->st, o->from->st);
        if (j->audio) r = ww_audio_restore(j->audio, j->st, o->from->sound, o->from->sound_bytes, err);
        if (r) return r;
    }
    ww_steps_progress p;
    ww_steps_progress_begin(&p, o->progress == WW_PROGRESS_ON ||
                                    (o->progress == WW_PROGRESS_AUTO && !o->quiet && isatty(2)),
                            "simulating the prefix", j->st->step, o->first * sc->steps_per_frame);
    r = ww_prefix_advance(sc, j->st, o->first * sc->steps_per_frame, j->audio ? hear_step : NULL,
                          j->audio, &p, &job_signal, err);
    ww_steps_progress_end(&p, j->st->step);
    return r;
}

/* ---- resume -------------------------------------------------------------------------------- */

/* frame f is on disk, whole (an atomic rename published it; the check catches files copied or
 * damaged by other means, which are then rendered again) */
static int frame_done(const ww_job_opts *o, int64_t f) {
    char path[1024];
    frame_path(o, f, path, sizeof path);
    return o->format == WW_OUT_PNG ? ww_png_complete(path) : ww_exr_complete(path);
}

/* temporary files of this slice's frames ("frame_00012.png.tmp.PID") left by a killed run;
 * other slices' are left alone, as another process may be writing them */
static void remove_stale_temps(const ww_job_opts *o) {
    DIR *d = opendir(o->out_dir);
    if (!d) return;
    char suffix[16];
    snprintf(suffix, sizeof suffix, ".%s.tmp.", ww_out_format_ext(o->format));
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *n = e->d_name;
        if (strncmp(n, "frame_", 6) != 0) continue;
        char *end = NULL;
        long long f = strtoll(n + 6, &end, 10);
        if (end == n + 6 || strncmp(end, suffix, strlen(suffix)) != 0) continue;
        if (f < o->first || f >= o->last) continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", o->out_dir, n);
        unlink(path);
    }
    closedir(d);
}

/* ---- progress and stats -------------------------------------------------------------------- */

typedef struct progress {
    int on;
    double t0, last;
    int width;                 /* characters of the last line, to clear it */
} progress;

static void progress_show(progress *p, long long done, long long total, int final) {
    double now = ww_now_seconds();
    if (!p->on || (!final && now - p->last < PROGRESS_PERIOD_S)) return;
    p->last = now;
    double el = now - p->t0, fps = el > 0 ? (double)done / el : 0.0;
    long eta = fps > 0 ? (long)((double)(total - done) / fps + 0.5) : 0;
    int n = fprintf(stderr, "\rframe %lld/%lld  %.1f fps  ETA %ld:%02ld ", done, total, fps,
                    eta / 60, eta % 60);
    if (n > p->width) p->width = n;
    fflush(stderr);
}

static void progress_clear(progress *p) {
    if (!p->on || p->width == 0) return;
    fprintf(stderr, "\r%*s\r", p->width, "");
    fflush(stderr);
}

/* --stats: one JSON line per frame written, then the summary; atomic */
static ww_result write_stats(const job *j, const ww_job_stats *s, ww_error *err) {
    const ww_job_opts *o = j->o;
    ww_stream out;
    ww_result r = ww_stream_open(&out, o->stats_path, err);
    if (r) return r;
    for (int64_t f = o->first; f < o->last; f++) {
        const frame_rec *fr = &j->recs[f - o->first];
        if (!fr->written) continue;
        fprintf(out.f,
                "{\"frame\": %lld, \"t\": %.9g, \"sim_ms\": %.3f, \"render_ms\": %.3f, "
                "\"readback_ms\": %.3f, \"encode_ms\": %.3f, \"queue_wait_ms\": %.3f, "
                "\"bytes\": %zu}\n",
                (long long)f, fr->t, fr->sim_ms, fr->render_ms, fr->readback_ms, fr->encode_ms,
                fr->wait_ms, fr->bytes);
    }
    double fps = s->loop_s > 0 ? (double)s->frames / s->loop_s : 0.0;
    fprintf(out.f,
            "{\"summary\": true, \"format\": \"%s\", \"frames\": %lld, \"skipped\": %lld, "
            "\"threads\": %d, \"wall_s\": %.3f, \"fps\": %.3f, \"sim_s\": %.3f, \"render_s\": "
            "%.3f, \"readback_s\": %.3f, \"encode_s\": %.3f, \"encode_wait_s\": %.3f, "
            "\"peak_rss_kib\": %ld}\n",
            o->format == WW_OUT_NONE ? "none" : ww_out_format_ext(o->format),
            (long long)s->frames, (long long)s->skipped, j->threads, s->wall_s, fps, s->sim_s,
            s->render_s, s->readback_s, s->encode_s, s->encode_wait_s, s->peak_rss_kib);
    if (ferror(out.f)) {
        ww_stream_abort(&out);
        return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot write %s", o->stats_path);
    }
    return ww_stream_commit(&out, err);
}

/* ---- the render loop ----------------------------------------------------------------------- */

/* what an interrupted job says */
static ww_result interrupted(const job *j, int sig, ww_error *err) {
    const ww_job_opts *o = j->o;
    long long n = atomic_load(&j->written);
    const char *name = sig == SIGTERM ? "SIGTERM" : "SIGINT";
    if (!is_stream(o->format))
        return ww_error_set(err, WW_E_INTERRUPTED, NULL, 0, 0,
                            "interrupted by %s: %lld frames written to %s, none partial; run the "
                            "same command with --resume to render the rest",
                            name, n, o->format == WW_OUT_NONE ? "nowhere (--format none)" : o->out_dir);
    if (strcmp(o->out_dir, "-") == 0)
        return ww_error_set(err, WW_E_INTERRUPTED, NULL, 0, 0,
                            "interrupted by %s: the stream on stdout ends after %lld whole frames",
                            name, n);
    return ww_error_set(err, WW_E_INTERRUPTED, NULL, 0, 0,
                        "interrupted by %s after %lld frames: %s not written (a stream is kept "
                        "only whole); run the command again",
                        name, n, o->out_dir);
}

/* render frame f into a free slot and queue it */
static ww_result render_frame(job *j, int64_t f, double sim_s, ww_job_stats *s, ww_error *err) {
    const ww_job_opts *o = j->o;
    double a = ww_now_seconds();
    slot *sl = ww_queue_pop(&j->free_q);
    double b = ww_now_seconds();
    ww_result r = ww_render_frame(j->renderer, j->sc, j->st, err);
    if (r) {
        ww_queue_push(&j->free_q, sl);
        return r;
    }
    ww_renderer_finish(j->renderer);
    double c = ww_now_seconds();
    r = o->format == WW_OUT_EXR ? ww_renderer_read_hdr(j->renderer, &sl->img, err)
                                : ww_renderer_read_ldr(j->renderer, &sl->img, err);
    if (!r && o->alpha) r = ww_renderer_read_coverage(j->renderer, &sl->img, j->depth, err);
    double d = ww_now_seconds();
    if (r) {
        ww_queue_push(&j->free_q, sl);
        return r;
    }
    s->encode_wait_s += b - a;
    s->render_s += c - b;
    s->readback_s += d - c;
    if (f == o->first) s->first_render_s = c - b;
    if (j->recs) {
        frame_rec *fr = &j->recs[f - o->first];
        *fr = (frame_rec){.t = j->st->t, .sim_ms = 1e3 * sim_s, .render_ms = 1e3 * (c - b),
                          .readback_ms = 1e3 * (d - c), .wait_ms = 1e3 * (b - a)};
    }
    sl->frame = f;
    sl->t = j->st->t;
    ww_queue_push(&j->work_q, sl);
    return WW_OK;
}

static ww_result check_opts(const ww_job_opts *o, ww_error *err) {
    WW_ASSERT(o->first >= 0 && o->last > o->first);
    if (o->resume && o->format != WW_OUT_PNG && o->format != WW_OUT_EXR)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--resume needs frame files (--format png or exr), not %s",
                            o->format == WW_OUT_NONE ? "none" : ww_out_format_ext(o->format));
    if (o->alpha && o->format != WW_OUT_PNG && o->format != WW_OUT_EXR)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--alpha needs --format png or exr");

    /* every output, before anything is read, stepped or drawn: a folder named by --audio is
     * found now, not after the last frame */
    ww_result r = WW_OK;
    const char *stream = is_stream(o->format) ? o->out_dir : NULL;
    if (o->format == WW_OUT_PNG || o->format == WW_OUT_EXR) r = ww_check_out_dir("-o", o->out_dir, err);
    if (!r && stream) r = ww_check_out_file("-o", stream, 1, err);
    if (!r && o->stats_path) r = ww_check_out_file("--stats", o->stats_path, 1, err);
    if (!r && o->audio_path) r = ww_check_out_file("--audio", o->audio_path, 1, err);
    if (!r) r = ww_check_out_distinct("-o", stream, "--stats", o->stats_path, err);
    if (!r) r = ww_check_out_distinct("-o", stream, "--audio", o->audio_path, err);
    if (!r) r = ww_check_out_distinct("--stats", o->stats_path, "--audio", o->audio_path, err);
    return r;
}

/* the GL side and the state; the output (folder or stream) once nothing before it can fail */
static ww_result job_open(job *j, ww_job_stats *s, ww_error *err) {
    const ww_job_opts *o = j->o;
    double t0 = ww_now_seconds();
    ww_result r = ww_backend_open(o->backend, &j->backend, err);
    if (r) return r;
    snprintf(s->backend, sizeof s->backend, "%s", ww_backend_describe(j->backend));
    snprintf(s->renderer, sizeof s->renderer, "%s", ww_backend_renderer(j->backend));
    snprintf(s->gl_version, sizeof s->gl_version, "%s", ww_backend_version(j->backend));
    snprintf(j->renderer_name, sizeof j->renderer_name, "%s", s->renderer);
    if ((r = ww_renderer_for_scene(ww_backend_gl(j->backend), j->sc, o->width, o->height,
                                   &j->renderer, err)))
        return r;
    if (!(j->st = ww_state_new(j->sc)))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
    s->state_bytes = j->st->bytes;
    if ((r = pipeline_start(j, err))) return r;
    s->setup_s = ww_now_seconds() - t0;
    if (o->time_passes != WW_TIMING_OFF) ww_renderer_time_passes(j->renderer, o->time_passes);

    if (o->format == WW_OUT_PNG || o->format == WW_OUT_EXR) {
        if ((r = ww_make_dirs(o->out_dir, err))) return r;
        remove_stale_temps(o);
    } else if (is_stream(o->format)) {
        if ((r = ww_stream_open(&j->stream, o->out_dir, err))) return r;
        j->stream_open = 1;
        if (o->format == WW_OUT_Y4M) {
            char h[160];
            int n = ww_y4m_header(h, sizeof h, o->width, o->height, j->sc->fps, o->y4m_420);
            if (fwrite(h, 1, (size_t)n, j->stream.f) != (size_t)n)
                return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot write the Y4M header: %s",
                                    strerror(errno));
        }
    }
    return WW_OK;
}

/* frames [first, last): simulate each, render those not already on disk */
static ww_result job_loop(job *j, ww_job_stats *s, ww_error *err) {
    const ww_job_opts *o = j->o;
    const ww_scene *sc = j->sc;
    progress pg = {.on = o->progress == WW_PROGRESS_ON ||
                         (o->progress == WW_PROGRESS_AUTO && !o->quiet && isatty(2)),
                   .t0 = ww_now_seconds()};
    pg.last = pg.t0;
    long long total = o->last - o->first;
    ww_result r = WW_OK;
    for (int64_t f = o->first; f < o->last && !r; f++) {
        if (job_signal || atomic_load(&j->failed)) break;
        double a = ww_now_seconds();
        if ((r = advance(sc, j, f * sc->steps_per_frame, err))) break;
        double sim = ww_now_seconds() - a;
        s->sim_s += sim;
        if (o->resume && frame_done(o, f)) {
            s->skipped++;
            continue;
        }
        r = render_frame(j, f, sim, s, err);
        /* the first frame's pass times carry shader compilation: dropped, as bench does */
        if (!r && o->time_passes != WW_TIMING_OFF && f == o->first && total > 1)
            ww_renderer_pass_times(j->renderer, &s->passes);
        progress_show(&pg, atomic_load(&j->written) + s->skipped, total, 0);
    }
    pipeline_stop(j);
    s->frames = atomic_load(&j->written);
    s->encode_s = j->encode_s;
    if (!r || r == WW_E_INTERRUPTED) progress_show(&pg, s->frames + s->skipped, total, 1);
    progress_clear(&pg);
    if (o->time_passes != WW_TIMING_OFF && !r) ww_renderer_pass_times(j->renderer, &s->passes);
    s->loop_s = ww_now_seconds() - pg.t0;
    if (r) return r;
    if (atomic_load(&j->failed)) {
        *err = j->first_err;
        return j->first_r;
    }
    return WW_OK;
}

ww_result ww_job_run(const ww_scene *sc, const ww_job_opts *o, ww_job_stats *s, ww_error *err) {
    memset(s, 0, sizeof *s);
    double job_t0 = ww_now_seconds();
    ww_result r = check_opts(o, err);
    if (r) return r;
    job j = {.sc = sc, .o = o};
    atomic_init(&j.failed, 0);
    atomic_init(&j.written, 0);
    job_signals js;
    signals_install(&js);

    /* the sound track first: its files are the scene's input, and bad input leaves no folder */
    if (o->audio_path && (r = ww_audio_new(sc, o->first * sc->steps_per_frame,
                                           o->last * sc->steps_per_frame, &j.audio, err)))
        goto done;
    if ((r = job_open(&j, s, err))) goto done;
    /* the prefix is stepped, not rendered (and heard by the sound track, not kept) */
    double t0 = ww_now_seconds();
    if ((r = step_prefix(sc, &j, err))) goto done;
    s->prefix_s = ww_now_seconds() - t0;
    if ((r = job_loop(&j, s, err))) goto done;
    if (job_signal) {
        r = interrupted(&j, (int)job_signal, err);
        /* stdout ends at a frame boundary; a stream file is removed by job_close */
        if (j.stream_open && j.stream.is_stdout) fflush(stdout);
        goto done;
    }

    /* the track runs to the end of the slice's last frame */
    if (j.audio) {
        if ((r = advance(sc, &j, o->last * sc->steps_per_frame, err))) goto done;
        if ((r = ww_audio_write(j.audio, o->audio_path, err))) goto done;
    }
    if (j.stream_open) {
        j.stream_open = 0;
        if ((r = ww_stream_commit(&j.stream, err))) goto done;
    }

done:;
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) == 0) s->peak_rss_kib = ru.ru_maxrss;
    s->wall_s = ww_now_seconds() - job_t0;
    if (!r && o->stats_path) r = write_stats(&j, s, err);
    job_close(&j);
    signals_restore(&js);
    return r;
}
