/* boxwater.c - a rigid box against the exact water surface (model in boxwater.h) */
#include "sim/boxwater.h"

#include <math.h>

#include "core/exp.h"
#include "core/lanes.h"
#include "core/mathx.h"
#include "core/sincos.h"
#include "sim/water.h"

/* unit quaternion q (w x y z) to the rotated local axes: ax[k] = R e_k */
void ww_box_axes(const double q[4], double ax[3][3]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    ax[0][0] = 1 - 2 * (y * y + z * z), ax[0][1] = 2 * (x * y + w * z), ax[0][2] = 2 * (x * z - w * y);
    ax[1][0] = 2 * (x * y - w * z), ax[1][1] = 1 - 2 * (x * x + z * z), ax[1][2] = 2 * (y * z + w * x);
    ax[2][0] = 2 * (x * z + w * y), ax[2][1] = 2 * (y * z - w * x), ax[2][2] = 1 - 2 * (x * x + y * y);
}

/* q <- exp(w dt / 2) q: the exact rotation by the world angular velocity w over dt */
void ww_box_turn(double q[4], const double w[3], double dt) {
    double ang = ww_m_len3(w) * dt;
    if (!(ang > 0.0)) return;
    double h = 0.5 * ang, sh, ch;
    ww_sincos(h, &sh, &ch);
    double s = sh / ww_m_len3(w), e[4] = {ch, w[0] * s, w[1] * s, w[2] * s};
    double r[4] = {e[0] * q[0] - e[1] * q[1] - e[2] * q[2] - e[3] * q[3],
                   e[0] * q[1] + e[1] * q[0] + e[2] * q[3] - e[3] * q[2],
                   e[0] * q[2] - e[1] * q[3] + e[2] * q[0] + e[3] * q[1],
                   e[0] * q[3] + e[1] * q[2] - e[2] * q[1] + e[3] * q[0]};
    double n = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    for (int k = 0; k < 4; k++) q[k] = r[k] / n;
}

/* index of the local axis nearest the vertical */
int ww_box_up_axis(double ax[3][3]) {
    int best = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(ax[k][1]) > fabs(ax[best][1])) best = k;
    return best;
}

/* ---- the columns ---------------------------------------------------------------------------- */

/* the box's column frame: U, the local axis nearest the vertical turned upward, and P, Q the
 * cross-section's axes; returns U's index */
static int box_frame(const double q[4], double ax[3][3], double U[3], int *ap, int *aq) {
    ww_box_axes(q, ax);
    int a = ww_box_up_axis(ax);
    double sg = ax[a][1] < 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) U[k] = sg * ax[a][k];
    *ap = (a + 1) % 3;
    *aq = (a + 2) % 3;
    return a;
}

/* the nodes along one side in units of the side, centred: the columns' centres where there
 * are as many (m = n <= 2), else Gauss-Legendre's, +-g (m = 2: g = 1 / (2 sqrt 3)) or 0, +-g
 * (m = 3: g = sqrt(3/5) / 2); t = x / g is the node coordinate, -1, (0,) 1 at the nodes */
static double node_step(int m) {
    return m == 2 ? 0.5 / sqrt(3.0) : 0.5 * sqrt(0.6);
}
static double node_at(int m, int n, int i) {
    if (m == n) return (i + 0.5) / n - 0.5;
    return (2.0 * i / (m - 1) - 1.0) * node_step(m);
}

void ww_box_node_points(const double c[3], const double q[4], const double extent[3], int n,
                        double *x, double *z) {
    double ax[3][3], U[3];
    int ap, aq, m = ww_box_nodes_per_side(n);
    box_frame(q, ax, U, &ap, &aq);
    const double *P = ax[ap], *Q = ax[aq];
    for (int i = 0; i < m; i++) {
        double u = node_at(m, n, i) * extent[ap];
        for (int j = 0; j < m; j++) {
            double v = node_at(m, n, j) * extent[aq];
            x[i * m + j] = c[0] + u * P[0] + v * Q[0];
            z[i * m + j] = c[2] + u * P[2] + v * Q[2];
        }
    }
}

