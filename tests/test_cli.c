/* test_cli.c - the command line as a user meets it: exit codes, messages with file:line:column,
 * nothing written on bad input, --help, determinism hashes, traces, frame slices, EXR output,
 * the layering rule, and memory that does not grow with the number of frames.
 */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/writers.h"
#include "test.h"

/* the state hash of scenes/demo.yaml after its last frame; re-pin only for an intended change
 * in the simulation (the failure message prints the new value) */
#define DEMO_HASH "26b170fbe011d8cf"

/* EXR stores half floats: 11 significant bits */
#define HALF_REL_TOL (1.0 / 2048.0)

static char cmd[2048];

static int count_files(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (e->d_name[0] != '.') n++;
    closedir(d);
    return n;
}

TEST_PROC(cli_help_and_version) {
    char dir[512], out[600], args[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_help"));
    snprintf(out, sizeof out, "%s/out.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("--help", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "render"));
    ENSURE_EQ_INT(ww_test_ww("--version", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "waterworld 0."));
    const char *cmds[] = {"render", "simulate", "plan", "bench"};
    for (int i = 0; i < 4; i++) {
        snprintf(args, sizeof args, "%s --help", cmds[i]);
        ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
        ENSURE(ww_test_file_contains(out, "usage: waterworld"));
    }
    ENSURE_EQ_INT(ww_test_ww("", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("frobnicate", NULL, NULL), 2);
}

TEST_PROC(cli_usage_errors_exit_2) {
    ENSURE_EQ_INT(ww_test_ww("render", NULL, NULL), 2);                                   /* no scene */
    ENSURE_EQ_INT(ww_test_ww("render scenes/minimal.yaml --format gif", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("render scenes/minimal.yaml --backend vulkan", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("render scenes/minimal.yaml --size 10x10", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("render scenes/minimal.yaml --frames 5:3", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("render scenes/minimal.yaml --frames 0:31", NULL, NULL), 2); /* 30 frames */
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/minimal.yaml --bogus", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/minimal.yaml --frames", NULL, NULL), 2);
}

TEST_PROC(cli_bad_scene_exit_2_with_place_and_nothing_written) {
    char dir[512], errf[600], args[1400], outdir[600], scene[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_bad_scene"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(outdir, sizeof outdir, "%s/frames", dir);
    snprintf(scene, sizeof scene, "%s/cli_bad.yaml", dir);
    ENSURE_EQ_INT(ww_test_write_text(scene, "time: {fps: 30}\nwater:\n  waves:\n    list:\n      - "
                                            "{direction: 0, wavelenght: 3, amplitude: 0.1}\n"), 0);
    snprintf(args, sizeof args, "render %s -o %s", scene, outdir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    char place[700];
    snprintf(place, sizeof place, "%s:5:", scene);
    ENSURE(ww_test_file_contains(errf, place));
    ENSURE(ww_test_file_contains(errf, "wavelength"));
    struct stat sb;
    ENSURE(stat(outdir, &sb) != 0); /* not even the folder */
    /* a --set error names the override */
    snprintf(args, sizeof args, "simulate scenes/minimal.yaml --set water.waves.list[0].amplitude=-1");
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, "--set[1]:1:"));
    ENSURE_EQ_INT(ww_test_ww("simulate does/not/exist.yaml", NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, "does/not/exist.yaml"));
}

TEST_PROC(cli_runtime_failures_exit_3) {
    char dir[512], errf[600], args[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_runtime"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    /* an output folder that cannot be made (a path component is a regular file) is bad input,
     * found before any work (test_bounds.c): exit 2, not 3 */
    snprintf(args, sizeof args, "render scenes/minimal.yaml --frames 1 -o %s/err.txt/frames", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, "err.txt/frames"));
    /* a backend that cannot open: the message says why and what to do */
    REQUIRE_GL();
    snprintf(cmd, sizeof cmd, "WW_EGL_DEVICE=99 %s render scenes/minimal.yaml --frames 1 --backend egl -o %s/x",
             ww_test_bin(), dir);
    ENSURE_EQ_INT(ww_test_run(cmd, NULL, errf), 3);
    ENSURE(ww_test_file_contains(errf, "WW_EGL_DEVICE"));
    ENSURE_EQ_INT(count_files(dir), 1); /* only err.txt: no frame folder */
}

TEST_PROC(cli_simulate_hash_pinned_and_repeatable) {
    char dir[512], a[600], b[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_hash"));
    snprintf(a, sizeof a, "%s/a.txt", dir);
    snprintf(b, sizeof b, "%s/b.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/demo.yaml --hash", a, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/demo.yaml --hash", b, NULL), 0);
    char *ha = ww_test_read_file(a, NULL), *hb = ww_test_read_file(b, NULL);
    ENSURE(ha && hb);
    if (ha && hb) {
        ENSURE(strcmp(ha, hb) == 0);
        ENSURE_MSG(strncmp(ha, DEMO_HASH, 16) == 0, "demo hash %.16s, pinned %s", ha, DEMO_HASH);
    }
    free(ha);
    free(hb);
    /* a --set that changes how the sea moves changes the hash */
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/demo.yaml --hash --set water.waves.list[0].wavelength=17", b, NULL), 0);
    ha = ww_test_read_file(a, NULL);
    hb = ww_test_read_file(b, NULL);
    ENSURE(ha && hb && strcmp(ha, hb) != 0);
    free(ha);
    free(hb);
}

TEST_PROC(cli_simulate_trace_one_line_per_frame) {
    char dir[512], tr[600], args[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_trace"));
    snprintf(tr, sizeof tr, "%s/trace.jsonl", dir);
    snprintf(args, sizeof args, "simulate scenes/demo.yaml --frames 10:20 --trace %s", tr);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    char *s = ww_test_read_file(tr, NULL);
    ENSURE(s != NULL);
    if (!s) return;
    int lines = 0;
    for (char *p = s; *p; p++) lines += *p == '\n';
    ENSURE_EQ_INT(lines, 10);
    ENSURE(strncmp(s, "{\"frame\":10,", 12) == 0);
    ENSURE(strstr(s, "\"cam_pos\":[") && strstr(s, "\"sun_dir\":[") && strstr(s, "\"wave_phase\":["));
    ENSURE(strstr(s, "\"time_of_day\":"));
    free(s);
    ENSURE_EQ_INT(count_files(dir), 1); /* no temporary left */
}

TEST_PROC(cli_plan_lists_systems_and_passes) {
    char dir[512], out[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_plan"));
    snprintf(out, sizeof out, "%s/plan.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("plan scenes/demo.yaml", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "waves"));
    ENSURE(ww_test_file_contains(out, "5 gerstner waves"));
    ENSURE(ww_test_file_contains(out, "main"));
    ENSURE(ww_test_file_contains(out, "tonemap"));
    ENSURE(ww_test_file_contains(out, "1280x720"));
    ENSURE(ww_test_file_contains(out, "gpu memory"));
    /* a flat sea runs no wave system */
    ENSURE_EQ_INT(ww_test_ww("plan scenes/minimal.yaml --set water.waves.model=flat", out, NULL), 0);
    ENSURE(!ww_test_file_contains(out, "gerstner waves"));
}

TEST_PROC(cli_render_slice_is_byte_identical_to_full_run) {
    REQUIRE_GL();
    char dir[512], full[600], part[600], args[1400];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_slice"));
    snprintf(full, sizeof full, "%s/full", dir);
    snprintf(part, sizeof part, "%s/part", dir);
    snprintf(args, sizeof args, "render scenes/demo.yaml --size 256x144 --frames 32 -o %s --quiet", full);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(args, sizeof args, "render scenes/demo.yaml --size 256x144 --frames 30:32 -o %s --quiet", part);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    ENSURE_EQ_INT(count_files(full), 32);
    ENSURE_EQ_INT(count_files(part), 2);
    for (int f = 30; f < 32; f++) {
        char pa[700], pb[700];
        snprintf(pa, sizeof pa, "%s/frame_%05d.png", full, f);
        snprintf(pb, sizeof pb, "%s/frame_%05d.png", part, f);
        size_t na = 0, nb = 0;
        char *a = ww_test_read_file(pa, &na), *b = ww_test_read_file(pb, &nb);
        ENSURE(a && b && na == nb && na > 1000 && memcmp(a, b, na) == 0);
        free(a);
        free(b);
    }
    /* and frame 30 differs from frame 0: the camera moved */
    char p0[700], p30[700];
    snprintf(p0, sizeof p0, "%s/frame_00000.png", full);
    snprintf(p30, sizeof p30, "%s/frame_00030.png", full);
    size_t n0 = 0, n30 = 0;
    char *a = ww_test_read_file(p0, &n0), *b = ww_test_read_file(p30, &n30);
    ENSURE(a && b && (n0 != n30 || memcmp(a, b, n0) != 0));
    free(a);
    free(b);
}

TEST_PROC(cli_render_exr_reads_back_linear_hdr) {
    REQUIRE_GL();
    char dir[512], args[1024], path[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_exr"));
    /* the exp curve, which the check below applies to the EXR's pixels */
    snprintf(args, sizeof args, "render scenes/minimal.yaml --format exr --frames 1 -o %s --quiet "
             "--set render.tonemap.operator=exp", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(path, sizeof path, "%s/frame_00000.exr", dir);
    ww_image hdr, ldr;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_read_exr(path, &hdr, &err), WW_OK);
    ENSURE_EQ_INT(hdr.width, 256);
    ENSURE_EQ_INT(hdr.height, 144);
    ENSURE_EQ_INT(hdr.channels, 4);
    /* the same frame as PNG: the tone-mapped EXR pixel gives the PNG pixel */
    snprintf(args, sizeof args, "render scenes/minimal.yaml --format png --frames 1 -o %s --quiet "
             "--set render.tonemap.operator=exp", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(path, sizeof path, "%s/frame_00000.png", dir);
    ENSURE_EQ_INT(ww_read_png(path, &ldr, &err), WW_OK);
    if (hdr.f32 && ldr.u8) {
        /* a sky pixel near the top centre: linear, positive, blue-dominated, and
         * 1 - exp(-E c) with E = 1, gamma 2.2 reproduces the PNG's byte within rounding
         * (plus the half-float error of the EXR) */
        int x = 128, y = 4;
        const float *px = hdr.f32 + ((size_t)y * 256 + (size_t)x) * 4;
        ENSURE(px[0] > 0 && px[2] > px[0]);
        ENSURE_NEAR(px[3], 1.0, HALF_REL_TOL);
        for (int c = 0; c < 3; c++) {
            double v = pow(1.0 - exp(-(double)px[c]), 1.0 / 2.2) * 255.0;
            ENSURE_NEAR(v, ldr.u8[((size_t)y * 256 + (size_t)x) * 3 + (size_t)c], 1.0 + 255.0 * HALF_REL_TOL);
        }
    }
    int frame = 0;
    double t = 0;
    char scene[64], renderer[128];
    snprintf(path, sizeof path, "%s/frame_00000.exr", dir);
    ENSURE_EQ_INT(ww_read_exr_meta(path, &frame, &t, scene, sizeof scene, renderer, sizeof renderer, &err),
                  WW_OK);
    ENSURE_EQ_INT(frame, 0);
    ENSURE(strcmp(scene, "minimal") == 0);
    ENSURE(renderer[0] != 0);
    ww_image_free(&hdr);
    ww_image_free(&ldr);
}

/* the whole render job without GL: the null backend feeds every writer black frames, so the
 * frame files, their names and the streams' sizes are checked on any machine */
TEST_PROC(cli_render_null_backend_writes_every_format) {
    char dir[512], args[1400], p[900];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_null"));
    const char *fmt[] = {"png", "exr"};
    for (int k = 0; k < 2; k++) {
        snprintf(args, sizeof args, "render scenes/demo.yaml --backend null --size 64x36 --frames 3 "
                 "--format %s -o %s/%s --quiet", fmt[k], dir, fmt[k]);
        ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
        snprintf(p, sizeof p, "%s/%s", dir, fmt[k]);
        ENSURE_EQ_INT(count_files(p), 3);
        snprintf(p, sizeof p, "%s/%s/frame_00002.%s", dir, fmt[k], fmt[k]);
        struct stat sb;
        ENSURE_MSG(stat(p, &sb) == 0 && sb.st_size > 0, "%s", p);
    }
    /* raw: 64 x 36 x 3 bytes a frame; y4m: its header, then a FRAME line and 3 planes a frame */
    snprintf(args, sizeof args, "render scenes/demo.yaml --backend null --size 64x36 --frames 3 "
             "--format raw -o %s/v.rgb --quiet", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(p, sizeof p, "%s/v.rgb", dir);
    size_t n = 0;
    char *raw = ww_test_read_file(p, &n);
    ENSURE(raw && n == 64u * 36u * 3u * 3u);
    free(raw);
    snprintf(args, sizeof args, "render scenes/demo.yaml --backend null --size 64x36 --frames 3 "
             "--format y4m -o %s/v.y4m --quiet", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(p, sizeof p, "%s/v.y4m", dir);
    char *y4m = ww_test_read_file(p, &n);
    ENSURE(y4m && strncmp(y4m, "YUV4MPEG2 W64 H36 F30:1", 23) == 0);
    size_t header = y4m ? (size_t)(strchr(y4m, '\n') - y4m) + 1 : 0;
    ENSURE_EQ_INT(n, header + 3 * (6 + 64 * 36 * 3));
    free(y4m);
    /* a backend name that does not exist is a usage error */
    ENSURE_EQ_INT(ww_test_ww("render scenes/demo.yaml --backend nul --frames 1 --format none", NULL, NULL), 2);
}

/* peak RSS of a child, from wait4 (the shell execs the binary, so the child is waterworld).
 * Mesa's shader cache is off for it: with the cache on, the first run on a fresh machine compiles
 * every shader and peaks ~15 MB above the runs that find them cached, whatever the frame count */
static long child_peak_rss_kib(const char *args) {
    pid_t pid = fork();
    if (pid == 0) {
        char c[2048];
        snprintf(c, sizeof c, "MESA_SHADER_CACHE_DISABLE=true exec %s %s >/dev/null 2>&1",
                 ww_test_bin(), args);
        execl("/bin/sh", "sh", "-c", c, (char *)NULL);
        _exit(127);
    }
    int status = 0;
    struct rusage ru;
    if (pid < 0 || wait4(pid, &status, 0, &ru) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return ru.ru_maxrss;
}

/* memory growth allowed over 90 frames once running: allocator noise, not per-frame buffers
 * (a leak of 23 KB a frame exceeds it) */
#define RSS_GROWTH_TOL_KIB 2048.0

/* peak RSS after 30, 120 and 210 frames: a GPU driver may still grow its caches over the first
 * hundred frames (NVIDIA's did by 2.2 MB), so the check is on the last 90 frames; llvmpipe's
 * three figures are equal */
TEST_PROC(cli_render_peak_memory_does_not_grow_with_frames) {
    REQUIRE_GL();
    if (getenv("WW_ASAN")) SKIP("ASan's quarantine holds freed memory: peak RSS says nothing here");
    long a = child_peak_rss_kib("render scenes/demo.yaml --size 128x72 --frames 30 --format none --quiet");
    long b = child_peak_rss_kib("render scenes/demo.yaml --size 128x72 --frames 120 --format none --quiet");
    long c = child_peak_rss_kib("render scenes/demo.yaml --size 128x72 --frames 210 --format none --quiet");
    ENSURE(a > 0 && b > 0 && c > 0);
    ENSURE(b >= a - (long)RSS_GROWTH_TOL_KIB); /* the runs are alike */
    ENSURE_NEAR((double)c, (double)b, RSS_GROWTH_TOL_KIB);
}

/* src/sim never reaches up into GL or the YAML parser; only one file includes yaml.h */
static int grep_includes(const char *dir, const char *const *bad, int nbad, char *hit, size_t cap) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t len = strlen(e->d_name);
        if (len < 3 || e->d_name[len - 2] != '.' || (e->d_name[len - 1] != 'c' && e->d_name[len - 1] != 'h'))
            continue;
        char path[700];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        char *s = ww_test_read_file(path, NULL);
        for (char *p = s; p && (p = strstr(p, "#include")); p++) {
            char *eol = strchr(p, '\n');
            for (int b = 0; b < nbad; b++) {
                char *m = strstr(p, bad[b]);
                if (m && (!eol || m < eol)) {
                    n++;
                    snprintf(hit, cap, "%s includes %s", path, bad[b]);
                }
            }
        }
        free(s);
    }
    closedir(d);
    return n;
}

TEST(cli_layering_sim_includes_no_gl_or_yaml) {
    const char *bad[] = {"gfx/", "GL/", "EGL/", "yaml.h", "scene/tree.h", "io/", "cli/"};
    char hit[800] = "";
    ENSURE_MSG(grep_includes("src/sim", bad, 7, hit, sizeof hit) == 0, "%s", hit);
    const char *up[] = {"gfx/", "io/", "cli/", "sim/"};
    ENSURE_MSG(grep_includes("src/scene", up, 4, hit, sizeof hit) == 0, "%s", hit);
    ENSURE_MSG(grep_includes("src/core", up, 4, hit, sizeof hit) == 0, "%s", hit);
    const char *yaml[] = {"<yaml.h>"};
    const char *dirs[] = {"src/core", "src/scene", "src/sim",  "src/gfx",   "src/io",
                          "src/render", "src/check", "src/bench", "src/sweep", "src/cli"};
    int total = 0;
    for (int i = 0; i < 10; i++) {
        int n = grep_includes(dirs[i], yaml, 1, hit, sizeof hit);
        ENSURE_MSG(n >= 0, "cannot read %s", dirs[i]);
        total += n;
    }
    ENSURE_EQ_INT(total, 1);
}

/* every folder of src/ includes only itself and the folders below it (DESIGN.md's layers): core
 * and io at the bottom, then scene, sim and gfx, then render (the render job, the sound track),
 * check (compare, golden, review) on render, bench and sweep on both, and cli on top. Siblings
 * bench and sweep never include each other. */
TEST(cli_layering_each_folder_includes_only_lower_ones) {
    static const struct {
        const char *dir;
        const char *above[10]; /* NULL-terminated */
    } rule[] = {
        {"src/core", {"\"io/", "\"scene/", "\"sim/", "\"gfx/", "\"render/", "\"check/",
                      "\"bench/", "\"sweep/", "\"cli/"}},
        {"src/io", {"\"scene/", "\"sim/", "\"gfx/", "\"render/", "\"check/", "\"bench/",
                    "\"sweep/", "\"cli/"}},
        {"src/scene", {"\"io/", "\"sim/", "\"gfx/", "\"render/", "\"check/", "\"bench/",
                       "\"sweep/", "\"cli/"}},
        {"src/sim", {"\"io/", "\"gfx/", "\"render/", "\"check/", "\"bench/", "\"sweep/",
                     "\"cli/"}},
        {"src/gfx", {"\"render/", "\"check/", "\"bench/", "\"sweep/", "\"cli/"}},
        {"src/render", {"\"check/", "\"bench/", "\"sweep/", "\"cli/"}},
        {"src/check", {"\"bench/", "\"sweep/", "\"cli/"}},
        {"src/bench", {"\"sweep/", "\"cli/"}},
        {"src/sweep", {"\"bench/", "\"cli/"}},
    };
    for (size_t i = 0; i < sizeof rule / sizeof rule[0]; i++) {
        int n = 0;
        while (rule[i].above[n]) n++;
        char hit[800] = "";
        int found = grep_includes(rule[i].dir, rule[i].above, n, hit, sizeof hit);
        ENSURE_MSG(found >= 0, "cannot read %s", rule[i].dir);
        ENSURE_MSG(found <= 0, "%s", hit);
    }
}
