/* cmd_sweep.c - `waterworld sweep`: wave statistics over a grid (or a seeded sample) of --set
 * values, as CSV / JSON lines, with job lines for a cluster and an optional contact sheet. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "io/outpath.h"
#include "sweep/sweep.h"

static const char usage[] =
    "usage: waterworld sweep SCENE.yaml --vary KEY=A:B:N [--vary KEY=v1,v2,...]... [options]\n"
    "\n"
    "Loads the scene once per point of a grid of --set values and prints one row per point:\n"
    "the point, its values, status (ok | warn | error) and the `waves --stats` numbers (count, hs,\n"
    "peak_period, mean_wavelength, max_slope, fold_sum, fold_margin, total_amplitude), then a\n"
    "message (the loader's error, or its warnings).\n"
    "\n"
    "  --vary KEY=A:B:N     N evenly spaced values from A to B inclusive (N = 1: A)\n"
    "  --vary KEY=v1,v2,..  a list of values, numbers or words (model=gerstner,sines)\n"
    "                       the grid is every combination, the first --vary slowest\n"
    "  --random N           N points instead of the grid, each axis drawn uniformly in [A, B]\n"
    "                       (KEY=A:B is enough) or from its list\n"
    "  --seed S             seed of the random points (default 0): same seed, same rows\n"
    "  --set KEY=VALUE      a base value for every point (the point's own values come after)\n"
    "  -o, --output DIR     write DIR/sweep.csv and DIR/sweep.jsonl (\"values\": {key: value})\n"
    "                       instead of CSV on stdout\n"
    "  --jobs N             compute the points in N processes (same output as one)\n"
    "  --emit-jobs          print one shell command per point instead (GNU parallel, Slurm):\n"
    "                         waterworld sweep SCENE ... --point I [-o DIR]\n"
    "  --point I            compute point I alone: its JSON line on stdout, or with -o in\n"
    "                       DIR/points/point_0000I.jsonl. After a job array, merge with\n"
    "                         waterworld join DIR\n"
    "                       (sweep.jsonl, sweep.csv and the contact sheet: the same bytes as a\n"
    "                       full sweep's; missing points listed with their commands)\n"
    "  --thumbs             render one small frame per point into DIR/thumbs/point_0000I.png and\n"
    "                       DIR/contact_sheet.png, labelled with the values (needs -o and GL)\n"
    "  --thumb-size WxH     thumbnail size (default 160x90)\n"
    "  --thumb-frame F      the frame rendered (default 0)\n"
    "  --backend B          auto | egl | osmesa | null, for thumbnails\n"
    "  --quiet              no summary on stderr\n"
    "\n"
    "A point whose values do not load (out of range, fold: error) is a row with status error;\n"
    "the sweep goes on. Bad --vary syntax or an unknown key stops it before any work.\n"
    "Example: waterworld sweep scenes/demo.yaml --vary water.waves.list[0].amplitude=0.1:0.5:5 \\\n"
    "           --vary water.waves.model=gerstner,sines --jobs 4 -o out/sweep\n"
    "\n"
    "Exit: 0 done (error rows included), 2 bad input, 3 runtime failure (no GL for --thumbs, I/O).\n";

/* a whole number in [lo, hi], or a usage error naming the option */
static ww_result parse_int(const char *opt, const char *t, long long lo, long long hi, long long *v,
                           ww_error *err) {
    char *e = NULL;
    errno = 0;
    long long x = (t[0] >= '0' && t[0] <= '9') ? strtoll(t, &e, 10) : -1;
    if (x < 0 || errno || !e || *e || x < lo || x > hi)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s wants a whole number in %lld..%lld, got '%s'",
                            opt, lo, hi, t);
    *v = x;
    return WW_OK;
}

static ww_result parse_seed(const char *t, uint64_t *seed, ww_error *err) {
    char *e = NULL;
    errno = 0;
    unsigned long long x = (t[0] >= '0' && t[0] <= '9') ? strtoull(t, &e, 10) : 0;
    if (!e || *e || errno)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--seed wants a whole number >= 0, got '%s'", t);
    *seed = x;
    return WW_OK;
}