/* a helper inlined where it is called with constant counts (nodes or columns a side), so that
 * its loops over them unroll or vectorise */
#define FIXED_COUNTS static inline __attribute__((always_inline))

/* the polynomial through m values at the nodes t = -1, (0,) 1, as coefficients of 1, t (, t^2),
 * written with the values' half-sums and half-differences: where the values are equal (flat
 * water) every coefficient but the first is 0 exactly and the first is the value */
FIXED_COUNTS void node_poly(int m, const double *f, int stride, double *k) {
    double lo = f[0], hi = f[(m - 1) * stride];
    double mean = 0.5 * (lo + hi), half_diff = 0.5 * (hi - lo);
    if (m == 2) {
        k[0] = mean, k[1] = half_diff;
    } else {
        double mid = f[stride];
        k[0] = mid, k[1] = half_diff, k[2] = mean - mid;
    }
}

/* the polynomial through the m x m node values (stride apart) as coefficients K[i m + j] of
 * tu^i tv^j: node_poly along Q, then along P */
FIXED_COUNTS void node_coefficients(int m, const double *f, int stride, double *K) {
    double row[3][3];
    for (int i = 0; i < m; i++) node_poly(m, f + i * m * stride, stride, row[i]);
    for (int j = 0; j < m; j++) {
        double col[3], k[3];
        for (int i = 0; i < m; i++) col[i] = row[i][j];
        node_poly(m, col, 1, k);
        for (int i = 0; i < m; i++) K[i * m + j] = k[i];
    }
}

/* the powers 1, t, t^2 of the columns' node coordinate along a side (the same along both: a box
 * has n columns each way) */
typedef struct column_powers {
    double p[WW_CUBE_MAX_COLUMNS][3];
} column_powers;

/* the polynomial of m x m coefficients K[i m + j] of tu^i tv^j at every column, row by row: the
 * row's polynomial in tv first, sum_i K[i m + j] tu^i, then its value. The constant term comes
 * first in each sum, so a polynomial whose other coefficients are 0 gives its constant exactly */
FIXED_COUNTS void poly_at_columns(int m, int n, const double *K, const column_powers *T,
                                double *out) {
    for (int iu = 0; iu < n; iu++) {
        const double *pu = T->p[iu];
        double row[3];
        for (int j = 0; j < m; j++) {
            double r = K[j];
            for (int i = 1; i < m; i++) r += K[i * m + j] * pu[i];
            row[j] = r;
        }
        for (int iv = 0; iv < n; iv++) {
            const double *pv = T->p[iv];
            double y = row[0];
            for (int j = 1; j < m; j++) y += row[j] * pv[j];
            out[iu * n + iv] = y;
        }
    }
}

/* bm[i m + j] = sum over the columns of vol tu^i tv^j, row by row */
FIXED_COUNTS void volume_moments(int m, int n, const double *vol, const column_powers *T,
                               double *bm) {
    for (int k = 0; k < m * m; k++) bm[k] = 0.0;
    for (int iu = 0; iu < n; iu++) {
        double r[3] = {0.0, 0.0, 0.0};
        for (int iv = 0; iv < n; iv++) {
            double v = vol[iu * n + iv];
            for (int j = 0; j < m; j++) r[j] += v * T->p[iv][j];
        }
        for (int i = 0; i < m; i++)
            for (int j = 0; j < m; j++) bm[i * m + j] += T->p[iu][i] * r[j];
    }
}

