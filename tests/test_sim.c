/* test_sim.c - the simulation against closed forms and finite differences: Gerstner surface and
 * normals, phase precision at large t, camera interpolation, sun path, determinism, no allocation
 * while stepping, the NaN guard. Scenes are built by hand here (no loader needed).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "sim/camera.h"
#include "sim/sky.h"
#include "sim/state.h"
#include "sim/events.h"
#include "sim/step.h"
#include "sim/systems.h"
#include "sim/waves.h"
#include "test.h"

/* finite-difference normal of the displaced surface against the analytic one */
#define NORMAL_FD_TOL 1e-6
/* closed form of one wave against the summed evaluation */
#define WAVE_CLOSED_FORM_TOL 1e-12
/* wrapped phase at t = 1e6 s against a long double reference: a few ulps of 2 pi * 1e6 */
#define PHASE_LARGE_T_TOL 1e-9
/* interpolated camera against the hand-computed value */
#define CAMERA_TOL 1e-12
/* sun direction components */
#define SUN_DIR_TOL 1e-12

/* the file format's defaults with a short clock: noon, 1 s of frames at 256x144 */
static ww_scene *hand_scene(void) {
    ww_scene *sc = malloc(sizeof *sc);
    ww_scene_defaults(sc);
    snprintf(sc->path, sizeof sc->path, "hand.yaml");
    sc->duration = 1;
    sc->frame_count = 30;
    sc->width = 256;
    sc->height = 144;
    sc->time_of_day = 12;
    sc->far_clip = 1000;
    return sc;
}

static void add_wave(ww_scene *sc, double dir_deg, double L, double A, double Q) {
    ww_wave *w = &sc->waves[sc->nwaves++];
    *w = (ww_wave){.direction = ww_m_rad(dir_deg), .wavelength = L, .amplitude = A, .steepness = Q};
    ww_wave_derive(w, 0.0);
    sc->wave_model = WW_WAVES_GERSTNER;
}

TEST(sim_waves_flat_sea_is_level_and_up) {
    ww_scene *sc = hand_scene();
    sc->water_level = 1.5;
    double p[3], n[3];
    ww_waves_eval(sc, NULL, 3, -4, p, n);
    ENSURE_NEAR(p[0], 3, WAVE_CLOSED_FORM_TOL);
    ENSURE_NEAR(p[1], 1.5, WAVE_CLOSED_FORM_TOL);
    ENSURE_NEAR(p[2], -4, WAVE_CLOSED_FORM_TOL);
    ENSURE_NEAR(n[1], 1, WAVE_CLOSED_FORM_TOL);
    free(sc);
}

TEST(sim_waves_single_gerstner_matches_closed_form) {
    ww_scene *sc = hand_scene();
    add_wave(sc, 30, 12, 0.25, 0.6);
    double ph[1], p[3];
    double t = 3.7, x = 2.5, z = -1.25;
    ww_waves_phases(sc, t, ph);
    ww_waves_eval(sc, ph, x, z, p, NULL);
    const ww_wave *w = &sc->waves[0];
    double phi = w->k * (w->dir[0] * x + w->dir[1] * z) - w->omega * t;
    ENSURE_NEAR(p[0], x + 0.6 * 0.25 * w->dir[0] * cos(phi), WAVE_CLOSED_FORM_TOL);
    ENSURE_NEAR(p[1], 0.25 * sin(phi), WAVE_CLOSED_FORM_TOL);
    ENSURE_NEAR(p[2], z + 0.6 * 0.25 * w->dir[1] * cos(phi), WAVE_CLOSED_FORM_TOL);
    /* deep-water dispersion: phase speed sqrt(g L / 2 pi) */
    ENSURE_NEAR(w->speed, sqrt(WW_G * 12 / WW_TAU), WAVE_CLOSED_FORM_TOL);
    free(sc);
}

