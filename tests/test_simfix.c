/* test_simfix.c - numbers as text (core/numfmt.h) and the sweep values printed with it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "core/numfmt.h"
#include "core/rng.h"
#include "io/image.h"
#include "scene/scene.h"
#include "sim/camera.h"
#include "sim/fish.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"
#include "bench/plot.h"
#include "sweep/sweep.h"

/* ---- numbers as people write them ----------------------------------------------------------- */

#define ROUND_TRIPS 20000 /* random doubles of every exponent read back from their text */

TEST(numfmt_shortest_text_reads_back_exactly) {
    char t[WW_NUM_TEXT];
    static const struct { double v; const char *text; } cases[] = {
        {0.4, "0.4"},
        {0.1 + 0.2, "0.30000000000000004"},
        {0.39999999999999997, "0.39999999999999997"}, /* the double below 0.4 */
        {30.0, "30"},
        {-2.5, "-2.5"},
        {1e-7, "1e-07"},
        {1e300, "1e+300"},
        {0.0, "0"},
        {1.0 / 3.0, "0.3333333333333333"},
        {123456789012.0, "123456789012"},
        {5e-324, "5e-324"}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ww_num_text(t, sizeof t, cases[i].v);
        ENSURE_MSG(strcmp(t, cases[i].text) == 0, "%.17g printed as %s, expected %s", cases[i].v, t,
                   cases[i].text);
    }
    ww_num_text(t, sizeof t, NAN);
    ENSURE(strcmp(t, "nan") == 0);
    ww_num_text(t, sizeof t, -INFINITY);
    ENSURE(strcmp(t, "-inf") == 0);

    /* random bit patterns (every exponent) and random values in [0, 1): the text reads back as
     * the same double and no shorter %g text does */
    ww_rng r;
    ww_rng_seed(&r, 42, 0);
    int bad = 0, long_ = 0;
    for (int i = 0; i < ROUND_TRIPS; i++) {
        double v;
        if (i % 2) {
            uint64_t bits = ((uint64_t)ww_rng_u32(&r) << 32) | ww_rng_u32(&r);
            memcpy(&v, &bits, sizeof v);
            if (!isfinite(v)) continue;
        } else {
            v = ww_rng_uniform(&r);
        }
        int n = ww_num_text(t, sizeof t, v);
        bad += strtod(t, NULL) != v || n != (int)strlen(t) || n >= WW_NUM_TEXT;
        /* one digit fewer does not read back (unless written without an exponent) */
        if (!strchr(t, 'e')) continue;
        char m[320];
        const char *e = strchr(t, 'e');
        int digits = 0;
        for (const char *p = t; p < e; p++) digits += *p >= '0' && *p <= '9';
        if (digits < 2) continue;
        snprintf(m, sizeof m, "%.*g", digits - 1, v);
        long_ += strtod(m, NULL) == v;
    }
    ENSURE_EQ_INT(bad, 0);
    ENSURE_EQ_INT(long_, 0);
}

TEST(numfmt_near_gives_the_decimal_meant) {
    char t[WW_NUM_TEXT];
    /* the second point of 0.1:0.4:4 as the grid computes it */
    double v = (0.1 * 2.0 + 0.4 * 1.0) / 3.0;
    ww_num_text(t, sizeof t, v);
    ENSURE(strcmp(t, "0.20000000000000004") == 0);
    ww_num_text_near(t, sizeof t, v, 1e-12);
    ENSURE(strcmp(t, "0.2") == 0);
    /* a tolerance of zero is exact */
    ww_num_text_near(t, sizeof t, v, 0.0);
    ENSURE(strcmp(t, "0.20000000000000004") == 0);
}

