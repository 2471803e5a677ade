/* test_reef.c - the treasure chest, air bubbles and camera collision (sim/chest.h, bubbles.h,
 * collide.h) against their rules and closed forms: spawn schedule, lifetime, the disc of spawn
 * places (uniform, edge included), collection within reach; bubbles rising at their speed,
 * zigzagging at their frequency, bursting at the exact surface and released again; the camera
 * held at the grown surface of a cube, the boat and a model, logged once, and passing through
 * with camera.collide false. Scenes are loaded from YAML text (the loader is part of the test).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "core/rng.h"
#include "sim/bubbles.h"
#include "sim/camera.h"
#include "sim/chest.h"
#include "sim/collide.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "test.h"

/* an event due at t fires on the first step at or after t: within one step of 1/120 s */
#define EVENT_STEP_TOL (1.0 / 120.0 + 1e-9)
/* a spawn place at the edge of the disc, measured from an anchor at (100, -50): a few ulps of
 * the coordinates */
#define CHEST_EDGE_TOL 1e-13
/* mean r^2 / R^2 of 4000 uniform points on the disc is 1/2; one standard error is
 * 0.289 / sqrt(4000) = 0.0046: five of them */
#define DISC_MEAN_TOL 0.023
/* the camera's distance to a solid against the margin (near clip): rounding of the slab test */
#define COLLIDE_MARGIN_TOL 1e-9
/* a bubble's measured rise speed against its band speed (0.9..1.1): rounding of y(t) */
#define RISE_SPEED_TOL 1e-9
/* a bubble's lateral offset against its wobble amplitude: rounding */
#define WOBBLE_TOL 1e-12

static ww_scene *load(const char *text) { return ww_test_scene_text("reef.yaml", text); }

/* events of kind k in the step's outbox; the last one's entry in *last */
static int count_events(const ww_scene *sc, const ww_state *st, int kind, const double **last) {
    int n = 0;
    for (int i = 0; i < ww_events_count(sc, st); i++) {
        const double *e = st->events + i * WW_SIM_EVENT_STRIDE;
        if ((int)e[0] != kind) continue;
        n++;
        if (last) *last = e;
    }
    return n;
}

/* ---- chest ----------------------------------------------------------------------------------- */

