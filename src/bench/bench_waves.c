/* bench_waves.c - `waterworld bench waves` (bench_waves.h): CPU evaluation against libm sincos,
 * exact height queries against their iteration cap, GPU frame time against component count,
 * and the figure. Every time is the median of repeats after a warm-up, on a monotonic clock.
 */
#define _GNU_SOURCE /* sincos(3), the baseline the evaluation is set against */
#include "bench/bench_waves.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench/plot.h"
#include "core/child.h"
#include "core/mathx.h"
#include "core/rng.h"
#include "gfx/backend.h"
#include "gfx/renderer.h"
#include "io/json.h"
#include "io/writers.h"
#include "render/job.h"
#include "scene/scene.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "sim/wave_stats.h"
#include "sim/waves.h"

#define SEA_SEED 20240601u     /* every sea of the report is drawn from this seed */
#define SEA_TIME 12.25         /* s: the time the CPU parts evaluate at */
#define SEA_SPAN 200.0         /* m: sample points lie in a square this wide around the origin */
#define MAX_REPEATS 9
#define CALLS_CAP (1 << 24)    /* calibration never runs a call more often per repeat */

/* (a) */
static const int cpu_counts[] = {1, 8, 32, 128};
#define NCPU_COUNTS 4
#define CPU_POINTS 1024
#define CPU_LMIN 0.5           /* m: wavelength range of the CPU seas */
#define CPU_LMAX 60.0
#define CPU_FOLD 0.5           /* sum Q k A of the Gerstner seas */

/* (b) */
static const double query_margins[] = {0.5, 0.2, 0.05};
#define NQUERY_MARGINS 3
static const int query_caps[] = {1, 2, 4, 8, 16, 32};
#define NQUERY_CAPS 6
#define QUERY_WAVES 32
#define QUERY_POINTS 1000

/* (c) */
static const int gpu_counts[] = {0, 1, 8, 32, 128, 256}; /* 0: the flat sea, the baseline */
#define NGPU_COUNTS 6
#define GPU_WIDTH 1280
#define GPU_HEIGHT 720
#define GPU_WARMUP 3
#define GPU_FRAMES 11
#define GPU_LMIN 0.05          /* m: down to what only the fade can keep from shimmering */
#define GPU_LMAX 200.0

typedef struct config {
    int points, repeats, query_points, tiny;
    double repeat_s;            /* each timed repeat runs at least this long, s */
    int gpu_w, gpu_h, gpu_warmup, gpu_frames;
} config;

static config make_config(int tiny) {
    if (tiny)
        return (config){.points = 64, .repeats = 3, .query_points = 40, .tiny = 1,
                        .repeat_s = 0.0005, .gpu_w = 160, .gpu_h = 90, .gpu_warmup = 1,
                        .gpu_frames = 1};
    return (config){.points = CPU_POINTS, .repeats = 7, .query_points = QUERY_POINTS,
                    .repeat_s = 0.02, .gpu_w = GPU_WIDTH, .gpu_h = GPU_HEIGHT,
                    .gpu_warmup = GPU_WARMUP, .gpu_frames = GPU_FRAMES};
}

/* ---- seas and timing ------------------------------------------------------------------------ */

/* a seeded sea of n components of one family: wavelengths log-uniform in [lmin, lmax], headings
 * within 60 degrees of +x, uniform phases, every component equally steep with sum k A = 1
 * (A = L / (2 pi n)), and for Gerstner one Q for all so that sum Q k A = fold_sum */
