/* floaters.c - floating models (model in floaters.h): the cubes' Archimedes buoyancy
 * (sim/cubes.c has the derivations and sources; sim/boxwater.c the columns and the heave both
 * use) for a box with edges e = (e0, e1, e2) along the model's axes instead of a cube.
 *
 * What changes from a cube of edge s:
 *   columns   the box is cut into n x n prisms along its axis U nearest the vertical; a prism's
 *             cross-section is (e_P / n)(e_Q / n) and its length e_U (P, Q the other two axes).
 *   mass      m = rho V, V = e0 e1 e2.
 *   inertia   principal I_k = m (e_k+1^2 + e_k+2^2) / 12 about the body axes (a cube's m s^2 / 6);
 *             the buoyancy's torque turns the body by w' = R I^-1 R^T tau. The gyroscopic term
 *             w x I w is left out, as the angular drag damps any spin long before it matters.
 *   tilt      linearly implicit with the stiffness bound rho g I_wp / I_min (the smallest
 *             principal inertia: the stiffest axis), unconditionally stable.
 *   drag      quadratic on the area V^(2/3) (a cube's s^2).
 *   seabed    the centre stays half the box's vertical extent above the bottom.
 * For e0 = e1 = e2 every formula is the cube's; tests/test_floaters.c runs the cubes' draft and
 * heave oracles on a floating `mesh: box` and on a cube of the same size and density.
 *
 * The surface is the exact one (ww_water_at: waves, then ripples), the same query as the cubes'
 * and the boat's: a model sits at the height of the water under it and tilts with its slope
 * (seed 001 set the height and the normal directly; here they come out of the buoyancy).
 */
#include "sim/floaters.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "core/mathx.h"
#include "sim/boxwater.h"
#include "sim/cubes.h"
#include "sim/ripples.h"
#include "sim/water.h"

/* ---- the body ------------------------------------------------------------------------------ */

static double body_volume(const ww_floater_desc *d) {
    return d->extent[0] * d->extent[1] * d->extent[2];
}

/* ---- water on a box ------------------------------------------------------------------------ */

/* the surface at every floater's nodes (sim/boxwater.h) at the step's start, asked in one query
 * so that the lanes of the query (sim/water.h) fill across floaters: heights, and velocities 3 a
 * node, in the order of the warm starts */
enum { MAX_NODES = WW_MAX_FLOATERS * WW_BOX_MAX_NODES };
typedef struct floater_nodes {
    double height[MAX_NODES], velocity[3 * MAX_NODES];
} floater_nodes;

static void floaters_surface(const ww_scene *sc, ww_state *st, floater_nodes *out) {
    double x[MAX_NODES], z[MAX_NODES];
    int n = WW_N_FLOATERS(sc), k = ww_floater_samples_before(sc, n);
    for (int j = 0; j < n; j++) {
        const ww_floater_desc *d = &sc->floaters.floater[j];
        int at = ww_floater_samples_before(sc, j);
        ww_box_node_points(st->floater_pos + 3 * j, st->floater_rot + 4 * j, d->extent, d->columns,
                           x + at, z + at);
    }
    if (k > 0)
        ww_water_at_warm_n(sc, st, k, x, z, 0.0, st->floater_warm, out->height,
                           out->velocity);
}

/* floater j's columns against the surface (sim/boxwater.h) from its nodes' samples */
static void box_water_at(const ww_scene *sc, ww_state *st, int j, const floater_nodes *N,
                         ww_box_water *out) {
    const ww_floater_desc *d = &sc->floaters.floater[j];
    int at = ww_floater_samples_before(sc, j);
    ww_box_water_from(st->floater_pos + 3 * j, st->floater_rot + 4 * j, d->extent, d->columns,
                      N->height + at, N->velocity + 3 * at, out);
}

/* ---- reset, pose --------------------------------------------------------------------------- */

