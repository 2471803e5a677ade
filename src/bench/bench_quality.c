/* bench_quality.c - `waterworld bench quality`: each render quality knob (reflection
 * resolution, shadow map size, bloom passes, shaft samples, MSAA, water grid density, the frame's
 * scale) against the ms it costs and the error it leaves: the final RGB8 frame of one scene is
 * rendered with every knob at its best (the reference), then once per value of each knob with
 * the others kept at their best, and compared with the reference (PSNR and the largest channel
 * difference).
 * A knob's feature is switched on for the bench when this build has its pass; a knob whose pass
 * is absent renders the same and is reported as having no effect. Then the render.quality
 * presets, each the scene as written with the preset set, against the same reference and against
 * the scene's frame at final. Table and out/bench/quality.png (the knobs').
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "bench/plot.h"
#include "gfx/backend.h"
#include "gfx/caustic_set.h"
#include "gfx/renderer.h"
#include "io/image.h"
#include "io/json.h"
#include "io/writers.h"
#include "render/job.h"
#include "scene/plan.h"
#include "sim/state.h"
#include "sim/step.h"

#define DEFAULT_SCENE "scenes/lake.yaml"
#define DEFAULT_WIDTH 640
#define DEFAULT_HEIGHT 360
#define DEFAULT_REPEATS 5
#define PSNR_PLOT_CAP 60.0    /* identical frames (PSNR infinite) are drawn at this height, */
#define PSNR_PLOT_ABOVE 10.0  /* or this far above the knob's closest differing frame */

/* ---- the knobs ------------------------------------------------------------------------------ */

static void set_reflection_scale(ww_scene *sc, double v, int on) {
    sc->render.reflection.scale = v;
    if (on) sc->render.reflection.on = 1;
}
static double get_reflection_scale(const ww_scene *sc) { return sc->render.reflection.scale; }

static void set_refraction_scale(ww_scene *sc, double v, int on) {
    sc->render.refraction_scale = v;
    if (on) sc->render.refraction = 1;
}
static double get_refraction_scale(const ww_scene *sc) { return sc->render.refraction_scale; }

static void set_shadow_size(ww_scene *sc, double v, int on) {
    sc->render.shadows.size = (int)v;
    if (on) sc->render.shadows.on = 1;
}
static double get_shadow_size(const ww_scene *sc) { return sc->render.shadows.size; }

/* the shadow technique as a number (ww_shadow_technique: 0 map, 1 projected, 2 volumes); the
 * map is last, so with render.shadows.size at its best the reference is a 4096 map and the
 * other rows are the stencilled techniques' cost and difference from it */
static void set_shadow_technique(ww_scene *sc, double v, int on) {
    sc->render.shadows.technique = (ww_shadow_technique)(int)v;
    if (on) sc->render.shadows.on = 1;
}
static double get_shadow_technique(const ww_scene *sc) {
    return sc->render.shadows.technique == WW_SHADOW_VOLUMES_VISIBLE
               ? WW_SHADOW_VOLUMES
               : (double)sc->render.shadows.technique;
}

static void set_bloom_passes(ww_scene *sc, double v, int on) {
    sc->render.bloom.passes = (int)v;
    if (on) sc->render.bloom.on = 1;
}
static double get_bloom_passes(const ww_scene *sc) { return sc->render.bloom.passes; }

static void set_shaft_samples(ww_scene *sc, double v, int on) {
    sc->render.shafts.samples = (int)v;
    if (on) sc->render.shafts.on = 1;
}
static double get_shaft_samples(const ww_scene *sc) { return sc->render.shafts.samples; }

static void set_msaa(ww_scene *sc, double v, int on) {
    (void)on;
    sc->render.msaa = (int)v;
}
static double get_msaa(const ww_scene *sc) { return sc->render.msaa; }

static void set_grid(ww_scene *sc, double v, int on) {
    (void)on;
    sc->render.grid = v;
}
static double get_grid(const ww_scene *sc) { return sc->render.grid; }

static void set_frame_scale(ww_scene *sc, double v, int on) {
    (void)on;
    sc->render.scale = v;
}
static double get_frame_scale(const ww_scene *sc) { return sc->render.scale; }