static void make_sea(ww_scene *sc, ww_wave_model model, int n, double fold_sum, double lmin,
                     double lmax, uint64_t seed) {
    ww_scene_defaults(sc);
    snprintf(sc->name, sizeof sc->name, "bench-%s-%d", ww_wave_model_name(model), n);
    sc->seed = seed;
    sc->wave_model = model;
    sc->nwaves = n;
    int moves = model == WW_WAVES_GERSTNER || model == WW_WAVES_SPECTRUM;
    ww_rng r;
    ww_rng_seed(&r, seed, WW_RNG_WAVES);
    for (int i = 0; i < n; i++) {
        ww_wave *w = &sc->waves[i];
        *w = (ww_wave){0};
        w->wavelength = lmin * pow(lmax / lmin, ww_rng_uniform(&r));
        w->direction = ww_m_rad(-60.0 + 120.0 * ww_rng_uniform(&r));
        w->phase = WW_TAU * ww_rng_uniform(&r);
        w->exponent = model == WW_WAVES_STEEP_SINES ? 1.5 + 1.5 * ww_rng_uniform(&r) : 1.0;
        w->amplitude = w->wavelength / (WW_TAU * n);
        w->steepness = moves ? fold_sum : 0.0;
        ww_wave_derive(w, 0.0);
    }
    sc->fold_sum = sc->fold_sum_given = moves && n > 0 ? fold_sum : 0.0;
}

