/* bench_output.c - `waterworld bench output`: frames per second of scenes/demo.yaml at 1280x720
 * written as none, PNG, EXR and Y4M, in one run, against the target (PNG at >= 0.85x the
 * rate of `none`: encoding hidden behind rendering), and the peak resident memory of a short and
 * a long PNG run (the frame queue is bounded, so memory stays flat however many frames).
 * Each configuration runs in its own child process (fork): its peak RSS is its own, not the
 * high-water mark of the configurations before it, and every format starts with the same cold
 * caches and a fresh GL context.
 */
#include "bench/bench.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/child.h"
#include "render/job.h"
#include "scene/scene.h"

/* the target: PNG frames at >= 0.85x the frames per second of rendering without writing */
#define TARGET_PNG_OVER_NONE 0.85
#define BENCH_W 1280
#define BENCH_H 720
#define TINY_W 256
#define TINY_H 144
#define DEFAULT_FRAMES 60
#define TINY_FRAMES 4
/* the memory check: peak RSS after RSS_SHORT frames against after RSS_LONG frames */
#define RSS_SHORT 30
#define RSS_LONG 300
/* growth of the long run's peak over the short run's below which memory counts as flat */
#define RSS_FLAT_FRACTION 0.05

typedef struct out_report {
    int ok;
    ww_job_stats s;
    char msg[sizeof(((ww_error *)0)->msg)];
} out_report;

static void child_run(const char *scene, ww_out_format fmt, int w, int h, int frames,
                      const char *dir, out_report *rep) {
    ww_error err = {0};
    ww_scene *sc = NULL;
    if (ww_scene_load(scene, NULL, 0, &sc, &err) != WW_OK) {
        snprintf(rep->msg, sizeof rep->msg, "%s", err.msg);
        return;
    }
    char path[256];
    snprintf(path, sizeof path, "%s/%s%s", dir, fmt == WW_OUT_NONE ? "none" : ww_out_format_ext(fmt),
             fmt == WW_OUT_Y4M ? ".y4m" : "");
    ww_job_opts o = ww_default_job_opts();
    o.format = fmt;
    o.width = w;
    o.height = h;
    o.first = 0;
    /* the scene is played on past its end if more frames are asked for than it lasts */
    o.last = frames;
    o.out_dir = path;
    o.quiet = 1;
    ww_result r = ww_job_run(sc, &o, &rep->s, &err);
    ww_scene_free(sc);
    if (r != WW_OK) {
        snprintf(rep->msg, sizeof rep->msg, "%s", err.msg);
        return;
    }
    rep->ok = 1;
}

/* one configuration of bench output */
typedef struct config {
    const char *scene, *dir;
    ww_out_format fmt;
    int w, h, frames;
} config;

static void config_run(const void *ctx, void *report) {
    const config *c = ctx;
    child_run(c->scene, c->fmt, c->w, c->h, c->frames, c->dir, report);
}

/* one configuration in a child process; its peak RSS (KiB), -1 on failure */
static long run_child(const char *scene, ww_out_format fmt, int w, int h, int frames,
                      const char *dir, out_report *rep) {
    config c = {.scene = scene, .dir = dir, .fmt = fmt, .w = w, .h = h, .frames = frames};
    ww_child_end end;
    if (ww_child_run(config_run, &c, rep, sizeof *rep, &end) == WW_CHILD_DIED)
        snprintf(rep->msg, sizeof rep->msg, "benchmark child died (status %d)",
                 end.status ? end.status : -1);
    return end.max_rss_kib;
}

/* frames per second after the first frame, whose render pays for llvmpipe's shader compilation
 * (the same for every format, so it would only dilute the differences) */
static double fps_of(const ww_job_stats *s) {
    double t = s->loop_s - s->first_render_s;
    return s->frames > 1 && t > 0 ? (double)(s->frames - 1) / t : 0.0;
}

static void print_row(FILE *to, int json, const char *name, const out_report *rep, long rss) {
    const ww_job_stats *s = &rep->s;
    double n = (double)(s->frames > 0 ? s->frames : 1);
    if (json) {
        fprintf(to,
                "{\"bench\": \"output\", \"format\": \"%s\", \"frames\": %lld, \"fps\": %.3f, "
                "\"render_ms\": %.3f, \"readback_ms\": %.3f, \"encode_ms\": %.3f, "
                "\"encode_wait_ms\": %.3f, \"peak_rss_kib\": %ld}\n",
                name, (long long)s->frames, fps_of(s), 1e3 * s->render_s / n,
                1e3 * s->readback_s / n, 1e3 * s->encode_s / n, 1e3 * s->encode_wait_s / n, rss);
        return;
    }
    fprintf(to, "%-6s %8.2f %10.2f %10.2f %10.2f %10.2f %10.1f\n", name, fps_of(s),
            1e3 * s->render_s / n, 1e3 * s->readback_s / n, 1e3 * s->encode_s / n,
            1e3 * s->encode_wait_s / n, (double)rss / 1024.0);
}

