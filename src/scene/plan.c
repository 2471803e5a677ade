/* plan.c - from a compiled scene to the list of systems that run and render passes that exist.
 * A scene pays only for what it uses: no waves, no wave system; later issues add passes here
 * (shadow map, reflection, bloom, shafts, FXAA) each behind the scene key that asks for it.
 */
#include "scene/plan.h"

static const char *const system_names[WW_SYS_COUNT] = {
    [WW_SYS_CLOCK] = "clock",
    [WW_SYS_CAMERA] = "camera",
    [WW_SYS_WAVES] = "waves",
    [WW_SYS_SCRIPT] = "script",
};

const char *ww_system_name(ww_system s) { return system_names[s]; }

size_t ww_format_bytes_per_pixel(ww_format f) {
    switch (f) {
    case WW_FMT_RGBA16F: return 8;
    case WW_FMT_DEPTH24: return 4; /* stored as 24+8 */
    case WW_FMT_RGBA8: return 4;
    }
    return 0;
}

const char *ww_format_name(ww_format f) {
    switch (f) {
    case WW_FMT_RGBA16F: return "rgba16f";
    case WW_FMT_DEPTH24: return "depth24";
    case WW_FMT_RGBA8: return "rgba8";
    }
    return "?";
}

static void add_pass(ww_plan *p, ww_pass_id id, const char *name, const char *what) {
    ww_pass_desc *d = &p->passes[p->npasses++];
    d->id = id;
    d->name = name;
    d->what = what;
    d->ntargets = 0;
}

static void add_target(ww_plan *p, const char *name, ww_format f, int w, int h) {
    ww_pass_desc *d = &p->passes[p->npasses - 1];
    d->targets[d->ntargets++] = (ww_target_desc){name, f, w, h};
}

void ww_plan_build(const ww_scene *sc, int width, int height, ww_plan *p) {
    *p = (ww_plan){0};
    p->system_on[WW_SYS_CLOCK] = 1;
    p->system_on[WW_SYS_CAMERA] = 1;
    p->system_on[WW_SYS_WAVES] = sc->nwaves > 0;
    p->system_on[WW_SYS_SCRIPT] = sc->nevents > 0;

    add_pass(p, WW_PASS_MAIN, "main", "HDR: gradient sky with sun disc, water surface");
    add_target(p, "hdr", WW_FMT_RGBA16F, width, height);
    add_target(p, "depth", WW_FMT_DEPTH24, width, height);
    add_pass(p, WW_PASS_TONEMAP, "tonemap",
             sc->tonemap == WW_TONEMAP_ACES ? "HDR -> sRGB8, ACES fit" : "HDR -> sRGB8, 1 - exp(-E c)");
    add_target(p, "ldr", WW_FMT_RGBA8, width, height);
}

void ww_plan_print(const ww_scene *sc, const ww_plan *p, FILE *to) {
    fprintf(to, "scene %s\n", sc->path);
    fprintf(to, "frames %lld at %g fps, dt %.9g s (%lld steps per frame)\n",
            (long long)sc->frame_count, sc->fps, sc->dt, (long long)sc->steps_per_frame);
    fprintf(to, "systems\n");
    for (int s = 0; s < WW_SYS_COUNT; s++) {
        if (!p->system_on[s]) continue;
        fprintf(to, "  %-10s", ww_system_name((ww_system)s));
        if (s == WW_SYS_WAVES) fprintf(to, " %d gerstner waves", sc->nwaves);
        if (s == WW_SYS_CAMERA) fprintf(to, " %d keys, %s", sc->ncam,
                                        sc->interp == WW_INTERP_LINEAR ? "linear" : "catmull-rom");
        if (s == WW_SYS_SCRIPT) fprintf(to, " %d events", sc->nevents);
        if (s == WW_SYS_CLOCK) fprintf(to, " %.2f h, day length %g s", sc->time_of_day, sc->day_length);
        fputc('\n', to);
    }
    fprintf(to, "passes\n");
    size_t total = 0;
    for (int i = 0; i < p->npasses; i++) {
        const ww_pass_desc *d = &p->passes[i];
        fprintf(to, "  %d %-10s %s\n", i + 1, d->name, d->what);
        for (int t = 0; t < d->ntargets; t++) {
            const ww_target_desc *td = &d->targets[t];
            size_t bytes = (size_t)td->width * (size_t)td->height * ww_format_bytes_per_pixel(td->format);
            total += bytes;
            fprintf(to, "      %-8s %-8s %5dx%-5d %10zu bytes\n", td->name, ww_format_name(td->format),
                    td->width, td->height, bytes);
        }
    }
    fprintf(to, "gpu memory %zu bytes (%.1f MiB) in render targets\n", total, (double)total / 1048576.0);
}
