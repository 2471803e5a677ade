/* test_tools.c - the water tools as a user meets them: `probe` (CSV rows, heights equal to
 * ww_water_height, ripples that arrive after their event), `waves --stats` (valid JSON, Hs of a
 * sum of sines), their usage errors, the plot rasteriser, and a tiny `bench waves` run.
 * No timing is asserted.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "io/writers.h"
#include "scene/scene.h"
#include "sim/water.h"
#include "sim/waves.h"
#include "test.h"
#include "bench/plot.h"

/* probe prints %.9g (heights, normals; |values| <= 1 here) and %.12g (times): what the CSV's
 * rounding allows */
#define CSV_PRINT_TOL 1e-8
#define CSV_TIME_TOL 1e-9
/* waves --stats prints %.12g; Hs = 4 sqrt(sum A^2 / 2) is a closed form, so only printing and
 * summation rounding separate them */
#define STATS_PRINT_TOL 1e-9
/* flat water before the ripple's event: nothing at all moves it */
#define FLAT_TOL 1e-12
/* after the event, the ripple is this tall at least somewhere 0.3 m from its centre (its
 * amplitude is 0.1 m, damped by e^(-alpha r) e^(-beta age): far more than this) */
#define RIPPLE_SEEN_MIN 1e-4

static const char gerstner_scene[] =
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    "water:\n"
    "  waves:\n"
    "    model: gerstner\n"
    "    list:\n"
    "      - {direction: 20, wavelength: 12, amplitude: 0.25, steepness: 0.6}\n"
    "      - {direction: -35, wavelength: 5, amplitude: 0.08, steepness: 0.4}\n";

/* ---- a small JSON validator (RFC 8259 grammar, no semantics) ---------------------------------- */


/* the number after "key": (NAN when absent or not a number) */
static double json_get(const char *s, const char *key) {
    char pat[80];
    snprintf(pat, sizeof pat, "\"%s\":", key);
    const char *p = strstr(s, pat);
    if (!p) return NAN;
    char *e = NULL;
    double v = strtod(p + strlen(pat), &e);
    return e == p + strlen(pat) ? NAN : v;
}

/* the numbers of the array after "key": (up to cap); returns how many, -1 when absent */
static int json_get_array(const char *s, const char *key, double *out, int cap) {
    char pat[80];
    snprintf(pat, sizeof pat, "\"%s\":[", key);
    const char *p = strstr(s, pat);
    if (!p) return -1;
    p += strlen(pat);
    int n = 0;
    while (*p && *p != ']' && n < cap) {
        char *e = NULL;
        out[n++] = strtod(p, &e);
        if (e == p) return -1;
        p = *e == ',' ? e + 1 : e;
    }
    return n;
}

TEST(tools_json_validator_knows_bad_json) {
    ENSURE(ww_test_json_valid("{\"a\":[1,2.5e-3,-0.1],\"b\":null,\"c\":\"x\\\"y\"}\n"));
    ENSURE(!ww_test_json_valid("{\"a\":nan}"));
    ENSURE(!ww_test_json_valid("{\"a\":1,}"));
    ENSURE(!ww_test_json_valid("{\"a\":01}"));
    ENSURE(!ww_test_json_valid("{\"a\":1} x"));
}

/* ---- probe ------------------------------------------------------------------------------------ */

typedef struct csv_row {
    double v[7];
} csv_row;

/* the rows of a CSV with a header line; returns how many (up to cap), -1 on a bad line */
static int read_csv(const char *path, int ncols, const char *header, csv_row *rows, int cap) {
    char *s = ww_test_read_file(path, NULL);
    if (!s) return -1;
    int n = 0;
    char *save = NULL;
    char *line = strtok_r(s, "\n", &save);
    if (!line || strcmp(line, header) != 0) {
        free(s);
        return -1;
    }
    while ((line = strtok_r(NULL, "\n", &save)) && n < cap) {
        char *p = line;
        for (int c = 0; c < ncols; c++) {
            char *e = NULL;
            rows[n].v[c] = strtod(p, &e);
            if (e == p || (c + 1 < ncols && *e != ',') || (c + 1 == ncols && *e)) {
                free(s);
                return -1;
            }
            p = e + 1;
        }
        n++;
    }
    free(s);
    return n;
}

