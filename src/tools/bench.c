/* bench.c - `waterworld bench`: each render configuration runs in a child process (fork), so its
 * peak RSS is its own and a crashing driver cannot take the table down; the child reports its
 * timings through a pipe. `bench sim` is in bench_sim.c.
 */
#include "tools/bench.h"

#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gfx/backend.h"
#include "gfx/renderer.h"
#include "scene/scene.h"
#include "tools/job.h"

typedef struct {
    int ok;
    ww_job_stats s;
    double floor_ms;
    char msg[sizeof(((ww_error *)0)->msg)];
} child_report;

static void child_run(const char *scene, ww_backend_kind kind, int w, int h, int frames,
                      const char *dir, child_report *rep) {
    ww_error err = {0};
    ww_scene *sc = NULL;
    if (ww_scene_load(scene, NULL, 0, &sc, &err) != WW_OK) {
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
    ww_result r = ww_job_run(sc, &o, &rep->s, &err);
    ww_scene_free(sc);
    if (r != WW_OK) {
        snprintf(rep->msg, sizeof rep->msg, "%s", err.msg);
        return;
    }
    ww_backend *b = NULL;
    if (ww_backend_open(kind, &b, &err) == WW_OK) {
        if (ww_gfx_fill_floor(ww_backend_gl(b), w, h, &rep->floor_ms, &err) != WW_OK)
            rep->floor_ms = -1;
        ww_backend_close(b);
    }
    rep->ok = 1;
}

/* run one configuration in a child; returns its peak RSS in KiB (or -1) */
static long run_config(const char *scene, ww_backend_kind kind, int w, int h, int frames,
                       const char *dir, child_report *rep) {
    int fd[2];
    memset(rep, 0, sizeof *rep);
    if (pipe(fd) != 0) return -1;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        child_report mine = {0};
        child_run(scene, kind, w, h, frames, dir, &mine);
        ssize_t n = write(fd[1], &mine, sizeof mine);
        _exit(n == (ssize_t)sizeof mine ? 0 : 1);
    }
    close(fd[1]);
    ssize_t got = pid > 0 ? read(fd[0], rep, sizeof *rep) : -1;
    close(fd[0]);
    int status = 0;
    struct rusage ru;
    if (pid < 0 || wait4(pid, &status, 0, &ru) < 0) return -1;
    if (got != (ssize_t)sizeof *rep) {
        memset(rep, 0, sizeof *rep);
        snprintf(rep->msg, sizeof rep->msg, "benchmark child died (status %d)", status);
    }
    return ru.ru_maxrss;
}

