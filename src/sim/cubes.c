/* cubes.c - floating cubes (seed 000 section 3.2): Archimedes buoyancy of a box against
 * the exact water surface, or seed 000's spring-damper; water drag; tilt; press and release.
 *
 * Archimedes. The box (edge s, density rho_c, mass m = rho_c s^3) is cut into columns x columns
 * prisms along its local axis U nearest the vertical (U.y >= 1/sqrt 3). A prism with base point
 * b (its middle) and cross-section dA = (s / columns)^2 is submerged for w < (h - b.y) / U.y,
 * h the surface over b (ww_water_at): length L = clamp((h - b.y) / U.y + s/2, 0, s), volume
 * dA L, centroid b + (L - s) / 2 U. This is exact for a plane surface cutting every prism
 * (flat water, any tilt that leaves the corners dry or wet as a whole) and converges as
 * columns^2 otherwise. Buoyancy F = rho_w g V_sub up, at the centre of buoyancy: the torque
 * (c_b - c) x F tilts the box toward the local slope, and a box whose metacentric height
 * GM = s^2 / (12 d) - (s - d) / 2 is negative (0.21 < rho_c / rho_w < 0.79 for a cube, d the
 * draft) turns over, as a real one does (Archimedes, "On Floating Bodies"; the metacentre of
 * Bouguer 1746).
 *
 * Heave. Over one step, with the surface and the tilt held, raising the box by xi changes each
 * column's wet length by -xi / U.y, so the buoyancy is an exact piecewise-linear function of xi
 * with an exact potential P(xi) = -rho_w g sum dA U.y (G(w_c) - G(w_c - xi / U.y)), G the
 * integral of clamp(., 0, s). The heave is advanced by the implicit midpoint rule with the
 * discrete gradient of that potential (Gonzalez 1996, "Time integration and discrete
 * Hamiltonian systems"): xi1 = dt (v0 + v1) / 2, v1 = v0 + dt (rho_w g Vbar / m + a - gamma
 * ((v0 + v1) / 2 - u_y)) with Vbar = (1 / xi1) int_0^xi1 V, solved for xi1 by bisection (the
 * residual is monotone since V decreases with xi). Kinetic plus buoyancy energy is conserved
 * to rounding at any dt without drag (and only lost with it), so a thin light box at dt = 1/15
 * (omega dt > 2, where semi-implicit Euler explodes) and a box leaving the water and falling
 * back cannot gain energy; in the linear range it is the trapezoidal rule, whose period error
 * is (omega dt)^2 / 12 (0.1% for a 0.8 m draft at dt = 1/30).
 * The spring mode is linear: it is advanced by the exact solution of its damped oscillator
 * (ww_m_damped_oscillator). Seed 000's explicit update (v += k (y_t - y) dt; v *= e^(-c dt);
 * y += v dt) is first-order and unstable for k dt^2 > 4 (Gaffer on Games, "Spring Physics").
 *
 * Drag (seed 000's future work: "water drag so that pushing the cube ... would encounter
 * resistance"), relative to the water velocity u, scaled by the submerged fraction f:
 * linear dv/dt = -b f (v - u), applied exactly (e^(-b f dt)); quadratic
 * F = -1/2 rho_w Cd s^2 f |v - u| (v - u), applied implicitly (v_rel / (1 + dt q |v_rel|)), which
 * cannot reverse the relative velocity at any dt.
 *
 * Rotation. A uniform cube's inertia is isotropic, I = m s^2 / 6, so w' = tau / I with no
 * gyroscopic term. The restoring torque is stiff for small boxes (its rate is
 * rho_w g I_wp / I): the tilting components are advanced linearly implicitly with the stiffness
 * bound K = rho_w g I_wp (I_wp the waterplane's polar second moment, >= its moment about any
 * horizontal axis): w <- (w + dt tau / I) / (1 + dt b_w f + dt^2 K / I), unconditionally
 * stable and never energy-gaining; the quaternion turns by the exact rotation of w dt.
 *
 * Ripples push a floating body down their slope (seed 000's "gradient nudges"): the pressure
 * gradient of the ripple's surface tilt gives F = -nudge rho_w g V_sub grad h_ripple, analytic
 * gradient from ww_ripples_height (seed 000 used finite differences).
 *
 * Press (seed 000): while held v_y -= a dt and the held time grows; on release
 * v_y += J0 + J1 min(held, Tmax), a ripple, events cube_press and cube_release.
 *
 * Changes from seed 000: Archimedes buoyancy from the submerged volume instead of a spring to a
 * target height (kept as `buoyancy: spring`); energy-conserving and exact integrators instead of
 * explicit Euler;
 * tilt from the centre of buoyancy; analytic ripple gradient; drag; a seabed.
 */
