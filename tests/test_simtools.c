/* test_simtools.c - the simulation's tools as a user meets them: a --script file merged with the
 * scene's events (order, and errors that name the script file with line and column), the events
 * JSON lines of `simulate --events` (each line parses, fields as emitted), state fields by name
 * and the system that owns each, the short soak (60 s of scenes/soak.yaml: no NaN), and a tiny
 * `bench sim` (the dt table and its figure). No timing is asserted.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/numfmt.h"
#include "scene/scene.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/systems.h"
#include "test.h"
#include "render/sim_out.h"

/* the JSON lines print the shortest text that reads back as the double (core/numfmt.h) */
#define JSON_ROUND_TRIP_TOL 0.0
/* bench sim's systems shares, each printed to 4 decimals, add up to 1 within their rounding */
#define SHARES_ROUNDING_TOL 2e-3

TEST(simtools_json_validator) {
    ENSURE_EQ_INT(ww_test_json_lines("{\"a\":[1,-2.5e3,null,true],\"b\":{\"c\":\"x\\n\"}}\n{}\n"), 2);
    ENSURE_EQ_INT(ww_test_json_lines("{\"a\":nan}\n"), -1);
    ENSURE_EQ_INT(ww_test_json_lines("{\"a\":1,}\n"), -1);
    ENSURE_EQ_INT(ww_test_json_lines("{\"a\":1}"), -1);
    ENSURE_EQ_INT(ww_test_json_lines("{\"a\":01}\n"), -1);
}

/* ---- --script -------------------------------------------------------------------------------- */

static const char script_scene[] =
    "time: {dt: 1/120, fps: 30, duration: 3}\n"
    "script:\n"
    "  - {t: 2, ripple: {at: [1, 1]}}\n"
    "  - {t: 1, time_of_day: 5}\n";

static const char script_file[] =
    "# merged after the scene's events\n"
    "script:\n"
    "  - {t: 1, time_of_day: 9}\n"
    "  - {t: 0.5, ripple: {at: [-1, 2], amplitude: 0.2}}\n";

TEST(simtools_script_merge_order) {
    const char *dir = ww_test_tmpdir("simtools_script_merge_order");
    char scene[512], script[512];
    snprintf(scene, sizeof scene, "%s/scene.yaml", dir);
    snprintf(script, sizeof script, "%s/script.yaml", dir);
    ENSURE(ww_test_write_text(scene, script_scene) == 0);
    ENSURE(ww_test_write_text(script, script_file) == 0);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load_with_script(scene, script, NULL, 0, &sc, &err), WW_OK);
    if (!sc) return;

    /* by time; at t = 1 the scene's event (line 4 of the scene) before the script's (line 3) */
    ENSURE_EQ_INT(sc->nevents, 4);
    ENSURE(sc->events[0].t == 0.5 && sc->events[0].kind == WW_EV_RIPPLE);
    ENSURE(sc->events[0].value == 0.2 && sc->events[0].line == 4);
    ENSURE(sc->events[1].t == 1 && sc->events[1].value == 5 && sc->events[1].line == 4);
    ENSURE(sc->events[2].t == 1 && sc->events[2].value == 9 && sc->events[2].line == 3);
    ENSURE(sc->events[3].t == 2 && sc->events[3].kind == WW_EV_RIPPLE);
    ENSURE(sc->ripples_on);
    for (int i = 0; i < 4; i++) ENSURE(sc->events[i].step == llround(sc->events[i].t * 120));

    /* both clock events fire on step 120, in that order: the script's 9 h is what stays */
    ww_state *st = ww_state_new(sc);
    ENSURE(st != NULL);
    if (st) {
        ENSURE_EQ_INT(ww_sim_advance_to(sc, st, 121, &err), WW_OK);
        ENSURE(st->clock_anchor[0] == 9);
        ENSURE(st->clock_anchor[1] == 1);
    }
    ww_state_free(st);
    ww_scene_free(sc);

    /* no script file: the plain load */
    ENSURE_EQ_INT(ww_scene_load_with_script(scene, NULL, NULL, 0, &sc, &err), WW_OK);
    if (sc) ENSURE_EQ_INT(sc->nevents, 2);
    ww_scene_free(sc);
}

