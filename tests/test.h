/* test.h - the one tiny test framework (after Box2D's test_macros.h).
 *
 *   TEST(loader_unknown_key) { ENSURE(x == 1); ENSURE_NEAR(h, 0.25, WAVE_HEIGHT_TOL); }
 *   TEST_PROC(cli_render_png) { REQUIRE_GL(); ... ww_test_ww("render ...", ...) ... }
 *   TEST_LONG(soak_hour) { ... }
 *
 * Tests register themselves in one of three tiers:
 *   TEST       unit: in process, no GL context, no child process (the runner fails a unit test
 *              that asks for either, so the tier stays honest);
 *   TEST_PROC  render and process tests: GL, or the binary under test run as a process;
 *   TEST_IMAGE render tests whose subject is the picture (goldens, feature toggles, backends
 *              and thread counts giving the same pixels): what they run on the CPU is what the
 *              process tests run too, so the sanitizer build leaves them out (`make asan`;
 *              scripts/sanitizer-coverage.sh shows that nothing the suite executes is lost);
 *   TEST_LONG  soaks, benchmarks and the largest renders: `make test-long`, not `make test`.
 * The runner (tests/main.c) runs each test in its own child process and its own temporary
 * folder, several at once (-j), and ends with "N passed, N failed, N skipped" and the reason of
 * every skip. A test that cannot run here says so with SKIP or REQUIRE_*: it counts as skipped,
 * never as passed. WW_REQUIRE_GL=1 (or a list: gl,egl,osmesa) makes a test skipped for want of
 * GL, or of a backend named in the list, fail instead: CI sets it where the backends must open.
 * Tolerances are named for what they allow and scaled by WW_TOL_SCALE (0 shows the residuals:
 * every NEAR check fails and prints the real difference).
 */
#ifndef WW_TEST_H
#define WW_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "io/image.h"

