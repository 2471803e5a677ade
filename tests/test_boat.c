/* test_boat.c - the boat against its closed forms: terminal speed a / k and the distance of a
 * straight run, the capped reverse speed, the turn rate and the radius of a steady turn, the
 * first-order response of height and pitch to a long swell, 50 cubes rammed at full throttle,
 * the seat camera and its easing, engine events, determinism; and the loader's boat keys.
 * Scenes are built by hand (ww_scene_defaults + ww_boat_defaults) except in the loader tests.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "sim/boat.h"
#include "sim/camera.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* terminal speed against a u / k: the brief's 1% (the exact integration meets it to rounding) */
#define BOAT_SPEED_REL_TOL 0.01
/* distance of a straight run from rest against v_inf (t - (1 - e^(-k t)) / k): the step's mean
 * speed is exact, so only rounding over 1200 steps remains */
#define BOAT_DISTANCE_TOL 1e-9
/* heading change per second and turn radius against the model's: the brief's 1% */
#define BOAT_TURN_REL_TOL 0.01
/* hull height against the continuous first-order response to the swell: the target is linear
 * between steps, so the error is the interpolation's, A (w dt)^2 / 8 = 3e-6 m here */
#define BOB_HEIGHT_TOL 2e-5
/* pitch against the lagged chord slope A k sinc(k l / 2) cos(phase) between bow and stern (l
 * the hull length): the model takes atan of it, (A k)^2 / 3 = 3e-4 of it away */
#define BOB_PITCH_REL_TOL 1e-3
/* the same against the slope at the centre, A k cos(phase): the chord is 1 - sinc = 0.7% flatter */
#define BOB_SLOPE_REL_TOL 0.01
/* a pushed cube's centre distance from the boat's against radius + size / 2 (rounding) */
#define PUSH_DISTANCE_TOL 1e-9
/* seat camera position and view against the hand-computed frame (rounding) */
#define SEAT_TOL 1e-12
/* seat view's off-heading angle against off0 e^(-t / look_time) (rounding) */
#define LOOK_EASE_TOL 1e-12

/* flat water, noon, a boat with every default; dt 1/120 */
static ww_scene *boat_scene(void) {
    ww_scene *sc = malloc(sizeof *sc);
    ww_scene_defaults(sc);
    snprintf(sc->path, sizeof sc->path, "boat.yaml");
    sc->wave_model = WW_WAVES_FLAT;
    sc->camera_collide = 0; /* the seat is inside the boat's sphere: collision is another test's */
    ww_boat_defaults(&sc->boat);
    sc->boat.on = 1;
    ww_scene_plan_systems(sc);
    return sc;
}

static void add_boat_action(ww_scene *sc, double t, double throttle, double steer, double until) {
    ww_event *e = &sc->events[sc->nevents++];
    *e = (ww_event){.t = t, .step = (int64_t)llround((t - sc->start) / sc->dt),
                    .kind = WW_EV_BOAT, .v = {throttle, steer, until}, .flags = until > 0};
}

static void add_camera_action(ww_scene *sc, double t, int mode) {
    ww_event *e = &sc->events[sc->nevents++];
    *e = (ww_event){.t = t, .step = (int64_t)llround((t - sc->start) / sc->dt),
                    .kind = WW_EV_CAMERA_MODE, .index = mode};
}

static ww_state *run_to(const ww_scene *sc, double t) {
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    ENSURE(ww_sim_advance_to(sc, st, (int64_t)llround((t - sc->start) / sc->dt), &err) == WW_OK);
    return st;
}

TEST(boat_full_throttle_reaches_terminal_speed_and_distance) {
    ww_scene *sc = boat_scene();
    add_boat_action(sc, 0.0, 1.0, 0.0, 0.0);
    double T = 10.0, k = sc->boat.drag, v_inf = sc->boat.acceleration / k; /* 5 m/s */
    ww_state *st = run_to(sc, T);
    ENSURE_NEAR(st->boat_speed[0], v_inf, BOAT_SPEED_REL_TOL * v_inf);
    ENSURE_NEAR(hypot(st->boat_vel[0], st->boat_vel[2]), v_inf, BOAT_SPEED_REL_TOL * v_inf);
    /* heading 0: along +x, the closed-form distance from rest */
    double x = v_inf * (T - (1.0 - exp(-k * T)) / k);
    ENSURE_NEAR(st->boat_pos[0] - sc->boat.position[0], x, BOAT_DISTANCE_TOL * x);
    ENSURE_NEAR(st->boat_pos[2], 0.0, BOAT_DISTANCE_TOL);
    ww_state_free(st);

    /* a cap below a / k binds: max_speed exactly */
    sc->boat.max_speed = 3.0;
    st = run_to(sc, T);
    ENSURE_NEAR(st->boat_speed[0], 3.0, BOAT_SPEED_REL_TOL * 3.0);
    ww_state_free(st);
    free(sc);
}

