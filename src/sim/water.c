/* water.c - the exact surface over a world point (water.h): inverts the Gerstner horizontal
 * displacement by a damped Newton iteration on a smoothed Jacobian, then adds the ripples;
 * height, normal and velocity. The same iteration over many points in vectorised lanes
 * (ww_water_at_warm_n) for the bodies that sample several.
 */
#include "sim/water.h"

#include <math.h>

#include "core/mathx.h"
#include "core/lanes.h"
#include "core/sincos.h"
#include "sim/ripples.h"
#include "sim/waves.h"

/* beyond this distance from the origin the phases move to a reference at the point, so the
 * positions the wave sum sees stay small (waves.h); closer, the origin's phases are exact enough */
#define FAR_FROM_ORIGIN 1024.0
/* Armijo's sufficient decrease of G along the step (Nocedal and Wright, eq. 3.4) */
#define ARMIJO 1e-4
/* a step that halves |F| is accepted whatever G does: near the answer G's decrease (|F|^2) is
 * below G's own rounding */
#define RESIDUAL_CUT 0.5
/* the line search's next step fraction stays within these parts of the last one */
#define LAMBDA_LO 0.1
#define LAMBDA_HI 0.5

/* one evaluation of the Gerstner sum at rest point a (relative to the reference): what the
 * iteration needs (F, G and each component's sine); the height, slope, Jacobian and velocity
 * are made once, at the answer (finish) */
typedef struct probe {
    double a[2];       /* rest point, m */
    double F[2];       /* a + D(a) - x, m */
    double norm;       /* |F|, m */
    double G;          /* the potential whose gradient is F (see ww_water_height), m^2; NaN until
                        * potential() works it out */
    double *sn, *cn;   /* sin(phi), cos(phi) per component (0 for the ignored ones) */
} probe;

/* what the answer reports at its rest point, from its sines and cosines */
typedef struct answer {
    double J[3];       /* horizontal Jacobian d(a + D)/da: xx, xz (= zx), zz */
    double Y;          /* surface height above the rest level at a, m */
    double dY[2];      /* dY/da */
    double vel[3];     /* particle velocity, m/s */
} answer;

/* a probe at rest point a whose waves displace it by (dx0, dz0): its residual against x */
static void close_probe(probe *pr, const double a[2], const double x[2], double dx0, double dz0) {
    pr->a[0] = a[0];
    pr->a[1] = a[1];
    pr->F[0] = a[0] + dx0 - x[0];
    pr->F[1] = a[1] + dz0 - x[1];
    pr->norm = sqrt(pr->F[0] * pr->F[0] + pr->F[1] * pr->F[1]);
    pr->G = NAN; /* potential(), where the line search needs it */
}

/* the Gerstner sum of waves.h at a, with G = |a - x|^2 / 2 + sum (Q A / k) sin(phi): its
 * gradient is F since d/da (Q A / k) sin(phi) = Q A D cos(phi) */
static void evaluate(const ww_scene *sc, const double *phase, double minL, const double x[2],
                     const double a[2], probe *pr) {
    double dx0 = 0.0, dz0 = 0.0;
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->wavelength < minL) {
            pr->sn[i] = pr->cn[i] = 0.0;
            continue;
        }
        double dx = w->dir[0], dz = w->dir[1];
        double ph = w->k * (dx * a[0] + dz * a[1]) + phase[i];
        double s, c;
        ww_sincos(ph, &s, &c);
        double qa = w->steepness * w->amplitude;
        pr->sn[i] = s;
        pr->cn[i] = c;
        dx0 += qa * dx * c;
        dz0 += qa * dz * c;
    }
    close_probe(pr, a, x, dx0, dz0);
}

/* G at the probe, from its sines, once: only a trial that does not halve |F| needs it */
static double potential(const ww_scene *sc, double minL, const double x[2], probe *pr) {
    if (isnan(pr->G)) {
        double phi = 0.0;
        for (int i = 0; i < sc->nwaves; i++) {
            const ww_wave *w = &sc->waves[i];
            if (w->wavelength < minL) continue;
            phi += w->steepness * w->amplitude / w->k * pr->sn[i];
        }
        double ex = pr->a[0] - x[0], ez = pr->a[1] - x[1];
        pr->G = 0.5 * (ex * ex + ez * ez) + phi;
    }
    return pr->G;
}

