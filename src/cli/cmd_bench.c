/* cmd_bench.c - `waterworld bench`: speed and memory figures (printed, never asserted). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench/bench.h"
#include "bench/bench_waves.h"
#include "cli/cli.h"
#include "io/outpath.h"

static const char usage[] =
    "usage: waterworld bench [render] [--frames N] [--size WxH] [--set KEY=VALUE]... [--json]\n"
    "                        [SCENE.yaml...]\n"
    "       waterworld bench sim [--frames N] [--json] [SCENE.yaml...]\n"
    "       waterworld bench quality [--knob NAME] [--size WxH] [--frame N] [--repeats N] [--json]\n"
    "                                [-o DIR] [SCENE.yaml]\n"
    "       waterworld bench waves [--json] [-o DIR]\n"
    "       waterworld bench compare [--size WxH] [--repeats N] [--json] [SCENE.yaml]\n"
    "       waterworld bench output [--frames N] [--json] [SCENE.yaml]\n"
    "\n"
    "  render (default)  per backend (egl, osmesa), scene (demo, lake, reef) and size (256x144,\n"
    "                    1280x720, or --size): ms per frame split into simulate / render / read back /\n"
    "                    encode (PNG), ms per pass (GL timer queries, else CPU time with glFinish\n"
    "                    between passes), fps, the fill floor (one trivial full-screen pass),\n"
    "                    render/floor against the speed targets at 1280x720 (15x for a scene with\n"
    "                    objects, 3x for water and sky; the reef within 1.5x the lake's render\n"
    "                    ms), the frame rates (on llvmpipe at 1280x720 lake.yaml in 66 ms,\n"
    "                    demo.yaml in 40; on a GPU lake.yaml at 1920x1080 within 8x the floor),\n"
    "                    peak RSS and the size of the state; --set KEY=VALUE overrides a value\n"
    "                    in every scene (e.g. --set render.quality=draft), the targets' rows then\n"
    "                    marked '(with --set)'\n"
    "  quality           each quality knob (render.reflection.scale, refraction.scale,\n"
    "                    shadows.size,\n"
    "                    shadows.technique (projected and volumes against a 4096 map), bloom.passes,\n"
    "                    god_rays.samples, msaa, grid, scale (the whole frame drawn smaller),\n"
    "                    water.look.caustics.method: 0 analytic, 1 texture, with the texture set's\n"
    "                    one-off ms) against ms per frame and the PSNR and max difference of the\n"
    "                    final frame against a reference with every knob at its best; each\n"
    "                    knob's feature is switched on where this build has its pass;\n"
    "                    the default, the speed/error front and the knee marked; DIR/quality.png;\n"
    "                    then the render.quality presets whole (final, preview, draft: the scene\n"
    "                    with the preset set), ms and PSNR against the reference and final.\n"
    "                    SCENE default scenes/lake.yaml, --size 640x360, --frame 0, --repeats 5;\n"
    "                    --knob NAME: that knob only (e.g. --knob render.grid), or\n"
    "                    --knob render.quality: the presets only\n"
    ;
/* the rest of the usage (one string may hold at most 4095 characters in ISO C) */
static const char usage_parts[] =
    "  sim               per scene: steps per second and simulated seconds per wall second\n"
    "                    over the scene's own run (`simulate SCENE`) repeated, the lake against\n"
    "                    its target (2000x real time); the step by system (us and share, each\n"
    "                    system's work timed on its own);\n"
    "                    the error of cube heave, boat position and stone paths at\n"
    "                    dt = 1/30, 1/60, 1/120, 1/240 against dt = 1/1920, next to steps per\n"
    "                    second (each scene named, else scenes/lake.yaml), and the figure\n"
    "                    DIR/sim.png; for archimedes cubes each columns count's error against a\n"
    "                    fine grid and its speed; the simulation's share of a frame of\n"
    "                    scenes/demo.yaml\n"
    "  waves             the wave field's speed against its error: CPU evaluations per second\n"
    "                    per family and component count (double, float, against the libm\n"
    "                    sincos calls they need) with the float error; height queries'\n"
    "                    iterations, residual and time at fold margins 0.5, 0.2, 0.05; GPU ms\n"
    "                    per frame at 1280x720 against component count, fade on and off; and\n"
    "                    the figure DIR/waves.png\n"
    "  compare           ms to compare a PNG pair (frames 0 and 1 of SCENE, default\n"
    "                    scenes/demo.yaml, at --size, default 1280x720): ours in process (load +\n"
    "                    every metric; the metrics alone; an identical pair), ours as a process,\n"
    "                    and ImageMagick's `compare -metric RMSE` by fork/exec in the same run,\n"
    "                    with the ratio (the target: ours at least 5x faster); best of\n"
    "                    --repeats (default 7) and the median\n"
    "  output            frames per second of SCENE (default scenes/demo.yaml) at 1280x720 written\n"
    "                    as none, png, exr and y4m (--frames each, default 60), each format in\n"
    "                    its own process; png/none against the 0.85 target; peak RSS of a\n"
    "                    30- and a 300-frame PNG run (flat: the frame queue is bounded)\n"
    "  -o DIR            folder for the waves, sim and quality figures (default out/bench)\n"
    "  --frames N        frames per configuration (default 20)\n"
    "  --json            one JSON object per line\n";

#define BENCH_MAX_FRAMES 1000000 /* --frames per configuration */

/* a whole number in [lo, hi] from text, or -1 */
static long long parse_whole(const char *text, long long lo, long long hi) {
    char *end = NULL;
    long long v = strtoll(text, &end, 10);
    return end != text && *end == 0 && v >= lo && v <= hi ? v : -1;
}

