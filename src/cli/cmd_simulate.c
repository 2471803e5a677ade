/* cmd_simulate.c - `waterworld simulate`: the simulation alone (no GL): state hash, trace. */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "io/stream.h"
#include "sim/state.h"
#include "sim/step.h"

static const char usage[] =
    "usage: waterworld simulate SCENE.yaml [options]\n"
    "\n"
    "Steps the simulation without rendering.\n"
    "\n"
    "  --frames N|A:B       simulate up to frame B-1 (default: the whole scene); the trace\n"
    "                       holds frames A..B-1\n"
    "  --trace FILE.jsonl   one JSON object per frame: frame, step, t, clock, sun, sky,\n"
    "                       camera and every system's state ('-' for stdout)\n"
    "  --hash               print the 64-bit hash of the state after the last frame (hex)\n"
    "  --set KEY=VALUE      override a scene value\n"
    "\n"
    "Exit: 0 done, 2 bad input, 3 NaN/Inf in the state (named) or I/O failure.\n";

ww_result ww_cmd_simulate(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    const char *trace = NULL;
    int want_hash = 0;
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
        if (ww_cli_opt(argc, argv, &i, "--trace", &trace, &r, err)) continue;
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "simulate: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;

    ww_scene *sc = NULL;
    ww_state *st = NULL;
    ww_stream ts = {0};
    int64_t first, last;
    if ((r = ww_cli_load(&so, "simulate", &sc, err))) return r;
    if ((r = ww_cli_frames(so.frames, sc, &first, &last, err))) goto done;
    if (!(st = ww_state_new(sc))) {
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
        goto done;
    }
    if (trace && (r = ww_stream_open(&ts, trace, err))) goto done;

    for (int64_t f = 0; f < last; f++) {
        if ((r = ww_sim_advance_to(sc, st, f * sc->steps_per_frame, err))) break;
        if (trace && f >= first) {
            fprintf(ts.f, "{\"frame\":%lld,\"state\":", (long long)f);
            ww_state_write_json(sc, st, ts.f);
            fputs("}\n", ts.f);
        }
    }
    if (trace) {
        if (r)
            ww_stream_abort(&ts);
        else
            r = ww_stream_commit(&ts, err);
    }
    if (!r && want_hash) printf("%016" PRIx64 "\n", ww_state_hash(sc, st));
done:
    ww_state_free(st);
    ww_scene_free(sc);
    return r;
}