TEST(boat_reverse_speed_is_the_reduced_one) {
    ww_scene *sc = boat_scene();
    add_boat_action(sc, 0.0, -1.0, 0.0, 0.0);
    ww_state *st = run_to(sc, 10.0);
    /* a / k = 5 m/s, capped at reverse_speed = 2 m/s, heading unchanged, moving along -x */
    ENSURE_NEAR(st->boat_speed[0], -sc->boat.reverse_speed, BOAT_SPEED_REL_TOL * 2.0);
    ENSURE(st->boat_speed[0] > -sc->boat.max_speed);
    ENSURE(st->boat_pos[0] < sc->boat.position[0]);
    ww_state_free(st);

    /* a weaker engine whose a / k = 1 m/s stays under the cap: the closed form again */
    sc->boat.acceleration = 1.2;
    st = run_to(sc, 10.0);
    ENSURE_NEAR(st->boat_speed[0], -1.0, BOAT_SPEED_REL_TOL * 1.0);
    ww_state_free(st);
    free(sc);
}

TEST(boat_constant_steer_turns_at_the_rate_on_a_circle) {
    ww_scene *sc = boat_scene();
    double steer = 0.5;
    add_boat_action(sc, 0.0, 1.0, steer, 0.0);
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    double rate = sc->boat.turn_rate * steer; /* rad/s */
    double v_inf = sc->boat.acceleration / sc->boat.drag, slip = sc->boat.slip * steer;
    double radius = sqrt(1.0 + slip * slip) * v_inf / rate;

    /* the heading, unwrapped, over 4 s; then the extent of one full circle after 10 s */
    int64_t n4 = (int64_t)llround(4.0 / sc->dt), n10 = (int64_t)llround(10.0 / sc->dt);
    int64_t nturn = n10 + (int64_t)ceil(WW_TAU / rate / sc->dt) + 2;
    double turned = 0.0, h = st->boat_heading[0];
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
    for (int64_t n = 1; n <= nturn; n++) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        double d = st->boat_heading[0] - h;
        h = st->boat_heading[0];
        if (n <= n4) turned += d - WW_TAU * round(d / WW_TAU);
        if (n >= n10)
            for (int c = 0; c < 2; c++) {
                lo[c] = fmin(lo[c], st->boat_pos[2 * c]);
                hi[c] = fmax(hi[c], st->boat_pos[2 * c]);
            }
    }
    ENSURE_NEAR(turned / 4.0, rate, BOAT_TURN_REL_TOL * rate);
    ENSURE(turned > 0.0); /* steer + turns to starboard: the heading grows toward +z */
    ENSURE_NEAR(0.5 * (hi[0] - lo[0]), radius, BOAT_TURN_REL_TOL * radius);
    ENSURE_NEAR(0.5 * (hi[1] - lo[1]), radius, BOAT_TURN_REL_TOL * radius);
    ww_state_free(st);
    free(sc);
}