TEST(sim_waves_analytic_normal_matches_finite_differences) {
    ww_scene *sc = hand_scene();
    add_wave(sc, 20, 12, 0.25, 0.6);
    add_wave(sc, -35, 5, 0.08, 0.4);
    add_wave(sc, 110, 2.5, 0.03, 0.8);
    double ph[3];
    ww_waves_phases(sc, 1.25, ph);
    for (int s = 0; s < 20; s++) {
        double x = -7.0 + 0.77 * s, z = 3.0 - 0.41 * s, e = 1e-5;
        double p[3], n[3], px0[3], px1[3], pz0[3], pz1[3], dx[3], dz[3], fd[3];
        ww_waves_eval(sc, ph, x, z, p, n);
        ww_waves_eval(sc, ph, x - e, z, px0, NULL);
        ww_waves_eval(sc, ph, x + e, z, px1, NULL);
        ww_waves_eval(sc, ph, x, z - e, pz0, NULL);
        ww_waves_eval(sc, ph, x, z + e, pz1, NULL);
        ww_m_sub3(px1, px0, dx);
        ww_m_sub3(pz1, pz0, dz);
        fd[0] = dz[1] * dx[2] - dz[2] * dx[1];
        fd[1] = dz[2] * dx[0] - dz[0] * dx[2];
        fd[2] = dz[0] * dx[1] - dz[1] * dx[0];
        ww_m_normalize3(fd);
        for (int c = 0; c < 3; c++) ENSURE_NEAR(n[c], fd[c], NORMAL_FD_TOL);
        ENSURE(n[1] > 0);
    }
    free(sc);
}

TEST(sim_waves_phase_stays_exact_at_large_time) {
    ww_scene *sc = hand_scene();
    add_wave(sc, 0, 7.3, 0.1, 0.5);
    sc->waves[0].phase = 0.3;
    double t = 1e6, ph[1];
    ww_waves_phases(sc, t, ph);
    long double ref = fmodl(0.3L - (long double)sc->waves[0].omega * (long double)t, 6.283185307179586476925L);
    if (ref < 0) ref += 6.283185307179586476925L;
    ENSURE(ph[0] >= 0 && ph[0] < WW_TAU);
    ENSURE_NEAR(ph[0], (double)ref, PHASE_LARGE_T_TOL);
    free(sc);
}

TEST(sim_camera_linear_and_catmull_rom_pass_through_keys) {
    ww_scene *sc = hand_scene();
    sc->ncam = 3;
    sc->cam[0] = (ww_camera_key){.t = 0, .position = {0, 2, 10}, .has_look_at = 1, .look_at = {0, 0, 0}};
    sc->cam[1] = (ww_camera_key){.t = 2, .position = {4, 2, 6}, .has_look_at = 1, .look_at = {0, 0, 0}};
    sc->cam[2] = (ww_camera_key){.t = 6, .position = {8, 4, 0}, .has_look_at = 1, .look_at = {0, 1, 0}};
    double pos[3], fwd[3], fov;
    for (int mode = 0; mode < 2; mode++) {
        sc->interp = mode ? WW_INTERP_LINEAR : WW_INTERP_CATMULL_ROM;
        ww_camera_eval(sc, 2.0, pos, fwd, &fov);
        ENSURE_NEAR(pos[0], 4, CAMERA_TOL);
        ENSURE_NEAR(pos[2], 6, CAMERA_TOL);
        /* the target is interpolated: between two keys aiming at the origin, a linear camera
         * keeps looking at it; at a key both modes aim exactly at the key's target */
        ww_camera_eval(sc, mode ? 1.0 : 2.0, pos, fwd, &fov);
        double d[3] = {-pos[0], -pos[1], -pos[2]};
        ww_m_normalize3(d);
        for (int c = 0; c < 3; c++) ENSURE_NEAR(fwd[c], d[c], CAMERA_TOL);
        ENSURE_NEAR(fov, sc->fov, CAMERA_TOL);
        /* holds outside the path */
        ww_camera_eval(sc, 100.0, pos, fwd, &fov);
        ENSURE_NEAR(pos[1], 4, CAMERA_TOL);
        ww_camera_eval(sc, -5.0, pos, fwd, &fov);
        ENSURE_NEAR(pos[2], 10, CAMERA_TOL);
    }
    /* linear midpoint is the average; Catmull-Rom differs there (it is curved) */
    sc->interp = WW_INTERP_LINEAR;
    ww_camera_eval(sc, 1.0, pos, fwd, &fov);
    ENSURE_NEAR(pos[0], 2, CAMERA_TOL);
    sc->interp = WW_INTERP_CATMULL_ROM;
    ww_camera_eval(sc, 1.0, pos, fwd, &fov);
    ENSURE(fabs(pos[0] - 2) > 1e-3);
    free(sc);
}

