/* water.h - exact queries of the water surface at a world point: what every floating thing
 * reads. Waves and ripples together.
 *
 * Gerstner waves move water sideways, so the surface above a world point (x, z) is the displaced
 * image of some other rest point a: a + D(a) = (x, z). The query inverts D by damped Newton
 * iteration on F(a) = a + D(a) - x from a = x (the fixed-point iteration a <- x - D(a) is a
 * contraction with rate sum Q k A, too slow near the fold): each component's term of the
 * Jacobian is damped where the step would turn its phase by more than a radian, and a line search
 * on the potential whose gradient is F keeps every step a descent (sim/water.c). The residual |F|
 * and the number of evaluations are reported. Sines and steep sines do not move water sideways:
 * a = x at once.
 *
 *   double phase[WW_MAX_WAVES]; ww_waves_phases(sc, t, phase);       // or st->wave_phase
 *   ww_field f = {.sc = sc, .phase = phase, .t = t, .ripples = st->ripple};
 *   ww_water_sample s; ww_water_height(&f, x, z, NULL, &s);
 */
#ifndef WW_WATER_H
#define WW_WATER_H

#include "scene/scene.h"
#include "sim/state.h"

/* the surface at one time */
typedef struct ww_field {
    const ww_scene *sc;
    const double *phase;   /* per-wave phases at the origin for time t (ww_waves_phases) */
    double t;              /* s, for the ripples' ages */
    const double *ripples; /* the state's pool (st->ripple), NULL for none */
} ww_field;

typedef struct ww_query_opts {
    double tolerance;      /* m: stop when |F| is below; default 1e-9 */
    int max_iterations;    /* default 32 */
    double min_wavelength; /* m: ignore shorter components (0: all) */
} ww_query_opts;

#define WW_QUERY_TOLERANCE 1e-9
#define WW_QUERY_MAX_ITERATIONS 32

typedef struct ww_water_sample {
    double height;      /* y of the surface over world (x, z), m */
    double normal[3];   /* unit, up */
    double velocity[3]; /* of the water at the surface there (orbital motion + ripple dh/dt), m/s */
    double rest[2];     /* the rest point whose displaced image is (x, z) */
    double residual;    /* |a + D(a) - x| at the answer, m */
    int iterations;     /* evaluations of the wave sum the inversion took */
    int converged;      /* residual <= tolerance */
} ww_water_sample;

/* the surface over world (x, z); returns out->converged. When it did not converge (a folding
 * sea) the answer is the best rest point found: finite, with its residual reported. */
int ww_water_height(const ww_field *f, double x, double z, const ww_query_opts *opts,
                    ww_water_sample *out);

/* the surface over (x, z) as the systems of a step read it: the waves at st->t (the state's
 * phases) and the state's ripples; components shorter than min_wavelength are ignored (0: all).
 * Default tolerance and iteration cap. Returns out->converged. */
int ww_water_at(const ww_scene *sc, const ww_state *st, double x, double z,
                double min_wavelength, ww_water_sample *out);

#endif
