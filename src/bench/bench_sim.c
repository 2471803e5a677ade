/* bench_sim.c - `waterworld bench sim`: the simulation alone, measured and printed (never
 * asserted). Three parts:
 *   speed   steps per second and simulated seconds per wall second of each scene, over its own
 *           run (the steps `simulate SCENE` takes) repeated from step 0, and the lake's against
 *           the simulation's speed target;
 *   systems each scene's step by system: the same run with each system's work timed on its own
 *           (ww_step_probe), us a step and share;
 *   dt      the error of named metrics at dt = 1/30, 1/60, 1/120, 1/240 against a dt = 1/1920
 *           reference of the same scene, next to the steps per second of each: cube heave (y of
 *           cube 0), boat position (x, z) and stone paths (each stone's position), compared at
 *           common times (every 1/30 s, a step of every dt), as a table and the figure
 *           DIR/sim.png (error and speed against 1 / dt, log-log). A contact between two
 *           moving bodies (a stone against a cube or the boat, the boat against a cube, a press)
 *           is resolved against the other body as it stands at that step, so what follows
 *           depends on the step it lands on, not on the integrator's order: comparing events
 *           (the k-th landing) or the whole run mixed that in and gave errors of cm and m that
 *           did not shrink with dt. So a body is compared until its first such contact in either
 *           run (cube 0: a press of it, a stone thud on a cube, the boat within reach; a stone:
 *           its first thud), and only while it flies (stones); the table says how long that is.
 *           Crossings of the water (skips, sinks) are solved inside the step and stay in;
 *   columns for the first scene of the dt table with archimedes cubes, each column count a
 *           side (objects.cubes[].columns): the exact queries a box takes, the submerged volume
 *           and its moment against a fine grid of exact queries (sample boxes of 0.6-1.2 m at
 *           their draft, tilted up to 25 degrees, on the scene's sea), and the scene's run with
 *           every such cube at that count, in us a step: the knob's speed against its error;
 *   share   the simulation's share of a frame of scenes/demo.yaml (sim ms / render ms, target
 *           under 1%), from one render job in a child process (bench.c).
 * Metrics read state fields by name (render/sim_out.h), so they follow the X-macro tables; a
 * metric whose system the scene lacks is skipped ("-"). The script's events fire on the first
 * step at or after their time, so part of a coarse dt's error is that up-to-one-step delay.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench/bench.h"
#include "bench/plot.h"
#include "core/mathx.h"
#include "core/rng.h"
#include "io/json.h"
#include "io/writers.h"
#include "render/sim_out.h"
#include "scene/scene.h"
#include "sim/boxwater.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/systems.h"
#include "sim/water.h"
#include "sim/waves.h"

#define NDT 4
static const int DT_DIVS[NDT] = {30, 60, 120, 240}; /* dt = 1 / div, s */
#define REF_DIV 1920           /* the reference's dt = 1/1920 s: 8x finer than the finest row */
#define SAMPLE_DIV 30          /* metrics compared at start + k / 30 s, a step of every dt */
#define DT_SECONDS 20.0        /* simulated seconds of a dt run (at most the scene's duration) */
#define DT_SECONDS_TINY 1.0
#define SPEED_WALL_S 0.5       /* a speed row steps until this much wall time has passed */
#define SPEED_WALL_S_TINY 0.02
#define SPEED_CHUNK 500        /* steps between clock reads */
#define SHARE_FRAMES 20        /* frames rendered for the share (bench --frames changes it) */
#define NMETRICS 3

static const char *const METRIC_NAMES[NMETRICS] = {"cube heave", "boat position", "stone path"};

/* the rows of the dt table: each integrator of time.integrator (scene.h), the reference exact */
#define NINTEG 2
static const char *const INTEGRATORS[NINTEG] = {"exact", "euler"};