TEST(reef_chest_spawns_at_first_expires_after_ttl_and_respawns_every) {
    ww_scene *sc = load("time: {dt: 1/120, fps: 30, duration: 14}\n"
                        "water: {depth: 6, waves: {model: flat}}\n"
                        "objects: {chest: {first: 2, every: 5, ttl: 1.5, radius: 12, near: camera,"
                        " reach: 0.5}}\n"
                        "camera: {path: [{t: 0, position: [3, 40, -7], yaw: 0, pitch: -30}]}\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    double spawns[8], expires[8];
    int ns = 0, ne = 0;
    while (st->t < 13.0) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        const double *e = NULL;
        if (count_events(sc, st, WW_SE_CHEST_SPAWN, &e) && ns < 8) {
            spawns[ns++] = st->t;
            /* within the radius of the camera (the anchor), on the seabed */
            ENSURE(hypot(e[2] - 3.0, e[4] + 7.0) <= 12.0);
            ENSURE_NEAR(e[3], -6.0, 0.0);
            ENSURE_NEAR(e[5], 1.5, 0.0);
            ENSURE(st->chest_state[0] == 1.0);
        }
        if (count_events(sc, st, WW_SE_CHEST_EXPIRE, NULL) && ne < 8) {
            expires[ne++] = st->t;
            ENSURE(st->chest_state[0] == 0.0);
        }
        ENSURE(count_events(sc, st, WW_SE_CHEST_COLLECT, NULL) == 0);
    }
    ENSURE_EQ_INT(ns, 3);
    ENSURE_EQ_INT(ne, 2);
    for (int i = 0; i < ns && i < 3; i++) ENSURE_NEAR(spawns[i], 2.0 + 5.0 * i, EVENT_STEP_TOL);
    for (int i = 0; i < ne && i < 2; i++) ENSURE_NEAR(expires[i], 3.5 + 5.0 * i, EVENT_STEP_TOL);
    ENSURE(st->chest_state[0] == 1.0); /* the third, spawned at 12, lives to 13.5 */
    ENSURE(st->prizes[0] == 0.0);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(reef_chest_places_fill_the_disc_and_its_edge) {
    /* the edge itself: u1 = 1 at every angle, and a zero radius */
    const double us[] = {0.0, 0.125, 0.25, 0.3, 0.5, 0.75, 0.999999999, 1.0};
    for (size_t i = 0; i < sizeof us / sizeof us[0]; i++) {
        double p[2];
        ww_chest_place(100.0, -50.0, 12.0, 1.0, us[i], p);
        ENSURE(isfinite(p[0]) && isfinite(p[1]));
        double r = hypot(p[0] - 100.0, p[1] + 50.0);
        ENSURE(r <= 12.0 + CHEST_EDGE_TOL);
        ENSURE_NEAR(r, 12.0, CHEST_EDGE_TOL);
        ww_chest_place(100.0, -50.0, 0.0, 1.0, us[i], p);
        ENSURE(p[0] == 100.0 && p[1] == -50.0);
    }

    /* uniform over the disc: E[r^2] = R^2 / 2, every point inside (the seed's square has
     * corners at 1.41 R) */
    double sum = 0.0, rmax = 0.0;
    const int n = 4000;
    for (int i = 0; i < n; i++) {
        double p[2];
        ww_chest_place(0.0, 0.0, 12.0, ww_rng_draw(9, WW_RNG_CHEST, (uint64_t)i, 0),
                       ww_rng_draw(9, WW_RNG_CHEST, (uint64_t)i, 1), p);
        double r = hypot(p[0], p[1]);
        sum += r * r / 144.0;
        if (r > rmax) rmax = r;
    }
    ENSURE_NEAR(sum / n, 0.5, DISC_MEAN_TOL);
    ENSURE(rmax <= 12.0 && rmax > 11.9);
}

/* the camera flies 0.9 m (or 1.6 m) over a chest forced at (5, 0) at t = 0.5 */
static void chest_flyover(double height, int *collected, double *prizes, double *dist_at) {
    char text[1024];
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 4}\n"
             "water: {depth: 4, waves: {model: flat}}\n"
             "objects: {chest: {reach: 1, size: [0.9, 0.6, 0.6]}}\n"
             "camera: {interpolation: linear, path: [{t: 0, position: [-5, %g, 0], yaw: 90},"
             " {t: 4, position: [15, %g, 0], yaw: 90}]}\n"
             "script: [{t: 0.5, chest: {at: [5, 0]}}]\n",
             -3.4 + height, -3.4 + height);
    ww_scene *sc = load(text);
    *collected = -1;
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    *collected = 0;
    *dist_at = -1.0;
    double prev_cam[3] = {0};
    while (st->t < 4.0) {
        for (int a = 0; a < 3; a++) prev_cam[a] = st->cam_pos[a];
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        const double *e = NULL;
        if (count_events(sc, st, WW_SE_CHEST_COLLECT, &e)) {
            (*collected)++;
            ENSURE_NEAR(e[5], st->prizes[0], 0.0);
            *dist_at = ww_chest_distance(sc->chest.size, st->chest_pos, prev_cam);
        }
    }
    *prizes = st->prizes[0];
    ENSURE(st->chest_state[0] == (*collected ? 0.0 : 1.0));
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(reef_chest_collected_when_the_camera_passes_within_reach) {
    int n;
    double prizes, d;
    chest_flyover(0.9, &n, &prizes, &d);
    ENSURE_EQ_INT(n, 1);
    ENSURE(prizes == 1.0);
    ENSURE(d <= 1.0 && d > 0.9 - 1e-9); /* the box's top is 0.9 below the path */
    chest_flyover(1.6, &n, &prizes, &d);
    ENSURE_EQ_INT(n, 0);
    ENSURE(prizes == 0.0);
}

