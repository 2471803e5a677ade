/* test_sweep.c - `waterworld sweep`: grid order and values, seeded random points, rows that are
 * the wave statistics of their point, --jobs and --point giving the same bytes as one process,
 * job lines that reproduce their rows, bad --vary stopping before any work, error rows, and the
 * contact sheet of --thumbs (its size, its cells, its labels).
 */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/writers.h"
#include "scene/scene.h"
#include "sim/wave_stats.h"
#include "test.h"
#include "render/contact.h"
#include "sweep/sweep.h"

/* a grid value is one weighted sum ((N-1-k) A + k B) / (N-1): a few ulps of the ends */
#define GRID_VALUE_TOL 1e-15
/* the mean of 2000 uniform draws in [0, 1]: its standard deviation is 0.289 / sqrt(2000) =
 * 0.0065; four of them */
#define RANDOM_MEAN_TOL 0.026
/* the share of one item of three in 2000 draws: sd sqrt(p (1 - p) / n) = 0.0105; four of them */
#define RANDOM_SHARE_TOL 0.042
/* two thumbnails of seas of different heights differ by more than this mean |difference| per
 * channel, in 8-bit levels (measured: 9 to 15 on llvmpipe for the amplitudes below) */
#define THUMB_DIFF_MIN 2.0

static char cmd[4096];

static const char *SCENE = "scenes/minimal.yaml";
static const char *AMP = "water.waves.list[0].amplitude";

static int run_sweep(const char *args, const char *out, const char *errf) {
    snprintf(cmd, sizeof cmd, "%s sweep %s", ww_test_bin(), args);
    return ww_test_run(cmd, out, errf);
}

/* line n (0-based) of text, without its newline, in a malloc'd string; NULL past the end */
static char *line_at(const char *text, int n) {
    const char *p = text;
    for (int i = 0; i < n && p; i++) {
        p = strchr(p, '\n');
        if (p) p++;
    }
    if (!p || !*p) return NULL;
    size_t len = strcspn(p, "\n");
    char *l = malloc(len + 1);
    if (!l) return NULL;
    memcpy(l, p, len);
    l[len] = 0;
    return l;
}

static int count_lines(const char *text) {
    int n = 0;
    for (const char *p = text; p && *p; p++) n += *p == '\n';
    return n;
}

/* field col of a CSV line whose earlier fields hold no quotes */
static void csv_field(const char *line, int col, char *out, size_t cap) {
    const char *p = line;
    for (int i = 0; i < col && p; i++) {
        p = strchr(p, ',');
        if (p) p++;
    }
    size_t len = p ? strcspn(p, ",") : 0;
    if (len >= cap) len = cap - 1;
    if (p) memcpy(out, p, len);
    out[len] = 0;
}

/* the column of name in a CSV header line, or -1 */
static int csv_column(const char *header, const char *name) {
    char f[128];
    for (int c = 0; c < 64; c++) {
        csv_field(header, c, f, sizeof f);
        if (strcmp(f, name) == 0) return c;
        if (!f[0]) break;
    }
    return -1;
}

static ww_sweep *make_sweep(const char *const *vary, int nvary, long long random, uint64_t seed) {
    ww_sweep_opts o = ww_default_sweep_opts();
    o.scene_path = SCENE;
    o.vary = vary;
    o.nvary = nvary;
    o.random = random;
    o.seed = seed;
    o.quiet = 1;
    ww_sweep *s = NULL;
    ww_error err = {0};
    ww_result r = ww_sweep_new(&o, &s, &err);
    ENSURE_MSG(r == WW_OK, "ww_sweep_new: %s", err.msg);
    return s;
}