static const char *base_name(const char *path) {
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* ---- speed --------------------------------------------------------------------------------- */

/* the simulation's speed target (x real time) and the scene it is measured on */
#define SPEED_TARGET_SCENE "lake.yaml"
#define SPEED_TARGET_RATIO 2000.0

/* the steps `simulate SCENE` takes (to its last frame), run again from step 0 until budget s of
 * wall time are spent; the resets between runs are not timed. *steps taken in *wall s. With a
 * probe (the systems' breakdown below) each step is ww_step_probed */
static ww_result time_run_probed(const ww_scene *sc, ww_state *st, const ww_step_probe *probe,
                                 double budget, double *steps, double *wall, ww_error *err) {
    int64_t run = (sc->frame_count - 1) * sc->steps_per_frame;
    if (run < 1) run = SPEED_CHUNK;
    ww_result r = WW_OK;
    *wall = *steps = 0.0;
    while (!r && *wall < budget) {
        if (st->step >= run) ww_state_reset(sc, st);
        int64_t from = st->step, to_step = from + SPEED_CHUNK < run ? from + SPEED_CHUNK : run;
        double t0 = ww_now_seconds();
        if (probe)
            while (!r && st->step < to_step) r = ww_step_probed(sc, st, probe, err);
        else
            r = ww_sim_advance_to(sc, st, to_step, err);
        *wall += ww_now_seconds() - t0;
        *steps += (double)(st->step - from);
    }
    return r;
}
static ww_result time_run(const ww_scene *sc, ww_state *st, double budget, double *steps,
                          double *wall, ww_error *err) {
    return time_run_probed(sc, st, NULL, budget, steps, wall, err);
}

/* the scene at path and a state at its step 0 */
static ww_result load_with_state(const char *path, ww_scene **sc, ww_state **st, ww_error *err) {
    *sc = NULL;
    *st = NULL;
    ww_result r = ww_scene_load(path, NULL, 0, sc, err);
    if (r) return r;
    *st = ww_state_new(*sc);
    if (*st) return WW_OK;
    ww_scene_free(*sc);
    *sc = NULL;
    return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory");
}

static ww_result part_speed(const ww_bench_opts *o, const char *const *scenes, FILE *to,
                            ww_error *err) {
    double budget = o->tiny ? SPEED_WALL_S_TINY : SPEED_WALL_S;
    double target_ratio = -1.0;
    if (!o->json)
        fprintf(to, "speed: steps of the whole simulation (every system the scene has), the "
                    "scene's run from step 0 repeated\n"
                    "%-16s %10s %12s %12s %14s %10s\n",
                "scene", "steps", "us/step", "steps/s", "sim s/wall s", "state B");
    for (int s = 0; scenes[s]; s++) {
        ww_scene *sc;
        ww_state *st;
        ww_result r = load_with_state(scenes[s], &sc, &st, err);
        if (r) return r;
        int64_t run = (sc->frame_count - 1) * sc->steps_per_frame;
        if (run < 1) run = SPEED_CHUNK;
        double wall, steps;
        r = time_run(sc, st, budget, &steps, &wall, err);
        double us = 1e6 * wall / steps;
        double ratio = steps * sc->dt / wall;
        if (!r && strcmp(base_name(scenes[s]), SPEED_TARGET_SCENE) == 0) target_ratio = ratio;
        if (!r && o->json)
            fprintf(to, "{\"part\":\"speed\",\"scene\":\"%s\",\"steps\":%.0f,\"run_steps\":%lld,"
                        "\"dt\":%.9g,\"us_per_step\":%.4f,\"steps_per_s\":%.1f,"
                        "\"sim_s_per_wall_s\":%.2f,\"state_bytes\":%zu}\n",
                    base_name(scenes[s]), steps, (long long)run, sc->dt, us, 1e6 / us, ratio,
                    st->bytes);
        else if (!r)
            fprintf(to, "%-16s %10.0f %12.3f %12.0f %14.1f %10zu\n", base_name(scenes[s]), steps,
                    us, 1e6 / us, ratio, st->bytes);
        ww_state_free(st);
        ww_scene_free(sc);
        if (r) return r;
    }
    if (!o->json && target_ratio >= 0.0)
        fprintf(to, "target: %s at >= %.0fx real time: %.0fx, %s\n", SPEED_TARGET_SCENE,
                SPEED_TARGET_RATIO, target_ratio,
                target_ratio >= SPEED_TARGET_RATIO ? "met" : "missed");
    return WW_OK;
}

/* ---- systems ------------------------------------------------------------------------------- */

/* a step's wall time by part (ww_step_probe): each system's hooks and script events, and the
 * step's own work (index WW_SYS_COUNT), with how many times each ran */
typedef struct part_times {
    double t0;
    double seconds[WW_SYS_COUNT + 1];
    int64_t calls[WW_SYS_COUNT + 1];
} part_times;

static void times_enter(void *ctx, int id) {
    (void)id;
    ((part_times *)ctx)->t0 = ww_now_seconds();
}
static void times_leave(void *ctx, int id) {
    part_times *t = ctx;
    t->seconds[id] += ww_now_seconds() - t->t0;
    t->calls[id]++;
}

#define PROBE_CALIBRATION 20000 /* empty enter/leave pairs a round */
#define PROBE_ROUNDS 5

/* what the probe records for a part that does nothing (a clock read and the bookkeeping), s a
 * call: the least of a few rounds' means, taken out of every part's time */
static double probe_cost(void) {
    double least = INFINITY;
    for (int round = 0; round < PROBE_ROUNDS; round++) {
        part_times t = {0};
        for (int k = 0; k < PROBE_CALIBRATION; k++) {
            times_enter(&t, 0);
            times_leave(&t, 0);
        }
        least = fmin(least, t.seconds[0] / PROBE_CALIBRATION);
    }
    return least;
}

/* each scene's step by system: its run (as the speed rows) with every part of each step timed
 * on its own, the probe's cost taken out; a part's share is of the parts' sum. The clock reads
 * around the parts slow the run, so the sum is a little above the speed row's us/step */
static ww_result part_systems(const ww_bench_opts *o, const char *const *scenes, FILE *to,
                              ww_error *err) {
    double budget = o->tiny ? SPEED_WALL_S_TINY : SPEED_WALL_S, cost = probe_cost();
    if (!o->json)
        fprintf(to, "\nsystems: the step's time by system (each system's work timed on its "
                    "own, the timer's %.0f ns a call taken out); step: the step's own work (the "
                    "outbox, the NaN guard)\n%-16s %-10s %12s %8s\n",
                1e9 * cost, "scene", "system", "us/step", "share");
    int nrows;
    const ww_system_row *rows = ww_systems(&nrows);
    for (int s = 0; scenes[s]; s++) {
        ww_scene *sc;
        ww_state *st;
        ww_result r = load_with_state(scenes[s], &sc, &st, err);
        if (r) return r;
        part_times t = {0};
        ww_step_probe probe = {.enter = times_enter, .leave = times_leave, .ctx = &t};
        double steps, wall;
        r = time_run_probed(sc, st, &probe, budget, &steps, &wall, err);
        ww_state_free(st);
        if (r) {
            ww_scene_free(sc);
            return r;
        }
        /* the parts in the order a step runs them (the table's), the step's own work last */
        int ids[WW_SYS_COUNT + 1], n = 0;
        for (int i = 0; i < nrows; i++)
            if (ww_system_runs(sc, &rows[i]) && t.calls[rows[i].id] > 0) ids[n++] = rows[i].id;
        ids[n++] = WW_SYS_COUNT;
        double us[WW_SYS_COUNT + 1], sum = 0.0;
        for (int k = 0; k < n; k++) {
            int id = ids[k];
            us[k] = fmax(0.0, 1e6 * (t.seconds[id] - cost * (double)t.calls[id]) / steps);
            sum += us[k];
        }
        for (int k = 0; k < n; k++) {
            const char *name = ids[k] == WW_SYS_COUNT ? "step" : ww_system_name(ids[k]);
            double share = sum > 0.0 ? us[k] / sum : 0.0;
            if (o->json)
                fprintf(to, "{\"part\":\"systems\",\"scene\":\"%s\",\"system\":\"%s\","
                            "\"us_per_step\":%.4f,\"share\":%.4f,\"calls_per_step\":%.3f}\n",
                        base_name(scenes[s]), name, us[k], share,
                        (double)t.calls[ids[k]] / steps);
            else
                fprintf(to, "%-16s %-10s %12.3f %7.1f%%\n", k == 0 ? base_name(scenes[s]) : "",
                        name, us[k], 100.0 * share);
        }
        if (!o->json) fprintf(to, "%-16s %-10s %12.3f\n", "", "sum", sum);
        ww_scene_free(sc);
    }
    return WW_OK;
}

/* ---- one run at one dt --------------------------------------------------------------------- */

typedef struct run {
    int div;                 /* dt = 1 / div */
    int64_t steps;
    double wall_s;
    int nsamples;
    int has[NMETRICS];       /* the scene has the metric's system */
    double *heave;           /* y of cube 0 at each sample, m */
    double *boat;            /* boat (x, z) at each sample, m */
    double *stone;           /* each stone's position at each sample, m (sample x stone x 3) */
    unsigned char *flying;   /* each stone flies at each sample (sample x stone) */
    double cube_contact;     /* time of cube 0's first contact with a moving body, s (inf: none) */
    double stone_contact[WW_MAX_STONES]; /* time of each stone's first thud, s */
} run;

static void run_free(run *u) {
    free(u->heave);
    free(u->boat);
    free(u->stone);
    free(u->flying);
    u->heave = u->boat = u->stone = NULL;
    u->flying = NULL;
}

/* the metrics of this state into sample k */
static void sample(const ww_scene *sc, const ww_state *st, run *u, int k) {
    long long n = 0;
    const double *p = ww_state_field(sc, st, "cube_pos", &n);
    if (u->has[0]) u->heave[k] = p[1];
    p = ww_state_field(sc, st, "boat_pos", &n);
    if (u->has[1]) {
        u->boat[2 * k] = p[0];
        u->boat[2 * k + 1] = p[2];
    }
    if (!u->has[2]) return;
    for (int i = 0; i < WW_MAX_STONES; i++) {
        size_t at = (size_t)k * WW_MAX_STONES + (size_t)i;
        for (int a = 0; a < 3; a++) u->stone[3 * at + a] = st->stone_pos[3 * i + a];
        u->flying[at] = st->stone_state[i] == 1.0;
    }
}

/* the contacts between moving bodies of this step: cube 0 pressed, a stone's thud (on a cube:
 * cube 0's too, the event does not say which), the boat within reach of cube 0 */
static void contacts(const ww_scene *sc, const ww_state *st, run *u) {
    int n = ww_events_count(sc, st);
    for (int i = 0; i < n; i++) {
        const double *e = st->events + i * WW_SIM_EVENT_STRIDE;
        int kind = (int)e[0], obj = (int)e[1];
        if (kind == WW_SE_CUBE_PRESS && obj == 0) u->cube_contact = fmin(u->cube_contact, st->t);
        if (kind != WW_SE_STONE_THUD) continue;
        if (e[6] == 0.0) u->cube_contact = fmin(u->cube_contact, st->t);
        if (obj >= 0 && obj < WW_MAX_STONES)
            u->stone_contact[obj] = fmin(u->stone_contact[obj], st->t);
    }
    if (u->has[0] && sc->boat.on) {
        double d[3], reach = sc->boat.radius + 0.5 * sqrt(3.0) * sc->cubes.cube[0].size;
        for (int a = 0; a < 3; a++) d[a] = st->boat_pos[a] - st->cube_pos[a];
        if (sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) < reach)
            u->cube_contact = fmin(u->cube_contact, st->t);
    }
}