/* height, slope, Jacobian and particle velocity at the probe's rest point */
static void finish(const ww_scene *sc, double minL, const probe *pr, answer *an) {
    double y = 0.0, yx = 0.0, yz = 0.0;
    double jxx = 1.0, jxz = 0.0, jzz = 1.0, vx = 0.0, vy = 0.0, vz = 0.0;
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->wavelength < minL) continue;
        double dx = w->dir[0], dz = w->dir[1], s = pr->sn[i], c = pr->cn[i];
        double A = w->amplitude, qa = w->steepness * A, qka = w->k * qa;
        y += A * s;
        yx += w->k * dx * A * c;
        yz += w->k * dz * A * c;
        jxx -= qka * dx * dx * s;
        jxz -= qka * dx * dz * s;
        jzz -= qka * dz * dz * s;
        vx += qa * w->omega * dx * s;
        vy -= w->omega * A * c;
        vz += qa * w->omega * dz * s;
    }
    an->J[0] = jxx;
    an->J[1] = jxz;
    an->J[2] = jzz;
    an->Y = y;
    an->dY[0] = yx;
    an->dY[1] = yz;
    an->vel[0] = vx;
    an->vel[1] = vy;
    an->vel[2] = vz;
}

/* the step direction at pr. Newton's d = -J^-1 F, but with each component's term of J damped
 * by rho = 1 / (1 + (k |F|)^2): over a step of about |F| a component whose phase would turn by
 * more than a radian has a local slope that says nothing about the step, and its slope averages
 * to 0 over a period. Far from the answer Newton then follows the long waves and treats the short
 * ones as a bounded perturbation; near it rho -> 1 (the error is O(|F|^2)) and Newton's quadratic
 * convergence returns. J_eff = I - sum rho Q k A D D^T sin(phi) is positive definite while
 * sum Q k A < 1; where it is not (a fold), the fixed-point direction -F, which G also decreases
 * along, is taken. */
static void direction(const ww_scene *sc, double minL, const probe *pr, double d[2]) {
    double jxx = 1.0, jxz = 0.0, jzz = 1.0;
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->wavelength < minL) continue;
        double kr = w->k * pr->norm, rho = 1.0 / (1.0 + kr * kr);
        double t = rho * w->steepness * w->k * w->amplitude * pr->sn[i];
        jxx -= t * w->dir[0] * w->dir[0];
        jxz -= t * w->dir[0] * w->dir[1];
        jzz -= t * w->dir[1] * w->dir[1];
    }
    double det = jxx * jzz - jxz * jxz;
    if (jxx > 0.0 && jzz > 0.0 && det > 0.0) {
        d[0] = -(jzz * pr->F[0] - jxz * pr->F[1]) / det;
        d[1] = -(jxx * pr->F[1] - jxz * pr->F[0]) / det;
    } else {
        d[0] = -pr->F[0];
        d[1] = -pr->F[1];
    }
}

/* a step that turns every phase by at most this (rad) makes its trial's sines and cosines from
 * the current ones by angle addition (evaluate_near) instead of the sincos of each phase */
#define NEAR_TURN 1e-2
/* the Taylor coefficients of sin e / e and cos e in e^2: -1/3!, 1/5!, -1/7!; -1/2!, 1/4!, -1/6! */
#define SIN3 (-1.0 / 6.0)
#define SIN5 (1.0 / 120.0)
#define SIN7 (-1.0 / 5040.0)
#define COS2 (-0.5)
#define COS4 (1.0 / 24.0)
#define COS6 (-1.0 / 720.0)

/* the trial at a from the probe from at a nearby point: each component's phase turns by
 * e = k D.(a - from.a), and sin(phi + e) = sin phi cos e + cos phi sin e, with sin e and cos e
 * from their Taylor series to e^7 and e^6 (truncation below 3e-21 for |e| <= NEAR_TURN, so the
 * same to rounding as evaluate's sincos of the phase). Returns 0, leaving pr alone, where a phase
 * would turn by more than NEAR_TURN. The residual is measured as in evaluate, not estimated. */
static int evaluate_near(const ww_scene *sc, double minL, const double x[2], const probe *from,
                         const double a[2], probe *pr) {
    double da0 = a[0] - from->a[0], da1 = a[1] - from->a[1];
    double dx0 = 0.0, dz0 = 0.0;
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->wavelength < minL) {
            pr->sn[i] = pr->cn[i] = 0.0;
            continue;
        }
        double dx = w->dir[0], dz = w->dir[1], e = w->k * (dx * da0 + dz * da1);
        if (!(fabs(e) <= NEAR_TURN)) return 0; /* pr is scratch until it is returned whole */
        double z = e * e;
        double se = e * (1.0 + z * (SIN3 + z * (SIN5 + z * SIN7)));
        double ce = 1.0 + z * (COS2 + z * (COS4 + z * COS6));
        double s = from->sn[i] * ce + from->cn[i] * se, c = from->cn[i] * ce - from->sn[i] * se;
        double qa = w->steepness * w->amplitude;
        pr->sn[i] = s;
        pr->cn[i] = c;
        dx0 += qa * dx * c;
        dz0 += qa * dz * c;
    }
    close_probe(pr, a, x, dx0, dz0);
    return 1;
}