void ww_box_water_at(const ww_scene *sc, const ww_state *st, const double c[3],
                     const double q[4], const double extent[3], int n, double *warm,
                     ww_box_water *out) {
    int m = ww_box_nodes_per_side(n), nn = m * m;
    double x[WW_BOX_MAX_NODES], z[WW_BOX_MAX_NODES], height[WW_BOX_MAX_NODES];
    double velocity[3 * WW_BOX_MAX_NODES];
    ww_box_node_points(c, q, extent, n, x, z);
    if (warm) {
        ww_water_at_warm_n(sc, st, nn, x, z, 0.0, warm, height, velocity);
    } else {
        for (int k = 0; k < nn; k++) {
            ww_water_sample ws;
            ww_water_at(sc, st, x[k], z[k], 0.0, &ws);
            height[k] = ws.height;
            for (int j = 0; j < 3; j++) velocity[3 * k + j] = ws.velocity[j];
        }
    }
    ww_box_water_from(c, q, extent, n, height, velocity, out);
}

/* ww_box_water_from for n columns a side; inlined with the default n as a constant, so that its
 * loops over the columns have a known count and vectorise */
FIXED_COUNTS void water_from(int n, const double c[3], const double q[4], const double extent[3],
                           const double *node_height, const double *node_velocity,
                           ww_box_water *out) {
    double ax[3][3], U[3];
    int ap, aq, m = ww_box_nodes_per_side(n), mm = m * m;
    int a = box_frame(q, ax, U, &ap, &aq);
    const double *P = ax[ap], *Q = ax[aq];
    double s = extent[a], h = 0.5 * s;
    double cp = extent[ap] / n, cq = extent[aq] / n, dA = cp * cq;

    enum { MAXC = WW_CUBE_MAX_COLUMNS * WW_CUBE_MAX_COLUMNS };
    int nc = n * n, interpolated = m < n;
    /* every field but the wet lengths, which the columns fill below: those past the last column
     * in its block of 8 are zero, the rest are never read (the heave runs in blocks of 8) */
    out->volume = out->waterplane = out->waterplane_moment = 0.0;
    for (int k = 0; k < 3; k++) {
        out->centre[k] = c[k];
        out->velocity[k] = 0.0;
    }
    out->ncolumns = nc;
    out->up_y = U[1];
    out->cell_area = dA;
    out->length = s;
    for (int col = nc; col < (nc + 7) / 8 * 8; col++) out->wet[col] = 0.0;
    /* the columns' centre lines (offsets r from the centre, one array a coordinate) */
    double rx[MAXC], ry[MAXC], rz[MAXC], height[MAXC];
    for (int iu = 0; iu < n; iu++) {
        double u = (iu + 0.5 - 0.5 * n) * cp;
        for (int iv = 0; iv < n; iv++) {
            int col = iu * n + iv;
            double v = (iv + 0.5 - 0.5 * n) * cq;
            rx[col] = u * P[0] + v * Q[0];
            ry[col] = u * P[1] + v * Q[1];
            rz[col] = u * P[2] + v * Q[2];
        }
    }
    /* the surface's height over them: the nodes' own where the nodes are the columns, else the
     * polynomial through the nodes (Kh; and Kv, each velocity component's, for the mean velocity
     * below) at the columns' node coordinates */
    double Kh[WW_BOX_MAX_NODES], Kv[3][WW_BOX_MAX_NODES];
    column_powers T;
    if (interpolated) {
        for (int i = 0; i < n; i++) {
            double t = ((i + 0.5) / n - 0.5) / node_step(m);
            T.p[i][0] = 1.0, T.p[i][1] = t, T.p[i][2] = t * t;
        }
        if (m == 2) {
            node_coefficients(2, node_height, 1, Kh);
            for (int k = 0; k < 3; k++) node_coefficients(2, node_velocity + k, 3, Kv[k]);
            poly_at_columns(2, n, Kh, &T, height);
        } else {
            node_coefficients(3, node_height, 1, Kh);
            for (int k = 0; k < 3; k++) node_coefficients(3, node_velocity + k, 3, Kv[k]);
            poly_at_columns(3, n, Kh, &T, height);
        }
    } else {
        for (int col = 0; col < nc; col++) height[col] = node_height[col];
    }
    /* each column's volume and centroid offset from the centre, and its share of the waterline
     * (0 where the waterline misses it); the terms first, branch-free, so the loop vectorises,
     * then the sums in column order */
    double vol[MAXC], ox[MAXC], oy[MAXC], oz[MAXC], plane[MAXC], plane_r2[MAXC];
    /* read once: the stores to out->wet could otherwise alias c[1] for all GCC knows, which
     * keeps it from vectorising the loop */
    double cut_area = dA / U[1], cy = c[1]; /* cut_area: a cut column's share of the waterline */
    for (int col = 0; col < nc; col++) {
        double wet = (height[col] - (cy + ry[col])) / U[1] + h; /* submerged length along U */
        double L = wet < 0.0 ? 0.0 : wet; /* clamp(wet, 0, s) as two selects */
        L = L > s ? s : L;
        out->wet[col] = wet;
        double r2 = rx[col] * rx[col] + rz[col] * rz[col];
        plane[col] = wet > 0.0 ? (wet < s ? cut_area : 0.0) : 0.0; /* the waterline cuts it */
        plane_r2[col] = plane[col] * r2; /* 0 where uncut: r2 is finite and >= 0 */
        double off = 0.5 * (L - s);
        vol[col] = dA * L;
        ox[col] = rx[col] + off * U[0];
        oy[col] = ry[col] + off * U[1];
        oz[col] = rz[col] + off * U[2];
    }
    for (int col = 0; col < nc; col++) {
        out->waterplane += plane[col];
        out->waterplane_moment += plane_r2[col];
    }
    /* sums over point-mirrored pairs, so that a symmetric box on flat water feels exactly no
     * torque (rounding would otherwise seed a tilt that an unstable box amplifies); the middle
     * column of an odd count last, alone */
    double moment[3] = {0.0, 0.0, 0.0};
    for (int a0 = 0; a0 < nc / 2; a0++) {
        int a1 = nc - 1 - a0;
        double v0 = vol[a0], v1 = vol[a1];
        out->volume += v0 + v1;
        moment[0] += v0 * ox[a0] + v1 * ox[a1];
        moment[1] += v0 * oy[a0] + v1 * oy[a1];
        moment[2] += v0 * oz[a0] + v1 * oz[a1];
    }
    if (nc % 2) {
        int a0 = nc / 2;
        double v0 = vol[a0];
        out->volume += v0;
        moment[0] += v0 * ox[a0];
        moment[1] += v0 * oy[a0];
        moment[2] += v0 * oz[a0];
    }
    if (!(out->volume > 0.0)) return;
    /* the water's velocity weighted by the columns' volumes: sum_c V_c u(c). Interpolated,
     * u(c) = sum_k Kv[k] b_k(c), so it is sum_k Kv[k] (sum_c V_c b_k(c)): a moment of the
     * volumes a monomial instead of the velocity at every column */
    double vel[3] = {0.0, 0.0, 0.0};
    if (interpolated) {
        double bm[WW_BOX_MAX_NODES];
        if (m == 2)
            volume_moments(2, n, vol, &T, bm);
        else
            volume_moments(3, n, vol, &T, bm);
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < mm; k++) vel[j] += Kv[j][k] * bm[k];
    } else {
        for (int col = 0; col < nc; col++)
            for (int j = 0; j < 3; j++) vel[j] += vol[col] * node_velocity[3 * col + j];
    }
    for (int k = 0; k < 3; k++) {
        out->centre[k] = c[k] + moment[k] / out->volume;
        out->velocity[k] = vel[k] / out->volume;
    }
}