/* the scene with the script's events written into it steps to the same hash as scene + script */
TEST_PROC(simtools_script_same_as_inline) {
    const char *dir = ww_test_tmpdir("simtools_script_same_as_inline");
    char scene[512], script[512], inline_scene[512], out1[512], out2[512];
    snprintf(scene, sizeof scene, "%s/scene.yaml", dir);
    snprintf(script, sizeof script, "%s/script.yaml", dir);
    snprintf(inline_scene, sizeof inline_scene, "%s/inline.yaml", dir);
    snprintf(out1, sizeof out1, "%s/h1.txt", dir);
    snprintf(out2, sizeof out2, "%s/h2.txt", dir);
    ENSURE(ww_test_write_text(scene, script_scene) == 0);
    ENSURE(ww_test_write_text(script, script_file) == 0);
    ENSURE(ww_test_write_text(inline_scene, "time: {dt: 1/120, fps: 30, duration: 3}\n"
                                            "script:\n"
                                            "  - {t: 2, ripple: {at: [1, 1]}}\n"
                                            "  - {t: 1, time_of_day: 5}\n"
                                            "  - {t: 1, time_of_day: 9}\n"
                                            "  - {t: 0.5, ripple: {at: [-1, 2], amplitude: 0.2}}\n") ==
           0);
    char args[2048];
    snprintf(args, sizeof args, "simulate %s --script %s --hash", scene, script);
    ENSURE_EQ_INT(ww_test_ww(args, out1, NULL), 0);
    snprintf(args, sizeof args, "simulate %s --hash", inline_scene);
    ENSURE_EQ_INT(ww_test_ww(args, out2, NULL), 0);
    char *a = ww_test_read_file(out1, NULL), *b = ww_test_read_file(out2, NULL);
    ENSURE(a && b && strlen(a) == 17 && strcmp(a, b) == 0);
    free(a);
    free(b);
    /* without the script the hash differs (the events do something) */
    snprintf(args, sizeof args, "simulate %s --hash", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out2, NULL), 0);
    a = ww_test_read_file(out1, NULL);
    b = ww_test_read_file(out2, NULL);
    ENSURE(a && b && strcmp(a, b) != 0);
    free(a);
    free(b);
}

typedef struct {
    const char *text;
    ww_result code;
    int line, column;
} bad_script;

