/* test_scene.c - the scene loader: defaults, units, numbers, --set overrides, and every file under
 * tests/bad/ failing with the code and the place written in its first line.
 */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "scene/scene.h"
#include "test.h"

/* values computed the same way as the loader: only rounding of the degree conversion differs */
#define SCENE_VALUE_TOL 1e-12
#define SCENE_ANGLE_TOL 1e-12
#define BAD_MIN_FILES 48

static ww_scene *load_text(const char *text, const ww_set *sets, int nsets, ww_error *err) {
    ww_scene *sc = NULL;
    ww_result r = ww_scene_load_string("inline.yaml", text, strlen(text), sets, nsets, &sc, err);
    if (r != WW_OK) {
        ENSURE(sc == NULL);
        return NULL;
    }
    return sc;
}

static ww_result load_code(const char *text, const ww_set *sets, int nsets, ww_error *err) {
    ww_scene *sc = load_text(text, sets, nsets, err);
    if (sc) {
        ww_scene_free(sc);
        return WW_OK;
    }
    return err->code;
}

static const char *TWO_WAVES =
    "water:\n"
    "  waves:\n"
    "    list:\n"
    "      - {direction: 0, wavelength: 10, amplitude: 0.5}\n"
    "      - {direction: 90, wavelength: 20, amplitude: 0.4}\n";

