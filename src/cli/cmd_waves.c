/* cmd_waves.c - `waterworld waves SCENE --stats`: the statistics of a scene's wave field
 * (sim/wave_stats.h) as one JSON object, the numbers a sweep row carries.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "io/json.h"
#include "sim/wave_stats.h"

static const char usage[] =
    "usage: waterworld waves SCENE.yaml --stats [--set KEY=VALUE]...\n"
    "\n"
    "Prints the statistics of the scene's wave field as one JSON object on stdout:\n"
    "  model, count            the wave family and its number of components\n"
    "  m0, hs                  height variance (m^2) and significant wave height 4 sqrt(m0) (m)\n"
    "  peak_period             s: of the spectrum's peak (model spectrum), else of the component\n"
    "                          with the most energy\n"
    "  mean_wavelength         energy-weighted, m\n"
    "  max_slope, slope_bound  largest |grad h| over a sample of the surface, and the bound\n"
    "                          sum k A h'max no slope can exceed\n"
    "  fold_sum, fold_margin   sum Q k A (above 1 the surface folds) and the smallest Jacobian of\n"
    "                          the horizontal motion over the sample (<= 0 where it folds)\n"
    "  total_amplitude         sum of amplitudes, m\n"
    "  samples                 points x times sampled\n"
    "  phase_speeds, wavelengths   per component, m/s and m\n"
    "Numbers that are not finite are written as null.\n"
    "Exit: 0 done, 2 bad input.\n";

/* a JSON number; JSON has no NaN or Inf */
static void json_number(FILE *to, double v) {
    if (isfinite(v))
        fprintf(to, "%.12g", v);
    else
        fputs("null", to);
}

static void json_field(FILE *to, const char *key, double v) {
    fprintf(to, ",\"%s\":", key);
    json_number(to, v);
}

static void write_stats(const ww_scene *sc, const ww_wave_stats *s, FILE *to) {
    fputs("{\"scene\":", to);
    ww_json_string(to, sc->name);
    fprintf(to, ",\"model\":\"%s\",\"count\":%d", ww_wave_model_name(sc->wave_model), s->count);
    json_field(to, "m0", s->m0);
    json_field(to, "hs", s->hs);
    json_field(to, "peak_period", s->peak_period);
    json_field(to, "mean_wavelength", s->mean_wavelength);
    json_field(to, "max_slope", s->max_slope);
    json_field(to, "slope_bound", s->slope_bound);
    json_field(to, "fold_sum", s->fold_sum);
    json_field(to, "fold_margin", s->fold_margin);
    json_field(to, "total_amplitude", s->total_amplitude);
    fprintf(to, ",\"samples\":%d,\"phase_speeds\":[", s->samples);
    for (int i = 0; i < sc->nwaves; i++) {
        if (i) fputc(',', to);
        json_number(to, sc->waves[i].speed);
    }
    fputs("],\"wavelengths\":[", to);
    for (int i = 0; i < sc->nwaves; i++) {
        if (i) fputc(',', to);
        json_number(to, sc->waves[i].wavelength);
    }
    fputs("]}\n", to);
}

ww_result ww_cmd_waves(int argc, char **argv, ww_error *err) {
    ww_cli_scene_opts so = {0};
    int stats = 0;
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (strcmp(argv[i], "--stats") == 0) {
            stats = 1;
            continue;
        }
        if (ww_cli_scene_arg(argc, argv, &i, &so, &r, err)) continue;
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "waves: unknown option '%s' (see --help)", argv[i]);
    }
    if (r) return r;
    if (so.frames || so.size)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "waves: %s does not apply",
                            so.frames ? "--frames" : "--size");
    if (!stats)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "waves: say what to print: --stats (see --help)");
    ww_scene *sc = NULL;
    if ((r = ww_cli_load(&so, "waves", &sc, err))) return r;
    ww_wave_stats s;
    ww_wave_stats_compute(sc, 0, 0, &s);
    write_stats(sc, &s, stdout);
    ww_scene_free(sc);
    if (fflush(stdout) != 0 || ferror(stdout))
        return ww_error_set(err, WW_E_IO, NULL, 0, 0, "waves: cannot write to stdout");
    return WW_OK;
}
