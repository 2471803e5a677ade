/* bench.c - `waterworld bench render`: each render configuration runs in a child process (fork),
 * so its peak RSS is its own and a crashing driver cannot take the table down; the child reports
 * its timings through a pipe. Next to the frame's split (simulate / render / read back / encode)
 * it gives ms per pass (GL timer queries, renderer.c) and the render time against the backend's
 * fill floor, with the speed targets: the full world within 15x the floor at 1280x720, water and
 * sky within 3x; the frame rates (on a CPU rasteriser the lake at 1280x720 in 66 ms, the open sea
 * in 40; on a GPU the lake at 1920x1080 within 8x the floor); the reef within 1.5x the lake.
 * `bench sim` is in bench_sim.c, `bench quality` in bench_quality.c.
 */
#include "bench/bench.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/child.h"
#include "gfx/backend.h"
#include "gfx/renderer.h"
#include "io/json.h"
#include "render/job.h"
#include "scene/scene.h"

/* the speed targets for render / fill floor at 1280x720: a scene with solid objects (the lake's
 * full world) and one of water and sky only */
#define TARGET_FULL_WORLD_X 15.0
#define TARGET_WATER_SKY_X 3.0
#define TARGET_WIDTH 1280
#define TARGET_HEIGHT 720

/* the frame-rate targets. On a CPU rasteriser (where most users render: CI runners, laptops) a
 * scene at 1280x720 in at most cpu_ms a frame of render time; on a GPU the lake at 1920x1080
 * within GPU_LAKE_FLOOR_X times the backend's fill floor (a GPU's ms say little across GPUs, its
 * floor scales with it) */
static const struct {
    const char *scene;
    double cpu_ms;
} FRAME_TARGETS[] = {{"lake.yaml", 66.0}, {"demo.yaml", 40.0}};
#define GPU_TARGET_WIDTH 1920
#define GPU_TARGET_HEIGHT 1080
#define GPU_LAKE_FLOOR_X 8.0

typedef struct {
    int ok;
    ww_job_stats s;
    double floor_ms, gpu_floor_ms; /* the fill floor: wall with glFinish; GPU timer (-1: none) */
    int full_world; /* the scene has solid objects (the 15x target), else water and sky (3x) */
    char msg[sizeof(((ww_error *)0)->msg)];
} child_report;

static void child_run(const char *scene, const ww_set *sets, int nsets, ww_backend_kind kind,
                      int w, int h, int frames, const char *dir, child_report *rep) {
    ww_error err = {0};
    ww_scene *sc = NULL;
    if (ww_scene_load(scene, sets, nsets, &sc, &err) != WW_OK) {
        snprintf(rep->msg, sizeof rep->msg, "%s", err.msg);
        return;
    }
    ww_job_opts o = ww_default_job_opts();
    o.backend = kind;
    o.width = w;
    o.height = h;
    o.first = 0;
    o.last = frames < sc->frame_count ? frames : sc->frame_count;
    o.out_dir = dir;
    o.quiet = 1;
    o.time_passes = WW_TIMING_AUTO;
    rep->full_world = ww_scene_has_objects(sc);
    ww_result r = ww_job_run(sc, &o, &rep->s, &err);
    ww_scene_free(sc);
    if (r != WW_OK) {
        snprintf(rep->msg, sizeof rep->msg, "%s", err.msg);
        return;
    }
    ww_backend *b = NULL;
    if (ww_backend_open(kind, &b, &err) == WW_OK) {
        if (ww_gfx_fill_floor(ww_backend_gl(b), w, h, &rep->floor_ms, &rep->gpu_floor_ms, &err) !=
            WW_OK)
            rep->floor_ms = rep->gpu_floor_ms = -1;
        ww_backend_close(b);
    }
    rep->ok = 1;
}

/* one configuration of bench render */
typedef struct config {
    const char *scene, *dir;
    const ww_set *sets;
    int nsets;
    ww_backend_kind kind;
    int w, h, frames;
} config;

static void config_run(const void *ctx, void *report) {
    const config *c = ctx;
    child_run(c->scene, c->sets, c->nsets, c->kind, c->w, c->h, c->frames, c->dir, report);
}