TEST(scene_defaults_fill_every_field) {
    ww_error err = {0};
    ww_scene *sc = load_text("seed: 5\n", NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_U64(sc->seed, 5);
    ENSURE(sc->dt == 1.0 / 120.0);
    ENSURE_NEAR(sc->fps, 30.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->duration, 10.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->start, 0.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->steps_per_frame, 4);
    ENSURE_EQ_INT(sc->frame_count, 300);
    ENSURE_EQ_INT(sc->width, 1280);
    ENSURE_EQ_INT(sc->height, 720);
    ENSURE_EQ_INT(sc->tonemap, WW_TONEMAP_ACES);
    ENSURE_NEAR(sc->exposure, 1.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->gamma, 2.2, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->time_of_day, 16.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->day_length, 0.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->sun_max_elevation, WW_PI / 3.0, SCENE_ANGLE_TOL);
    for (int i = 0; i < 3; i++) ENSURE(sc->fog_color[i] < 0.0);
    ENSURE_NEAR(sc->fog_density, 0.0004, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_level, 0.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_depth, 8.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_color[0], 0.01, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_color[1], 0.07, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_color[2], 0.15, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->wave_model, WW_WAVES_GERSTNER);
    ENSURE_EQ_INT(sc->nwaves, 0);
    ENSURE_NEAR(sc->fov, WW_PI / 3.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->near_clip, 0.1, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->far_clip, 5000.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->interp, WW_INTERP_CATMULL_ROM);
    ENSURE_EQ_INT(sc->nevents, 0);

    /* no camera: one key at (0, 2, 10) looking at the origin */
    ENSURE_EQ_INT(sc->ncam, 1);
    ENSURE(sc->cam[0].has_look_at);
    ENSURE_NEAR(sc->cam[0].t, 0.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->cam[0].position[1], 2.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->cam[0].position[2], 10.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(ww_m_len3(sc->cam[0].look_at), 0.0, SCENE_VALUE_TOL);
    ENSURE(strcmp(sc->name, "inline") == 0);
    ENSURE(strcmp(sc->path, "inline.yaml") == 0);
    ww_scene_free(sc);
}

/* no path is the default camera; an empty one is an error at the list, not a silent default */
TEST(scene_empty_camera_path_is_an_error) {
    ww_error err = {0};
    ww_scene *sc = load_text("camera:\n  fov: 70\n  path: []\n", NULL, 0, &err);
    ENSURE(sc == NULL);
    ENSURE_EQ_INT(err.code, WW_E_RANGE);
    ENSURE_EQ_INT(err.line, 3);
    ENSURE_EQ_INT(err.column, 9);
    ww_scene_free(sc);
    sc = load_text("camera:\n  fov: 70\n", NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->ncam, 1);
    ENSURE(sc->cam[0].has_look_at);
    ENSURE_NEAR(sc->cam[0].position[2], 10.0, SCENE_VALUE_TOL);
    ww_scene_free(sc);
}

TEST(scene_degrees_become_radians) {
    ww_error err = {0};
    ww_scene *sc = load_text("sky: {sun_max_elevation: 45}\n"
                             "water:\n"
                             "  waves:\n"
                             "    list:\n"
                             "      - {direction: 90, wavelength: 8, amplitude: 0.2, phase: 180}\n"
                             "camera:\n"
                             "  fov: 90\n"
                             "  path:\n"
                             "    - {t: 0, position: [0, 1, 0], yaw: -45, pitch: 30, fov: 20}\n",
                             NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_NEAR(sc->sun_max_elevation, WW_PI / 4.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[0].direction, WW_PI / 2.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[0].dir[0], 0.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[0].dir[1], 1.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[0].phase, WW_PI, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->fov, WW_PI / 2.0, SCENE_ANGLE_TOL);
    ENSURE(!sc->cam[0].has_look_at);
    ENSURE_NEAR(sc->cam[0].yaw, -WW_PI / 4.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->cam[0].pitch, WW_PI / 6.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->cam[0].fov, WW_PI / 9.0, SCENE_ANGLE_TOL);
    ww_scene_free(sc);
}

TEST(scene_fraction_dt_is_exact) {
    ww_error err = {0};
    ww_scene *sc = load_text("time: {dt: 1/120, fps: 60, duration: 2.5}\n", NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE(sc->dt == 1.0 / 120.0);
    ENSURE_EQ_INT(sc->steps_per_frame, 2);
    ENSURE_EQ_INT(sc->frame_count, 150);
    ENSURE_NEAR(ww_scene_frame_time(sc, 150), 2.5, SCENE_VALUE_TOL);
    ww_scene_free(sc);

    /* other number forms; a quoted number is a string */
    ENSURE_EQ_INT(load_code("water: {level: -1.5e1}\n", NULL, 0, &err), WW_OK);
    ENSURE_EQ_INT(load_code("water: {level: +.5}\n", NULL, 0, &err), WW_OK);
    ENSURE_EQ_INT(load_code("water: {level: 3 / -4}\n", NULL, 0, &err), WW_OK);
    ENSURE_EQ_INT(load_code("water: {level: 1/0}\n", NULL, 0, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {level: 0x10}\n", NULL, 0, &err), WW_E_TYPE);
    ENSURE_EQ_INT(load_code("water: {level: '1'}\n", NULL, 0, &err), WW_E_TYPE);
    ENSURE_EQ_INT(load_code("seed: 1.5\n", NULL, 0, &err), WW_E_TYPE);
    ENSURE_EQ_INT(load_code("seed: -1\n", NULL, 0, &err), WW_E_RANGE);
}

TEST(scene_nan_and_inf_in_every_spelling_are_nonfinite) {
    static const char *const words[] = {".nan", ".NaN", "nan", ".inf", "-.Inf", "inf",
                                        "Infinity", "1e999", "-1/0.0000", NULL};
    for (int i = 0; words[i]; i++) {
        char text[64];
        snprintf(text, sizeof text, "water: {level: %s}\n", words[i]);
        ww_error err = {0};
        ww_result want = i == 8 ? WW_E_RANGE : WW_E_NONFINITE; /* the last divides by zero */
        ENSURE_MSG(load_code(text, NULL, 0, &err) == want, "%s: got %s", words[i],
                   ww_result_name(err.code));
        ENSURE_EQ_INT(err.line, 1);
        ENSURE_EQ_INT(err.column, 16);
    }
}

TEST(scene_wave_dispersion_and_given_speed) {
    ww_error err = {0};
    ww_scene *sc = load_text("water:\n"
                             "  waves:\n"
                             "    list:\n"
                             "      - {direction: 0, wavelength: 10, amplitude: 0.5}\n"
                             "      - {direction: 0, wavelength: 20, amplitude: 0.4, speed: 2}\n",
                             NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->nwaves, 2);
    double k0 = WW_TAU / 10.0, k1 = WW_TAU / 20.0;
    ENSURE_NEAR(sc->waves[0].k, k0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[0].omega, sqrt(WW_G * k0), SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[0].speed, sqrt(WW_G / k0), SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[0].steepness, 0.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[1].omega, 2.0 * k1, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[1].speed, 2.0, SCENE_VALUE_TOL);
    ww_scene_free(sc);

    /* flat water has no waves, but its list is still checked */
    sc = load_text("water: {waves: {model: flat, list: [{direction: 0, wavelength: 9, "
                   "amplitude: 1}]}}\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_EQ_INT(sc->wave_model, WW_WAVES_FLAT);
        ENSURE_EQ_INT(sc->nwaves, 0);
        ww_scene_free(sc);
    }
    ENSURE_EQ_INT(load_code("water: {waves: {model: flat, list: [{direction: 0, wavelength: 9, "
                            "amplitude: -1}]}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
}

TEST(scene_events_sorted_stably_with_steps) {
    ww_error err = {0};
    ww_scene *sc = load_text("time: {dt: 1/100, fps: 25, start: 1}\n"
                             "script:\n"
                             "  - {t: 3, time_of_day: 9}\n"
                             "  - {t: 1.5, time_of_day: 7}\n"
                             "  - {t: 3, time_of_day: 10}\n"
                             "  - {t: 0.5, time_of_day: 6}\n"
                             "  - {t: 1.004, time_of_day: 8}\n",
                             NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->nevents, 5);
    static const double want_value[] = {6, 8, 7, 9, 10};
    static const int64_t want_step[] = {0, 1, 50, 200, 200};
    static const int want_line[] = {6, 7, 4, 3, 5};
    for (int i = 0; i < 5; i++) {
        ENSURE_NEAR(sc->events[i].value, want_value[i], SCENE_VALUE_TOL);
        ENSURE_EQ_INT(sc->events[i].step, want_step[i]);
        ENSURE_EQ_INT(sc->events[i].line, want_line[i]);
        ENSURE_EQ_INT(sc->events[i].column, 5);
        ENSURE_EQ_INT(sc->events[i].kind, WW_EV_TIME_OF_DAY);
    }
    ww_scene_free(sc);
}

/* ---- --set ---- */

TEST(scene_set_scalar_and_fraction) {
    ww_set sets[] = {{"time.dt=1/60"}, {"time.fps=60"}, {"seed=99"}};
    ww_error err = {0};
    ww_scene *sc = load_text("time: {dt: 1/120, fps: 30}\nseed: 1\n", sets, 3, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE(sc->dt == 1.0 / 60.0);
    ENSURE_EQ_INT(sc->steps_per_frame, 1);
    ENSURE_EQ_U64(sc->seed, 99);
    ww_scene_free(sc);
}

TEST(scene_set_list_item) {
    ww_set sets[] = {{"water.waves.list[1].amplitude=0.2"}};
    ww_error err = {0};
    ww_scene *sc = load_text(TWO_WAVES, sets, 1, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_NEAR(sc->waves[0].amplitude, 0.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[1].amplitude, 0.2, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[1].wavelength, 20.0, SCENE_VALUE_TOL);
    ww_scene_free(sc);
}

TEST(scene_set_whole_vector_and_enum) {
    ww_set sets[] = {{"render.size=[256,144]"}, {"camera.interpolation=linear"}};
    ww_error err = {0};
    ww_scene *sc = load_text("render: {size: [1920, 1080]}\n", sets, 2, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->width, 256);
    ENSURE_EQ_INT(sc->height, 144);
    ENSURE_EQ_INT(sc->interp, WW_INTERP_LINEAR);
    ww_scene_free(sc);
}

TEST(scene_set_creates_missing_sections_and_appends) {
    ww_set sets[] = {{"fog.above.density=0.01"},
                     {"water.waves.list[2]={direction: 45, wavelength: 5, amplitude: 0.1}"},
                     {"script[0]={t: 1, time_of_day: 6}"},
                     {"camera.path[0].t=0"},
                     {"camera.path[0].position=[1, 2, 3]"},
                     {"camera.path[0].yaw=90"}};
    ww_error err = {0};
    ww_scene *sc = load_text(TWO_WAVES, sets, 6, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_NEAR(sc->fog_density, 0.01, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->nwaves, 3);
    ENSURE_NEAR(sc->waves[2].wavelength, 5.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->nevents, 1);
    ENSURE_NEAR(sc->events[0].value, 6.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->ncam, 1);
    ENSURE(!sc->cam[0].has_look_at);
    ENSURE_NEAR(sc->cam[0].position[2], 3.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->cam[0].yaw, WW_PI / 2.0, SCENE_ANGLE_TOL);
    ww_scene_free(sc);
}

TEST(scene_set_syntax_errors) {
    static const struct {
        const char *text;
        int column;
    } bad[] = {
        {"render.size", 1},                      /* no '=' */
        {"=3", 1},                               /* empty key */
        {"water..level=1", 7},                   /* empty name */
        {"water.waves.list[=1", 17},             /* bad bracket */
        {"water.waves.list[x]=1", 17},           /* not an index */
        {"water.waves.list[0]x=1", 20},          /* junk after ']' */
        {"[0]=1", 1},                            /* index first */
        {"water.waves.list[5].amplitude=1", 17}, /* past the end */
        {"water.waves.list[0].direction.x=1", 31}, /* through a number */
        {"water.waves[0]=1", 12},                /* index into a mapping */
        {"water.level=", 13},                    /* no value */
        {"render.size=[256,144", 21},            /* value is not YAML */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ww_set set = {bad[i].text};
        ww_error err = {0};
        ww_result r = load_code(TWO_WAVES, &set, 1, &err);
        ENSURE_MSG(r == WW_E_SET, "'%s': got %s (%s)", bad[i].text, ww_result_name(r), err.msg);
        ENSURE_MSG(strcmp(err.file, "--set[1]") == 0, "'%s': file %s", bad[i].text, err.file);
        ENSURE_EQ_INT(err.line, 1);
        ENSURE_MSG(err.column == bad[i].column, "'%s': column %d, expected %d (%s)", bad[i].text,
                   err.column, bad[i].column, err.msg);
    }
}

TEST(scene_set_is_validated_like_the_file) {
    /* an unknown key in the path, pointed at in the set text, with a suggestion */
    ww_set unknown[] = {{"seed=2"}, {"water.waves.list[0].amplitde=0.3"}};
    ww_error err = {0};
    ENSURE_EQ_INT(load_code(TWO_WAVES, unknown, 2, &err), WW_E_UNKNOWN_KEY);
    ENSURE(strcmp(err.file, "--set[2]") == 0);
    ENSURE_EQ_INT(err.line, 1);
    ENSURE_EQ_INT(err.column, 21);
    ENSURE_MSG(strstr(err.msg, "'amplitude'") != NULL, "%s", err.msg);

    /* out of range: the place is the value after '=' */
    ww_set range[] = {{"render.tonemap.gamma=9"}};
    ENSURE_EQ_INT(load_code(TWO_WAVES, range, 1, &err), WW_E_RANGE);
    ENSURE(strcmp(err.file, "--set[1]") == 0);
    ENSURE_EQ_INT(err.column, 22);

    /* an element of a flow value keeps its own column */
    ww_set elem[] = {{"render.size=[256, 8]"}};
    ENSURE_EQ_INT(load_code(TWO_WAVES, elem, 1, &err), WW_E_RANGE);
    ENSURE_EQ_INT(err.column, 19);

    /* a set that breaks a rule between values */
    ww_set dt[] = {{"time.dt=0.007"}};
    ENSURE_EQ_INT(load_code(TWO_WAVES, dt, 1, &err), WW_E_INCONSISTENT);
    ENSURE_EQ_INT(err.column, 9);
}

/* ---- files ---- */

TEST(scene_full_file_loads_every_key) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load("tests/data/full.yaml", NULL, 0, &sc, &err);
    ENSURE_MSG(r == WW_OK, "%s:%d:%d: %s", err.file, err.line, err.column, err.msg);
    if (!sc) return;
    ENSURE(strcmp(sc->name, "full") == 0);
    ENSURE(strcmp(sc->path, "tests/data/full.yaml") == 0);
    ENSURE_EQ_U64(sc->seed, 42);
    ENSURE(sc->dt == 1.0 / 240.0);
    ENSURE_NEAR(sc->fps, 24.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->duration, 12.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->start, 3.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->steps_per_frame, 10);
    ENSURE_EQ_INT(sc->frame_count, 300);
    ENSURE_EQ_INT(sc->width, 640);
    ENSURE_EQ_INT(sc->height, 360);
    ENSURE_EQ_INT(sc->tonemap, WW_TONEMAP_ACES);
    ENSURE_NEAR(sc->exposure, 1.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->gamma, 2.4, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->time_of_day, 6.25, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->day_length, 600.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->sun_max_elevation, WW_PI / 4.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->fog_color[0], 0.6, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->fog_color[2], 0.8, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->fog_density, 0.002, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_level, -1.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_depth, 12.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->water_color[1], 0.05, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->wave_model, WW_WAVES_GERSTNER);
    ENSURE_EQ_INT(sc->nwaves, 2);
    ENSURE_NEAR(sc->waves[0].steepness, 0.3, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[0].phase, WW_PI / 2.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[0].dir[0], 1.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[1].speed, 3.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[1].k, WW_TAU / 12.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->fov, ww_m_rad(50.0), SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->near_clip, 0.5, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->far_clip, 2000.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->interp, WW_INTERP_LINEAR);
    ENSURE_EQ_INT(sc->ncam, 2);
    ENSURE(sc->cam[0].has_look_at);
    ENSURE_NEAR(sc->cam[0].fov, ww_m_rad(40.0), SCENE_ANGLE_TOL);
    ENSURE(!sc->cam[1].has_look_at);
    ENSURE_NEAR(sc->cam[1].t, 5.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->cam[1].position[0], 4.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->cam[1].yaw, ww_m_rad(30.0), SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->cam[1].pitch, ww_m_rad(-10.0), SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->cam[1].fov, 0.0, SCENE_ANGLE_TOL);
    ENSURE_EQ_INT(sc->nevents, 2);
    ENSURE_NEAR(sc->events[0].t, 2.5, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->events[0].step, 0); /* before start = 3 s */
    ENSURE_EQ_INT(sc->events[0].line, 45);
    ENSURE_NEAR(sc->events[1].value, 7.0, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->events[1].step, 1200); /* (8 - 3) * 240 */
    ww_scene_free(sc);
}

TEST(scene_missing_file_is_nofile) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    const char *path = "tests/data/no-such-scene.yaml";
    ENSURE_EQ_INT(ww_scene_load(path, NULL, 0, &sc, &err), WW_E_NOFILE);
    ENSURE(sc == NULL);
    ENSURE(strcmp(err.file, path) == 0);
    ENSURE(strstr(err.msg, path) != NULL);
}

/* the first line of a bad file: "# expect: CODE LINE:COLUMN", then optionally "words the message
 * must contain" */
typedef struct expectation {
    char code[32];
    int line, column;
    char text[128];
} expectation;

static int read_expectation(const char *path, expectation *e) {
    size_t len = 0;
    char *buf = ww_test_read_file(path, &len);
    if (!buf) return 0;
    memset(e, 0, sizeof *e);
    int ok = 1;
    if (len == 0) {
        /* an empty file cannot carry its comment: it is empty, with no place */
        snprintf(e->code, sizeof e->code, "empty");
    } else {
        ok = sscanf(buf, "# expect: %31s %d:%d", e->code, &e->line, &e->column) == 3;
        char *nl = strchr(buf, '\n');
        if (nl) *nl = 0;
        char *q0 = strchr(buf, '"'), *q1 = q0 ? strrchr(buf, '"') : NULL;
        if (q0 && q1 > q0) snprintf(e->text, sizeof e->text, "%.*s", (int)(q1 - q0 - 1), q0 + 1);
    }
    free(buf);
    return ok;
}

static int cmp_names(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

TEST(scene_bad_files_fail_with_code_and_place) {
    DIR *d = opendir("tests/bad");
    ENSURE_MSG(d != NULL, "cannot open tests/bad (run from the repository root)");
    if (!d) return;
    char *names[256];
    int n = 0;
    struct dirent *de;
    while ((de = readdir(d)) && n < 256) {
        size_t l = strlen(de->d_name);
        if (l > 5 && strcmp(de->d_name + l - 5, ".yaml") == 0) names[n++] = strdup(de->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof names[0], cmp_names);
    ENSURE_MSG(n >= BAD_MIN_FILES, "only %d files in tests/bad", n);

    for (int i = 0; i < n; i++) {
        char path[512];
        snprintf(path, sizeof path, "tests/bad/%s", names[i]);
        expectation e;
        ENSURE_MSG(read_expectation(path, &e), "%s: first line is not '# expect: CODE L:C'", path);

        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_result r = ww_scene_load(path, NULL, 0, &sc, &err);
        ENSURE_MSG(r != WW_OK && sc == NULL, "%s: loaded, expected %s", path, e.code);
        ww_scene_free(sc);
        ENSURE_MSG(strcmp(ww_result_name(r), e.code) == 0 && err.line == e.line &&
                       err.column == e.column,
                   "%s: got %s %d:%d, expected %s %d:%d (%s)", path, ww_result_name(r), err.line,
                   err.column, e.code, e.line, e.column, err.msg);
        ENSURE_MSG(strcmp(err.file, path) == 0, "%s: error names file '%s'", path, err.file);
        ENSURE_MSG(err.msg[0] && strstr(err.msg, e.text), "%s: message '%s' lacks '%s'", path,
                   err.msg, e.text);
        free(names[i]);
    }
}

TEST_PROC(scene_only_yaml_tree_includes_yaml_h) {
    const char *dir = ww_test_tmpdir("scene_yaml_h");
    ENSURE(dir != NULL);
    if (!dir) return;
    char out[600];
    snprintf(out, sizeof out, "%s/grep.txt", dir);
    ww_test_run("grep -rl '#include <yaml.h>' src", out, NULL);
    char *got = ww_test_read_file(out, NULL);
    ENSURE(got != NULL);
    if (got) ENSURE_MSG(strcmp(got, "src/scene/yaml_tree.c\n") == 0, "yaml.h included by: %s", got);
    free(got);
}

/* ww_scene_defaults is what a file with no sections loads as, so code-built scenes match */
TEST(scene_defaults_match_an_empty_file) {
    ww_scene *a = NULL, d;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load_string("empty-sections.yaml", "seed: 1\n", 8, NULL, 0, &a, &err), WW_OK);
    if (!a) return;
    ww_scene_defaults(&d);
    ENSURE(a->seed == d.seed && a->dt == d.dt && a->fps == d.fps && a->duration == d.duration);
    ENSURE(a->steps_per_frame == d.steps_per_frame && a->frame_count == d.frame_count);
    ENSURE(a->width == d.width && a->height == d.height && a->exposure == d.exposure && a->gamma == d.gamma);
    ENSURE(a->tonemap == d.tonemap && a->time_of_day == d.time_of_day && a->day_length == d.day_length);
    ENSURE(a->sun_max_elevation == d.sun_max_elevation && a->fog_density == d.fog_density);
    ENSURE(a->water_level == d.water_level && a->water_depth == d.water_depth && a->wave_model == d.wave_model);
    ENSURE(a->nwaves == 0 && d.nwaves == 0 && a->nevents == 0 && d.nevents == 0);
    ENSURE(a->fov == d.fov && a->near_clip == d.near_clip && a->far_clip == d.far_clip && a->interp == d.interp);
    ENSURE(a->ncam == 1 && d.ncam == 1 && a->cam[0].t == d.cam[0].t);
    ENSURE(a->cam[0].has_look_at == d.cam[0].has_look_at && a->cam[0].fov == d.cam[0].fov);
    for (int i = 0; i < 3; i++) {
        ENSURE(a->fog_color[i] == d.fog_color[i] && a->water_color[i] == d.water_color[i]);
        ENSURE(a->cam[0].position[i] == d.cam[0].position[i] && a->cam[0].look_at[i] == d.cam[0].look_at[i]);
    }
    ww_scene_free(a);
}

/* ---- wave families, random draws, spectra, fold policy, ripples ---- */

/* steep sines' mean from an independent rule: the average of ((sin + 1) / 2)^e over 20000
 * midpoints of a period (the midpoint rule is spectrally exact for periodic integrands) */
#define STEEP_MEAN_QUADRATURE_TOL 1e-12
/* a direction vector normalised, against the exact fractions */
#define DIRECTION_VECTOR_TOL 1e-15
/* sum Q k A after the clamp against WW_FOLD_CLAMP_SUM: rounding of a short sum */
#define FOLD_CLAMP_TOL 1e-12

static double mean_by_quadrature(double e) {
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i < n; i++) sum += pow((sin(WW_TAU * (i + 0.5) / n) + 1.0) / 2.0, e);
    return sum / n;
}

TEST(scene_waves_sines_and_steep_sines) {
    ww_error err = {0};
    ww_scene *sc = load_text("water:\n"
                             "  waves:\n"
                             "    model: sines\n"
                             "    list:\n"
                             "      - {direction: 30, wavelength: 12, amplitude: 0.25, phase: 90}\n",
                             NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->wave_model, WW_WAVES_SINES);
    ENSURE_EQ_INT(sc->nwaves, 1);
    ENSURE(sc->waves[0].steepness == 0.0 && sc->waves[0].exponent == 1.0);
    ENSURE_NEAR(sc->waves[0].amplitude, 0.25, SCENE_VALUE_TOL);
    ENSURE_NEAR(sc->waves[0].omega, sqrt(WW_G * WW_TAU / 12.0), SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->waves[0].line, 5);
    ENSURE_EQ_INT(sc->waves[0].column, 9);
    ENSURE(sc->fold_sum == 0.0 && sc->nwarnings == 0);
    ww_scene_free(sc);

    /* steep sines: exponent 2 by default, or as given; the mean of the profile from it */
    sc = load_text("water:\n"
                   "  waves:\n"
                   "    model: steep_sines\n"
                   "    list:\n"
                   "      - {direction: 0, wavelength: 8, amplitude: 0.2}\n"
                   "      - {direction: 0, wavelength: 5, amplitude: 0.1, exponent: 4}\n"
                   "      - {direction: 0, wavelength: 3, amplitude: 0.1, exponent: 2.7}\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->nwaves, 3);
    ENSURE(sc->waves[0].exponent == 2.0 && sc->waves[1].exponent == 4.0);
    ENSURE(sc->waves[1].steepness == 0.0);
    /* exact: e = 2 gives (1/2 + 1) / 4 = 3/8; e = 4 gives 35/128 */
    ENSURE_NEAR(sc->waves[0].mean, 0.375, STEEP_MEAN_QUADRATURE_TOL);
    ENSURE_NEAR(sc->waves[1].mean, 35.0 / 128.0, STEEP_MEAN_QUADRATURE_TOL);
    ENSURE_NEAR(sc->waves[2].mean, mean_by_quadrature(2.7), STEEP_MEAN_QUADRATURE_TOL);
    ww_scene_free(sc);

    /* a steepness is checked but only Gerstner models read it: a scene switches family by --set */
    sc = load_text("water: {waves: {model: steep_sines, list: [{direction: 0, "
                   "wavelength: 8, amplitude: 0.2, steepness: 0.5}]}}\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE(sc->waves[0].steepness == 0.0 && sc->waves[0].exponent == 2.0);
        ww_scene_free(sc);
    }
    ENSURE_EQ_INT(load_code("water: {waves: {model: sines, list: [{direction: 0, "
                            "wavelength: 8, amplitude: 0.2, steepness: 1.5}]}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
    /* an exponent is checked but only steep sines read it; speed 0 is deep-water dispersion */
    sc = load_text("water: {waves: {model: gerstner, list: [{direction: 0, wavelength: 8, "
                   "amplitude: 0.2, exponent: 3, speed: 0}]}}\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE(sc->waves[0].exponent == 1.0 && sc->waves[0].steepness == 0.5);
        ENSURE_NEAR(sc->waves[0].omega, sqrt(WW_G * WW_TAU / 8.0), SCENE_VALUE_TOL);
        ww_scene_free(sc);
    }
    ENSURE_EQ_INT(load_code("water: {waves: {model: gerstner, list: [{direction: 0, "
                            "wavelength: 8, amplitude: 0.2, exponent: 65}]}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {waves: {model: steep_sines, list: [{direction: 0, "
                            "wavelength: 8, amplitude: 0.2, exponent: 0.5}]}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
    /* flat water accepts both, so one --set switches any scene to flat */
    ww_set flat[] = {{"water.waves.model=flat"}};
    ENSURE_EQ_INT(load_code("water: {waves: {model: steep_sines, list: [{direction: 0, "
                            "wavelength: 8, amplitude: 0.2, exponent: 3}]}}\n",
                            flat, 1, &err),
                  WW_OK);
    ENSURE_EQ_INT(load_code(TWO_WAVES, flat, 1, &err), WW_OK);
}

TEST(scene_direction_vector_normalises) {
    ww_error err = {0};
    ww_scene *sc = load_text("water:\n"
                             "  waves:\n"
                             "    list:\n"
                             "      - {direction: [3, 4], wavelength: 10, amplitude: 0.1}\n"
                             "      - {direction: [-0.002, 0], wavelength: 10, amplitude: 0.1}\n",
                             NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    ENSURE_NEAR(sc->waves[0].dir[0], 0.6, DIRECTION_VECTOR_TOL);
    ENSURE_NEAR(sc->waves[0].dir[1], 0.8, DIRECTION_VECTOR_TOL);
    ENSURE_NEAR(sc->waves[0].direction, atan2(4.0, 3.0), SCENE_ANGLE_TOL);
    ENSURE_NEAR(sc->waves[1].dir[0], -1.0, DIRECTION_VECTOR_TOL);
    ENSURE_NEAR(sc->waves[1].dir[1], 0.0, DIRECTION_VECTOR_TOL);
    ENSURE_NEAR(sc->waves[1].direction, WW_PI, SCENE_ANGLE_TOL);
    ww_scene_free(sc);

    /* the zero vector, a vector of the wrong length, a non-finite component */
    ENSURE_EQ_INT(load_code("water: {waves: {list: [{direction: [0, 0], wavelength: 9, "
                            "amplitude: 1}]}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
    ENSURE_EQ_INT(err.column, 36); /* the vector */
    ENSURE_EQ_INT(load_code("water: {waves: {list: [{direction: [1, 0, 0], wavelength: 9, "
                            "amplitude: 1}]}}\n",
                            NULL, 0, &err),
                  WW_E_TYPE);
    ENSURE_EQ_INT(load_code("water: {waves: {list: [{direction: [1, .inf], wavelength: 9, "
                            "amplitude: 1}]}}\n",
                            NULL, 0, &err),
                  WW_E_NONFINITE);
    ENSURE_EQ_INT(err.column, 40); /* the component */
}

static const char *RANDOM_WAVES =
    "seed: 3\n"
    "water:\n"
    "  waves:\n"
    "    model: gerstner\n"
    "    list:\n"
    "      - {direction: 0, wavelength: 40, amplitude: 0.3}\n"
    "    random: {count: 24, wavelength: [2, 30], amplitude: [0.02, 0.1], direction: 60,\n"
    "             spread: 90, steepness: 0.2}\n";

TEST(scene_random_waves_seeded_and_in_range) {
    ww_error err = {0};
    ww_scene *a = load_text(RANDOM_WAVES, NULL, 0, &err);
    ww_scene *b = load_text(RANDOM_WAVES, NULL, 0, &err);
    ww_set other[] = {{"seed=4"}};
    ww_scene *c = load_text(RANDOM_WAVES, other, 1, &err);
    ENSURE_MSG(a && b && c, "%s", err.msg);
    if (a && b && c) {
        ENSURE_EQ_INT(a->nwaves, 25);
        ENSURE_EQ_INT(a->wave_random.count, 24);
        ENSURE_NEAR(a->waves[0].wavelength, 40.0, SCENE_VALUE_TOL); /* the list comes first */
        ENSURE(memcmp(a->waves, b->waves, sizeof(ww_wave) * 25) == 0);
        int moved = 0;
        for (int i = 1; i < 25; i++) {
            const ww_wave *w = &a->waves[i];
            ENSURE(w->wavelength >= 2.0 && w->wavelength <= 30.0);
            ENSURE(w->amplitude >= 0.02 && w->amplitude <= 0.1);
            ENSURE(w->direction >= ww_m_rad(15.0) && w->direction <= ww_m_rad(105.0));
            ENSURE(w->phase >= 0.0 && w->phase < WW_TAU);
            ENSURE(w->steepness == 0.2 && w->exponent == 1.0);
            ENSURE_NEAR(w->omega, sqrt(WW_G * WW_TAU / w->wavelength), SCENE_VALUE_TOL);
            ENSURE_EQ_INT(w->line, 7);
            moved += c->waves[i].wavelength != w->wavelength && c->waves[i].phase != w->phase;
        }
        ENSURE_EQ_INT(moved, 24); /* another seed, other draws */
    }
    ww_scene_free(a);
    ww_scene_free(b);
    ww_scene_free(c);

    /* an empty section draws the default 16; sines draw no steepness; steep sines the exponent */
    ww_scene *s = load_text("water: {waves: {model: steep_sines, random: {exponent: 5}}}\n", NULL,
                            0, &err);
    ENSURE_MSG(s != NULL, "%s", err.msg);
    if (s) {
        ENSURE_EQ_INT(s->nwaves, 16);
        ENSURE(s->waves[15].steepness == 0.0 && s->waves[15].exponent == 5.0);
        ENSURE(s->waves[15].wavelength >= 2.0 && s->waves[15].wavelength <= 30.0);
        ww_scene_free(s);
    }
    ENSURE_EQ_INT(load_code("water: {waves: {random: {count: 4, wavelength: [5, 5]}}}\n", NULL, 0,
                            &err),
                  WW_E_INCONSISTENT);
    ENSURE_EQ_INT(load_code("water: {waves: {random: {count: 256}}}\n", NULL, 0, &err), WW_OK);
    ENSURE_EQ_INT(load_code("water: {waves: {random: {count: 257}}}\n", NULL, 0, &err),
                  WW_E_RANGE);
}

TEST(scene_spectrum_model_loads_components) {
    ww_error err = {0};
    ww_scene *sc = load_text("seed: 9\n"
                             "water:\n"
                             "  waves:\n"
                             "    model: spectrum\n"
                             "    spectrum: {kind: jonswap, wind_speed: 12, fetch: 50000, "
                             "gamma: 2, direction: [0, 1],\n"
                             "               spread: 15, count: 48, wavelength: [0.5, 200], "
                             "steepness: 0.4}\n",
                             NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (!sc) return;
    const ww_spectrum_desc *d = &sc->spectrum;
    ENSURE_EQ_INT(sc->wave_model, WW_WAVES_SPECTRUM);
    ENSURE_EQ_INT(d->kind, WW_SPECTRUM_JONSWAP);
    ENSURE_NEAR(d->wind_speed, 12.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(d->fetch, 50000.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(d->gamma, 2.0, SCENE_VALUE_TOL);
    ENSURE_NEAR(d->direction, WW_PI / 2.0, SCENE_ANGLE_TOL);
    ENSURE_NEAR(d->spread, ww_m_rad(15.0), SCENE_ANGLE_TOL);
    ENSURE_NEAR(d->wavelength[0], 0.5, SCENE_VALUE_TOL);
    ENSURE_EQ_INT(sc->nwaves, 48);
    ENSURE_NEAR(sc->fold_sum, 0.4, FOLD_CLAMP_TOL);
    ENSURE(sc->fold_sum == sc->fold_sum_given);
    for (int i = 0; i < sc->nwaves; i++) {
        ENSURE(sc->waves[i].wavelength >= 0.5 * (1 - 1e-12) &&
               sc->waves[i].wavelength <= 200.0 * (1 + 1e-12));
        ENSURE_EQ_INT(sc->waves[i].line, 5);
    }
    ww_scene_free(sc);

    /* the defaults (Pierson-Moskowitz at 8 m/s, 32 components) and the model's exclusions */
    sc = load_text("water: {waves: {model: spectrum}}\n", NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_EQ_INT(sc->spectrum.kind, WW_SPECTRUM_PM);
        ENSURE_EQ_INT(sc->nwaves, 32);
        ENSURE_NEAR(sc->fold_sum, 0.5, FOLD_CLAMP_TOL);
        ww_scene_free(sc);
    }
    ENSURE_EQ_INT(load_code("water: {waves: {model: spectrum, random: {count: 3}}}\n", NULL, 0,
                            &err),
                  WW_E_INCONSISTENT);
    ENSURE_EQ_INT(load_code("water: {waves: {model: gerstner, spectrum: {count: 3}}}\n", NULL, 0,
                            &err),
                  WW_E_INCONSISTENT);
    ENSURE_EQ_INT(load_code("water: {waves: {model: spectrum, spectrum: {steepness: 0.96}}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {waves: {model: spectrum, spectrum: {gamma: 0.5}}}\n", NULL,
                            0, &err),
                  WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {waves: {model: spectrum, spectrum: {wind_speed: 0}}}\n",
                            NULL, 0, &err),
                  WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {waves: {model: spectrum, spectrum: {count: 0}}}\n", NULL, 0,
                            &err),
                  WW_E_RANGE);
    /* a range far from the peak (1 m/s wind peaks at 0.83 m): an empty sea is an error */
    ENSURE_EQ_INT(load_code("water: {waves: {model: spectrum, spectrum: {wind_speed: 1, "
                            "wavelength: [10, 300]}}}\n",
                            NULL, 0, &err),
                  WW_E_INCONSISTENT);
    ENSURE_MSG(strstr(err.msg, "hold almost none") && strstr(err.msg, "0.8327 m"), "%s", err.msg);
}

/* sum Q k A = 0.8 (2 pi / 5) 0.4 + 0.6 (2 pi / 3) 0.2 + 0.9 (2 pi / 4) 0.25
 *           = 0.4021 + 0.2513 + 0.3534 = 1.0068: no wave folds alone, together they do */
static const char *FOLDING =
    "water:\n"
    "  waves:\n"
    "    list:\n"
    "      - {direction: 0, wavelength: 5, amplitude: 0.4, steepness: 0.8}\n"
    "      - {direction: 60, wavelength: 3, amplitude: 0.2, steepness: 0.6}\n"
    "      - {direction: 120, wavelength: 4, amplitude: 0.25, steepness: 0.9}\n";

TEST(scene_fold_policies) {
    double want = 0.8 * WW_TAU / 5.0 * 0.4 + 0.6 * WW_TAU / 3.0 * 0.2 + 0.9 * WW_TAU / 4.0 * 0.25;
    ww_error err = {0};

    /* warn, the default: kept as given, one warning with the place, the sum and the margin */
    ww_scene *sc = load_text(FOLDING, NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_EQ_INT(sc->fold, WW_FOLD_WARN);
        ENSURE_NEAR(sc->fold_sum, want, FOLD_CLAMP_TOL);
        ENSURE(sc->fold_sum == sc->fold_sum_given);
        ENSURE_NEAR(sc->waves[2].steepness, 0.9, SCENE_VALUE_TOL);
        ENSURE_EQ_INT(sc->nwarnings, 1);
        char sum[32], margin[32];
        snprintf(sum, sizeof sum, "sum Q k A = %.6g", want);
        snprintf(margin, sizeof margin, "margin 1 - sum = %.6g", 1.0 - want);
        ENSURE_MSG(strstr(sc->warnings[0], "inline.yaml:2:3: warning: water.waves folds") ==
                           sc->warnings[0] &&
                       strstr(sc->warnings[0], sum) && strstr(sc->warnings[0], margin),
                   "%s", sc->warnings[0]);
        ww_scene_free(sc);
    }

    /* clamp: every Q scaled by one factor, to a sum of 0.9, with a warning saying so */
    ww_set clamp[] = {{"water.fold=clamp"}};
    sc = load_text(FOLDING, clamp, 1, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_NEAR(sc->fold_sum, WW_FOLD_CLAMP_SUM, FOLD_CLAMP_TOL);
        ENSURE_NEAR(ww_waves_fold_sum(sc), WW_FOLD_CLAMP_SUM, FOLD_CLAMP_TOL);
        ENSURE_NEAR(sc->fold_sum_given, want, FOLD_CLAMP_TOL);
        ENSURE_NEAR(sc->waves[0].steepness / 0.8, WW_FOLD_CLAMP_SUM / want, FOLD_CLAMP_TOL);
        ENSURE_NEAR(sc->waves[2].steepness / 0.9, WW_FOLD_CLAMP_SUM / want, FOLD_CLAMP_TOL);
        ENSURE_EQ_INT(sc->nwarnings, 1);
        ENSURE_MSG(strstr(sc->warnings[0], "clamp scaled every steepness") &&
                       strstr(sc->warnings[0], "to a sum of 0.9"),
                   "%s", sc->warnings[0]);
        ww_scene_free(sc);
    }

    /* error: a range error at water.waves */
    ww_set error[] = {{"water.fold=error"}};
    ENSURE_EQ_INT(load_code(FOLDING, error, 1, &err), WW_E_RANGE);
    ENSURE_EQ_INT(err.line, 2);
    ENSURE_EQ_INT(err.column, 3);
    ENSURE_MSG(strstr(err.msg, "folds over itself") && strstr(err.msg, "warn") &&
                   strstr(err.msg, "clamp"),
               "%s", err.msg);

    /* under 1 every policy loads quietly; a typo in the policy is an enum error */
    sc = load_text(TWO_WAVES, error, 1, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_EQ_INT(sc->nwarnings, 0);
        ENSURE_NEAR(sc->fold_sum, 0.5 * WW_TAU / 10.0 * 0.5 + 0.5 * WW_TAU / 20.0 * 0.4,
                    FOLD_CLAMP_TOL);
        ww_scene_free(sc);
    }
    ww_set typo[] = {{"water.fold=clmap"}};
    ENSURE_EQ_INT(load_code(TWO_WAVES, typo, 1, &err), WW_E_ENUM);
    ENSURE(strstr(err.msg, "did you mean 'clamp'") != NULL);
}

TEST(scene_ripples_defaults_and_events) {
    ww_error err = {0};
    /* no section and no events: no pool */
    ww_scene *sc = load_text(TWO_WAVES, NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE(!sc->ripples_on);
        ww_scene_free(sc);
    }

    /* an empty section: the defaults, speed from capillary-gravity dispersion */
    sc = load_text("water: {ripples: {}}\n", NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        const ww_ripple_desc *d = &sc->ripples;
        double k = 4.0 * WW_PI;
        ENSURE(sc->ripples_on);
        ENSURE_NEAR(d->amplitude, 0.05, SCENE_VALUE_TOL);
        ENSURE_NEAR(d->lifetime, 4.0, SCENE_VALUE_TOL);
        ENSURE_EQ_INT(d->max, 64);
        ENSURE_NEAR(d->radial_decay, 0.25, SCENE_VALUE_TOL);
        ENSURE_NEAR(d->time_decay, 0.6, SCENE_VALUE_TOL);
        ENSURE_NEAR(d->wavenumber, k, SCENE_VALUE_TOL);
        ENSURE_NEAR(d->speed, sqrt(WW_G / k + 0.0728 * k / 1000.0), SCENE_VALUE_TOL);
        ww_scene_free(sc);
    }

    /* given values; the default speed follows the wavenumber, a given speed overrides it */
    sc = load_text("water: {ripples: {amplitude: 0.2, lifetime: 3, max: 8, radial_decay: 0.5,\n"
                   "                  time_decay: 1, wavenumber: 100}}\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_EQ_INT(sc->ripples.max, 8);
        ENSURE_NEAR(sc->ripples.speed, sqrt(WW_G / 100.0 + 0.0728 * 100.0 / 1000.0),
                    SCENE_VALUE_TOL);
        ww_scene_free(sc);
    }
    ww_set speed[] = {{"water.ripples.speed=0.3"}};
    sc = load_text("water: {ripples: {wavenumber: 100}}\n", speed, 1, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_NEAR(sc->ripples.speed, 0.3, SCENE_VALUE_TOL);
        ww_scene_free(sc);
    }

    /* events alone turn the pool on; amplitude defaults to the section's; sorted with others */
    sc = load_text("time: {dt: 1/100, fps: 25}\n"
                   "script:\n"
                   "  - {t: 2, ripple: {at: [3, -4], amplitude: 0.1}}\n"
                   "  - {t: 1, time_of_day: 9}\n"
                   "  - {t: 0.5, ripple: {at: [0, 1.5]}}\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE(sc->ripples_on);
        ENSURE_EQ_INT(sc->nevents, 3);
        ENSURE_EQ_INT(sc->events[0].kind, WW_EV_RIPPLE);
        ENSURE_NEAR(sc->events[0].value, 0.05, SCENE_VALUE_TOL);
        ENSURE_NEAR(sc->events[0].at[1], 1.5, SCENE_VALUE_TOL);
        ENSURE_EQ_INT(sc->events[0].step, 50);
        ENSURE_EQ_INT(sc->events[1].kind, WW_EV_TIME_OF_DAY);
        ENSURE_EQ_INT(sc->events[2].kind, WW_EV_RIPPLE);
        ENSURE_NEAR(sc->events[2].value, 0.1, SCENE_VALUE_TOL);
        ENSURE_NEAR(sc->events[2].at[0], 3.0, SCENE_VALUE_TOL);
        ENSURE_NEAR(sc->events[2].at[1], -4.0, SCENE_VALUE_TOL);
        ENSURE_EQ_INT(sc->events[2].step, 200);
        ENSURE_EQ_INT(sc->events[2].line, 3);
        ww_scene_free(sc);
    }
    sc = load_text("water: {ripples: {amplitude: 0.3}}\nscript: [{t: 1, ripple: {at: [0, 0]}}]\n",
                   NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%s", err.msg);
    if (sc) {
        ENSURE_NEAR(sc->events[0].value, 0.3, SCENE_VALUE_TOL);
        ww_scene_free(sc);
    }

    /* bad ripples */
    ENSURE_EQ_INT(load_code("water: {ripples: {max: 257}}\n", NULL, 0, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {ripples: {lifetime: 0}}\n", NULL, 0, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {ripples: {amplitude: 11}}\n", NULL, 0, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {ripples: {wavenumber: 0}}\n", NULL, 0, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_code("water: {ripples: {time_decay: -1}}\n", NULL, 0, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_code("script: [{t: 1, ripple: {at: [0, 0], amplitude: -1}}]\n", NULL, 0,
                            &err),
                  WW_E_RANGE);
    ENSURE_EQ_INT(load_code("script: [{t: 1, ripple: 0.1}]\n", NULL, 0, &err), WW_E_TYPE);
    ENSURE_EQ_INT(load_code("script: [{t: 1, ripple: {at: [0, 0]}, time_of_day: 3}]\n", NULL, 0,
                            &err),
                  WW_E_INCONSISTENT);
    ENSURE(strstr(err.msg, "two actions") != NULL);
}

/* the shipped example scenes load, each with the family its name says and no warnings */
TEST(scene_examples_load) {
    static const struct {
        const char *path;
        ww_wave_model model;
        int ripples;
    } ex[] = {{"scenes/sines.yaml", WW_WAVES_SINES, 0},
              {"scenes/steep_sines.yaml", WW_WAVES_STEEP_SINES, 0},
              {"scenes/spectrum.yaml", WW_WAVES_SPECTRUM, 0},
              {"scenes/ripples.yaml", WW_WAVES_GERSTNER, 1}};
    for (size_t i = 0; i < sizeof ex / sizeof ex[0]; i++) {
        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_result r = ww_scene_load(ex[i].path, NULL, 0, &sc, &err);
        ENSURE_MSG(r == WW_OK, "%s:%d:%d: %s", err.file, err.line, err.column, err.msg);
        if (!sc) continue;
        ENSURE_EQ_INT(sc->wave_model, ex[i].model);
        ENSURE(sc->nwaves > 0);
        ENSURE_EQ_INT(sc->ripples_on, ex[i].ripples);
        ENSURE_EQ_INT(sc->nwarnings, 0);
        ENSURE(sc->width == 256 && sc->height == 144);
        ENSURE(sc->duration >= 2.0 && sc->duration <= 4.0);
        ww_scene_free(sc);
    }
}

/* the format's reference block (every wave key, random and ripples), as documented */
TEST(scene_format_reference_block_loads) {
    ww_error err = {0};
    ww_scene *sc = load_text(
        "water:\n"
        "  fold: warn\n"
        "  waves:\n"
        "    model: gerstner\n"
        "    list:\n"
        "      - {direction: 20, wavelength: 12, amplitude: 0.25, steepness: 0.6, phase: 0, "
        "speed: 0, exponent: 2}\n"
        "    random: {count: 16, wavelength: [2, 30], amplitude: [0.02, 0.1], direction: 0, "
        "spread: 90,\n"
        "             steepness: 0.5, exponent: 2}\n"
        "  ripples: {amplitude: 0.05, lifetime: 4, max: 64, radial_decay: 0.25, time_decay: 0.6,\n"
        "            wavenumber: 12.566}\n"
        "script:\n"
        "  - {t: 2, ripple: {at: [1, -3], amplitude: 0.1}}\n",
        NULL, 0, &err);
    ENSURE_MSG(sc != NULL, "%d:%d: %s", err.line, err.column, err.msg);
    if (!sc) return;
    ENSURE_EQ_INT(sc->nwaves, 17);
    ENSURE(sc->ripples_on && sc->nevents == 1 && sc->events[0].kind == WW_EV_RIPPLE);
    ww_scene_free(sc);
}