/* 1: water.look.caustics.method texture (cheaper per frame, a one-off set-up); 0: analytic */
static void set_caustics_method(ww_scene *sc, double v, int on) {
    sc->render.water.caustics_method = v > 0.5 ? WW_CAUSTICS_TEXTURE : WW_CAUSTICS_ANALYTIC;
    if (on) sc->render.water.caustics = 1;
}
static double get_caustics_method(const ww_scene *sc) {
    return sc->render.water.caustics_method == WW_CAUSTICS_TEXTURE ? 1.0 : 0.0;
}

/* values within the scene format's ranges (compile_render.c), cheapest first */
static const ww_quality_knob KNOBS[] = {
    {"render.reflection.scale", WW_PASS_REFLECTION, 4, {0.125, 0.25, 0.5, 1.0},
     set_reflection_scale, get_reflection_scale},
    /* the prepass's own time; below full size the water also reads its depth at the frame's
     * size (docs/rendering.md, "Outlines seen through the water"), a cost of the main pass */
    {"render.refraction.scale", WW_PASS_PREPASS, 4, {0.125, 0.25, 0.5, 1.0},
     set_refraction_scale, get_refraction_scale},
    {"render.shadows.size", WW_PASS_SHADOW, 5, {256, 512, 1024, 2048, 4096}, set_shadow_size,
     get_shadow_size},
    {"render.shadows.technique", WW_PASS_MAIN, 3,
     {WW_SHADOW_PROJECTED, WW_SHADOW_VOLUMES, WW_SHADOW_MAP}, set_shadow_technique,
     get_shadow_technique},
    {"render.bloom.passes", WW_PASS_BLOOM, 6, {1, 2, 3, 4, 5, 6}, set_bloom_passes,
     get_bloom_passes},
    {"render.god_rays.samples", WW_PASS_SHAFTS, 6, {8, 16, 32, 48, 64, 128}, set_shaft_samples,
     get_shaft_samples},
    {"render.msaa", WW_PASS_MAIN, 4, {0, 2, 4, 8}, set_msaa, get_msaa},
    {"render.grid", WW_PASS_MAIN, 5, {0.5, 0.75, 1.0, 1.5, 2.0}, set_grid, get_grid},
    /* the whole frame drawn smaller and scaled up: every pass gains; the main pass's time
     * stands for them */
    {"render.scale", WW_PASS_MAIN, 4, {0.5, 0.75, 0.9, 1.0}, set_frame_scale, get_frame_scale},
    {"water.look.caustics.method", WW_PASS_MAIN, 2, {1, 0}, set_caustics_method,
     get_caustics_method},
};

const ww_quality_knob *ww_quality_knobs(int *n) {
    *n = (int)(sizeof KNOBS / sizeof KNOBS[0]);
    return KNOBS;
}

/* ---- one configuration ---------------------------------------------------------------------- */

/* every knob at its best, then knob `vary` (or -1) at value v */
static void configure(ww_scene *sc, const ww_quality_knob *knobs, int nknobs, int vary, double v) {
    for (int k = 0; k < nknobs; k++) {
        const ww_quality_knob *q = &knobs[k];
        q->set(sc, k == vary ? v : q->value[q->nvalues - 1], ww_renderer_has_pass(q->pass));
    }
}

/* one configuration, built and kept while its knob's values are timed in turn */
typedef struct config {
    ww_scene *sc;
    ww_renderer *r;
    ww_state *st;
    int pass;        /* the ww_pass_id the varied knob tunes (-1: the reference) */
    double ms;       /* the least frame time so far */
    double pass_ms;  /* the least time of that pass so far (INFINITY: not planned) */
} config;

static void config_close(config *c) {
    ww_state_free(c->st);
    if (c->r) ww_renderer_free(c->r);
    ww_scene_free(c->sc);
    *c = (config){0};
}

/* build the scene configured so (preset: the scene as written with that --set instead, its
 * knobs untouched), render frame o->frame once (untimed: it pays for shader compilation) and
 * read it into im (RGB8) */