TEST(sim_camera_catmull_rom_is_c1_at_keys) {
    ww_scene *sc = hand_scene();
    sc->ncam = 3;
    sc->cam[0] = (ww_camera_key){.t = 0, .position = {0, 2, 10}, .yaw = 0};
    sc->cam[1] = (ww_camera_key){.t = 1, .position = {4, 3, 6}, .yaw = 0.5};
    sc->cam[2] = (ww_camera_key){.t = 4, .position = {8, 2, 0}, .yaw = 1.0};
    double a[3], b[3], c[3], f[3], fov, e = 1e-6;
    ww_camera_eval(sc, 1 - e, a, f, &fov);
    ww_camera_eval(sc, 1, b, f, &fov);
    ww_camera_eval(sc, 1 + e, c, f, &fov);
    /* left and right velocities agree to the finite-difference error */
    for (int k = 0; k < 3; k++) ENSURE_NEAR((b[k] - a[k]) / e, (c[k] - b[k]) / e, 1e-4);
    free(sc);
}

TEST(sim_camera_yaw_turns_the_short_way) {
    ww_scene *sc = hand_scene();
    sc->ncam = 2;
    sc->interp = WW_INTERP_LINEAR;
    sc->cam[0] = (ww_camera_key){.t = 0, .position = {0, 2, 0}, .yaw = ww_m_rad(170)};
    sc->cam[1] = (ww_camera_key){.t = 2, .position = {0, 2, 0}, .yaw = ww_m_rad(-170)};
    double p[3], f[3], fov, want[3];
    ww_camera_eval(sc, 1.0, p, f, &fov);
    ww_camera_dir(WW_PI, 0, want); /* 180 degrees, not 0 */
    for (int c = 0; c < 3; c++) ENSURE_NEAR(f[c], want[c], CAMERA_TOL);
    free(sc);
}

TEST(sim_sky_sun_path_follows_the_clock) {
    double d[3];
    ww_sky_sun_dir(6.0, ww_m_rad(60), d); /* sunrise in the east */
    ENSURE_NEAR(d[0], 1, SUN_DIR_TOL);
    ENSURE_NEAR(d[1], 0, SUN_DIR_TOL);
    ww_sky_sun_dir(12.0, ww_m_rad(60), d); /* noon: max elevation, toward -z */
    ENSURE_NEAR(asin(d[1]), ww_m_rad(60), SUN_DIR_TOL);
    ENSURE(d[2] < 0);
    ww_sky_sun_dir(18.0, ww_m_rad(60), d);
    ENSURE_NEAR(d[0], -1, SUN_DIR_TOL);
    double sun[3], z[3], h[3], a[3];
    ww_sky_sun_dir(0.0, ww_m_rad(60), d); /* midnight: no sun, dark sky */
    ww_sky_colors(d, sun, z, h, a);
    ENSURE_NEAR(sun[0] + sun[1] + sun[2], 0, 1e-12);
    ENSURE(z[2] < 0.05);
    ww_sky_sun_dir(12.0, ww_m_rad(60), d); /* noon: blue zenith, white-ish sun */
    ww_sky_colors(d, sun, z, h, a);
    ENSURE(z[2] > z[0]);
    ENSURE(sun[0] > 1.0 && sun[2] > 0.5 * sun[0]);
    ww_sky_sun_dir(17.8, ww_m_rad(60), d); /* low sun: reddened */
    ww_sky_colors(d, sun, z, h, a);
    ENSURE(sun[0] > 2 * sun[2]);
}

