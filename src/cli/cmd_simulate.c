/* cmd_simulate.c - `waterworld simulate`: the simulation alone (no GL): state hash, trace, the
 * events of every step as JSON lines, and the speed (simulated seconds per wall second). A NaN or
 * Inf anywhere stops the run with exit 3, naming the system, field, index and step.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "io/outpath.h"
#include "io/stream.h"
#include "io/writers.h"
#include "render/audio.h"
#include "render/checkpoint.h"
#include "render/job.h"
#include "render/prefix.h"
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
    "  --checkpoint-every K write the state every K steps (K >= 1) into DIR (-o), as\n"
    "                       DIR/step_000000001200.wwck: `render --from-checkpoint` starts there\n"
    "                       instead of simulating the prefix (the sound track's state included)\n"
    "  -o, --output DIR     the checkpoints' folder (made with its parents)\n"
    "  --from-checkpoint F  start from a checkpoint instead of step 0 (--frames A:B: at or\n"
    "                       before frame A); F a file or a folder of them (the latest that\n"
    "                       fits); another scene's, other --set/--script values' or another\n"
    "                       build's is refused (exit 2)\n"
    "  --progress           steps done / total, rate and ETA on stderr even when it is not a\n"
    "                       terminal (shown on a terminal unless --quiet)\n"
    "  --quiet              no progress line\n"
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

/* what stepping does besides the step: the events written, the sound track's state heard (for
 * the checkpoints), the checkpoints written every K steps */
typedef struct sim_run {
    sim_out *o;
    int64_t ev_from;           /* events from this step on */
    ww_audio *audio;           /* listens only (an empty track): its state goes in checkpoints */
    int64_t every;             /* --checkpoint-every, 0: none */
    const char *dir;
    uint64_t scene_hash;
    long long ncheck;
    double write_s;            /* writing the checkpoints (state and sound copied, file), s */
    size_t bytes;              /* of the last checkpoint */
} sim_run;

static void after_step(void *ctx, const ww_scene *sc, const ww_state *st) {
    sim_run *u = ctx;
    if (u->o->ef && st->step >= u->ev_from) u->o->nevents += ww_sim_events_write(sc, st, u->o->ef);
    if (u->audio) ww_audio_step(u->audio, sc, st);
}

static ww_result write_checkpoint(sim_run *u, const ww_state *st, ww_error *err) {
    char path[1024];
    double t0 = ww_now_seconds();
    ww_checkpoint_path(u->dir, st->step, path, sizeof path);
    size_t n = u->audio ? ww_audio_save(u->audio, NULL, 0) : 0;
    unsigned char *sound = n ? malloc(n) : NULL;
    if (n && !sound) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a checkpoint");
    if (n) ww_audio_save(u->audio, sound, n);
    ww_result r = ww_checkpoint_write(path, u->scene_hash, st, sound, n, err);
    free(sound);
    u->ncheck += !r;
    u->write_s += ww_now_seconds() - t0;
    u->bytes = WW_CKPT_HEADER_BYTES + st->bytes - ww_state_arrays_offset() + n;
    return r;
}

/* step to `target`, stopping at every checkpoint on the way */
static ww_result run_to(sim_run *u, const ww_scene *sc, ww_state *st, int64_t target,
                        ww_steps_progress *pg, ww_error *err) {
    int hook = u->o->ef || u->audio;
    while (st->step < target) {
        int64_t end = target, next = u->every ? (st->step / u->every + 1) * u->every : target;
        if (next < end) end = next;
        ww_result r = ww_prefix_advance(sc, st, end, hook ? after_step : NULL, u, pg, NULL, err);
        if (!r && u->every && st->step % u->every == 0) r = write_checkpoint(u, st, err);
        if (r) return r;
    }
    return WW_OK;
}

/* a positive whole number of steps, at most CHECKPOINT_EVERY_MAX (past any run's length, and
 * far from where the next multiple could overflow) */
#define CHECKPOINT_EVERY_MAX 1000000000000000LL
static ww_result parse_every(const char *v, int64_t *out, ww_error *err) {
    char *end = NULL;
    long long n = strtoll(v, &end, 10);
    if (end == v || *end != 0 || n < 1 || n > CHECKPOINT_EVERY_MAX)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--checkpoint-every wants a whole number of steps in 1..1e15, got '%s'", v);
    *out = n;
    return WW_OK;
}