static ww_result config_open(config *c, const ww_quality_opts *o, const ww_gl *gl,
                             const ww_quality_knob *knobs, int nknobs, int vary, double v,
                             const ww_set *preset, ww_image *im, ww_quality_effect *effect,
                             ww_error *err) {
    *c = (config){.ms = INFINITY, .pass_ms = INFINITY, .pass = vary >= 0 ? (int)knobs[vary].pass : -1};
    ww_result rc = ww_scene_load(o->scene, preset, preset ? 1 : 0, &c->sc, err);
    if (rc) return rc;
    if (!preset) configure(c->sc, knobs, nknobs, vary, v);
    if ((rc = ww_renderer_for_scene(gl, c->sc, o->width, o->height, &c->r, err))) return rc;
    if (vary >= 0) {
        ww_pass_id id = knobs[vary].pass;
        *effect = !ww_renderer_has_pass(id)                     ? WW_QUALITY_NOT_BUILT
                  : !ww_plan_pass(ww_renderer_plan(c->r), id) ? WW_QUALITY_NOT_PLANNED
                                                               : WW_QUALITY_MEASURED;
    }
    ww_renderer_time_passes(c->r, WW_TIMING_AUTO);
    if (!(c->st = ww_state_new(c->sc)))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bench quality: out of memory for the state");
    if ((rc = ww_sim_advance_to(c->sc, c->st, o->frame * c->sc->steps_per_frame, err))) return rc;
    if ((rc = ww_render_frame(c->r, c->sc, c->st, err))) return rc;
    ww_renderer_finish(c->r);
    ww_pass_times t;
    ww_renderer_pass_times(c->r, &t); /* the first frame's, with compilation: dropped */
    return ww_renderer_read_ldr(c->r, im, err);
}

/* one timed render; the configuration keeps the least (other processes on the machine can only
 * add to a render's time, so the least is the steadiest estimate of its own cost) */
static ww_result config_time(config *c, ww_error *err) {
    double a = ww_now_seconds();
    ww_result rc = ww_render_frame(c->r, c->sc, c->st, err);
    ww_renderer_finish(c->r);
    double ms = 1e3 * (ww_now_seconds() - a);
    if (ms < c->ms) c->ms = ms;
    ww_pass_times t;
    ww_renderer_pass_times(c->r, &t);
    for (int i = 0; i < t.npasses; i++)
        if ((int)t.id[i] == c->pass && t.frames > 0 && t.ms[i] / t.frames < c->pass_ms)
            c->pass_ms = t.ms[i] / t.frames;
    return rc;
}

static void image_error(const ww_image *a, const ww_image *b, double *psnr, int *max_diff) {
    size_t n = (size_t)a->width * (size_t)a->height * (size_t)a->channels;
    double se = 0.0;
    int mx = 0;
    for (size_t i = 0; i < n; i++) {
        int e = abs((int)a->u8[i] - (int)b->u8[i]);
        if (e > mx) mx = e;
        se += (double)e * e;
    }
    double mse = se / (double)n;
    *psnr = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
    *max_diff = mx;
}

/* the speed/error front and the knee of each knob's rows, by the time of the pass the knob tunes
 * (its own cost: the frame's time carries every other knob at its best, and their noise) */
static void mark_front(ww_quality_result *res, int knob) {
    ww_quality_row *rows = res->rows;
    int knee = -1;
    for (int i = 0; i < res->nrows; i++) {
        ww_quality_row *a = &rows[i];
        if (a->knob != knob) continue;
        a->front = 1;
        for (int j = 0; j < res->nrows && a->front; j++) {
            const ww_quality_row *b = &rows[j];
            if (j == i || b->knob != knob) continue;
            if (b->pass_ms <= a->pass_ms && b->psnr >= a->psnr &&
                (b->pass_ms < a->pass_ms || b->psnr > a->psnr))
                a->front = 0;
        }
        if (a->psnr >= WW_QUALITY_GOOD_DB && (knee < 0 || a->pass_ms < rows[knee].pass_ms)) knee = i;
    }
    if (knee >= 0) rows[knee].knee = 1;
}

