/* test_world.c - the scripted world as a whole: scenes/lake.yaml (every system of seed 000) and
 * scenes/reef.yaml (seed 003's underwater objects) run their scripts to the events they promise,
 * with pinned state hashes, equal across runs and across --frames slices; one system's random
 * draws never move another's.
 */
#include <stdlib.h>
#include <string.h>

#include "scene/scene.h"
#include "sim/events.h"
#include "sim/floater_stats.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* `simulate --hash` of the whole run; re-pin only for an intended change of the simulation */
#define LAKE_HASH "0ec10daeb2943062"
#define REEF_HASH "4382509839f42aeb"

static char cmd[2048];

static char *simulate(const char *args, const char *tag) {
    char out[600];
    snprintf(out, sizeof out, "%s/%s.txt", ww_test_tmpdir("world"), tag);
    snprintf(cmd, sizeof cmd, "%s simulate %s", ww_test_bin(), args);
    if (ww_test_run(cmd, out, NULL) != 0) return NULL;
    return ww_test_read_file(out, NULL);
}

TEST_PROC(world_lake_hash_pinned_repeatable_and_sliced) {
    char *a = simulate("scenes/lake.yaml --hash", "a");
    char *b = simulate("scenes/lake.yaml --hash", "b");
    /* frames 300..599 after simulating 0..299 without output: the same final state */
    char *c = simulate("scenes/lake.yaml --frames 300:600 --hash", "c");
    ENSURE(a && b && c);
    if (a && b && c) {
        ENSURE(strcmp(a, b) == 0);
        ENSURE(strcmp(a, c) == 0);
        ENSURE_MSG(strncmp(a, LAKE_HASH, 16) == 0, "lake hash %.16s, pinned %s", a, LAKE_HASH);
    }
    free(a);
    free(b);
    free(c);
}