/* ---- bubbles --------------------------------------------------------------------------------- */

typedef struct bubble_run {
    int releases;        /* slots (re)filled after step 0 */
    int bursts;          /* bubbles that reached the surface */
    double max_lateral;  /* largest offset from the vent's vertical, m */
    double max_over;     /* largest top - surface of a rising bubble (must stay < 0), m */
    double min_speed, max_speed; /* measured dy/dt over speed */
    double min_burst_top;/* lowest top - surface on the step before a burst (flat water), m */
    int crossings;       /* sign changes of one bubble's lateral offset over its rise */
    double rise_time;    /* that bubble's time from release to burst, s */
} bubble_run;

static void run_bubbles(const char *water, double seconds, bubble_run *out) {
    char text[1024];
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 30}\n"
             "water: %s\n"
             "objects: {bubbles: [{at: [1, -3, 2], rate: 2, speed: 0.5, wobble: 0.05,"
             " frequency: 1.5, size: 0.01, count: 16}]}\n",
             water);
    ww_scene *sc = load(text);
    *out = (bubble_run){.min_speed = 1e9, .max_over = -1e9, .min_burst_top = 1e9};
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    const int nb = sc->bubbles.total;
    double prev_y[64], prev_t0[64], prev_on[64], prev_top_gap[64], prev_s[64];
    int tracked = -1;
    double tracked_t0 = 0.0;
    for (int b = 0; b < nb; b++) {
        prev_y[b] = st->bubble_pos[3 * b + 1];
        prev_t0[b] = st->bubble_t0[b];
        prev_on[b] = st->bubble_on[b];
        prev_top_gap[b] = 0.0;
        prev_s[b] = 0.0;
    }
    while (st->t < seconds) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        for (int b = 0; b < nb; b++) {
            const double *p = st->bubble_pos + 3 * b;
            int fresh = st->bubble_on[b] != 0.0 && st->bubble_t0[b] != prev_t0[b];
            if (fresh) out->releases++;
            if (prev_on[b] != 0.0 && st->bubble_on[b] == 0.0) {
                out->bursts++;
                out->min_burst_top = fmin(out->min_burst_top, prev_top_gap[b]);
                if (b == tracked) {
                    out->rise_time = st->t - tracked_t0;
                    tracked = -2;
                }
            }
            if (prev_on[b] != 0.0 && st->bubble_on[b] == 0.0 && fresh) out->bursts++;
            if (st->bubble_on[b] == 0.0) {
                prev_on[b] = 0.0;
                continue;
            }
            ww_water_sample w;
            ww_water_at(sc, st, p[0], p[2], 0.0, &w);
            double gap = p[1] + st->bubble_radius[b] - w.height;
            out->max_over = fmax(out->max_over, gap);
            double lat = hypot(p[0] - 1.0, p[2] - 2.0);
            out->max_lateral = fmax(out->max_lateral, lat);
            /* signed offset along the bubble's plane */
            double s = (p[0] - 1.0) * cos(st->bubble_wobble[2 * b + 1]) +
                       (p[2] - 2.0) * sin(st->bubble_wobble[2 * b + 1]);
            if (!fresh && prev_on[b] != 0.0) {
                double v = (p[1] - prev_y[b]) / sc->dt / 0.5;
                out->min_speed = fmin(out->min_speed, v);
                out->max_speed = fmax(out->max_speed, v);
                if (b == tracked && s * prev_s[b] < 0.0) out->crossings++;
            }
            if (fresh && tracked == -1 && st->t > 1.0) {
                tracked = b;
                tracked_t0 = st->bubble_t0[b];
            }
            prev_y[b] = p[1];
            prev_t0[b] = st->bubble_t0[b];
            prev_on[b] = 1.0;
            prev_top_gap[b] = gap;
            prev_s[b] = s;
        }
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(reef_bubbles_rise_wobble_burst_at_flat_surface_and_are_released_again) {
    bubble_run r;
    run_bubbles("{waves: {model: flat}}", 20.0, &r);
    /* rise speed within the +-10% band of speed */
    ENSURE(r.min_speed >= 0.9 - RISE_SPEED_TOL && r.max_speed <= 1.1 + RISE_SPEED_TOL);
    ENSURE(r.max_speed - r.min_speed > 0.05); /* the bubbles differ */
    /* the zigzag stays within its amplitude and reaches most of it */
    ENSURE(r.max_lateral <= 0.05 + WOBBLE_TOL && r.max_lateral > 0.045);
    /* 1.5 Hz over the rise time: two sign changes per period (+-1 at the ends) */
    ENSURE(r.rise_time > 0.0);
    ENSURE(fabs(r.crossings - 2.0 * 1.5 * r.rise_time) <= 1.5);
    /* 3 m at 0.45..0.55 m/s: 5.5..6.7 s; 2 per second fill 11..14 of the 16 slots */
    ENSURE(r.rise_time > 3.0 / 0.55 - 0.02 && r.rise_time < 3.0 / 0.45 + 0.02);
    /* releases at the rate (40 in 20 s, +-1), bursts keep up after the first rise */
    ENSURE(abs(r.releases - 40) <= 1);
    ENSURE(r.bursts >= 30);
    /* never above the surface; burst within one step's rise of it */
    ENSURE(r.max_over < 0.0);
    ENSURE(r.min_burst_top >= -1.1 * 0.5 / 120.0 - RISE_SPEED_TOL);
}