ww_result ww_bench_quality_measure(const ww_quality_opts *opts, const ww_quality_knob *knobs,
                                   int nknobs, ww_quality_result *res, ww_error *err) {
    WW_ASSERT(nknobs > 0 && nknobs <= WW_QUALITY_MAX_KNOBS);
    ww_quality_opts o = *opts;
    if (!o.scene) o.scene = DEFAULT_SCENE;
    if (o.width <= 0 || o.height <= 0) {
        o.width = DEFAULT_WIDTH;
        o.height = DEFAULT_HEIGHT;
    }
    memset(res, 0, sizeof *res);

    /* the defaults: the knobs' values in the scene as loaded */
    double def[WW_QUALITY_MAX_KNOBS];
    ww_scene *sc = NULL;
    ww_result rc = ww_scene_load(o.scene, NULL, 0, &sc, err);
    if (rc) return rc;
    for (int k = 0; k < nknobs; k++) def[k] = knobs[k].get(sc);
    ww_scene_free(sc);

    ww_backend *b = NULL;
    ww_image ref = {0}, im = {0}, fin = {0};
    if ((rc = ww_backend_open(o.backend, &b, err))) return rc;
    snprintf(res->device, sizeof res->device, "%s", ww_backend_describe(b));
    snprintf(res->renderer, sizeof res->renderer, "%s", ww_backend_renderer(b));
    if (ww_image_alloc(&ref, o.width, o.height, 3, WW_PIX_U8) ||
        ww_image_alloc(&im, o.width, o.height, 3, WW_PIX_U8) ||
        ww_image_alloc(&fin, o.width, o.height, 3, WW_PIX_U8)) {
        rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bench quality: out of memory for frames");
        goto done;
    }
    const ww_gl *gl = ww_backend_gl(b);
    int repeats = o.repeats > 0 ? o.repeats : DEFAULT_REPEATS;
    config cfg[WW_QUALITY_MAX_VALUES + 1] = {0};
    ww_quality_effect unused;
    rc = config_open(&cfg[0], &o, gl, knobs, nknobs, -1, 0.0, NULL, &ref, &unused, err);
    for (int t = 0; t < repeats && !rc; t++) rc = config_time(&cfg[0], err);
    res->reference_ms = cfg[0].ms;
    config_close(&cfg[0]);

    /* each value of each knob, the others at their best; the best value is rendered again, so
     * its row also shows that two renderers give the same frame. A knob's values are built
     * together and timed in turn, round after round, so that a change in the machine's load
     * falls on all of them alike */
    for (int k = 0; k < nknobs && !rc; k++) {
        const ww_quality_knob *q = &knobs[k];
        WW_ASSERT(q->nvalues > 0 && q->nvalues <= WW_QUALITY_MAX_VALUES);
        if (o.knob && strcmp(o.knob, q->name) != 0) continue;
        ww_quality_row *rows = &res->rows[res->nrows];
        for (int i = 0; i < q->nvalues && !rc; i++) {
            rows[i] = (ww_quality_row){.knob = k, .value = q->value[i],
                                       .is_default = q->value[i] == def[k],
                                       .is_reference = i == q->nvalues - 1};
            rc = config_open(&cfg[i], &o, gl, knobs, nknobs, k, q->value[i], NULL, &im,
                             &rows[i].effect, err);
            if (!rc) image_error(&ref, &im, &rows[i].psnr, &rows[i].max_diff);
        }
        for (int t = 0; t < repeats && !rc; t++)
            for (int i = 0; i < q->nvalues && !rc; i++) rc = config_time(&cfg[i], err);
        for (int i = 0; i < q->nvalues; i++) {
            rows[i].ms = cfg[i].ms;
            rows[i].pass_ms = isfinite(cfg[i].pass_ms) ? cfg[i].pass_ms : 0.0;
            config_close(&cfg[i]);
        }
        if (rc) break;
        res->nrows += q->nvalues;
        mark_front(res, k);
    }

    /* the presets, each the scene as written with render.quality set: against the reference
     * and against the scene's own frame at final; built together and timed in turn as a
     * knob's values are */
    if (!rc && (!o.knob || strcmp(o.knob, WW_QUALITY_PRESET_KNOB) == 0)) {
        static const char *const names[WW_QUALITY_PRESETS] = {"final", "preview", "draft"};
        static const ww_set sets[WW_QUALITY_PRESETS] = {
            {"render.quality=final"}, {"render.quality=preview"}, {"render.quality=draft"}};
        ww_quality_effect effect;
        for (int i = 0; i < WW_QUALITY_PRESETS && !rc; i++) {
            ww_quality_preset *p = &res->presets[i];
            *p = (ww_quality_preset){.name = names[i]};
            /* final's frame stays in fin, the others' come and go in im */
            rc = config_open(&cfg[i], &o, gl, knobs, nknobs, -1, 0.0, &sets[i], i ? &im : &fin,
                             &effect, err);
            if (!rc) image_error(&ref, i ? &im : &fin, &p->psnr, &p->max_diff);
            int unused_diff;
            if (!rc) image_error(&fin, i ? &im : &fin, &p->psnr_final, &unused_diff);
        }
        for (int t = 0; t < repeats && !rc; t++)
            for (int i = 0; i < WW_QUALITY_PRESETS && !rc; i++) rc = config_time(&cfg[i], err);
        for (int i = 0; i < WW_QUALITY_PRESETS; i++) {
            res->presets[i].ms = cfg[i].ms;
            config_close(&cfg[i]);
        }
        if (!rc) res->npresets = WW_QUALITY_PRESETS;
    }

done:
    ww_image_free(&ref);
    ww_image_free(&fin);
    ww_image_free(&im);
    ww_backend_close(b);
    return rc;
}

