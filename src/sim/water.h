/* water.h - exact queries of the water surface at a world point: what every floating thing
 * reads. Waves and ripples together.
 *
 * Gerstner waves move water sideways, so the surface above a world point (x, z) is the displaced
 * image of some other rest point a: a + D(a) = (x, z). The query inverts D by damped Newton
 * iteration on F(a) = a + D(a) - x from a = x or from a warm start (ww_water_at_warm); the
 * fixed-point iteration a <- x - D(a) is a contraction with rate sum Q k A, too slow near the
 * fold. Each component's term of the Jacobian is damped where the step would turn its phase by
 * more than a radian, and a line search on the potential whose gradient is F keeps every step a
 * descent (sim/water.c). The residual |F|
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
    int ripple_slots;      /* entries of the pool to read (st->ripple_slots); 0: all */
} ww_field;

typedef struct ww_query_opts {
    double tolerance;      /* m: stop when |F| is below; default 1e-9 */
    int max_iterations;    /* default 32 */
    double min_wavelength; /* m: ignore shorter components (0: all) */
    double start[2];       /* m: the first guess's offset from the world point, a - x (0: the
                            * cold start a = x) */
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

/* how low the surface can be anywhere now: the rest level less every wave's and live ripple's
 * reach (steep sines reach 2 A below their mean, the others A), m. What lies lower is under
 * water wherever it is, without a query. */
double ww_water_lowest(const ww_scene *sc, const ww_state *st);

/* the same query warm-started from the answer at this sample point one step before: the rest
 * point's offset from the world point moves little between steps (the body and the waves move by
 * a few mm), so the inversion starts at the offset extrapolated linearly from the last two steps
 * and needs fewer evaluations than from a = x. warm (WW_WARM_STRIDE values, sim/state.h, kept in the owning
 * system's state, one per sample point): [0, 1] the last answer's a - x, m; [2, 3] its change
 * over the last step, m. All 0 is the cold start (reset); the query updates it. The answer is the
 * cold query's within the tolerance (1e-9 m): only where a sea folds can the two find different
 * rest points. */
int ww_water_at_warm(const ww_scene *sc, const ww_state *st, double x, double z,
                     double min_wavelength, double warm[WW_WARM_STRIDE], ww_water_sample *out);

/* the warm query at n points at once, for what needs only the height and the water's velocity
 * (a box's columns, sim/boxwater.c; the boat's samples): x, z, min_wavelength and warm
 * (WW_WARM_STRIDE values a point) as n ww_water_at_warm calls would take them; height (n) and
 * velocity (3 n, xyz a point; NULL: not wanted) as their answers' height and velocity, to the
 * bit. The points go through the iteration together in lanes (structure of arrays, vectorised
 * by the compiler); a point that leaves the common path (a trial that does not halve |F|, a far
 * point, a long wave list) is answered by ww_water_at_warm itself. Returns the number of points
 * that converged. */
int ww_water_at_warm_n(const ww_scene *sc, const ww_state *st, int n, const double *x,
                       const double *z, double min_wavelength, double *warm, double *height,
                       double *velocity);

#endif
