/* test_golden.c - `render --golden DIR`: renderer keys, the scene's golden: section, frames that
 * pass, fail (diff in red where the golden was changed) and have no golden, per-renderer folders
 * over flat ones, the fallback list, thresholds from the scene with the command line's winning,
 * and the HTML report (escaped, relative links, rendered by headless Chromium).
 * Every GL test blesses its own goldens from scenes/minimal.yaml at 256x144, so none depends on
 * golden/ nor on the renderer at hand.
 */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "gfx/backend.h"
#include "io/writers.h"
#include "scene/scene.h"
#include "test.h"
#include "check/golden.h"

#define SCENE "scenes/minimal.yaml"
#define SIZE "--size 256x144"
/* the rectangle the tests paint into a golden, pixels: x0, y0, x1, y1 (exclusive) */
static const int RECT[4] = {100, 50, 140, 80};
/* a pixel of the diff image counts as "red" (pixelmatch's colour for a difference) with at least
 * this much red and at most this much green and blue; the report's banner (183, 28, 28) is not */
#define RED_MIN 220
#define OTHER_MAX 60
/* share of the painted rectangle the diff must mark red, and of the rest it may */
#define RECT_RED_SHARE_MIN 0.95
#define OUTSIDE_RED_SHARE_MAX 0.001
/* the painted golden and the diff as they appear in Chromium's screenshot: the rectangle is
 * 40x30 px shown at ~1.2x, so well over this many pixels of each colour */
#define SHOT_COLOR_PIXELS_MIN 500

/* ---- helpers ------------------------------------------------------------------------------- */

static int file_exists(const char *path) {
    struct stat st;
    return stat(path, &st) == 0;
}

/* render SCENE at 256x144 with args; stderr into err_path when not NULL */
static int render(const char *args, const char *err_path) {
    char a[8192];
    snprintf(a, sizeof a, "render %s %s %s", SCENE, SIZE, args);
    return ww_test_ww(a, NULL, err_path);
}

/* bless frames 0..n-1 into dir */
static int bless(const char *dir, int n) {
    char a[1024];
    snprintf(a, sizeof a, "--frames %d -o '%s' --quiet", n, dir);
    return render(a, NULL);
}

/* the renderer key of the auto backend here ("" without GL) */
static void key_here(char *out, size_t cap) {
    out[0] = 0;
    ww_backend *b = NULL;
    ww_error err = {0};
    if (ww_backend_open(WW_BACKEND_AUTO, &b, &err) != WW_OK) return;
    ww_golden_renderer_key(ww_backend_renderer(b), ww_backend_version(b), out, cap);
    ww_backend_close(b);
}

/* paint RECT of a PNG: a solid colour (delta < 0) or every channel raised by delta levels */
static void paint(const char *path, int r, int g, int b, int delta) {
    ww_image im = {0};
    ww_error err = {0};
    ENSURE_MSG(ww_read_png(path, &im, &err) == WW_OK, "%s: %s", path, err.msg);
    if (!im.u8) return;
    const int rgb[3] = {r, g, b};
    for (int y = RECT[1]; y < RECT[3]; y++) {
        for (int x = RECT[0]; x < RECT[2]; x++) {
            uint8_t *p = im.u8 + ((size_t)y * (size_t)im.width + (size_t)x) * (size_t)im.channels;
            for (int c = 0; c < 3; c++) {
                int v = delta < 0 ? rgb[c] : p[c] + delta;
                p[c] = (uint8_t)(v > 255 ? 255 : v);
            }
        }
    }
    ENSURE_MSG(ww_write_png(path, &im, &err) == WW_OK, "%s: %s", path, err.msg);
    ww_image_free(&im);
}

/* pixels of a PNG close to (r, g, b) within OTHER_MAX-style bounds, inside RECT and outside */
typedef struct color_count {
    long inside, outside, inside_px, outside_px;
} color_count;

static int is_pure(const uint8_t *p, int want_r, int want_g, int want_b) {
    const int want[3] = {want_r, want_g, want_b};
    for (int c = 0; c < 3; c++) {
        if (want[c] && p[c] < RED_MIN) return 0;
        if (!want[c] && p[c] > OTHER_MAX) return 0;
    }
    return 1;
}

