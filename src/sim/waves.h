/* waves.h - the wave field of every family (scene.h: ww_wave_model), evaluated in double on the
 * CPU; the water shaders evaluate the same formulas in float from the same parameters
 * (shaders/gerstner.glsl).
 *
 * For component i with unit direction D, amplitude A, steepness Q, wavenumber k = 2 pi / L,
 * angular frequency w (deep water: w^2 = g k) and phase offset p0, at rest point x = (x, z) and
 * time t:
 *
 *   phi = k D.x - w t + p0                       (travels along +D)
 *   X   = x + sum Q A D cos(phi)                  (horizontal displacement; Q = 0 for sines)
 *   Y   = level + sum h(phi)                      (h = A sin(phi), or for steep sines
 *                                                  2 A (((sin(phi) + 1) / 2)^e - mean_e))
 *
 * Seed 000 writes the phase as k D.x + c t, with the phase speed c in place of w = c k: that mixes
 * units (m/s added to radians) and sends the wave backwards; we use w t with the sign above.
 * The state keeps each wave's phase at the world origin, wrapped to [0, 2 pi): -w t + p0. So a
 * consumer evaluates phi = k D.x + wave_phase[i], which keeps float shaders exact at t = 1e6 s.
 * Far from the origin a consumer moves the origin instead: ww_waves_phases_at() gives the
 * phases at a reference point (the camera, a floating object), and positions are taken
 * relative to it.
 */
#ifndef WW_WAVES_H
#define WW_WAVES_H

#include "scene/scene.h"

/* per-wave phases at the origin for time t, wrapped to [0, 2 pi) (nwaves values) */
void ww_waves_phases(const ww_scene *sc, double t, double *phase);
/* the same phases moved to the reference point (rx, rz): phase_at[i] = wrap(phase[i] + k D.r);
 * positions are then given relative to (rx, rz) */
void ww_waves_phases_at(const ww_scene *sc, const double *phase, double rx, double rz,
                        double *phase_at);

/* one rest point's displaced surface point and its partials */
typedef struct ww_wave_point {
    double p[3];      /* (X, Y, Z): displaced point, m (relative to the phases' reference) */
    double dpdx[3];   /* partial of the point with respect to the rest x */
    double dpdz[3];   /* partial with respect to the rest z */
    double vel[3];    /* velocity of the water particle, m/s */
    double normal[3]; /* unit, up: normalize(dpdz x dpdx) */
} ww_wave_point;

/* components shorter than min_wavelength are left out (0 evaluates all); a floating object
 * ignores waves shorter than itself this way */
void ww_waves_point(const ww_scene *sc, const double *phase, double x, double z,
                    double min_wavelength, ww_wave_point *out);

/* the displaced surface point of rest point (x, z): out = (X, Y, Z); and the analytic normal
 * (unit, pointing up) when normal is not NULL. phase from ww_waves_phases. */
void ww_waves_eval(const ww_scene *sc, const double *phase, double x, double z, double out[3],
                   double normal[3]);

/* many rest points at once, structure of arrays, vectorised across points: X, Y, Z (each n) and,
 * when nx is not NULL, the unit normal in nx, ny, nz. Uses ww_sincos (core/sincos.h) so results
 * equal ww_waves_eval's to rounding. */
void ww_waves_eval_batch(const ww_scene *sc, const double *phase, int n, const double *x,
                         const double *z, double *X, double *Y, double *Z, double *nx,
                         double *ny, double *nz);
/* the same in float (what a shader computes), for the speed and error report */
void ww_waves_eval_batch_f(const ww_scene *sc, const double *phase, int n, const float *x,
                           const float *z, float *X, float *Y, float *Z, float *nx, float *ny,
                           float *nz);

/* the largest excursion of the surface from its rest level, m: the sum of the amplitudes
 * (a steep sine's component reaches 2 A (1 - mean) above the level) */
double ww_waves_total_amplitude(const ww_scene *sc);

#endif