#include "sim/cubes.h"

#include <math.h>

#include "core/error.h"
#include "core/mathx.h"
#include "core/oscillator.h"
#include "sim/events.h"
#include "sim/ripples.h"
#include "sim/water.h"


/* ---- pure helpers -------------------------------------------------------------------------- */

/* unit quaternion q (w x y z) to the rotated local axes: ax[k] = R e_k */
static void quat_axes(const double q[4], double ax[3][3]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    ax[0][0] = 1 - 2 * (y * y + z * z), ax[0][1] = 2 * (x * y + w * z), ax[0][2] = 2 * (x * z - w * y);
    ax[1][0] = 2 * (x * y - w * z), ax[1][1] = 1 - 2 * (x * x + z * z), ax[1][2] = 2 * (y * z + w * x);
    ax[2][0] = 2 * (x * z + w * y), ax[2][1] = 2 * (y * z - w * x), ax[2][2] = 1 - 2 * (x * x + y * y);
}

/* q <- exp(w dt / 2) q: the exact rotation by the world angular velocity w over dt */
static void quat_turn(double q[4], const double w[3], double dt) {
    double ang = ww_m_len3(w) * dt;
    if (!(ang > 0.0)) return;
    double h = 0.5 * ang, s = sin(h) / ww_m_len3(w), e[4] = {cos(h), w[0] * s, w[1] * s, w[2] * s};
    double r[4] = {e[0] * q[0] - e[1] * q[1] - e[2] * q[2] - e[3] * q[3],
                   e[0] * q[1] + e[1] * q[0] + e[2] * q[3] - e[3] * q[2],
                   e[0] * q[2] - e[1] * q[3] + e[2] * q[0] + e[3] * q[1],
                   e[0] * q[3] + e[1] * q[2] - e[2] * q[1] + e[3] * q[0]};
    double n = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    for (int k = 0; k < 4; k++) q[k] = r[k] / n;
}

static void cross3(const double a[3], const double b[3], double out[3]) {
    double o[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    out[0] = o[0], out[1] = o[1], out[2] = o[2];
}

/* index of the local axis nearest the vertical */
static int up_axis(double ax[3][3]) {
    int best = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(ax[k][1]) > fabs(ax[best][1])) best = k;
    return best;
}

/* ---- water on a cube ----------------------------------------------------------------------- */

/* the columns of cube i against the surface; warm: the cube's warm starts (ww_cube_samples of
 * them, sim/water.h), NULL for cold queries */
