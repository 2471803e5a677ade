/* boat.c - seed 000's arcade boat made analog (boat.h states the model; desc_boat.h the
 * parameters): engine and drag, steering and side slip, bobbing and tilting on the exact surface
 * (ww_water_at), pushing cubes, the seat camera.
 *
 * Where this departs from seed 000, and why:
 *  - Seed 000 steps v <- v + a dt, then v <- v e^(-1.2 dt): its terminal speed a dt / (e^(k dt)
 *    - 1) depends on the frame rate (0.5% low at 120 Hz, 2% at 30 Hz). We integrate
 *    dv/dt = a u - k v exactly for the step's constant input, so the terminal speed is a u / k at
 *    any dt, and move the boat by the step's exact mean speed, so a straight run covers the
 *    closed-form distance.
 *  - Seed 000 adds the side slip in proportion to the turn input alone, so a boat at rest slides
 *    sideways while turning; here the slip scales with the forward speed as well.
 *  - Seed 000 eases the height with a per-frame fraction lambda (frame-rate dependent); here the
 *    height, pitch and roll follow the surface through dy/dt = (y_t - y) / tau, solved exactly
 *    with the target linear across the step (a first-order hold), so the response to a swell is
 *    the continuous filter's: amplitude 1 / sqrt(1 + (w tau)^2), lag atan(w tau).
 *  - Seed 000 treats cubes as spheres; here they are circles in XZ of radius size / 2, and a
 *    pushed cube also takes the boat's velocity along the contact normal, so it is not pushed
 *    again on every step by a boat that is still faster than it.
 *  - Seed 001 sets the tilt from the surface normal at the centre; we take pitch and roll from
 *    samples at bow, stern, port and starboard, and ignore waves shorter than the hull (a boat
 *    does not follow chop shorter than itself).
 */
#include "sim/boat.h"

#include <math.h>

#include "core/atan.h"
#include "core/mathx.h"
#include "core/sincos.h"
#include "sim/events.h"
#include "sim/water.h"

#define UNTIL_NONE (-1.0)
/* an `until` time counts as reached on the first step within this of it (as script events) */
#define UNTIL_EPS 1e-9
/* a cube centre this close to the boat's (m) has no direction: it is pushed out ahead */
#define CENTRED_EPS 1e-12

/* a in [-pi, pi) */
static double wrap_pi(double a) { return ww_m_wrap_tau(a + WW_PI) - WW_PI; }

/* sin(x) / x */
static double sinc(double x) {
    if (fabs(x) < 1e-4) return 1.0 - x * x / 6.0;
    double s, c;
    ww_sincos(x, &s, &c);
    return s / x;
}

void ww_boat_frame(double heading, double pitch, double roll, double fwd[3], double up[3],
                   double stbd[3]) {
    double ch, sh, cp, sp, cr, sr;
    ww_sincos(heading, &sh, &ch);
    ww_sincos(pitch, &sp, &cp);
    ww_sincos(roll, &sr, &cr);
    /* level frame: forward (cos h, 0, sin h), up +y, starboard = forward x up = (-sin h, 0, cos h);
     * pitch turns forward toward up about starboard, roll turns up toward starboard about forward */
    double f0[3] = {ch, 0.0, sh}, u0[3] = {0.0, 1.0, 0.0}, r0[3] = {-sh, 0.0, ch};
    for (int c = 0; c < 3; c++) {
        double u1 = u0[c] * cp - f0[c] * sp;
        fwd[c] = f0[c] * cp + u0[c] * sp;
        up[c] = u1 * cr + r0[c] * sr;
        stbd[c] = r0[c] * cr - u1 * sr;
    }
}

/* what the hull follows at (x, z) with the heading whose cosine and sine are fx, fz: [0] the
 * height of the hull centre, [1] pitch from bow and stern, [2] roll from port and starboard (seed
 * 001's sampling) */
