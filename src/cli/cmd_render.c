/* cmd_render.c - `waterworld render`: scene -> frames on disk, a video stream on stdout, a sound
 * track, and (with --golden) the frames checked against golden images.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check/golden.h"
#include "cli/cli.h"
#include "cli/render_jobs.h"
#include "gfx/backend.h"
#include "render/checkpoint.h"
#include "render/job.h"
#include "render/slices.h"

static const char usage[] =
    "usage: waterworld render SCENE.yaml [options]\n"
    "\n"
    "Steps the simulation and renders every frame of the scene (or a slice) into DIR.\n"
    "\n"
    "  -o, --output DIR     folder for frame_00000.png ... (default out/SCENE_NAME); for y4m and\n"
    "                       raw the stream's file (default out/SCENE_NAME.y4m|.rgb), - for stdout\n"
    "  --format FMT         png (sRGB8, default) | exr (linear RGBA) | y4m (YUV4MPEG2 for ffmpeg)\n"
    "                       | raw (packed RGB8 frames) | none (render and read back only)\n"
    "  --alpha              png (RGBA8) and exr: alpha = coverage, 0 where only the sky is seen\n"
    "  --exr-float          exr: 32-bit float channels (default half)\n"
    "  --exr-compression C  exr: none | zip (default) | piz\n"
    "  --y4m-420            y4m: 4:2:0 chroma (C420jpeg) instead of 4:4:4\n"
    "  --frames N|A:B       the first N frames, or frames A..B-1 (the prefix is simulated,\n"
    "                       not rendered, so a slice is byte-identical to a full run)\n"
    "  --size WxH           render size (default: the scene's render.size)\n"
    "  --backend B          auto (EGL, then OSMesa) | egl | osmesa | null (no GL: black frames,\n"
    "                       for testing the job and its outputs)\n"
    "  --set KEY=VALUE      override a scene value, e.g. --set water.waves.list[0].amplitude=0.4\n"
    "  --script FILE        a YAML file with a script: list, merged with the scene's events\n"
    "  --threads N          encoder threads beside the render thread (default: cores - 1, >= 1)\n"
    "  --jobs N             render in N processes, each a slice of the frames with llvmpipe's\n"
    "                       threads shared out (LP_NUM_THREADS = cores / N unless set), then\n"
    "                       joined: the frames and sound track of one process, byte for byte;\n"
    "                       png, exr or none (default 1)\n"
    "  --resume             keep frames already complete in DIR, render only the others\n"
    "  --stats FILE.jsonl   one line per frame: simulate, render, read back, encode ms\n"
    "  --audio FILE.wav     the sound track of the frames rendered (44.1 kHz stereo 16-bit)\n"
    "  --golden DIR         compare every frame with its golden: DIR/KEY/frame_XXXXX.png (KEY:\n"
    "                       `waterworld backends --key`), then the keys of the scene's\n"
    "                       golden.fallback, then DIR/frame_XXXXX.png; report.html and the\n"
    "                       failing frames' diff/ and expected/ images go into the output folder;\n"
    "                       exact match unless a threshold is given; thresholds from the scene's\n"
    "                       golden: section, with these options over them:\n"
    "                       --threshold T --max M --fail-percent P --fail-pixels N --psnr-min DB\n"
    "                       --yiq Y --yiq-pixels N --ssim-min S --rel-max R --no-aa\n"
    "";
/* the rest of the help (one string literal is limited to 4095 characters) */
static const char usage_slices[] =
    "  --slices N --emit-jobs  print N shell commands, one per slice: this command with\n"
    "                       --slice I/N (for GNU parallel, a Slurm array, a Kubernetes Job)\n"
    "  --slice I/N          render slice I (0-based) of N near-equal pieces of the frames into\n"
    "                       DIR as a full run would, its sound track, stats and completion record\n"
    "                       under DIR/slices/; then `waterworld join DIR`. Here --audio [NAME.wav]\n"
    "                       and --stats [NAME.jsonl] name the joined files in DIR (default\n"
    "                       audio.wav, stats.jsonl); --resume skips a complete slice\n"
    "  --checkpoints DIR    with --slices N --emit-jobs: each slice's command starts from the\n"
    "                       latest checkpoint in DIR at or before its first frame\n"
    "  --from-checkpoint F  start from a checkpoint (simulate --checkpoint-every) at or before\n"
    "                       the first frame instead of simulating the prefix; F a file, or the\n"
    "                       folder of them (the latest at or before the first frame is taken);\n"
    "                       one from another scene, other --set/--script values or another\n"
    "                       build is refused (exit 2)\n"
    "  --progress           progress on stderr even when it is not a terminal (the prefix's\n"
    "                       steps, then the frames)\n"
    "  --quiet              no progress and no summary on stderr\n"
    "\n"
    "Exit: 0 done (and every frame matched), 1 a frame differs from its golden, 2 bad input\n"
    "(nothing written), 3 runtime failure (GL, I/O, NaN), 130 interrupted (Ctrl-C, SIGTERM: the\n"
    "frames in flight are finished, nothing partial is left).\n"
    "Environment: WW_EGL_PLATFORM=device|surfaceless, WW_EGL_DEVICE=N, WW_SHADER_DIR=DIR.\n";