TEST(reef_bubbles_never_above_a_wavy_surface) {
    bubble_run r;
    run_bubbles("{waves: {model: gerstner, list: [{direction: 30, wavelength: 6, amplitude: 0.4,"
                " steepness: 0.6}, {direction: -50, wavelength: 2.5, amplitude: 0.1,"
                " steepness: 0.5}]}}",
                15.0, &r);
    ENSURE(r.max_over < 0.0);
    ENSURE(r.bursts >= 10);
    ENSURE(abs(r.releases - 30) <= 1);
}

/* ---- camera collision ------------------------------------------------------------------------ */

/* distance from p to the box of half extents h at c turned by the unit quaternion q (zero: no
 * turn), written out independently of collide.c: p - c rotated by the conjugate as a matrix */
static double box_distance(const double c[3], const double q_in[4], const double h[3],
                           const double p[3]) {
    double q[4] = {1, 0, 0, 0};
    double n = sqrt(q_in[0] * q_in[0] + q_in[1] * q_in[1] + q_in[2] * q_in[2] + q_in[3] * q_in[3]);
    if (n > 0)
        for (int a = 0; a < 4; a++) q[a] = q_in[a] / n;
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    double d[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]}, s = 0;
    for (int a = 0; a < 3; a++) {
        double l = R[0][a] * d[0] + R[1][a] * d[1] + R[2][a] * d[2]; /* R^T d */
        double o = fabs(l) - h[a];
        if (o > 0) s += o * o;
    }
    return sqrt(s);
}

typedef struct fly {
    int blocked;        /* camera_blocked events */
    int what;           /* aux of the last one */
    double min_dist;    /* smallest distance camera - solid over the run, m */
    int rejoined;       /* at the end the camera is on its path again (its path ends behind the
                         * solid: a camera that stops or slides never gets there) */
} fly;

enum { FLY_CUBE, FLY_BOAT, FLY_MODEL };

