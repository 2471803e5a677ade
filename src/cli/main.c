/* main.c - the waterworld command: dispatch to a subcommand, print its error, choose the exit
 * code (0 ok, 1 check failed, 2 bad input, 3 runtime failure). The only place that decides one.
 */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

static const char usage[] =
    "waterworld " WW_VERSION " - headless water world renderer and simulation batch tool\n"
    "\n"
    "usage: waterworld COMMAND [options]   (waterworld COMMAND --help for each)\n"
    "\n"
    "  render   SCENE.yaml [-o DIR|FILE|-] [--format png|exr|y4m|raw|none] [--frames N|A:B]\n"
    "                      [--size WxH] [--backend auto|egl|osmesa|null] [--script FILE] [--set KEY=VALUE]...\n"
    "                      [--threads N] [--resume] [--stats FILE] [--audio FILE.wav] [--golden DIR]\n"
    "                      [--slices N --emit-jobs | --slice I/N]   one command per slice, or one slice\n"
    "  simulate SCENE.yaml [--frames N|A:B] [--trace FILE.jsonl] [--events FILE.jsonl] [--hash]\n"
    "                      [--stats] [--script FILE] [--set KEY=VALUE]...\n"
    "  plan     SCENE.yaml                systems and render passes the scene needs\n"
    "  probe    SCENE.yaml --at X,Z [--from T0] [--to T1] [--every DT]\n"
    "                                    the exact water surface over a point, CSV\n"
    "  waves    SCENE.yaml --stats       wave statistics (Hs, periods, slopes, fold margin), JSON\n"
    "  sweep    SCENE.yaml --vary KEY=A:B:N [--vary KEY=v1,v2]... [--random N --seed S]\n"
    "                      [--jobs N] [--emit-jobs | --point I] [--thumbs] [-o DIR]\n"
    "                      wave statistics over a grid of --set values\n"
    "  bench    [render|quality|sim|output|compare] [--frames N] [--json] [-o DIR]\n"
    "                                    speed, memory, quality knobs, sim error vs dt, output\n"
    "                                    formats, compare against ImageMagick\n"
    "  bench    waves [--json] [-o DIR]  the wave field's speed against its error, and a figure\n"
    "  compare  EXPECTED ACTUAL [--diff FILE] [--max M] [--psnr-min DB] [--yiq Y] [--json]...\n"
    "                                    two images or folders of frames; exit 1 when they differ\n"
    "  review   LIST [-o DIR] [--jobs N] [--size WxH] [--no-render]\n"
    "                                    one frame per shot of a review list, a labelled contact\n"
    "                                    sheet and an HTML page (make review)\n"
    "  join     DIR                      put the slices of a render (render --slice) or the points\n"
    "                                    of a sweep (sweep --point) back together; lists what is\n"
    "                                    missing and the commands that complete it\n"
    "  backends [--renderer] [--key]     which GL backends open here, on what; the golden key\n"
    "  --help | --version\n"
    "\n"
    "Exit codes: 0 success, 1 check failed, 2 bad input or usage, 3 runtime failure,\n"
    "            130 interrupted (nothing partial written).\n";

typedef struct {
    const char *name;
    ww_result (*run)(int argc, char **argv, ww_error *err);
} command;

static const command commands[] = {
    {"render", ww_cmd_render},
    {"simulate", ww_cmd_simulate},
    {"plan", ww_cmd_plan},
    {"bench", ww_cmd_bench},
    {"sweep", ww_cmd_sweep},
    {"backends", ww_cmd_backends},
    {"probe", ww_cmd_probe},
    {"waves", ww_cmd_waves},
    {"compare", ww_cmd_compare},
    {"review", ww_cmd_review},
    {"join", ww_cmd_join},
};

int main(int argc, char **argv) {
    if (argc < 2) {
        fputs(usage, stderr);
        return 2;
    }
    if (ww_cli_is_help(argv[1])) {
        fputs(usage, stdout);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("waterworld %s\n", WW_VERSION);
        return 0;
    }
    for (size_t c = 0; c < sizeof commands / sizeof commands[0]; c++) {
        if (strcmp(argv[1], commands[c].name) != 0) continue;
        ww_error err = {0};
        ww_result r = commands[c].run(argc - 2, argv + 2, &err);
        if (r != WW_OK) ww_error_print(&err, stderr);
        return ww_result_exit_code(r);
    }
    fprintf(stderr, "error: unknown command '%s'\n\n%s", argv[1], usage);
    return 2;
}