/* ---- table, JSON and figure ------------------------------------------------------------------ */

/* the plan's name of a pass id, for the table */
static const char *pass_name(ww_pass_id id) {
    static const char *const names[WW_PASS_COUNT] = {
        [WW_PASS_SKYMAP] = "skymap", [WW_PASS_SHADOW] = "shadow", [WW_PASS_PREPASS] = "prepass",
        [WW_PASS_REFLECTION] = "reflection", [WW_PASS_MAIN] = "main", [WW_PASS_BLOOM] = "bloom",
        [WW_PASS_SHAFTS] = "shafts", [WW_PASS_TONEMAP] = "tonemap", [WW_PASS_FXAA] = "fxaa",
        [WW_PASS_UPSCALE] = "upscale", [WW_PASS_HUD] = "hud"};
    return id >= 0 && id < WW_PASS_COUNT && names[id] ? names[id] : "?";
}

static const char *effect_words(ww_quality_effect e) {
    switch (e) {
    case WW_QUALITY_NOT_BUILT: return "no effect: pass absent (not in this build)";
    case WW_QUALITY_NOT_PLANNED: return "no effect: pass absent (not planned for this scene)";
    case WW_QUALITY_MEASURED: break;
    }
    return "no effect on this frame (the renderer does not read it, or what it tunes is not in view)";
}

static int knob_measured(const ww_quality_result *res, int k) {
    for (int i = 0; i < res->nrows; i++)
        if (res->rows[i].knob == k) return 1;
    return 0;
}

/* what a knob's rows say as a whole: 1 when every value renders the reference's frame */
static int knob_without_effect(const ww_quality_result *res, int k, ww_quality_effect *why) {
    int same = 1;
    *why = WW_QUALITY_MEASURED;
    for (int i = 0; i < res->nrows; i++) {
        const ww_quality_row *r = &res->rows[i];
        if (r->knob != k) continue;
        if (isfinite(r->psnr)) same = 0;
        if (r->effect != WW_QUALITY_MEASURED) *why = r->effect;
    }
    return same;
}

/* a PSNR for the table: "inf" for the same frame */
static void db_text(char buf[16], double db) {
    if (isfinite(db)) snprintf(buf, 16, "%.2f", db);
    else snprintf(buf, 16, "inf");
}

/* the presets' rows under the knobs' */
static void print_presets(const ww_quality_result *res, FILE *to) {
    if (res->npresets == 0) return;
    fprintf(to, "\n%-24s %8s %9s %9s %8s %14s\n", "render.quality (whole)", "", "frame ms",
            "PSNR dB", "max diff", "dB from final");
    for (int i = 0; i < res->npresets; i++) {
        const ww_quality_preset *p = &res->presets[i];
        char psnr[16], fin[16];
        db_text(psnr, p->psnr);
        db_text(fin, p->psnr_final);
        fprintf(to, "%-24s %8s %9.2f %9s %8d %14s\n", "", p->name, p->ms, psnr, p->max_diff, fin);
    }
    fputs("each preset is the scene as written with render.quality set (its other knobs as the "
          "preset and the scene\nhave them): frame ms the least of the timed renders, its frame "
          "against the reference (PSNR, max diff)\nand against the scene's frame at final\n", to);
}

