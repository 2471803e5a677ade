/* bench_compare.c - `waterworld bench compare`: ms to compare a 1280x720 PNG pair (two rendered
 * frames of scenes/demo.yaml), ours next to ImageMagick's RMSE over R, G, B on the same pair in
 * the same run (IM 7's `magick compare -channel RGB -metric RMSE`, else IM 6's `compare` with the
 * same options), both timed by wall clock (processes by fork/exec). Printed, never asserted.
 */
#include "bench/bench.h"

#include <fcntl.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check/compare.h"

#define DEFAULT_REPEATS 7
#define DEFAULT_W 1280
#define DEFAULT_H 720
#define SELF "/proc/self/exe"
#define TARGET_RATIO 5.0 /* the target: at least 5x faster than ImageMagick */

extern char **environ;

/* run argv with stdout and stderr to /dev/null; its exit status, or -1 */
static int run_quiet(char *const argv[]) {
    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa) != 0) return -1;
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid;
    int rc = posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) return -1;
    int st;
    if (waitpid(pid, &st, 0) != pid || !WIFEXITED(st)) return -1;
    return WEXITSTATUS(st);
}

static int cmp_double(const void *x, const void *y) {
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* best and median of n timings, ms */
typedef struct timing { double best, median; } timing;

static timing summarise(double *ms, int n) {
    qsort(ms, (size_t)n, sizeof *ms, cmp_double);
    return (timing){ms[0], ms[n / 2]};
}

/* wall ms of a process, n times; -1 when it could not run (exit status above 1) */
static int time_process(char *const argv[], int n, timing *t) {
    double ms[64];
    for (int i = 0; i < n; i++) {
        double t0 = ww_now_seconds();
        int rc = run_quiet(argv);
        ms[i] = 1e3 * (ww_now_seconds() - t0);
        if (rc < 0 || rc > 1) return -1; /* compare's 1 is "they differ" */
    }
    *t = summarise(ms, n);
    return 0;
}

typedef struct ours_times { timing full, metrics, identical; } ours_times;

/* in process: load + every metric (ww_cmp_pair, as `compare` runs it); the metrics alone on the
 * loaded pair; the identical fast path (a frame against a second copy of itself: the hash, then
 * every byte compared) */
static ww_result time_ours(const char *f0, const char *f1, int n, ours_times *t, ww_error *err) {
    double full[64], metrics[64], same[64];
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_image c0, c1;
    ww_result rc = ww_cmp_load_pair(f0, f0, &c0, &c1, err);
    for (int i = 0; i < n && rc == WW_OK; i++) {
        ww_cmp_image a, b;
        ww_cmp_result res;
        double t0 = ww_now_seconds();
        ww_result r = ww_cmp_pair(f0, f1, &o, &a, &b, &res, err);
        double t1 = ww_now_seconds();
        if (r == WW_OK) r = ww_cmp_images(&a, &b, &o, &res, err);
        double t2 = ww_now_seconds();
        if (r == WW_OK) r = ww_cmp_images(&c0, &c1, &o, &res, err);
        double t3 = ww_now_seconds();
        ww_cmp_image_free(&a);
        ww_cmp_image_free(&b);
        rc = r;
        full[i] = 1e3 * (t1 - t0);
        metrics[i] = 1e3 * (t2 - t1);
        same[i] = 1e3 * (t3 - t2);
    }
    ww_cmp_image_free(&c0);
    ww_cmp_image_free(&c1);
    if (rc != WW_OK) return rc;
    t->full = summarise(full, n);
    t->metrics = summarise(metrics, n);
    t->identical = summarise(same, n);
    return WW_OK;
}

/* render frames 0 and 1 of the scene into dir with this binary */
static ww_result render_pair(const ww_bench_compare_opts *o, const char *dir, ww_error *err) {
    char size[32];
    snprintf(size, sizeof size, "%dx%d", o->width, o->height);
    char *argv[] = {SELF, "render", (char *)o->scene, "--frames", "0:2", "--size", size, "-o",
                    (char *)dir, "--quiet", NULL};
    if (run_quiet(argv) != 0)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "bench compare: rendering %s at %s failed (run it with `render` to "
                            "see why)", o->scene, size);
    return WW_OK;
}