TEST(boat_bobs_with_a_long_swell_as_a_first_order_lag) {
    ww_scene *sc = boat_scene();
    sc->wave_model = WW_WAVES_SINES;
    double A = 0.3, L = 60.0;
    ww_wave *w = &sc->waves[sc->nwaves++];
    *w = (ww_wave){.direction = 0.0, .wavelength = L, .amplitude = A};
    ww_wave_derive(w, 0.0);
    double k = w->k, om = w->omega, tau = sc->boat.bob_time;
    double gain = 1.0 / sqrt(1.0 + om * tau * om * tau), lag = atan(om * tau) / om;
    double half = 0.5 * k * sc->boat.length, chord = sin(half) / half;

    /* the boat at rest at the origin, bow along the wave (+x): it pitches and does not roll */
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    double worst_h = 0.0, worst_p = 0.0, worst_slope = 0.0, worst_follow = 0.0, worst_roll = 0.0;
    int64_t n0 = (int64_t)llround(3.0 / sc->dt), n1 = n0 + (int64_t)llround(WW_TAU / om / sc->dt);
    for (int64_t n = 1; n <= n1; n++) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        if (n < n0) continue;
        /* surface at the origin: A sin(-w t); the filter's steady state is its value lag earlier,
         * scaled by gain; the slope is A k cos(-w t), the bow-stern chord's sinc times that */
        double t = st->t, ph = -om * (t - lag);
        double h_want = sc->water_level + sc->boat.ride_height + gain * A * sin(ph);
        double slope = gain * A * k * cos(ph);
        worst_h = fmax(worst_h, fabs(st->boat_pos[1] - h_want));
        worst_p = fmax(worst_p, fabs(st->boat_tilt[0] - chord * slope));
        worst_slope = fmax(worst_slope, fabs(st->boat_tilt[0] - slope));
        worst_roll = fmax(worst_roll, fabs(st->boat_tilt[1]));
        worst_follow = fmax(worst_follow, fabs(st->boat_pos[1] - sc->boat.ride_height -
                                               A * sin(-om * t)));
    }
    ENSURE_NEAR(worst_h, 0.0, BOB_HEIGHT_TOL);
    ENSURE_NEAR(worst_p, 0.0, BOB_PITCH_REL_TOL * A * k);
    ENSURE_NEAR(worst_slope, 0.0, BOB_SLOPE_REL_TOL * A * k);
    ENSURE_NEAR(worst_roll, 0.0, SEAT_TOL);
    /* it follows the surface within the lag's reach, A sqrt((1 - g)^2 + ...) <= A w tau */
    ENSURE(worst_follow <= A * om * tau);
    ENSURE(worst_follow > 0.5 * A * om * tau); /* and it does lag: not glued to the surface */
    ww_state_free(st);
    free(sc);
}

TEST(boat_full_throttle_into_50_cubes) {
    ww_scene *sc = boat_scene();
    sc->boat.acceleration = 12.0; /* a / k = 10 m/s: the 8 m/s cap binds */
    sc->boat.position[0] = -10.0;
    sc->cubes.on = 1;
    ww_scene_plan_systems(sc);
    sc->cubes.count = 50;
    for (int i = 0; i < 50; i++) {
        ww_cube_desc *c = &sc->cubes.cube[i];
        /* a 10 x 5 block ahead, 1.2 m apart, sizes 0.4 .. 1.0 m */
        *c = (ww_cube_desc){.position = {2.0 + 1.2 * (i % 10), 0.0, -2.4 + 1.2 * (i / 10)},
                            .size = 0.4 + 0.6 * (double)(i % 7) / 6.0, .density = 500.0};
    }
    add_boat_action(sc, 0.0, 1.0, 0.0, 6.0);
    add_boat_action(sc, 6.0, 1.0, 0.6, 12.0); /* then a turn through what is left */
    ww_state *st = ww_state_new(sc);
    for (int i = 0; i < 50; i++)
        for (int c = 0; c < 3; c++) st->cube_pos[3 * i + c] = sc->cubes.cube[i].position[c];
    ww_error err = {0};
    double vmax = sc->boat.max_speed * sqrt(1.0 + sc->boat.slip * sc->boat.slip);
    double worst_gap = 0.0, fastest_cube = 0.0, fastest_boat = 0.0;
    int pushed = 0;
    for (int64_t n = 1; n <= (int64_t)llround(14.0 / sc->dt); n++) {
        ENSURE(ww_step(sc, st, &err) == WW_OK); /* the NaN guard */
        fastest_boat = fmax(fastest_boat, hypot(st->boat_vel[0], st->boat_vel[2]));
        for (int i = 0; i < 50; i++) {
            const double *c = st->cube_pos + 3 * i, *v = st->cube_vel + 3 * i;
            double reach = sc->boat.radius + 0.5 * sc->cubes.cube[i].size;
            double d = hypot(c[0] - st->boat_pos[0], c[2] - st->boat_pos[2]);
            worst_gap = fmax(worst_gap, reach - d);
            double s = hypot(v[0], v[2]);
            fastest_cube = fmax(fastest_cube, s);
            pushed += s > 0.0;
        }
    }
    ENSURE_NEAR(fmax(worst_gap, 0.0), 0.0, PUSH_DISTANCE_TOL);
    ENSURE(fastest_boat <= vmax * (1.0 + 1e-12));
    ENSURE(fastest_cube <= 2.0 * vmax);
    ENSURE(pushed > 0);
    /* the cubes did not stop the arcade boat: it reached its cap */
    ENSURE(fastest_boat >= sc->boat.max_speed);
    ww_state_free(st);
    free(sc);
}