static void cube_water(const ww_scene *sc, const ww_state *st, int i, double *warm,
                       ww_cube_water *out) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    const double *c = st->cube_pos + 3 * i;
    double ax[3][3];
    quat_axes(st->cube_rot + 4 * i, ax);
    int a = up_axis(ax);
    double sg = ax[a][1] < 0.0 ? -1.0 : 1.0;
    double U[3] = {sg * ax[a][0], sg * ax[a][1], sg * ax[a][2]};
    const double *P = ax[(a + 1) % 3], *Q = ax[(a + 2) % 3];
    double s = d->size, h = 0.5 * s;
    int n = d->columns > 0 ? d->columns : WW_CUBE_DEFAULT_COLUMNS;
    double cell = s / n, dA = cell * cell;

    *out = (ww_cube_water){.centre = {c[0], c[1], c[2]}, .ncolumns = n * n, .up_y = U[1],
                           .cell_area = dA};
    /* each column's volume and centroid offset from the centre, then sums over point-mirrored
     * pairs, so that a symmetric box on flat water feels exactly no torque (rounding would
     * otherwise seed a tilt that an unstable box amplifies) */
    enum { MAXC = WW_CUBE_MAX_COLUMNS * WW_CUBE_MAX_COLUMNS };
    double vol[MAXC], off3[MAXC][3], vel3[MAXC][3];
    for (int iu = 0; iu < n; iu++) {
        for (int iv = 0; iv < n; iv++) {
            int col = iu * n + iv;
            double u = (iu + 0.5 - 0.5 * n) * cell, v = (iv + 0.5 - 0.5 * n) * cell, r[3];
            for (int k = 0; k < 3; k++) r[k] = u * P[k] + v * Q[k];
            ww_water_sample ws;
            if (warm)
                ww_water_at_warm(sc, st, c[0] + r[0], c[2] + r[2], 0.0,
                                 warm + WW_WARM_STRIDE * col, &ws);
            else
                ww_water_at(sc, st, c[0] + r[0], c[2] + r[2], 0.0, &ws);
            double wet = (ws.height - (c[1] + r[1])) / U[1] + h; /* submerged length along U */
            double L = ww_m_clamp(wet, 0.0, s);
            out->wet[col] = wet;
            if (wet > 0.0 && wet < s) {
                double r2 = r[0] * r[0] + r[2] * r[2];
                out->waterplane += dA / U[1];
                out->waterplane_moment += dA / U[1] * r2;
            }
            double off = 0.5 * (L - s);
            vol[col] = dA * L;
            for (int k = 0; k < 3; k++) {
                off3[col][k] = r[k] + off * U[k];
                vel3[col][k] = ws.velocity[k];
            }
        }
    }
    double moment[3] = {0.0, 0.0, 0.0}, vel[3] = {0.0, 0.0, 0.0};
    int nc = n * n;
    for (int a0 = 0; a0 < (nc + 1) / 2; a0++) {
        int a1 = nc - 1 - a0;
        if (a1 == a0) {
            out->volume += vol[a0];
            for (int k = 0; k < 3; k++) {
                moment[k] += vol[a0] * off3[a0][k];
                vel[k] += vol[a0] * vel3[a0][k];
            }
            continue;
        }
        out->volume += vol[a0] + vol[a1];
        for (int k = 0; k < 3; k++) {
            moment[k] += vol[a0] * off3[a0][k] + vol[a1] * off3[a1][k];
            vel[k] += vol[a0] * vel3[a0][k] + vol[a1] * vel3[a1][k];
        }
    }
    if (out->volume > 0.0) {
        for (int k = 0; k < 3; k++) {
            out->centre[k] = c[k] + moment[k] / out->volume;
            out->velocity[k] = vel[k] / out->volume;
        }
    }
}

void ww_cubes_water(const ww_scene *sc, const ww_state *st, int i, ww_cube_water *out) {
    cube_water(sc, st, i, NULL, out);
}

/* cube i's warm starts in the state */
static double *cube_warm(const ww_scene *sc, ww_state *st, int i) {
    return st->cube_warm + WW_WARM_STRIDE * ww_cube_samples_before(sc, i);
}

/* the heave's root is found to this fraction of its bracket's size (rounding) */
#define HEAVE_TOLERANCE 1e-15
#define HEAVE_MAX_ITERATIONS 100

/* int_0^x clamp(x', 0, s) dx' */
static double clamp_integral(double x, double s) {
    if (x <= 0.0) return 0.0;
    if (x < s) return 0.5 * x * x;
    return 0.5 * s * s + s * (x - s);
}

/* the mean submerged volume over [0, xi], (1 / xi) int_0^xi V (the discrete gradient), and its
 * derivative in xi. With V(xi) = dA sum clamp(w_c - xi / U.y, 0, s):
 * int_0^xi V = dA U.y sum (C(w_c) - C(w_c - xi / U.y)), C = clamp_integral, and
 * d Vbar / d xi = (V(xi) - Vbar) / xi. Below a ten-millionth of the box the secant cancels: there
 * Vbar is V at the midpoint (exact on a linear piece) and its slope half of V's there. */
static double volume_mean(const ww_cube_water *w, double s, double xi, double *slope) {
    double lift = xi / w->up_y;
    if (fabs(lift) < 1e-7 * s) {
        double v = 0.0, wet = 0.0;
        for (int c = 0; c < w->ncolumns; c++) {
            double x = w->wet[c] - 0.5 * lift;
            v += ww_m_clamp(x, 0.0, s);
            wet += x > 0.0 && x < s;
        }
        *slope = -0.5 * w->cell_area * wet / w->up_y;
        return w->cell_area * v;
    }
    double acc = 0.0, v = 0.0;
    for (int c = 0; c < w->ncolumns; c++) {
        double x = w->wet[c] - lift;
        acc += clamp_integral(w->wet[c], s) - clamp_integral(x, s);
        v += ww_m_clamp(x, 0.0, s);
    }
    double mean = w->cell_area * w->up_y * acc / xi;
    *slope = (w->cell_area * v - mean) / xi;
    return mean;
}