TEST(simtools_script_errors) {
    const char *dir = ww_test_tmpdir("simtools_script_errors");
    char scene[512], script[512];
    snprintf(scene, sizeof scene, "%s/scene.yaml", dir);
    snprintf(script, sizeof script, "%s/script.yaml", dir);
    ENSURE(ww_test_write_text(scene, script_scene) == 0);
    static const bad_script cases[] = {
        /* an action misspelt: unknown key at the key */
        {"script:\n  - {t: 1, time_of_day: 3}\n  - {t: 2, rippel: {at: [0, 0]}}\n",
         WW_E_UNKNOWN_KEY, 3, 12},
        /* out of range: at the value */
        {"script:\n  - {t: 1, time_of_day: 30}\n", WW_E_RANGE, 2, 25},
        /* a negative time */
        {"script:\n  - {t: -1, time_of_day: 3}\n", WW_E_RANGE, 2, 9},
        /* an event with no time: at its mapping */
        {"script:\n  - {time_of_day: 3}\n", WW_E_MISSING, 2, 5},
        /* two actions in one event */
        {"script:\n  - {t: 1, time_of_day: 3, ripple: {at: [0, 0]}}\n", WW_E_INCONSISTENT, 2,
         28},
        /* anything but script at the top */
        {"script: []\nseed: 4\n", WW_E_UNKNOWN_KEY, 2, 1},
        /* no script at all */
        {"{}\n", WW_E_MISSING, 1, 1},
        /* script not a list */
        {"script: {t: 1}\n", WW_E_TYPE, 1, 9},
        /* not YAML */
        {"script: [\n", WW_E_SYNTAX, 0, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ENSURE(ww_test_write_text(script, cases[i].text) == 0);
        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_result r = ww_scene_load_with_script(scene, script, NULL, 0, &sc, &err);
        ENSURE_MSG(r == cases[i].code, "case %zu: %s, expected %s (%s)", i, ww_result_name(r),
                   ww_result_name(cases[i].code), err.msg);
        ENSURE(sc == NULL);
        ENSURE_MSG(strcmp(err.file, script) == 0, "case %zu: error in '%s'", i, err.file);
        if (cases[i].line)
            ENSURE_MSG(err.line == cases[i].line && err.column == cases[i].column,
                       "case %zu: at %d:%d, expected %d:%d (%s)", i, err.line, err.column,
                       cases[i].line, cases[i].column, err.msg);
        ww_scene_free(sc);
    }

    /* a file that is not there */
    ww_scene *sc = NULL;
    ww_error err = {0};
    char missing[600];
    snprintf(missing, sizeof missing, "%s/none.yaml", dir);
    ENSURE_EQ_INT(ww_scene_load_with_script(scene, missing, NULL, 0, &sc, &err), WW_E_NOFILE);

    /* more events than the scene can hold, scene and script together */
    FILE *f = fopen(script, "w");
    ENSURE(f != NULL);
    if (f) {
        fputs("script:\n", f);
        for (int i = 0; i < WW_MAX_EVENTS - 1; i++) fprintf(f, "  - {t: %d, time_of_day: 3}\n", i);
        fclose(f);
    }
    ENSURE_EQ_INT(ww_scene_load_with_script(scene, script, NULL, 0, &sc, &err), WW_E_RANGE);
    ENSURE(strcmp(err.file, script) == 0 && err.line == 2);
}

TEST_PROC(simtools_script_cli) {
    const char *dir = ww_test_tmpdir("simtools_script_cli");
    char scene[512], script[512], errf[512], args[2048];
    snprintf(scene, sizeof scene, "%s/scene.yaml", dir);
    snprintf(script, sizeof script, "%s/bad.yaml", dir);
    snprintf(errf, sizeof errf, "%s/stderr.txt", dir);
    ENSURE(ww_test_write_text(scene, script_scene) == 0);
    ENSURE(ww_test_write_text(script, "script:\n  - {t: 1, time_of_day: 30}\n") == 0);

    /* bad input: exit 2, "FILE:LINE:COL: error:" of the script file */
    char where[600];
    snprintf(where, sizeof where, "%s:2:25: error:", script);
    snprintf(args, sizeof args, "simulate %s --script %s", scene, script);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, where));
    snprintf(args, sizeof args, "render %s --script %s --format none", scene, script);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, where));
    snprintf(args, sizeof args, "probe %s --script %s --at 0,0", scene, script);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, where));
    /* sweep does not take one */
    snprintf(args, sizeof args, "sweep %s --script %s --vary seed=1,2", scene, script);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, "--script"));
    /* a missing value */
    snprintf(args, sizeof args, "simulate %s --script", scene);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
}

/* ---- events --------------------------------------------------------------------------------- */

