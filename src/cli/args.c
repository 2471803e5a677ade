/* args.c - option helpers shared by the subcommands: values, --set collection, --frames and
 * --size parsing, --script, scene loading (which prints the scene's warnings to stderr). Errors are
 * WW_E_USAGE naming the option.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "render/audio.h"

int ww_cli_is_help(const char *arg) { return strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0; }

int ww_cli_opt(int argc, char **argv, int *i, const char *name, const char **val, ww_result *r,
               ww_error *err) {
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0) return 0;
    if (a[n] == '=') {
        *val = a + n + 1;
        return 1;
    }
    if (a[n] != 0) return 0;
    if (*i + 1 >= argc) {
        *r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "option %s needs a value", name);
        return 1;
    }
    *val = argv[++*i];
    return 1;
}

int ww_cli_scene_arg(int argc, char **argv, int *i, ww_cli_scene_opts *o, ww_result *r, ww_error *err) {
    const char *v = NULL;
    if (ww_cli_opt(argc, argv, i, "--set", &v, r, err)) {
        if (*r) return 1;
        if (o->nsets >= WW_CLI_MAX_SETS) {
            *r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "more than %d --set options", WW_CLI_MAX_SETS);
            return 1;
        }
        o->sets[o->nsets++].text = v;
        return 1;
    }
    if (ww_cli_opt(argc, argv, i, "--frames", &o->frames, r, err)) return 1;
    if (ww_cli_opt(argc, argv, i, "--size", &o->size, r, err)) return 1;
    if (ww_cli_opt(argc, argv, i, "--script", &o->script, r, err)) return 1;
    const char *a = argv[*i];
    if (a[0] == '-' && a[1] != 0) return 0; /* someone else's option */
    if (o->scene_path) {
        *r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "unexpected argument '%s' (scene already given: %s)",
                          a, o->scene_path);
        return 1;
    }
    o->scene_path = a;
    return 1;
}

/* a whole non-negative integer: its value, or -1 when s does not start with a digit, -2 when it
 * is past what a long long holds; *end after its digits */
static long long parse_count(const char *s, const char **end) {
    *end = s;
    if (*s < '0' || *s > '9') return -1;
    errno = 0;
    char *e = NULL;
    long long v = strtoll(s, &e, 10);
    *end = e;
    return errno == ERANGE ? -2 : v;
}

ww_result ww_cli_load(const ww_cli_scene_opts *o, const char *cmd, ww_scene **sc, ww_error *err) {
    if (!o->scene_path)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s needs a scene file (waterworld %s --help)",
                            cmd, cmd);
    ww_result r = ww_scene_load_with_script(o->scene_path, o->script, o->sets, o->nsets, sc, err);
    /* the WAV files' headers (images' are looked at by the loader): every command refuses a bad
     * file at its scene line, not only the one that plays it */
    if (!r && (r = ww_audio_check(*sc, err))) {
        ww_scene_free(*sc);
        *sc = NULL;
    }
    if (r) return r;
    /* what the loader accepted but noticed (a folding sea under water.fold: warn, ...) */
    for (int i = 0; i < (*sc)->nwarnings; i++) fprintf(stderr, "%s\n", (*sc)->warnings[i]);
    if (!o->size) return WW_OK;
    const char *e = NULL;
    long long w = parse_count(o->size, &e), h = -1;
    if (w >= 0 && (*e == 'x' || *e == 'X')) h = parse_count(e + 1, &e);
    /* the range of the scene's render.size */
    if (w < WW_SIZE_MIN || h < WW_SIZE_MIN || w > WW_SIZE_MAX || h > WW_SIZE_MAX || *e != 0) {
        ww_scene_free(*sc);
        *sc = NULL;
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--size wants WIDTHxHEIGHT with each in %d..%d (as render.size), got "
                            "'%s'",
                            WW_SIZE_MIN, WW_SIZE_MAX, o->size);
    }
    (*sc)->width = (int)w;
    (*sc)->height = (int)h;
    return WW_OK;
}

ww_result ww_cli_frames(const char *text, const ww_scene *sc, int64_t *first, int64_t *last,
                        ww_error *err) {
    *first = 0;
    *last = sc->frame_count;
    if (!text) return WW_OK;
    const char *e = NULL, *bt = text;
    long long a = parse_count(text, &e), b;
    if (a >= 0 && *e == ':') {
        bt = e + 1;
        b = parse_count(bt, &e);
    } else {
        b = a;
        a = 0;
    }
    /* a number too large for a long long is past any scene's frames (at most 1e10) */
    if (a == -2 || b == -2) b = LLONG_MAX;
    else if (a < 0 || b < 0 || *e != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--frames wants N or A:B in whole frames (frames A..B-1), got '%s'%s",
                            text, *e == '.' || *e == 'e' || *e == 'E' ? ": not a whole number" : "");
    if (b <= a)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--frames %s holds no frame: expected N >= 1, or A:B with A < B", text);
    if (b > sc->frame_count)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--frames %s goes past the scene's %lld frames (time.duration %g s at %g fps)",
                            text, (long long)sc->frame_count, sc->duration, sc->fps);
    *first = a;
    *last = b;
    return WW_OK;
}