static ww_result run_dt(const char *path, int div, int integ, double seconds, run *u,
                        ww_error *err) {
    char dt_set[64], integ_set[64];
    snprintf(dt_set, sizeof dt_set, "time.dt=1/%d", div);
    snprintf(integ_set, sizeof integ_set, "time.integrator=%s", INTEGRATORS[integ]);
    ww_set sets[3] = {{dt_set}, {"time.fps=30"}, {integ_set}};
    ww_scene *sc = NULL;
    *u = (run){.div = div};
    ww_result r = ww_scene_load(path, sets, 3, &sc, err);
    if (r) return r;
    ww_state *st = ww_state_new(sc);
    u->nsamples = (int)floor(seconds * SAMPLE_DIV) + 1;
    u->heave = calloc((size_t)u->nsamples, sizeof *u->heave);
    u->boat = calloc(2 * (size_t)u->nsamples, sizeof *u->boat);
    u->stone = calloc(3 * (size_t)u->nsamples * WW_MAX_STONES, sizeof *u->stone);
    u->flying = calloc((size_t)u->nsamples * WW_MAX_STONES, sizeof *u->flying);
    u->cube_contact = INFINITY;
    for (int i = 0; i < WW_MAX_STONES; i++) u->stone_contact[i] = INFINITY;
    if (!st || !u->heave || !u->boat || !u->stone || !u->flying) {
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bench sim: out of memory");
        goto done;
    }
    long long n = 0;
    u->has[0] = ww_state_field(sc, st, "cube_pos", &n) && n >= 3;
    u->has[1] = ww_state_field(sc, st, "boat_pos", &n) && n >= 3;
    u->has[2] = sc->stones.on;
    int per_sample = div / SAMPLE_DIV;
    u->steps = (int64_t)(u->nsamples - 1) * per_sample;
    double t0 = ww_now_seconds();
    sample(sc, st, u, 0);
    contacts(sc, st, u);
    while (!r && st->step < u->steps) {
        r = ww_step(sc, st, err);
        if (r) break;
        contacts(sc, st, u);
        if (st->step % per_sample == 0) sample(sc, st, u, (int)(st->step / per_sample));
    }
    u->wall_s = ww_now_seconds() - t0;
done:
    ww_state_free(st);
    ww_scene_free(sc);
    return r;
}