TEST(sim_clock_advances_by_day_length_and_events_reset_it) {
    ww_scene *sc = hand_scene();
    sc->day_length = 240; /* 24 h in 240 s: 0.1 h per s */
    sc->time_of_day = 6;
    sc->nevents = 1;
    sc->events[0] = (ww_event){.t = 2.0, .step = 240, .kind = WW_EV_TIME_OF_DAY, .value = 20};
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    ENSURE(ww_sim_advance_to(sc, st, 120, &err) == WW_OK); /* t = 1 s */
    ENSURE_NEAR(st->time_of_day[0], 6.1, 1e-12);
    ENSURE(ww_sim_advance_to(sc, st, 360, &err) == WW_OK); /* 1 s after the event */
    ENSURE_NEAR(st->time_of_day[0], 20.1, 1e-12);
    ENSURE_EQ_INT(st->event_next, 1);
    ww_state_free(st);
    free(sc);
}

TEST(sim_step_allocates_nothing) {
    ww_scene *sc = hand_scene();
    add_wave(sc, 20, 12, 0.25, 0.6);
    add_wave(sc, -35, 5, 0.08, 0.4);
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    long before = ww_test_alloc_count();
    ENSURE(ww_sim_advance_to(sc, st, 1000, &err) == WW_OK);
    ENSURE_EQ_INT(ww_test_alloc_count() - before, 0);
    ww_state_free(st);
    free(sc);
}

TEST(sim_state_hash_determinism_copy_and_sensitivity) {
    ww_scene *sc = hand_scene();
    add_wave(sc, 20, 12, 0.25, 0.6);
    sc->day_length = 600;
    ww_state *a = ww_state_new(sc), *b = ww_state_new(sc), *c = ww_state_new(sc);
    ww_error err = {0};
    ww_sim_advance_to(sc, a, 500, &err);
    ww_sim_advance_to(sc, b, 250, &err);
    ww_state_copy(c, b); /* a snapshot continues like the original */
    ww_sim_advance_to(sc, b, 500, &err);
    ww_sim_advance_to(sc, c, 500, &err);
    ENSURE_EQ_U64(ww_state_hash(sc, a), ww_state_hash(sc, b));
    ENSURE_EQ_U64(ww_state_hash(sc, a), ww_state_hash(sc, c));
    ww_step(sc, c, &err);
    ENSURE(ww_state_hash(sc, a) != ww_state_hash(sc, c));
    ww_state_free(a);
    ww_state_free(b);
    ww_state_free(c);
    free(sc);
}

TEST(sim_nan_guard_names_field_index_and_step) {
    ww_scene *sc = hand_scene();
    add_wave(sc, 20, 12, 0.25, 0.6);
    add_wave(sc, 0, 5, 0.1, 0.5);
    sc->waves[1].omega = NAN;
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    ENSURE_EQ_INT(ww_step(sc, st, &err), WW_E_NAN);
    ENSURE(strstr(err.msg, "wave_phase[1]") != NULL);
    ENSURE(strstr(err.msg, "step 1") != NULL);
    ww_state_free(st);
    free(sc);
}

/* one value of a double field made NaN: the guard must fail and name the field and index, and
 * pass again once the value is back */
static void nan_guard_sees(const ww_scene *sc, ww_state *st, double *v, const char *name,
                           long long i) {
    char want[96];
    snprintf(want, sizeof want, "%s[%lld]", name, i);
    double keep = v[i];
    v[i] = NAN;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_E_NAN);
    ENSURE_MSG(strstr(err.msg, want) != NULL, "%s: wanted %s in: %s", sc->path, want, err.msg);
    v[i] = keep;
    ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_OK);
}
static void nan_guard_ignores_int(const ww_scene *sc, ww_state *st, int32_t *v, const char *name,
                                  long long i) {
    (void)sc, (void)st, (void)v, (void)name, (void)i;
}
#define NAN_GUARD_SEES(sc, st, v, name, i)                                                        \
    _Generic((v), double *: nan_guard_sees, int32_t *: nan_guard_ignores_int)(sc, st, v, name, i)