/* the writer, on an outbox filled by hand (a scene with the cubes system on and no cubes) */
TEST(simtools_events_jsonl) {
    const char *dir = ww_test_tmpdir("simtools_events_jsonl");
    char path[512];
    snprintf(path, sizeof path, "%s/events.jsonl", dir);
    ww_scene *sc = calloc(1, sizeof *sc);
    ENSURE(sc != NULL);
    if (!sc) return;
    ww_scene_defaults(sc);
    sc->cubes.on = 1;
    ww_scene_plan_systems(sc);
    ww_state *st = ww_state_new(sc);
    ENSURE(st != NULL);
    if (!st) {
        free(sc);
        return;
    }
    ww_error err = {0};
    ENSURE_EQ_INT(ww_sim_advance_to(sc, st, 7, &err), WW_OK);
    ww_events_clear(sc, st);
    const double p0[3] = {1.25, -0.5, 1.0 / 3.0}, p1[3] = {-2e-7, 0, 12345.678};
    ww_emit(sc, st, WW_SE_STONE_SKIP, 3, p0, 4.5, 2);
    ww_emit(sc, st, WW_SE_CHEST_COLLECT, 0, p1, 7, 0);
    ww_emit(sc, st, WW_SE_BOAT_STOP, 0, NULL, NAN, 0);
    FILE *f = fopen(path, "w");
    ENSURE(f != NULL);
    if (f) {
        ENSURE_EQ_INT(ww_sim_events_write(sc, st, f), 3);
        fclose(f);
    }
    char *text = ww_test_read_file(path, NULL);
    ENSURE(text != NULL);
    if (text) {
        ENSURE_EQ_INT(ww_test_json_lines(text), 3);
        long long step = -1;
        double t = -1, x, y, z, m, aux;
        int object = -1;
        char kind[32] = "";
        ENSURE_EQ_INT(sscanf(text,
                             "{\"step\":%lld,\"t\":%lf,\"kind\":\"%31[^\"]\",\"object\":%d,"
                             "\"pos\":[%lf,%lf,%lf],\"magnitude\":%lf,\"aux\":%lf}",
                             &step, &t, kind, &object, &x, &y, &z, &m, &aux),
                      9);
        ENSURE_EQ_INT(step, 7);
        ENSURE_NEAR(t, st->t, JSON_ROUND_TRIP_TOL);
        ENSURE(strcmp(kind, "stone_skip") == 0 && object == 3);
        ENSURE_NEAR(x, p0[0], JSON_ROUND_TRIP_TOL);
        ENSURE_NEAR(y, p0[1], JSON_ROUND_TRIP_TOL);
        ENSURE_NEAR(z, p0[2], JSON_ROUND_TRIP_TOL);
        ENSURE_NEAR(m, 4.5, JSON_ROUND_TRIP_TOL);
        ENSURE_NEAR(aux, 2, JSON_ROUND_TRIP_TOL);
        const char *second = strchr(text, '\n') + 1;
        ENSURE(strstr(second, "\"kind\":\"chest_collect\"") != NULL);
        char pos[128], x1[WW_NUM_TEXT], z1[WW_NUM_TEXT];
        ww_num_text(x1, sizeof x1, p1[0]);
        ww_num_text(z1, sizeof z1, p1[2]);
        snprintf(pos, sizeof pos, "\"pos\":[%s,0,%s]", x1, z1);
        ENSURE(strstr(second, pos) != NULL);
        /* JSON has no NaN: a non-finite magnitude is null */
        ENSURE(strstr(second, "\"kind\":\"boat_stop\",\"object\":0,\"pos\":[0,0,0],"
                              "\"magnitude\":null,\"aux\":0}") != NULL);
    }
    free(text);
    ww_state_free(st);
    free(sc);
}

/* simulate --events on a scene with no object system: an empty file; '-' is stdout */
TEST_PROC(simtools_events_cli) {
    const char *dir = ww_test_tmpdir("simtools_events_cli");
    char path[512], out[512], args[2048];
    snprintf(path, sizeof path, "%s/events.jsonl", dir);
    snprintf(out, sizeof out, "%s/stdout.txt", dir);
    snprintf(args, sizeof args, "simulate scenes/ripples.yaml --frames 10 --events %s", path);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    size_t len = 99;
    char *text = ww_test_read_file(path, &len);
    ENSURE(text != NULL && len == 0);
    free(text);
    snprintf(args, sizeof args, "simulate scenes/ripples.yaml --frames 10 --events - --hash");
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    text = ww_test_read_file(out, &len);
    ENSURE(text != NULL && len == 17);
    free(text);
    /* trace and events into one file: refused */
    snprintf(args, sizeof args, "simulate scenes/ripples.yaml --events %s --trace %s", path, path);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 2);
}

/* the real systems of scenes/soak.yaml: every line parses and names a known kind; its stones
 * skip and sink, its boat starts and its cubes are pressed */