TEST(boat_seat_camera_at_the_bow_then_the_path_again) {
    ww_scene *sc = boat_scene();
    add_camera_action(sc, 1.0, 1);
    add_camera_action(sc, 2.0, 0);
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    const ww_boat_desc *b = &sc->boat;
    int64_t on = (int64_t)llround(1.0 / sc->dt), off = (int64_t)llround(2.0 / sc->dt);
    double pos[3], fwd[3], fov;
    ww_camera_eval(sc, 0.0, pos, fwd, &fov);
    double off0 = atan2(fwd[2], fwd[0]) - b->heading; /* the path looks along -z: -90 deg */
    for (int64_t n = 1; n <= off + 10; n++) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        ww_camera_eval(sc, st->t, pos, fwd, &fov);
        if (n >= on && n < off) {
            /* flat water: the seat is seat[0] ahead of the centre, seat[1] up */
            double h = st->boat_heading[0];
            ENSURE_NEAR(st->cam_pos[0], st->boat_pos[0] + b->seat[0] * cos(h), SEAT_TOL);
            ENSURE_NEAR(st->cam_pos[1], st->boat_pos[1] + b->seat[1], SEAT_TOL);
            ENSURE_NEAR(st->cam_pos[2], st->boat_pos[2] + b->seat[0] * sin(h), SEAT_TOL);
            double ahead = (st->cam_pos[0] - st->boat_pos[0]) * cos(h) +
                           (st->cam_pos[2] - st->boat_pos[2]) * sin(h);
            ENSURE(ahead > 0.0 && ahead <= 0.5 * b->length);
            /* the view eases from the path's heading: off0 e^(-t / look_time) since the last
             * free step */
            double t_free = (double)(on - 1) * sc->dt;
            double want = off0 * exp(-(st->t - t_free) / b->look_time);
            ENSURE_NEAR(st->boat_look_yaw[0] - h, want, LOOK_EASE_TOL);
            ENSURE_NEAR(st->cam_fwd[1], sin(b->look_pitch), SEAT_TOL);
        } else {
            for (int c = 0; c < 3; c++) {
                ENSURE_NEAR(st->cam_pos[c], pos[c], SEAT_TOL);
                ENSURE_NEAR(st->cam_fwd[c], fwd[c], SEAT_TOL);
            }
        }
    }
    ww_state_free(st);
    free(sc);
}

/* the outbox's events of one kind */
static int count_events(const ww_scene *sc, const ww_state *st, ww_sim_event_kind kind,
                        double *magnitude) {
    int n = 0;
    for (int i = 0; i < ww_events_count(sc, st); i++) {
        const double *e = st->events + i * WW_SIM_EVENT_STRIDE;
        if ((int)e[0] != (int)kind) continue;
        if (magnitude) *magnitude = e[5];
        n++;
    }
    return n;
}

TEST(boat_engine_events_and_until) {
    ww_scene *sc = boat_scene();
    add_boat_action(sc, 0.5, 0.8, 0.0, 3.0);
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    int64_t n_start = (int64_t)llround(0.5 / sc->dt), n_stop = (int64_t)llround(3.0 / sc->dt);
    int starts = 0, stops = 0;
    double v_stop = 0.0, mag = 0.0;
    for (int64_t n = 1; n <= n_stop + 120; n++) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        if (count_events(sc, st, WW_SE_BOAT_START, &mag)) {
            starts++;
            ENSURE_EQ_INT(n, n_start);
            ENSURE_NEAR(mag, 0.8, SEAT_TOL);
        }
        if (count_events(sc, st, WW_SE_BOAT_STOP, &mag)) {
            stops++;
            ENSURE_EQ_INT(n, n_stop);
            v_stop = st->boat_speed[0];
            ENSURE_NEAR(mag, v_stop, SEAT_TOL);
        }
    }
    ENSURE_EQ_INT(starts, 1);
    ENSURE_EQ_INT(stops, 1);
    /* the engine ran over [0.5, 3] s exactly: v = (a u / k) (1 - e^(-k 2.5)), then coasting
     * v e^(-k 1) (seed 000's drag alone) */
    double k = sc->boat.drag, v_inf = sc->boat.acceleration * 0.8 / k;
    ENSURE_NEAR(v_stop, v_inf * -expm1(-k * 2.5), BOAT_SPEED_REL_TOL * v_inf);
    ENSURE_NEAR(st->boat_speed[0], v_stop * exp(-k * 1.0), BOAT_SPEED_REL_TOL * v_stop);
    ww_state_free(st);
    free(sc);
}

