/* cmd_plan.c - `waterworld plan`: the systems and render passes a scene needs, with target
 * sizes, formats and bytes. */
#include <stdio.h>

#include "cli/cli.h"
#include "scene/plan.h"

static const char usage[] =
    "usage: waterworld plan SCENE.yaml [--size WxH] [--set KEY=VALUE]...\n"
    "\n"
    "Prints the systems the simulation runs and the render passes (with their targets,\n"
    "formats and bytes) that this scene needs; nothing else is allocated or run.\n";

ww_result ww_cmd_plan(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "plan: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    ww_scene *sc = NULL;
    if ((r = ww_cli_load(&so, "plan", &sc, err))) return r;
    ww_plan p;
    ww_plan_build(sc, sc->width, sc->height, &p);
    ww_plan_print(sc, &p, stdout);
    /* audio: scripts/make-video.sh greps this line to decide whether to mux a track */
    if (sc->audio.on)
        printf("audio: 44100 Hz stereo 16-bit, volume %g, music %s%s\n", sc->audio.volume,
               sc->audio.music_on ? "on" : "off",
               sc->audio.music_on ? (sc->audio.music_file.path[0] ? " (file)" : " (procedural)") : "");
    ww_scene_free(sc);
    return WW_OK;
}