ww_result ww_cmd_simulate(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    sim_out o = {0};
    int want_hash = 0, want_stats = 0, progress = 0, quiet = 0;
    const char *every_s = NULL, *dir = NULL, *from = NULL;
    sim_run u = {.o = &o};
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
        if (ww_cli_opt(argc, argv, &i, "--checkpoint-every", &every_s, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "-o", &dir, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--output", &dir, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--from-checkpoint", &from, &r, err)) continue;
        if (strcmp(argv[i], "--progress") == 0 || strcmp(argv[i], "--quiet") == 0) {
            *(argv[i][2] == 'p' ? &progress : &quiet) = 1;
            continue;
        }
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
    if (every_s && (r = parse_every(every_s, &u.every, err))) return r;
    if (!!every_s != !!dir)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            every_s ? "simulate: --checkpoint-every needs -o DIR, the "
                                      "checkpoints' folder"
                                    : "simulate: -o DIR is the checkpoints' folder: give "
                                      "--checkpoint-every K too");
    if (dir && (r = ww_check_out_dir("-o", dir, err))) return r;
    u.dir = dir;

    ww_scene *sc = NULL;
    ww_state *st = NULL;
    ww_checkpoint ck = {0};
    int64_t first, last, spf;
    if ((r = ww_cli_load(&so, "simulate", &sc, err))) return r;
    spf = sc->steps_per_frame;
    if ((r = ww_cli_frames(so.frames, sc, &first, &last, err))) goto done;
    /* a checkpoint: at or before --frames A's step; without --frames the run starts there */
    double read_t0 = ww_now_seconds();
    if (from && (r = ww_cli_checkpoint_load(&so, sc, from, so.frames ? first * spf : INT64_MAX, 0,
                                            &ck, err)))
        goto done;
    double read_s = ww_now_seconds() - read_t0;
    if (dir && (r = ww_checkpoint_scene_hash(so.scene_path, so.script, so.sets, so.nsets,
                                             &u.scene_hash, err)))
        goto done;
    double t0 = ww_now_seconds();
    if (!(st = ww_state_new(sc))) {
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
        goto done;
    }
    if (ck.st) {
        ww_state_copy(st, ck.st);
        int64_t f0 = (ck.step + spf - 1) / spf;
        if (f0 > first) first = f0;
        if (first >= last) {
            r = ww_error_set(err, WW_E_INCONSISTENT, from, 0, 0,
                             "--from-checkpoint: the checkpoint is at step %lld, past the last "
                             "frame simulated (%lld)",
                             (long long)ck.step, (long long)last - 1);
            goto done;
        }
    }
    int64_t start_step = st->step;
    /* the sound track listens, so that each checkpoint carries its state (render --audio) */
    if (dir && (!ck.st || ck.sound)) {
        if ((r = ww_audio_new(sc, start_step, start_step, &u.audio, err))) goto done;
        if (ck.st && (r = ww_audio_restore(u.audio, st, ck.sound, ck.sound_bytes, err))) goto done;
    }
    if (dir && (r = ww_make_dirs(dir, err))) goto done;
    if ((r = open_outputs(&o, err))) {
        close_outputs(&o, r, err);
        goto done;
    }

    /* the events of every step from frame `first` on: step by step when they are wanted */
    u.ev_from = first * spf;
    if (!(r = ww_state_check(sc, st, err)) && o.ef && u.ev_from == st->step)
        o.nevents += ww_sim_events_write(sc, st, o.ef);
    ww_steps_progress pg;
    ww_steps_progress_begin(&pg, progress || (!quiet && isatty(2)), "simulating", start_step,
                            (last - 1) * spf);
    for (int64_t f = (start_step + spf - 1) / spf; f < last && !r; f++) {
        r = run_to(&u, sc, st, f * spf, &pg, err);
        if (!r && o.tf && f >= first) {
            fprintf(o.tf, "{\"frame\":%lld,\"state\":", (long long)f);
            ww_state_write_json(sc, st, o.tf);
            fputs("}\n", o.tf);
        }
    }
    ww_steps_progress_end(&pg, st->step);
    r = close_outputs(&o, r, err);
    double wall = ww_now_seconds() - t0;
    if (!r && want_hash) printf("%016" PRIx64 "\n", ww_state_hash(sc, st));
    if (!r && want_stats) {
        double simulated = (double)(st->step - start_step) * sc->dt;
        /* the outbox exists only in scenes with objects */
        long long dropped = ww_scene_has_objects(sc) ? (long long)st->events_dropped[0] : 0;
        fprintf(stderr,
                "simulated %.3f s (%lld steps of %.6g s) in %.3f s wall: %.1f simulated s per "
                "wall s, %.3f us per step",
                simulated, (long long)(st->step - start_step), sc->dt, wall,
                wall > 0 ? simulated / wall : 0.0,
                st->step > start_step ? 1e6 * wall / (double)(st->step - start_step) : 0.0);
        if (ck.st)
            fprintf(stderr, "; from the checkpoint at step %lld (%zu bytes, read and checked in "
                    "%.3f ms)", (long long)ck.step, ck.file_bytes, 1e3 * read_s);
        if (dir)
            fprintf(stderr, "; %lld checkpoints written to %s (%zu bytes each, %.3f ms each)",
                    u.ncheck, dir, u.bytes, u.ncheck ? 1e3 * u.write_s / (double)u.ncheck : 0.0);
        if (o.ef) fprintf(stderr, "; %lld events written", o.nevents);
        fprintf(stderr, "; %lld events dropped by a full outbox\n", dropped);
    }
done:
    ww_audio_free(u.audio);
    ww_checkpoint_free(&ck);
    ww_state_free(st);
    ww_scene_free(sc);
    return r;
}
