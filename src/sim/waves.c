/* waves.c - the Gerstner sum of seed 000 in double precision (formulas in waves.h). Phases are
 * kept per wave at the origin and wrapped, so large t loses no precision in consumers.
 */
#include "sim/waves.h"

#include <math.h>

#include "core/mathx.h"

void ww_waves_phases(const ww_scene *sc, double t, double *phase) {
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        /* fmod of omega t alone keeps the wrap exact to ~1 ulp of 2 pi even at t = 1e6 s */
        phase[i] = ww_m_wrap_tau(w->phase - ww_m_wrap_tau(w->omega * t));
    }
}

void ww_waves_eval(const ww_scene *sc, const double *phase, double x, double z, double out[3],
                   double normal[3]) {
    double X = x, Y = sc->water_level, Z = z;
    /* partials of the displaced point with respect to the rest coordinates */
    double dxx = 1.0, dxy = 0.0, dxz = 0.0, dzx = 0.0, dzy = 0.0, dzz = 1.0;
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        double dx = w->dir[0], dz = w->dir[1];
        double ph = w->k * (dx * x + dz * z) + phase[i];
        double s = sin(ph), c = cos(ph);
        double qa = w->steepness * w->amplitude;
        X += qa * dx * c;
        Z += qa * dz * c;
        Y += w->amplitude * s;
        double wa = w->k * w->amplitude, qwa = w->k * qa;
        dxx -= qwa * dx * dx * s;
        dxy += wa * dx * c;
        dxz -= qwa * dx * dz * s;
        dzx -= qwa * dx * dz * s;
        dzy += wa * dz * c;
        dzz -= qwa * dz * dz * s;
    }
    out[0] = X;
    out[1] = Y;
    out[2] = Z;
    if (normal) {
        /* n = dP/dz x dP/dx, up for a flat sea */
        normal[0] = dzy * dxz - dzz * dxy;
        normal[1] = dzz * dxx - dzx * dxz;
        normal[2] = dzx * dxy - dzy * dxx;
        ww_m_normalize3(normal);
    }
}