static void surface_targets(const ww_scene *sc, ww_state *st, double x, double z, double fx,
                            double fz, double out[3]) {
    const ww_boat_desc *b = &sc->boat;
    /* starboard is (-fz, fx) */
    double hl = 0.5 * b->length, hb = 0.5 * b->beam, minL = b->length;
    /* centre, bow, stern, port, starboard: one warm start per sample, in this order, queried
     * together (sim/water.h) */
    double px[5] = {x, x + hl * fx, x - hl * fx, x + hb * fz, x - hb * fz};
    double pz[5] = {z, z + hl * fz, z - hl * fz, z - hb * fx, z + hb * fx}, h[5];
    ww_water_at_warm_n(sc, st, 5, px, pz, minL, st->boat_warm, h, NULL);
    out[0] = h[0] + b->ride_height;
    out[1] = ww_atan2(h[1] - h[2], b->length);
    out[2] = ww_atan2(h[3] - h[4], b->beam);
}

/* y follows u through dy/dt = (u - y) / tau over a step in which u goes linearly from u0 to u1:
 * y(t) = u(t) - s tau + (y0 - u0 + s tau) e^(-t / tau) with s = (u1 - u0) / dt, exact; decay is
 * e^(-dt / tau) */
static double follow(double y0, double u0, double u1, double dt, double tau, double decay) {
    if (tau <= 0.0) return u1;
    double s_tau = (u1 - u0) * (tau / dt);
    return u1 - s_tau + (y0 - u0 + s_tau) * decay;
}

/* forward speed after dt under throttle u: dv/dt = a u - k v from v0, exact; *mean is the mean
 * speed over the step, v_inf + (v0 - v_inf) (1 - e^(-k dt)) / (k dt) */
static double speed_after(const ww_boat_desc *b, double v0, double u, double dt, double *mean) {
    double a = b->acceleration * u, k = b->drag, v1;
    if (k > 0.0) {
        double v_inf = a / k, decay = -expm1(-k * dt); /* 1 - e^(-k dt) */
        v1 = v0 + (v_inf - v0) * decay;
        *mean = v_inf + (v0 - v_inf) * decay / (k * dt);
    } else {
        v1 = v0 + a * dt;
        *mean = v0 + 0.5 * a * dt;
    }
    *mean = ww_m_clamp(*mean, -b->reverse_speed, b->max_speed);
    return ww_m_clamp(v1, -b->reverse_speed, b->max_speed);
}

/* engine and rudder over [t - dt, t] with the inputs in force, then bobbing to the surface at t */
static void move(const ww_scene *sc, ww_state *st, double dt) {
    const ww_boat_desc *b = &sc->boat;
    double *p = st->boat_pos, *v = st->boat_vel;
    double u = st->boat_input[0], steer = st->boat_input[1];

    /* speed, heading, and the exact displacement of an arc at the mean speed */
    double mean, v1 = speed_after(b, st->boat_speed[0], u, dt, &mean);
    double h0 = st->boat_heading[0], dh = b->turn_rate * steer * dt, hm = h0 + 0.5 * dh;
    double slip = -b->slip * steer; /* starboard speed per forward speed: outward */
    double arc = dt * sinc(0.5 * dh);
    double fx, fz;
    ww_sincos(hm, &fz, &fx);
    if (sc->integrator == WW_INTEGRATE_EULER) {
        /* seed 000's update, the baseline of time.integrator: v += a u dt, v <- v e^(-k dt),
         * then a straight move along the new heading */
        v1 = ww_m_clamp((st->boat_speed[0] + b->acceleration * u * dt) * exp(-b->drag * dt),
                        -b->reverse_speed, b->max_speed);
        mean = v1;
        arc = dt;
        ww_sincos(h0 + dh, &fz, &fx);
    }
    p[0] += arc * mean * (fx - slip * fz);
    p[2] += arc * mean * (fz + slip * fx);
    double h1 = wrap_pi(h0 + dh);
    st->boat_heading[0] = h1;
    st->boat_speed[0] = v1;
    double c1, s1;
    ww_sincos(h1, &s1, &c1);
    v[0] = v1 * (c1 - slip * s1);
    v[2] = v1 * (s1 + slip * c1);

    /* height, pitch and roll after the surface (first-order hold of the targets) */
    double target[3], y0 = p[1], decay = b->bob_time > 0.0 ? exp(-dt / b->bob_time) : 0.0;
    surface_targets(sc, st, p[0], p[2], c1, s1, target);
    p[1] = follow(p[1], st->boat_follow[0], target[0], dt, b->bob_time, decay);
    for (int i = 0; i < 2; i++)
        st->boat_tilt[i] = follow(st->boat_tilt[i], st->boat_follow[1 + i], target[1 + i], dt,
                                  b->bob_time, decay);
    for (int i = 0; i < 3; i++) st->boat_follow[i] = target[i];
    v[1] = (p[1] - y0) / dt;
    st->boat_odometer[0] += fabs(arc * mean) * sqrt(1.0 + slip * slip);
}