/* the slot that is neither the current point nor the best so far */
static probe *free_slot(probe slot[3], const probe *cur, const probe *top) {
    for (int k = 0; k < 2; k++)
        if (&slot[k] != cur && &slot[k] != top) return &slot[k];
    return &slot[2];
}

/* damped Newton on F(a) = a + D(a) - x from a = a0 (x for a cold start). F is the gradient of
 * G(a) = |a - x|^2 / 2 + sum (Q A / k) sin(phi), strongly convex while sum Q k A < 1 (its Hessian J
 * has eigenvalues in [1 - sum, 1 + sum]), so a descent direction with a backtracking line search
 * on G converges from any start (Nocedal and Wright, "Numerical Optimization", 2nd ed., ch. 3:
 * Armijo condition, quadratic interpolation of the step). Returns the evaluations taken. */
static int invert(const ww_scene *sc, const double *phase, double minL, const double x[2],
                  const double a0[2], double tol, int maxit, probe slot[3], const probe **best) {
    /* the probes change roles (current point, trial, best so far) by pointer, not by copying */
    probe *cur = &slot[0], *top = cur;
    evaluate(sc, phase, minL, x, a0, cur);
    int it = 1;
    while (cur->norm > tol && it < maxit) {
        double d[2];
        direction(sc, minL, cur, d);
        double slope = cur->F[0] * d[0] + cur->F[1] * d[1]; /* dG/dlambda at 0 */
        double lam = 1.0;
        probe *next = NULL;
        while (it < maxit) {
            probe *trial = free_slot(slot, cur, top);
            double a[2] = {cur->a[0] + lam * d[0], cur->a[1] + lam * d[1]};
            if (!evaluate_near(sc, minL, x, cur, a, trial)) evaluate(sc, phase, minL, x, a, trial);
            it++;
            if (trial->norm < top->norm) top = trial;
            if (trial->norm <= RESIDUAL_CUT * cur->norm ||
                potential(sc, minL, x, trial) <= potential(sc, minL, x, cur) + ARMIJO * lam * slope) {
                next = trial;
                break;
            }
            /* minimiser of the quadratic through G(0), G'(0) and G(lam) */
            double q = -slope * lam * lam / (2.0 * (trial->G - cur->G - slope * lam));
            lam = fmin(fmax(q, LAMBDA_LO * lam), LAMBDA_HI * lam);
        }
        if (!next) break;
        cur = next;
    }
    *best = top;
    return it;
}