/* a swell, cubes, a drive with turns and a camera switch */
static ww_scene *busy_scene(void) {
    ww_scene *sc = boat_scene();
    sc->wave_model = WW_WAVES_GERSTNER;
    double dir[2] = {10, -40}, L[2] = {25, 7}, A[2] = {0.3, 0.06};
    for (int i = 0; i < 2; i++) {
        ww_wave *w = &sc->waves[sc->nwaves++];
        *w = (ww_wave){.direction = ww_m_rad(dir[i]), .wavelength = L[i], .amplitude = A[i],
                       .steepness = 0.5};
        ww_wave_derive(w, 0.0);
    }
    sc->cubes.on = 1;
    ww_scene_plan_systems(sc);
    sc->cubes.count = 6;
    for (int i = 0; i < 6; i++)
        sc->cubes.cube[i] = (ww_cube_desc){.position = {3.0 + 2.0 * i, 0.0, 0.5 * (i % 3)},
                                           .size = 0.6, .density = 600.0};
    add_boat_action(sc, 0.2, 1.0, 0.3, 2.5);
    add_camera_action(sc, 1.0, 1);
    add_boat_action(sc, 2.5, -0.5, -1.0, 4.0);
    return sc;
}

TEST(boat_determinism_by_hash_and_snapshot) {
    ww_scene *sc = busy_scene();
    ww_state *a = ww_state_new(sc), *b = ww_state_new(sc), *c = ww_state_new(sc);
    ww_error err = {0};
    ENSURE(ww_sim_advance_to(sc, a, 600, &err) == WW_OK);
    ENSURE(ww_sim_advance_to(sc, b, 300, &err) == WW_OK);
    ww_state_copy(c, b); /* a --frames slice starts from a snapshot */
    ENSURE(ww_sim_advance_to(sc, b, 600, &err) == WW_OK);
    ENSURE(ww_sim_advance_to(sc, c, 600, &err) == WW_OK);
    uint64_t h = ww_state_hash(sc, a);
    ENSURE_EQ_U64(h, ww_state_hash(sc, b));
    ENSURE_EQ_U64(h, ww_state_hash(sc, c));
    ENSURE(a->boat_pos[0] != sc->boat.position[0]); /* it moved */

    /* and the hash sees the boat: another steer, another hash */
    sc->events[0].v[1] = 0.31;
    ww_state *d = ww_state_new(sc);
    ENSURE(ww_sim_advance_to(sc, d, 600, &err) == WW_OK);
    ENSURE(ww_state_hash(sc, d) != h);
    ww_state_free(a);
    ww_state_free(b);
    ww_state_free(c);
    ww_state_free(d);
    free(sc);
}

TEST(boat_step_allocates_nothing) {
    ww_scene *sc = busy_scene();
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    long before = ww_test_alloc_count();
    ENSURE(ww_sim_advance_to(sc, st, 500, &err) == WW_OK);
    ENSURE_EQ_INT(ww_test_alloc_count() - before, 0);
    ww_state_free(st);
    free(sc);
}