static void print_table(const ww_quality_opts *o, const ww_quality_knob *knobs, int nknobs,
                        const ww_quality_result *res, FILE *to) {
    fprintf(to, "bench quality: %s, frame %lld at %dx%d, %s (%s), least of %d renders\n",
            o->scene, (long long)o->frame, o->width, o->height, res->device, res->renderer,
            o->repeats > 0 ? o->repeats : DEFAULT_REPEATS);
    fputs("reference: every knob at its best (", to);
    for (int k = 0; k < nknobs; k++)
        fprintf(to, "%s%s=%g", k ? " " : "", knobs[k].name, knobs[k].value[knobs[k].nvalues - 1]);
    fprintf(to, "): %.2f ms\n\n", res->reference_ms);
    if (res->nrows > 0)
        fprintf(to, "%-24s %8s %9s %-10s %8s %9s %8s  %s\n", "knob", "value", "frame ms", "pass",
                "pass ms", "PSNR dB", "max diff", "");
    for (int k = 0; k < nknobs; k++) {
        if (!knob_measured(res, k)) continue;
        ww_quality_effect why;
        int none = knob_without_effect(res, k, &why);
        int first = 1;
        for (int i = 0; i < res->nrows; i++) {
            const ww_quality_row *r = &res->rows[i];
            if (r->knob != k) continue;
            char psnr[16], flags[48];
            db_text(psnr, r->psnr);
            snprintf(flags, sizeof flags, "%s%s%s%s", r->is_default ? " default" : "",
                     r->is_reference ? " ref" : "", !none && r->front ? " front" : "",
                     !none && r->knee ? " knee" : "");
            fprintf(to, "%-24s %8g %9.2f %-10s %8.2f %9s %8d %s\n", first ? knobs[k].name : "",
                    r->value, r->ms, pass_name(knobs[k].pass), r->pass_ms, psnr, r->max_diff, flags);
            first = 0;
        }
        if (none) {
            fprintf(to, "%-24s %s\n", "", effect_words(why));
            continue;
        }
        /* where the default stands */
        for (int i = 0; i < res->nrows; i++) {
            const ww_quality_row *r = &res->rows[i];
            if (r->knob != k || !r->is_default) continue;
            fprintf(to, "%-24s default %g: %s the speed/error front%s\n", "", r->value,
                    r->front ? "on" : "off", r->knee ? ", at the knee" : "");
        }
    }
    print_presets(res, to);
    if (res->nrows == 0) return;
    fputs("\nrender.shadows.technique: 0 map, 1 projected, 2 volumes (drawn in the main pass and "
          "the prepass; the map's own pass is in the frame ms)", to);
    fprintf(to, "\nframe ms: render + glFinish of one frame; pass ms: the pass the knob tunes (GL timer "
                "queries; 0: not planned);\nboth the least of the timed renders. PSNR and max diff: "
                "the final RGB8 frame against the reference\n(inf: identical). front: no other value "
                "of the knob has both a cheaper pass and a closer frame;\nknee: the value with the "
                "cheapest pass within %.0f dB of the reference. On a shared machine ms differences\n"
                "of 10%% are noise\n",
            WW_QUALITY_GOOD_DB);
}

/* a JSON row's opening: the scene, device, size and frame it was measured on */
static void json_row_head(const ww_quality_opts *o, const ww_quality_result *res, FILE *to) {
    fputs("{\"scene\":", to);
    ww_json_string(to, o->scene);
    fprintf(to, ",\"device\":");
    ww_json_string(to, res->device);
    fprintf(to, ",\"width\":%d,\"height\":%d,\"frame\":%lld,", o->width, o->height,
            (long long)o->frame);
}

/* a PSNR in JSON, which has no infinity: null is "identical" */
static void json_db(FILE *to, double db) {
    if (isfinite(db)) fprintf(to, "%.4f", db);
    else fputs("null", to);
}