int ww_water_height(const ww_field *f, double x, double z, const ww_query_opts *opts,
                    ww_water_sample *out) {
    const ww_scene *sc = f->sc;
    double tol = opts && opts->tolerance > 0.0 ? opts->tolerance : WW_QUERY_TOLERANCE;
    int maxit = opts && opts->max_iterations > 0 ? opts->max_iterations : WW_QUERY_MAX_ITERATIONS;
    double minL = opts ? opts->min_wavelength : 0.0;

    /* phases at a reference near a far point; positions relative to it */
    double phase_at[WW_MAX_WAVES];
    const double *phase = f->phase;
    double ref[2] = {0.0, 0.0};
    if (fabs(x) > FAR_FROM_ORIGIN || fabs(z) > FAR_FROM_ORIGIN) {
        ref[0] = round(x);
        ref[1] = round(z);
        ww_waves_phases_at(sc, f->phase, ref[0], ref[1], phase_at);
        phase = phase_at;
    }
    double xr[2] = {x - ref[0], z - ref[1]};

    /* the wave surface over xr: its height, slope in rest coordinates, horizontal Jacobian and
     * particle velocity at the rest point */
    double y, dy[2], J[3], vel[3], rest[2], residual;
    int iterations;
    if (sc->wave_model == WW_WAVES_GERSTNER || sc->wave_model == WW_WAVES_SPECTRUM) {
        double buf[6][WW_MAX_WAVES];
        probe slot[3]; /* evaluate fills every other field */
        for (int k = 0; k < 3; k++) {
            slot[k].sn = buf[2 * k];
            slot[k].cn = buf[2 * k + 1];
        }
        const probe *best;
        answer an;
        double a0[2] = {xr[0], xr[1]};
        if (opts) {
            a0[0] += opts->start[0];
            a0[1] += opts->start[1];
        }
        iterations = invert(sc, phase, minL, xr, a0, tol, maxit, slot, &best);
        finish(sc, minL, best, &an);
        y = sc->water_level + an.Y;
        dy[0] = an.dY[0];
        dy[1] = an.dY[1];
        for (int c = 0; c < 3; c++) {
            J[c] = an.J[c];
            vel[c] = an.vel[c];
        }
        rest[0] = best->a[0];
        rest[1] = best->a[1];
        residual = best->norm;
    } else {
        /* no sideways motion: the rest point is the world point */
        ww_wave_point p;
        ww_waves_point(sc, phase, xr[0], xr[1], minL, &p);
        iterations = 1;
        y = p.p[1];
        dy[0] = p.dpdx[1];
        dy[1] = p.dpdz[1];
        J[0] = p.dpdx[0];
        J[1] = p.dpdz[0];
        J[2] = p.dpdz[2];
        for (int c = 0; c < 3; c++) vel[c] = p.vel[c];
        rest[0] = xr[0];
        rest[1] = xr[1];
        residual = hypot(p.p[0] - xr[0], p.p[2] - xr[1]);
    }

    /* the ripples at the world point */
    double rg[2], rdt;
    int slots = f->ripple_slots > 0 ? f->ripple_slots : sc->ripples.max;
    double rh = ww_ripples_height_n(sc, f->ripples, slots, f->t, x, z, rg, &rdt);
    out->height = y + rh;

    /* normal: grad h = J^-T grad_a Y + ripple gradient, n = normalize(-hx, 1, -hz). Multiplied
     * through by det J it is the cross-product normal dP/dz x dP/dx plus det J (-rx, 0, -rz),
     * which stays defined where det J -> 0 (a fold); |det J| keeps it pointing up */
    double det = J[0] * J[2] - J[1] * J[1];
    double n[3] = {dy[1] * J[1] - J[2] * dy[0] - det * rg[0], det,
                   J[1] * dy[0] - dy[1] * J[0] - det * rg[1]};
    if (det < 0.0)
        for (int c = 0; c < 3; c++) n[c] = -n[c];
    double len = ww_m_len3(n);
    if (len > 0.0 && isfinite(len)) {
        for (int c = 0; c < 3; c++) out->normal[c] = n[c] / len;
    } else {
        out->normal[0] = out->normal[2] = 0.0;
        out->normal[1] = 1.0;
    }
    out->velocity[0] = vel[0];
    out->velocity[1] = vel[1] + rdt;
    out->velocity[2] = vel[2];
    out->rest[0] = rest[0] + ref[0];
    out->rest[1] = rest[1] + ref[1];
    out->residual = residual;
    out->iterations = iterations;
    out->converged = residual <= tol;
    return out->converged;
}

double ww_water_lowest(const ww_scene *sc, const ww_state *st) {
    double low = sc->water_level;
    for (int i = 0; i < sc->nwaves; i++) low -= 2.0 * fabs(sc->waves[i].amplitude);
    if (sc->ripples_on)
        for (int i = 0; i < st->ripple_slots[0]; i++) low -= fabs(st->ripple[4 * i + 3]);
    return low;
}

/* the state's pool as a query reads it: NULL while every slot is free */
static const double *ripples_in_use(const ww_scene *sc, const ww_state *st) {
    return sc->ripples_on && st->ripple_slots[0] > 0 ? st->ripple : NULL;
}

int ww_water_at(const ww_scene *sc, const ww_state *st, double x, double z,
                double min_wavelength, ww_water_sample *out) {
    ww_field f = {.sc = sc, .phase = st->wave_phase, .t = st->t, .ripples = ripples_in_use(sc, st),
                  .ripple_slots = sc->ripples_on ? st->ripple_slots[0] : 0};
    ww_query_opts o = {.tolerance = WW_QUERY_TOLERANCE,
                       .max_iterations = WW_QUERY_MAX_ITERATIONS,
                       .min_wavelength = min_wavelength};
    return ww_water_height(&f, x, z, &o, out);
}

