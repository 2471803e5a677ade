/* wave.c - a wave component's derived fields and the wave families' words, shared by the
 * compiler, the spectrum sampler and the plan (scene/scene.h). */
#include <math.h>

#include "core/mathx.h"
#include "scene/scene.h"

const char *const ww_wave_model_words[] = {[WW_WAVES_FLAT] = "flat",
                                           [WW_WAVES_GERSTNER] = "gerstner",
                                           [WW_WAVES_SINES] = "sines",
                                           [WW_WAVES_STEEP_SINES] = "steep_sines",
                                           [WW_WAVES_SPECTRUM] = "spectrum", NULL};

const char *ww_wave_model_name(ww_wave_model m) {
    return m >= WW_WAVES_FLAT && m <= WW_WAVES_SPECTRUM ? ww_wave_model_words[m] : "unknown";
}

void ww_wave_derive(ww_wave *w, double speed) {
    /* deep-water dispersion w^2 = g k (Airy wave theory) unless the phase speed is given */
    w->dir[0] = cos(w->direction);
    w->dir[1] = sin(w->direction);
    w->k = WW_TAU / w->wavelength;
    w->omega = speed > 0.0 ? speed * w->k : sqrt(WW_G * w->k);
    w->speed = w->omega / w->k;
    /* mean of ((sin phi + 1) / 2)^e over a period: with u = (sin + 1) / 2 = sin^2(phi / 2 +
     * pi / 4), the Wallis integral (1 / pi) int_0^pi sin^(2e) = Gamma(e + 1/2) / (sqrt(pi)
     * Gamma(e + 1)) (Abramowitz and Stegun 6.1.1, 6.2.1) */
    w->mean = tgamma(w->exponent + 0.5) / (sqrt(WW_PI) * tgamma(w->exponent + 1.0));
}

double ww_waves_fold_sum(const ww_scene *sc) {
    double sum = 0.0;
    for (int i = 0; i < sc->nwaves; i++)
        sum += sc->waves[i].steepness * sc->waves[i].k * sc->waves[i].amplitude;
    return sum;
}