#define MAX_CMP_ARGS 32

/* drop[k]: argv[k] is not repeated by the slices' commands (DROP_SLICES) or by the children of
 * --jobs (DROP_JOBS), which are given their own -o, --slice, --quiet, --audio and --stats */
enum { DROP_SLICES = 1, DROP_JOBS = 2 };

/* --slice or --slices anywhere on the line: --audio and --stats then take an optional name */
static int is_slicing(int argc, char **argv) {
    for (int i = 0; i < argc; i++)
        if (strncmp(argv[i], "--slice", 7) == 0 && strchr("s=", argv[i][7])) return 1;
    return 0;
}

/* with slices: `--audio [NAME.wav]` (`--stats [NAME.jsonl]`): the next word is the name when it
 * ends in ext, else the default; returns 1 when argv[*i] was the option */
static int opt_name(int argc, char **argv, int *i, const char *name, const char *ext,
                    const char *fallback, const char **val) {
    size_t n = strlen(name), e = strlen(ext);
    const char *a = argv[*i];
    if (strncmp(a, name, n) != 0 || (a[n] != 0 && a[n] != '=')) return 0;
    *val = a[n] == '=' ? a + n + 1 : fallback;
    const char *next = *i + 1 < argc ? argv[*i + 1] : "";
    size_t k = strlen(next);
    if (!a[n] && next[0] != '-' && k > e && strcmp(next + k - e, ext) == 0) *val = argv[++*i];
    return 1;
}

static ww_result parse_threads(const char *v, int *out, ww_error *err) {
    char *end = NULL;
    long n = strtol(v, &end, 10);
    if (end == v || *end != 0 || n < 1 || n > 64)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--threads wants 1..64, got '%s'", v);
    *out = (int)n;
    return WW_OK;
}

static ww_result parse_jobs(const char *v, int *out, ww_error *err) {
    char *end = NULL;
    long n = strtol(v, &end, 10);
    if (end == v || *end != 0 || n < 1 || n > WW_RENDER_MAX_JOBS)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--jobs wants 1..%d, got '%s'",
                            WW_RENDER_MAX_JOBS, v);
    *out = (int)n;
    return WW_OK;
}

/* --jobs N: the slices in child processes, then joined (cli/render_jobs.h). With goldens, st
 * gets the renderer that picks them: this binary's backend, as the children opened it */
static ww_result render_in_jobs(const ww_job_opts *jo, const ww_slice_opts *sl, int njobs,
                                int golden, ww_job_stats *st, ww_error *err) {
    if (!sl->exe)
        return ww_error_set(err, WW_E_IO, "/proc/self/exe", 0, 0,
                            "render --jobs: cannot find this binary");
    ww_render_jobs rj = {.jobs = njobs, .exe = sl->exe, .words = sl->words, .nwords = sl->nwords,
                         .dir = jo->out_dir, .audio_path = jo->audio_path,
                         .stats_path = jo->stats_path, .resume = jo->resume, .quiet = jo->quiet,
                         .progress = jo->progress, .first = jo->first, .last = jo->last,
                         .format = jo->format};
    ww_render_jobs_stats js;
    ww_result r = ww_render_jobs_run(&rj, &js, err);
    if (r) return r;
    if (golden) {
        ww_backend *b = NULL;
        if ((r = ww_backend_open(jo->backend, &b, err))) return r;
        snprintf(st->renderer, sizeof st->renderer, "%s", ww_backend_renderer(b));
        snprintf(st->gl_version, sizeof st->gl_version, "%s", ww_backend_version(b));
        ww_backend_close(b);
    }
    if (!jo->quiet) {
        fprintf(stderr, "rendered %lld frames (%lld..%lld) at %dx%d in %d processes",
                (long long)(jo->last - jo->first), (long long)jo->first, (long long)jo->last - 1,
                jo->width, jo->height, js.jobs);
        if (js.threads) fprintf(stderr, " (LP_NUM_THREADS=%d each)", js.threads);
        fprintf(stderr, " in %.2f s", js.wall_s);
        if (jo->format == WW_OUT_PNG || jo->format == WW_OUT_EXR)
            fprintf(stderr, " -> %s/frame_%05lld.%s ...", jo->out_dir, (long long)jo->first,
                    ww_out_format_ext(jo->format));
        fprintf(stderr, "\n");
    }
    return WW_OK;
}