int ww_water_at_warm(const ww_scene *sc, const ww_state *st, double x, double z,
                     double min_wavelength, double warm[WW_WARM_STRIDE], ww_water_sample *out) {
    ww_field f = {.sc = sc, .phase = st->wave_phase, .t = st->t, .ripples = ripples_in_use(sc, st),
                  .ripple_slots = sc->ripples_on ? st->ripple_slots[0] : 0};
    ww_query_opts o = {.tolerance = WW_QUERY_TOLERANCE,
                       .max_iterations = WW_QUERY_MAX_ITERATIONS,
                       .min_wavelength = min_wavelength,
                       .start = {warm[0] + warm[2], warm[1] + warm[3]}};
    int ok = ww_water_height(&f, x, z, &o, out);
    double off[2] = {out->rest[0] - x, out->rest[1] - z};
    warm[2] = off[0] - warm[0];
    warm[3] = off[1] - warm[1];
    warm[0] = off[0];
    warm[1] = off[1];
    return ok;
}

/* ---- many points at once (ww_water_at_warm_n) ----------------------------------------------- */

/* points per lane block: every loop over a block runs this many iterations over local arrays (a
 * short block is padded with its last point), so GCC's -O2 cost model vectorises them without an
 * epilogue or alias checks */
#define LANES 8
/* the lanes keep the sines and cosines of this many components; a longer list takes the
 * one-point path */
#define LANE_WAVES 64
/* a point stays in the lanes for at most this many evaluations (the lake's queries take 2.03) */
#define LANE_EVALUATIONS 8

/* the components a lane query sums (those not shorter than its min_wavelength), in order */
typedef struct lane_wave {
    double k, dir[2], steepness, amplitude, omega;
    int index; /* in sc->waves, for its phase */
} lane_wave;
typedef struct lane_waves {
    int n;
    lane_wave w[LANE_WAVES];
} lane_waves;

/* one probe per lane (struct of arrays): rest point, residual, each component's sine and cosine */
typedef struct lane_probe {
    double a[2][LANES];
    double F[2][LANES];
    double norm[LANES];
    double sn[LANE_WAVES][LANES], cn[LANE_WAVES][LANES];
} lane_probe;

/* F = a + D - x and |F| of every lane, as close_probe; d: the displacements. The root has its
 * own loop, which vectorises (the build's -fno-math-errno makes sqrt an instruction, not a call
 * that may set errno) */
WW_LANE_STEP void lanes_close(lane_probe *p, double x[2][LANES], double d[2][LANES]) {
    double n2[LANES];
    for (int c = 0; c < LANES; c++) {
        p->F[0][c] = p->a[0][c] + d[0][c] - x[0][c];
        p->F[1][c] = p->a[1][c] + d[1][c] - x[1][c];
        n2[c] = p->F[0][c] * p->F[0][c] + p->F[1][c] * p->F[1][c];
    }
    for (int c = 0; c < LANES; c++) p->norm[c] = sqrt(n2[c]);
}

/* the Gerstner sum at every lane's rest point p->a, as evaluate */
WW_LANE_STEP void lanes_evaluate(const lane_waves *lw, const double *phase, double x[2][LANES],
                           lane_probe *p) {
    double d[2][LANES] = {{0.0}};
    for (int i = 0; i < lw->n; i++) {
        const lane_wave *w = &lw->w[i];
        double k = w->k, dx = w->dir[0], dz = w->dir[1], ph0 = phase[w->index];
        double qa = w->steepness * w->amplitude;
        for (int c = 0; c < LANES; c++) {
            double s, co;
            ww_sincos(k * (dx * p->a[0][c] + dz * p->a[1][c]) + ph0, &s, &co);
            p->sn[i][c] = s;
            p->cn[i][c] = co;
            d[0][c] += qa * dx * co;
            d[1][c] += qa * dz * co;
        }
    }
    lanes_close(p, x, d);
}

/* the trial at t->a from the probe p by angle addition, as evaluate_near; far[c] becomes 1 where
 * a phase of lane c turns by more than NEAR_TURN (its trial is then evaluate's) */