/* the camera flies along x through a solid at the origin, 4 m in 2 s, at y, z */
static void fly_through(int solid, int collide, double y, double z, fly *out) {
    char text[1024];
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 3}\n"
             "water: {waves: {model: flat}}\n"
             "objects: {models: [%s]}\n"
             "camera: {collide: %s, near: 0.1, interpolation: linear, path: [{t: 0.5, position:"
             " [-4, %g, %g], yaw: 90}, {t: 2.5, position: [4, %g, %g], yaw: 90}]}\n",
             solid == FLY_MODEL ? "{name: rock, min: [-1, -0.5, -1.5], max: [1, 0.5, 1.5]}" : "",
             collide ? "true" : "false", y, z, y, z);
    ww_scene *sc = load(text);
    *out = (fly){.min_dist = 1e9, .what = -1};
    if (!sc) return;
    /* the cube and the boat are other systems' sections: set their descriptions by hand */
    if (solid == FLY_CUBE) {
        sc->cubes.on = 1;
        ww_scene_plan_systems(sc);
        sc->cubes.count = 1;
        sc->cubes.cube[0] = (ww_cube_desc){.position = {0, 0, 0}, .size = 1.0, .density = 500};
    } else if (solid == FLY_BOAT) {
        sc->boat.on = 1;
        ww_scene_plan_systems(sc);
        sc->boat.radius = 1.5;
    }
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    while (st->t < 3.0) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        double d;
        if (solid == FLY_CUBE) {
            double h[3] = {0.5, 0.5, 0.5};
            d = box_distance(st->cube_pos, st->cube_rot, h, st->cam_pos);
        } else if (solid == FLY_BOAT) {
            double v[3];
            ww_m_sub3(st->cam_pos, st->boat_pos, v);
            d = ww_m_len3(v) - 1.5;
            if (d < 0) d = 0;
        } else {
            double c[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0}, h[3] = {1, 0.5, 1.5};
            d = box_distance(c, q, h, st->cam_pos);
        }
        out->min_dist = fmin(out->min_dist, d);
        const double *e = NULL;
        int n = count_events(sc, st, WW_SE_CAMERA_BLOCKED, &e);
        out->blocked += n;
        if (n) out->what = (int)e[6];
    }
    double p[3], f[3], fov;
    ww_camera_eval(sc, st->t, p, f, &fov);
    out->rejoined = p[0] == st->cam_pos[0] && p[1] == st->cam_pos[1] && p[2] == st->cam_pos[2];
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(reef_camera_is_held_at_a_cube_logged_once_and_passes_without_collide) {
    fly f;
    fly_through(FLY_CUBE, 1, 0.0, 0.0, &f);
    ENSURE(f.min_dist >= 0.1 - COLLIDE_MARGIN_TOL);
    ENSURE_EQ_INT(f.blocked, 1);
    ENSURE_EQ_INT(f.what, WW_SOLID_CUBE);
    ENSURE(!f.rejoined); /* held at the near face: it never passes to the path's far end */
    fly_through(FLY_CUBE, 0, 0.0, 0.0, &f);
    ENSURE(f.min_dist == 0.0);
    ENSURE_EQ_INT(f.blocked, 0);
}

TEST(reef_camera_is_held_at_the_boat_logged_once_and_passes_without_collide) {
    fly f;
    fly_through(FLY_BOAT, 1, 0.2, 0.3, &f);
    ENSURE(f.min_dist >= 0.1 - COLLIDE_MARGIN_TOL);
    ENSURE_EQ_INT(f.blocked, 1);
    ENSURE_EQ_INT(f.what, WW_SOLID_BOAT);
    fly_through(FLY_BOAT, 0, 0.2, 0.3, &f);
    ENSURE(f.min_dist == 0.0);
    ENSURE_EQ_INT(f.blocked, 0);
}

TEST(reef_camera_is_held_at_a_model_grazing_or_head_on) {
    fly f;
    fly_through(FLY_MODEL, 1, 0.0, 0.0, &f);
    ENSURE(f.min_dist >= 0.1 - COLLIDE_MARGIN_TOL);
    ENSURE_EQ_INT(f.blocked, 1);
    ENSURE_EQ_INT(f.what, WW_SOLID_MODEL);
    ENSURE(!f.rejoined);
    /* through the grown margin only (0.05 m inside it), and just outside it */
    fly_through(FLY_MODEL, 1, 0.0, 1.55, &f);
    ENSURE(f.min_dist >= 0.1 - COLLIDE_MARGIN_TOL);
    ENSURE_EQ_INT(f.blocked, 1);
    fly_through(FLY_MODEL, 1, 0.0, 1.65, &f);
    ENSURE_NEAR(f.min_dist, 0.15, COLLIDE_MARGIN_TOL);
    ENSURE_EQ_INT(f.blocked, 0);
    fly_through(FLY_MODEL, 0, 0.0, 0.0, &f);
    ENSURE(f.min_dist == 0.0);
    ENSURE_EQ_INT(f.blocked, 0);
}