ww_result ww_bench_output(const ww_bench_opts *o, FILE *to, ww_error *err) {
    const char *scene = o->scenes[0] ? o->scenes[0] : "scenes/demo.yaml";
    int w = o->tiny ? TINY_W : BENCH_W, h = o->tiny ? TINY_H : BENCH_H;
    int frames = o->frames > 0 ? o->frames : o->tiny ? TINY_FRAMES : DEFAULT_FRAMES;
    int rss_short = o->tiny ? TINY_FRAMES : RSS_SHORT, rss_long = o->tiny ? 2 * TINY_FRAMES : RSS_LONG;
    char dir[128];
    snprintf(dir, sizeof dir, "/tmp/waterworld-bench-output.%ld", (long)getpid());

    static const ww_out_format fmts[4] = {WW_OUT_NONE, WW_OUT_PNG, WW_OUT_EXR, WW_OUT_Y4M};
    static const char *const names[4] = {"none", "png", "exr", "y4m"};
    out_report rep[4], shortr, longr;
    long rss[4], rs = -1, rl = -1;
    ww_result r = WW_OK;
    for (int i = 0; i < 4 && !r; i++) {
        rss[i] = run_child(scene, fmts[i], w, h, frames, dir, &rep[i]);
        if (!rep[i].ok) r = ww_error_set(err, WW_E_BACKEND, scene, 0, 0, "%s", rep[i].msg);
    }
    if (!r) {
        rs = run_child(scene, WW_OUT_PNG, w, h, rss_short, dir, &shortr);
        rl = run_child(scene, WW_OUT_PNG, w, h, rss_long, dir, &longr);
        if (!shortr.ok || !longr.ok)
            r = ww_error_set(err, WW_E_BACKEND, scene, 0, 0, "%s", !shortr.ok ? shortr.msg : longr.msg);
    }
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) { /* best effort: the folder is in /tmp */ }
    if (r) return r;

    double ratio = fps_of(&rep[0].s) > 0 ? fps_of(&rep[1].s) / fps_of(&rep[0].s) : 0.0;
    double growth = rs > 0 ? (double)(rl - rs) / (double)rs : 0.0;
    if (!o->json) {
        fprintf(to, "bench output: %s at %dx%d, %d frames per format, each in its own process\n",
                scene, w, h, frames);
        fprintf(to, "backend %s, %s\n", rep[0].s.backend, rep[0].s.renderer);
        fprintf(to, "%-6s %8s %10s %10s %10s %10s %10s\n", "format", "fps", "render ms",
                "readback", "encode ms", "wait ms", "peak MiB");
    }
    for (int i = 0; i < 4; i++) print_row(to, o->json, names[i], &rep[i], rss[i]);
    int met = ratio >= TARGET_PNG_OVER_NONE, flat = growth <= RSS_FLAT_FRACTION;
    if (o->json) {
        fprintf(to,
                "{\"bench\": \"output\", \"png_over_none\": %.3f, \"target\": %.2f, \"met\": %s, "
                "\"rss_short_frames\": %d, \"rss_short_kib\": %ld, \"rss_long_frames\": %d, "
                "\"rss_long_kib\": %ld, \"rss_growth\": %.4f, \"flat\": %s}\n",
                ratio, TARGET_PNG_OVER_NONE, met ? "true" : "false", rss_short, rs, rss_long, rl,
                growth, flat ? "true" : "false");
        return WW_OK;
    }
    fprintf(to, "encode ms: summed over the encoder threads (hidden when fps keeps up with none); "
                "wait ms: the render thread waiting for a free slot\n");
    fprintf(to, "png / none: %.3f (target >= %.2f: %s)\n", ratio, TARGET_PNG_OVER_NONE,
            met ? "met" : "not met");
    fprintf(to, "peak RSS, png: %d frames %.1f MiB, %d frames %.1f MiB (%+.1f%%: %s)\n", rss_short,
            (double)rs / 1024.0, rss_long, (double)rl / 1024.0, 100.0 * growth,
            flat ? "flat, the queue is bounded" : "grows");
    return WW_OK;
}