/* the heave over dt by the discrete-gradient midpoint rule: returns xi1, sets *v.
 * R(xi) = (2 / dt + gamma) xi - 2 v0 - dt (kb Vbar(xi) + a + gamma u) = 0, R increasing;
 * Vbar in [0, s^3] brackets the root. kb = rho_w g / m. Solved by Newton's method kept inside the
 * bracket, bisecting where a step would leave it (Press et al., "Numerical Recipes", rtsafe):
 * R is piecewise smooth (its pieces change where a column's wet length reaches 0 or s), so
 * Newton converges in a few steps where bisection took 50 to reach the bracket's rounding. */
static double heave_step(const ww_cube_water *w, double s, double kb, double a, double gamma,
                         double u, double dt, double *v) {
    double v0 = *v, den = 2.0 / dt + gamma, base = 2.0 * v0 + dt * (a + gamma * u);
    double lo = base / den, hi = (base + dt * kb * s * s * s) / den;
    /* first guess: the root with the buoyancy linear in xi, V = V0 - A_w xi (so Vbar = V0 -
     * A_w xi / 2), which is the answer while no column's wet length reaches 0 or the box */
    double xi = (base + dt * kb * w->volume) / (den + 0.5 * dt * kb * w->waterplane);
    if (!(xi > lo && xi < hi)) xi = 0.5 * (lo + hi);
    for (int it = 0; it < HEAVE_MAX_ITERATIONS; it++) {
        double slope, r = den * xi - base - dt * kb * volume_mean(w, s, xi, &slope);
        if (r == 0.0) break;
        if (r > 0.0)
            hi = xi;
        else
            lo = xi;
        double dr = den - dt * kb * slope, next = xi - r / dr;
        if (!(dr > 0.0) || !(next > lo && next < hi)) next = 0.5 * (lo + hi);
        double tol = HEAVE_TOLERANCE * (fabs(lo) + fabs(hi)) + 1e-300;
        if (fabs(next - xi) <= tol || hi - lo <= tol || next <= lo || next >= hi) {
            xi = next;
            break;
        }
        xi = next;
    }
    *v = 2.0 * xi / dt - v0;
    return xi;
}

/* ---- reset and events ---------------------------------------------------------------------- */

void ww_cubes_reset(const ww_scene *sc, ww_state *st) {
    for (int i = 0; i < WW_N_CUBES(sc); i++) {
        const ww_cube_desc *d = &sc->cubes.cube[i];
        for (int k = 0; k < 3; k++) {
            st->cube_pos[3 * i + k] = d->position[k];
            st->cube_vel[3 * i + k] = 0.0;
            st->cube_omega[3 * i + k] = 0.0;
        }
        const double *q = d->rotation;
        int zero = q[0] == 0.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0;
        for (int k = 0; k < 4; k++) st->cube_rot[4 * i + k] = zero ? (k == 0) : q[k];
        st->cube_press[2 * i] = st->cube_press[2 * i + 1] = 0.0;
        st->cube_submerged[i] = 0.0;
    }
    /* every query starts cold */
    int nw = WW_WARM_STRIDE * ww_cube_samples_before(sc, WW_N_CUBES(sc));
    for (int k = 0; k < nw; k++) st->cube_warm[k] = 0.0;
}

void ww_cubes_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    WW_ASSERT(ev->kind == WW_EV_PRESS && ev->index >= 0 && ev->index < WW_N_CUBES(sc));
    int i = ev->index;
    st->cube_press[2 * i] = ev->v[0];
    st->cube_press[2 * i + 1] = 0.0;
    ww_emit(sc, st, WW_SE_CUBE_PRESS, i, st->cube_pos + 3 * i, ev->v[0], 0.0);
}

/* ---- one step ------------------------------------------------------------------------------ */

/* the forces of one model on cube i over the step: vertical acceleration at the start pose,
 * heave stiffness w2 (1/s^2) and damping gamma (1/s), the water velocity, horizontal
 * acceleration, angular acceleration, tilt stiffness (1/s^2) and angular damping (1/s) */
