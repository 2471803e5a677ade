/* oscillator.h - the damped harmonic oscillator x'' = acc - w2 x - gamma x', advanced exactly
 * (under-, critically and overdamped, and the spring-free limit): what makes the cubes' spring
 * buoyancy exact at any step. */
#ifndef WW_OSCILLATOR_H
#define WW_OSCILLATOR_H

/* (x, v) advanced by dt */
void ww_m_damped_oscillator(double w2, double gamma, double acc, double dt, double *x,
                            double *v);

#endif
