/* cmd_simulate.c - `waterworld simulate`: the simulation alone (no GL): state hash, trace, the
 * events of every step as JSON lines, and the speed (simulated seconds per wall second). A NaN or
 * Inf anywhere stops the run with exit 3, naming the system, field, index and step.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "io/outpath.h"
#include "io/stream.h"
#include "render/job.h"
#include "render/sim_out.h"
#include "sim/state.h"
#include "sim/step.h"

static const char usage[] =
    "usage: waterworld simulate SCENE.yaml [options]\n"
    "\n"
    "Steps the simulation without rendering.\n"
    "\n"
    "  --frames N|A:B       simulate up to frame B-1 (default: the whole scene); the trace\n"
    "                       holds frames A..B-1, the events steps A*k..(B-1)*k (k steps a frame)\n"
    "  --script FILE        a YAML file with a script: list, merged with the scene's events\n"
    "                       (sorted by time; the scene's first at equal times)\n"
    "  --trace FILE.jsonl   one JSON object per frame: frame, step, t, clock, sun, sky,\n"
    "                       camera and every system's state ('-' for stdout)\n"
    "  --events FILE.jsonl  one JSON object per simulation event, after every step ('-' for\n"
    "                       stdout): {\"step\",\"t\",\"kind\",\"object\",\"pos\":[x,y,z],\n"
    "                       \"magnitude\",\"aux\"}; kinds and magnitudes in src/sim/events.h\n"
    "  --hash               print the 64-bit hash of the state after the last frame (hex)\n"
    "  --stats              print steps, simulated and wall seconds and simulated seconds per\n"
    "                       wall second on stderr\n"
    "  --set KEY=VALUE      override a scene value\n"
    "\n"
    "Exit: 0 done, 2 bad input, 3 NaN/Inf in the state (system, field, index and step named)\n"
    "or I/O failure.\n";

typedef struct sim_out {
    const char *trace, *events;
    ww_stream ts, es;
    FILE *tf, *ef;
    long long nevents;
} sim_out;

/* open the trace and event files (the same '-' may serve both) */
static ww_result open_outputs(sim_out *o, ww_error *err) {
    if (o->trace) {
        ww_result r = ww_stream_open(&o->ts, o->trace, err);
        if (r) return r;
        o->tf = o->ts.f;
    }
    if (o->events) {
        if (o->trace && strcmp(o->trace, "-") == 0 && strcmp(o->events, "-") == 0) {
            o->ef = o->tf;
        } else {
            ww_result r = ww_stream_open(&o->es, o->events, err);
            if (r) return r;
            o->ef = o->es.f;
        }
    }
    return WW_OK;
}

static ww_result close_outputs(sim_out *o, ww_result r, ww_error *err) {
    int shared = o->ef && o->ef == o->tf;
    if (o->tf) {
        if (r)
            ww_stream_abort(&o->ts);
        else
            r = ww_stream_commit(&o->ts, err);
    }
    if (o->ef && !shared) {
        if (r)
            ww_stream_abort(&o->es);
        else
            r = ww_stream_commit(&o->es, err);
    }
    return r;
}

ww_result ww_cmd_simulate(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    sim_out o = {0};
    int want_hash = 0, want_stats = 0;
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (strcmp(argv[i], "--hash") == 0) {
            want_hash = 1;
            continue;
        }
        if (strcmp(argv[i], "--stats") == 0) {
            want_stats = 1;
            continue;
        }
        if (ww_cli_opt(argc, argv, &i, "--trace", &o.trace, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--events", &o.events, &r, err)) continue;
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "simulate: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (o.trace && o.events && strcmp(o.trace, "-") != 0 && strcmp(o.trace, o.events) == 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "simulate: --trace and --events name the same file '%s'", o.trace);
    /* the outputs before the scene: a folder named by --trace is found before any step */
    if (o.trace && (r = ww_check_out_file("--trace", o.trace, 1, err))) return r;
    if (o.events && (r = ww_check_out_file("--events", o.events, 1, err))) return r;

    ww_scene *sc = NULL;
    ww_state *st = NULL;
    int64_t first, last;
    if ((r = ww_cli_load(&so, "simulate", &sc, err))) return r;
    if ((r = ww_cli_frames(so.frames, sc, &first, &last, err))) goto done;
    double t0 = ww_now_seconds();
    if (!(st = ww_state_new(sc))) {
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
        goto done;
    }
    if ((r = open_outputs(&o, err))) {
        close_outputs(&o, r, err);
        goto done;
    }

    /* the events of every step from frame `first` on: step by step when they are wanted */
    int64_t ev_from = first * sc->steps_per_frame;
    if (!(r = ww_state_check(sc, st, err)) && o.ef && ev_from == 0)
        o.nevents += ww_sim_events_write(sc, st, o.ef);
    for (int64_t f = 0; f < last && !r; f++) {
        int64_t target = f * sc->steps_per_frame;
        if (!o.ef) {
            r = ww_sim_advance_to(sc, st, target, err);
        } else {
            while (!r && st->step < target) {
                r = ww_step(sc, st, err);
                if (!r && st->step >= ev_from) o.nevents += ww_sim_events_write(sc, st, o.ef);
            }
        }
        if (!r && o.tf && f >= first) {
            fprintf(o.tf, "{\"frame\":%lld,\"state\":", (long long)f);
            ww_state_write_json(sc, st, o.tf);
            fputs("}\n", o.tf);
        }
    }
    /* the step's own check names the field; say which system wrote it */
    r = close_outputs(&o, r, err);
    double wall = ww_now_seconds() - t0;
    if (!r && want_hash) printf("%016" PRIx64 "\n", ww_state_hash(sc, st));
    if (!r && want_stats) {
        double simulated = (double)st->step * sc->dt;
        /* the outbox exists only in scenes with objects */
        long long dropped = ww_scene_has_objects(sc) ? (long long)st->events_dropped[0] : 0;
        fprintf(stderr,
                "simulated %.3f s (%lld steps of %.6g s) in %.3f s wall: %.1f simulated s per "
                "wall s, %.3f us per step",
                simulated, (long long)st->step, sc->dt, wall, wall > 0 ? simulated / wall : 0.0,
                st->step > 0 ? 1e6 * wall / (double)st->step : 0.0);
        if (o.ef) fprintf(stderr, "; %lld events written", o.nevents);
        fprintf(stderr, "; %lld events dropped by a full outbox\n", dropped);
    }
done:
    ww_state_free(st);
    ww_scene_free(sc);
    return r;
}