typedef void (*bench_fn)(void *ctx);

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n) {
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* seconds per call of fn: one warm-up call, then enough calls per repeat that a repeat lasts
 * cf->repeat_s, and the median over cf->repeats repeats */
static double time_median(bench_fn fn, void *ctx, const config *cf) {
    fn(ctx);
    long calls = 1;
    for (;;) {
        double t0 = ww_now_seconds();
        for (long c = 0; c < calls; c++) fn(ctx);
        double dt = ww_now_seconds() - t0;
        if (dt >= cf->repeat_s || calls >= CALLS_CAP) break;
        double grow = dt > 0.0 ? 1.2 * cf->repeat_s / dt : 16.0;
        calls = (long)fmin((double)CALLS_CAP, fmax(2.0 * (double)calls, (double)calls * grow));
    }
    double rep[MAX_REPEATS];
    int n = cf->repeats < MAX_REPEATS ? cf->repeats : MAX_REPEATS;
    for (int k = 0; k < n; k++) {
        double t0 = ww_now_seconds();
        for (long c = 0; c < calls; c++) fn(ctx);
        rep[k] = (ww_now_seconds() - t0) / (double)calls;
    }
    return median(rep, n);
}

/* ---- (a) CPU evaluation ----------------------------------------------------------------------- */

typedef struct cpu_ctx {
    const ww_scene *sc;
    const double *phase;
    int n;
    const double *x, *z;
    const float *xf, *zf;
    double *X, *Y, *Z, *nx, *ny, *nz;
    float *Xf, *Yf, *Zf, *nxf, *nyf, *nzf;
    double sink;
} cpu_ctx;

static void run_double(void *p) {
    cpu_ctx *c = p;
    ww_waves_eval_batch(c->sc, c->phase, c->n, c->x, c->z, c->X, c->Y, c->Z, c->nx, c->ny, c->nz);
}

static void run_float(void *p) {
    cpu_ctx *c = p;
    ww_waves_eval_batch_f(c->sc, c->phase, c->n, c->xf, c->zf, c->Xf, c->Yf, c->Zf, c->nxf, c->nyf,
                          c->nzf);
}

static void run_scalar(void *p) {
    cpu_ctx *c = p;
    double out[3], nrm[3];
    for (int j = 0; j < c->n; j++) {
        ww_waves_eval(c->sc, c->phase, c->x[j], c->z[j], out, nrm);
        c->Y[j] = out[1];
    }
}

/* the baseline: one libm sincos per component per point, of the same phases, results stored */
static void run_sincos(void *p) {
    cpu_ctx *c = p;
    for (int i = 0; i < c->sc->nwaves; i++) {
        const ww_wave *w = &c->sc->waves[i];
        double kx = w->k * w->dir[0], kz = w->k * w->dir[1], ph = c->phase[i];
        for (int j = 0; j < c->n; j++) sincos(kx * c->x[j] + kz * c->z[j] + ph, &c->X[j], &c->Z[j]);
    }
    c->sink += c->X[0] + c->Z[c->n - 1];
}

typedef struct cpu_row {
    ww_wave_model model;
    int count;
    double ns_double, ns_float, ns_scalar, ns_sincos; /* per point */
    double err_h, err_xz, err_rel, err_normal_deg;     /* float against double */
} cpu_row;

/* angle between two unit vectors, degrees (atan2 of |a x b| and a.b, exact for small angles) */
static double angle_deg(double ax, double ay, double az, double bx, double by, double bz) {
    double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    return ww_m_deg(atan2(sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz));
}

static void cpu_measure(cpu_ctx *c, const config *cf, cpu_row *row) {
    double n = (double)c->n;
    row->ns_double = 1e9 * time_median(run_double, c, cf) / n;
    row->ns_float = 1e9 * time_median(run_float, c, cf) / n;
    row->ns_scalar = 1e9 * time_median(run_scalar, c, cf) / n;
    row->ns_sincos = 1e9 * time_median(run_sincos, c, cf) / n;

    /* the float error, against double at the same (float) rest points */
    run_double(c);
    run_float(c);
    row->err_h = row->err_xz = row->err_normal_deg = 0.0;
    for (int j = 0; j < c->n; j++) {
        row->err_h = fmax(row->err_h, fabs((double)c->Yf[j] - c->Y[j]));
        row->err_xz = fmax(row->err_xz, fmax(fabs((double)c->Xf[j] - c->X[j]),
                                             fabs((double)c->Zf[j] - c->Z[j])));
        row->err_normal_deg =
            fmax(row->err_normal_deg, angle_deg(c->nx[j], c->ny[j], c->nz[j], (double)c->nxf[j],
                                                (double)c->nyf[j], (double)c->nzf[j]));
    }
    double amp = ww_waves_total_amplitude(c->sc);
    row->err_rel = amp > 0.0 ? row->err_h / amp : 0.0;
}

/* one allocation for every point array of (a) */
typedef struct cpu_buffers {
    void *block;
    double *d[8];  /* x, z, X, Y, Z, nx, ny, nz */
    float *f[8];   /* x, z, X, Y, Z, nx, ny, nz */
} cpu_buffers;

static int cpu_alloc(cpu_buffers *b, int n) {
    size_t nd = 8 * (size_t)n, bytes = nd * sizeof(double) + nd * sizeof(float);
    if (!(b->block = malloc(bytes))) return -1;
    double *d = b->block;
    float *f = (float *)(d + nd);
    for (int k = 0; k < 8; k++) {
        b->d[k] = d + (size_t)k * (size_t)n;
        b->f[k] = f + (size_t)k * (size_t)n;
    }
    return 0;
}

static void cpu_print_header(FILE *to, const config *cf) {
    fprintf(to, "(a) CPU wave evaluation: %d points per batch, displaced point + normal, ns per point"
                " (median of %d)\n", cf->points, cf->repeats);
    fprintf(to, "%-11s %5s | %9s %9s %9s | %9s %7s %7s | %10s %9s %10s\n", "family", "comps",
            "double", "float", "scalar", "sincos", "dbl/sc", "flt/sc", "f32 err h", "rel", "normal deg");
}

static void cpu_print_row(FILE *to, const cpu_row *r, int json, int points) {
    double rd = r->ns_double / r->ns_sincos, rf = r->ns_float / r->ns_sincos;
    if (json) {
        fprintf(to,
                "{\"part\":\"cpu\",\"family\":\"%s\",\"components\":%d,\"points\":%d,"
                "\"double_ns_per_point\":%.4f,\"float_ns_per_point\":%.4f,\"scalar_ns_per_point\":%.4f,"
                "\"sincos_ns_per_point\":%.4f,\"double_evals_per_s\":%.6g,\"float_evals_per_s\":%.6g,"
                "\"double_over_sincos\":%.4f,\"float_over_sincos\":%.4f,\"float_height_err_m\":%.4g,"
                "\"float_xz_err_m\":%.4g,\"float_height_err_rel\":%.4g,\"float_normal_err_deg\":%.4g}\n",
                ww_wave_model_name(r->model), r->count, points, r->ns_double, r->ns_float, r->ns_scalar,
                r->ns_sincos, 1e9 / r->ns_double, 1e9 / r->ns_float, rd, rf, r->err_h, r->err_xz,
                r->err_rel, r->err_normal_deg);
        return;
    }
    fprintf(to, "%-11s %5d | %9.2f %9.2f %9.2f | %9.2f %7.2f %7.2f | %10.2e %9.2e %10.2e\n",
            ww_wave_model_name(r->model), r->count, r->ns_double, r->ns_float, r->ns_scalar, r->ns_sincos, rd,
            rf, r->err_h, r->err_rel, r->err_normal_deg);
}

static const ww_wave_model cpu_models[] = {WW_WAVES_GERSTNER, WW_WAVES_SINES, WW_WAVES_STEEP_SINES};
#define NCPU_MODELS 3

static ww_result part_cpu(ww_scene *sc, const config *cf, int json, FILE *to,
                          cpu_row rows[NCPU_MODELS][NCPU_COUNTS], ww_error *err) {
    cpu_buffers b;
    if (cpu_alloc(&b, cf->points))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bench waves: out of memory");
    ww_rng r;
    ww_rng_seed(&r, SEA_SEED, WW_RNG_WAVES + 100);
    for (int j = 0; j < cf->points; j++) {
        b.f[0][j] = (float)(SEA_SPAN * (ww_rng_uniform(&r) - 0.5));
        b.f[1][j] = (float)(SEA_SPAN * (ww_rng_uniform(&r) - 0.5));
        b.d[0][j] = (double)b.f[0][j];
        b.d[1][j] = (double)b.f[1][j];
    }
    double phase[WW_MAX_WAVES];
    cpu_ctx c = {.sc = sc, .phase = phase, .n = cf->points, .x = b.d[0], .z = b.d[1],
                 .xf = b.f[0], .zf = b.f[1], .X = b.d[2], .Y = b.d[3], .Z = b.d[4], .nx = b.d[5],
                 .ny = b.d[6], .nz = b.d[7], .Xf = b.f[2], .Yf = b.f[3], .Zf = b.f[4],
                 .nxf = b.f[5], .nyf = b.f[6], .nzf = b.f[7]};
    if (!json) cpu_print_header(to, cf);
    for (int m = 0; m < NCPU_MODELS; m++) {
        for (int k = 0; k < NCPU_COUNTS; k++) {
            make_sea(sc, cpu_models[m], cpu_counts[k], CPU_FOLD, CPU_LMIN, CPU_LMAX, SEA_SEED);
            ww_waves_phases(sc, SEA_TIME, phase);
            cpu_row *row = &rows[m][k];
            *row = (cpu_row){.model = cpu_models[m], .count = cpu_counts[k]};
            cpu_measure(&c, cf, row);
            cpu_print_row(to, row, json, cf->points);
            fflush(to);
        }
    }
    if (!json)
        fprintf(to, "double/float: ww_waves_eval_batch(_f); scalar: ww_waves_eval per point; sincos: "
                    "libm sincos of every\ncomponent's phase (the calls the sum needs); dbl/sc, flt/sc: "
                    "cost against that baseline\n(target <= 2); f32 err: float against double at the "
                    "same points, height in m, rel = / sum A\n\n");
    free(b.block);
    return WW_OK;
}

/* ---- (b) exact height queries ------------------------------------------------------------------ */

typedef struct query_ctx {
    ww_field f;
    ww_query_opts o;
    int n;
    const double *x, *z;
    double sink;
} query_ctx;

static void run_queries(void *p) {
    query_ctx *q = p;
    ww_water_sample s;
    for (int j = 0; j < q->n; j++) {
        ww_water_height(&q->f, q->x[j], q->z[j], &q->o, &s);
        q->sink += s.height;
    }
}

static void part_queries(ww_scene *sc, const config *cf, int json, FILE *to, double *work) {
    int n = cf->query_points;
    double *x = work, *z = work + n, *res = work + 2 * n;
    ww_rng r;
    ww_rng_seed(&r, SEA_SEED, WW_RNG_WAVES + 200);
    for (int j = 0; j < n; j++) {
        x[j] = SEA_SPAN * (ww_rng_uniform(&r) - 0.5);
        z[j] = SEA_SPAN * (ww_rng_uniform(&r) - 0.5);
    }
    if (!json) {
        fprintf(to, "(b) exact height queries (ww_water_height): %d Gerstner components, %d points, "
                    "tolerance %g m\n", QUERY_WAVES, n, WW_QUERY_TOLERANCE);
        fprintf(to, "%6s %8s %5s | %7s %5s %7s | %10s %10s | %9s\n", "margin", "min jac", "cap",
                "iters", "max", "conv %", "median res", "max res", "us/query");
    }
    double phase[WW_MAX_WAVES];
    for (int m = 0; m < NQUERY_MARGINS; m++) {
        make_sea(sc, WW_WAVES_GERSTNER, QUERY_WAVES, 1.0 - query_margins[m], 1.0, 100.0, SEA_SEED);
        ww_waves_phases(sc, SEA_TIME, phase);
        ww_wave_stats ws;
        ww_wave_stats_compute(sc, cf->tiny ? 16 : 0, cf->tiny ? 2 : 0, &ws);
        for (int k = 0; k < NQUERY_CAPS; k++) {
            query_ctx q = {.f = {.sc = sc, .phase = phase, .t = SEA_TIME, .ripples = NULL},
                           .o = {.tolerance = WW_QUERY_TOLERANCE, .max_iterations = query_caps[k]},
                           .n = n, .x = x, .z = z};
            /* the answers, then the time */
            double iters = 0.0, max_res = 0.0;
            int max_it = 0, conv = 0;
            for (int j = 0; j < n; j++) {
                ww_water_sample s;
                conv += ww_water_height(&q.f, x[j], z[j], &q.o, &s) ? 1 : 0;
                iters += s.iterations;
                max_it = s.iterations > max_it ? s.iterations : max_it;
                res[j] = s.residual;
                max_res = fmax(max_res, s.residual);
            }
            double med_res = median(res, n);
            double us = 1e6 * time_median(run_queries, &q, cf) / (double)n;
            double pc = 100.0 * conv / n;
            if (json)
                fprintf(to,
                        "{\"part\":\"query\",\"fold_margin\":%g,\"fold_sum\":%g,\"min_jacobian\":%.4f,"
                        "\"components\":%d,\"points\":%d,\"max_iterations\":%d,\"mean_iterations\":%.3f,"
                        "\"most_iterations\":%d,\"converged_pct\":%.2f,\"median_residual_m\":%.3g,"
                        "\"max_residual_m\":%.3g,\"us_per_query\":%.4f}\n",
                        query_margins[m], sc->fold_sum, ws.fold_margin, QUERY_WAVES, n, query_caps[k],
                        iters / n, max_it, pc, med_res, max_res, us);
            else
                fprintf(to, "%6.2f %8.4f %5d | %7.2f %5d %7.1f | %10.2e %10.2e | %9.3f\n",
                        query_margins[m], ws.fold_margin, query_caps[k], iters / n, max_it, pc, med_res,
                        max_res, us);
            fflush(to);
        }
    }
    if (!json)
        fprintf(to, "margin: 1 - sum Q k A; min jac: the smallest Jacobian of the horizontal map over a "
                    "sample (wave_stats);\ncap: iteration limit; iters: wave-sum evaluations per query "
                    "(mean, max); conv: residual <= tolerance\n\n");
}

/* ---- (c) GPU frame time ------------------------------------------------------------------------ */

typedef struct gpu_report {
    int ok;
    int no_backend;       /* the backend did not open: the rest of (c) is skipped */
    double ms, ms_min;    /* per frame: median and fastest */
    int frames;
    char backend[64];
    char renderer[128];
    char msg[sizeof(((ww_error *)0)->msg)];
} gpu_report;

/* in the child: a sea of n components (none: flat) seen from 4 m up, looking at the horizon */
static void gpu_child(const config *cf, int n, int fade, gpu_report *rep) {
    ww_error err = {0};
    ww_scene *sc = malloc(sizeof *sc);
    ww_backend *b = NULL;
    ww_renderer *ren = NULL;
    ww_state *st = NULL;
    double ms[64];
    if (!sc) {
        snprintf(rep->msg, sizeof rep->msg, "out of memory");
        return;
    }
    if (!fade) setenv("WW_WATER_FADE", "0", 1);
    make_sea(sc, n ? WW_WAVES_GERSTNER : WW_WAVES_FLAT, n, CPU_FOLD, GPU_LMIN, GPU_LMAX, SEA_SEED);
    sc->cam[0] = (ww_camera_key){.t = 0.0, .position = {0.0, 4.0, 0.0}, .has_look_at = 1,
                                 .look_at = {0.0, 0.0, -40.0}};
    sc->ncam = 1;
    sc->width = cf->gpu_w;
    sc->height = cf->gpu_h;
    if (ww_backend_open(WW_BACKEND_AUTO, &b, &err) != WW_OK) {
        rep->no_backend = 1;
        goto done;
    }
    snprintf(rep->backend, sizeof rep->backend, "%s", ww_backend_describe(b));
    snprintf(rep->renderer, sizeof rep->renderer, "%s", ww_backend_renderer(b));
    if (ww_renderer_for_scene(ww_backend_gl(b), sc, cf->gpu_w, cf->gpu_h, &ren, &err) != WW_OK)
        goto done;
    if (!(st = ww_state_new(sc))) {
        ww_error_set(&err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
        goto done;
    }
    int total = cf->gpu_warmup + cf->gpu_frames, kept = 0;
    for (int f = 0; f < total; f++) {
        if (ww_sim_advance_to(sc, st, f * sc->steps_per_frame, &err) != WW_OK) goto done;
        double t0 = ww_now_seconds();
        if (ww_render_frame(ren, sc, st, &err) != WW_OK) goto done;
        ww_renderer_finish(ren);
        double dt = ww_now_seconds() - t0;
        if (f >= cf->gpu_warmup && kept < 64) ms[kept++] = 1e3 * dt;
    }
    rep->frames = kept;
    rep->ms = median(ms, kept);
    rep->ms_min = ms[0]; /* sorted by median() */
    rep->ok = 1;
done:
    if (!rep->ok) snprintf(rep->msg, sizeof rep->msg, "%s", err.msg);
    ww_state_free(st);
    if (ren) ww_renderer_free(ren);
    if (b) ww_backend_close(b);
    free(sc);
}

/* what a GPU child runs: one configuration, one component count, fade on or off */
typedef struct gpu_job {
    const config *cf;
    int n, fade;
} gpu_job;

static void gpu_job_run(const void *ctx, void *report) {
    const gpu_job *j = ctx;
    gpu_child(j->cf, j->n, j->fade, report);
}

/* one configuration in a child process (core/child.h), so a driver crash or leak stays there */
static void gpu_run(const config *cf, int n, int fade, gpu_report *rep) {
    gpu_job j = {cf, n, fade};
    ww_child_end end;
    ww_child_outcome o = ww_child_run(gpu_job_run, &j, rep, sizeof *rep, &end);
    if (o == WW_CHILD_NO_PIPE)
        snprintf(rep->msg, sizeof rep->msg, "pipe failed");
    else if (o != WW_CHILD_REPORTED)
        snprintf(rep->msg, sizeof rep->msg, "benchmark child died (status %d)", end.status);
}

typedef struct gpu_table {
    int ran;                              /* at least one configuration ran */
    char note[200];                       /* why (c) was skipped or what failed */
    char renderer[128];
    double ms[2][NGPU_COUNTS];            /* [fade on, fade off][count], NAN when not run */
} gpu_table;

static void part_gpu(const config *cf, int json, FILE *to, gpu_table *g) {
    static const int tiny_counts[] = {0, 8};
    const int *counts = cf->tiny ? tiny_counts : gpu_counts;
    int ncounts = cf->tiny ? 2 : NGPU_COUNTS;
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < NGPU_COUNTS; k++) g->ms[a][k] = NAN;
    if (!json)
        fprintf(to, "(c) GPU frame at %dx%d: ms per frame (water + sky + tone map, glFinish), median "
                    "of %d after %d warm-up\n", cf->gpu_w, cf->gpu_h, cf->gpu_frames, cf->gpu_warmup);
    int header = 0;
    double flat_ms = NAN;
    for (int k = 0; k < ncounts; k++) {
        for (int fade = 1; fade >= 0; fade--) {
            if (counts[k] == 0 && !fade) continue; /* nothing to fade on a flat sea */
            gpu_report rep;
            gpu_run(cf, counts[k], fade, &rep);
            if (rep.no_backend) {
                snprintf(g->note, sizeof g->note, "skipped: no GL backend opens here (%.150s)", rep.msg);
                if (json) {
                    fputs("{\"part\":\"gpu\",\"skipped\":", to);
                    ww_json_string(to, g->note);
                    fputs("}\n", to);
                } else {
                    fprintf(to, "%s\n\n", g->note);
                }
                return;
            }
            if (!rep.ok) {
                snprintf(g->note, sizeof g->note, "%d components: %.150s", counts[k], rep.msg);
                if (json) {
                    fprintf(to, "{\"part\":\"gpu\",\"components\":%d,\"fade\":%d,\"error\":",
                            counts[k], fade);
                    ww_json_string(to, rep.msg);
                    fputs("}\n", to);
                } else {
                    fprintf(to, "%5d %-4s failed: %s\n", counts[k], fade ? "on" : "off", rep.msg);
                }
                continue;
            }
            g->ran = 1;
            snprintf(g->renderer, sizeof g->renderer, "%s", rep.renderer);
            if (counts[k] == 0) flat_ms = rep.ms;
            int slot = 0;
            for (int s = 0; s < NGPU_COUNTS; s++)
                if (gpu_counts[s] == counts[k]) slot = s;
            g->ms[fade ? 0 : 1][slot] = rep.ms;
            double waves_ms = rep.ms - flat_ms;
            if (json) {
                fputs("{\"part\":\"gpu\",\"backend\":", to);
                ww_json_string(to, rep.backend);
                fputs(",\"renderer\":", to);
                ww_json_string(to, rep.renderer);
                fprintf(to,
                        ",\"width\":%d,\"height\":%d,\"components\":%d,\"fade\":%d,\"frames\":%d,"
                        "\"ms\":%.4f,\"ms_min\":%.4f,\"waves_ms\":%.4f}\n",
                        cf->gpu_w, cf->gpu_h, counts[k], fade, rep.frames, rep.ms, rep.ms_min,
                        isfinite(waves_ms) ? waves_ms : 0.0);
            } else {
                if (!header) {
                    fprintf(to, "on %s: %s\n", rep.backend, rep.renderer);
                    fprintf(to, "%5s %-4s | %9s %9s | %9s\n", "comps", "fade", "ms", "min ms",
                            "waves ms");
                    header = 1;
                }
                fprintf(to, "%5d %-4s | %9.3f %9.3f | %9.3f\n", counts[k],
                        counts[k] == 0 ? "-" : fade ? "on" : "off", rep.ms, rep.ms_min,
                        isfinite(waves_ms) ? waves_ms : 0.0);
            }
            fflush(to);
        }
    }
    if (!json)
        fprintf(to, "0 components: the flat sea (mesh and shading, no waves); waves ms: ms minus "
                    "that; fade off: WW_WATER_FADE=0\n\n");
}

/* ---- the figure ------------------------------------------------------------------------------ */

#define FIG_W 1280
#define FIG_H 520

static ww_result write_figure(const char *dir, const gpu_table *g,
                              cpu_row rows[NCPU_MODELS][NCPU_COUNTS], char *path, size_t cap,
                              ww_error *err) {
    ww_result r = ww_make_dirs(dir, err);
    if (r) return r;
    snprintf(path, cap, "%s/waves.png", dir);
    ww_image im;
    if (ww_image_alloc(&im, FIG_W, FIG_H, 3, WW_PIX_U8))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the figure");
    ww_plot_fill(&im, WW_PLOT_WHITE);

    /* left: GPU ms against components, fade on and off (the flat sea has no place on a log axis) */
    double gx[NGPU_COUNTS];
    for (int k = 0; k < NGPU_COUNTS; k++) gx[k] = gpu_counts[k];
    char title[96];
    snprintf(title, sizeof title, "GPU frame, %.36s", g->ran ? g->renderer : "no GL backend");
    ww_plot gp = {.title = title, .xlabel = "wave components", .ylabel = "ms per frame",
                  .log_x = 1, .log_y = 1, .nxticks = NGPU_COUNTS - 1,
                  .note = g->ran ? NULL : "skipped: no GL backend"};
    for (int k = 1; k < NGPU_COUNTS; k++) gp.xticks[k - 1] = gpu_counts[k];
    ww_plot_add(&gp, "fade on", gx, g->ms[0], NGPU_COUNTS, WW_PLOT_BLUE);
    ww_plot_add(&gp, "fade off", gx, g->ms[1], NGPU_COUNTS, WW_PLOT_ORANGE);
    ww_plot_draw(&gp, &im, 0, 0, FIG_W / 2, FIG_H);

    /* right: CPU ns per point against components */
    double cx[NCPU_COUNTS], y[5][NCPU_COUNTS];
    for (int k = 0; k < NCPU_COUNTS; k++) {
        cx[k] = cpu_counts[k];
        y[0][k] = rows[0][k].ns_double;
        y[1][k] = rows[0][k].ns_float;
        y[2][k] = rows[1][k].ns_double;
        y[3][k] = rows[2][k].ns_double;
        y[4][k] = rows[0][k].ns_sincos;
    }
    ww_plot cp = {.title = "CPU evaluation (point + normal)", .xlabel = "wave components",
                  .ylabel = "ns per point", .log_x = 1, .log_y = 1, .nxticks = NCPU_COUNTS};
    for (int k = 0; k < NCPU_COUNTS; k++) cp.xticks[k] = cpu_counts[k];
    ww_plot_add(&cp, "gerstner double", cx, y[0], NCPU_COUNTS, WW_PLOT_BLUE);
    ww_plot_add(&cp, "gerstner float", cx, y[1], NCPU_COUNTS, WW_PLOT_ORANGE);
    ww_plot_add(&cp, "sines double", cx, y[2], NCPU_COUNTS, WW_PLOT_GREEN);
    ww_plot_add(&cp, "steep sines double", cx, y[3], NCPU_COUNTS, WW_PLOT_PURPLE);
    ww_plot_add(&cp, "libm sincos calls", cx, y[4], NCPU_COUNTS, WW_PLOT_RED);
    ww_plot_draw(&cp, &im, FIG_W / 2, 0, FIG_W / 2, FIG_H);

    r = ww_write_png(path, &im, err);
    ww_image_free(&im);
    return r;
}

ww_result ww_bench_waves(const ww_bench_waves_opts *o, FILE *to, ww_error *err) {
    config cf = make_config(o->tiny);
    const char *dir = o->out_dir ? o->out_dir : "out/bench";
    ww_scene *sc = malloc(sizeof *sc);
    double *work = malloc(3 * (size_t)cf.query_points * sizeof *work);
    cpu_row rows[NCPU_MODELS][NCPU_COUNTS];
    gpu_table g = {0};
    ww_result r = WW_OK;
    if (!sc || !work) {
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bench waves: out of memory");
        goto done;
    }
    if ((r = part_cpu(sc, &cf, o->json, to, rows, err))) goto done;
    part_queries(sc, &cf, o->json, to, work);
    part_gpu(&cf, o->json, to, &g);

    char path[700];
    if ((r = write_figure(dir, &g, rows, path, sizeof path, err))) goto done;
    if (o->json) {
        fputs("{\"part\":\"figure\",\"path\":", to);
        ww_json_string(to, path);
        fputs("}\n", to);
    } else {
        fprintf(to, "figure: %s\n", path);
    }
done:
    free(work);
    free(sc);
    return r;
}