/* the stern's place, the time and the odometer into the wake's trail, every WW_BOAT_WAKE_EVERY
 * seconds of steps (the renderer draws the wake from it: gfx/wake.h) */
static void trail(const ww_scene *sc, ww_state *st) {
    int64_t every = (int64_t)floor(WW_BOAT_WAKE_EVERY / sc->dt + 0.5);
    if (every < 1) every = 1;
    if (st->step % every != 0) return;
    int k = (int)st->boat_wake_next[0];
    double c, s, *w = st->boat_wake + 4 * k;
    ww_sincos(st->boat_heading[0], &s, &c);
    w[0] = st->boat_pos[0] - 0.5 * sc->boat.length * c;
    w[1] = st->boat_pos[2] - 0.5 * sc->boat.length * s;
    w[2] = st->t;
    w[3] = st->boat_odometer[0];
    st->boat_wake_next[0] = (double)((k + 1) % WW_BOAT_WAKE);
}

/* the action of this step takes over; inputs whose `until` has come end; the engine's start and
 * stop are events */
static void update_inputs(const ww_scene *sc, ww_state *st) {
    double *in = st->boat_input, *cmd = st->boat_command;
    double before = in[0];
    if (cmd[3] != 0.0) {
        in[0] = cmd[0];
        in[1] = cmd[1];
        in[2] = cmd[2];
        cmd[3] = 0.0;
    }
    if (in[2] >= 0.0 && st->t >= in[2] - UNTIL_EPS) {
        in[0] = in[1] = 0.0;
        in[2] = UNTIL_NONE;
    }
    if (before == 0.0 && in[0] != 0.0)
        ww_emit(sc, st, WW_SE_BOAT_START, 0, st->boat_pos, in[0], 0.0);
    else if (before != 0.0 && in[0] == 0.0)
        ww_emit(sc, st, WW_SE_BOAT_STOP, 0, st->boat_pos, fabs(st->boat_speed[0]), 0.0);
}

/* circles in XZ: out to radius + size / 2, and at least the boat's velocity along the normal */
static void push_cubes(const ww_scene *sc, ww_state *st) {
    if (!sc->cubes.on) return;
    const double *p = st->boat_pos, *bv = st->boat_vel;
    for (int i = 0; i < sc->cubes.count; i++) {
        double *c = st->cube_pos + 3 * i, *cv = st->cube_vel + 3 * i;
        double reach = sc->boat.radius + 0.5 * sc->cubes.cube[i].size;
        double dx = c[0] - p[0], dz = c[2] - p[2], d = hypot(dx, dz);
        if (d >= reach) continue;
        double nx, nz;
        if (d > CENTRED_EPS) {
            nx = dx / d;
            nz = dz / d;
        } else {
            nx = cos(st->boat_heading[0]);
            nz = sin(st->boat_heading[0]);
        }
        c[0] = p[0] + nx * reach;
        c[2] = p[2] + nz * reach;
        double closing = (cv[0] - bv[0]) * nx + (cv[2] - bv[2]) * nz;
        if (closing < 0.0) {
            cv[0] -= closing * nx;
            cv[2] -= closing * nz;
        }
    }
}

