/* cubes.c - floating cubes (seed 000 section 3.2): Archimedes buoyancy of a box against
 * the exact water surface, or seed 000's spring-damper; water drag; tilt; press and release.
 *
 * Archimedes. The box (edge s, density rho_c, mass m = rho_c s^3) is cut into columns x columns
 * prisms along its local axis U nearest the vertical (U.y >= 1/sqrt 3). A prism with base point
 * b (its middle) and cross-section dA = (s / columns)^2 is submerged for w < (h - b.y) / U.y,
 * h the surface over b: length L = clamp((h - b.y) / U.y + s/2, 0, s), volume dA L, centroid
 * b + (L - s) / 2 U. h is the exact surface (ww_water_at) at the Gauss-Legendre nodes of the
 * cross-section, 2 x 2 up to 4 x 4 columns and 3 x 3 above, interpolated to the prisms by the
 * polynomial through them (sim/boxwater.h). This is exact for a plane surface cutting every
 * prism (flat water, any tilt that leaves the corners dry or wet as a whole) and converges as
 * columns^2 otherwise, up to the interpolation's error. Buoyancy F = rho_w g V_sub up, at the
 * centre of buoyancy: the torque (c_b - c) x F tilts the box toward the local slope, and a box
 * whose metacentric height GM = s^2 / (12 d) - (s - d) / 2 is negative (0.21 < rho_c / rho_w <
 * 0.79 for a cube, d the draft) turns over, as a real one does (Archimedes, "On Floating
 * Bodies"; the metacentre of Bouguer 1746).
 *
 * Heave. Over one step, with the surface and the tilt held, raising the box by xi changes each
 * column's wet length by -xi / U.y, so the buoyancy is an exact piecewise-linear function of xi
 * with an exact potential P(xi) = -rho_w g sum dA U.y (G(w_c) - G(w_c - xi / U.y)), G the
 * integral of clamp(., 0, s). The heave is advanced by the implicit midpoint rule with the
 * discrete gradient of that potential (Gonzalez 1996, "Time integration and discrete
 * Hamiltonian systems"): xi1 = dt (v0 + v1) / 2, v1 = v0 + dt (rho_w g Vbar / m + a - gamma
 * ((v0 + v1) / 2 - u_y)) with Vbar = (1 / xi1) int_0^xi1 V, solved for xi1 by Newton's method
 * kept inside its bracket (the residual is monotone since V decreases with xi). Kinetic plus
 * buoyancy energy is conserved to rounding at any dt without drag (and only lost with it), so a
 * thin light box at dt = 1/15 (omega dt > 2, where semi-implicit Euler explodes) and a box
 * leaving the water and falling back cannot gain energy; in the linear range it is the
 * trapezoidal rule, whose period error is (omega dt)^2 / 12 (0.1% for a 0.8 m draft at
 * dt = 1/30).
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
#include <stddef.h>
#include <string.h>

#include "core/error.h"
#include "core/mathx.h"
#include "core/oscillator.h"
#include "sim/boxwater.h"
#include "sim/events.h"
#include "sim/ripples.h"
#include "sim/water.h"


/* ---- pure helpers -------------------------------------------------------------------------- */

static void cross3(const double a[3], const double b[3], double out[3]) {
    double o[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    out[0] = o[0], out[1] = o[1], out[2] = o[2];
}

/* ---- water on a cube ----------------------------------------------------------------------- */

/* cube i's columns a side */
static int cube_columns(const ww_cube_desc *d) {
    return d->columns > 0 ? d->columns : WW_CUBE_DEFAULT_COLUMNS;
}

/* the columns of cube i against the surface, cold queries (the step's are warm, below) */
void ww_cubes_water(const ww_scene *sc, const ww_state *st, int i, ww_cube_water *out) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    double e[3] = {d->size, d->size, d->size};
    ww_box_water_at(sc, st, st->cube_pos + 3 * i, st->cube_rot + 4 * i, e, cube_columns(d), NULL,
                    out);
}

/* cube i's warm starts in the state */
static double *cube_warm(const ww_scene *sc, ww_state *st, int i) {
    return st->cube_warm + WW_WARM_STRIDE * ww_cube_warm_index(sc, i);
}

/* the surface at every archimedes cube's nodes at the step's start, asked in one query so that
 * the lanes of the query (sim/water.h) fill across cubes: heights, and velocities 3 a node, in
 * the order of the warm starts */
enum { MAX_NODES = WW_MAX_CUBES * WW_BOX_MAX_NODES };
typedef struct cube_nodes {
    double height[MAX_NODES], velocity[3 * MAX_NODES];
} cube_nodes;

static void cubes_surface(const ww_scene *sc, ww_state *st, cube_nodes *out) {
    double x[MAX_NODES], z[MAX_NODES];
    int k = 0;
    for (int i = 0; i < WW_N_CUBES(sc); i++) {
        const ww_cube_desc *d = &sc->cubes.cube[i];
        if (d->buoyancy == WW_CUBE_SPRING) continue;
        double e[3] = {d->size, d->size, d->size};
        ww_box_node_points(st->cube_pos + 3 * i, st->cube_rot + 4 * i, e, cube_columns(d), x + k,
                           z + k);
        k += ww_cube_samples(sc, i);
    }
    if (k > 0)
        ww_water_at_warm_n(sc, st, k, x, z, 0.0, st->cube_warm, out->height, out->velocity);
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
    int nw = WW_WARM_STRIDE * ww_cube_samples_all(sc);
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
    double ay, w2, f;
    ww_box_motion m; /* quadratic drag on the area s^2 */
    int archimedes;
    ww_cube_water water; /* archimedes: the columns, for the heave */
} cube_forces;