TEST_PROC(numfmt_sweep_grid_values_are_written_as_meant) {
    const char *vary[] = {"water.waves.list[0].amplitude=0.1:0.7:7"};
    ww_sweep_opts o = ww_default_sweep_opts();
    o.scene_path = "scenes/minimal.yaml";
    o.vary = vary;
    o.nvary = 1;
    o.quiet = 1;
    ww_sweep *s = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_sweep_new(&o, &s, &err) == WW_OK, "ww_sweep_new: %s", err.msg);
    if (!s) return;
    static const char *const want[] = {"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7"};
    char v[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX];
    for (int i = 0; i < 7; i++) {
        ww_sweep_values(s, i, v);
        ENSURE_MSG(strcmp(v[0], want[i]) == 0, "point %d: %s, expected %s", i, v[0], want[i]);
    }
    ww_sweep_free(s);

    /* the CSV's value column and a metric written by the same helper */
    char dir[512], cmd[1200];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep"));
    snprintf(cmd, sizeof cmd,
             "sweep scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.1:0.4:4 -o %s", dir);
    ENSURE_EQ_INT(ww_test_ww(cmd, NULL, NULL), 0);
    snprintf(cmd, sizeof cmd, "%s/sweep.csv", dir);
    ENSURE(ww_test_file_contains(cmd, "\n1,0.2,"));
    ENSURE(!ww_test_file_contains(cmd, "0.20000000000000004"));
}

/* ---- the project's goldens through render --golden ------------------------------------------ */

/* golden/features/NAME.png is frame 0 of scenes/features/NAME.yaml: render --golden finds it (a
 * comparison, pass or fail by this renderer), where it used to look only for frame_00000.png */
TEST_PROC(golden_features_layout_is_found_by_render_golden) {
    REQUIRE_GL();
    char dir[512], args[1200], err_path[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("fog"));
    snprintf(err_path, sizeof err_path, "%s/stderr.txt", dir);
    snprintf(args, sizeof args,
             "render scenes/features/fog.yaml --frames 1 -o %s/out --golden golden/features",
             dir);
    int rc = ww_test_ww(args, NULL, err_path);
    ENSURE_MSG(rc == 0 || rc == 1, "exit %d", rc);
    ENSURE(ww_test_file_contains(err_path, "0 missing"));
    ENSURE(!ww_test_file_contains(err_path, "MISSING"));
    ENSURE(ww_test_file_contains(err_path, "golden/features"));
    /* frame 1 has no single-frame golden: still reported missing, with the paths tried */
    snprintf(args, sizeof args,
             "render scenes/features/fog.yaml --frames 1:2 -o %s/out1 --golden golden/features",
             dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, err_path), 1);
    ENSURE(ww_test_file_contains(err_path, "1 missing"));
}

/* ---- camera collision: slide or stop, never pass -------------------------------------------- */

static ww_scene *load(const char *text) { return ww_test_scene_text("simfix.yaml", text); }

/* the segment a + u (b - a), u in [0, 1], meets the open box |x - c| < h (slab test written out
 * here, independently of collide.c) */
static int segment_hits_box(const double a[3], const double b[3], const double c[3],
                            const double h[3]) {
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 3; k++) {
        double o = a[k] - c[k], v = b[k] - a[k];
        if (v == 0.0) {
            if (fabs(o) >= h[k]) return 0;
            continue;
        }
        double t1 = (-h[k] - o) / v, t2 = (h[k] - o) / v;
        if (t1 > t2) {
            double x = t1;
            t1 = t2;
            t2 = x;
        }
        lo = fmax(lo, t1);
        hi = fmin(hi, t2);
    }
    return lo < hi;
}

/* a crate (a model's box, 1 m, centre (0, 1.5, 0)) and a camera path straight through it along
 * +x at its centre, 8 m in 2 s, then (t = 2.5 .. 3.5) 3 m sideways, around it */