static const char *base_name(const char *path) {
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

ww_result ww_bench_render(const ww_bench_opts *o, FILE *to, ww_error *err) {
    static const char *const default_scenes[] = {"scenes/minimal.yaml", "scenes/demo.yaml", NULL};
    static const int sizes[][2] = {{256, 144}, {1280, 720}};
    static const struct { const char *name; ww_backend_kind kind; } kinds[] = {
        {"egl", WW_BACKEND_EGL}, {"osmesa", WW_BACKEND_OSMESA}};
    const char *const *scenes = o->scenes[0] ? o->scenes : default_scenes;
    int frames = o->frames > 0 ? o->frames : 20;
    char dir[128];
    snprintf(dir, sizeof dir, "/tmp/waterworld-bench.%ld", (long)getpid());

    if (!o->json)
        fprintf(to, "%-7s %-13s %-9s %6s | %8s %8s %8s %8s %8s | %8s %8s %6s | %8s %8s\n", "backend",
                "scene", "size", "frames", "sim", "render", "readback", "encode", "total", "1st rend", "floor",
                "x", "rss MiB", "state B");
    int any = 0;
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        for (int s = 0; scenes[s]; s++) {
            for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
                child_report rep;
                long rss = run_config(scenes[s], kinds[k].kind, sizes[z][0], sizes[z][1], frames, dir, &rep);
                char cmdline[200];
                snprintf(cmdline, sizeof cmdline, "rm -rf '%s'", dir);
                if (system(cmdline) != 0) { /* best effort: the folder is in /tmp */ }
                if (!rep.ok) {
                    if (o->json)
                        fprintf(to, "{\"backend\":\"%s\",\"scene\":\"%s\",\"error\":\"%s\"}\n",
                                kinds[k].name, base_name(scenes[s]), rep.msg);
                    else
                        fprintf(to, "%-7s %-13s unavailable: %s\n", kinds[k].name, base_name(scenes[s]), rep.msg);
                    continue;
                }
                any = 1;
                double n = (double)(rep.s.frames > 0 ? rep.s.frames : 1);
                /* the first frame pays for llvmpipe's shader compilation: reported apart */
                double nr = n > 1 ? n - 1 : 1, first = 1e3 * rep.s.first_render_s;
                double sim = 1e3 * rep.s.sim_s / n, ren = (1e3 * rep.s.render_s - (n > 1 ? first : 0)) / nr;
                double rb = 1e3 * rep.s.readback_s / n, enc = 1e3 * rep.s.encode_s / n;
                double tot = sim + ren + rb + enc;
                if (o->json) {
                    fprintf(to,
                            "{\"backend\":\"%s\",\"device\":\"%s\",\"renderer\":\"%s\",\"scene\":\"%s\","
                            "\"width\":%d,\"height\":%d,\"frames\":%lld,\"sim_ms\":%.4f,\"render_ms\":%.4f,"
                            "\"readback_ms\":%.4f,\"encode_ms\":%.4f,\"total_ms\":%.4f,\"first_render_ms\":%.4f,\"floor_ms\":%.4f,"
                            "\"peak_rss_kib\":%ld,\"state_bytes\":%zu}\n",
                            kinds[k].name, rep.s.backend, rep.s.renderer, base_name(scenes[s]), sizes[z][0],
                            sizes[z][1], (long long)rep.s.frames, sim, ren, rb, enc, tot, first, rep.floor_ms, rss,
                            rep.s.state_bytes);
                } else {
                    char sz[16];
                    snprintf(sz, sizeof sz, "%dx%d", sizes[z][0], sizes[z][1]);
                    fprintf(to, "%-7s %-13s %-9s %6lld | %8.3f %8.3f %8.3f %8.3f %8.3f | %8.1f %8.3f %6.1f | %8.1f %8zu\n",
                            kinds[k].name, base_name(scenes[s]), sz, (long long)rep.s.frames, sim, ren, rb, enc,
                            tot, first, rep.floor_ms, rep.floor_ms > 0 ? ren / rep.floor_ms : 0.0,
                            (double)rss / 1024.0, rep.s.state_bytes);
                }
                fflush(to);
            }
        }
    }
    if (!o->json)
        fprintf(to, "ms per frame after the first (1st rend: the first frame's render, with shader compilation);\n"
                    "floor: one trivial full-screen pass into RGBA16F at the same size;\n"
                    "x: render / floor; rss: peak resident memory of the whole render process\n");
    if (!any) return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0, "no configuration could run");
    return WW_OK;
}

ww_result ww_bench_render_once(const char *scene, int width, int height, int frames,
                               ww_job_stats *stats, ww_error *err) {
    char dir[128];
    snprintf(dir, sizeof dir, "/tmp/waterworld-bench.%ld", (long)getpid());
    child_report rep;
    run_config(scene, WW_BACKEND_AUTO, width, height, frames, dir, &rep);
    char cmdline[200];
    snprintf(cmdline, sizeof cmdline, "rm -rf '%s'", dir);
    if (system(cmdline) != 0) { /* best effort: the folder is in /tmp */ }
    if (!rep.ok) return ww_error_set(err, WW_E_BACKEND, scene, 0, 0, "%s", rep.msg);
    *stats = rep.s;
    return WW_OK;
}