TEST_PROC(simtools_events_soak_scene) {
    const char *dir = ww_test_tmpdir("simtools_events_soak_scene");
    char path[512], args[2048];
    snprintf(path, sizeof path, "%s/events.jsonl", dir);
    snprintf(args, sizeof args, "simulate scenes/soak.yaml --frames 450 --events %s", path);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    char *text = ww_test_read_file(path, NULL);
    ENSURE(text != NULL);
    if (!text) return;
    int n = ww_test_json_lines(text);
    ENSURE(n > 0);
    int known = 0;
    for (const char *p = strstr(text, "\"kind\":\""); p; p = strstr(p + 1, "\"kind\":\"")) {
        char kind[32] = "";
        ENSURE_EQ_INT(sscanf(p, "\"kind\":\"%31[^\"]\"", kind), 1);
        for (int k = 1; k < WW_SE_COUNT; k++)
            if (strcmp(kind, ww_sim_event_name((ww_sim_event_kind)k)) == 0) known++;
    }
    ENSURE_EQ_INT(known, n);
    ENSURE(strstr(text, "\"kind\":\"stone_skip\"") != NULL);
    ENSURE(strstr(text, "\"kind\":\"stone_sink\"") != NULL);
    ENSURE(strstr(text, "\"kind\":\"boat_start\"") != NULL);
    ENSURE(strstr(text, "\"kind\":\"cube_press\"") != NULL);
    free(text);
}

/* ---- fields by name, NaN reports ------------------------------------------------------------ */

/* the system a field belongs to, as the state table says: a WW_SYSTEM_LIST name or "events";
 * NULL for no such field */
static const char *field_system(const char *name) {
#define WW_FIELD_SYSTEM(type, fname, n, sys, comment)                                             \
    if (strcmp(name, #fname) == 0) return sys;
    WW_STATE_FIELDS(WW_FIELD_SYSTEM)
#undef WW_FIELD_SYSTEM
    return NULL;
}

TEST(simtools_fields_by_name) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load("scenes/ripples.yaml", NULL, 0, &sc, &err), WW_OK);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ENSURE(st != NULL);
    if (!st) {
        ww_scene_free(sc);
        return;
    }
    long long n = -1;
    ENSURE(ww_state_field(sc, st, "cam_pos", &n) == st->cam_pos && n == 3);
    ENSURE(ww_state_field(sc, st, "wave_phase", &n) == st->wave_phase && n == sc->nwaves);
    ENSURE(ww_state_field(sc, st, "ripple", &n) == st->ripple && n == 4 * sc->ripples.max);
    /* a system the scene lacks: the field exists, with no values */
    ENSURE(ww_state_field(sc, st, "cube_pos", &n) != NULL && n == 0);
    ENSURE(ww_state_field(sc, st, "no_such_field", &n) == NULL && n == 0);

    ENSURE(strcmp(field_system("cube_pos"), "cubes") == 0);
    ENSURE(strcmp(field_system("boat_pos"), "boat") == 0);
    ENSURE(strcmp(field_system("stone_pos"), "stones") == 0);
    ENSURE(strcmp(field_system("fish_pos"), "fish") == 0);
    ENSURE(strcmp(field_system("lure_pos"), "rod") == 0);
    ENSURE(strcmp(field_system("chest_pos"), "chest") == 0);
    ENSURE(strcmp(field_system("collide_prev"), "collide") == 0);
    ENSURE(strcmp(field_system("cam_pos"), "camera") == 0);
    ENSURE(strcmp(field_system("events"), "events") == 0);
    ENSURE(field_system("no_such_field") == NULL);
    /* every field's system is one of the scene's systems, or the outbox */
#define WW_FIELD_OWNER(type, fname, cnt, sys, comment)                                             \
    {                                                                                             \
        int known = strcmp(sys, "events") == 0;                                                   \
        for (int s_ = 0; s_ < WW_SYS_COUNT; s_++) known |= strcmp(sys, ww_system_name(s_)) == 0;  \
        ENSURE_MSG(known, "%s: system '%s' is not in WW_SYSTEM_LIST", #fname, sys);              \
    }
    WW_STATE_FIELDS(WW_FIELD_OWNER)
#undef WW_FIELD_OWNER

    /* the first non-finite value, named with its system, index and step */
    ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_OK);
    ENSURE_EQ_INT(ww_sim_advance_to(sc, st, 5, &err), WW_OK);
    st->ripple[6] = INFINITY;
    ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_E_NAN);
    ENSURE(strstr(err.msg, "ripples system: ripple[6] = inf at step 5") != NULL);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(simtools_nan_guard_reads_the_live_outbox) {
    /* the guard reads the outbox up to its event count (the slots past it are never written):
     * a NaN in a live event is named, and an emptied outbox passes */
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load("scenes/lake.yaml", NULL, 0, &sc, &err), WW_OK);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    ENSURE(st != NULL);
    if (st) {
        double pos[3] = {1.0, 0.0, -2.0};
        ww_emit(sc, st, WW_SE_STONE_THROW, 0, pos, 3.0, 0.0);
        ww_emit(sc, st, WW_SE_STONE_THROW, 1, pos, NAN, 0.0);
        ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_E_NAN);
        ENSURE(strstr(err.msg, "events system: events[13] = nan") != NULL);
        ww_events_clear(sc, st);
        ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_OK);
        ww_state_free(st);
    }
    ww_scene_free(sc);
}