void ww_floaters_reset(const ww_scene *sc, ww_state *st) {
    for (int j = 0; j < WW_N_FLOATERS(sc); j++) {
        const ww_floater_desc *d = &sc->floaters.floater[j];
        for (int k = 0; k < 3; k++) {
            st->floater_pos[3 * j + k] = d->position[k];
            st->floater_vel[3 * j + k] = 0.0;
            st->floater_omega[3 * j + k] = 0.0;
        }
        for (int k = 0; k < 4; k++) st->floater_rot[4 * j + k] = d->rotation[k];
        st->floater_submerged[j] = 0.0;
    }
    /* every query starts cold */
    int nw = WW_WARM_STRIDE * ww_floater_samples_before(sc, WW_N_FLOATERS(sc));
    for (int k = 0; k < nw; k++) st->floater_warm[k] = 0.0;
}

void ww_floater_pose(const ww_scene *sc, const ww_state *st, int j, double m[16]) {
    const ww_floater_desc *d = &sc->floaters.floater[j];
    double ax[3][3];
    ww_box_axes(st->floater_rot + 4 * j, ax);
    for (int col = 0; col < 3; col++) {
        for (int row = 0; row < 3; row++) m[4 * col + row] = ax[col][row];
        m[4 * col + 3] = 0.0;
    }
    for (int row = 0; row < 3; row++)
        m[12 + row] = st->floater_pos[3 * j + row] - ax[0][row] * d->offset[0] -
                      ax[1][row] * d->offset[1] - ax[2][row] * d->offset[2];
    m[15] = 1.0;
}

int ww_floater_box(const ww_scene *sc, const ww_state *st, int k, double c[3], double half[3],
                   double q[4]) {
    if (!sc->floaters.on) return 0;
    int root = k;
    for (int guard = 0; sc->models.model[root].parent >= 0 && guard < WW_MAX_MODELS; guard++)
        root = sc->models.model[root].parent;
    int j = ww_floater_of_model(sc, root);
    if (j < 0) return 0;
    if (root != k) return -1;
    const ww_floater_desc *d = &sc->floaters.floater[j];
    for (int a = 0; a < 3; a++) {
        c[a] = st->floater_pos[3 * j + a];
        half[a] = 0.5 * d->extent[a];
    }
    for (int a = 0; a < 4; a++) q[a] = st->floater_rot[4 * j + a];
    return 1;
}

/* ---- one step ------------------------------------------------------------------------------ */

/* the water's pull on floater j at its start pose (sim/cubes.c's cube_forces, archimedes) */
typedef struct box_forces {
    double ay, f;
    ww_box_motion m; /* quadratic drag on the area V^(2/3) */
    ww_box_water water;
} box_forces;