WW_LANES void ww_box_water_from(const double c[3], const double q[4], const double extent[3],
                                int n, const double *node_height, const double *node_velocity,
                                ww_box_water *out) {
    if (n == WW_CUBE_DEFAULT_COLUMNS)
        water_from(WW_CUBE_DEFAULT_COLUMNS, c, q, extent, node_height, node_velocity, out);
    else
        water_from(n, c, q, extent, node_height, node_velocity, out);
}

/* ---- the heave ------------------------------------------------------------------------------ */

/* the heave's root is found to this fraction of its bracket's size (rounding) */
#define HEAVE_TOLERANCE 1e-15
#define HEAVE_MAX_ITERATIONS 100

/* the heave's loops over the columns run in blocks of 8, a count GCC vectorises at -O2 (a count
 * known only at run time it leaves scalar): the columns past ncolumns in the last block are
 * worked out (ww_box_water's wet lengths are zero there) and not summed */
enum { HEAVE_BLOCKS = (WW_CUBE_MAX_COLUMNS * WW_CUBE_MAX_COLUMNS + 7) / 8 };

/* clamp(x, 0, s) as two selects */
WW_LANE_STEP double clamp_length(double x, double s) {
    double l = x < 0.0 ? 0.0 : x;
    return l > s ? s : l;
}

