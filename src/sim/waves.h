/* waves.h - the Gerstner wave field of seed 000, evaluated in double on the CPU; the water shaders
 * evaluate the same formulas in float from the same parameters (shaders/water.vert.glsl).
 *
 * For wave i with unit direction D, amplitude A, steepness Q, wavenumber k = 2 pi / L, angular
 * frequency w (deep water: w^2 = g k) and phase offset p0, at rest point x = (x, z) and time t:
 *
 *   phi = k D.x - w t + p0                       (travels along +D)
 *   X   = x + sum Q A D cos(phi)                  (horizontal displacement, seed 000)
 *   Y   = level + sum A sin(phi)
 *
 * Seed 000 writes the phase as k D.x + c t, with the phase speed c in place of w = c k: that mixes
 * units (m/s added to radians) and sends the wave backwards; we use w t with the sign above.
 * The state keeps each wave's phase at the world origin, wrapped to [0, 2 pi): -w t + p0. So a
 * consumer evaluates phi = k D.x + wave_phase[i], which keeps float shaders exact at t = 1e6 s.
 */
#ifndef WW_WAVES_H
#define WW_WAVES_H

#include "scene/scene.h"

/* per-wave phases at the origin for time t, wrapped to [0, 2 pi) (nwaves values) */
void ww_waves_phases(const ww_scene *sc, double t, double *phase);

/* the displaced surface point of rest point (x, z): out = (X, Y, Z); and the analytic normal
 * (unit, pointing up) when normal is not NULL. phase from ww_waves_phases. */
void ww_waves_eval(const ww_scene *sc, const double *phase, double x, double z, double out[3],
                   double normal[3]);

#endif