WW_LANE_STEP void lanes_near(const lane_waves *lw, double x[2][LANES], const lane_probe *p,
                       lane_probe *t, double far[LANES]) {
    double d[2][LANES] = {{0.0}}, da[2][LANES];
    for (int c = 0; c < LANES; c++) {
        da[0][c] = t->a[0][c] - p->a[0][c];
        da[1][c] = t->a[1][c] - p->a[1][c];
        far[c] = 0.0;
    }
    for (int i = 0; i < lw->n; i++) {
        const lane_wave *w = &lw->w[i];
        double k = w->k, dx = w->dir[0], dz = w->dir[1], qa = w->steepness * w->amplitude;
        for (int c = 0; c < LANES; c++) {
            double e = k * (dx * da[0][c] + dz * da[1][c]);
            far[c] = fabs(e) <= NEAR_TURN ? far[c] : 1.0;
            double z = e * e;
            double se = e * (1.0 + z * (SIN3 + z * (SIN5 + z * SIN7)));
            double ce = 1.0 + z * (COS2 + z * (COS4 + z * COS6));
            double s = p->sn[i][c] * ce + p->cn[i][c] * se;
            double co = p->cn[i][c] * ce - p->sn[i][c] * se;
            t->sn[i][c] = s;
            t->cn[i][c] = co;
            d[0][c] += qa * dx * co;
            d[1][c] += qa * dz * co;
        }
    }
    lanes_close(t, x, d);
}

/* the damped Newton direction of every lane, as direction */
WW_LANE_STEP void lanes_direction(const lane_waves *lw, const lane_probe *p, double d[2][LANES]) {
    double jxx[LANES], jxz[LANES], jzz[LANES];
    for (int c = 0; c < LANES; c++) {
        jxx[c] = 1.0;
        jxz[c] = 0.0;
        jzz[c] = 1.0;
    }
    for (int i = 0; i < lw->n; i++) {
        const lane_wave *w = &lw->w[i];
        double k = w->k, q = w->steepness, A = w->amplitude, dx = w->dir[0], dz = w->dir[1];
        for (int c = 0; c < LANES; c++) {
            double kr = k * p->norm[c], rho = 1.0 / (1.0 + kr * kr);
            double t = rho * q * k * A * p->sn[i][c];
            jxx[c] -= t * dx * dx;
            jxz[c] -= t * dx * dz;
            jzz[c] -= t * dz * dz;
        }
    }
    /* both candidates are worked out and one kept, so the loop has no branch */
    for (int c = 0; c < LANES; c++) {
        double det = jxx[c] * jzz[c] - jxz[c] * jxz[c], F0 = p->F[0][c], F1 = p->F[1][c];
        double n0 = -(jzz[c] * F0 - jxz[c] * F1) / det, n1 = -(jxx[c] * F1 - jxz[c] * F0) / det;
        int ok = (jxx[c] > 0.0) & (jzz[c] > 0.0) & (det > 0.0); /* &, not &&: no branch */
        d[0][c] = ok ? n0 : -F0;
        d[1][c] = ok ? n1 : -F1;
    }
}

/* lane c of p <- lane c of q where take[c] is not 0 */
WW_LANE_STEP void lanes_take(const lane_waves *lw, lane_probe *p, const lane_probe *q,
                       const double take[LANES]) {
    for (int c = 0; c < LANES; c++) {
        int k = take[c] != 0.0;
        p->a[0][c] = k ? q->a[0][c] : p->a[0][c];
        p->a[1][c] = k ? q->a[1][c] : p->a[1][c];
        p->F[0][c] = k ? q->F[0][c] : p->F[0][c];
        p->F[1][c] = k ? q->F[1][c] : p->F[1][c];
        p->norm[c] = k ? q->norm[c] : p->norm[c];
    }
    for (int i = 0; i < lw->n; i++)
        for (int c = 0; c < LANES; c++) {
            int k = take[c] != 0.0;
            p->sn[i][c] = k ? q->sn[i][c] : p->sn[i][c];
            p->cn[i][c] = k ? q->cn[i][c] : p->cn[i][c];
        }
}

/* the sum over the ripples of pool (n entries, as ww_ripples_reaching lists them) at every
 * lane's world point: height rh and dh/dt rdt, as ww_ripples_height_n gives them to the bit (the
 * same term in the same order; an entry whose front does not reach a lane adds nothing there) */