TEST_PROC(sweep_grid_order_and_values) {
    /* the first axis slowest; A:B:N has N values with both ends; lists keep their words */
    const char *vary[] = {"water.waves.list[0].amplitude=0.1:0.5:5", "water.waves.model=gerstner,flat"};
    ww_sweep *s = make_sweep(vary, 2, 0, 0);
    if (!s) return;
    ENSURE_EQ_INT(ww_sweep_points(s), 10);
    ENSURE_EQ_INT(ww_sweep_axes(s), 2);
    ENSURE(strcmp(ww_sweep_axis_key(s, 0), AMP) == 0);
    char v[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX];
    for (int i = 0; i < 10; i++) {
        ww_sweep_values(s, i, v);
        ENSURE_NEAR(strtod(v[0], NULL), 0.1 + 0.1 * (i / 2), GRID_VALUE_TOL);
        ENSURE(strcmp(v[1], i % 2 ? "flat" : "gerstner") == 0);
    }
    /* the ends exactly as written, and no 0.30000000000000004 in between */
    ww_sweep_values(s, 0, v);
    ENSURE(strcmp(v[0], "0.1") == 0);
    ww_sweep_values(s, 4, v);
    ENSURE(strcmp(v[0], "0.3") == 0);
    ww_sweep_values(s, 9, v);
    ENSURE(strcmp(v[0], "0.5") == 0);
    ww_sweep_free(s);

    /* descending, a single value, and a list whose items are YAML lists (commas inside []) */
    const char *vary2[] = {"water.waves.list[1].direction=30:-30:3", "water.waves.list[0].wavelength=12:99:1",
                           "camera.path[0].position=[0, 3, 12],[0, 5, 12]"};
    s = make_sweep(vary2, 3, 0, 0);
    if (!s) return;
    ENSURE_EQ_INT(ww_sweep_points(s), 6);
    const char *dir[] = {"30", "0", "-30"};
    for (int i = 0; i < 6; i++) {
        ww_sweep_values(s, i, v);
        ENSURE(strcmp(v[0], dir[i / 2]) == 0);
        ENSURE(strcmp(v[1], "12") == 0);
        ENSURE(strcmp(v[2], i % 2 ? "[0, 5, 12]" : "[0, 3, 12]") == 0);
    }
    ww_sweep_free(s);

    /* the CLI prints the same grid in the same order */
    char dir_[512], out[600];
    snprintf(dir_, sizeof dir_, "%s", ww_test_tmpdir("sweep_grid"));
    snprintf(out, sizeof out, "%s/out.csv", dir_);
    ENSURE_EQ_INT(run_sweep("scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.1:0.5:5 "
                            "--vary water.waves.model=gerstner,flat --quiet", out, NULL), 0);
    char *csv = ww_test_read_file(out, NULL);
    ENSURE(csv != NULL);
    if (!csv) return;
    ENSURE_EQ_INT(count_lines(csv), 11);
    char *h = line_at(csv, 0);
    ENSURE(h && strncmp(h, "point,water.waves.list[0].amplitude,water.waves.model,status,count,hs,", 70) == 0);
    ENSURE(h && strstr(h, ",total_amplitude,cube_heave_rms,cube_tilt_rms,boat_heave_rms,"
                              "boat_pitch_rms,message"));
    for (int i = 0; i < 10; i++) {
        char *l = line_at(csv, i + 1);
        char f[64];
        csv_field(l ? l : "", 0, f, sizeof f);
        ENSURE_EQ_INT(atoi(f), i);
        csv_field(l ? l : "", 2, f, sizeof f);
        ENSURE(strcmp(f, i % 2 ? "flat" : "gerstner") == 0);
        free(l);
    }
    free(h);
    free(csv);
}