typedef void (*ww_test_fn)(void);
enum { WW_TIER_UNIT = 0, WW_TIER_PROC = 1, WW_TIER_IMAGE = 2, WW_TIER_LONG = 3 };
void ww_test_register(const char *name, ww_test_fn fn, int tier);
/* why a test is skipped: the kind decides what WW_REQUIRE_GL turns into a failure */
enum { WW_SKIP_OTHER = 0, WW_SKIP_GL = 1, WW_SKIP_EGL = 2, WW_SKIP_OSMESA = 3 };
void ww_test_skip(int kind, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* the current test is a unit test that wants a process or GL: record the failure (the tier) */
void ww_test_needs_proc(const char *what);
void ww_test_fail(const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
double ww_test_tol(double tol);      /* tol scaled by WW_TOL_SCALE */
int ww_test_failed_now(void);        /* the current test has failed a check */

#define WW_TEST_TIER(name, tier)                                                                \
    static void test_##name(void);                                                              \
    __attribute__((constructor)) static void reg_##name(void) {                                 \
        ww_test_register(#name, test_##name, tier);                                             \
    }                                                                                           \
    static void test_##name(void)
#define TEST(name) WW_TEST_TIER(name, WW_TIER_UNIT)
#define TEST_PROC(name) WW_TEST_TIER(name, WW_TIER_PROC)
#define TEST_IMAGE(name) WW_TEST_TIER(name, WW_TIER_IMAGE)
#define TEST_LONG(name) WW_TEST_TIER(name, WW_TIER_LONG)

/* end the current test as skipped, with the reason (printf-style) */
#define SKIP(...)                                                                               \
    do {                                                                                        \
        ww_test_skip(WW_SKIP_OTHER, __VA_ARGS__);                                               \
        return;                                                                                 \
    } while (0)

/* skip unless a GL backend opens here (the reason is the backend's own message) */
#define REQUIRE_GL()                                                                            \
    do {                                                                                        \
        if (!ww_test_have_gl()) {                                                               \
            ww_test_skip(WW_SKIP_GL, "no GL backend opens: %s", ww_test_gl_error());            \
            return;                                                                             \
        }                                                                                       \
    } while (0)

/* skip unless this backend (WW_BACKEND_EGL or WW_BACKEND_OSMESA) opens here */
#define REQUIRE_BACKEND(kind)                                                                   \
    do {                                                                                        \
        if (!ww_test_have_backend(kind)) {                                                      \
            ww_test_skip((kind) == 1 ? WW_SKIP_EGL : WW_SKIP_OSMESA, "%s",                      \
                         ww_test_backend_error(kind));                                          \
            return;                                                                             \
        }                                                                                       \
    } while (0)

/* skip unless this machine's renderer is the one that blessed the flat goldens (golden/KEY) */
#define REQUIRE_BLESSED_RENDERER()                                                              \
    do {                                                                                        \
        if (!ww_test_renderer_is_blessed()) {                                                   \
            ww_test_skip(WW_SKIP_OTHER, "this renderer did not bless golden/ (golden/KEY)");    \
            return;                                                                             \
        }                                                                                       \
    } while (0)

/* skip unless a command is on PATH (ImageMagick's compare, oiiotool, ffprobe, chromium...) */
#define REQUIRE_TOOL(cmd)                                                                       \
    do {                                                                                        \
        if (!ww_test_have_tool(cmd)) {                                                          \
            ww_test_skip(WW_SKIP_OTHER, "%s is not installed", cmd);                            \
            return;                                                                             \
        }                                                                                       \
    } while (0)

#define ENSURE(c)                                                                               \
    do {                                                                                        \
        if (!(c)) ww_test_fail(__FILE__, __LINE__, "%s", #c);                                   \
    } while (0)

#define ENSURE_MSG(c, ...)                                                                      \
    do {                                                                                        \
        if (!(c)) ww_test_fail(__FILE__, __LINE__, __VA_ARGS__);                                \
    } while (0)

#define ENSURE_EQ_INT(a, b)                                                                     \
    do {                                                                                        \
        long long a_ = (long long)(a), b_ = (long long)(b);                                     \
        if (a_ != b_) ww_test_fail(__FILE__, __LINE__, "%s == %s: %lld != %lld", #a, #b, a_, b_); \
    } while (0)

#define ENSURE_EQ_U64(a, b)                                                                     \
    do {                                                                                        \
        uint64_t a_ = (a), b_ = (b);                                                            \
        if (a_ != b_)                                                                           \
            ww_test_fail(__FILE__, __LINE__, "%s == %s: 0x%016llx != 0x%016llx", #a, #b,        \
                         (unsigned long long)a_, (unsigned long long)b_);                       \
    } while (0)

#define ENSURE_NEAR(a, b, tol)                                                                  \
    do {                                                                                        \
        double a_ = (a), b_ = (b), t_ = ww_test_tol(tol);                                       \
        if (!(fabs(a_ - b_) <= t_))                                                             \
            ww_test_fail(__FILE__, __LINE__, "|%s - %s| = |%.17g - %.17g| = %.3g > %s = %.3g",  \
                         #a, #b, a_, b_, fabs(a_ - b_), #tol, t_);                              \
    } while (0)

/* allocation counter of the test binary (the link wraps malloc/calloc/realloc) */
long ww_test_alloc_count(void);

/* test helpers shared by the test files (tests/util.c) */
/* run a shell command line; returns its exit status (or -1); stdout/stderr to the given files
 * when not NULL */
int ww_test_run(const char *cmdline, const char *out_path, const char *err_path);
/* the waterworld binary under test ($WW_BIN, default ./waterworld) */
const char *ww_test_bin(void);
/* a fresh folder named name inside the current test's own temporary folder; returns its path
 * (a static buffer: copy it to keep it) */
const char *ww_test_tmpdir(const char *name);
/* 1 when both files can be read and hold the same bytes */
int ww_test_files_equal(const char *a, const char *b);
/* read a whole file; returns malloc'd NUL-terminated bytes and its length, or NULL */
char *ww_test_read_file(const char *path, size_t *len);
/* run the binary under test with args (a shell word list); exit status as ww_test_run */
int ww_test_ww(const char *args, const char *out_path, const char *err_path);
/* write text to path; 0 on success */
int ww_test_write_text(const char *path, const char *text);
/* 1 when the file exists and contains needle */
int ww_test_file_contains(const char *path, const char *needle);
/* tests/json_check.c: text is one JSON value (surrounding white space allowed) */
int ww_test_json_valid(const char *text);
/* every line of text is one JSON object ending in a newline; the count, or -1 at the first bad */
int ww_test_json_lines(const char *text);
/* the number after "key": in a JSON line (the first such key from line on), or -1 when absent
 * or null */
double ww_test_json_number(const char *line, const char *key);
/* 1 when a GL backend can be opened here (the runner asks once, in a child of its own) */
int ww_test_have_gl(void);
/* why none opens, when ww_test_have_gl() is 0 */
const char *ww_test_gl_error(void);
/* 1 when this backend kind (1 EGL, 2 OSMesa: ww_backend_kind) opens here; why not */
int ww_test_have_backend(int kind);
const char *ww_test_backend_error(int kind);
/* CRC-32 of PNG section 5.5, bit by bit: the tests' own, so a bad table in a reader shows */
uint32_t ww_test_crc32(const unsigned char *p, size_t n);
/* the folder of the test binary (build, build/asan): what the Makefile built beside it */
const char *ww_test_build_dir(void);
/* 1 when cmd is found on PATH */
int ww_test_have_tool(const char *cmd);

/* tests/golden.c: scenes, projections and images */
struct ww_scene;
struct ww_state;
/* a scene from YAML text, named `name` in its messages; a failed load fails the test (NULL) */
struct ww_scene *ww_test_scene_text(const char *name, const char *text);
/* the state advanced to `step`; a failed step fails the test (0) */
int ww_test_run_to(const struct ww_scene *sc, struct ww_state *st, int64_t step);
/* world point p to pixel coordinates (x right, y down, pixel centres at +0.5) as the state's
 * camera sees it in the scene's frame */
void ww_test_project(const struct ww_scene *sc, const struct ww_state *st, const double p[3],
                     double px[2]);
/* the 8-bit pixel at (x, y) of an image read with ww_read_png (y from the top row) */
const unsigned char *ww_test_pixel(const ww_image *im, int x, int y);
/* an 8-bit PNG read back for measuring, with its size */
typedef struct ww_test_pic {
    ww_image im;
    int w, h;
} ww_test_pic;
/* read path into p (a failed check names the file); 1 when it holds pixels */
int ww_test_pic_load(const char *path, ww_test_pic *p);
/* Rec. 601 luma of pixel (x, y), the coordinates clamped to the image, 8-bit levels */
double ww_test_pic_luma(const ww_test_pic *p, int x, int y);
/* frame `frame` of scene rendered at size (WxH) with extra args (NULL: none) into the test's
 * folder `name`, read into p; 0 (a failed check) when the render or the read fails */
int ww_test_render_pic(const char *scene, int frame, const char *size, const char *args,
                       const char *name, ww_test_pic *p);
/* a scene's text written as tag/scene.yaml under the test's folder and its frame rendered with
 * and without `without` (arguments that take something out of the picture); 1 when both are
 * read back, else a failed check and both freed */
int ww_test_render_with_without(const char *tag, const char *text, int frame, const char *size,
                                const char *without, ww_test_pic *with, ww_test_pic *none);
/* whether a channel of a pixel within `radius` px of (x, y) differs between a and b by more than
 * `levels` (8-bit); pixels off the image do not count */
int ww_test_moved_near(const ww_test_pic *a, const ww_test_pic *b, double x, double y, int radius,
                       int levels);
/* PSNR of b against a over RGB (8-bit; INFINITY when equal) and the largest channel difference */
double ww_test_pic_psnr(const ww_test_pic *a, const ww_test_pic *b, int *max_diff);
/* this machine's GL renderer is the one that blessed golden/ (golden/RENDERER) */
int ww_test_renderer_is_blessed(void);
/* actual (PNG) against golden (PNG), e.g. golden/features/fog.png: exact on the blessing renderer
 * or against this renderer's own golden/features/KEY/fog.png where one exists, within a tolerance
 * elsewhere; a failure names both files and says how to re-bless */
void ww_test_check_golden(const char *golden, const char *actual);
/* render frame 0 of scene into dir/frame_00000.png with extra arguments (e.g. "--set
 * render.bloom=false"); the exit status */
int ww_test_render(const char *scene, const char *args, const char *dir);
/* where two PNGs of one size differ, inside and outside a rectangle given as fractions of the
 * image (x0, y0, x1, y1; y from the top row): pixels whose largest channel difference exceeds
 * thresh, and the largest difference on each side */
typedef struct ww_test_region {
    long inside, outside;       /* differing pixels */
    long inside_px, outside_px; /* pixels on each side */
    int max_inside, max_outside;
} ww_test_region;
int ww_test_region_diff(const char *a, const char *b, const double rect[4], int thresh,
                        ww_test_region *d);

#endif
