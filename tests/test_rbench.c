/* test_rbench.c - render timing and the quality bench: per-pass times (GL timer queries and the
 * CPU fallback) name the planned passes in order, are positive and do not add up to more than
 * the frame's wall time; the quality bench's reference renders the same frame twice (PSNR inf)
 * and a lowered knob gives a finite PSNR; `bench render` and `bench quality` print valid JSON
 * lines, the table and the figure. No timing is asserted beyond that consistency.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/backend.h"
#include "gfx/renderer.h"
#include "io/image.h"
#include "io/writers.h"
#include "scene/plan.h"
#include "sim/state.h"
#include "test.h"
#include "tools/bench.h"
#include "tools/job.h"

/* the passes of one frame may not add up to more than its wall time, beyond this slack (clock
 * granularity and the query's own begin/end placement), ms per frame + fraction */
#define PASS_SUM_SLACK_MS 0.5
#define PASS_SUM_SLACK_FRAC 0.05
#define TIMED_FRAMES 4

/* render a few frames of the tiny scene with timing in `mode`; check the pass times */
static void check_pass_times(ww_timing mode) {
    ww_backend *b = NULL;
    ww_error err = {0};
    ww_scene *sc = NULL;
    ww_renderer *r = NULL;
    ww_state *st = NULL;
    ENSURE_MSG(ww_backend_open(WW_BACKEND_AUTO, &b, &err) == WW_OK, "%s", err.msg);
    ENSURE_MSG(ww_scene_load("scenes/minimal.yaml", NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!b || !sc) goto done;
    ww_plan plan;
    ww_plan_build(sc, 96, 54, &plan);
    ENSURE_MSG(ww_renderer_new(ww_backend_gl(b), sc, &plan, &r, &err) == WW_OK, "%s", err.msg);
    st = ww_state_new(sc);
    if (!r || !st) goto done;

    ww_timing got = ww_renderer_time_passes(r, mode);
    ENSURE(got == WW_TIMING_GPU || got == WW_TIMING_CPU);
    if (mode != WW_TIMING_AUTO) ENSURE(got == mode || (mode == WW_TIMING_GPU && got == WW_TIMING_CPU));
    ww_pass_times t;
    /* the first frame compiles shaders: timed apart */
    ENSURE(ww_render_frame(r, sc, st, &err) == WW_OK);
    ww_renderer_finish(r);
    ww_renderer_pass_times(r, &t);
    ENSURE_EQ_INT(t.frames, 1);

    double wall = 0.0;
    for (int i = 0; i < TIMED_FRAMES; i++) {
        double a = ww_now_seconds();
        ENSURE(ww_render_frame(r, sc, st, &err) == WW_OK);
        ww_renderer_finish(r);
        wall += 1e3 * (ww_now_seconds() - a);
    }
    ww_renderer_pass_times(r, &t);
    ENSURE(t.mode == got);
    ENSURE_EQ_INT(t.frames, TIMED_FRAMES);
    ENSURE_EQ_INT(t.npasses, plan.npasses);
    double sum = 0.0;
    for (int i = 0; i < t.npasses && i < plan.npasses; i++) {
        ENSURE_EQ_INT(t.id[i], plan.passes[i].id);
        ENSURE_MSG(strcmp(t.name[i], plan.passes[i].name) == 0, "pass %d: '%s' != '%s'", i,
                   t.name[i], plan.passes[i].name);
        ENSURE_MSG(t.ms[i] > 0.0, "%s: pass %s took %g ms", ww_timing_name(got), t.name[i], t.ms[i]);
        sum += t.ms[i];
    }
    double allowed = wall * (1.0 + PASS_SUM_SLACK_FRAC) + PASS_SUM_SLACK_MS * TIMED_FRAMES;
    ENSURE_MSG(sum <= allowed, "%s: passes %.3f ms over %d frames of %.3f ms wall time",
               ww_timing_name(got), sum, TIMED_FRAMES, wall);
    if (got == WW_TIMING_CPU) ENSURE(t.frame_ms >= sum - 1e-9 && t.frame_ms <= allowed);

    /* the sums restart at each read */
    ww_renderer_pass_times(r, &t);
    ENSURE_EQ_INT(t.frames, 0);
    ENSURE(t.ms[0] == 0.0);

done:
    ww_state_free(st);
    if (r) ww_renderer_free(r);
    ww_scene_free(sc);
    if (b) ww_backend_close(b);
}

TEST(rbench_pass_times_gpu_within_frame) {
    if (!ww_test_have_gl()) return;
    check_pass_times(WW_TIMING_AUTO);
    check_pass_times(WW_TIMING_GPU);
}

TEST(rbench_pass_times_cpu_within_frame) {
    if (!ww_test_have_gl()) return;
    check_pass_times(WW_TIMING_CPU);
}

/* ---- bench quality ------------------------------------------------------------------------- */

/* a knob every build has (the main pass's exposure), so the machinery is tested before the
 * knobs' passes exist */
static void set_exposure(ww_scene *sc, double v, int on) {
    (void)on;
    sc->exposure = v;
}
static double get_exposure(const ww_scene *sc) { return sc->exposure; }

TEST(rbench_quality_reference_identical_lower_knob_finite) {
    if (!ww_test_have_gl()) return;
    static const ww_quality_knob knobs[] = {
        {"render.tonemap.exposure", WW_PASS_MAIN, 3, {0.3, 0.6, 1.1}, set_exposure, get_exposure}};
    ww_quality_opts o = {.scene = "scenes/demo.yaml", .width = 64, .height = 36, .repeats = 1};
    ww_quality_result *res = malloc(sizeof *res);
    ww_error err = {0};
    ENSURE(res != NULL);
    if (!res) return;
    ENSURE_MSG(ww_bench_quality_measure(&o, knobs, 1, res, &err) == WW_OK, "%s", err.msg);
    ENSURE_EQ_INT(res->nrows, 3);
    ENSURE(res->reference_ms > 0.0);
    const ww_quality_row *lo = &res->rows[0], *mid = &res->rows[1], *ref = &res->rows[2];
    ENSURE(ref->is_reference && !lo->is_reference);
    ENSURE(ref->is_default); /* demo.yaml sets exposure 1.1 */
    ENSURE_MSG(isinf(ref->psnr) && ref->max_diff == 0, "reference row: PSNR %g, max diff %d",
               ref->psnr, ref->max_diff);
    ENSURE_MSG(isfinite(lo->psnr) && lo->max_diff > 0, "exposure 0.3: PSNR %g, max diff %d",
               lo->psnr, lo->max_diff);
    /* further from the reference, further off */
    ENSURE_MSG(lo->psnr < mid->psnr, "PSNR %g at 0.3, %g at 0.6", lo->psnr, mid->psnr);
    ENSURE(lo->effect == WW_QUALITY_MEASURED);
    /* exactly one knee (the reference is within any PSNR), and the reference is on the front */
    int knees = 0;
    for (int i = 0; i < res->nrows; i++) knees += res->rows[i].knee;
    ENSURE_EQ_INT(knees, 1);
    ENSURE(ref->front);
    free(res);
}

/* the six knobs of issue 5: the reference row is the same frame; a knob whose pass this build
 * lacks is said so; the reflection's scale, once its pass is built, changes the lake's frame (the
 * water covers half of it) at its cheapest value. (Other knobs may not show on frame 0 of the
 * lake: its sun is behind the camera, so the shafts add nothing there.) */
TEST(rbench_quality_issue_knobs) {
    if (!ww_test_have_gl()) return;
    int nknobs;
    const ww_quality_knob *knobs = ww_quality_knobs(&nknobs);
    ENSURE_EQ_INT(nknobs, 6);
    ww_quality_opts o = {.scene = "scenes/lake.yaml", .width = 64, .height = 36, .repeats = 1};
    ww_quality_result *res = malloc(sizeof *res);
    ww_error err = {0};
    ENSURE(res != NULL);
    if (!res) return;
    ENSURE_MSG(ww_bench_quality_measure(&o, knobs, nknobs, res, &err) == WW_OK, "%s", err.msg);
    int defaults[6] = {0};
    for (int i = 0; i < res->nrows; i++) {
        const ww_quality_row *r = &res->rows[i];
        const ww_quality_knob *k = &knobs[r->knob];
        defaults[r->knob] += r->is_default;
        if (r->is_reference)
            ENSURE_MSG(isinf(r->psnr), "%s=%g (reference): PSNR %g", k->name, r->value, r->psnr);
        if (!ww_renderer_has_pass(k->pass)) ENSURE(r->effect == WW_QUALITY_NOT_BUILT);
        int cheapest = r->value == k->value[0];
        if (cheapest && r->effect == WW_QUALITY_MEASURED && k->pass == WW_PASS_REFLECTION)
            ENSURE_MSG(isfinite(r->psnr) && r->max_diff > 0,
                       "%s=%g: the same frame as the reference", k->name, r->value);
    }
    /* every knob's default is one of its values */
    for (int k = 0; k < nknobs; k++) ENSURE_MSG(defaults[k] == 1, "%s: %d defaults", knobs[k].name, defaults[k]);
    free(res);
}

/* ---- the commands ---------------------------------------------------------------------------- */

/* every line of a file is one JSON object holding each of the keys; the count */
static int json_lines_with(const char *path, const char *const *keys) {
    char *s = ww_test_read_file(path, NULL);
    if (!s) return -1;
    int n = ww_test_json_lines(s);
    char *save = NULL;
    for (char *line = strtok_r(s, "\n", &save); line && n > 0; line = strtok_r(NULL, "\n", &save)) {
        ENSURE_MSG(ww_test_json_valid(line), "not JSON: %s", line);
        for (int k = 0; keys[k]; k++) ENSURE_MSG(strstr(line, keys[k]) != NULL, "no %s in %s", keys[k], line);
    }
    free(s);
    return n;
}

TEST(rbench_bench_render_json) {
    if (!ww_test_have_gl()) return;
    char dir[512], out[600], errf[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("rbench_bench_render_json"));
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("bench render --frames 2 --json scenes/minimal.yaml", out, errf), 0);
    static const char *const keys[] = {"\"passes\":[{\"name\":", "{\"name\":\"main\",\"ms\":",
                                       "{\"name\":\"tonemap\",\"ms\":", "\"pass_timer\":",
                                       "\"fps\":", "\"floor_x\":", NULL};
    /* 2 backends x 2 sizes (a backend that cannot open prints an error line instead) */
    int n = json_lines_with(out, keys);
    ENSURE_MSG(n == 4, "%d JSON lines", n);
    ENSURE(ww_test_file_contains(out, "\"target_x\":3.0")); /* minimal: water and sky at 1280x720 */
}