TEST_PROC(sweep_random_reproducible_for_a_seed) {
    const char *vary[] = {"water.waves.list[0].amplitude=0:1", "water.waves.model=gerstner,flat,sines"};
    ww_sweep *a = make_sweep(vary, 2, 2000, 7), *b = make_sweep(vary, 2, 2000, 7),
             *c = make_sweep(vary, 2, 2000, 8);
    if (!a || !b || !c) return;
    ENSURE_EQ_INT(ww_sweep_points(a), 2000);
    char va[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX], vb[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX],
        vc[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX];
    int same = 1, differ = 0, inside = 1, words[3] = {0, 0, 0};
    double sum = 0.0;
    for (int i = 0; i < 2000; i++) {
        ww_sweep_values(a, i, va);
        ww_sweep_values(b, i, vb);
        ww_sweep_values(c, i, vc);
        same &= strcmp(va[0], vb[0]) == 0 && strcmp(va[1], vb[1]) == 0;
        differ += strcmp(va[0], vc[0]) != 0;
        double x = strtod(va[0], NULL);
        inside &= x >= 0.0 && x <= 1.0;
        sum += x;
        words[0] += strcmp(va[1], "gerstner") == 0;
        words[1] += strcmp(va[1], "flat") == 0;
        words[2] += strcmp(va[1], "sines") == 0;
    }
    ENSURE(same);
    ENSURE(differ > 1990); /* another seed, other points (a tie is a 1-in-2^53 event) */
    ENSURE(inside);
    ENSURE_EQ_INT(words[0] + words[1] + words[2], 2000);
    ENSURE_NEAR(sum / 2000.0, 0.5, RANDOM_MEAN_TOL);
    for (int k = 0; k < 3; k++) ENSURE_NEAR(words[k] / 2000.0, 1.0 / 3.0, RANDOM_SHARE_TOL);
    ww_sweep_free(a);
    ww_sweep_free(b);
    ww_sweep_free(c);

    /* through the CLI: the same seed prints the same bytes, another seed others */
    char dir[512], o1[600], o2[600], o3[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_random"));
    snprintf(o1, sizeof o1, "%s/a.csv", dir);
    snprintf(o2, sizeof o2, "%s/b.csv", dir);
    snprintf(o3, sizeof o3, "%s/c.csv", dir);
    const char *args = "scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.05:0.5 "
                       "--vary water.waves.list[1].direction=-90:90 --random 6 --quiet";
    char full[512];
    snprintf(full, sizeof full, "%s --seed 3", args);
    ENSURE_EQ_INT(run_sweep(full, o1, NULL), 0);
    ENSURE_EQ_INT(run_sweep(full, o2, NULL), 0);
    snprintf(full, sizeof full, "%s --seed 4", args);
    ENSURE_EQ_INT(run_sweep(full, o3, NULL), 0);
    ENSURE(ww_test_files_equal(o1, o2));
    ENSURE(!ww_test_files_equal(o1, o3));
    char *t = ww_test_read_file(o1, NULL);
    ENSURE(t && count_lines(t) == 7);
    free(t);
}

TEST_PROC(sweep_rows_are_the_points_wave_stats) {
    /* every metric cell is ww_wave_stats_compute of the scene loaded with the point's --set,
     * to the last bit (the text is the shortest that reads back as the same double); and hs
     * grows with the amplitude it is swept over */
    char dir[512], out[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_stats"));
    snprintf(out, sizeof out, "%s/out.csv", dir);
    ENSURE_EQ_INT(run_sweep("scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.05:0.45:5 --quiet",
                            out, NULL), 0);
    char *csv = ww_test_read_file(out, NULL);
    ENSURE(csv != NULL);
    if (!csv) return;
    char *h = line_at(csv, 0);
    const char *names[] = {"count", "hs", "peak_period", "mean_wavelength", "max_slope", "fold_sum",
                           "fold_margin", "total_amplitude"};
    int col[8];
    for (int m = 0; m < 8; m++) {
        col[m] = h ? csv_column(h, names[m]) : -1;
        ENSURE_MSG(col[m] > 0, "no column %s", names[m]);
    }
    int status_col = h ? csv_column(h, "status") : -1;
    double prev_hs = -1.0;
    for (int i = 0; i < 5; i++) {
        char *l = line_at(csv, i + 1), f[64], set[128];
        if (!l) {
            ENSURE(l != NULL);
            break;
        }
        csv_field(l, 1, f, sizeof f);
        snprintf(set, sizeof set, "%s=%s", AMP, f);
        ww_set sets[1] = {{set}};
        ww_scene *sc = NULL;
        ww_error err = {0};
        ENSURE(ww_scene_load(SCENE, sets, 1, &sc, &err) == WW_OK);
        if (!sc) {
            free(l);
            break;
        }
        ww_wave_stats st;
        ww_wave_stats_compute(sc, 0, 0, &st);
        double want[8] = {st.count, st.hs, st.peak_period, st.mean_wavelength, st.max_slope,
                          st.fold_sum, st.fold_margin, st.total_amplitude};
        for (int m = 0; m < 8; m++) {
            csv_field(l, col[m], f, sizeof f);
            ENSURE_MSG(strtod(f, NULL) == want[m], "point %d %s: row %s, direct %.17g", i, names[m], f, want[m]);
        }
        csv_field(l, status_col, f, sizeof f);
        ENSURE(strcmp(f, "ok") == 0);
        ENSURE(st.hs > prev_hs);
        prev_hs = st.hs;
        ww_scene_free(sc);
        free(l);
    }
    free(h);
    free(csv);
}

TEST_PROC(sweep_jobs_output_byte_identical) {
    char dir[512], a[600], b[600], args[1024], p[700], q[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_jobs"));
    snprintf(a, sizeof a, "%s/one", dir);
    snprintf(b, sizeof b, "%s/three", dir);
    const char *grid = "scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.05:0.5:4 "
                       "--vary water.waves.list[1].wavelength=2,3.5,bogus --vary water.waves.model=gerstner,flat --quiet";
    snprintf(args, sizeof args, "%s -o %s --jobs 1", grid, a);
    ENSURE_EQ_INT(run_sweep(args, NULL, NULL), 0);
    snprintf(args, sizeof args, "%s -o %s --jobs 3", grid, b);
    ENSURE_EQ_INT(run_sweep(args, NULL, NULL), 0);
    snprintf(p, sizeof p, "%s/sweep.csv", a);
    snprintf(q, sizeof q, "%s/sweep.csv", b);
    ENSURE(ww_test_files_equal(p, q));
    char *t = ww_test_read_file(p, NULL);
    ENSURE(t && count_lines(t) == 25);
    free(t);
    snprintf(p, sizeof p, "%s/sweep.jsonl", a);
    snprintf(q, sizeof q, "%s/sweep.jsonl", b);
    ENSURE(ww_test_files_equal(p, q));
    /* and on stdout, with more workers than points */
    snprintf(p, sizeof p, "%s/one.csv", dir);
    snprintf(q, sizeof q, "%s/many.csv", dir);
    ENSURE_EQ_INT(run_sweep(grid, p, NULL), 0);
    snprintf(args, sizeof args, "%s --jobs 40", grid);
    ENSURE_EQ_INT(run_sweep(args, q, NULL), 0);
    ENSURE(ww_test_files_equal(p, q));
}

TEST_PROC(sweep_emit_jobs_lines_reproduce_rows) {
    char dir[512], outd[600], jobs[600], args[2048], path[700], one[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_emit"));
    snprintf(outd, sizeof outd, "%s/full", dir);
    snprintf(jobs, sizeof jobs, "%s/jobs.sh", dir);
    /* a base --set and a list value that need shell quoting (brackets, a quote, a space) */
    const char *sweep = "scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.1:0.4:2 "
                        "--vary \"water.waves.model=gerstner,'flat'\" --set 'water.waves.list[1].amplitude=0.03' "
                        "--random 5 --seed 11 --quiet";
    snprintf(args, sizeof args, "%s -o %s", sweep, outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, NULL), 0);
    snprintf(path, sizeof path, "%s/sweep.jsonl", outd);
    char *full = ww_test_read_file(path, NULL);
    ENSURE(full && count_lines(full) == 5);

    /* one line per point, each ending in --point I; running line 3 prints row 3 */
    snprintf(args, sizeof args, "%s --emit-jobs", sweep);
    ENSURE_EQ_INT(run_sweep(args, jobs, NULL), 0);
    char *lines = ww_test_read_file(jobs, NULL);
    ENSURE(lines && count_lines(lines) == 5);
    char *l3 = lines ? line_at(lines, 3) : NULL;
    ENSURE(l3 && strstr(l3, " --point 3") && strstr(l3, " --random 5 --seed 11"));
    ENSURE(l3 && strstr(l3, "'water.waves.model=gerstner,'\\''flat'\\'''"));
    snprintf(one, sizeof one, "%s/row3.jsonl", dir);
    if (l3) ENSURE_EQ_INT(ww_test_run(l3, one, NULL), 0);
    char *got = ww_test_read_file(one, NULL), *want = full ? line_at(full, 3) : NULL;
    ENSURE(got && want && strncmp(got, want, strlen(want)) == 0 && got[strlen(want)] == '\n');
    ENSURE(want && strstr(want, "\"point\":3,\"values\":{"));
    free(got);
    free(want);
    free(l3);
    free(lines);

    /* with -o every job writes DIR/points/point_NNNNN.jsonl; their cat is sweep.jsonl */
    char pts[600];
    snprintf(pts, sizeof pts, "%s/parts", dir);
    snprintf(args, sizeof args, "%s -o %s --emit-jobs", sweep, pts);
    ENSURE_EQ_INT(run_sweep(args, jobs, NULL), 0);
    snprintf(args, sizeof args, "sh %s", jobs);
    ENSURE_EQ_INT(ww_test_run(args, NULL, NULL), 0);
    snprintf(args, sizeof args, "cat %s/points/point_*.jsonl", pts);
    snprintf(one, sizeof one, "%s/merged.jsonl", dir);
    ENSURE_EQ_INT(ww_test_run(args, one, NULL), 0);
    ENSURE(ww_test_files_equal(one, path));
    snprintf(one, sizeof one, "%s/points/point_00004.jsonl", pts);
    struct stat sb;
    ENSURE(stat(one, &sb) == 0);
    free(full);
}

TEST_PROC(sweep_bad_vary_exit_2_before_any_work) {
    char dir[512], outd[600], errf[600], args[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_bad"));
    snprintf(outd, sizeof outd, "%s/out", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    const char *bad[] = {
        "--vary water.waves.list[0].amplitude=0.1:0.5",      /* a grid needs N */
        "--vary water.waves.list[0].amplitude=0.1:0.5:0",    /* N < 1 */
        "--vary water.waves.list[0].amplitude=0.1:0.5:2.5",  /* N not whole */
        "--vary water.waves.list[0].amplitude=a:0.5:3",      /* A not a number */
        "--vary water.waves.list[0].amplitude=0:1:2:3",      /* too many colons */
        "--vary water.waves.list[0].amplitude=0.1,,0.2",     /* an empty item */
        "--vary water.waves.list[0].amplitude=",             /* no values */
        "--vary =1,2",                                       /* no key */
        "--vary water.waves.list[0].amplitude",              /* no '=' */
        "--vary water.waves.list[0].amplitude=1,2 --vary water.waves.list[0].amplitude=3,4",
        "--vary water.waves.list[0].amplitude=1,2 --point 2", /* past the last point */
        "--vary water.waves.list[0].amplitude=1,2 --jobs 0",
        "",                                                   /* no axis at all */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(args, sizeof args, "scenes/minimal.yaml %s -o %s", bad[i], outd);
        ENSURE_MSG(run_sweep(args, NULL, errf) == 2, "exit 2 for: %s", bad[i]);
    }
    ENSURE_EQ_INT(run_sweep("scenes/minimal.yaml --vary water.waves.model=flat --thumbs", NULL, errf), 2);
    ENSURE_EQ_INT(run_sweep("--help", errf, NULL), 0);
    char *help = ww_test_read_file(errf, NULL);
    ENSURE(help && strstr(help, "usage: waterworld sweep") && strstr(help, "waterworld join DIR"));
    free(help);
    /* an unknown key: found by loading the first point, named as the axis */
    snprintf(args, sizeof args, "scenes/minimal.yaml --vary water.waves.list[0].amplitud=0.1:0.5:3 -o %s", outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, errf), 2);
    char *e = ww_test_read_file(errf, NULL);
    ENSURE(e && strstr(e, "--vary[1]:1:") && strstr(e, "amplitude"));
    free(e);
    snprintf(args, sizeof args, "scenes/minimal.yaml --vary water.wavez.model=flat -o %s", outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, errf), 2);
    snprintf(args, sizeof args, "does/not/exist.yaml --vary water.waves.model=flat -o %s", outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, errf), 2);
    struct stat sb;
    ENSURE(stat(outd, &sb) != 0); /* nothing written, not even the folder */
}

TEST_PROC(sweep_invalid_point_is_an_error_row) {
    char dir[512], outd[600], path[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_error_row"));
    snprintf(outd, sizeof outd, "%s/out", dir);
    char args[1024];
    snprintf(args, sizeof args, "scenes/minimal.yaml --vary water.waves.list[0].amplitude=-1,0.2 "
             "--vary water.waves.model=gerstner,bogus -o %s --quiet", outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, NULL), 0);
    snprintf(path, sizeof path, "%s/sweep.jsonl", outd);
    char *j = ww_test_read_file(path, NULL);
    ENSURE(j && count_lines(j) == 4);
    char *r0 = j ? line_at(j, 0) : NULL, *r1 = j ? line_at(j, 1) : NULL, *r2 = j ? line_at(j, 2) : NULL,
         *r3 = j ? line_at(j, 3) : NULL;
    /* amplitude -1: out of range, with the axis as the place */
    ENSURE(r0 && strstr(r0, "\"status\":\"error\",\"code\":\"range\"") && strstr(r0, "--vary[1]:1:"));
    ENSURE(r0 && !strstr(r0, "\"metrics\""));
    ENSURE(r1 && strstr(r1, "\"status\":\"error\""));
    ENSURE(r2 && strstr(r2, "\"values\":{\"water.waves.list[0].amplitude\":0.2,\"water.waves.model\":\"gerstner\"}"));
    ENSURE(r2 && strstr(r2, "\"status\":\"ok\",\"metrics\":{\"count\":2,"));
    ENSURE(r3 && strstr(r3, "\"status\":\"error\",\"code\":\"enum\"") && strstr(r3, "--vary[2]:1:"));
    free(r0);
    free(r1);
    free(r2);
    free(r3);
    free(j);
    /* the CSV says the same, metrics left empty */
    snprintf(path, sizeof path, "%s/sweep.csv", outd);
    char *c = ww_test_read_file(path, NULL), *l = c ? line_at(c, 1) : NULL;
    ENSURE(l && strncmp(l, "0,-1,gerstner,error,,,,,,,,,,,,,\"--vary[1]:1:", 45) == 0);
    free(l);
    free(c);

    /* a sea that folds (sum Q k A = 1.3): fold: warn is a row with status warn and the
     * loader's warning, fold: error an error row, fold: clamp a warn row clamped to 0.9 */
    snprintf(args, sizeof args, "scenes/minimal.yaml --set water.waves.list[0].amplitude=4 "
             "--vary water.fold=warn,error,clamp -o %s --quiet", outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, NULL), 0);
    snprintf(path, sizeof path, "%s/sweep.jsonl", outd);
    j = ww_test_read_file(path, NULL);
    r0 = j ? line_at(j, 0) : NULL;
    r1 = j ? line_at(j, 1) : NULL;
    r2 = j ? line_at(j, 2) : NULL;
    ENSURE(r0 && strstr(r0, "\"status\":\"warn\",\"metrics\":{") && strstr(r0, "\"message\":\"scenes/minimal.yaml:"));
    ENSURE(r1 && strstr(r1, "\"status\":\"error\",\"code\":\"range\""));
    ENSURE(r2 && strstr(r2, "\"status\":\"warn\"") && strstr(r2, "\"fold_sum\":0.9"));
    free(r0);
    free(r1);
    free(r2);
    free(j);
}

TEST(sweep_contact_layout_and_text) {
    ww_contact_layout L;
    ENSURE_EQ_INT(ww_contact_plan(7, 3, 160, 90, 3, &L), 0);
    ENSURE_EQ_INT(L.rows, 3);
    ENSURE_EQ_INT(L.label_h, 3 * WW_CONTACT_LINE_H + WW_CONTACT_PAD);
    ENSURE_EQ_INT(L.width, 3 * (160 + WW_CONTACT_GAP) + WW_CONTACT_GAP);
    ENSURE_EQ_INT(L.height, 3 * (90 + L.label_h + WW_CONTACT_GAP) + WW_CONTACT_GAP);
    ENSURE_EQ_INT(ww_contact_plan(200, 200, 160, 90, 2, &L), -1); /* 32804 px wide */

    /* text lands inside its box, and a long line is cut at max_w */
    ww_image im = {0};
    ENSURE(ww_image_alloc(&im, 200, 20, 3, WW_PIX_U8) == 0);
    if (!im.u8) return;
    memset(im.u8, 0, (size_t)200 * 20 * 3);
    const uint8_t white[3] = {255, 255, 255};
    int w = ww_contact_text(&im, 10, 4, 60, "water.waves.list[0].amplitude=0.25", white);
    ENSURE(w <= 60 && w > 40);
    int lit = 0, outside = 0;
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 200; x++) {
            int on = im.u8[(y * 200 + x) * 3] == 255;
            lit += on;
            outside += on && (x < 10 || x >= 70 || y < 4 || y >= 4 + WW_CONTACT_LINE_H);
        }
    ENSURE(lit > 50);
    ENSURE_EQ_INT(outside, 0);
    ww_image_free(&im);
}