static void print_json(const ww_quality_opts *o, const ww_quality_knob *knobs,
                       const ww_quality_result *res, FILE *to) {
    for (int i = 0; i < res->nrows; i++) {
        const ww_quality_row *r = &res->rows[i];
        ww_quality_effect why;
        int none = knob_without_effect(res, r->knob, &why);
        json_row_head(o, res, to);
        fprintf(to, "\"knob\":\"%s\",\"value\":%g,\"ms\":%.4f,\"pass\":\"%s\",\"pass_ms\":%.4f,"
                    "\"reference_ms\":%.4f,\"psnr\":",
                knobs[r->knob].name, r->value, r->ms, pass_name(knobs[r->knob].pass), r->pass_ms,
                res->reference_ms);
        json_db(to, r->psnr);
        fprintf(to, ",\"identical\":%s,\"max_diff\":%d,\"default\":%s,\"reference\":%s,"
                    "\"front\":%s,\"knee\":%s,\"effect\":",
                isfinite(r->psnr) ? "false" : "true", r->max_diff, r->is_default ? "true" : "false",
                r->is_reference ? "true" : "false", !none && r->front ? "true" : "false",
                !none && r->knee ? "true" : "false");
        ww_json_string(to, none ? effect_words(why) : "measured");
        fputs("}\n", to);
    }
    for (int i = 0; i < res->npresets; i++) {
        const ww_quality_preset *p = &res->presets[i];
        json_row_head(o, res, to);
        fprintf(to, "\"preset\":\"%s\",\"ms\":%.4f,\"reference_ms\":%.4f,\"psnr\":", p->name,
                p->ms, res->reference_ms);
        json_db(to, p->psnr);
        fprintf(to, ",\"identical\":%s,\"max_diff\":%d,\"psnr_final\":",
                isfinite(p->psnr) ? "false" : "true", p->max_diff);
        json_db(to, p->psnr_final);
        fputs("}\n", to);
    }
}

#define FIG_COLS 3
#define FIG_PANEL_W 420
#define FIG_PANEL_H 340

static ww_result write_figure(const char *dir, const ww_quality_knob *knobs, int nknobs,
                              const ww_quality_result *res, char *path, size_t cap,
                              ww_error *err) {
    ww_result r = ww_make_dirs(dir, err);
    if (r) return r;
    snprintf(path, cap, "%s/quality.png", dir);
    int shown = 0;
    for (int k = 0; k < nknobs; k++) shown += knob_measured(res, k);
    int cols = shown < FIG_COLS ? (shown > 0 ? shown : 1) : FIG_COLS;
    int rows = (shown + FIG_COLS - 1) / FIG_COLS;
    if (rows < 1) rows = 1;
    ww_image im;
    if (ww_image_alloc(&im, cols * FIG_PANEL_W, rows * FIG_PANEL_H, 3, WW_PIX_U8))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the figure");
    ww_plot_fill(&im, WW_PLOT_WHITE);
    double x[WW_QUALITY_MAX_KNOBS][WW_QUALITY_MAX_VALUES], y[WW_QUALITY_MAX_KNOBS][WW_QUALITY_MAX_VALUES];
    double dx[WW_QUALITY_MAX_KNOBS], dy[WW_QUALITY_MAX_KNOBS];
    for (int k = 0, panel = 0; k < nknobs; k++) {
        if (!knob_measured(res, k)) continue;
        int n = 0, nd = 0;
        double cap = PSNR_PLOT_CAP;
        for (int i = 0; i < res->nrows; i++)
            if (res->rows[i].knob == k && isfinite(res->rows[i].psnr) &&
                res->rows[i].psnr + PSNR_PLOT_ABOVE > cap)
                cap = ceil(res->rows[i].psnr + PSNR_PLOT_ABOVE);
        for (int i = 0; i < res->nrows; i++) {
            const ww_quality_row *q = &res->rows[i];
            if (q->knob != k) continue;
            double p = isfinite(q->psnr) ? q->psnr : cap;
            x[k][n] = q->pass_ms;
            y[k][n++] = p;
            if (q->is_default) {
                dx[k] = q->pass_ms;
                dy[k] = p;
                nd = 1;
            }
        }
        ww_quality_effect why;
        int none = knob_without_effect(res, k, &why);
        char title[96];
        snprintf(title, sizeof title, "%s %g .. %g", knobs[k].name, knobs[k].value[0],
                 knobs[k].value[knobs[k].nvalues - 1]);
        const char *note = why == WW_QUALITY_NOT_BUILT     ? "no effect: pass not built"
                           : why == WW_QUALITY_NOT_PLANNED ? "no effect: pass not planned"
                                                           : "no effect on this frame";
        char xlabel[48];
        snprintf(xlabel, sizeof xlabel, "ms of the %s pass", pass_name(knobs[k].pass));
        char ylabel[48];
        snprintf(ylabel, sizeof ylabel, "PSNR dB (%.0f: identical)", cap);
        ww_plot p = {.title = title, .xlabel = xlabel, .ylabel = ylabel,
                     .note = none ? note : NULL};
        ww_plot_add(&p, "values, cheapest first", x[k], y[k], n, WW_PLOT_BLUE);
        if (nd) ww_plot_add(&p, "default", &dx[k], &dy[k], 1, WW_PLOT_RED);
        ww_plot_draw(&p, &im, (panel % FIG_COLS) * FIG_PANEL_W, (panel / FIG_COLS) * FIG_PANEL_H,
                     FIG_PANEL_W, FIG_PANEL_H);
        panel++;
    }
    r = ww_write_png(path, &im, err);
    ww_image_free(&im);
    return r;
}