/* the guard's runs of fields (found once a block) cover the first and last value of every
 * double field of scenes that between them run every system, and the outbox's live events */
TEST(sim_nan_guard_sees_every_double_field) {
    static const char *const scenes[] = {"scenes/lake.yaml", "scenes/reef.yaml",
                                         "scenes/features/floating_models.yaml"};
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        ww_scene *sc = NULL;
        ww_error err = {0};
        ENSURE_EQ_INT(ww_scene_load(scenes[k], NULL, 0, &sc, &err), WW_OK);
        ww_state *st = ww_state_new(sc);
        ENSURE_EQ_INT(ww_sim_advance_to(sc, st, 12, &err), WW_OK);
        int fields = 0;
#define NAN_GUARD_FIELD(type, name, count, sys, comment)                                          \
    if ((long long)(count) > 0 && (const void *)&st->name != (const void *)&st->events) {         \
        NAN_GUARD_SEES(sc, st, st->name, #name, 0);                                               \
        NAN_GUARD_SEES(sc, st, st->name, #name, (long long)(count) - 1);                          \
        fields++;                                                                                 \
    }
        WW_STATE_FIELDS(NAN_GUARD_FIELD)
#undef NAN_GUARD_FIELD
        ENSURE(fields > 10);
        if (ww_scene_has_objects(sc)) {
            int32_t live = st->event_count[0];
            st->event_count[0] = 2;
            NAN_GUARD_SEES(sc, st, st->events, "events", 2 * WW_SIM_EVENT_STRIDE - 1);
            st->event_count[0] = live;
        }
        ww_state_free(st);
        ww_scene_free(sc);
    }
}

/* a probe that counts each part's calls and that every enter is followed by its own leave */
typedef struct counting_probe {
    int open; /* the part entered and not left, -1 none */
    int bad;  /* an enter inside a part, a leave of another part, an id out of range */
    int64_t calls[WW_SYS_COUNT + 1];
} counting_probe;
static void count_enter(void *ctx, int id) {
    counting_probe *c = ctx;
    if (c->open >= 0 || id < 0 || id > WW_SYS_COUNT) c->bad++;
    c->open = id;
}
static void count_leave(void *ctx, int id) {
    counting_probe *c = ctx;
    if (c->open != id) c->bad++;
    if (id >= 0 && id <= WW_SYS_COUNT) c->calls[id]++;
    c->open = -1;
}

/* bench sim's breakdown: a probed step is the same step (the lake's hash after 600 steps), and
 * the probe sees each system the scene runs once a step at least (more where a script event
 * goes to it), no system it lacks, and the step's own two parts (the outbox, the NaN guard) */
TEST(sim_step_probed_sees_every_part_and_changes_nothing) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load("scenes/lake.yaml", NULL, 0, &sc, &err), WW_OK);
    if (!sc) return;
    enum { STEPS = 600 };
    ww_state *plain = ww_state_new(sc), *probed = ww_state_new(sc);
    counting_probe c = {.open = -1};
    ww_step_probe probe = {.enter = count_enter, .leave = count_leave, .ctx = &c};
    for (int k = 0; k < STEPS; k++) {
        ENSURE_EQ_INT(ww_step(sc, plain, &err), WW_OK);
        ENSURE_EQ_INT(ww_step_probed(sc, probed, &probe, &err), WW_OK);
    }
    ENSURE_EQ_U64(ww_state_hash(sc, plain), ww_state_hash(sc, probed));
    ENSURE_EQ_INT(c.bad, 0);
    ENSURE_EQ_INT(c.open, -1);
    ENSURE_EQ_INT((int)c.calls[WW_SYS_COUNT], 2 * STEPS);
    int nrows;
    const ww_system_row *rows = ww_systems(&nrows);
    for (int i = 0; i < nrows; i++) {
        int id = rows[i].id;
        if (ww_system_runs(sc, &rows[i]))
            ENSURE_MSG(c.calls[id] >= STEPS, "%s: %lld calls", ww_system_name(id),
                       (long long)c.calls[id]);
        else
            ENSURE_MSG(c.calls[id] == 0, "%s: %lld calls", ww_system_name(id),
                       (long long)c.calls[id]);
    }
    /* a step hook each step, and the script's events in the first 5 s each to its system: two
     * throws (t = 1 and 3 s) to the stones, a cast (2 s) to the rod, none to the fish */
    ENSURE_EQ_INT((int)c.calls[WW_SYS_STONES], STEPS + 2);
    ENSURE_EQ_INT((int)c.calls[WW_SYS_ROD], STEPS + 1);
    ENSURE_EQ_INT((int)c.calls[WW_SYS_FISH], STEPS);
    ww_state_free(plain);
    ww_state_free(probed);
    ww_scene_free(sc);
}

