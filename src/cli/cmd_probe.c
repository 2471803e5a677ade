/* cmd_probe.c - `waterworld probe`: the exact water surface (waves and ripples) over world
 * points through time, as CSV. Steps the simulation so script events (ripples) apply; each
 * sample uses the state of the last step at or before its time, with the wave phases taken at
 * exactly that time, and ww_water_height's inversion of the Gerstner displacement.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "sim/waves.h"

#define PROBE_MAX_POINTS 64
#define PROBE_MAX_ROWS 10000000LL /* sample times; more is almost surely a typo in --every */
#define PROBE_TIME_EPS 1e-9       /* of --every: a last sample this close past --to still counts */

static const char usage[] =
    "usage: waterworld probe SCENE.yaml --at X,Z [--at X,Z]... [options]\n"
    "\n"
    "Prints the exact water surface over world points through time as CSV on stdout:\n"
    "  t,height,nx,ny,nz          (one --at)\n"
    "  t,x,z,height,nx,ny,nz      (several --at: one row per point per time)\n"
    "height is the y of the surface over (x, z), waves and ripples together, with Gerstner's\n"
    "sideways motion inverted; (nx, ny, nz) its unit normal. The simulation is stepped so script\n"
    "events (ripples) apply: a sample at t uses the state of the last step at or before t, with\n"
    "the wave phases at exactly t (t need not fall on a step).\n"
    "\n"
    "  --at X,Z          world point, m (up to 64)\n"
    "  --from T0         first sample time, s (default: the scene's time.start)\n"
    "  --to T1           last sample time, s (default: start + duration); samples at\n"
    "                    T0, T0 + DT, ... up to T1\n"
    "  --every DT        sample spacing, s (default: one frame, 1 / fps)\n"
    "Times are limited as the scene's own: T0 >= time.start, T1 <= 1e9 s (or the scene's end),\n"
    "0 < DT <= 1e7 s, and at most 10 million sample times.\n"
    "  --set KEY=VALUE   override a scene value\n"
    "  --script FILE     a YAML file with a script: list, merged with the scene's events\n"
    "\n"
    "A query that does not converge (a sea at its folding limit) still prints its best answer;\n"
    "a warning on stderr counts them.\n"
    "Exit: 0 done, 2 bad input (bad --at, T0 > T1, DT <= 0, a time out of its limits), 3 NaN or\n"
    "I/O.\n";

/* a finite number filling all of s up to end (or to the end of s when end is 0) */
static int parse_number(const char *s, char end, double *v, const char **rest) {
    errno = 0;
    char *e = NULL;
    *v = strtod(s, &e);
    if (e == s || errno || !isfinite(*v) || *e != end) return 0;
    if (rest) *rest = e + 1;
    return 1;
}

static ww_result parse_time(const char *opt, const char *s, double *v, ww_error *err) {
    if (!parse_number(s, 0, v, NULL))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s wants a time in seconds, got '%s'", opt, s);
    return WW_OK;
}

/* the last step whose time start + n dt is <= t (t >= start) */
static int64_t step_at(const ww_scene *sc, double t) {
    int64_t n = (int64_t)floor((t - sc->start) / sc->dt);
    if (n < 0) n = 0;
    while (sc->start + (double)(n + 1) * sc->dt <= t) n++;
    while (n > 0 && sc->start + (double)n * sc->dt > t) n--;
    return n;
}

typedef struct probe_opts {
    int npoints;
    double at[PROBE_MAX_POINTS][2];
    const char *from, *to, *every;
} probe_opts;