static const char *CRATE_FLY =
    "time: {dt: 1/120, fps: 30, duration: 4.5}\n"
    "water: {waves: {model: flat}}\n"
    "objects: {models: [{name: crate, min: [-0.5, 1, -0.5], max: [0.5, 2, 0.5]}]}\n"
    "camera: {collide: %s, near: 0.1, interpolation: linear, path: [\n"
    "  {t: 0.5, position: [-4, 1.5, 0], yaw: 90}, {t: 2.5, position: [4, 1.5, 0], yaw: 90},\n"
    "  {t: 3.5, position: [4, 1.5, 3], yaw: 90}]}\n";

typedef struct crate_fly {
    int far_side;      /* frames (1/30 s) with the camera behind the crate or in it */
    int crossings;     /* steps whose move passed through the crate */
    int rejoined;      /* frames on the path after it went around */
    double min_dist;   /* smallest distance to the crate's box, m */
} crate_fly;

static void fly_crate(int collide, crate_fly *out) {
    char text[1024];
    snprintf(text, sizeof text, CRATE_FLY, collide ? "true" : "false");
    *out = (crate_fly){.min_dist = 1e9};
    ww_scene *sc = load(text);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    const double c[3] = {0.0, 1.5, 0.0}, h[3] = {0.5, 0.5, 0.5};
    double prev[3] = {-4.0, 1.5, 0.0};
    while (st->t < 4.5) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        const double *p = st->cam_pos;
        out->crossings += segment_hits_box(prev, p, c, h);
        for (int k = 0; k < 3; k++) prev[k] = p[k];
        double d2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double o = fabs(p[k] - c[k]) - h[k];
            if (o > 0.0) d2 += o * o;
        }
        out->min_dist = fmin(out->min_dist, sqrt(d2));
        if (st->step % 4) continue; /* a frame every 4 steps */
        /* behind: past the far face, within the crate's outline seen along x (its shadow) */
        int behind = p[0] > -0.5 && fabs(p[1] - c[1]) < h[1] && fabs(p[2] - c[2]) < h[2];
        out->far_side += behind;
        double q[3], f[3], fov;
        ww_camera_eval(sc, st->t, q, f, &fov);
        out->rejoined += st->t > 3.5 && q[0] == p[0] && q[1] == p[1] && q[2] == p[2];
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

/* measured: without collision 39 frames in or behind the crate and 30 steps through it; the old
 * rule (rejoin the path once it is clear) put the camera behind it for 31 frames after one step
 * through it; now 0 and 0 */
TEST(collide_camera_never_passes_through_a_crate) {
    crate_fly f;
    fly_crate(1, &f);
    ENSURE_EQ_INT(f.far_side, 0);
    ENSURE_EQ_INT(f.crossings, 0);
    ENSURE(f.min_dist >= 0.1 - 1e-9);
    /* once the path has gone around, the camera is on it again */
    ENSURE(f.rejoined >= 25);
    printf("  collide on: far side %d frames, crossings %d, rejoined %d frames, min distance "
           "%.4f m\n",
           f.far_side, f.crossings, f.rejoined, f.min_dist);
    fly_crate(0, &f);
    ENSURE(f.far_side > 0 && f.crossings > 0);
    printf("  collide off: far side %d frames, crossings %d\n", f.far_side, f.crossings);
}

/* ---- a parent's scale is its own ------------------------------------------------------------ */

#define MODEL_FRAME_TOL 1e-12 /* a few roundings of the matrix products, m */