/* --size WIDTHxHEIGHT (NULL: leave *w and *h): each side parsed whole, the width cut at the x */
static ww_result parse_size(const char *size, int *w, int *h, ww_error *err) {
    if (!size) return WW_OK;
    const char *x = strchr(size, 'x');
    char wtext[16];
    snprintf(wtext, sizeof wtext, "%.*s", x ? (int)(x - size) : 0, size);
    long long pw = parse_whole(wtext, 16, 16384), ph = x ? parse_whole(x + 1, 16, 16384) : -1;
    if (pw < 0 || ph < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--size wants WIDTHxHEIGHT with each in 16..16384, got '%s'", size);
    *w = (int)pw;
    *h = (int)ph;
    return WW_OK;
}

/* bench quality's options; --tiny (tests) is a 96x54 frame rendered twice per configuration */
/* opt: --size, --frame, --repeats, --knob as given (NULL: absent) */
static ww_result bench_quality(const ww_bench_opts *b, int nscenes, const char *frames,
                               const char *out, const char *const opt[4], int tiny, ww_error *err) {
    const char *size = opt[0], *frame = opt[1], *repeats = opt[2];
    ww_quality_opts q = {.scene = b->scenes[0], .json = b->json, .out_dir = out, .knob = opt[3]};
    if (nscenes > 1 || frames)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "bench quality takes one scene and --frame, not %s",
                            frames ? "--frames" : "several scenes");
    ww_result r = parse_size(size, &q.width, &q.height, err);
    if (r) return r;
    if (frame && (q.frame = parse_whole(frame, 0, 100000000)) < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--frame wants a frame number, got '%s'", frame);
    long long n = repeats ? parse_whole(repeats, 1, 64) : 0;
    if (n < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--repeats wants 1..64, got '%s'", repeats);
    q.repeats = (int)n;
    if (tiny) {
        if (!size) {
            q.width = 96;
            q.height = 54;
        }
        if (!repeats) q.repeats = 2;
    }
    return ww_bench_quality(&q, stdout, err);
}

/* bench compare's options: a scene, --size, --repeats, --json */
static ww_result bench_compare(const ww_bench_opts *b, int nscenes, int other, const char *size,
                               const char *repeats, ww_error *err) {
    ww_bench_compare_opts c = {.scene = b->scenes[0], .json = b->json};
    if (nscenes > 1 || other)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "bench compare takes one scene, --size, --repeats and --json only");
    ww_result r = parse_size(size, &c.width, &c.height, err);
    if (r) return r;
    long long n = repeats ? parse_whole(repeats, 1, 64) : 0;
    if (n < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--repeats wants 1..64, got '%s'", repeats);
    c.repeats = (int)n;
    return ww_bench_compare(&c, stdout, err);
}

ww_result ww_cmd_bench(int argc, char **argv, ww_error *err) {
    ww_bench_opts o = {0};
    const char *what = "render", *frames = NULL, *out = NULL;
    const char *size = NULL, *frame = NULL, *repeats = NULL, *knob = NULL; /* bench quality */
    int tiny = 0;
    int nscenes = 0;
    ww_set sets[WW_CLI_MAX_SETS]; /* bench render's --set, for every scene */
    int nsets = 0;
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            fputs(usage_parts, stdout);
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
        if (ww_cli_opt(argc, argv, &i, "--size", &size, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--frame", &frame, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--repeats", &repeats, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--knob", &knob, &r, err)) continue;
        const char *set = NULL;
        if (ww_cli_opt(argc, argv, &i, "--set", &set, &r, err)) {
            if (!r && nsets >= WW_CLI_MAX_SETS)
                r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "more than %d --set options",
                                 WW_CLI_MAX_SETS);
            else if (!r)
                sets[nsets++].text = set;
            continue;
        }
        if (strcmp(argv[i], "render") == 0 || strcmp(argv[i], "sim") == 0 ||
            strcmp(argv[i], "waves") == 0 || strcmp(argv[i], "quality") == 0 ||
            strcmp(argv[i], "compare") == 0 || strcmp(argv[i], "output") == 0) {
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
    if (nsets > 0 && strcmp(what, "render") != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "bench: --set applies to bench render only (bench quality sets its "
                            "knobs itself)");
    o.sets = sets;
    o.nsets = nsets;
    if (frames && (o.frames = (int)parse_whole(frames, 1, BENCH_MAX_FRAMES)) <= 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--frames wants a count in 1..%d, got '%s'",
                            BENCH_MAX_FRAMES, frames);
    if (out && (r = ww_check_out_dir("-o", out, err))) return r;
    int waves = strcmp(what, "waves") == 0, sim = strcmp(what, "sim") == 0;
    if (strcmp(what, "quality") == 0) {
        const char *q[] = {size, frame, repeats, knob};
        return bench_quality(&o, nscenes, frames, out, q, tiny, err);
    }
    if (strcmp(what, "compare") == 0) return bench_compare(&o, nscenes, frames || frame || knob || out,
                                                           size, repeats, err);
    if (strcmp(what, "render") == 0 && size) {
        r = parse_size(size, &o.width, &o.height, err);
        if (r) return r;
        size = NULL;
    }
    if (size || frame || repeats || knob)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "bench: %s applies to bench %s only",
                            size ? "--size" : frame ? "--frame" : repeats ? "--repeats" : "--knob",
                            size ? "render, quality and compare" : repeats ? "quality and compare" : "quality");
    if (strcmp(what, "output") == 0) { /* [frames] */
        if (out || nscenes > 1)
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "bench output takes one scene and no -o");
        o.tiny = tiny;
        return ww_bench_output(&o, stdout, err);
    }
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