/* the guard sums the fields of doubles that lie next to each other in one run: an infinity at
 * either end of any field of path's state (but the outbox, whose live part alone is read) is
 * still found and named, and a NaN in a field's padding (never state) does not fail the check.
 * Returns the fields tried; *padded counts those with padding */
static int nan_guard_every_field(const char *path, int *padded) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load(path, NULL, 0, &sc, &err), WW_OK);
    if (!sc) return 0;
    ww_state *st = ww_state_new(sc);
    ENSURE(st != NULL);
    int fields = 0;
    char want[160];
#define TRY_FIELD(type, name, count, sys, comment)                                                \
    if (st && _Generic(st->name, double *: 1, default: 0) && (count) > 0 &&                       \
        strcmp(#name, "events") != 0) {                                                           \
        long long n = (long long)(count), ends[2] = {0, n - 1};                                   \
        double *a = (double *)(void *)st->name;                                                   \
        for (int e = 0; e < 2; e++) {                                                             \
            double keep = a[ends[e]];                                                             \
            a[ends[e]] = INFINITY;                                                                \
            ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_E_NAN);                                \
            snprintf(want, sizeof want, "%s[%lld] = inf", #name, ends[e]);                        \
            ENSURE_MSG(strstr(err.msg, want) != NULL, "%s not named: %s", want, err.msg);         \
            a[ends[e]] = keep;                                                                    \
        }                                                                                         \
        if (n % 2) { /* one double of padding to 16 bytes */                                      \
            a[n] = NAN;                                                                           \
            ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_OK);                                   \
            a[n] = 0.0;                                                                           \
            (*padded)++;                                                                          \
        }                                                                                         \
        fields++;                                                                                 \
    }
    WW_STATE_FIELDS(TRY_FIELD)
#undef TRY_FIELD
    if (st) ENSURE_EQ_INT(ww_state_check(sc, st, &err), WW_OK);
    ww_state_free(st);
    ww_scene_free(sc);
    return fields;
}

TEST(simtools_nan_guard_finds_every_field) {
    /* the lake's state has the outbox, which ends a run, among its fields; the sea of sines has
     * no objects and an empty outbox */
    int padded = 0;
    ENSURE(nan_guard_every_field("scenes/lake.yaml", &padded) > 30);
    ENSURE(nan_guard_every_field("scenes/sines.yaml", &padded) > 3);
    ENSURE(padded > 0);
}

/* ---- soak ------------------------------------------------------------------------------------ */

/* the first minute of `make soak`: every system, 7200 steps at 120 Hz, no NaN or Inf */
TEST_PROC(simtools_soak_short) {
    const char *dir = ww_test_tmpdir("simtools_soak_short");
    char errf[512];
    snprintf(errf, sizeof errf, "%s/stderr.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/soak.yaml --set time.dt=1/120 --set time.fps=30 "
                         "--set time.duration=60 --stats",
                         NULL, errf),
                  0);
    ENSURE(ww_test_file_contains(errf, "(7196 steps of 0.00833333 s)"));
    ENSURE(ww_test_file_contains(errf, "simulated s per wall s"));
}