typedef struct cube_forces {
    double ay, w2, gamma, f;
    double u[3];
    double ah[2];
    double alpha[3], tilt_k, spin_damp;
    double drag_q; /* quadratic drag: 1/2 rho_w Cd s^2 f / m, 1/m */
    int archimedes;
    ww_cube_water water; /* archimedes: the columns, for the heave */
} cube_forces;

static void forces_archimedes(const ww_scene *sc, ww_state *st, int i, cube_forces *F) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    const double *c = st->cube_pos + 3 * i;
    double s = d->size, vol = s * s * s, m = d->density * vol, inertia = m * s * s / 6.0;
    const ww_cube_water *w = &F->water;
    cube_water(sc, st, i, cube_warm(sc, st, i), &F->water);
    F->archimedes = 1;
    double fb = WW_WATER_RHO * WW_G * w->volume;
    F->f = w->volume / vol;
    F->ay = fb / m - WW_G;
    F->w2 = WW_WATER_RHO * WW_G * w->waterplane / m;
    F->gamma = d->drag_linear * F->f;
    for (int k = 0; k < 3; k++) F->u[k] = w->velocity[k];

    /* torque of the buoyancy at the centre of buoyancy: (c_b - c) x (0, fb, 0) */
    double r[3] = {w->centre[0] - c[0], w->centre[1] - c[1], w->centre[2] - c[2]};
    F->alpha[0] = -r[2] * fb / inertia;
    F->alpha[1] = 0.0;
    F->alpha[2] = r[0] * fb / inertia;
    F->tilt_k = WW_WATER_RHO * WW_G * w->waterplane_moment / inertia;
    F->spin_damp = d->drag_angular * F->f;
    F->drag_q = 0.5 * WW_WATER_RHO * d->drag_quadratic * s * s * F->f / m;

    /* the ripples' slope force */
    double grad[2] = {0.0, 0.0};
    if (sc->ripples_on && w->volume > 0.0)
        ww_ripples_height(sc, st->ripple, st->t, c[0], c[2], grad, NULL);
    double push = d->nudge * WW_WATER_RHO * WW_G * w->volume / m;
    F->ah[0] = -push * grad[0];
    F->ah[1] = -push * grad[1];
}

static void forces_spring(const ww_scene *sc, ww_state *st, int i, cube_forces *F) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    const double *c = st->cube_pos + 3 * i;
    ww_water_sample ws;
    ww_water_at_warm(sc, st, c[0], c[2], 0.0, cube_warm(sc, st, i), &ws);
    double target = ws.height + d->spring_offset;
    F->f = ww_m_clamp((ws.height - (c[1] - 0.5 * d->size)) / d->size, 0.0, 1.0);
    F->ay = d->spring_stiffness * (target - c[1]);
    F->w2 = d->spring_stiffness;
    F->gamma = d->spring_damping;
    /* seed 000 damps v itself, not v relative to the water */
    F->u[0] = F->u[1] = F->u[2] = 0.0;

    /* the up axis springs toward the surface normal: alpha = k (U x n) */
    double ax[3][3], U[3];
    quat_axes(st->cube_rot + 4 * i, ax);
    int a = up_axis(ax);
    double sg = ax[a][1] < 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) U[k] = sg * ax[a][k];
    cross3(U, ws.normal, F->alpha);
    for (int k = 0; k < 3; k++) F->alpha[k] *= d->spring_stiffness;
    F->tilt_k = d->spring_stiffness;
    F->spin_damp = d->spring_damping;
    F->drag_q = 0.0;

    double grad[2] = {0.0, 0.0};
    if (sc->ripples_on) ww_ripples_height(sc, st->ripple, st->t, c[0], c[2], grad, NULL);
    F->ah[0] = -d->nudge * WW_G * grad[0];
    F->ah[1] = -d->nudge * WW_G * grad[1];
}

/* lowest centre height on the seabed: half the box's vertical extent above the bottom */
static double seabed_floor(const ww_scene *sc, const double q[4], double size) {
    double ax[3][3];
    quat_axes(q, ax);
    double ext = 0.5 * size * (fabs(ax[0][1]) + fabs(ax[1][1]) + fabs(ax[2][1]));
    return sc->water_level - sc->water_depth + ext;
}