/* run one configuration in a child; returns its peak RSS in KiB (or -1) */
static long run_config(const char *scene, const ww_set *sets, int nsets, ww_backend_kind kind,
                       int w, int h, int frames, const char *dir, child_report *rep) {
    config c = {.scene = scene, .dir = dir, .sets = sets, .nsets = nsets, .kind = kind, .w = w,
                .h = h, .frames = frames};
    ww_child_end end;
    if (ww_child_run(config_run, &c, rep, sizeof *rep, &end) == WW_CHILD_DIED)
        snprintf(rep->msg, sizeof rep->msg, "benchmark child died (status %d)",
                 end.status ? end.status : -1);
    return end.max_rss_kib;
}

static const char *base_name(const char *path) {
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* the speed target a configuration is held to (render time over the fill floor), or 0 at sizes
 * other than the targets' 1280x720 */
static double target_x(const child_report *rep, int w, int h) {
    if (w != TARGET_WIDTH || h != TARGET_HEIGHT) return 0.0;
    return rep->full_world ? TARGET_FULL_WORLD_X : TARGET_WATER_SKY_X;
}

/* one configuration's figures, ms per frame after the first */
typedef struct {
    double sim, ren, rb, enc, tot, first, fps, x, target;
} row_figures;

static row_figures figures(const child_report *rep, int w, int h) {
    row_figures f;
    double n = (double)(rep->s.frames > 0 ? rep->s.frames : 1);
    /* the first frame pays for llvmpipe's shader compilation: reported apart */
    double nr = n > 1 ? n - 1 : 1;
    f.first = 1e3 * rep->s.first_render_s;
    f.sim = 1e3 * rep->s.sim_s / n;
    f.ren = (1e3 * rep->s.render_s - (n > 1 ? f.first : 0)) / nr;
    f.rb = 1e3 * rep->s.readback_s / n;
    f.enc = 1e3 * rep->s.encode_s / n;
    f.tot = f.sim + f.ren + f.rb + f.enc;
    f.fps = f.ren > 0 ? 1e3 / f.ren : 0.0;
    f.x = rep->floor_ms > 0 ? f.ren / rep->floor_ms : 0.0;
    f.target = target_x(rep, w, h);
    return f;
}

/* a frame-rate target's row: on a CPU rasteriser render ms against ms, on a GPU render / floor
 * against its multiple */
typedef struct {
    const char *backend, *scene;
    int w, h, cpu;
    double value, target;
} frame_row;

/* a CPU rasteriser: Mesa's llvmpipe or softpipe (GL_RENDERER names them), not a GPU */
static int cpu_rasteriser(const char *renderer) {
    return strstr(renderer, "llvmpipe") || strstr(renderer, "softpipe");
}

/* the frame-rate target of a configuration: 1 with its row filled, 0 where none applies */
static int frame_target(const char *backend, const char *scene, int w, int h,
                        const child_report *rep, const row_figures *f, frame_row *out) {
    if (cpu_rasteriser(rep->s.renderer)) {
        if (w != TARGET_WIDTH || h != TARGET_HEIGHT) return 0;
        for (size_t i = 0; i < sizeof FRAME_TARGETS / sizeof FRAME_TARGETS[0]; i++)
            if (strcmp(scene, FRAME_TARGETS[i].scene) == 0) {
                *out = (frame_row){backend, scene, w, h, 1, f->ren, FRAME_TARGETS[i].cpu_ms};
                return 1;
            }
        return 0;
    }
    if (w != GPU_TARGET_WIDTH || h != GPU_TARGET_HEIGHT || strcmp(scene, "lake.yaml") != 0)
        return 0;
    *out = (frame_row){backend, scene, w, h, 0, f->x, GPU_LAKE_FLOOR_X};
    return 1;
}

static int frame_met(const frame_row *r) { return r->value > 0 && r->value <= r->target; }

/* note: what the figure was measured with when not the scene as written ("" when it is) */
static void print_frame_row(FILE *to, const frame_row *r, const char *note) {
    char sz[16];
    snprintf(sz, sizeof sz, "%dx%d", r->w, r->h);
    if (r->cpu)
        fprintf(to, "  %-7s %-15s %-9s CPU  render %6.1f ms (%4.1f fps)  target <= %4.1f ms "
                    "(%2.0f fps)  %s%s\n",
                r->backend, r->scene, sz, r->value, r->value > 0 ? 1e3 / r->value : 0.0,
                r->target, 1e3 / r->target, frame_met(r) ? "met" : "missed", note);
    else
        fprintf(to, "  %-7s %-15s %-9s GPU  render / floor x %6.1f  target <= %4.1f  %s%s\n",
                r->backend, r->scene, sz, r->value, r->target, frame_met(r) ? "met" : "missed",
                note);
}

/* the --set overrides as a JSON array of strings */
static void print_json_sets(FILE *to, const ww_set *sets, int nsets) {
    fputs("\"sets\":[", to);
    for (int i = 0; i < nsets; i++) {
        if (i) fputc(',', to);
        ww_json_string(to, sets[i].text);
    }
    fputs("],", to);
}

static void print_json_row(FILE *to, const char *backend, const char *scene, int w, int h,
                           const child_report *rep, const row_figures *f, const frame_row *fr,
                           long rss, const ww_bench_opts *o) {
    const ww_pass_times *pt = &rep->s.passes;
    fprintf(to, "{\"backend\":\"%s\",\"device\":", backend);
    ww_json_string(to, rep->s.backend);
    fputs(",\"renderer\":", to);
    ww_json_string(to, rep->s.renderer);
    fputs(",\"scene\":", to);
    ww_json_string(to, scene);
    fprintf(to,
            ",\"width\":%d,\"height\":%d,\"frames\":%lld,\"sim_ms\":%.4f,\"render_ms\":%.4f,"
            "\"readback_ms\":%.4f,\"encode_ms\":%.4f,\"total_ms\":%.4f,\"first_render_ms\":%.4f,"
            "\"fps\":%.3f,\"floor_ms\":%.4f,\"gpu_floor_ms\":%.4f,\"floor_x\":%.3f,",
            w, h, (long long)rep->s.frames, f->sim, f->ren, f->rb, f->enc, f->tot, f->first, f->fps,
            rep->floor_ms, rep->gpu_floor_ms, f->x);
    if (o->nsets > 0) print_json_sets(to, o->sets, o->nsets);
    if (f->target > 0)
        fprintf(to, "\"target_x\":%.1f,\"target_met\":%s,", f->target,
                f->x > 0 && f->x <= f->target ? "true" : "false");
    if (fr && fr->cpu)
        fprintf(to, "\"frame_target_ms\":%.1f,\"frame_target_met\":%s,", fr->target,
                frame_met(fr) ? "true" : "false");
    else if (fr)
        fprintf(to, "\"gpu_target_x\":%.1f,\"gpu_target_met\":%s,", fr->target,
                frame_met(fr) ? "true" : "false");
    fprintf(to, "\"pass_timer\":\"%s\",\"passes\":[", ww_timing_name(pt->mode));
    for (int i = 0; i < pt->npasses; i++)
        fprintf(to, "%s{\"name\":\"%s\",\"ms\":%.4f}", i ? "," : "", pt->name[i],
                pt->frames > 0 ? pt->ms[i] / pt->frames : 0.0);
    fprintf(to, "],\"peak_rss_kib\":%ld,\"state_bytes\":%zu}\n", rss, rep->s.state_bytes);
}

/* the pass line under a table row: ms per pass, their sum and what measured them */
static void print_passes(FILE *to, const ww_pass_times *pt, double gpu_floor_ms) {
    double sum = 0.0;
    fputs("        passes:", to);
    for (int i = 0; i < pt->npasses; i++) {
        double ms = pt->frames > 0 ? pt->ms[i] / pt->frames : 0.0;
        sum += ms;
        fprintf(to, " %s %.3f", pt->name[i], ms);
    }
    fprintf(to, "; sum %.3f ms (%s, %d frames)", sum, ww_timing_name(pt->mode), pt->frames);
    if (gpu_floor_ms > 0) fprintf(to, "; floor by timer %.3f ms", gpu_floor_ms);
    fputc('\n', to);
}

typedef struct {
    const char *backend, *scene;
    int full_world;
    double x, target;
} target_row;

/* the reef against the lake, each backend at the targets' size: the reef (models, shadow
 * volumes, the lantern's glow, caustics) should cost at most REEF_OVER_LAKE times the lake
 * there (at small sizes its fixed costs, the volumes and the vertices, weigh more) */
#define REEF_OVER_LAKE 1.5
typedef struct {
    int kind, w, h;
    int scene; /* 0 lake, 1 reef */
    double ms;
} ratio_row;

static int lake_or_reef(const char *base) {
    return strcmp(base, "lake.yaml") == 0 ? 0 : strcmp(base, "reef.yaml") == 0 ? 1 : -1;
}

static void print_reef_ratio(FILE *to, const ratio_row *r, int n, const char *const *kind_names,
                             int nkinds, const char *note) {
    for (int k = 0; k < nkinds; k++) {
        const ratio_row *lake = NULL, *reef = NULL;
        for (int i = 0; i < n; i++)
            if (r[i].kind == k && r[i].w == TARGET_WIDTH && r[i].h == TARGET_HEIGHT) {
                if (r[i].scene == 0) lake = &r[i];
                else reef = &r[i];
            }
        if (lake && reef && lake->ms > 0.0)
            fprintf(to, "  %-7s reef / lake     render %.2fx (%.1f / %.1f ms)  target <= %.1f  %s%s\n",
                    kind_names[k], reef->ms / lake->ms, reef->ms, lake->ms, REEF_OVER_LAKE,
                    reef->ms <= REEF_OVER_LAKE * lake->ms ? "met" : "missed", note);
    }
}

ww_result ww_bench_render(const ww_bench_opts *o, FILE *to, ww_error *err) {
    static const char *const default_scenes[] = {"scenes/demo.yaml", "scenes/lake.yaml",
                                                 "scenes/reef.yaml", NULL};
    int sizes[2][2] = {{256, 144}, {1280, 720}};
    size_t nsizes = 2;
    if (o->width > 0) {
        sizes[0][0] = o->width;
        sizes[0][1] = o->height;
        nsizes = 1;
    }
    static const struct { const char *name; ww_backend_kind kind; } kinds[] = {
        {"egl", WW_BACKEND_EGL}, {"osmesa", WW_BACKEND_OSMESA}};
    enum { NKINDS = sizeof kinds / sizeof kinds[0] };
    const char *const *scenes = o->scenes[0] ? o->scenes : default_scenes;
    int frames = o->frames > 0 ? o->frames : 20;
    char dir[128];
    snprintf(dir, sizeof dir, "/tmp/waterworld-bench.%ld", (long)getpid());
    target_row targets[NKINDS * 4];
    int ntargets = 0;
    frame_row frows[NKINDS * 4];
    int nframes = 0;
    ratio_row ratios[NKINDS * 8];
    int nratios = 0;

    /* overrides that do not load are bad input, named before any configuration runs */
    for (int s = 0; o->nsets > 0 && scenes[s]; s++) {
        ww_scene *sc = NULL;
        ww_result r = ww_scene_load(scenes[s], o->sets, o->nsets, &sc, err);
        ww_scene_free(sc);
        if (r != WW_OK) return r;
    }
    if (!o->json && o->nsets > 0) {
        fputs("every scene with", to);
        for (int i = 0; i < o->nsets; i++) fprintf(to, " --set %s", o->sets[i].text);
        fputc('\n', to);
    }
    if (!o->json)
        fprintf(to, "%-7s %-15s %-9s %6s | %8s %8s %8s %8s %8s | %8s %8s %6s %7s | %8s %8s\n", "backend",
                "scene", "size", "frames", "sim", "render", "readback", "encode", "total", "1st rend", "floor",
                "x", "fps", "rss MiB", "state B");
    int any = 0;
    for (size_t k = 0; k < NKINDS; k++) {
        for (int s = 0; scenes[s]; s++) {
            for (size_t z = 0; z < nsizes; z++) {
                int w = sizes[z][0], h = sizes[z][1];
                child_report rep;
                long rss = run_config(scenes[s], o->sets, o->nsets, kinds[k].kind, w, h, frames,
                                      dir, &rep);
                char cmdline[200];
                snprintf(cmdline, sizeof cmdline, "rm -rf '%s'", dir);
                if (system(cmdline) != 0) { /* best effort: the folder is in /tmp */ }
                if (!rep.ok) {
                    if (o->json) {
                        fprintf(to, "{\"backend\":\"%s\",\"scene\":", kinds[k].name);
                        ww_json_string(to, base_name(scenes[s]));
                        fputs(",\"error\":", to);
                        ww_json_string(to, rep.msg);
                        fputs("}\n", to);
                    } else {
                        fprintf(to, "%-7s %-15s unavailable: %s\n", kinds[k].name, base_name(scenes[s]), rep.msg);
                    }
                    continue;
                }
                any = 1;
                row_figures f = figures(&rep, w, h);
                int lr = lake_or_reef(base_name(scenes[s]));
                if (lr >= 0 && nratios < (int)(sizeof ratios / sizeof ratios[0]))
                    ratios[nratios++] = (ratio_row){(int)k, w, h, lr, f.ren};
                if (f.target > 0 && ntargets < (int)(sizeof targets / sizeof targets[0]))
                    targets[ntargets++] = (target_row){kinds[k].name, base_name(scenes[s]),
                                                       rep.full_world, f.x, f.target};
                frame_row fr;
                int has_fr = frame_target(kinds[k].name, base_name(scenes[s]), w, h, &rep, &f, &fr);
                if (has_fr && nframes < (int)(sizeof frows / sizeof frows[0]))
                    frows[nframes++] = fr;
                if (o->json) {
                    print_json_row(to, kinds[k].name, base_name(scenes[s]), w, h, &rep, &f,
                                   has_fr ? &fr : NULL, rss, o);
                } else {
                    char sz[16];
                    snprintf(sz, sizeof sz, "%dx%d", w, h);
                    fprintf(to, "%-7s %-15s %-9s %6lld | %8.3f %8.3f %8.3f %8.3f %8.3f | %8.1f %8.3f %6.1f %7.1f | %8.1f %8zu\n",
                            kinds[k].name, base_name(scenes[s]), sz, (long long)rep.s.frames, f.sim, f.ren, f.rb,
                            f.enc, f.tot, f.first, rep.floor_ms, f.x, f.fps, (double)rss / 1024.0,
                            rep.s.state_bytes);
                    print_passes(to, &rep.s.passes, rep.gpu_floor_ms);
                }
                fflush(to);
            }
        }
    }
    if (!o->json) {
        fprintf(to, "ms per frame after the first (1st rend: the first frame's render, with shader compilation);\n"
                    "floor: one trivial full-screen pass into RGBA16F at the same size;\n"
                    "x: render / floor; fps: 1000 / render (render only); rss: peak resident memory of\n"
                    "the whole render process; passes: ms per pass in plan order\n");
        if (ntargets > 0 || nframes > 0)
            fprintf(to, "\ntargets (render / floor at %dx%d; frame rates; the reef against the "
                        "lake)\n", TARGET_WIDTH, TARGET_HEIGHT);
        /* the targets are the scenes' as written; measured with overrides, the rows say so */
        const char *note = o->nsets > 0 ? " (with --set)" : "";
        for (int i = 0; i < ntargets; i++) {
            const target_row *t = &targets[i];
            fprintf(to, "  %-7s %-15s %-14s x %6.1f  target <= %4.1f  %s%s\n", t->backend, t->scene,
                    t->full_world ? "full world" : "water and sky", t->x, t->target,
                    t->x > 0 && t->x <= t->target ? "met" : "missed", note);
        }
        for (int i = 0; i < nframes; i++) print_frame_row(to, &frows[i], note);
        const char *kind_names[NKINDS];
        for (size_t k = 0; k < NKINDS; k++) kind_names[k] = kinds[k].name;
        print_reef_ratio(to, ratios, nratios, kind_names, NKINDS, note);
    }
    if (!any) return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0, "no configuration could run");
    return WW_OK;
}

ww_result ww_bench_render_once(const char *scene, int width, int height, int frames,
                               ww_job_stats *stats, ww_error *err) {
    char dir[128];
    snprintf(dir, sizeof dir, "/tmp/waterworld-bench.%ld", (long)getpid());
    child_report rep;
    run_config(scene, NULL, 0, WW_BACKEND_AUTO, width, height, frames, dir, &rep);
    char cmdline[200];
    snprintf(cmdline, sizeof cmdline, "rm -rf '%s'", dir);
    if (system(cmdline) != 0) { /* best effort: the folder is in /tmp */ }
    if (!rep.ok) return ww_error_set(err, WW_E_BACKEND, scene, 0, 0, "%s", rep.msg);
    *stats = rep.s;
    return WW_OK;
}