WW_LANE_STEP void lanes_ripples(const ww_scene *sc, const double *pool, int n, double t,
                                double x[2][LANES], double rh[LANES], double rdt[LANES]) {
    const ww_ripple_desc *rd = &sc->ripples;
    double kr = rd->wavenumber, v = rd->speed;
    double lambda = WW_TAU / kr, r0 = 1.0 / kr;
    for (int i = 0; i < n; i++) {
        const double *e = pool + i * WW_RIPPLE_STRIDE;
        double age = t - e[2], front = v * age + lambda;
        double reach = WW_RIPPLE_FRONT_MARGIN * front * front;
        double r2[LANES], r[LANES];
        for (int c = 0; c < LANES; c++) {
            double dx = x[0][c] - e[0], dz = x[1][c] - e[1];
            r2[c] = dx * dx + dz * dz + r0 * r0;
        }
        for (int c = 0; c < LANES; c++) r[c] = sqrt(r2[c]);
        for (int c = 0; c < LANES; c++) {
            double u = (v * age - r[c]) / lambda + 1.0, h, dhdr, dhda;
            ww_ripple_term(rd, e[3], age, r[c], u, lambda, &h, &dhdr, &dhda);
            int in = r2[c] <= reach && u > 0.0;
            rh[c] = in ? rh[c] + h : rh[c];
            rdt[c] = in ? rdt[c] + dhda : rdt[c];
        }
    }
}

/* the warm queries of up to LANES points (m of them, the block padded with the last): the
 * iteration of invert while every trial is its first step (lambda = 1) and halves |F|, which the
 * best so far then is; a point where that fails, or far from the origin, is left to
 * ww_water_at_warm (alone[c]). Then finish's height and velocity, and the ripples; velocity
 * may be NULL. */
WW_LANE_STEP int lanes_query(const ww_scene *sc, const ww_state *st, const lane_waves *lw,
                       double minL, int m, const double *x, const double *z, double *warm,
                       double *height, double *velocity) {
    lane_probe P[3];
    lane_probe *cur = &P[0], *trial = &P[1], *cold = &P[2];
    double xw[2][LANES], alone[LANES];
    for (int c = 0; c < LANES; c++) {
        int j = c < m ? c : m - 1;
        const double *wm = warm + WW_WARM_STRIDE * j;
        xw[0][c] = x[j];
        xw[1][c] = z[j];
        cur->a[0][c] = x[j] + (wm[0] + wm[2]);
        cur->a[1][c] = z[j] + (wm[1] + wm[3]);
        alone[c] = (fabs(x[j]) > FAR_FROM_ORIGIN) | (fabs(z[j]) > FAR_FROM_ORIGIN) ? 1.0 : 0.0;
    }
    lanes_evaluate(lw, st->wave_phase, xw, cur);
    for (int evals = 1;; evals++) {
        double open[LANES], d[2][LANES], far[LANES], take[LANES];
        double nopen = 0.0; /* a count, summed without a branch so the loop vectorises */
        for (int c = 0; c < LANES; c++) {
            open[c] = alone[c] == 0.0 && cur->norm[c] > WW_QUERY_TOLERANCE ? 1.0 : 0.0;
            nopen += open[c];
        }
        if (nopen == 0.0) break;
        if (evals >= LANE_EVALUATIONS) {
            for (int c = 0; c < LANES; c++) alone[c] = open[c] != 0.0 ? 1.0 : alone[c];
            break;
        }
        lanes_direction(lw, cur, d);
        for (int c = 0; c < LANES; c++) {
            trial->a[0][c] = cur->a[0][c] + d[0][c];
            trial->a[1][c] = cur->a[1][c] + d[1][c];
        }
        lanes_near(lw, xw, cur, trial, far);
        double nfar = 0.0;
        for (int c = 0; c < LANES; c++) {
            far[c] = open[c] != 0.0 ? far[c] : 0.0;
            nfar += far[c];
        }
        if (nfar != 0.0) {
            for (int c = 0; c < LANES; c++) {
                cold->a[0][c] = trial->a[0][c];
                cold->a[1][c] = trial->a[1][c];
            }
            lanes_evaluate(lw, st->wave_phase, xw, cold);
            lanes_take(lw, trial, cold, far);
        }
        /* a trial that halves |F| is taken, as invert takes it; any other point goes alone.
         * Where every lane takes its trial (most first steps) the probes swap roles */
        double ntake = 0.0;
        for (int c = 0; c < LANES; c++) {
            int halves = trial->norm[c] <= RESIDUAL_CUT * cur->norm[c];
            take[c] = open[c] != 0.0 && halves ? 1.0 : 0.0;
            alone[c] = open[c] != 0.0 && !halves ? 1.0 : alone[c];
            ntake += take[c];
        }
        if (ntake == LANES) {
            lane_probe *was = cur;
            cur = trial;
            trial = was;
        } else {
            lanes_take(lw, cur, trial, take);
        }
    }

    /* finish's height and velocity */
    double y[LANES], v[3][LANES];
    for (int c = 0; c < LANES; c++) y[c] = v[0][c] = v[1][c] = v[2][c] = 0.0;
    for (int i = 0; i < lw->n; i++) {
        const lane_wave *w = &lw->w[i];
        double A = w->amplitude, qa = w->steepness * A, om = w->omega;
        double dx = w->dir[0], dz = w->dir[1];
        for (int c = 0; c < LANES; c++) {
            double s = cur->sn[i][c], co = cur->cn[i][c];
            y[c] += A * s;
            v[0][c] += qa * om * dx * s;
            v[1][c] -= om * A * co;
            v[2][c] += qa * om * dz * s;
        }
    }

    /* the ripples at the world points (those whose front reaches the block's rectangle), the
     * answers and the warm starts */
    const double *rip = ripples_in_use(sc, st);
    int rslots = sc->ripples_on ? st->ripple_slots[0] : 0, converged = 0;
    if (rslots <= 0) rslots = sc->ripples.max;
    double near[WW_MAX_RIPPLES * WW_RIPPLE_STRIDE];
    if (rip) {
        double lo[2] = {x[0], z[0]}, hi[2] = {x[0], z[0]};
        /* ternaries, not fmin and fmax: those are libm calls at -O2, and the points are finite */
        for (int c = 1; c < m; c++) {
            lo[0] = x[c] < lo[0] ? x[c] : lo[0], hi[0] = x[c] > hi[0] ? x[c] : hi[0];
            lo[1] = z[c] < lo[1] ? z[c] : lo[1], hi[1] = z[c] > hi[1] ? z[c] : hi[1];
        }
        rslots = ww_ripples_reaching(sc, rip, rslots, st->t, lo, hi, near);
        rip = rslots > 0 ? near : NULL;
    }
    /* where no ripple reaches the block their sum is 0, as ww_ripples_height_n gives it */
    double rh[LANES] = {0.0}, rdt[LANES] = {0.0};
    if (rip) lanes_ripples(sc, rip, rslots, st->t, xw, rh, rdt);
    for (int c = 0; c < m; c++) {
        double *wm = warm + WW_WARM_STRIDE * c;
        if (alone[c] != 0.0) {
            ww_water_sample ws;
            converged += ww_water_at_warm(sc, st, x[c], z[c], minL, wm, &ws);
            height[c] = ws.height;
            if (velocity)
                for (int k = 0; k < 3; k++) velocity[3 * c + k] = ws.velocity[k];
            continue;
        }
        height[c] = sc->water_level + y[c] + rh[c];
        if (velocity) {
            velocity[3 * c] = v[0][c];
            velocity[3 * c + 1] = v[1][c] + rdt[c];
            velocity[3 * c + 2] = v[2][c];
        }
        for (int k = 0; k < 2; k++) {
            double off = cur->a[k][c] - (k ? z[c] : x[c]);
            wm[2 + k] = off - wm[k];
            wm[k] = off;
        }
        converged += cur->norm[c] <= WW_QUERY_TOLERANCE;
    }
    return converged;
}