TEST(boat_frame_is_orthonormal_and_signed) {
    double f[3], u[3], r[3];
    ww_boat_frame(ww_m_rad(30), ww_m_rad(10), ww_m_rad(-5), f, u, r);
    ENSURE_NEAR(ww_m_dot3(f, f), 1.0, SEAT_TOL);
    ENSURE_NEAR(ww_m_dot3(u, u), 1.0, SEAT_TOL);
    ENSURE_NEAR(ww_m_dot3(r, r), 1.0, SEAT_TOL);
    ENSURE_NEAR(ww_m_dot3(f, u), 0.0, SEAT_TOL);
    ENSURE_NEAR(ww_m_dot3(f, r), 0.0, SEAT_TOL);
    ENSURE_NEAR(ww_m_dot3(u, r), 0.0, SEAT_TOL);
    ENSURE_NEAR(f[1], sin(ww_m_rad(10)), SEAT_TOL); /* bow up */
    ENSURE(r[1] > 0.0);                              /* roll < 0: starboard up */
    /* level at heading 90 deg: forward +z, starboard -x */
    ww_boat_frame(ww_m_rad(90), 0, 0, f, u, r);
    ENSURE_NEAR(f[2], 1.0, SEAT_TOL);
    ENSURE_NEAR(r[0], -1.0, SEAT_TOL);
}

/* ---- loader --------------------------------------------------------------------------------- */

static ww_scene *load(const char *text, ww_result *r, ww_error *err) {
    ww_scene *sc = NULL;
    *r = ww_scene_load_string("boat.yaml", text, strlen(text), NULL, 0, &sc, err);
    return sc;
}

TEST(boat_loader_reads_keys_and_actions) {
    const char *text = "time: {dt: 1/120, fps: 30, duration: 4}\n"
                       "objects:\n"
                       "  boat: {position: [1, 0.3, -2], heading: 90, radius: 2.5, turn_rate: 30,\n"
                       "         max_speed: 9, reverse_speed: 3, seat: [1, 1.1, 0.2]}\n"
                       "script:\n"
                       "  - {t: 0.5, boat: {throttle: 1, steer: -0.25, until: 2}}\n"
                       "  - {t: 1, camera: boat}\n"
                       "  - {t: 2.5, boat: {throttle: -0.5}}\n"
                       "  - {t: 3, camera: free}\n";
    ww_result r;
    ww_error err = {0};
    ww_scene *sc = load(text, &r, &err);
    ENSURE_MSG(r == WW_OK, "%s", err.msg);
    if (!sc) return;
    const ww_boat_desc *b = &sc->boat;
    ENSURE(b->on);
    ENSURE_NEAR(b->position[2], -2.0, SEAT_TOL);
    ENSURE_NEAR(b->heading, 0.5 * WW_PI, SEAT_TOL);
    ENSURE_NEAR(b->radius, 2.5, SEAT_TOL);
    ENSURE_NEAR(b->turn_rate, ww_m_rad(30), SEAT_TOL);
    ENSURE_NEAR(b->seat[2], 0.2, SEAT_TOL);
    ENSURE_NEAR(b->drag, 1.2, SEAT_TOL); /* seed 000's default */
    ENSURE_EQ_INT(sc->nevents, 4);
    ENSURE_EQ_INT(sc->events[0].kind, WW_EV_BOAT);
    ENSURE_NEAR(sc->events[0].v[0], 1.0, SEAT_TOL);
    ENSURE_NEAR(sc->events[0].v[1], -0.25, SEAT_TOL);
    ENSURE_NEAR(sc->events[0].v[2], 2.0, SEAT_TOL);
    ENSURE_EQ_INT(sc->events[0].flags, 1);
    ENSURE_EQ_INT(sc->events[1].kind, WW_EV_CAMERA_MODE);
    ENSURE_EQ_INT(sc->events[1].index, 1);
    ENSURE_EQ_INT(sc->events[2].flags, 0); /* no until: holds until the next action */
    ENSURE_EQ_INT(sc->events[3].index, 0);
    ww_scene_free(sc);

    /* an action alone puts a default boat in; `camera: free` alone does not */
    sc = load("script:\n  - {t: 1, boat: {throttle: 0.5}}\n", &r, &err);
    ENSURE_MSG(r == WW_OK, "%s", err.msg);
    if (sc) {
        ENSURE(sc->boat.on);
        ENSURE_NEAR(sc->boat.acceleration, 6.0, SEAT_TOL);
        ww_scene_free(sc);
    }
    sc = load("script:\n  - {t: 1, camera: free}\n", &r, &err);
    ENSURE_MSG(r == WW_OK, "%s", err.msg);
    if (sc) {
        ENSURE(!sc->boat.on);
        ww_state *st = run_to(sc, 2.0); /* the action finds no boat and does nothing */
        ww_state_free(st);
        ww_scene_free(sc);
    }
}