/* WIDTHxHEIGHT, each a whole number (the range is the sweep's, checked with the other options) */
static ww_result parse_size(const char *t, int *w, int *h, ww_error *err) {
    char *e = NULL, *f = NULL;
    errno = 0;
    long a = (t[0] >= '0' && t[0] <= '9') ? strtol(t, &e, 10) : -1;
    long b = a >= 0 && (*e == 'x' || *e == 'X') && e[1] >= '0' && e[1] <= '9' ? strtol(e + 1, &f, 10) : -1;
    if (a < 0 || b < 0 || errno || *f || a > INT_MAX || b > INT_MAX)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumb-size wants WIDTHxHEIGHT, got '%s'", t);
    *w = (int)a;
    *h = (int)b;
    return WW_OK;
}

ww_result ww_cmd_sweep(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    ww_sweep_opts o = ww_default_sweep_opts();
    const char *vary[WW_SWEEP_MAX_AXES + 1];
    int nvary = 0, emit = 0;
    const char *random = NULL, *seed = NULL, *jobs = NULL, *point = NULL, *size = NULL,
               *frame = NULL, *backend = NULL, *v = NULL;
    ww_result r = WW_OK;

    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (ww_cli_opt(argc, argv, &i, "--vary", &v, &r, err)) {
            if (!r && nvary == WW_SWEEP_MAX_AXES)
                r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "more than %d --vary axes", WW_SWEEP_MAX_AXES);
            if (!r) vary[nvary++] = v;
            continue;
        }
        if (ww_cli_opt(argc, argv, &i, "-o", &o.out_dir, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--output", &o.out_dir, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--random", &random, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--seed", &seed, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--jobs", &jobs, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--point", &point, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--thumb-size", &size, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--thumb-frame", &frame, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--backend", &backend, &r, err)) continue;
        if (strcmp(argv[i], "--emit-jobs") == 0) {
            emit = 1;
            continue;
        }
        if (strcmp(argv[i], "--thumbs") == 0) {
            o.thumbs = 1;
            continue;
        }
        if (strcmp(argv[i], "--quiet") == 0) {
            o.quiet = 1;
            continue;
        }
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "sweep: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (so.script)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "sweep: --script does not apply (a point's statistics read no events)");
    if (so.frames || so.size)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "sweep: --%s does not apply (thumbnails take --thumb-frame and --thumb-size)",
                            so.frames ? "frames" : "size");

    long long n = 0;
    if (random && (r = parse_int("--random", random, 1, WW_SWEEP_MAX_POINTS, &o.random, err))) return r;
    if (seed && !random)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--seed goes with --random N");
    if (seed && (r = parse_seed(seed, &o.seed, err))) return r;
    if (jobs) {
        if ((r = parse_int("--jobs", jobs, 1, WW_SWEEP_MAX_JOBS, &n, err))) return r;
        o.jobs = (int)n;
    }
    if (point && (r = parse_int("--point", point, 0, WW_SWEEP_MAX_POINTS - 1, &o.point, err))) return r;
    if (frame) {
        if ((r = parse_int("--thumb-frame", frame, 0, INT32_MAX, &n, err))) return r;
        o.thumb_frame = n;
    }
    if (size && (r = parse_size(size, &o.thumb_w, &o.thumb_h, err))) return r;
    if ((size || frame) && !o.thumbs)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumb-size and --thumb-frame go with --thumbs");
    if (backend && (int)(o.backend = (ww_backend_kind)ww_backend_kind_parse(backend)) < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--backend wants auto, egl, osmesa or null, got '%s'", backend);
    if (emit && point)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--emit-jobs prints the --point commands; give one or the other");

    /* job lines name this very binary, so they run wherever this one did */
    char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len > 0) {
        exe[len] = 0;
        o.exe = exe;
    }

    /* the output folder before any point is loaded (a file in its place fails now, not at the
     * end of the grid) */
    if (o.out_dir && (r = ww_check_out_dir("-o", o.out_dir, err))) return r;

    o.scene_path = so.scene_path;
    o.sets = so.sets;
    o.nsets = so.nsets;
    o.vary = vary;
    o.nvary = nvary;
    ww_sweep *s = NULL;
    if ((r = ww_sweep_new(&o, &s, err))) return r;
    r = emit ? ww_sweep_emit_jobs(s, stdout, err) : ww_sweep_run(s, stdout, err);
    ww_sweep_free(s);
    return r;
}