/* int_0^x clamp(x', 0, s) dx' = L^2 / 2 + s max(x - s, 0) with L = clamp(x, 0, s): 0 for x <= 0,
 * x^2 / 2 below s, s^2 / 2 + s (x - s) above, the same values as those three pieces, written
 * with selects of values every lane works out, so that the loops over the columns vectorise */
WW_LANE_STEP double clamp_integral(double x, double s) {
    double l = clamp_length(x, s), over = x - s;
    over = over > 0.0 ? over : 0.0;
    return 0.5 * l * l + s * over;
}

/* the mean submerged volume over [0, xi], (1 / xi) int_0^xi V (the discrete gradient), and its
 * derivative in xi. With V(xi) = dA sum clamp(w_c - xi / U.y, 0, s):
 * int_0^xi V = dA U.y sum (C(w_c) - C(w_c - xi / U.y)), C = clamp_integral, and
 * d Vbar / d xi = (V(xi) - Vbar) / xi. Below a ten-millionth of the box the secant cancels: there
 * Vbar is V at the midpoint (exact on a linear piece) and its slope half of V's there. Each
 * column's terms first (vectorised), then their sums in column order */
WW_LANE_STEP double volume_mean(const ww_box_water *w, const double *wet_integral, double xi,
                                double *slope) {
    double s = w->length, lift = xi / w->up_y, term[HEAVE_BLOCKS * 8], length[HEAVE_BLOCKS * 8];
    int nc = w->ncolumns, nb = (nc + 7) / 8;
    if (fabs(lift) < 1e-7 * s) {
        double v = 0.0, wet = 0.0;
        for (int b = 0; b < nb; b++)
            for (int j = 0; j < 8; j++) {
                int c = 8 * b + j;
                double x = w->wet[c] - 0.5 * lift;
                length[c] = clamp_length(x, s);
                term[c] = x > 0.0 ? (x < s ? 1.0 : 0.0) : 0.0;
            }
        for (int c = 0; c < nc; c++) {
            v += length[c];
            wet += term[c];
        }
        *slope = -0.5 * w->cell_area * wet / w->up_y;
        return w->cell_area * v;
    }
    for (int b = 0; b < nb; b++)
        for (int j = 0; j < 8; j++) {
            int c = 8 * b + j;
            double x = w->wet[c] - lift;
            term[c] = wet_integral[c] - clamp_integral(x, s);
            length[c] = clamp_length(x, s);
        }
    double acc = 0.0, v = 0.0;
    for (int c = 0; c < nc; c++) {
        acc += term[c];
        v += length[c];
    }
    double mean = w->cell_area * w->up_y * acc / xi;
    *slope = (w->cell_area * v - mean) / xi;
    return mean;
}