static void forces_archimedes(const ww_scene *sc, ww_state *st, int i, const cube_nodes *N,
                              cube_forces *F) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    const double *c = st->cube_pos + 3 * i;
    double s = d->size, vol = s * s * s, m = d->density * vol, inertia = m * s * s / 6.0;
    const ww_cube_water *w = &F->water;
    double e[3] = {s, s, s};
    int k = ww_cube_warm_index(sc, i);
    ww_box_water_from(c, st->cube_rot + 4 * i, e, cube_columns(d), N->height + k,
                      N->velocity + 3 * k, &F->water);
    F->archimedes = 1;
    double fb = WW_WATER_RHO * WW_G * w->volume;
    F->f = w->volume / vol;
    F->ay = fb / m - WW_G;
    F->w2 = WW_WATER_RHO * WW_G * w->waterplane / m;
    F->m.gamma = d->drag_linear * F->f;
    for (int k = 0; k < 3; k++) F->m.u[k] = w->velocity[k];

    /* torque of the buoyancy at the centre of buoyancy: (c_b - c) x (0, fb, 0) */
    double r[3] = {w->centre[0] - c[0], w->centre[1] - c[1], w->centre[2] - c[2]};
    F->m.alpha[0] = -r[2] * fb / inertia;
    F->m.alpha[1] = 0.0;
    F->m.alpha[2] = r[0] * fb / inertia;
    F->m.tilt_k = WW_WATER_RHO * WW_G * w->waterplane_moment / inertia;
    F->m.spin_damp = d->drag_angular * F->f;
    F->m.drag_q = 0.5 * WW_WATER_RHO * d->drag_quadratic * s * s * F->f / m;

    /* the ripples' slope force */
    double grad[2] = {0.0, 0.0};
    if (sc->ripples_on && w->volume > 0.0)
        ww_ripples_height_n(sc, st->ripple, st->ripple_slots[0], st->t, c[0], c[2], grad, NULL);
    double push = d->nudge * WW_WATER_RHO * WW_G * w->volume / m;
    F->m.ah[0] = -push * grad[0];
    F->m.ah[1] = -push * grad[1];
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
    F->m.gamma = d->spring_damping;
    /* seed 000 damps v itself, not v relative to the water */
    F->m.u[0] = F->m.u[1] = F->m.u[2] = 0.0;

    /* the up axis springs toward the surface normal: alpha = k (U x n) */
    double ax[3][3], U[3];
    ww_box_axes(st->cube_rot + 4 * i, ax);
    int a = ww_box_up_axis(ax);
    double sg = ax[a][1] < 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) U[k] = sg * ax[a][k];
    cross3(U, ws.normal, F->m.alpha);
    for (int k = 0; k < 3; k++) F->m.alpha[k] *= d->spring_stiffness;
    F->m.tilt_k = d->spring_stiffness;
    F->m.spin_damp = d->spring_damping;
    F->m.drag_q = 0.0;

    double grad[2] = {0.0, 0.0};
    if (sc->ripples_on)
        ww_ripples_height_n(sc, st->ripple, st->ripple_slots[0], st->t, c[0], c[2], grad, NULL);
    F->m.ah[0] = -d->nudge * WW_G * grad[0];
    F->m.ah[1] = -d->nudge * WW_G * grad[1];
}

/* lowest centre height on the seabed: half the box's vertical extent above the bottom */
static double seabed_floor(const ww_scene *sc, const double q[4], double size) {
    double ax[3][3];
    ww_box_axes(q, ax);
    double ext = 0.5 * size * (fabs(ax[0][1]) + fabs(ax[1][1]) + fabs(ax[2][1]));
    return sc->water_level - sc->water_depth + ext;
}

static void step_cube(const ww_scene *sc, ww_state *st, int i, const cube_nodes *N) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    double dt = sc->dt, *p = st->cube_pos + 3 * i, *v = st->cube_vel + 3 * i;
    double *w = st->cube_omega + 3 * i, *q = st->cube_rot + 4 * i, *press = st->cube_press + 2 * i;
    /* zero but the columns' water (the last member): forces_archimedes sets it whole
     * (ww_box_water_from), and only the archimedes heave reads it */
    cube_forces F;
    memset(&F, 0, offsetof(cube_forces, water));
    if (d->buoyancy == WW_CUBE_SPRING)
        forces_spring(sc, st, i, &F);
    else
        forces_archimedes(sc, st, i, N, &F);
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
        vy += dt * (F.ay - F.m.gamma * (vy - F.m.u[1]));
        y = vy * dt;
    } else if (F.archimedes) {
        double m = d->density * d->size * d->size * d->size;
        double a = F.ay - WW_WATER_RHO * WW_G * F.water.volume / m; /* all but buoyancy */
        double e[3] = {d->size, d->size, d->size};
        y = ww_box_heave_step(&F.water, e, WW_WATER_RHO * WW_G / m, a, F.m.gamma, F.m.u[1], dt, &vy);
    } else {
        ww_m_damped_oscillator(F.w2, F.m.gamma, F.ay + F.m.gamma * F.m.u[1], dt, &y, &vy);
    }
    v[1] = vy;

    ww_box_move(&F.m, y, dt, p, v, w, q);

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
    cube_nodes N;
    cubes_surface(sc, st, &N);
    /* step 0 is the described start: nothing has moved yet */
    if (st->step == 0) {
        for (int i = 0; i < WW_N_CUBES(sc); i++) {
            cube_forces F = {0};
            if (sc->cubes.cube[i].buoyancy == WW_CUBE_SPRING)
                forces_spring(sc, st, i, &F);
            else
                forces_archimedes(sc, st, i, &N, &F);
            st->cube_submerged[i] = F.f;
        }
        return;
    }
    for (int i = 0; i < WW_N_CUBES(sc); i++) step_cube(sc, st, i, &N);
}