/* ---- bench sim ------------------------------------------------------------------------------ */

/* `bench sim --tiny --json SCENE` with its figure in the test's own folder: what it printed, NULL
 * (a failed check) when it did not exit 0 or printed nothing */
static char *bench_sim_json(const char *test, const char *scene) {
    const char *dir = ww_test_tmpdir(test);
    char out[512], args[2048];
    snprintf(out, sizeof out, "%s/stdout.txt", dir);
    snprintf(args, sizeof args, "bench sim --tiny --json %s -o %s", scene, dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    char *text = ww_test_read_file(out, NULL);
    ENSURE(text != NULL);
    return text;
}

TEST_PROC(simtools_bench_sim_tiny) {
    const char *dir = ww_test_tmpdir("simtools_bench_sim_tiny");
    char out[512], png[512], args[2048];
    snprintf(out, sizeof out, "%s/stdout.txt", dir);
    snprintf(png, sizeof png, "%s/sim.png", dir);
    snprintf(args, sizeof args, "bench sim --tiny scenes/soak.yaml -o %s", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "dt: soak.yaml, 1 s simulated, error against dt = 1/1920"));
    ENSURE(ww_test_file_contains(out, "\nexact  1/30 "));
    ENSURE(ww_test_file_contains(out, "\nexact  1/240 "));
    ENSURE(ww_test_file_contains(out, "\neuler  1/30 "));
    ENSURE(ww_test_file_contains(out, "\neuler  1/240 "));
    ENSURE(ww_test_file_contains(out, "cube heave m"));
    ENSURE(ww_test_file_contains(out, "sim s/wall s"));
    struct stat sb;
    ENSURE(stat(png, &sb) == 0 && sb.st_size > 1000);

    /* --json: one object per line */
    char *text = bench_sim_json("simtools_bench_sim_tiny_json", "scenes/soak.yaml");
    /* one speed line, a systems line for each of the soak's twelve systems and the step's own
     * work, four dt lines for each of the two integrators, the figure, and a columns line for
     * each of the seven column counts (the soak has archimedes cubes) */
    if (text) ENSURE_EQ_INT(ww_test_json_lines(text), 30);
    free(text);
}

/* the columns table: a row per count with the queries its nodes take, and errors against the
 * fine grid that shrink from one column to eight (what the speed costs is not asserted) */
TEST_PROC(simtools_bench_sim_columns_speed_against_error) {
    char *text = bench_sim_json("simtools_bench_sim_columns", "scenes/cubes.yaml");
    if (!text) return;
    static const int counts[] = {1, 2, 3, 4, 5, 6, 8};
    double volume[7] = {0}, moment[7] = {0};
    for (int k = 0; k < 7; k++) {
        char want[96];
        snprintf(want, sizeof want, "\"part\":\"columns\",\"scene\":\"cubes.yaml\",\"columns\":%d,",
                 counts[k]);
        const char *line = strstr(text, want);
        ENSURE_MSG(line != NULL, "no columns line for %d", counts[k]);
        if (!line) continue;
        int m = ww_box_nodes_per_side(counts[k]);
        ENSURE_EQ_INT((int)ww_test_json_number(line, "queries"), m * m);
        volume[k] = ww_test_json_number(line, "volume_error");
        moment[k] = ww_test_json_number(line, "moment_error");
        ENSURE(volume[k] >= 0.0 && moment[k] >= 0.0);
        ENSURE(ww_test_json_number(line, "us_per_step") > 0.0);
    }
    printf("  volume error 1x1 %.2e, 4x4 %.2e, 8x8 %.2e\n", volume[0], volume[3], volume[6]);
    ENSURE_MSG(volume[6] < volume[3] && volume[3] < volume[0], "volume errors %.2e %.2e %.2e",
               volume[0], volume[3], volume[6]);
    ENSURE_MSG(moment[6] < moment[3] && moment[3] < moment[0], "moment errors %.2e %.2e %.2e",
               moment[0], moment[3], moment[6]);
    free(text);
    /* a scene without archimedes cubes has no columns table */
    text = bench_sim_json("simtools_bench_sim_columns_demo", "scenes/demo.yaml");
    ENSURE(text && !strstr(text, "\"part\":\"columns\""));
    free(text);
}