/* max over the common samples of the distance to the reference's, each body until its first
 * contact with a moving body in either run (stones: while flying in both); -1 when skipped.
 * *unpaired counts stone samples flying in one run only (a flight ends a step apart) */
static double metric_error(const run *u, const run *ref, int m, int *unpaired) {
    if (!u->has[m]) return -1;
    double e = 0;
    if (m == 0) {
        double until = fmin(u->cube_contact, ref->cube_contact);
        for (int k = 0; k < u->nsamples && (double)k / SAMPLE_DIV < until; k++)
            e = fmax(e, fabs(u->heave[k] - ref->heave[k]));
    }
    if (m == 1)
        for (int k = 0; k < u->nsamples; k++)
            e = fmax(e, hypot(u->boat[2 * k] - ref->boat[2 * k],
                              u->boat[2 * k + 1] - ref->boat[2 * k + 1]));
    if (m == 2) {
        *unpaired = 0;
        for (int i = 0; i < WW_MAX_STONES; i++) {
            double until = fmin(u->stone_contact[i], ref->stone_contact[i]);
            for (int k = 0; k < u->nsamples && (double)k / SAMPLE_DIV < until; k++) {
                size_t at = (size_t)k * WW_MAX_STONES + (size_t)i;
                if (u->flying[at] != ref->flying[at]) (*unpaired)++;
                if (!u->flying[at] || !ref->flying[at]) continue;
                const double *a = u->stone + 3 * at, *b = ref->stone + 3 * at;
                double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
                e = fmax(e, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
            }
        }
    }
    return e;
}

/* ---- the dt table and its figure ----------------------------------------------------------- */

typedef struct dt_table {
    double dt[NDT], rate[NDT];                          /* rate: 1 / dt, Hz */
    double steps_per_s[NINTEG][NDT], err[NINTEG][NMETRICS][NDT];
    double ref_steps_per_s;
    int has[NMETRICS];
} dt_table;

static void print_metric(FILE *to, double e, int unpaired, int with_unpaired) {
    if (e < 0) {
        fprintf(to, " %16s", "-");
        return;
    }
    if (!with_unpaired) {
        fprintf(to, " %16.3e", e);
        return;
    }
    char cell[40];
    snprintf(cell, sizeof cell, "%.3e (%d)", e, unpaired);
    fprintf(to, " %16s", cell);
}

static ww_result part_dt(const ww_bench_opts *o, const char *path, dt_table *tab, FILE *to,
                         ww_error *err) {
    ww_scene *sc = NULL;
    ww_result r = ww_scene_load(path, NULL, 0, &sc, err);
    if (r) return r;
    double seconds = fmin(sc->duration, o->tiny ? DT_SECONDS_TINY : DT_SECONDS);
    ww_scene_free(sc);

    run ref = {0}, u = {0};
    if ((r = run_dt(path, REF_DIV, 0, seconds, &ref, err))) {
        run_free(&ref);
        return r;
    }
    memset(tab, 0, sizeof *tab);
    tab->ref_steps_per_s = (double)ref.steps / ref.wall_s;
    for (int m = 0; m < NMETRICS; m++) tab->has[m] = ref.has[m];
    if (!o->json) {
        fprintf(to, "\ndt: %s, %.3g s simulated, error against dt = 1/%d (%.0f steps/s); "
                    "max over samples every 1/%d s\n",
                base_name(path), seconds, REF_DIV, tab->ref_steps_per_s, SAMPLE_DIV);
        fprintf(to, "%-6s %-8s %12s %12s |", "integ", "dt", "steps/s", "sim s/wall s");
        for (int m = 0; m < NMETRICS; m++) fprintf(to, " %14s m", METRIC_NAMES[m]);
        fputc('\n', to);
    }
    for (int g = 0; g < NINTEG && !r; g++) {
        for (int d = 0; d < NDT && !r; d++) {
            if ((r = run_dt(path, DT_DIVS[d], g, seconds, &u, err))) break;
            tab->dt[d] = 1.0 / DT_DIVS[d];
            tab->rate[d] = DT_DIVS[d];
            tab->steps_per_s[g][d] = (double)u.steps / u.wall_s;
            int unpaired = 0;
            for (int m = 0; m < NMETRICS; m++)
                tab->err[g][m][d] = metric_error(&u, &ref, m, &unpaired);
            double cube_s = fmin(seconds, fmin(u.cube_contact, ref.cube_contact));
            double sps = tab->steps_per_s[g][d];
            if (o->json) {
                fprintf(to, "{\"part\":\"dt\",\"scene\":\"%s\",\"integrator\":\"%s\",\"dt\":%.9g,"
                            "\"reference_dt\":%.9g,\"seconds\":%.6g,\"steps_per_s\":%.1f,"
                            "\"sim_s_per_wall_s\":%.2f",
                        base_name(path), INTEGRATORS[g], tab->dt[d], 1.0 / REF_DIV, seconds, sps,
                        sps * tab->dt[d]);
                static const char *const keys[NMETRICS] = {"cube_heave_m", "boat_position_m",
                                                           "stone_path_m"};
                for (int m = 0; m < NMETRICS; m++) {
                    if (tab->err[g][m][d] < 0)
                        fprintf(to, ",\"%s\":null", keys[m]);
                    else
                        fprintf(to, ",\"%s\":%.6e", keys[m], tab->err[g][m][d]);
                }
                fprintf(to, ",\"cube_compared_s\":%.6g,\"stone_samples_unpaired\":%d}\n",
                        tab->has[0] ? cube_s : 0.0, unpaired);
            } else {
                char dts[16];
                snprintf(dts, sizeof dts, "1/%d", DT_DIVS[d]);
                fprintf(to, "%-6s %-8s %12.0f %12.1f |", INTEGRATORS[g], dts, sps, sps * tab->dt[d]);
                for (int m = 0; m < NMETRICS; m++)
                    print_metric(to, tab->err[g][m][d], unpaired, m == 2);
                if (tab->has[0]) fprintf(to, "  cube to %.4g s", cube_s);
                fputc('\n', to);
            }
            run_free(&u);
        }
    }
    run_free(&u);
    run_free(&ref);
    if (!r && !o->json)
        fputs("at common times: cube heave: |y - y_ref| of cube 0 until its first contact with\n"
              "a moving body in either run (a press of it, a stone on a cube, the boat within\n"
              "reach: 'cube to' says when); boat position: XZ distance; stone path: distance of\n"
              "each stone while it flies in both runs, until its first thud (n: samples flying\n"
              "in one run only); '-': the scene has no such system; integ: time.integrator\n"
              "(exact: closed forms and the energy-keeping midpoint rule; euler: the seeds'\n"
              "semi-implicit Euler); the reference is exact\n",
              to);
    return r;
}

#define FIG_W 1200
#define FIG_H 480

static ww_result write_figure(const char *dir, const char *scene, const dt_table *tab,
                              char *path, size_t cap, ww_error *err) {
    ww_result r = ww_make_dirs(dir, err);
    if (r) return r;
    snprintf(path, cap, "%s/sim.png", dir);
    ww_image im;
    if (ww_image_alloc(&im, FIG_W, FIG_H, 3, WW_PIX_U8))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the figure");
    ww_plot_fill(&im, WW_PLOT_WHITE);

    /* left: each metric's error against dt */
    const ww_plot_rgb colors[NMETRICS] = {WW_PLOT_BLUE, WW_PLOT_ORANGE, WW_PLOT_GREEN};
    char title[96];
    snprintf(title, sizeof title, "error against dt = 1/%d, %.40s", REF_DIV, scene);
    int any = 0;
    for (int m = 0; m < NMETRICS; m++) any |= tab->has[m];
    ww_plot ep = {.title = title, .xlabel = "steps per simulated second (1 / dt)", .ylabel = "max error, m", .log_x = 1,
                  .log_y = 1, .nxticks = NDT,
                  .note = any ? NULL : "no cubes, boat or stones in the scene"};
    for (int d = 0; d < NDT; d++) ep.xticks[d] = tab->rate[d];
    const ww_plot_rgb euler_colors[NMETRICS] = {WW_PLOT_RED, WW_PLOT_PURPLE, WW_PLOT_BROWN};
    char names[NINTEG][NMETRICS][48];
    for (int g = 0; g < NINTEG; g++)
        for (int m = 0; m < NMETRICS; m++) {
            if (!tab->has[m]) continue;
            snprintf(names[g][m], sizeof names[g][m], "%s, %s", METRIC_NAMES[m], INTEGRATORS[g]);
            ww_plot_add(&ep, names[g][m], tab->rate, tab->err[g][m], NDT,
                        g == 0 ? colors[m] : euler_colors[m]);
        }
    ww_plot_draw(&ep, &im, 0, 0, FIG_W / 2, FIG_H);

    /* right: the speed bought by each dt */
    ww_plot sp = {.title = "simulation speed", .xlabel = "steps per simulated second (1 / dt)", .ylabel = "steps per second",
                  .log_x = 1, .log_y = 1, .nxticks = NDT};
    for (int d = 0; d < NDT; d++) sp.xticks[d] = tab->rate[d];
    ww_plot_add(&sp, "exact", tab->rate, tab->steps_per_s[0], NDT, WW_PLOT_BLUE);
    ww_plot_add(&sp, "euler", tab->rate, tab->steps_per_s[1], NDT, WW_PLOT_RED);
    ww_plot_draw(&sp, &im, FIG_W / 2, 0, FIG_W / 2, FIG_H);

    r = ww_write_png(path, &im, err);
    ww_image_free(&im);
    return r;
}

/* ---- the share of a frame ------------------------------------------------------------------ */

static void part_share(const ww_bench_opts *o, FILE *to) {
    static const char demo[] = "scenes/demo.yaml";
    int frames = o->frames > 0 ? o->frames : SHARE_FRAMES;
    ww_job_stats s;
    ww_error err = {0};
    if (frames < 2) frames = 2;
    if (ww_bench_render_once(demo, 1280, 720, frames, &s, &err) != WW_OK) {
        if (o->json) {
            fputs("{\"part\":\"share\",\"scene\":\"demo.yaml\",\"error\":", to);
            ww_json_string(to, err.msg);
            fputs("}\n", to);
        } else {
            fprintf(to, "\nshare of a frame: unavailable: %s\n", err.msg);
        }
        return;
    }
    /* the first frame pays for shader compilation: left out, as bench render does */
    double n = (double)s.frames;
    double sim = 1e3 * s.sim_s / n, ren = 1e3 * (s.render_s - s.first_render_s) / (n - 1);
    double share = 100.0 * sim / ren;
    if (o->json)
        fprintf(to, "{\"part\":\"share\",\"scene\":\"demo.yaml\",\"backend\":\"%s\",\"frames\":%lld,"
                    "\"sim_ms\":%.5f,\"render_ms\":%.4f,\"share_percent\":%.4f}\n",
                s.backend, (long long)s.frames, sim, ren, share);
    else
        fprintf(to, "\nshare of a frame, demo.yaml at 1280x720 on %s (%s), %lld frames: sim %.4f ms, "
                    "render %.3f ms: %.3f%% (target < 1%%)\n",
                s.backend, s.renderer, (long long)s.frames, sim, ren, share);
}

/* ---- columns ------------------------------------------------------------------------------- */

static const int COLUMN_COUNTS[] = {1, 2, 3, 4, 5, 6, 8};
#define NCOLUMN_COUNTS ((int)(sizeof COLUMN_COUNTS / sizeof COLUMN_COUNTS[0]))
#define COLUMN_BOXES 60        /* sample boxes of the error (tiny: COLUMN_BOXES_TINY) */
#define COLUMN_BOXES_TINY 6
#define COLUMN_FINE 32         /* the reference's exact queries a side (tiny: COLUMN_FINE_TINY) */
#define COLUMN_FINE_TINY 12
#define COLUMN_MAX_TILT_DEG 25.0
#define COLUMN_WALL_S 0.25     /* wall time of a count's speed row (tiny: SPEED_WALL_S_TINY) */

/* the submerged volume V and its moment V (c_b - c) of the box of edge s at c turned by q in
 * fine x fine columns, each with an exact surface query at its centre: the reference */
static void fine_volume(const ww_scene *sc, const ww_state *st, int fine, const double c[3],
                        const double q[4], double s, double *V, double M[3]) {
    double ax[3][3];
    ww_box_axes(q, ax);
    int a = ww_box_up_axis(ax);
    double sg = ax[a][1] < 0.0 ? -1.0 : 1.0, U[3] = {sg * ax[a][0], sg * ax[a][1], sg * ax[a][2]};
    const double *P = ax[(a + 1) % 3], *Q = ax[(a + 2) % 3];
    double dA = s * s / (fine * fine);
    *V = M[0] = M[1] = M[2] = 0.0;
    for (int i = 0; i < fine; i++)
        for (int j = 0; j < fine; j++) {
            double u = ((i + 0.5) / fine - 0.5) * s, v = ((j + 0.5) / fine - 0.5) * s;
            double r[3] = {u * P[0] + v * Q[0], u * P[1] + v * Q[1], u * P[2] + v * Q[2]};
            ww_water_sample ws;
            ww_water_at(sc, st, c[0] + r[0], c[2] + r[2], 0.0, &ws);
            double L = ww_m_clamp((ws.height - (c[1] + r[1])) / U[1] + 0.5 * s, 0.0, s);
            *V += dA * L;
            for (int k = 0; k < 3; k++) M[k] += dA * L * (r[k] + 0.5 * (L - s) * U[k]);
        }
}

/* the largest volume (/ s^3) and moment (/ s^4) error of each column count over the sample
 * boxes, on sc's sea */
static void column_errors(const ww_scene *sc, ww_state *st, int tiny, double *ev, double *em) {
    static const double sizes[4] = {0.6, 0.8, 1.0, 1.2}, dens[3] = {0.4, 0.6, 0.85};
    int boxes = tiny ? COLUMN_BOXES_TINY : COLUMN_BOXES;
    int fine = tiny ? COLUMN_FINE_TINY : COLUMN_FINE;
    for (int k = 0; k < NCOLUMN_COUNTS; k++) ev[k] = em[k] = 0.0;
    for (int b = 0; b < boxes; b++) {
        double r[5];
        for (int k = 0; k < 5; k++)
            r[k] = ww_rng_draw(sc->seed, WW_RNG_BENCH, (uint64_t)b, (uint64_t)k);
        st->t = fmax(sc->duration, 1.0) * r[0];
        ww_waves_phases(sc, st->t, st->wave_phase);
        double s = sizes[b % 4], c[3] = {-10.0 + 20.0 * r[1], 0.0, -10.0 + 20.0 * r[2]};
        ww_water_sample ws;
        ww_water_at(sc, st, c[0], c[2], 0.0, &ws);
        c[1] = ws.height + 0.5 * s - dens[b % 3] * s;
        double ang = ww_m_rad(COLUMN_MAX_TILT_DEG) * r[3], az = WW_TAU * r[4];
        double q[4] = {cos(0.5 * ang), sin(0.5 * ang) * cos(az), 0.0, sin(0.5 * ang) * sin(az)};
        double Vr, Mr[3], e[3] = {s, s, s};
        fine_volume(sc, st, fine, c, q, s, &Vr, Mr);
        for (int k = 0; k < NCOLUMN_COUNTS; k++) {
            ww_box_water bw;
            ww_box_water_at(sc, st, c, q, e, COLUMN_COUNTS[k], NULL, &bw);
            double dm[3];
            for (int j = 0; j < 3; j++) dm[j] = bw.volume * (bw.centre[j] - c[j]) - Mr[j];
            ev[k] = fmax(ev[k], fabs(bw.volume - Vr) / (s * s * s));
            em[k] = fmax(em[k], ww_m_len3(dm) / (s * s * s * s));
        }
    }
}

/* the scene's run with every archimedes cube at n columns a side: *us a step */
static ww_result columns_speed(const char *path, int n, double budget, double *us,
                               ww_error *err) {
    ww_scene *sc = NULL;
    ww_result r = ww_scene_load(path, NULL, 0, &sc, err);
    if (r) return r;
    for (int i = 0; i < sc->cubes.count; i++)
        if (sc->cubes.cube[i].buoyancy == WW_CUBE_ARCHIMEDES) sc->cubes.cube[i].columns = n;
    ww_state *st = ww_state_new(sc);
    if (!st) {
        ww_scene_free(sc);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory");
    }
    double wall, steps;
    r = time_run(sc, st, budget, &steps, &wall, err);
    ww_state_free(st);
    ww_scene_free(sc);
    *us = 1e6 * wall / steps;
    return r;
}

/* 1 when the scene has a cube floating by Archimedes */
static int has_archimedes(const ww_scene *sc) {
    for (int i = 0; sc->cubes.on && i < sc->cubes.count; i++)
        if (sc->cubes.cube[i].buoyancy == WW_CUBE_ARCHIMEDES) return 1;
    return 0;
}

/* the columns table of the scene at path, when it has archimedes cubes (*done: it had) */
static ww_result part_columns(const ww_bench_opts *o, const char *path, FILE *to, int *done,
                              ww_error *err) {
    ww_scene *sc = NULL;
    ww_result r = ww_scene_load(path, NULL, 0, &sc, err);
    if (r) return r;
    *done = has_archimedes(sc);
    if (!*done) {
        ww_scene_free(sc);
        return WW_OK;
    }
    ww_state *st = ww_state_new(sc);
    if (!st) {
        ww_scene_free(sc);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory");
    }
    double ev[NCOLUMN_COUNTS], em[NCOLUMN_COUNTS], dt = sc->dt;
    column_errors(sc, st, o->tiny, ev, em);
    ww_state_free(st);
    ww_scene_free(sc);
    int boxes = o->tiny ? COLUMN_BOXES_TINY : COLUMN_BOXES;
    int fine = o->tiny ? COLUMN_FINE_TINY : COLUMN_FINE;
    if (!o->json)
        fprintf(to, "\ncolumns: %s's archimedes cubes at n x n columns "
                    "(objects.cubes[].columns);\nerror of the submerged volume and its moment "
                    "against %d x %d exact queries, largest over\n%d boxes of 0.6-1.2 m at their "
                    "draft tilted up to %.0f deg on its sea; the scene's run at that count\n"
                    "%-8s %8s %16s %16s %10s %14s\n",
                base_name(path), fine, fine, boxes, COLUMN_MAX_TILT_DEG, "columns", "queries",
                "volume err/s^3", "moment err/s^4", "us/step", "sim s/wall s");
    double budget = o->tiny ? SPEED_WALL_S_TINY : COLUMN_WALL_S;
    for (int k = 0; k < NCOLUMN_COUNTS; k++) {
        int n = COLUMN_COUNTS[k], m = ww_box_nodes_per_side(n);
        double us = 0.0;
        if ((r = columns_speed(path, n, budget, &us, err))) return r;
        if (o->json) {
            fprintf(to, "{\"part\":\"columns\",\"scene\":\"%s\",\"columns\":%d,\"queries\":%d,"
                        "\"volume_error\":%.6e,\"moment_error\":%.6e,\"us_per_step\":%.4f,"
                        "\"sim_s_per_wall_s\":%.2f}\n",
                    base_name(path), n, m * m, ev[k], em[k], us, 1e6 * dt / us);
        } else {
            char cols[16];
            snprintf(cols, sizeof cols, "%dx%d%s", n, n, n == WW_CUBE_DEFAULT_COLUMNS ? "*" : "");
            fprintf(to, "%-8s %8d %16.2e %16.2e %10.3f %14.1f\n", cols, m * m, ev[k], em[k], us,
                    1e6 * dt / us);
        }
    }
    if (!o->json)
        fputs("queries: exact surface queries a box (its nodes, interpolated to the columns);\n"
              "*: the default\n",
              to);
    return WW_OK;
}

/* ---- bench sim ----------------------------------------------------------------------------- */

ww_result ww_bench_sim(const ww_bench_opts *o, FILE *to, ww_error *err) {
    /* by default: the plain scenes, and the lake (every system of seed 000) where it exists */
    const char *defaults[4] = {"scenes/minimal.yaml", "scenes/demo.yaml", NULL, NULL};
    static const char lake[] = "scenes/lake.yaml";
    int have_lake = access(lake, R_OK) == 0;
    if (have_lake) defaults[2] = lake;
    const char *const *scenes = o->scenes[0] ? o->scenes : defaults;

    ww_result r = part_speed(o, scenes, to, err);
    if (r) return r;
    if ((r = part_systems(o, scenes, to, err))) return r;

    /* the dt table: each scene named, else the lake */
    const char *const dt_default[2] = {have_lake ? lake : NULL, NULL};
    const char *const *dt_scenes = o->scenes[0] ? o->scenes : dt_default;
    if (!dt_scenes[0] && !o->json)
        fprintf(to, "\ndt: skipped (%s not found; name a scene)\n", lake);
    const char *dir = o->out_dir ? o->out_dir : "out/bench";
    for (int s = 0; dt_scenes[s]; s++) {
        dt_table tab;
        if ((r = part_dt(o, dt_scenes[s], &tab, to, err))) return r;
        if (s > 0) continue;
        char path[700];
        if ((r = write_figure(dir, base_name(dt_scenes[s]), &tab, path, sizeof path, err))) return r;
        if (o->json) {
            fputs("{\"part\":\"figure\",\"path\":", to);
            ww_json_string(to, path);
            fputs("}\n", to);
        } else {
            fprintf(to, "figure: %s\n", path);
        }
    }

    /* the columns table: the first scene of the dt table with archimedes cubes */
    for (int s = 0, done = 0; dt_scenes[s] && !done; s++)
        if ((r = part_columns(o, dt_scenes[s], to, &done, err))) return r;

    if (o->tiny) {
        if (!o->json) fprintf(to, "\nshare of a frame: skipped (--tiny)\n");
        return WW_OK;
    }
    part_share(o, to);
    return WW_OK;
}