static void forces(const ww_scene *sc, ww_state *st, int j, const floater_nodes *N,
                   box_forces *F) {
    const ww_floater_desc *d = &sc->floaters.floater[j];
    const double *c = st->floater_pos + 3 * j, *e = d->extent;
    double vol = body_volume(d), m = d->density * vol;
    const ww_box_water *w = &F->water;
    box_water_at(sc, st, j, N, &F->water);
    double fb = WW_WATER_RHO * WW_G * w->volume;
    F->f = w->volume / vol;
    F->ay = fb / m - WW_G;
    F->m.gamma = d->drag_linear * F->f;
    for (int k = 0; k < 3; k++) F->m.u[k] = w->velocity[k];

    /* torque of the buoyancy at the centre of buoyancy, through the inverse inertia in the
     * body's axes: alpha = R I^-1 R^T tau */
    double r[3] = {w->centre[0] - c[0], w->centre[1] - c[1], w->centre[2] - c[2]};
    double tau[3] = {-r[2] * fb, 0.0, r[0] * fb}, ax[3][3], inertia[3];
    for (int k = 0; k < 3; k++) {
        double a = e[(k + 1) % 3], b = e[(k + 2) % 3];
        inertia[k] = m * (a * a + b * b) / 12.0;
    }
    ww_box_axes(st->floater_rot + 4 * j, ax);
    for (int i = 0; i < 3; i++) F->m.alpha[i] = 0.0;
    for (int k = 0; k < 3; k++) {
        double t = (ax[k][0] * tau[0] + ax[k][1] * tau[1] + ax[k][2] * tau[2]) / inertia[k];
        for (int i = 0; i < 3; i++) F->m.alpha[i] += ax[k][i] * t;
    }
    double imin = fmin(inertia[0], fmin(inertia[1], inertia[2]));
    F->m.tilt_k = WW_WATER_RHO * WW_G * w->waterplane_moment / imin;
    F->m.spin_damp = d->drag_angular * F->f;
    F->m.drag_q = 0.5 * WW_WATER_RHO * d->drag_quadratic * cbrt(vol * vol) * F->f / m;

    double grad[2] = {0.0, 0.0};
    if (sc->ripples_on && w->volume > 0.0)
        ww_ripples_height_n(sc, st->ripple, st->ripple_slots[0], st->t, c[0], c[2], grad, NULL);
    double push = d->nudge * WW_WATER_RHO * WW_G * w->volume / m;
    F->m.ah[0] = -push * grad[0];
    F->m.ah[1] = -push * grad[1];
}

/* lowest centre height on the seabed: half the box's vertical extent above the bottom */
static double seabed_floor(const ww_scene *sc, const ww_floater_desc *d, const double q[4]) {
    double ax[3][3];
    ww_box_axes(q, ax);
    double ext = 0.5 * (d->extent[0] * fabs(ax[0][1]) + d->extent[1] * fabs(ax[1][1]) +
                        d->extent[2] * fabs(ax[2][1]));
    return sc->water_level - sc->water_depth + ext;
}

static void step_floater(const ww_scene *sc, ww_state *st, int j, const floater_nodes *N) {
    const ww_floater_desc *d = &sc->floaters.floater[j];
    double dt = sc->dt, *p = st->floater_pos + 3 * j, *v = st->floater_vel + 3 * j;
    double *w = st->floater_omega + 3 * j, *q = st->floater_rot + 4 * j;
    /* zero but the water (the last member), which forces sets whole (ww_box_water_from) */
    box_forces F;
    memset(&F, 0, offsetof(box_forces, water));
    forces(sc, st, j, N, &F);
    st->floater_submerged[j] = F.f;

    /* heave: the discrete-gradient midpoint rule, or the seeds' Euler (time.integrator) */
    double y = 0.0, vy = v[1], vol = body_volume(d), m = d->density * vol;
    if (sc->integrator == WW_INTEGRATE_EULER) {
        vy += dt * (F.ay - F.m.gamma * (vy - F.m.u[1]));
        y = vy * dt;
    } else {
        double a = F.ay - WW_WATER_RHO * WW_G * F.water.volume / m; /* all but buoyancy */
        y = ww_box_heave_step(&F.water, d->extent, WW_WATER_RHO * WW_G / m, a, F.m.gamma, F.m.u[1], dt,
                               &vy);
    }
    v[1] = vy;

    ww_box_move(&F.m, y, dt, p, v, w, q);

    double floor_y = seabed_floor(sc, d, q);
    if (p[1] < floor_y) {
        p[1] = floor_y;
        if (v[1] < 0.0) v[1] = 0.0;
    }
}

void ww_floaters_step(const ww_scene *sc, ww_state *st) {
    floater_nodes N;
    floaters_surface(sc, st, &N);
    /* step 0 is the described start: nothing has moved yet */
    for (int j = 0; j < WW_N_FLOATERS(sc); j++) {
        if (st->step == 0) {
            box_forces F = {0};
            forces(sc, st, j, &N, &F);
            st->floater_submerged[j] = F.f;
        } else {
            step_floater(sc, st, j, &N);
        }
    }
}