TEST(sim_camera_spinning_path_keeps_turning_one_way) {
    /* yaw keys 0, 120, 240, 0, 120 degrees: each step is +120 the short way, so between the
     * third and fourth key the camera looks at 300 degrees, not back through 120 */
    ww_scene *sc = hand_scene();
    sc->ncam = 5;
    sc->interp = WW_INTERP_LINEAR;
    static const double yaw[] = {0, 120, 240, 0, 120};
    for (int k = 0; k < 5; k++)
        sc->cam[k] = (ww_camera_key){.t = k, .position = {0, 2, 0}, .yaw = ww_m_rad(yaw[k])};
    double p[3], f[3], fov, want[3];
    ww_camera_eval(sc, 2.5, p, f, &fov);
    ww_camera_dir(ww_m_rad(300), 0, want);
    for (int c = 0; c < 3; c++) ENSURE_NEAR(f[c], want[c], CAMERA_TOL);
    ww_camera_eval(sc, 3.5, p, f, &fov);
    ww_camera_dir(ww_m_rad(60), 0, want);
    for (int c = 0; c < 3; c++) ENSURE_NEAR(f[c], want[c], CAMERA_TOL);
    free(sc);
}

/* the table of systems: every system has one row; every script event kind is taken by one row
 * and every simulation event kind emitted by one, so nothing a script or a system does goes
 * unowned */
TEST(sim_systems_table_owns_every_system_and_event_once) {
    int n;
    const ww_system_row *rows = ww_systems(&n);
    int seen[WW_SYS_COUNT] = {0};
    uint32_t takes = 0, emits = 0;
    for (int i = 0; i < n; i++) {
        ENSURE(rows[i].id >= 0 && rows[i].id < WW_SYS_COUNT);
        seen[rows[i].id]++;
        ENSURE_MSG((takes & rows[i].takes) == 0, "%s takes a kind another row takes",
                   ww_system_name(rows[i].id));
        ENSURE_MSG((emits & rows[i].emits) == 0, "%s emits a kind another row emits",
                   ww_system_name(rows[i].id));
        ENSURE_MSG(!rows[i].takes == !rows[i].event, "%s: event kinds without a handler, or back",
                   ww_system_name(rows[i].id));
        takes |= rows[i].takes;
        emits |= rows[i].emits;
    }
    /* the script is the driver's own (the events stage), not a row */
    for (int s = 0; s < WW_SYS_COUNT; s++)
        ENSURE_MSG(seen[s] == (s == WW_SYS_SCRIPT ? 0 : 1), "%s has %d rows", ww_system_name(s),
                   seen[s]);
    for (int k = WW_EV_TIME_OF_DAY; k <= WW_EV_CHEST; k++)
        ENSURE_MSG(ww_system_taking((ww_event_kind)k) != NULL, "script event kind %d unowned", k);
    for (int k = 1; k < WW_SE_COUNT; k++)
        ENSURE_MSG(emits & (1u << k), "simulation event %s emitted by no row", ww_sim_event_name((ww_sim_event_kind)k));
}
