/* cmd_bench.c - `waterworld bench`: speed and memory figures (printed, never asserted). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "tools/bench.h"
#include "tools/bench_waves.h"

static const char usage[] =
    "usage: waterworld bench [render|sim] [--frames N] [--json] [SCENE.yaml...]\n"
    "       waterworld bench waves [--json] [-o DIR]\n"
    "\n"
    "  render (default)  per backend (egl, osmesa), scene (minimal, demo) and size (256x144,\n"
    "                    1280x720): ms per frame split into simulate / render / read back /\n"
    "                    encode (PNG), the fill floor (one trivial full-screen pass), render/floor,\n"
    "                    peak RSS of the render process and the size of the state\n"
    "  sim               per scene: steps per second and simulated seconds per wall second;\n"
    "                    the error of cube heave, boat position and stone landing points at\n"
    "                    dt = 1/30, 1/60, 1/120, 1/240 against dt = 1/1920, next to steps per\n"
    "                    second (each scene named, else scenes/lake.yaml), and the figure\n"
    "                    DIR/sim.png; the simulation's share of a frame of scenes/demo.yaml\n"
    "  waves             the wave field's speed against its error: CPU evaluations per second\n"
    "                    per family and component count (double, float, against the libm\n"
    "                    sincos calls they need) with the float error; height queries'\n"
    "                    iterations, residual and time at fold margins 0.5, 0.2, 0.05; GPU ms\n"
    "                    per frame at 1280x720 against component count, fade on and off; and\n"
    "                    the figure DIR/waves.png\n"
    "  -o DIR            folder for the waves and sim figures (default out/bench)\n"
    "  --frames N        frames per configuration (default 20)\n"
    "  --json            one JSON object per line\n";

ww_result ww_cmd_bench(int argc, char **argv, ww_error *err) {
    ww_bench_opts o = {0};
    const char *what = "render", *frames = NULL, *out = NULL;
    int tiny = 0;
    int nscenes = 0;
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (strcmp(argv[i], "--json") == 0) {
            o.json = 1;
            continue;
        }
        /* not in the help: a seconds-long `bench waves` or `bench sim` for the tests */
        if (strcmp(argv[i], "--tiny") == 0) {
            tiny = 1;
            continue;
        }
        if (ww_cli_opt(argc, argv, &i, "--frames", &frames, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "-o", &out, &r, err)) continue;
        if (strcmp(argv[i], "render") == 0 || strcmp(argv[i], "sim") == 0 ||
            strcmp(argv[i], "waves") == 0) {
            what = argv[i];
            continue;
        }
        if (argv[i][0] != '-' && nscenes < 3) {
            o.scenes[nscenes++] = argv[i];
            continue;
        }
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "bench: unknown argument '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (frames && (o.frames = atoi(frames)) <= 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--frames wants a positive count, got '%s'", frames);
    int waves = strcmp(what, "waves") == 0, sim = strcmp(what, "sim") == 0;
    if (!waves && !sim && (out || tiny))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "bench: %s applies to bench waves and sim only",
                            out ? "-o" : "--tiny");
    if (waves && (nscenes || frames))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "bench waves takes no scenes or --frames (it builds its own seas)");
    if (waves) {
        ww_bench_waves_opts wo = {.json = o.json, .out_dir = out, .tiny = tiny};
        return ww_bench_waves(&wo, stdout, err);
    }
    o.out_dir = out;
    o.tiny = tiny;
    if (sim) return ww_bench_sim(&o, stdout, err);
    return ww_bench_render(&o, stdout, err);
}