static ww_result probe_run(const ww_scene *sc, const probe_opts *po, ww_error *err) {
    double t0 = sc->start, t1 = sc->start + sc->duration, dt = 1.0 / sc->fps;
    ww_result r;
    if (po->from && (r = parse_time("--from", po->from, &t0, err))) return r;
    if (po->to && (r = parse_time("--to", po->to, &t1, err))) return r;
    if (po->every && (r = parse_time("--every", po->every, &dt, err))) return r;
    /* the scene's own limits: a sample time is one a scene may name (time.start, an event's t),
     * or inside this scene's run; a spacing is at most a duration */
    double latest = fmax(WW_TIME_MAX, sc->start + sc->duration);
    if (!(dt > 0.0) || dt > WW_DURATION_MAX)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--every wants a time in (0, %g] s (as time.duration), got %g",
                            WW_DURATION_MAX, dt);
    if (t0 > t1)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--from %g is after --to %g", t0, t1);
    if (t0 < sc->start)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--from %g is before the scene's start (time.start %g s): there is no "
                            "state to probe", t0, sc->start);
    if (t1 > latest)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "%s %g is past the latest time a scene may name (%g s, as time.start "
                            "and event times)",
                            po->to ? "--to" : "--from", po->to ? t1 : t0, latest);
    double span = (t1 - t0) / dt;
    if (span + 1.0 > (double)PROBE_MAX_ROWS)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--from %g --to %g --every %g makes more than %lld samples", t0, t1, dt,
                            PROBE_MAX_ROWS);
    int64_t rows = (int64_t)floor(span + PROBE_TIME_EPS) + 1;

    ww_state *st = ww_state_new(sc);
    if (!st) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
    double phase[WW_MAX_WAVES];
    long long missed = 0;
    double worst = 0.0;
    int many = po->npoints > 1;
    r = WW_OK;
    fputs(many ? "t,x,z,height,nx,ny,nz\n" : "t,height,nx,ny,nz\n", stdout);
    for (int64_t i = 0; i < rows && !r; i++) {
        double t = t0 + (double)i * dt;
        /* only ripples read the state; without them stepping would change nothing probed (and
         * a probe at t = 1e6 s need not take 1.2e8 steps) */
        if (sc->ripples_on && (r = ww_sim_advance_to(sc, st, step_at(sc, t), err))) break;
        ww_waves_phases(sc, t, phase);
        ww_field f = {.sc = sc, .phase = phase, .t = t, .ripples = sc->ripples_on ? st->ripple : NULL};
        for (int p = 0; p < po->npoints; p++) {
            ww_water_sample s;
            if (!ww_water_height(&f, po->at[p][0], po->at[p][1], NULL, &s)) {
                missed++;
                worst = fmax(worst, s.residual);
            }
            if (many)
                printf("%.12g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", t, po->at[p][0], po->at[p][1], s.height,
                       s.normal[0], s.normal[1], s.normal[2]);
            else
                printf("%.12g,%.9g,%.9g,%.9g,%.9g\n", t, s.height, s.normal[0], s.normal[1], s.normal[2]);
        }
    }
    ww_state_free(st);
    if (missed)
        fprintf(stderr,
                "warning: %lld of %lld queries did not converge (residual up to %.3g m): the sea is "
                "near its folding limit (waterworld waves SCENE --stats)\n",
                missed, (long long)rows * po->npoints, worst);
    if (!r && (fflush(stdout) != 0 || ferror(stdout)))
        r = ww_error_set(err, WW_E_IO, NULL, 0, 0, "probe: cannot write to stdout");
    return r;
}

ww_result ww_cmd_probe(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    probe_opts po = {0};
    const char *at = NULL;
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (ww_cli_opt(argc, argv, &i, "--at", &at, &r, err)) {
            if (r) break;
            const char *rest = NULL;
            if (po.npoints >= PROBE_MAX_POINTS)
                r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "more than %d --at points", PROBE_MAX_POINTS);
            else if (!parse_number(at, ',', &po.at[po.npoints][0], &rest) ||
                     !parse_number(rest, 0, &po.at[po.npoints][1], NULL))
                r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--at wants X,Z in metres, got '%s'", at);
            else
                po.npoints++;
            continue;
        }
        if (ww_cli_opt(argc, argv, &i, "--from", &po.from, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--to", &po.to, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--every", &po.every, &r, err)) continue;
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "probe: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (so.frames || so.size)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "probe: %s does not apply (use --from, --to, --every)",
                            so.frames ? "--frames" : "--size");
    if (po.npoints == 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "probe needs a point: --at X,Z (see --help)");
    ww_scene *sc = NULL;
    if ((r = ww_cli_load(&so, "probe", &sc, err))) return r;
    r = probe_run(sc, &po, err);
    ww_scene_free(sc);
    return r;
}