TEST(rbench_bench_render_table) {
    if (!ww_test_have_gl()) return;
    char dir[512], out[600], errf[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("rbench_bench_render_table"));
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("bench render --frames 2 scenes/minimal.yaml", out, errf), 0);
    ENSURE(ww_test_file_contains(out, "passes:"));
    ENSURE(ww_test_file_contains(out, " main "));
    ENSURE(ww_test_file_contains(out, " tonemap "));
    ENSURE(ww_test_file_contains(out, "targets (issue 5"));
    ENSURE(ww_test_file_contains(out, "water and sky"));

    /* options that belong to another bench */
    ENSURE_EQ_INT(ww_test_ww("bench render --size 64x36", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("bench quality --frames 3", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("bench quality --size 64", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("bench quality --repeats 0", NULL, NULL), 2);
}

TEST(rbench_bench_quality_json_table_and_figure) {
    if (!ww_test_have_gl()) return;
    char dir[512], out[600], errf[600], fig[600], args[1200];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("rbench_bench_quality"));
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(fig, sizeof fig, "%s/fig/quality.png", dir);
    snprintf(args, sizeof args, "bench quality --tiny --size 48x27 --repeats 1 --json -o %s/fig scenes/lake.yaml", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    static const char *const keys[] = {"\"knob\":", "\"psnr\":", "\"max_diff\":", "\"effect\":", NULL};
    int n = json_lines_with(out, keys);
    ENSURE_MSG(n == 4 + 5 + 6 + 6 + 4 + 5, "%d JSON lines", n);
    ENSURE(ww_test_file_contains(out, "\"knob\":\"render.reflection.scale\",\"value\":1,"));

    snprintf(args, sizeof args, "bench quality --tiny --size 48x27 --repeats 1 -o %s/fig scenes/lake.yaml", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    ENSURE(ww_test_file_contains(out, "reference: every knob at its best"));
    ENSURE(ww_test_file_contains(out, "render.god_rays.samples"));
    ENSURE(ww_test_file_contains(out, "figure:"));
    ww_image im = {0};
    ww_error err = {0};
    ENSURE_MSG(ww_read_png(fig, &im, &err) == WW_OK, "%s", err.msg);
    ENSURE(im.width > 0 && im.height > 0);
    ww_image_free(&im);
}