/* the speed row runs the scene's own run (what `simulate SCENE` steps: (frames - 1) x steps a
 * frame, 2396 on the lake) again and again from step 0, and the lake's is set against the
 * simulation's target; what the row measures is not asserted, only what it covers and says */
TEST_PROC(simtools_bench_sim_speed_over_the_scene_run) {
    const char *dir = ww_test_tmpdir("simtools_bench_sim_run");
    char out[512], args[2048];
    snprintf(out, sizeof out, "%s/stdout.txt", dir);
    snprintf(args, sizeof args, "bench sim --tiny --json scenes/lake.yaml -o %s", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "\"part\":\"speed\",\"scene\":\"lake.yaml\""));
    ENSURE(ww_test_file_contains(out, "\"run_steps\":2396,"));
    snprintf(args, sizeof args, "bench sim --tiny scenes/lake.yaml -o %s", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "target: lake.yaml at >= 2000x real time: "));
    ENSURE(ww_test_file_contains(out, "x, met\n") || ww_test_file_contains(out, "x, missed\n"));
    /* a scene without the target prints no target line */
    snprintf(args, sizeof args, "bench sim --tiny scenes/soak.yaml -o %s", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    ENSURE(!ww_test_file_contains(out, "target: "));
}

/* the step by system: a row for each system the scene runs and one for the step's own work,
 * none for a system it lacks, each with its calls a step; what the times are is not asserted,
 * only that they are there and the shares add up */
TEST_PROC(simtools_bench_sim_systems_breakdown) {
    char *text = bench_sim_json("simtools_bench_sim_systems", "scenes/lake.yaml");
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load("scenes/lake.yaml", NULL, 0, &sc, &err), WW_OK);
    if (!text || !sc) {
        free(text);
        ww_scene_free(sc);
        return;
    }
    int nrows, rows_seen = 0;
    const ww_system_row *rows = ww_systems(&nrows);
    double shares = 0.0;
    for (int i = 0; i <= nrows; i++) {
        const char *name = i < nrows ? ww_system_name(rows[i].id) : "step";
        char want[160];
        snprintf(want, sizeof want,
                 "\"part\":\"systems\",\"scene\":\"lake.yaml\",\"system\":\"%s\",", name);
        const char *line = strstr(text, want);
        int runs = i == nrows || ww_system_runs(sc, &rows[i]);
        ENSURE_MSG((line != NULL) == runs, "%s: %s a systems line", name,
                   runs ? "wanted" : "did not want");
        if (!line) continue;
        rows_seen++;
        double us = ww_test_json_number(line, "us_per_step");
        double share = ww_test_json_number(line, "share");
        double calls = ww_test_json_number(line, "calls_per_step");
        ENSURE_MSG(us >= 0.0 && share >= 0.0 && share <= 1.0, "%s: %g us, share %g", name, us,
                   share);
        /* every system the lake runs has a hook in each step; the step's own work is two (the
         * outbox, the NaN guard) */
        ENSURE_MSG(calls >= (i == nrows ? 2.0 : 1.0), "%s: %g calls a step", name, calls);
        shares += share;
    }
    ENSURE(rows_seen >= 10);
    ENSURE_NEAR(shares, 1.0, SHARES_ROUNDING_TOL);
    free(text);
    ww_scene_free(sc);
}

/* ten simulated minutes of the soak scene, every system on, at 120 Hz: no NaN or Inf (exit 3
 * would name it), every step taken; the hour of `make soak` in small */
TEST_LONG(simtools_soak_ten_minutes) {
    const char *dir = ww_test_tmpdir("simtools_soak_long");
    char errf[512];
    snprintf(errf, sizeof errf, "%s/stderr.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/soak.yaml --set time.dt=1/120 --set time.fps=30 "
                             "--set time.duration=600 --stats",
                             NULL, errf),
                  0);
    ENSURE(ww_test_file_contains(errf, "(71996 steps of 0.00833333 s)"));
}