/* the comparison thresholds: the scene's, then the command line's words over them */
static ww_result golden_opts(const ww_scene *sc, char **words, int nwords, ww_cmp_opts *o,
                             ww_error *err) {
    *o = ww_golden_scene_opts(sc);
    ww_result r = WW_OK;
    for (int i = 0; i < nwords && !r; i++) {
        if (!ww_cmp_opt_arg(nwords, words, &i, o, &r, err))
            r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "render: unknown option '%s'", words[i]);
    }
    return r;
}

/* the slicing options against each other */
static ww_result slice_opts(const char *slice, const char *slices, int emit, ww_slice_opts *sl,
                            ww_error *err) {
    if (slice && slices)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--slice I/N renders one slice, --slices N --emit-jobs prints them "
                            "all: give one or the other");
    if (emit != (slices != NULL))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            emit ? "--emit-jobs goes with --slices N"
                                 : "--slices N goes with --emit-jobs (or render one slice with "
                                   "--slice I/N)");
    if (slice) return ww_slice_parse(slice, &sl->index, &sl->count, err);
    if (slices) return ww_slices_parse(slices, &sl->count, err);
    return WW_OK;
}

/* the command; drop and words have argc + 1 places (the slices' word list is built in them) */
static ww_result render(int argc, char **argv, char *drop, char **words, ww_error *err) {
    ww_cli_scene_opts so = {0};
    ww_job_opts jo = ww_default_job_opts();
    const char *out = NULL, *format = NULL, *backend = NULL, *threads = NULL, *compression = NULL;
    const char *golden = NULL, *from = NULL;
    int progress = 0;
    char *cmp_words[MAX_CMP_ARGS];
    int ncmp = 0;
    ww_result r = WW_OK;
    /* slices: the words every slice repeats are argv less the slicing ones (dropped) */
    ww_slice_opts sl = {.index = -1};
    const char *slice = NULL, *slices = NULL, *jobs = NULL;
    int emit = 0, slicing = is_slicing(argc, argv);

    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            fputs(usage_slices, stdout);
            return WW_OK;
        }
        /* the slicing options with a value: not repeated by the slices' commands */
        const struct { const char *name; const char **val; } slicing_opts[] = {
            {"--slice", &slice}, {"--slices", &slices}, {"--checkpoints", &sl.checkpoints},
        };
        int at = i, sliced = 0;
        for (size_t k = 0; k < sizeof slicing_opts / sizeof slicing_opts[0] && !sliced; k++)
            sliced = ww_cli_opt(argc, argv, &i, slicing_opts[k].name, slicing_opts[k].val, &r, err);
        if (sliced || ww_cli_opt(argc, argv, &i, "--jobs", &jobs, &r, err)) {
            for (int k = at; k <= i && k < argc; k++) drop[k] = DROP_SLICES | DROP_JOBS;
            continue;
        }
        if (strcmp(argv[i], "--emit-jobs") == 0 || strcmp(argv[i], "--resume") == 0) {
            if (argv[i][2] == 'e') emit = 1;
            else jo.resume = 1; /* join adds it to the commands it prints where it applies */
            drop[i] = DROP_SLICES | DROP_JOBS;
            continue;
        }
        if (slicing && (opt_name(argc, argv, &i, "--audio", ".wav", WW_SLICE_AUDIO_DEFAULT, &sl.audio_name) ||
                        opt_name(argc, argv, &i, "--stats", ".jsonl", WW_SLICE_STATS_DEFAULT, &sl.stats_name)))
            continue;
        /* the options --jobs gives its children in its own way */
        const struct { const char *name; const char **val; } own[] = {
            {"-o", &out},           {"--output", &out},           {"--stats", &jo.stats_path},
            {"--audio", &jo.audio_path}, {"--golden", &golden},
        };
        int owned = 0;
        for (size_t k = 0; k < sizeof own / sizeof own[0] && !owned; k++)
            owned = ww_cli_opt(argc, argv, &i, own[k].name, own[k].val, &r, err);
        if (owned) {
            for (int k = at; k <= i && k < argc; k++) drop[k] |= DROP_JOBS;
            continue;
        }
        if (ww_cli_opt(argc, argv, &i, "--format", &format, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--backend", &backend, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--threads", &threads, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--exr-compression", &compression, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--from-checkpoint", &from, &r, err)) continue;
        const struct { const char *name; int *flag; int value; } flags[] = {
            {"--quiet", &jo.quiet, 1},        {"--alpha", &jo.alpha, 1},
            {"--exr-float", &jo.exr_float, 1}, {"--y4m-420", &jo.y4m_420, 1},
            {"--progress", &progress, 1},
        };
        int flag = 0;
        for (size_t k = 0; k < sizeof flags / sizeof flags[0] && !flag; k++) {
            if (strcmp(argv[i], flags[k].name) == 0) {
                *flags[k].flag = flags[k].value;
                flag = 1;
                if (flags[k].flag == &jo.quiet || flags[k].flag == &progress) drop[i] |= DROP_JOBS;
            }
        }
        if (flag) continue;
        /* a comparison threshold: kept as words, applied over the scene's once it is loaded */
        int start = i;
        ww_cmp_opts probe = ww_cmp_default_opts();
        if (ww_cmp_opt_arg(argc, argv, &i, &probe, &r, err)) {
            for (int k = start; k <= i && ncmp < MAX_CMP_ARGS; k++) {
                cmp_words[ncmp++] = argv[k];
                drop[k] |= DROP_JOBS;
            }
            continue;
        }
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "render: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (format && (int)(jo.format = (ww_out_format)ww_out_format_parse(format)) < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--format wants png, exr, y4m, raw or none, got '%s'", format);
    if (backend && (int)(jo.backend = (ww_backend_kind)ww_backend_kind_parse(backend)) < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--backend wants auto, egl, osmesa or null, got '%s'", backend);
    if (threads && (r = parse_threads(threads, &jo.threads, err))) return r;
    int njobs = 1;
    if (jobs && (r = parse_jobs(jobs, &njobs, err))) return r;
    if (compression) {
        static const char *const names[] = {"zip", "none", "piz"};
        int k = 0;
        while (k < 3 && strcmp(compression, names[k]) != 0) k++;
        if (k == 3)
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                "--exr-compression wants none, zip or piz, got '%s'", compression);
        jo.exr_compression = (ww_exr_compression)k;
    }
    int stream = jo.format == WW_OUT_Y4M || jo.format == WW_OUT_RAW;
    if (out && strcmp(out, "-") == 0 && !stream)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "-o - (stdout) needs --format y4m or raw");
    if (golden && jo.format != WW_OUT_PNG)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--golden compares PNG frames: drop --format");
    jo.progress = jo.quiet ? WW_PROGRESS_OFF : progress ? WW_PROGRESS_ON : WW_PROGRESS_AUTO;
    if ((r = slice_opts(slice, slices, emit, &sl, err))) return r;
    if (sl.checkpoints && !slices)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--checkpoints DIR goes with --slices N --emit-jobs (one slice takes "
                            "--from-checkpoint)");
    if (jobs && (slice || slices))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--jobs N renders the slices here; --slice and --slices are for a "
                            "scheduler: give one or the other");
    if (njobs > 1 && stream)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--jobs N writes frames (png, exr or none): a %s stream is written "
                            "by one process",
                            jo.format == WW_OUT_Y4M ? "y4m" : "raw");
    for (int k = 0; k < argc; k++)
        if (!(drop[k] & (njobs > 1 ? DROP_JOBS : DROP_SLICES))) words[sl.nwords++] = argv[k];
    sl.words = words;
    sl.scene_path = so.scene_path;
    sl.script = so.script;
    sl.sets = so.sets;
    sl.nsets = so.nsets;
    char exe[PATH_MAX];
    ssize_t exe_len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (exe_len > 0) {
        exe[exe_len] = 0;
        sl.exe = exe; /* job lines name this very binary, so they run wherever this one did */
    }

    ww_scene *sc = NULL;
    ww_checkpoint ck = {0};
    if ((r = ww_cli_load(&so, "render", &sc, err))) return r;
    ww_golden_opts go = {.golden_dir = golden};
    if (golden && (r = golden_opts(sc, cmp_words, ncmp, &go.cmp, err))) goto done;
    if ((r = ww_cli_frames(so.frames, sc, &jo.first, &jo.last, err))) goto done;
    char dir[600];
    if (out) {
        snprintf(dir, sizeof dir, "%s", out);
    } else {
        snprintf(dir, sizeof dir, "out/%s%s", sc->name,
                 jo.format == WW_OUT_Y4M ? ".y4m" : jo.format == WW_OUT_RAW ? ".rgb" : "");
    }
    jo.out_dir = dir;
    go.out_dir = dir;
    go.log = jo.quiet ? NULL : stderr;
    /* golden: a missing DIR, or DIR as the output folder, is known before anything renders */
    if (golden && (r = ww_golden_prepare(&go, err))) goto done;
    jo.width = sc->width;
    jo.height = sc->height;

    int skip = 0;
    if (slices) {
        r = ww_slices_emit(&sl, sc, &jo, stdout, err);
        goto done;
    }
    ww_job_stats st = {0};
    if (njobs > 1) {
        r = render_in_jobs(&jo, &sl, njobs, golden != NULL, &st, err);
        if (r || !golden) goto done;
        goto check;
    }
    /* the checkpoint at or before the first frame rendered here (a slice's own first) */
    int64_t first = jo.first, last = jo.last;
    if (slice) ww_slice_range(jo.first, jo.last, sl.index, sl.count, &first, &last);
    if (from && (r = ww_cli_checkpoint_load(&so, sc, from, first * sc->steps_per_frame,
                                            jo.audio_path != NULL || sl.audio_name != NULL, &ck,
                                            err)))
        goto done;
    jo.from = ck.st ? &ck : NULL;
    if (slice && ((r = ww_slice_begin(&sl, sc, &jo, &skip, err)) || skip)) {
        if (skip && !jo.quiet)
            fprintf(stderr, "slice %s (frames %lld..%lld) already complete: %s\n", slice,
                    (long long)jo.first, (long long)jo.last - 1, sl.record);
        goto done;
    }
    r = ww_job_run(sc, &jo, &st, err);
    if (slice && !r) r = ww_slice_end(&sl, sc, &jo, st.renderer, err);
    if (!jo.quiet && (!r || r == WW_E_INTERRUPTED)) {
        fprintf(stderr, "%s %lld frames (%lld..%lld) at %dx%d on %s (%s) in %.2f s",
                r ? "interrupted after" : "rendered", (long long)st.frames, (long long)jo.first,
                (long long)jo.last - 1, jo.width, jo.height, st.backend, st.renderer, st.wall_s);
        if (st.skipped) fprintf(stderr, ", %lld already done", (long long)st.skipped);
        if (jo.format == WW_OUT_PNG || jo.format == WW_OUT_EXR)
            fprintf(stderr, " -> %s/frame_%05lld.%s ...", dir, (long long)jo.first,
                    ww_out_format_ext(jo.format));
        else if (stream && strcmp(dir, "-") != 0)
            fprintf(stderr, " -> %s", dir);
        fprintf(stderr, "\n");
    }
    if (r || !golden) goto done;

check:
    go.first = jo.first;
    go.last = jo.last;
    go.renderer = st.renderer;
    go.gl_version = st.gl_version;
    ww_golden_summary gs;
    r = ww_golden_check(sc, &go, &gs, err);
    if ((!r || r == WW_E_MISMATCH) && !jo.quiet)
        fprintf(stderr, "golden: %lld frames, %lld passed, %lld failed, %lld missing (%.2f s); "
                "goldens from %s; renderer key %s; report %s\n",
                (long long)gs.frames, (long long)gs.passed, (long long)gs.failed,
                (long long)gs.missing, gs.wall_s, gs.golden_dir, gs.key, gs.report);
done:
    ww_checkpoint_free(&ck);
    ww_scene_free(sc);
    return r;
}

ww_result ww_cmd_render(int argc, char **argv, ww_error *err) {
    char *drop = calloc((size_t)argc + 1, 1);
    char **words = calloc((size_t)argc + 1, sizeof *words);
    ww_result r = drop && words ? render(argc, argv, drop, words, err)
                                : ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory");
    free(drop);
    free(words);
    return r;
}