static void step_cube(const ww_scene *sc, ww_state *st, int i) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    double dt = sc->dt, *p = st->cube_pos + 3 * i, *v = st->cube_vel + 3 * i;
    double *w = st->cube_omega + 3 * i, *q = st->cube_rot + 4 * i, *press = st->cube_press + 2 * i;
    cube_forces F = {0};
    if (d->buoyancy == WW_CUBE_SPRING)
        forces_spring(sc, st, i, &F);
    else
        forces_archimedes(sc, st, i, &F);
    st->cube_submerged[i] = F.f;

    /* press: a downward acceleration while held */
    int pressed = press[0] > 0.0, release = 0;
    if (pressed) {
        F.ay -= d->press_accel;
        press[1] += dt;
        press[0] -= dt;
        release = press[0] <= 0.5 * dt;
    }

    /* heave: the discrete-gradient midpoint rule (archimedes), the exact oscillator (spring) */
    double y = 0.0, vy = v[1];
    if (sc->integrator == WW_INTEGRATE_EULER) { /* the seeds' baseline (time.integrator) */
        vy += dt * (F.ay - F.gamma * (vy - F.u[1]));
        y = vy * dt;
    } else if (F.archimedes) {
        double m = d->density * d->size * d->size * d->size;
        double a = F.ay - WW_WATER_RHO * WW_G * F.water.volume / m; /* all but buoyancy */
        y = heave_step(&F.water, d->size, WW_WATER_RHO * WW_G / m, a, F.gamma, F.u[1], dt, &vy);
    } else {
        ww_m_damped_oscillator(F.w2, F.gamma, F.ay + F.gamma * F.u[1], dt, &y, &vy);
    }
    v[1] = vy;

    /* horizontal: slope force, then linear drag toward the water exactly */
    double e = exp(-F.gamma * dt);
    for (int k = 0; k < 3; k += 2) {
        v[k] += F.ah[k / 2] * dt;
        v[k] = F.u[k] + (v[k] - F.u[k]) * e;
    }

    /* quadratic drag, implicitly: the relative velocity shrinks, never reverses */
    if (F.drag_q > 0.0) {
        double rel[3] = {v[0] - F.u[0], v[1] - F.u[1], v[2] - F.u[2]};
        double shrink = 1.0 / (1.0 + dt * F.drag_q * ww_m_len3(rel));
        for (int k = 0; k < 3; k++) v[k] = F.u[k] + rel[k] * shrink;
    }
    p[0] += v[0] * dt;
    p[1] += y;
    p[2] += v[2] * dt;

    /* rotation: tilt linearly implicit with its stiffness bound, spin damped */
    double tilt = 1.0 + dt * F.spin_damp + dt * dt * F.tilt_k;
    w[0] = (w[0] + dt * F.alpha[0]) / tilt;
    w[1] = (w[1] + dt * F.alpha[1]) / (1.0 + dt * F.spin_damp);
    w[2] = (w[2] + dt * F.alpha[2]) / tilt;
    quat_turn(q, w, dt);

    /* the seabed stops a sinking box */
    double floor_y = seabed_floor(sc, q, d->size);
    if (p[1] < floor_y) {
        p[1] = floor_y;
        if (v[1] < 0.0) v[1] = 0.0;
    }

    /* release: the upward kick J0 + J1 min(held, Tmax), a splash ripple */
    if (release) {
        double kick = d->press_j0 + d->press_j1 * fmin(press[1], d->press_max_hold);
        double m = d->density * d->size * d->size * d->size;
        v[1] += kick;
        press[0] = press[1] = 0.0;
        ww_ripples_add(sc, st, p[0], p[2], sc->ripples.amplitude);
        ww_emit(sc, st, WW_SE_CUBE_RELEASE, i, p, m * kick, 0.0);
    }
}

void ww_cubes_step(const ww_scene *sc, ww_state *st) {
    /* step 0 is the described start: nothing has moved yet */
    if (st->step == 0) {
        for (int i = 0; i < WW_N_CUBES(sc); i++) {
            cube_forces F = {0};
            if (sc->cubes.cube[i].buoyancy == WW_CUBE_SPRING)
                forces_spring(sc, st, i, &F);
            else
                forces_archimedes(sc, st, i, &F);
            st->cube_submerged[i] = F.f;
        }
        return;
    }
    for (int i = 0; i < WW_N_CUBES(sc); i++) step_cube(sc, st, i);
}
