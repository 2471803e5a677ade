/* wave_stats.h - the statistics of a scene's wave field (`waterworld waves --stats`, sweep rows).
 *
 * m0 is the variance of the surface height (sum of each component's variance: A^2 / 2 for a
 * sine, the exact variance of the steep-sine profile otherwise), Hs = 4 sqrt(m0) (the spectral
 * significant wave height). Peak period: of the spectrum's peak for model spectrum, otherwise of
 * the component with the most energy. Mean wavelength: energy-weighted. Max slope and the fold
 * margin (the smallest Jacobian determinant of the horizontal map x -> x + D(x), 1 for no
 * sideways motion, <= 0 where the surface folds) come from a sample of the surface over a grid
 * of points and times.
 */
#ifndef WW_WAVE_STATS_H
#define WW_WAVE_STATS_H

#include "scene/scene.h"

typedef struct ww_wave_stats {
    int count;               /* components */
    double m0;               /* height variance, m^2 */
    double hs;               /* significant wave height 4 sqrt(m0), m */
    double peak_period;      /* s */
    double mean_wavelength;  /* energy-weighted, m */
    double max_slope;        /* largest |grad h| over the sample */
    double slope_bound;      /* sum k A h'max / (1 - fold_sum): no slope can exceed it
                              * (INFINITY when fold_sum >= 1) */
    double fold_sum;         /* sum Q k A */
    double fold_margin;      /* min Jacobian over the sample */
    double total_amplitude;  /* sum of amplitudes, m */
    int samples;             /* points x times sampled */
} ww_wave_stats;

/* the statistics of sc's waves; samples the surface over an n x n grid per time at ntimes times
 * (0 for the defaults 64 and 8) */
void ww_wave_stats_compute(const ww_scene *sc, int n, int ntimes, ww_wave_stats *out);

#endif