/* column c of a model's world matrix: its axis c in the world, as long as its own scale */
static double column_length(const ww_model_desc *m, int c) {
    const double *w = m->world + 4 * c;
    return sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

static double column_dot(const ww_model_desc *m, int a, int b) {
    const double *u = m->world + 4 * a, *v = m->world + 4 * b;
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

TEST(models_child_of_a_stretched_parent_keeps_its_shape_and_metres) {
    /* a plank 4 m long along its x, turned yaw 30; a post on it 1.5 m along the plank, its
     * own scale [0.2, 2, 0.2]; a lamp on the post 1 m up, turned about its own axis */
    static const char *text =
        "time: {dt: 1/120, fps: 30, duration: 1}\n"
        "objects:\n"
        "  models:\n"
        "    - {name: plank, mesh: box, position: [2, 0, -3], rotation: 30, scale: [4, 1, 1]}\n"
        "    - {name: post, mesh: box, parent: plank, position: [1.5, 0, 0],"
        " scale: [0.2, 2, 0.2]}\n"
        "    - {name: lamp, mesh: sphere, parent: post, position: [0, 1, 0], rotation: [0, 0, 45],"
        " scale: 0.3}\n";
    ww_scene *sc = load(text);
    if (!sc) return;
    const ww_model_desc *plank = &sc->models.model[0], *post = &sc->models.model[1],
                        *lamp = &sc->models.model[2];
    /* the plank is stretched, its children are not: each axis as long as its own scale and the
     * axes at right angles (no shear) */
    ENSURE_NEAR(column_length(plank, 0), 4.0, MODEL_FRAME_TOL);
    const double post_scale[3] = {0.2, 2.0, 0.2};
    for (int c = 0; c < 3; c++) {
        ENSURE_NEAR(column_length(post, c), post_scale[c], MODEL_FRAME_TOL);
        ENSURE_NEAR(column_length(lamp, c), 0.3, MODEL_FRAME_TOL);
        for (int d = c + 1; d < 3; d++) {
            ENSURE_NEAR(column_dot(post, c, d), 0.0, MODEL_FRAME_TOL);
            ENSURE_NEAR(column_dot(lamp, c, d), 0.0, MODEL_FRAME_TOL);
        }
    }
    /* where the README says: 1.5 m along the plank's turned x (yaw 30 turns +x toward +z) */
    double a = ww_m_rad(30.0);
    ENSURE_NEAR(post->world[12], 2.0 + 1.5 * cos(a), MODEL_FRAME_TOL);
    ENSURE_NEAR(post->world[13], 0.0, MODEL_FRAME_TOL);
    ENSURE_NEAR(post->world[14], -3.0 + 1.5 * sin(a), MODEL_FRAME_TOL);
    /* and the lamp 1 m above the post's origin, whatever the post's own scale */
    ENSURE_NEAR(lamp->world[12], post->world[12], MODEL_FRAME_TOL);
    ENSURE_NEAR(lamp->world[13], 1.0, MODEL_FRAME_TOL);
    ENSURE_NEAR(lamp->world[14], post->world[14], MODEL_FRAME_TOL);
    /* the post's camera bounds: its own box (0.2 x 2 x 0.2) turned by 30 degrees */
    ENSURE_NEAR(post->max[1] - post->min[1], 2.0, MODEL_FRAME_TOL);
    ENSURE_NEAR(post->max[0] - post->min[0], 0.2 * cos(a) + 0.2 * sin(a), MODEL_FRAME_TOL);
    ww_scene_free(sc);
}

/* ---- fish flee ----------------------------------------------------------------------------- */

/* 30 wandering fish in a school 5 m across at 2 m depth; a diver (the camera) swims straight
 * through its middle at 2 m/s, and back 1 m higher. %s: objects.fish.avoid (0: no fleeing) */
static const char *SCHOOL =
    "seed: 5\n"
    "time: {dt: 1/120, fps: 30, duration: 20}\n"
    "water: {depth: 8, waves: {model: flat}}\n"
    "objects:\n"
    "  fish: {count: 30, center: [0, -2, 0], radius: 5, spread: 0.6, avoid: %s}\n"
    "camera: {interpolation: linear, path: [{t: 0, position: [-10, -2, 0], yaw: 90},\n"
    "  {t: 10, position: [10, -2, 0.5], yaw: 90},\n"
    "  {t: 20, position: [-10, -1.5, -0.5], yaw: -90}]}\n";

/* a floating cube and the boat in the middle of a school near the surface, both still: the
 * school's fish-frames within `near` of each */
static const char *OBJECTS =
    "seed: 9\n"
    "time: {dt: 1/120, fps: 30, duration: 20}\n"
    "water: {depth: 6, waves: {model: flat}}\n"
    "objects:\n"
    "  boat: {position: [-2.5, 0.25, 0], heading: 0, radius: 1.5}\n"
    "  cubes: [{position: [2.5, 0, 0], size: 1.2, density: 500}]\n"
    "  fish: {count: 30, center: [0, -0.9, 0], radius: 5, spread: 0.3, margin: 0.2, avoid: %s}\n"
    "camera: {path: [{t: 0, position: [0, 12, 14], look_at: [0, 0, 0]}]}\n";

#define FLEE_NEAR 1.5   /* m: a fish this close to the diver counts */
/* fleeing must cut the fish-frames within FLEE_NEAR of the diver at least this many times
 * (measured: 549 without fleeing, 504 with the former steering-only avoidance, 0 now) */
#define FLEE_FACTOR 8.0
/* and those near the boat and the cube (measured, off / steering-only / now: boat 2963 / 1403 /
 * 71, cube 589 / 89 / 4) */
#define AVOID_FACTOR 4.0
/* |dv| / dt against WW_FISH_MAX_ACCEL, |v| against max_speed: the rounding of a scaled vector */
#define FISH_ACCEL_TOL 1e-9

typedef struct near_count {
    long diver, boat, cube; /* (fish, frame) pairs within the distance, frames at 30 fps */
    double worst_accel;     /* largest |dv| / dt of a swimming fish, m/s^2 */
    double worst_speed;     /* largest |v|, m/s */
} near_count;

static double dist3(const double *a, const double *b) {
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static void count_near(const char *fmt, const char *avoid, double boat_near, double cube_near,
                       near_count *out) {
    char text[2048];
    snprintf(text, sizeof text, fmt, avoid);
    *out = (near_count){0};
    ww_scene *sc = load(text);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ww_error err = {0};
    int n = sc->fish.count;
    double *v0 = calloc((size_t)(3 * n), sizeof *v0);
    while (v0 && st->t < sc->duration) {
        for (int k = 0; k < 3 * n; k++) v0[k] = st->fish_vel[k];
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        for (int i = 0; i < n; i++) {
            const double *v = st->fish_vel + 3 * i;
            double dv[3] = {v[0] - v0[3 * i], v[1] - v0[3 * i + 1], v[2] - v0[3 * i + 2]};
            double a = sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]) / sc->dt;
            out->worst_accel = fmax(out->worst_accel, a);
            double speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            out->worst_speed = fmax(out->worst_speed, speed);
        }
        if (st->step % 4) continue;
        for (int i = 0; i < n; i++) {
            const double *p = st->fish_pos + 3 * i;
            out->diver += dist3(p, st->cam_pos) < FLEE_NEAR;
            if (sc->boat.on) out->boat += dist3(p, st->boat_pos) < boat_near;
            if (sc->cubes.on) out->cube += dist3(p, st->cube_pos) < cube_near;
        }
    }
    free(v0);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(fish_flee_from_a_diver_swimming_through_the_school) {
    near_count off, on;
    count_near(SCHOOL, "0", 0, 0, &off);
    count_near(SCHOOL, "4", 0, 0, &on);
    printf("  fish-frames within %.1f m of the diver: %ld fleeing off, %ld fleeing on\n", FLEE_NEAR,
           off.diver, on.diver);
    printf("  largest acceleration %.2f m/s^2, speed %.3f m/s\n", on.worst_accel, on.worst_speed);
    ENSURE(off.diver > 100); /* the path does go through the school */
    ENSURE(on.worst_accel <= WW_FISH_MAX_ACCEL * (1.0 + FISH_ACCEL_TOL));
    ENSURE(on.worst_speed <= 3.0 * (1.0 + FISH_ACCEL_TOL)); /* max_speed: the burst's limit */
    ENSURE_MSG(on.diver * FLEE_FACTOR <= off.diver, "%ld x %g > %ld", on.diver, FLEE_FACTOR,
               off.diver);
}

TEST(fish_avoid_the_boat_and_the_cubes) {
    near_count off, on;
    /* within 1 m of the boat's sphere and of the cube's faces (centre distances) */
    count_near(OBJECTS, "0", 2.5, 1.6, &off);
    count_near(OBJECTS, "4", 2.5, 1.6, &on);
    printf("  fish-frames near the boat: %ld off, %ld on; near the cube: %ld off, %ld on\n",
           off.boat, on.boat, off.cube, on.cube);
    ENSURE(off.boat > 50 && off.cube > 50);
    ENSURE(on.boat * AVOID_FACTOR <= off.boat);
    ENSURE(on.cube * AVOID_FACTOR <= off.cube);
}

/* ---- bench sim: errors that converge ------------------------------------------------------ */

/* within 1 s: a stone skipping over open water and one knocking a floating cube, the boat
 * driving; the contact with the cube is found at a step's end */
static const char *CONVERGE =
    "seed: 4\n"
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "water:\n"
    "  depth: 6\n"
    "  waves:\n"
    "    model: gerstner\n"
    "    list:\n"
    "      - {direction: 20, wavelength: 8, amplitude: 0.2, steepness: 0.5}\n"
    "      - {direction: -40, wavelength: 3, amplitude: 0.05, steepness: 0.4}\n"
    "objects:\n"
    "  boat: {position: [-6, 0.25, -4], heading: 0}\n"
    "  cubes: [{position: [3, 0, -3], size: 1, density: 600}]\n"
    "  stones: {}\n"
    "camera: {path: [{t: 0, position: [0, 1.5, 6], look_at: [0, 0, -6]}]}\n"
    "script:\n"
    "  - {t: 0.1, throw: {speed: 12, angle: 8, from: [0, 0.6, 4], heading: 180}}\n"
    "  - {t: 0.1, throw: {speed: 9, angle: 2, from: [0, 0.5, -3], heading: 0}}\n"
    "  - {t: 0, boat: {throttle: 1, steer: 0.3, until: 1}}\n";

/* an error at dt / 2 is at most the error at dt (plus rounding: the exact parabola's errors are
 * 1e-15 m) ... */
#define CONVERGE_ROUNDING 1e-9
/* ... and two halvings at least halve it (first order quarters it; measured: 0.06 for the exact
 * boat, 0.22 .. 0.36 for the other metrics and integrators) */
#define CONVERGE_TWO_HALVINGS 0.5

TEST_PROC(bench_sim_errors_shrink_as_dt_halves) {
    char dir[512], scene[600], out[600], args[1400];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("converge"));
    snprintf(scene, sizeof scene, "%s/converge.yaml", dir);
    snprintf(out, sizeof out, "%s/out.jsonl", dir);
    ENSURE_EQ_INT(ww_test_write_text(scene, CONVERGE), 0);
    snprintf(args, sizeof args, "bench sim --tiny --json %s -o %s", scene, dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    char *text = ww_test_read_file(out, NULL);
    ENSURE(text != NULL);
    if (!text) return;
    static const char *const keys[3] = {"cube_heave_m", "boat_position_m", "stone_path_m"};
    static const char *const integ[2] = {"exact", "euler"};
    static const char *const dts[3] = {"\"dt\":0.0333333333", "\"dt\":0.0166666667",
                                       "\"dt\":0.00833333333"};
    for (int g = 0; g < 2; g++)
        for (int m = 0; m < 3; m++) {
            double e[3] = {-1, -1, -1};
            for (int d = 0; d < 3; d++) {
                char want[64];
                snprintf(want, sizeof want, "\"integrator\":\"%s\",%s", integ[g], dts[d]);
                const char *line = strstr(text, want);
                ENSURE_MSG(line != NULL, "no line %s", want);
                if (line) e[d] = ww_test_json_number(line, keys[m]);
            }
            printf("  %s %s: %.3e %.3e %.3e\n", integ[g], keys[m], e[0], e[1], e[2]);
            ENSURE(e[0] >= 0 && e[1] >= 0 && e[2] >= 0);
            ENSURE_MSG(e[1] <= e[0] + CONVERGE_ROUNDING && e[2] <= e[1] + CONVERGE_ROUNDING,
                       "%s %s grows as dt halves: %.3e %.3e %.3e", integ[g], keys[m], e[0], e[1],
                       e[2]);
            ENSURE_MSG(e[2] <= CONVERGE_TWO_HALVINGS * e[0] + CONVERGE_ROUNDING,
                       "%s %s: %.3e at dt/4 against %.3e", integ[g], keys[m], e[2], e[0]);
        }
    free(text);
}

/* ---- plot legends keep off the data --------------------------------------------------------- */

/* pixels of the series' colours inside box, in a plot drawn without its legend */
static long series_pixels_in(const ww_image *im, const ww_plot *p, const int box[4]) {
    long n = 0;
    for (int y = box[1]; y < box[3]; y++)
        for (int x = box[0]; x < box[2]; x++) {
            if (x < 0 || y < 0 || x >= im->width || y >= im->height) continue;
            const unsigned char *px = im->u8 + ((size_t)y * (size_t)im->width + (size_t)x) * 3;
            for (int k = 0; k < p->nseries; k++)
                n += memcmp(px, p->series[k].color.c, 3) == 0;
        }
    return n;
}

TEST(plot_legend_never_covers_plotted_points) {
    /* falling curves through the top left (the old place of the legend); then curves through
     * all four corners, which leave no corner free */
    static const double x[4] = {30, 60, 120, 240};
    static const double fall[3][4] = {{1e-1, 5e-2, 2.5e-2, 1.2e-2}, {2e-1, 1e-2, 5e-4, 2e-5},
                                      {8e-2, 4e-2, 2e-2, 1e-2}};
    static const double corners[2][4] = {{1e-5, 1e-3, 1e-2, 1e-1}, {1e-1, 1e-2, 1e-3, 1e-5}};
    for (int c = 0; c < 2; c++) {
        ww_plot p = {.title = "error", .xlabel = "1 / dt", .ylabel = "m", .log_x = 1, .log_y = 1,
                     .no_legend = 1};
        if (c == 0)
            for (int k = 0; k < 3; k++) ww_plot_add(&p, "a long series name, exact", x, fall[k], 4,
                                                    k ? WW_PLOT_ORANGE : WW_PLOT_BLUE);
        else
            for (int k = 0; k < 2; k++) ww_plot_add(&p, "through the corners", x, corners[k], 4,
                                                    k ? WW_PLOT_GREEN : WW_PLOT_RED);
        ww_image im;
        ENSURE(ww_image_alloc(&im, 600, 480, 3, WW_PIX_U8) == 0);
        ww_plot_fill(&im, WW_PLOT_WHITE);
        ENSURE(ww_plot_draw(&p, &im, 0, 0, 600, 480) > 0);
        int box[4];
        ww_plot_legend_box(&p, 0, 0, 600, 480, box);
        ENSURE(box[2] > box[0] && box[3] > box[1]);
        ENSURE_EQ_INT(series_pixels_in(&im, &p, box), 0);
        /* drawn, the legend is inside the panel and shows each series' swatch */
        p.no_legend = 0;
        ww_plot_fill(&im, WW_PLOT_WHITE);
        ww_plot_draw(&p, &im, 0, 0, 600, 480);
        ENSURE(box[0] >= 0 && box[1] >= 0 && box[2] <= 600 && box[3] <= 480);
        ENSURE(series_pixels_in(&im, &p, box) > 0);
        ww_image_free(&im);
    }
}