/* every kind the scene's script is written to cause, counted over the whole run */
static void count_kinds(const char *path, int counts[WW_SE_COUNT]) {
    memset(counts, 0, sizeof(int) * WW_SE_COUNT);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load(path, NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    int64_t last = sc->frame_count * sc->steps_per_frame;
    for (int64_t s = 0; s <= last; s++) {
        if (s > 0) ENSURE(ww_step(sc, st, &err) == WW_OK);
        for (int i = 0; i < ww_events_count(sc, st); i++) {
            int k = (int)st->events[i * WW_SIM_EVENT_STRIDE];
            if (k > 0 && k < WW_SE_COUNT) counts[k]++;
        }
    }
    ENSURE(st->events_dropped[0] == 0.0);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(world_lake_script_does_what_it_says) {
    int n[WW_SE_COUNT];
    count_kinds("scenes/lake.yaml", n);
    /* stones thrown, skipping and sinking; a cast, a bite and a catch; the boat driven; a cube
     * pressed and released; a chest spawned and collected */
    ENSURE(n[WW_SE_STONE_THROW] == 3);
    ENSURE(n[WW_SE_STONE_SKIP] >= 1 && n[WW_SE_STONE_SINK] >= 1);
    ENSURE(n[WW_SE_ROD_CAST] == 1 && n[WW_SE_LURE_LAND] == 1);
    ENSURE(n[WW_SE_BITE] >= 1 && n[WW_SE_CATCH] >= 1);
    ENSURE(n[WW_SE_BOAT_START] == 2 && n[WW_SE_BOAT_STOP] == 2);
    ENSURE(n[WW_SE_CUBE_PRESS] == 1 && n[WW_SE_CUBE_RELEASE] == 1);
    ENSURE(n[WW_SE_CHEST_SPAWN] >= 1 && n[WW_SE_CHEST_COLLECT] == 1);
}

TEST_PROC(world_reef_script_does_what_it_says) {
    int n[WW_SE_COUNT];
    count_kinds("scenes/reef.yaml", n);
    ENSURE(n[WW_SE_CAMERA_BLOCKED] == 1);
    ENSURE(n[WW_SE_CHEST_COLLECT] == 1);
    char *a = simulate("scenes/reef.yaml --hash", "ra");
    char *b = simulate("scenes/reef.yaml --frames 200:600 --hash", "rb");
    ENSURE(a && b);
    if (a && b) {
        ENSURE(strcmp(a, b) == 0);
        ENSURE_MSG(strncmp(a, REEF_HASH, 16) == 0, "reef hash %.16s, pinned %s", a, REEF_HASH);
    }
    free(a);
    free(b);
}

/* the stones of the lake fly the same paths with twelve fish, one fish or none: each system
 * draws from its own stream, and fish do not touch stones */
TEST(world_fish_do_not_move_the_stones) {
    static const char *const variants[] = {NULL, "objects.fish.count=1"};
    double final[2][3 * WW_MAX_STONES];
    for (int v = 0; v < 2; v++) {
        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_set set = {variants[v]};
        ENSURE_MSG(ww_scene_load("scenes/lake.yaml", &set, variants[v] ? 1 : 0, &sc, &err) ==
                       WW_OK,
                   "%s", err.msg);
        if (!sc) return;
        ww_state *st = ww_state_new(sc);
        ENSURE(ww_sim_advance_to(sc, st, 4 * 120, &err) == WW_OK); /* three throws by t = 4 s */
        memcpy(final[v], st->stone_pos, sizeof final[v]);
        ww_state_free(st);
        ww_scene_free(sc);
    }
    ENSURE(memcmp(final[0], final[1], sizeof final[0]) == 0);
}

/* heave of a floating body on a long swell of amplitude A: a small stable cube (and the boat)
 * rides it, so its height RMS about the mean approaches the swell's A / sqrt(2); on flat water it
 * is still. The tolerance allows the cube's response above 1 near its own heave period (an
 * undamped oscillator driven at w: 1 / (1 - (w / wn)^2) = 1.077 for a 0.45 m draft on a 5.1 s
 * swell; measured 1.089), the boat's lag and the bodies' size against a 40 m wavelength. */
#define RIDES_THE_SWELL_REL_TOL 0.15
#define STILL_WATER_HEAVE_TOL 1e-3 /* m */

static void floaters_on_swell(double amplitude, ww_floater_stats *f) {
    char text[1024];
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 24}\n"
             "water: {waves: {model: sines, list: [{direction: 0, wavelength: 40, amplitude: %g}]}}\n"
             "objects:\n"
             "  cubes: [{position: [0, -0.2, 0], size: 0.5, density: 900}]   # at its draft of 0.45 m\n"
             "  boat: {position: [10, 0.25, 10], heading: 0}   # bow into the swell\n",
             amplitude);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("swell.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return;
    ENSURE(ww_floater_stats_compute(sc, f, &err) == WW_OK);
    ww_scene_free(sc);
}

TEST(world_floaters_heave_with_the_swell) {
    ww_floater_stats calm = {0}, swell = {0};
    floaters_on_swell(0.0, &calm);
    floaters_on_swell(0.5, &swell);
    ENSURE(calm.samples > 0 && swell.samples == calm.samples);
    ENSURE_NEAR(calm.cube_heave_rms, 0.0, STILL_WATER_HEAVE_TOL);
    ENSURE_NEAR(calm.boat_heave_rms, 0.0, STILL_WATER_HEAVE_TOL);
    double expect = 0.5 / sqrt(2.0);
    ENSURE_NEAR(swell.cube_heave_rms / expect, 1.0, RIDES_THE_SWELL_REL_TOL);
    ENSURE_NEAR(swell.boat_heave_rms / expect, 1.0, RIDES_THE_SWELL_REL_TOL);
    /* the boat pitches with the slope: 2 pi A / L = 0.079 rad at most, RMS about 0.055 */
    ENSURE_MSG(swell.boat_pitch_rms > 0.02 && swell.boat_pitch_rms < 0.079, "pitch rms %g", swell.boat_pitch_rms);
    ENSURE(calm.boat_pitch_rms < 1e-6);
}

/* passive floaters never gain energy: on flat water, cubes of every stability class (stable
 * upright, turning onto an edge, dense and light) and the boat come to rest, and stay at rest:
 * their largest speed over the last minute of ten is below this (m/s, rad/s) */
#define AT_REST_SPEED_TOL 1e-3
#define REST_RUN_SECONDS 600.0
#define REST_WATCH_SECONDS 60.0

TEST(world_passive_floaters_come_to_rest_and_stay) {
    static const char text[] =
        "time: {dt: 1/120, fps: 30, duration: 600}\n"
        "water: {waves: {model: flat}}\n"
        "objects:\n"
        "  cubes:\n"
        "    - {position: [0, 0.5, 0], size: 1, density: 500}\n"
        "    - {position: [3, 0, 0], size: 0.6, density: 900, rotation: [20, 0, 10]}\n"
        "    - {position: [-3, 0, 0], size: 0.8, density: 150}\n"
        "    - {position: [0, 0, 3], size: 1.2, density: 300, buoyancy: spring}\n"
        "    - {position: [0, -1, -3], size: 0.5, density: 700}\n"
        "  boat: {position: [8, 1, 8], heading: 30}\n";
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("rest.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    int64_t watch = (int64_t)((REST_RUN_SECONDS - REST_WATCH_SECONDS) / sc->dt);
    int64_t end = (int64_t)(REST_RUN_SECONDS / sc->dt);
    double vmax = 0.0;
    for (int64_t s = 1; s <= end; s++) {
        if (ww_step(sc, st, &err) != WW_OK) {
            ENSURE_MSG(0, "%s", err.msg);
            break;
        }
        if (s < watch) continue;
        for (int i = 0; i < 3 * sc->cubes.count; i++)
            vmax = fmax(vmax, fmax(fabs(st->cube_vel[i]), fabs(st->cube_omega[i])));
        for (int i = 0; i < 3; i++) vmax = fmax(vmax, fabs(st->boat_vel[i]));
    }
    ENSURE_MSG(vmax < AT_REST_SPEED_TOL, "largest speed in the last minute %g", vmax);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* time.integrator: the exact boat run matches the closed form at any dt; the seeds' Euler is
 * first order (its error halves when dt halves) */
#define BOAT_EXACT_TOL 1e-9        /* m over 10 s: rounding */
#define EULER_ORDER_TOL 0.1        /* on the error ratio 2 between dt and dt / 2 */

static double boat_run_error(const char *integrator, int div) {
    char text[1024];
    snprintf(text, sizeof text,
             "time: {dt: 1/%d, fps: %d, duration: 10, integrator: %s}\n"
             "water: {waves: {model: flat}}\n"
             "objects: {boat: {position: [0, 0.25, 0], heading: 0, acceleration: 6, drag: 1.2,"
             " max_speed: 50}}\n"
             "camera: {collide: false}\n"
             "script: [{t: 0, boat: {throttle: 1}}]\n",
             div, div, integrator);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("run.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return NAN;
    ww_state *st = ww_state_new(sc);
    double T = 10.0, k = 1.2, v = 6.0 / k;
    ENSURE(ww_sim_advance_to(sc, st, (int64_t)div * 10, &err) == WW_OK);
    double x = v * (T - (1.0 - exp(-k * T)) / k); /* dv/dt = a - k v from rest */
    double e = fabs(st->boat_pos[0] - x);
    ww_state_free(st);
    ww_scene_free(sc);
    return e;
}

TEST(world_integrator_knob_exact_and_euler) {
    ENSURE_NEAR(boat_run_error("exact", 30), 0.0, BOAT_EXACT_TOL);
    ENSURE_NEAR(boat_run_error("exact", 240), 0.0, BOAT_EXACT_TOL);
    double e30 = boat_run_error("euler", 30), e60 = boat_run_error("euler", 60);
    ENSURE(e30 > 1e-3);
    ENSURE_NEAR(e30 / e60, 2.0, EULER_ORDER_TOL * 2.0);
}

/* a cross-check on an event written in a --script file names that file, not the scene */
TEST(world_script_file_errors_name_the_script) {
    char path[600];
    snprintf(path, sizeof path, "%s/bad_press.yaml", ww_test_tmpdir("world_script"));
    ENSURE(ww_test_write_text(path, "script:\n  - {t: 1, throw: {charge: 0.5}}\n"
                                    "  - {t: 2, press: {cube: 9, hold: 1}}\n") == 0);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load_with_script("scenes/lake.yaml", path, NULL, 0, &sc, &err),
                  WW_E_INCONSISTENT);
    ENSURE(sc == NULL);
    ENSURE_MSG(strcmp(err.file, path) == 0 && err.line == 3 && err.column == 5, "%s:%d:%d: %s",
               err.file, err.line, err.column, err.msg);
}
