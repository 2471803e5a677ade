/* spectrum.h - wave spectra and the components sampled from them (water.waves.model: spectrum).
 *
 * Pierson-Moskowitz (1964), U = wind speed at 19.5 m:
 *   S(w) = alpha g^2 w^-5 exp(-beta (w0 / w)^4),  alpha = 8.1e-3, beta = 0.74, w0 = g / U
 *   which gives Hs = 4 sqrt(m0) = 2 sqrt(alpha / beta) U^2 / g ~ 0.21 U^2 / g and a peak at
 *   wp = (4 beta / 5)^(1/4) g / U ~ 0.877 g / U.
 * JONSWAP (Hasselmann et al. 1973), U = wind speed at 10 m, fetch F:
 *   S(w) = alpha g^2 w^-5 exp(-5/4 (wp / w)^4) gamma^r,  r = exp(-(w - wp)^2 / (2 sigma^2 wp^2))
 *   alpha = 0.076 (U^2 / (F g))^0.22, wp = 22 (g^2 / (U F))^(1/3), sigma = 0.07 (w <= wp), 0.09.
 *
 * Sampling: the frequency range of the wavelength range (deep water, w = sqrt(2 pi g / L)) is cut
 * into `count` bands of equal width in log w; each band's component carries the band's energy
 * exactly (A = sqrt(2 int S dw over the band), integrated numerically), at a frequency drawn
 * inside the band, a heading drawn from a normal distribution of the spread, and a random phase
 * (stream WW_RNG_WAVES). Q is one value for all components, so that sum Q k A = steepness.
 */
#ifndef WW_SPECTRUM_H
#define WW_SPECTRUM_H

#include "scene/scene.h"

/* S(w), m^2 s / rad, of the described spectrum */
double ww_spectrum_density(const ww_spectrum_desc *d, double omega);
/* angular frequency of the peak, rad/s */
double ww_spectrum_peak(const ww_spectrum_desc *d);
/* int S dw over [w0, w1] (adaptive Simpson to a relative 1e-10) */
double ww_spectrum_integral(const ww_spectrum_desc *d, double w0, double w1);
/* the components: writes d->count waves into out (each derived, line/column left 0) */
void ww_spectrum_sample(const ww_spectrum_desc *d, uint64_t seed, ww_wave *out);

#endif