TEST_PROC(tools_probe_rows_match_water_height) {
    char dir[512], scene[600], out[600], errf[600], args[2048];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("tools_probe"));
    snprintf(scene, sizeof scene, "%s/sea.yaml", dir);
    snprintf(out, sizeof out, "%s/out.csv", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    ENSURE(ww_test_write_text(scene, gerstner_scene) == 0);

    /* 0.037 s is no multiple of the step: samples fall between steps */
    const double x = 1.5, z = -2.25, t0 = 0.5, t1 = 1.5, every = 0.037;
    snprintf(args, sizeof args, "probe %s --at %g,%g --from %g --to %g --every %g", scene, x, z, t0,
             t1, every);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    csv_row rows[64];
    int n = read_csv(out, 5, "t,height,nx,ny,nz", rows, 64);
    ENSURE_EQ_INT(n, (int)floor((t1 - t0) / every) + 1); /* 28: t0, t0 + every, ... <= t1 */

    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE(ww_scene_load(scene, NULL, 0, &sc, &err) == WW_OK);
    if (!sc) return;
    double phase[WW_MAX_WAVES];
    double hmin = 1e9, hmax = -1e9;
    for (int i = 0; i < n; i++) {
        double t = t0 + i * every;
        ENSURE_NEAR(rows[i].v[0], t, CSV_TIME_TOL);
        ww_waves_phases(sc, t, phase);
        ww_field f = {.sc = sc, .phase = phase, .t = t, .ripples = NULL};
        ww_water_sample s;
        ENSURE(ww_water_height(&f, x, z, NULL, &s));
        ENSURE_NEAR(rows[i].v[1], s.height, CSV_PRINT_TOL);
        for (int c = 0; c < 3; c++) ENSURE_NEAR(rows[i].v[2 + c], s.normal[c], CSV_PRINT_TOL);
        hmin = fmin(hmin, rows[i].v[1]);
        hmax = fmax(hmax, rows[i].v[1]);
    }
    ENSURE(hmax - hmin > 0.05); /* the sea moves over a second: the rows are not one row copied */
    ww_scene_free(sc);

    /* defaults: start to start + duration, one row per frame */
    snprintf(args, sizeof args, "probe %s --at 0,0", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    csv_row many[128];
    ENSURE_EQ_INT(read_csv(out, 5, "t,height,nx,ny,nz", many, 128), 61); /* 2 s at 30 fps, both ends */

    /* several points: x and z columns, one row per point per time */
    snprintf(args, sizeof args, "probe %s --at 0,0 --at=3,4 --from 1 --to 1.1 --every 0.05", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    ENSURE_EQ_INT(read_csv(out, 7, "t,x,z,height,nx,ny,nz", many, 128), 6);
    ENSURE_NEAR(many[1].v[1], 3.0, CSV_PRINT_TOL);
    ENSURE_NEAR(many[1].v[2], 4.0, CSV_PRINT_TOL);
    ENSURE_NEAR(many[5].v[0], 1.1, CSV_TIME_TOL);
}

TEST_PROC(tools_probe_ripple_arrives_after_its_event) {
    char dir[512], scene[600], out[600], errf[600], args[2048];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("tools_probe_ripple"));
    snprintf(scene, sizeof scene, "%s/pond.yaml", dir);
    snprintf(out, sizeof out, "%s/out.csv", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    ENSURE(ww_test_write_text(scene, "time: {dt: 1/120, fps: 30, duration: 3}\n"
                             "water: {waves: {model: flat}}\n"
                             "script:\n"
                             "  - {t: 1, ripple: {at: [2, -1], amplitude: 0.1}}\n") == 0);
    snprintf(args, sizeof args, "probe %s --at 2.3,-1 --from 0 --to 2.5 --every 0.01", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    csv_row rows[300];
    int n = read_csv(out, 5, "t,height,nx,ny,nz", rows, 300);
    ENSURE_EQ_INT(n, 251);
    double before = 0.0, after = 0.0;
    for (int i = 0; i < n; i++) {
        if (rows[i].v[0] < 1.0 - 1e-9)
            before = fmax(before, fabs(rows[i].v[1]));
        else
            after = fmax(after, fabs(rows[i].v[1]));
    }
    ENSURE_NEAR(before, 0.0, FLAT_TOL);
    ENSURE_MSG(after > RIPPLE_SEEN_MIN, "the ripple never reached the probe: max |h| = %g m", after);

    /* at its centre it is there from the step of its event on: a sample between steps (0.995 s)
     * reads the step before, one at 1 s the event's step */
    snprintf(args, sizeof args, "probe %s --at 2,-1 --from 0.985 --to 1.0 --every 0.005", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    ENSURE_EQ_INT(read_csv(out, 5, "t,height,nx,ny,nz", rows, 300), 4);
    ENSURE_NEAR(rows[2].v[0], 0.995, CSV_TIME_TOL);
    ENSURE_NEAR(rows[2].v[1], 0.0, FLAT_TOL);
    ENSURE_MSG(fabs(rows[3].v[1]) > RIPPLE_SEEN_MIN, "no ripple at its centre at its time: h = %g m",
               rows[3].v[1]);
    /* far away, in the same time, it has not arrived or has died out */
    snprintf(args, sizeof args, "probe %s --at 500,500 --from 0 --to 2.5 --every 0.01", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    n = read_csv(out, 5, "t,height,nx,ny,nz", rows, 300);
    ENSURE_EQ_INT(n, 251);
    double far = 0.0;
    for (int i = 0; i < n; i++) far = fmax(far, fabs(rows[i].v[1]));
    ENSURE_NEAR(far, 0.0, FLAT_TOL);
}

TEST_PROC(tools_probe_and_waves_usage_errors_exit_2) {
    char dir[512], scene[600], errf[600], args[2048];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("tools_usage"));
    snprintf(scene, sizeof scene, "%s/sea.yaml", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    ENSURE(ww_test_write_text(scene, gerstner_scene) == 0);
    static const char *const bad[] = {
        "",                                    /* no --at */
        "--at 1",                              /* no z */
        "--at 1,",                             /* empty z */
        "--at x,2",                            /* not a number */
        "--at 1,2,3",                          /* one too many */
        "--at 1,nan",                          /* not finite */
        "--at 1,2 --from 2 --to 1",            /* from after to */
        "--at 1,2 --every 0",                  /* no progress */
        "--at 1,2 --every -0.1",
        "--at 1,2 --from -1",                  /* before the scene's start */
        "--at 1,2 --from 0 --to 1e9 --every 1e-6", /* absurdly many rows */
        "--at 1,2 --frames 3",                 /* not a probe option */
        "--at 1,2 --bogus",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(args, sizeof args, "probe %s %s", scene, bad[i]);
        ENSURE_MSG(ww_test_ww(args, NULL, errf) == 2, "probe %s: exit is not 2", bad[i]);
    }
    ENSURE(ww_test_file_contains(errf, "--bogus"));
    ENSURE_EQ_INT(ww_test_ww("probe --at 1,2", NULL, NULL), 2);                     /* no scene */
    ENSURE_EQ_INT(ww_test_ww("probe does/not/exist.yaml --at 1,2", NULL, NULL), 2); /* no file */
    snprintf(args, sizeof args, "waves %s", scene);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2); /* nothing asked */
    ENSURE(ww_test_file_contains(errf, "--stats"));
    snprintf(args, sizeof args, "waves %s --stats --bogus", scene);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("bench waves --frames 3", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("bench render -o somewhere", NULL, NULL), 2);
    /* help */
    char out[600];
    snprintf(out, sizeof out, "%s/help.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("probe --help", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "usage: waterworld probe"));
    ENSURE_EQ_INT(ww_test_ww("waves --help", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "usage: waterworld waves"));
    ENSURE_EQ_INT(ww_test_ww("bench --help", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "bench waves"));
    ENSURE_EQ_INT(ww_test_ww("--help", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "probe") && ww_test_file_contains(out, "waves"));
}

/* ---- waves --stats ------------------------------------------------------------------------------ */

TEST_PROC(tools_waves_stats_json_of_sines) {
    char dir[512], scene[600], out[600], args[2048];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("tools_waves_stats"));
    snprintf(scene, sizeof scene, "%s/sines.yaml", dir);
    snprintf(out, sizeof out, "%s/out.json", dir);
    ENSURE(ww_test_write_text(scene, "water:\n"
                             "  waves:\n"
                             "    model: sines\n"
                             "    list:\n"
                             "      - {direction: 0, wavelength: 10, amplitude: 0.3}\n"
                             "      - {direction: 45, wavelength: 4, amplitude: 0.1}\n"
                             "      - {direction: 100, wavelength: 25, amplitude: 0.5}\n") == 0);
    snprintf(args, sizeof args, "waves %s --stats", scene);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    char *s = ww_test_read_file(out, NULL);
    ENSURE(s != NULL);
    if (!s) return;
    ENSURE_MSG(ww_test_json_valid(s), "not JSON: %s", s);
    ENSURE(strstr(s, "\"model\":\"sines\"") != NULL);
    static const char *const keys[] = {"count", "hs", "m0", "peak_period", "mean_wavelength",
                                       "max_slope", "slope_bound", "fold_sum", "fold_margin",
                                       "total_amplitude"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        ENSURE_MSG(isfinite(json_get(s, keys[i])), "no number for \"%s\" in %s", keys[i], s);
    const double A[3] = {0.3, 0.1, 0.5}, L[3] = {10.0, 4.0, 25.0};
    double m0 = (A[0] * A[0] + A[1] * A[1] + A[2] * A[2]) / 2.0, sum_a = A[0] + A[1] + A[2];
    ENSURE_NEAR(json_get(s, "count"), 3.0, STATS_PRINT_TOL);
    ENSURE_NEAR(json_get(s, "m0"), m0, STATS_PRINT_TOL);
    ENSURE_NEAR(json_get(s, "hs"), 4.0 * sqrt(m0), STATS_PRINT_TOL);
    ENSURE_NEAR(json_get(s, "total_amplitude"), sum_a, STATS_PRINT_TOL);
    ENSURE_NEAR(json_get(s, "fold_sum"), 0.0, STATS_PRINT_TOL); /* sines do not move sideways */
    double c[8], w[8];
    ENSURE_EQ_INT(json_get_array(s, "phase_speeds", c, 8), 3);
    ENSURE_EQ_INT(json_get_array(s, "wavelengths", w, 8), 3);
    for (int i = 0; i < 3; i++) {
        ENSURE_NEAR(w[i], L[i], STATS_PRINT_TOL);
        ENSURE_NEAR(c[i], sqrt(WW_G * L[i] / WW_TAU), STATS_PRINT_TOL); /* deep water: c^2 = g / k */
    }
    free(s);
}

/* ---- plot --------------------------------------------------------------------------------------- */

TEST(tools_plot_writes_a_png_with_its_line) {
    char dir[512], path[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("tools_plot"));
    snprintf(path, sizeof path, "%s/plot.png", dir);
    const int W = 360, H = 220;
    const double x[] = {1, 8, 32, 128, 256}, y[] = {0.5, 0.9, 2.0, NAN, 9.0};
    const ww_plot_rgb line = {{10, 200, 30}};
    ww_image im;
    ENSURE(ww_image_alloc(&im, W, H, 3, WW_PIX_U8) == 0);
    ww_plot_fill(&im, WW_PLOT_WHITE);
    ww_plot p = {.title = "test", .xlabel = "components", .ylabel = "ms", .log_x = 1, .log_y = 1};
    ww_plot_add(&p, "series", x, y, 5, line);
    ENSURE_EQ_INT(ww_plot_draw(&p, &im, 0, 0, W, H), 4); /* the NaN is skipped */
    ww_error err = {0};
    ENSURE(ww_write_png(path, &im, &err) == WW_OK);
    ww_image_free(&im);

    ww_image back;
    ENSURE(ww_read_png(path, &back, &err) == WW_OK);
    ENSURE_EQ_INT(back.width, W);
    ENSURE_EQ_INT(back.height, H);
    int line_px = 0, colours = 0;
    const unsigned char *first = back.u8;
    for (int i = 0; back.u8 && i < W * H; i++) {
        const unsigned char *px = back.u8 + (size_t)i * (size_t)back.channels;
        if (px[0] == line.c[0] && px[1] == line.c[1] && px[2] == line.c[2]) line_px++;
        if (px[0] != first[0] || px[1] != first[1] || px[2] != first[2]) colours = 1;
    }
    ENSURE(colours);
    ENSURE_MSG(line_px > 100, "only %d pixels of the line colour", line_px);
    ww_image_free(&back);
}

/* ---- bench waves -------------------------------------------------------------------------------- */

TEST_LONG(tools_bench_waves_tiny_prints_its_tables_and_figure) {
    char dir[512], out[600], errf[600], fig[600], args[2048];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("tools_bench_waves"));
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(fig, sizeof fig, "%s/fig/waves.png", dir);
    snprintf(args, sizeof args, "bench waves --tiny -o %s/fig", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    static const char *const heads[] = {"(a) CPU wave evaluation", "family", "sincos", "dbl/sc",
                                        "(b) exact height queries", "margin", "us/query",
                                        "(c) GPU frame", "figure:"};
    for (size_t i = 0; i < sizeof heads / sizeof heads[0]; i++)
        ENSURE_MSG(ww_test_file_contains(out, heads[i]), "no '%s' in the output", heads[i]);
    ENSURE(ww_test_file_contains(out, "steep_sines"));
    ww_image im;
    ww_error err = {0};
    ENSURE(ww_read_png(fig, &im, &err) == WW_OK);
    ENSURE(im.width > 0 && im.height > 0);
    ww_image_free(&im);

    /* --json: every line one JSON object with its part */
    snprintf(args, sizeof args, "bench waves --tiny --json -o %s/fig", dir);
    ENSURE_EQ_INT(ww_test_ww(args, out, errf), 0);
    char *s = ww_test_read_file(out, NULL);
    ENSURE(s != NULL);
    int lines = 0, cpu = 0, query = 0;
    char *save = NULL;
    for (char *line = s ? strtok_r(s, "\n", &save) : NULL; line; line = strtok_r(NULL, "\n", &save)) {
        lines++;
        ENSURE_MSG(ww_test_json_valid(line), "not JSON: %s", line);
        ENSURE(strstr(line, "\"part\":") != NULL);
        cpu += strstr(line, "\"part\":\"cpu\"") != NULL;
        query += strstr(line, "\"part\":\"query\"") != NULL;
    }
    ENSURE_EQ_INT(cpu, 12);   /* 3 families x 4 component counts */
    ENSURE_EQ_INT(query, 18); /* 3 fold margins x 6 iteration caps */
    ENSURE(lines > cpu + query);
    free(s);
}