/* the heave over dt by the discrete-gradient midpoint rule: returns xi1, sets *v.
 * R(xi) = (2 / dt + gamma) xi - 2 v0 - dt (kb Vbar(xi) + a + gamma u) = 0, R increasing;
 * Vbar in [0, the box's volume] brackets the root. kb = rho_w g / m. Solved by Newton's method
 * kept inside the bracket, bisecting where a step would leave it (Press et al., "Numerical
 * Recipes", rtsafe):
 * R is piecewise smooth (its pieces change where a column's wet length reaches 0 or s), so
 * Newton converges in a few steps where bisection took 50 to reach the bracket's rounding. */
WW_LANES double ww_box_heave_step(const ww_box_water *w, const double extent[3], double kb,
                                  double a, double gamma, double u, double dt, double *v) {
    double v0 = *v, den = 2.0 / dt + gamma, base = 2.0 * v0 + dt * (a + gamma * u);
    double lo = base / den, hi = (base + dt * kb * extent[0] * extent[1] * extent[2]) / den;
    /* first guess: the root with the buoyancy linear in xi, V = V0 - A_w xi (so Vbar = V0 -
     * A_w xi / 2), which is the answer while no column's wet length reaches 0 or the box */
    double xi = (base + dt * kb * w->volume) / (den + 0.5 * dt * kb * w->waterplane);
    if (!(xi > lo && xi < hi)) xi = 0.5 * (lo + hi);
    /* C(w_c) of every column, the same at every iterate */
    double wet_integral[HEAVE_BLOCKS * 8];
    for (int b = 0; b < (w->ncolumns + 7) / 8; b++)
        for (int j = 0; j < 8; j++)
            wet_integral[8 * b + j] = clamp_integral(w->wet[8 * b + j], w->length);
    for (int it = 0; it < HEAVE_MAX_ITERATIONS; it++) {
        double slope, r = den * xi - base - dt * kb * volume_mean(w, wet_integral, xi, &slope);
        if (r == 0.0) break;
        if (r > 0.0)
            hi = xi;
        else
            lo = xi;
        double dr = den - dt * kb * slope, next = xi - r / dr;
        double tol = HEAVE_TOLERANCE * (fabs(lo) + fabs(hi)) + 1e-300;
        /* a Newton step within the tolerance: xi is the root to rounding. Tested before the
         * safeguard, which takes a step onto the bracket's end (xi itself, most often the
         * first guess's) for one leaving it and bisects, two evaluations for nothing */
        if (dr > 0.0 && fabs(next - xi) <= tol) {
            xi = next;
            break;
        }
        if (!(dr > 0.0) || !(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (fabs(next - xi) <= tol || hi - lo <= tol || next <= lo || next >= hi) {
            xi = next;
            break;
        }
        xi = next;
    }
    *v = 2.0 * xi / dt - v0;
    return xi;
}

/* ---- the rest of the step ------------------------------------------------------------------ */

void ww_box_move(const ww_box_motion *m, double y, double dt, double p[3], double v[3],
                 double w[3], double q[4]) {
    double e = ww_exp(-m->gamma * dt);
    for (int k = 0; k < 3; k += 2) {
        v[k] += m->ah[k / 2] * dt;
        v[k] = m->u[k] + (v[k] - m->u[k]) * e;
    }
    if (m->drag_q > 0.0) {
        double rel[3] = {v[0] - m->u[0], v[1] - m->u[1], v[2] - m->u[2]};
        double shrink = 1.0 / (1.0 + dt * m->drag_q * ww_m_len3(rel));
        for (int k = 0; k < 3; k++) v[k] = m->u[k] + rel[k] * shrink;
    }
    p[0] += v[0] * dt;
    p[1] += y;
    p[2] += v[2] * dt;
    double tilt = 1.0 + dt * m->spin_damp + dt * dt * m->tilt_k;
    w[0] = (w[0] + dt * m->alpha[0]) / tilt;
    w[1] = (w[1] + dt * m->alpha[1]) / (1.0 + dt * m->spin_damp);
    w[2] = (w[2] + dt * m->alpha[2]) / tilt;
    ww_box_turn(q, w, dt);
}
