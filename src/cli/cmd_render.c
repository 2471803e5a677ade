/* cmd_render.c - `waterworld render`: scene -> frames on disk (or nowhere, for timing). */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "gfx/backend.h"
#include "tools/job.h"

static const char usage[] =
    "usage: waterworld render SCENE.yaml [options]\n"
    "\n"
    "Steps the simulation and renders every frame of the scene (or a slice) into DIR.\n"
    "\n"
    "  -o, --output DIR     folder for frame_00000.png ... (default out/SCENE_NAME)\n"
    "  --format FMT         png (sRGB8, default) | exr (linear half-float RGBA) | none\n"
    "  --frames N|A:B       the first N frames, or frames A..B-1 (the prefix is simulated,\n"
    "                       not rendered, so a slice is byte-identical to a full run)\n"
    "  --size WxH           render size (default: the scene's render.size)\n"
    "  --backend B          auto (EGL, then OSMesa) | egl | osmesa\n"
    "  --set KEY=VALUE      override a scene value, e.g. --set water.waves.list[0].amplitude=0.4\n"
    "  --script FILE        a YAML file with a script: list, merged with the scene's events\n"
    "  --quiet              no summary on stderr\n"
    "\n"
    "Exit: 0 done, 2 bad input (nothing written), 3 runtime failure (GL, I/O, NaN).\n"
    "Environment: WW_EGL_PLATFORM=device|surfaceless, WW_EGL_DEVICE=N, WW_SHADER_DIR=DIR.\n";

ww_result ww_cmd_render(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    ww_job_opts jo = ww_default_job_opts();
    const char *out = NULL, *format = NULL, *backend = NULL;
    ww_result r = WW_OK;

    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (ww_cli_opt(argc, argv, &i, "-o", &out, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--output", &out, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--format", &format, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--backend", &backend, &r, err)) continue;
        if (strcmp(argv[i], "--quiet") == 0) {
            jo.quiet = 1;
            continue;
        }
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "render: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (format && (int)(jo.format = (ww_out_format)ww_out_format_parse(format)) < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--format wants png, exr or none, got '%s'", format);
    if (backend && (int)(jo.backend = (ww_backend_kind)ww_backend_kind_parse(backend)) < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--backend wants auto, egl or osmesa, got '%s'", backend);

    ww_scene *sc = NULL;
    if ((r = ww_cli_load(&so, "render", &sc, err))) return r;
    if ((r = ww_cli_frames(so.frames, sc, &jo.first, &jo.last, err))) goto done;
    char dir[600];
    if (out) {
        snprintf(dir, sizeof dir, "%s", out);
    } else {
        snprintf(dir, sizeof dir, "out/%s", sc->name);
    }
    jo.out_dir = dir;
    jo.width = sc->width;
    jo.height = sc->height;

    ww_job_stats st;
    double t0 = ww_now_seconds();
    r = ww_job_run(sc, &jo, &st, err);
    double wall = ww_now_seconds() - t0;
    if (!r && !jo.quiet) {
        fprintf(stderr, "rendered %lld frames (%lld..%lld) at %dx%d on %s (%s) in %.2f s",
                (long long)st.frames, (long long)jo.first, (long long)jo.last - 1, jo.width,
                jo.height, st.backend, st.renderer, wall);
        if (jo.format != WW_OUT_NONE)
            fprintf(stderr, " -> %s/frame_%05lld.%s ...", dir, (long long)jo.first,
                    ww_out_format_ext(jo.format));
        fprintf(stderr, "\n");
    }
done:
    ww_scene_free(sc);
    return r;
}
