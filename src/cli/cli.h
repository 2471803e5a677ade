/* cli.h - the subcommands and the option helpers they share. Each cmd_*.c parses its own
 * options and returns a ww_result; only main.c turns results into exit codes.
 */
#ifndef WW_CLI_H
#define WW_CLI_H

#include <stdint.h>

#include "core/error.h"
#include "scene/scene.h"

#define WW_CLI_MAX_SETS 256

/* options every scene-reading command takes */
typedef struct ww_cli_scene_opts {
    const char *scene_path;
    ww_set sets[WW_CLI_MAX_SETS];
    int nsets;
    const char *frames;      /* "N" or "A:B", NULL for all */
    const char *size;        /* "WxH", NULL for the scene's */
    const char *script;      /* --script FILE: events merged with the scene's, NULL for none */
} ww_cli_scene_opts;

ww_result ww_cmd_render(int argc, char **argv, ww_error *err);
ww_result ww_cmd_simulate(int argc, char **argv, ww_error *err);
ww_result ww_cmd_plan(int argc, char **argv, ww_error *err);
ww_result ww_cmd_bench(int argc, char **argv, ww_error *err);
ww_result ww_cmd_backends(int argc, char **argv, ww_error *err);
ww_result ww_cmd_probe(int argc, char **argv, ww_error *err);
ww_result ww_cmd_waves(int argc, char **argv, ww_error *err);
ww_result ww_cmd_sweep(int argc, char **argv, ww_error *err);
ww_result ww_cmd_compare(int argc, char **argv, ww_error *err);
ww_result ww_cmd_review(int argc, char **argv, ww_error *err);
ww_result ww_cmd_join(int argc, char **argv, ww_error *err);

/* is argv[*i] the option `name`? then *val = its argument (next word, or after '='), *i moves on;
 * a missing argument is WW_E_USAGE */
int ww_cli_opt(int argc, char **argv, int *i, const char *name, const char **val, ww_result *r,
               ww_error *err);
/* the shared options: --set, --frames, --size, --script and the scene path; returns 1 when argv[*i] was one */
int ww_cli_scene_arg(int argc, char **argv, int *i, ww_cli_scene_opts *o, ww_result *r, ww_error *err);
/* load the scene with the --set overrides and the --script file, and apply --size; WW_E_USAGE when no scene was named */
ww_result ww_cli_load(const ww_cli_scene_opts *o, const char *cmd, ww_scene **sc, ww_error *err);
/* "N" -> [0, N), "A:B" -> [A, B); checked against the scene's frame count */
ww_result ww_cli_frames(const char *text, const ww_scene *sc, int64_t *first, int64_t *last,
                        ww_error *err);
int ww_cli_is_help(const char *arg);
/* --from-checkpoint FILE (cli/checkpoint_args.c): the checkpoint read for the scene as loaded
 * from o (its file, --set and --script), refused (exit 2, the file named) when it is from another
 * scene or build, damaged, later than first_step, or without the sound state a --audio track
 * needs (need_sound) */
struct ww_checkpoint;
ww_result ww_cli_checkpoint_load(const ww_cli_scene_opts *o, const ww_scene *sc, const char *path,
                                 int64_t first_step, int need_sound, struct ww_checkpoint *ck,
                                 ww_error *err);
/* `backends`' closing advice from which backends opened and EGL's GL_VERSION (its Mesa version
 * says whether OSMesa can exist here); NULL when both opened */
const char *ww_cli_backends_advice(int egl_ok, const char *egl_version, int osmesa_ok);

#endif