void ww_boat_reset(const ww_scene *sc, ww_state *st) {
    const ww_boat_desc *b = &sc->boat;
    for (int c = 0; c < 3; c++) {
        st->boat_pos[c] = b->position[c];
        st->boat_vel[c] = 0.0;
    }
    st->boat_heading[0] = wrap_pi(b->heading);
    st->boat_speed[0] = 0.0;
    st->boat_tilt[0] = st->boat_tilt[1] = 0.0;
    for (int k = 0; k < WW_WARM_STRIDE * WW_BOAT_SAMPLES; k++) st->boat_warm[k] = 0.0; /* cold */
    surface_targets(sc, st, b->position[0], b->position[2], cos(st->boat_heading[0]),
                    sin(st->boat_heading[0]), st->boat_follow);
    st->boat_input[0] = st->boat_input[1] = 0.0;
    st->boat_input[2] = UNTIL_NONE;
    st->boat_command[0] = st->boat_command[1] = st->boat_command[3] = 0.0;
    st->boat_command[2] = UNTIL_NONE;
    st->boat_look_yaw[0] = st->boat_heading[0];
    st->boat_camera[0] = 0.0;
    st->boat_odometer[0] = 0.0;
    st->boat_wake_next[0] = 0.0;
    /* no trail yet: samples long gone (finite, for the state's check) */
    for (int k = 0; k < WW_BOAT_WAKE; k++) {
        double *w = st->boat_wake + 4 * k;
        w[0] = st->boat_pos[0], w[1] = st->boat_pos[2], w[2] = sc->start - 1e6, w[3] = 0.0;
    }
}

void ww_boat_step(const ww_scene *sc, ww_state *st) {
    /* step 0 is the start pose: nothing to integrate yet */
    if (st->step > 0) move(sc, st, sc->dt);
    trail(sc, st);
    update_inputs(sc, st);
    push_cubes(sc, st);
}

void ww_boat_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    if (!sc->boat.on) return;
    if (ev->kind == WW_EV_BOAT) {
        st->boat_command[0] = ev->v[0];
        st->boat_command[1] = ev->v[1];
        st->boat_command[2] = (ev->flags & 1) ? ev->v[2] : UNTIL_NONE;
        st->boat_command[3] = 1.0;
    } else if (ev->kind == WW_EV_CAMERA_MODE) {
        st->boat_camera[0] = ev->index == 1 ? 1.0 : 0.0;
    }
}

void ww_boat_camera(const ww_scene *sc, ww_state *st) {
    const ww_boat_desc *b = &sc->boat;
    double *look = st->boat_look_yaw;

    /* free: the path camera stays; the seat view starts from its heading when the mode switches */
    if (st->boat_camera[0] == 0.0) {
        if (st->cam_fwd[0] != 0.0 || st->cam_fwd[2] != 0.0)
            look[0] = atan2(st->cam_fwd[2], st->cam_fwd[0]);
        return;
    }

    /* the view's heading eases back to the boat's: off-heading angle decays as e^(-t / look_time) */
    double h = st->boat_heading[0], off = wrap_pi(look[0] - h);
    double dt = st->step > 0 ? sc->dt : 0.0;
    if (b->look_time > 0.0)
        off *= exp(-dt / b->look_time);
    else
        off = 0.0;
    look[0] = wrap_pi(h + off);

    /* the seat in the tilted hull frame; the view pitches with the bow */
    double f[3], u[3], r[3];
    ww_boat_frame(h, st->boat_tilt[0], st->boat_tilt[1], f, u, r);
    for (int c = 0; c < 3; c++)
        st->cam_pos[c] = st->boat_pos[c] + b->seat[0] * f[c] + b->seat[1] * u[c] + b->seat[2] * r[c];
    double pitch = ww_m_clamp(b->look_pitch + st->boat_tilt[0], -0.5 * WW_PI + 1e-3,
                              0.5 * WW_PI - 1e-3);
    st->cam_fwd[0] = cos(pitch) * cos(look[0]);
    st->cam_fwd[1] = sin(pitch);
    st->cam_fwd[2] = cos(pitch) * sin(look[0]);
}