static color_count count_color(const char *path, int r, int g, int b, int use_rect) {
    color_count n = {0};
    ww_image im = {0};
    ww_error err = {0};
    ENSURE_MSG(ww_read_png(path, &im, &err) == WW_OK, "%s: %s", path, err.msg);
    for (int y = 0; im.u8 && y < im.height; y++) {
        for (int x = 0; x < im.width; x++) {
            const uint8_t *p = im.u8 + ((size_t)y * (size_t)im.width + (size_t)x) * (size_t)im.channels;
            int in = use_rect && x >= RECT[0] && x < RECT[2] && y >= RECT[1] && y < RECT[3];
            int hit = is_pure(p, r, g, b);
            if (in) n.inside += hit, n.inside_px++;
            else n.outside += hit, n.outside_px++;
        }
    }
    ww_image_free(&im);
    return n;
}

static int copy(const char *from, const char *to) {
    char c[4096];
    snprintf(c, sizeof c, "mkdir -p \"$(dirname '%s')\" && cp '%s' '%s'", to, from, to);
    return ww_test_run(c, NULL, NULL);
}

/* ---- no GL: keys and the scene section ----------------------------------------------------- */

TEST(golden_renderer_key_rules) {
    static const struct { const char *renderer, *version, *key; } cases[] = {
        {"llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6", "llvmpipe-mesa-22.3"},
        {"softpipe", "3.3 (Core Profile) Mesa 23.1.0-devel", "softpipe-mesa-23.1"},
        {"Mesa Intel(R) UHD Graphics 620 (KBL GT2)", "4.6 (Core Profile) Mesa 23.2.1",
         "intel-mesa-23.2"},
        {"AMD Radeon RX 6800 (navi21, LLVM 15.0.6, DRM 3.49, 6.1.0)",
         "4.6 (Core Profile) Mesa 22.3.6", "amd-mesa-22.3"},
        {"zink (NVIDIA GeForce RTX 3060)", "4.6 (Core Profile) Mesa 24.0.5", "zink-mesa-24.0"},
        {"NVIDIA H100 80GB HBM3/PCIe/SSE2", "4.6.0 NVIDIA 535.104.05", "nvidia-535"},
        /* as an H100's EGL device reported it (notes-gpu.txt) */
        {"NVIDIA H100 80GB HBM3/PCIe/SSE2", "3.3.0 NVIDIA 580.159.04", "nvidia-580"},
        {"AMD Radeon Pro W6800", "4.6.14756 Compatibility Profile Context 20.45", "amd-gl-4.6"},
        {"", "", "unknown"},
        {NULL, NULL, "unknown"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char key[WW_GOLDEN_KEY_SIZE];
        ww_golden_renderer_key(cases[i].renderer, cases[i].version, key, sizeof key);
        ENSURE_MSG(strcmp(key, cases[i].key) == 0, "'%s' | '%s' -> '%s', expected '%s'",
                   cases[i].renderer ? cases[i].renderer : "(null)",
                   cases[i].version ? cases[i].version : "(null)", key, cases[i].key);
    }
}

TEST(golden_scene_section_becomes_compare_options) {
    static const char text[] =
        "time: {dt: 1/120, fps: 30, duration: 1}\n"
        "golden:\n"
        "  threshold: 3\n  yiq: 0.2\n  aa: false\n  max: 8\n  fail_percent: 0.1\n"
        "  fail_pixels: 50\n  psnr_min: 40\n  yiq_pixels: 10\n  ssim_min: 0.99\n"
        "  fallback: [llvmpipe-mesa-22.3, nvidia-535]\n";
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("g.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return;
    ww_cmp_opts o = ww_golden_scene_opts(sc);
    ENSURE(o.threshold == 3 && o.yiq == 0.2 && o.detect_aa == 0 && o.max == 8);
    ENSURE(o.fail_percent == 0.1 && o.fail_pixels == 50 && o.psnr_min == 40);
    ENSURE(o.yiq_pixels == 10 && o.ssim_min == 0.99 && o.rel_max < 0);
    ENSURE_EQ_INT(sc->golden.nfallback, 2);
    ENSURE(strcmp(sc->golden.fallback[1], "nvidia-535") == 0);
    ww_scene_free(sc);

    /* no section: compare's defaults, every rule off */
    static const char bare[] = "time: {dt: 1/120, fps: 30, duration: 1}\n";
    ENSURE(ww_scene_load_string("b.yaml", bare, strlen(bare), NULL, 0, &sc, &err) == WW_OK);
    if (!sc) return;
    o = ww_golden_scene_opts(sc);
    ww_cmp_opts d = ww_cmp_default_opts();
    ENSURE(o.threshold == d.threshold && o.yiq == d.yiq && o.detect_aa == d.detect_aa);
    ENSURE(o.max < 0 && o.fail_percent < 0 && o.fail_pixels < 0 && o.psnr_min < 0);
    ENSURE(o.yiq_pixels < 0 && o.ssim_min < 0 && !sc->golden.on);
    ww_scene_free(sc);
}

/* ---- GL: the workflow ---------------------------------------------------------------------- */

TEST_PROC(golden_pass_then_changed_golden_fails_with_red_diff) {
    REQUIRE_GL();
    char dir[512], g[600], o[600], a[4096], errp[600], p[700], q[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_pass_fail"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(errp, sizeof errp, "%s/err.txt", dir);
    ENSURE_EQ_INT(bless(g, 3), 0);

    snprintf(a, sizeof a, "--frames 3 -o '%s' --golden '%s'", o, g);
    ENSURE_EQ_INT(render(a, errp), 0);
    snprintf(p, sizeof p, "%s/report.html", o);
    ENSURE_MSG(ww_test_file_contains(p, "PASS: 3 frames, 3 passed, 0 failed, 0 missing"),
               "%s does not say 3 passed", p);
    ENSURE(ww_test_file_contains(errp, "3 passed, 0 failed"));

    /* a green rectangle in frame 1's golden: exact matching (no rule given) fails it */
    snprintf(p, sizeof p, "%s/frame_00001.png", g);
    paint(p, 0, 255, 0, -1);
    ENSURE_EQ_INT(render(a, errp), 1);
    ENSURE(ww_test_file_contains(errp, "frame 00001 FAILED"));
    snprintf(q, sizeof q, "%s/diff/frame_00001.png", o);
    color_count red = count_color(q, 255, 0, 0, 1);
    ENSURE_MSG(red.inside >= RECT_RED_SHARE_MIN * (double)red.inside_px,
               "diff: %ld of %ld pixels red in the changed rectangle", red.inside, red.inside_px);
    ENSURE_MSG(red.outside <= OUTSIDE_RED_SHARE_MAX * (double)red.outside_px,
               "diff: %ld of %ld pixels red outside it", red.outside, red.outside_px);
    snprintf(q, sizeof q, "%s/diff/frame_00000.png", o);
    ENSURE_MSG(!file_exists(q), "%s written for a passing frame", q);
    /* the golden's copy beside the actual, byte for byte */
    size_t la = 0, lb = 0;
    char *ga = ww_test_read_file(p, &la);
    snprintf(q, sizeof q, "%s/expected/frame_00001.png", o);
    char *gb = ww_test_read_file(q, &lb);
    ENSURE_MSG(ga && gb && la == lb && memcmp(ga, gb, la) == 0, "%s is not a copy of %s", q, p);
    free(ga);
    free(gb);
    snprintf(p, sizeof p, "%s/report.html", o);
    ENSURE(ww_test_file_contains(p, "FAIL: 3 frames, 2 passed, 1 failed, 0 missing"));
    ENSURE(ww_test_file_contains(p, "<h3>frame_00001.png</h3>"));
    ENSURE(ww_test_file_contains(p, "<tr><td>no pixel over threshold</td><td class=\"num\">0</td>"));
    ENSURE(ww_test_file_contains(p, "FAILS"));
    ENSURE(ww_test_file_contains(p, "src=\"diff/frame_00001.png\""));
    ENSURE(ww_test_file_contains(p, "src=\"expected/frame_00001.png\""));
    ENSURE(ww_test_file_contains(p, "src=\"frame_00001.png\""));

    /* loose enough: passes again, and the stale diff goes */
    snprintf(a, sizeof a, "--frames 3 -o '%s' --golden '%s' --max 255", o, g);
    ENSURE_EQ_INT(render(a, errp), 0);
    snprintf(q, sizeof q, "%s/diff/frame_00001.png", o);
    ENSURE_MSG(!file_exists(q), "stale %s left after the frame passed", q);
    ENSURE(ww_test_file_contains(p, "PASS: 3 frames, 3 passed"));
}

TEST_PROC(golden_per_renderer_folder_wins_over_flat) {
    REQUIRE_GL();
    char dir[512], g[600], o[600], a[4096], key[WW_GOLDEN_KEY_SIZE], flat[700], mine[800], rep[700];
    key_here(key, sizeof key);
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_per_renderer"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(rep, sizeof rep, "%s/report.html", o);
    ENSURE_EQ_INT(bless(g, 1), 0);
    snprintf(flat, sizeof flat, "%s/frame_00000.png", g);
    snprintf(mine, sizeof mine, "%s/%s/frame_00000.png", g, key);
    ENSURE_EQ_INT(copy(flat, mine), 0);
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s'", o, g);

    /* the flat one wrong, this renderer's right: passes, from the renderer's folder */
    paint(flat, 0, 255, 0, -1);
    ENSURE_EQ_INT(render(a, NULL), 0);
    ENSURE(ww_test_file_contains(rep, key));
    ENSURE(ww_test_file_contains(rep, mine));
    /* this renderer's wrong, the flat one right: fails, so the flat one was not consulted */
    paint(mine, 0, 255, 0, -1);
    ENSURE_EQ_INT(bless(g, 1), 0);
    ENSURE_EQ_INT(render(a, NULL), 1);
    /* without a folder for this renderer, the flat one serves */
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s' --quiet", o, g);
    char rm[900];
    snprintf(rm, sizeof rm, "rm -r '%s/%s'", g, key);
    ENSURE_EQ_INT(ww_test_run(rm, NULL, NULL), 0);
    ENSURE_EQ_INT(render(a, NULL), 0);
    ENSURE(ww_test_file_contains(rep, "(flat)") || ww_test_file_contains(rep, ">flat<"));
}

TEST_PROC(golden_fallback_list_is_honoured) {
    REQUIRE_GL();
    char dir[512], g[600], o[600], a[4096], flat[700], other[800], rep[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_fallback"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(rep, sizeof rep, "%s/report.html", o);
    ENSURE_EQ_INT(bless(g, 1), 0);
    snprintf(flat, sizeof flat, "%s/frame_00000.png", g);
    snprintf(other, sizeof other, "%s/other-mesa-1.0/frame_00000.png", g);
    ENSURE_EQ_INT(copy(flat, other), 0);
    paint(flat, 0, 255, 0, -1);
    /* a key nobody renders with, then the accepted one: its golden is used over the flat one */
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s' --quiet "
             "--set 'golden.fallback=[nobody-gl-1.0, other-mesa-1.0]'", o, g);
    ENSURE_EQ_INT(render(a, NULL), 0);
    ENSURE(ww_test_file_contains(rep, "fallback other-mesa-1.0"));
    /* not accepted: the flat (changed) one is compared */
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s' --quiet", o, g);
    ENSURE_EQ_INT(render(a, NULL), 1);
}

TEST_PROC(golden_missing_frame_fails_and_is_listed) {
    REQUIRE_GL();
    char dir[512], g[600], o[600], a[4096], errp[600], rep[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_missing"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(errp, sizeof errp, "%s/err.txt", dir);
    snprintf(rep, sizeof rep, "%s/report.html", o);
    ENSURE_EQ_INT(bless(g, 2), 0);
    snprintf(a, sizeof a, "--frames 3 -o '%s' --golden '%s'", o, g);
    ENSURE_EQ_INT(render(a, errp), 1);
    ENSURE(ww_test_file_contains(errp, "frame 00002 MISSING"));
    ENSURE(ww_test_file_contains(errp, "2 passed, 0 failed, 1 missing"));
    ENSURE(ww_test_file_contains(rep, "FAIL: 3 frames, 2 passed, 0 failed, 1 missing"));
    ENSURE(ww_test_file_contains(rep, "Frames without a golden"));
    ENSURE(ww_test_file_contains(rep, "frame_00002.png</a>: none of"));
}

TEST_PROC(golden_scene_thresholds_apply_and_command_line_wins) {
    REQUIRE_GL();
    char dir[512], g[600], o[600], a[4096], sp[600], p[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_thresholds"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    ENSURE_EQ_INT(bless(g, 1), 0);
    /* every channel of the rectangle 12 levels brighter (fewer where it clips at 255) */
    snprintf(p, sizeof p, "%s/frame_00000.png", g);
    paint(p, 0, 0, 0, 12);
    /* the scene file: minimal.yaml with a golden: section allowing 20 levels */
    char *text = ww_test_read_file(SCENE, NULL);
    ENSURE(text != NULL);
    if (!text) return;
    snprintf(sp, sizeof sp, "%s/loose.yaml", dir);
    char *scene = malloc(strlen(text) + 64);
    sprintf(scene, "%sgolden: {max: 20}\n", text);
    ENSURE_EQ_INT(ww_test_write_text(sp, scene), 0);
    free(scene);
    free(text);
    const struct { const char *extra; int exit; } cases[] = {
        {"", 0},                               /* the scene's max 20 holds */
        {"--max 5", 1},                        /* the command line's max 5 wins */
        {"--set golden.max=5", 1},             /* a scene allowing 5 */
        {"--set golden.max=5 --max 20", 0},    /* ... and the command line over it */
        {"--set golden.max=5 --psnr-min 20", 1}, /* a rule added keeps the scene's */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(a, sizeof a, "render '%s' %s --frames 1 -o '%s' --golden '%s' --quiet %s", sp,
                 SIZE, o, g, cases[i].extra);
        ENSURE_MSG(ww_test_ww(a, NULL, NULL) == cases[i].exit, "case '%s': expected exit %d",
                   cases[i].extra, cases[i].exit);
    }
    /* no rule anywhere: no pixel may differ by more than the per-pixel threshold */
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s' --quiet --threshold 20", o, g);
    ENSURE_EQ_INT(render(a, NULL), 0);
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s' --quiet --threshold 5", o, g);
    ENSURE_EQ_INT(render(a, NULL), 1);
}

TEST_PROC(golden_folder_missing_or_holding_the_output_is_bad_input) {
    REQUIRE_GL();
    char dir[512], g[600], o[600], a[4096], key[WW_GOLDEN_KEY_SIZE], errp[600], p[700];
    key_here(key, sizeof key);
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_bad_dirs"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(errp, sizeof errp, "%s/err.txt", dir);
    /* no such folder: exit 2 before anything is rendered */
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s/nowhere'", o, dir);
    ENSURE_EQ_INT(render(a, errp), 2);
    ENSURE(ww_test_file_contains(errp, "no such folder"));
    snprintf(p, sizeof p, "%s/frame_00000.png", o);
    ENSURE_MSG(!file_exists(p), "%s rendered although the golden folder is missing", p);
    /* the goldens themselves (or a renderer's folder of them) as the output */
    ENSURE_EQ_INT(bless(g, 1), 0);
    snprintf(a, sizeof a, "--frames 1 -o '%s' --golden '%s'", g, g);
    ENSURE_EQ_INT(render(a, errp), 2);
    ENSURE(ww_test_file_contains(errp, "overwrite the goldens"));
    snprintf(a, sizeof a, "--frames 1 -o '%s/%s' --golden '%s'", g, key, g);
    ENSURE_EQ_INT(render(a, errp), 2);
    snprintf(p, sizeof p, "%s/%s", g, key);
    ENSURE_MSG(!file_exists(p), "%s made although it lies in the golden folder", p);
}

/* the report's escaping needs no pixels: the null backend, so this runs without GL too */
TEST_PROC(golden_report_escapes_what_it_shows) {
    char dir[512], g[600], o[600], a[4096], sp[600], rep[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_escape"));
    /* a scene and a golden folder whose names are HTML */
    snprintf(g, sizeof g, "%s/g&<i>", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(sp, sizeof sp, "%s/a\"<b>.yaml", dir);
    snprintf(rep, sizeof rep, "%s/report.html", o);
    char *text = ww_test_read_file(SCENE, NULL);
    ENSURE(text && ww_test_write_text(sp, text) == 0);
    free(text);
    snprintf(a, sizeof a, "render '%s' %s --backend null --frames 1 -o '%s' --quiet", sp, SIZE, g);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "render '%s' %s --backend null --frames 1 -o '%s' --golden '%s' --quiet",
             sp, SIZE, o, g);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    ENSURE(ww_test_file_contains(rep, "a&quot;&lt;b&gt;"));
    ENSURE(ww_test_file_contains(rep, "g&amp;&lt;i&gt;"));
    ENSURE(!ww_test_file_contains(rep, "<b>") && !ww_test_file_contains(rep, "<i>"));
    ENSURE(!ww_test_file_contains(rep, "<script"));
}

/* the report as a browser shows it, from a copy of the output folder with the goldens gone (a
 * CI artifact): the golden's green rectangle and the diff's red are on the page */
TEST_PROC(golden_report_renders_in_headless_chromium) {
    REQUIRE_GL();
    REQUIRE_TOOL("chromium");
    char dir[512], g[600], o[600], art[600], a[4096], p[700], shot[600], cmd[4096];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden_chromium"));
    snprintf(g, sizeof g, "%s/golden", dir);
    snprintf(o, sizeof o, "%s/out", dir);
    snprintf(art, sizeof art, "%s/artifact", dir);
    snprintf(shot, sizeof shot, "%s/shot.png", dir);
    ENSURE_EQ_INT(bless(g, 2), 0);
    snprintf(p, sizeof p, "%s/frame_00001.png", g);
    paint(p, 0, 255, 0, -1);
    snprintf(a, sizeof a, "--frames 2 -o '%s' --golden '%s' --quiet", o, g);
    ENSURE_EQ_INT(render(a, NULL), 1);
    snprintf(cmd, sizeof cmd, "cp -r '%s' '%s' && rm -r '%s'", o, art, g);
    ENSURE_EQ_INT(ww_test_run(cmd, NULL, NULL), 0);

    char *abs = realpath(art, NULL);
    ENSURE(abs != NULL);
    if (!abs) return;
    snprintf(cmd, sizeof cmd,
             "chromium --headless --disable-gpu --no-sandbox --user-data-dir='%s/profile' "
             "--screenshot='%s' --window-size=1000,800 'file://%s/report.html'",
             dir, shot, abs);
    free(abs);
    ENSURE_EQ_INT(ww_test_run(cmd, NULL, NULL), 0);
    color_count red = count_color(shot, 255, 0, 0, 0);
    color_count green = count_color(shot, 0, 255, 0, 0);
    ENSURE_MSG(red.outside >= SHOT_COLOR_PIXELS_MIN, "%ld red pixels on the page (diff image)",
               red.outside);
    ENSURE_MSG(green.outside >= SHOT_COLOR_PIXELS_MIN,
               "%ld green pixels on the page (the golden's copy)", green.outside);
}

/* the project's own goldens (flat, blessed on the renderer named in golden/KEY) pass through
 * render --golden on that renderer, and golden/KEY is this renderer's key there */
TEST_IMAGE(golden_project_goldens_pass_on_the_blessed_renderer) {
    REQUIRE_GL();
    REQUIRE_BLESSED_RENDERER();
    char key[WW_GOLDEN_KEY_SIZE], a[1024];
    key_here(key, sizeof key);
    char *blessed = ww_test_read_file("golden/KEY", NULL);
    ENSURE_MSG(blessed && strncmp(blessed, key, strlen(key)) == 0 && blessed[strlen(key)] == '\n',
               "golden/KEY is '%s', this renderer's key '%s' (run make golden)",
               blessed ? blessed : "(missing)", key);
    free(blessed);
    snprintf(a, sizeof a, "render scenes/minimal.yaml --frames 1 -o '%s' --golden golden/minimal --quiet",
             ww_test_tmpdir("golden_project"));
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
}