/* ---- determinism ----------------------------------------------------------------------------- */

static const char *REEF_ALL =
    "seed: 11\n"
    "time: {dt: 1/120, fps: 30, duration: 6}\n"
    "water: {depth: 5, waves: {model: gerstner, list: [{direction: 10, wavelength: 8,"
    " amplitude: 0.3, steepness: 0.5}]}}\n"
    "objects:\n"
    "  chest: {first: 1, every: 2, ttl: 1, radius: 6, near: camera}\n"
    "  bubbles: [{at: [0, -4, 0]}, {at: [2, -4.5, 1], rate: 5, count: 32}]\n"
    "  models: [{name: rock, min: [-1, -5, -1], max: [1, -3, 1]}]\n"
    "camera: {path: [{t: 0, position: [-6, -3.5, 0], yaw: 90}, {t: 6, position: [6, -3.5, 0],"
    " yaw: 90}]}\n"
    "script: [{t: 2.5, chest: {}}, {t: 3, chest: {at: [1, 1]}}]\n";

TEST(reef_runs_are_equal_copies_continue_and_steps_allocate_nothing) {
    ww_scene *sc = load(REEF_ALL);
    if (!sc) return;
    ww_state *a = ww_state_new(sc), *b = ww_state_new(sc), *c = ww_state_new(sc);
    ww_error err = {0};
    long before = ww_test_alloc_count();
    ENSURE(ww_sim_advance_to(sc, a, 720, &err) == WW_OK);
    ENSURE_EQ_INT(ww_test_alloc_count() - before, 0);
    ENSURE(ww_sim_advance_to(sc, b, 300, &err) == WW_OK);
    ww_state_copy(c, b);
    ENSURE(ww_sim_advance_to(sc, b, 720, &err) == WW_OK);
    ENSURE(ww_sim_advance_to(sc, c, 720, &err) == WW_OK);
    ENSURE_EQ_U64(ww_state_hash(sc, a), ww_state_hash(sc, b));
    ENSURE_EQ_U64(ww_state_hash(sc, a), ww_state_hash(sc, c));
    ENSURE(a->prizes[0] >= 0.0 && a->chest_state[0] >= 0.0);
    ww_state_free(a);
    ww_state_free(b);
    ww_state_free(c);
    ww_scene_free(sc);
}

/* the chest's draws are its own stream: removing the bubbles moves no chest */
TEST(reef_chest_places_do_not_depend_on_the_bubbles) {
    ww_scene *with = load(REEF_ALL);
    if (!with) return;
    ww_scene *without = load(REEF_ALL);
    without->bubbles = (ww_bubbles_desc){0};
    ww_state *a = ww_state_new(with), *b = ww_state_new(without);
    ww_error err = {0};
    int spawns = 0;
    for (int i = 0; i < 720; i++) {
        ww_step(with, a, &err);
        ww_step(without, b, &err);
        const double *ea = NULL, *eb = NULL;
        int na = count_events(with, a, WW_SE_CHEST_SPAWN, &ea);
        ENSURE_EQ_INT(na, count_events(without, b, WW_SE_CHEST_SPAWN, &eb));
        if (na && ea && eb) {
            spawns++;
            ENSURE(ea[2] == eb[2] && ea[4] == eb[4]);
        }
    }
    ENSURE(spawns >= 4);
    ww_state_free(a);
    ww_state_free(b);
    ww_scene_free(with);
    ww_scene_free(without);
}
