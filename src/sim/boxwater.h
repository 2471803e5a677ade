/* boxwater.h - a rigid box against the exact water surface, shared by the floating cubes
 * (sim/cubes.c) and floating models (sim/floaters.c): the rotation helpers, the submerged volume
 * by Archimedes columns, and the heave's implicit step.
 *
 * The box is cut into n x n columns along its axis nearest the vertical (U); each column's wet
 * length comes from the surface's height at its centre line, so the volume, the centre of
 * buoyancy, the waterline's area and moment and the water's velocity follow. The surface is
 * queried exactly (sim/water.h) at m x m nodes of the cross-section (ww_box_nodes_per_side,
 * scene/desc_cubes.h): the columns' own centres up to 2 x 2 columns, else the Gauss-Legendre
 * nodes, 2 x 2 up to 4 x 4 columns and 3 x 3 above, and the polynomial through them (bilinear,
 * biquadratic) gives every column its height and the box its mean velocity. Against a query at
 * every column that costs at most a quarter more error on waves (a test measures it) for 4 or 9
 * queries instead of up to 64. The heave is integrated by the discrete-gradient midpoint rule
 * with the surface and the tilt held over the step (docs/simulation.md, "Cubes").
 */
#ifndef WW_BOXWATER_H
#define WW_BOXWATER_H

#include "scene/scene.h"
#include "sim/state.h"

/* what the water does to a box at its pose, at st->t */
typedef struct ww_box_water {
    double volume;      /* submerged volume, m^3 */
    double centre[3];   /* centre of buoyancy, m (the box's centre when volume is 0) */
    double waterplane;  /* -dV/dy: the waterline area the heave sees, m^2 */
    double waterplane_moment; /* sum over the waterline of area x horizontal offset^2, m^4 */
    double velocity[3]; /* volume-weighted water velocity, m/s */
    /* the heave's exact buoyancy law over the step (surface and tilt held): raising the box by
     * xi makes column c's wet length clamp(wet[c] - xi / up_y, 0, length) */
    int ncolumns;
    double up_y, cell_area;
    double length;      /* the box along U, where a column's wet part ends, m */
    double wet[WW_CUBE_MAX_COLUMNS * WW_CUBE_MAX_COLUMNS]; /* unclamped wet lengths, m */
} ww_box_water;

/* unit quaternion q (w x y z) to the rotated local axes: ax[k] = R e_k */
void ww_box_axes(const double q[4], double ax[3][3]);
/* q <- exp(w dt / 2) q: the exact rotation by the world angular velocity w over dt */
void ww_box_turn(double q[4], const double w[3], double dt);
/* index of the local axis nearest the vertical */
int ww_box_up_axis(double ax[3][3]);

/* the box centred at c, turned by q, of edge lengths extent (local x, y, z), in n x n columns;
 * warm: its nodes' warm starts (ww_box_nodes_per_side(n) squared, sim/water.h), NULL for cold
 * queries */
void ww_box_water_at(const ww_scene *sc, const ww_state *st, const double c[3],
                     const double q[4], const double extent[3], int n, double *warm,
                     ww_box_water *out);
/* the two halves of ww_box_water_at, for callers that query several boxes' nodes at once: the
 * nodes' horizontal positions (x, z: ww_box_nodes_per_side(n) squared each), then the columns
 * from the surface's height and velocity (3 a node) there */
void ww_box_node_points(const double c[3], const double q[4], const double extent[3], int n,
                        double *x, double *z);
void ww_box_water_from(const double c[3], const double q[4], const double extent[3], int n,
                       const double *node_height, const double *node_velocity,
                       ww_box_water *out);

/* the heave over dt: returns the rise xi over the step and sets *v, the new vertical velocity.
 * extent: the box's edges (its volume brackets the mean submerged volume); kb = rho_w g / m; a:
 * the other vertical accelerations; gamma, u: the linear drag and the water's vertical velocity */
double ww_box_heave_step(const ww_box_water *w, const double extent[3], double kb, double a,
                         double gamma, double u, double dt, double *v);

/* what moves a box over a step besides its heave (the body's own forces, sim/cubes.c and
 * sim/floaters.c) */
typedef struct ww_box_motion {
    double gamma;     /* linear drag toward the water's velocity, 1/s */
    double u[3];      /* the water's velocity at the box, m/s */
    double ah[2];     /* horizontal accelerations (x, z): the slope's push, m/s^2 */
    double drag_q;    /* quadratic drag: 1/2 rho_w Cd A f / m, 1/m */
    double alpha[3];  /* angular acceleration, world, rad/s^2 */
    double tilt_k;    /* the tilt's stiffness bound, 1/s^2 */
    double spin_damp; /* angular drag, 1/s */
} ww_box_motion;

/* the rest of a step once the heave has given the rise y and v[1]: the horizontal velocity (the
 * slope's push, then linear drag toward the water exactly), the quadratic drag implicitly (the
 * relative velocity shrinks, never reverses), the position, and the rotation (tilt linearly
 * implicit with its stiffness bound, spin damped) */
void ww_box_move(const ww_box_motion *m, double y, double dt, double p[3], double v[3],
                 double w[3], double q[4]);

#endif