static void print_table(const ww_bench_compare_opts *o, const ours_times *us, const timing *proc,
                        const timing *im, int have_im, FILE *to) {
    fprintf(to, "bench compare: %dx%d PNG pair (frames 0 and 1 of %s), best of %d (median)\n",
            o->width, o->height, o->scene, o->repeats);
    fprintf(to, "  ours, load + every metric, in process   %8.1f ms (%.1f)\n", us->full.best,
            us->full.median);
    fprintf(to, "  ours, the metrics alone                 %8.1f ms (%.1f)\n", us->metrics.best,
            us->metrics.median);
    fprintf(to, "  ours, identical pair (hash fast path)   %8.2f ms (%.2f)\n", us->identical.best,
            us->identical.median);
    fprintf(to, "  ours, `waterworld compare` process      %8.1f ms (%.1f)\n", proc->best,
            proc->median);
    if (!have_im) {
        fprintf(to, "  ImageMagick `compare`: not found (apt-get install imagemagick)\n");
        return;
    }
    fprintf(to, "  ImageMagick `compare`, RMSE of R, G, B  %8.1f ms (%.1f)\n", im->best, im->median);
    double x_in = im->best / us->full.best, x_proc = im->best / proc->best;
    double x_med = im->median / proc->median;
    fprintf(to, "  ImageMagick / ours: %.1fx in process, %.1fx process against process, %.1fx by "
                "medians (target >= %.0fx: %s)\n",
            x_in, x_proc, x_med, TARGET_RATIO,
            x_proc >= TARGET_RATIO && x_med >= TARGET_RATIO ? "met" : "not met");
}

static void print_json(const ww_bench_compare_opts *o, const ours_times *us, const timing *proc,
                       const timing *im, int have_im, FILE *to) {
    fprintf(to, "{\"bench\":\"compare\",\"width\":%d,\"height\":%d,\"repeats\":%d,"
                "\"ours_ms\":%.3f,\"ours_median_ms\":%.3f,\"metrics_ms\":%.3f,\"identical_ms\":%.3f,"
                "\"process_ms\":%.3f,\"process_median_ms\":%.3f",
            o->width, o->height, o->repeats, us->full.best, us->full.median, us->metrics.best,
            us->identical.best, proc->best, proc->median);
    if (have_im)
        fprintf(to, ",\"imagemagick_ms\":%.3f,\"imagemagick_median_ms\":%.3f,\"ratio\":%.3f,"
                    "\"ratio_process\":%.3f,\"ratio_process_median\":%.3f",
                im->best, im->median, im->best / us->full.best, im->best / proc->best,
                im->median / proc->median);
    fprintf(to, "}\n");
}

ww_result ww_bench_compare(const ww_bench_compare_opts *opts, FILE *to, ww_error *err) {
    ww_bench_compare_opts o = *opts;
    if (!o.scene) o.scene = "scenes/demo.yaml";
    if (o.width <= 0 || o.height <= 0) o.width = DEFAULT_W, o.height = DEFAULT_H;
    if (o.repeats <= 0) o.repeats = DEFAULT_REPEATS;
    if (o.repeats > 64) o.repeats = 64;

    char dir[128], f0[192], f1[192];
    snprintf(dir, sizeof dir, "/tmp/waterworld-bench-compare.%ld", (long)getpid());
    snprintf(f0, sizeof f0, "%s/frame_00000.png", dir);
    snprintf(f1, sizeof f1, "%s/frame_00001.png", dir);
    ww_result r = render_pair(&o, dir, err);

    /* the same pair, the same run: ours in process, ours as a process, ImageMagick */
    ours_times us = {0};
    timing proc = {0}, im = {0};
    int have_im = 0;
    if (r == WW_OK) r = time_ours(f0, f1, o.repeats, &us, err);
    if (r == WW_OK) {
        char *ours[] = {SELF, "compare", f0, f1, NULL};
        /* the same measure from IM 6 and 7: IM 7 counts alpha in RMSE unless told the channels */
        char *magick7[] = {"magick", "compare", "-channel", "RGB", "-metric", "RMSE", f0, f1,
                           "null:", NULL};
        char *magick6[] = {"compare", "-channel", "RGB", "-metric", "RMSE", f0, f1, "null:", NULL};
        if (time_process(ours, o.repeats, &proc) != 0)
            r = ww_error_set(err, WW_E_IO, NULL, 0, 0, "bench compare: `waterworld compare` failed");
        have_im = r == WW_OK && (time_process(magick7, o.repeats, &im) == 0 ||
                                 time_process(magick6, o.repeats, &im) == 0);
    }
    if (r == WW_OK) (o.json ? print_json : print_table)(&o, &us, &proc, &im, have_im, to);

    /* the frames are the bench's own: remove them */
    unlink(f0);
    unlink(f1);
    rmdir(dir);
    return r;
}