WW_LANES int ww_water_at_warm_n(const ww_scene *sc, const ww_state *st, int n, const double *x,
                       const double *z, double min_wavelength, double *warm, double *height,
                       double *velocity) {
    int converged = 0;
    lane_waves lw;
    lw.n = 0;
    int lanes = (sc->wave_model == WW_WAVES_GERSTNER || sc->wave_model == WW_WAVES_SPECTRUM) &&
                sc->nwaves <= LANE_WAVES;
    for (int i = 0; lanes && i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->wavelength < min_wavelength) continue;
        lw.w[lw.n++] = (lane_wave){.k = w->k, .dir = {w->dir[0], w->dir[1]},
                                   .steepness = w->steepness, .amplitude = w->amplitude,
                                   .omega = w->omega, .index = i};
    }
    for (int j = 0; j < n; j += LANES) {
        int m = n - j < LANES ? n - j : LANES;
        double *vj = velocity ? velocity + 3 * j : NULL;
        if (lanes) {
            converged += lanes_query(sc, st, &lw, min_wavelength, m, x + j, z + j,
                                     warm + WW_WARM_STRIDE * j, height + j, vj);
            continue;
        }
        for (int c = 0; c < m; c++) {
            ww_water_sample ws;
            converged += ww_water_at_warm(sc, st, x[j + c], z[j + c], min_wavelength,
                                          warm + WW_WARM_STRIDE * (j + c), &ws);
            height[j + c] = ws.height;
            if (vj)
                for (int k = 0; k < 3; k++) vj[3 * c + k] = ws.velocity[k];
        }
    }
    return converged;
}