/* the caustics' texture set (water.look.caustics.method texture) is computed once, when the
 * renderer is made: its cost, the least of `repeats` makings, in ms (the frame times above
 * leave it out: config_open renders once untimed) */
static ww_result caustic_set_ms(const ww_quality_opts *o, double *ms, ww_error *err) {
    ww_scene *sc = NULL;
    ww_result rc = ww_scene_load(o->scene, NULL, 0, &sc, err);
    *ms = INFINITY;
    for (int t = 0; t < (o->repeats > 0 ? o->repeats : DEFAULT_REPEATS) && !rc; t++) {
        ww_caustic_set cs;
        double a = ww_now_seconds();
        rc = ww_caustic_set_make(sc, &cs, err);
        double b = 1e3 * (ww_now_seconds() - a);
        if (!rc && b < *ms) *ms = b;
        ww_caustic_set_free(&cs);
    }
    ww_scene_free(sc);
    return rc;
}

ww_result ww_bench_quality(const ww_quality_opts *opts, FILE *to, ww_error *err) {
    ww_quality_opts o = *opts;
    if (!o.scene) o.scene = DEFAULT_SCENE;
    if (o.width <= 0 || o.height <= 0) {
        o.width = DEFAULT_WIDTH;
        o.height = DEFAULT_HEIGHT;
    }
    int nknobs;
    const ww_quality_knob *knobs = ww_quality_knobs(&nknobs);
    int presets_only = o.knob && strcmp(o.knob, WW_QUALITY_PRESET_KNOB) == 0;
    if (o.knob && !presets_only) {
        /* one knob (ww_bench_quality_measure skips the others; the reference still has every
         * knob at its best) */
        int k = 0;
        while (k < nknobs && strcmp(knobs[k].name, o.knob) != 0) k++;
        if (k == nknobs) {
            char names[256] = "";
            for (int i = 0; i < nknobs; i++)
                snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? ", " : "",
                         knobs[i].name);
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                "bench quality: no knob '%s' (knobs: %s, or %s for the presets)",
                                o.knob, names, WW_QUALITY_PRESET_KNOB);
        }
    }
    ww_quality_result *res = malloc(sizeof *res);
    if (!res) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bench quality: out of memory");
    ww_result r = ww_bench_quality_measure(&o, knobs, nknobs, res, err);
    if (!r) {
        if (o.json) print_json(&o, knobs, res, to);
        else print_table(&o, knobs, nknobs, res, to);
    }
    if (!r && !o.json && (!o.knob || strcmp(o.knob, "water.look.caustics.method") == 0)) {
        double ms;
        r = caustic_set_ms(&o, &ms, err);
        if (!r)
            fprintf(to, "water.look.caustics.method: 0 analytic, 1 texture; the texture set (%d "
                        "frames of %dx%d) is made once in %.1f ms\n",
                    WW_CAUSTIC_SET_FRAMES, WW_CAUSTIC_SET_SIZE, WW_CAUSTIC_SET_SIZE, ms);
    }
    if (!r && !o.no_figure && !presets_only) {
        char path[1024];
        r = write_figure(o.out_dir ? o.out_dir : "out/bench", knobs, nknobs, res, path,
                         sizeof path, err);
        if (!r && !o.json) fprintf(to, "figure: %s\n", path);
    }
    free(res);
    return r;
}