TEST_PROC(sweep_thumbs_contact_sheet) {
    /* without GL: a clear failure (exit 3) before any work */
    char dir[512], outd[700], errf[700], args[1400], path[800];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_thumbs"));
    snprintf(outd, sizeof outd, "%s/nogl", dir);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(cmd, sizeof cmd, "WW_EGL_DEVICE=99 %s sweep scenes/minimal.yaml --vary water.waves.model=flat "
             "--thumbs --backend egl -o %s", ww_test_bin(), outd);
    ENSURE_EQ_INT(ww_test_run(cmd, NULL, errf), 3);
    char *e = ww_test_read_file(errf, NULL);
    ENSURE(e && strstr(e, "--thumbs needs a GL backend"));
    free(e);
    struct stat sb;
    ENSURE(stat(outd, &sb) != 0);
    REQUIRE_GL();

    /* three heights of sea and a point that does not load: 2 x 2 cells of 160x90 */
    snprintf(outd, sizeof outd, "%s/out", dir);
    snprintf(args, sizeof args, "scenes/minimal.yaml --vary water.waves.list[0].amplitude=0.05,0.6,-1,1.2 "
             "--thumbs -o %s --jobs 2 --quiet", outd);
    ENSURE_EQ_INT(run_sweep(args, NULL, errf), 0);
    ww_contact_layout L;
    ENSURE_EQ_INT(ww_contact_plan(4, 4, 160, 90, 2, &L), 0);
    ww_image sheet = {0}, th[4] = {{0}};
    ww_error err = {0};
    snprintf(path, sizeof path, "%s/contact_sheet.png", outd);
    ENSURE(ww_read_png(path, &sheet, &err) == WW_OK);
    ENSURE_EQ_INT(sheet.width, L.width);
    ENSURE_EQ_INT(sheet.height, L.height);
    for (int i = 0; i < 4; i++) {
        snprintf(path, sizeof path, "%s/thumbs/point_%05d.png", outd, i);
        ww_result r = ww_read_png(path, &th[i], &err);
        ENSURE_EQ_INT(r, i == 2 ? WW_E_NOFILE : WW_OK); /* no image for the error row */
        if (i != 2) ENSURE(th[i].width == 160 && th[i].height == 90);
    }
    if (sheet.u8 && th[0].u8 && th[1].u8 && th[3].u8 && th[0].width == 160 && th[1].width == 160 &&
        th[3].width == 160) {
        /* the thumbnails differ from one another */
        const int pairs[3][2] = {{0, 1}, {1, 3}, {0, 3}};
        for (int p = 0; p < 3; p++) {
            const ww_image *a = &th[pairs[p][0]], *b = &th[pairs[p][1]];
            double diff = 0.0;
            for (int k = 0; k < 160 * 90; k++)
                for (int c = 0; c < 3; c++)
                    diff += fabs((double)a->u8[k * a->channels + c] - (double)b->u8[k * b->channels + c]);
            diff /= 160.0 * 90.0 * 3.0;
            ENSURE_MSG(diff > THUMB_DIFF_MIN, "thumbnails %d and %d differ by %.3f levels", pairs[p][0],
                       pairs[p][1], diff);
        }
        /* each cell holds its thumbnail pixel for pixel, and a label below it */
        for (int i = 0; i < 4; i++) {
            if (i == 2) continue;
            int x0 = WW_CONTACT_GAP + i * (160 + WW_CONTACT_GAP), y0 = WW_CONTACT_GAP, same = 1;
            for (int y = 0; y < 90; y++)
                for (int x = 0; x < 160; x++)
                    for (int c = 0; c < 3; c++)
                        same &= sheet.u8[((y0 + y) * sheet.width + x0 + x) * sheet.channels + c] ==
                                th[i].u8[(y * 160 + x) * th[i].channels + c];
            ENSURE_MSG(same, "cell %d is not its thumbnail", i);
            int text = 0;
            for (int y = y0 + 90; y < y0 + 90 + L.label_h; y++)
                for (int x = x0; x < x0 + 160; x++)
                    text += sheet.u8[(y * sheet.width + x) * sheet.channels] > 200;
            ENSURE_MSG(text > 40, "cell %d has %d label pixels", i, text);
        }
    }
    ww_image_free(&sheet);
    for (int i = 0; i < 4; i++) ww_image_free(&th[i]);
    snprintf(path, sizeof path, "%s/sweep.jsonl", outd);
    char *j = ww_test_read_file(path, NULL);
    ENSURE(j && strstr(j, "\"thumb\":\"thumbs/point_00003.png\""));
    free(j);
}
