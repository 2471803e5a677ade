/* test_post.c - the post-processing passes (bloom, light shafts, FXAA, MSAA, HUD, the frame's
 * scale): a golden per feature scene (scenes/features/NAME.yaml), and toggle tests: the feature
 * switched off changes the picture where the feature acts and nowhere else, and removes its pass
 * from `plan`. The regions are computed from the pictures themselves: the bright areas for
 * bloom, an edge mask of the input for FXAA and MSAA, the HUD's boxes for the HUD.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/render_impl.h"
#include "io/writers.h"
#include "test.h"

#define BLOOM_KERNEL_TOL 1e-6
#define BLOOM_SCALE_PSNR_MIN 50.0   /* dB: a quarter- or eighth-size blur against the half-size one */
#define BLOOM_SCALE_ENERGY_TOL 0.05 /* the glow's total light, a share of the half-size blur's */
/* the merged kernel's variance against n rounds': its dropped tail (pass_bloom.c BLOOM_TAIL,
 * 2e-3 of the weight beyond ~3.3 sigma) takes at most ~2.5% of it */
#define BLOOM_MERGED_VAR_TOL 0.03
/* what may bloom: pixels whose exposed luminance reaches the knee's start, threshold 1 - knee
 * 0.5, which the scene's exp curve and gamma 2.2 put at 255 (1 - e^-0.5)^(1 / 2.2) = 165 */
#define BLOOM_BRIGHT_LUMA 165
#define BLOOM_REACH_PX 28          /* bloom spreads about 3 sigma: 3 passes of sigma 1.7 at half res */
#define BLOOM_MIN_CHANGED 0.01     /* at least this share of the frame blooms */
#define SHAFTS_MIN_CHANGED 0.25    /* under water the shafts light at least this share */
#define EDGE_SOBEL_MIN 24.0        /* Sobel magnitude (8-bit luma) that makes a pixel an edge */
#define EDGE_NEAR_PX 1             /* "on or near an edge": within this many pixels */
#define FXAA_ON_EDGES_MIN 0.95     /* share of the pixels FXAA changed that lie on/near edges */
#define FXAA_MIN_CHANGED 0.005
#define MSAA_ON_EDGES_MIN 0.95
#define MSAA_MIN_CHANGED 0.005
/* MSAA also averages the two shadings of a pixel that an edge between two triangles of one
 * smooth surface crosses (each shaded at the pixel centre): changes of up to three levels that
 * no edge in the image explains; what counts as a change for MSAA */
#define MSAA_LEVELS 3
#define HUD_BOX_RECT_PX 170        /* the text box: the boat line, ~150 px wide, plus margins */
#define HUD_BOX_RECT_PY 44
static const double HUD_MARKER_RECT[4] = {0.35, 0.7, 0.65, 1.0}; /* x0 y0 x1 y1, image fractions */
#define HUD_MARKER_MIN_PX 60       /* the diamond, its glow and the arrow */
#define SCALE_BLIT_TOL 1           /* levels: GL's bilinear blit of 8-bit texels against a float
                                    * bilinear of the same texels, rounded */
#define SCALE_ALPHA_ROWS 2         /* --alpha read nearest from the smaller depth: at most this many
                                    * rows' worth of pixels differ from the full-size coverage */


/* render frame 0 of scene with args into tmp dir `name`; the PNG's path in out */
static int render_to(const char *scene, const char *args, const char *name, char *out, size_t cap) {
    char dir[768];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(name));
    int rc = ww_test_render(scene, args, dir);
    snprintf(out, cap, "%s/frame_00000.png", dir);
    ENSURE_MSG(rc == 0, "render %s %s: exit %d", scene, args ? args : "", rc);
    return rc;
}

/* `plan scene args` lists pass `what` (a phrase of its line) */
static int plan_lists(const char *scene, const char *args, const char *what) {
    char out[1024], c[2048];
    snprintf(out, sizeof out, "%s/plan.txt", ww_test_tmpdir("post_plan"));
    snprintf(c, sizeof c, "plan %s %s", scene, args ? args : "");
    ENSURE(ww_test_ww(c, out, NULL) == 0);
    return ww_test_file_contains(out, what);
}

static void golden(const char *name) {
    char scene[256], gold[256], got[1024], dir[64];
    snprintf(scene, sizeof scene, "scenes/features/%s.yaml", name);
    snprintf(gold, sizeof gold, "golden/features/%s.png", name);
    snprintf(dir, sizeof dir, "post_golden_%s", name);
    if (render_to(scene, NULL, dir, got, sizeof got) != 0) return;
    ww_test_check_golden(gold, got);
}

typedef ww_test_pic pic;

/* largest channel difference of pixel (x, y) */
static int pixel_diff(const pic *a, const pic *b, int x, int y) {
    int e = 0;
    for (int c = 0; c < a->im.channels; c++) {
        size_t i = ((size_t)y * (size_t)a->w + (size_t)x) * (size_t)a->im.channels + (size_t)c;
        int d = abs((int)a->im.u8[i] - (int)b->im.u8[i]);
        if (d > e) e = d;
    }
    return e;
}

/* mask[i] = 1 where some pixel within r (Chebyshev) has src[] set */
static void dilate(const unsigned char *src, unsigned char *dst, int w, int h, int r) {
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            unsigned char m = 0;
            for (int dy = -r; dy <= r && !m; dy++)
                for (int dx = -r; dx <= r && !m; dx++) {
                    int u = x + dx, v = y + dy;
                    if (u >= 0 && u < w && v >= 0 && v < h) m = src[v * w + u];
                }
            dst[y * w + x] = m;
        }
}

/* Sobel edge mask of p's luma, dilated by EDGE_NEAR_PX */
static unsigned char *edge_mask(const pic *p) {
    size_t n = (size_t)p->w * (size_t)p->h;
    unsigned char *e = calloc(n, 1), *d = calloc(n, 1);
    if (!e || !d) {
        free(e);
        free(d);
        return NULL;
    }
    for (int y = 0; y < p->h; y++)
        for (int x = 0; x < p->w; x++) {
            double gx = ww_test_pic_luma(p, x + 1, y - 1) + 2 * ww_test_pic_luma(p, x + 1,
                                         y) + ww_test_pic_luma(p, x + 1, y + 1) -
                        ww_test_pic_luma(p, x - 1, y - 1) - 2 * ww_test_pic_luma(p, x - 1,
                                         y) - ww_test_pic_luma(p, x - 1, y + 1);
            double gy = ww_test_pic_luma(p, x - 1, y + 1) + 2 * ww_test_pic_luma(p, x,
                                         y + 1) + ww_test_pic_luma(p, x + 1, y + 1) -
                        ww_test_pic_luma(p, x - 1, y - 1) - 2 * ww_test_pic_luma(p, x,
                                         y - 1) - ww_test_pic_luma(p, x + 1, y - 1);
            /* /4: the kernel's gain, so the threshold is in luma levels per pixel */
            e[(size_t)y * p->w + x] = sqrt(gx * gx + gy * gy) / 4.0 >= EDGE_SOBEL_MIN;
        }
    dilate(e, d, p->w, p->h, EDGE_NEAR_PX);
    free(e);
    return d;
}

typedef struct masked {
    long changed, in_mask, mask_px;
} masked;

/* pixels that differ between a and b by more than thresh levels, and how many of them lie
 * inside mask */
static masked count_in_mask(const pic *a, const pic *b, const unsigned char *mask, int thresh) {
    masked m = {0};
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++) {
            int in = mask[(size_t)y * a->w + x];
            m.mask_px += in;
            if (pixel_diff(a, b, x, y) <= thresh) continue;
            m.changed++;
            m.in_mask += in;
        }
    return m;
}

TEST(post_bloom_kernel_sums_to_one) {
    float w[WW_BLOOM_MAX_FETCHES], o[WW_BLOOM_MAX_FETCHES];
    ENSURE_EQ_INT(ww_bloom_kernel(1, 0.5, w, o), 3);
    ENSURE_NEAR(w[0] + 2.0 * (w[1] + w[2]), 1.0, BLOOM_KERNEL_TOL);
    /* Rakos 2010's published figures for the same kernel */
    ENSURE_NEAR(w[0], 0.2270270270, BLOOM_KERNEL_TOL);
    ENSURE_NEAR(w[1], 0.3162162162, BLOOM_KERNEL_TOL);
    ENSURE_NEAR(w[2], 0.0702702703, BLOOM_KERNEL_TOL);
    ENSURE_NEAR(o[1], 1.3846153846, BLOOM_KERNEL_TOL);
    ENSURE_NEAR(o[2], 3.2307692308, BLOOM_KERNEL_TOL);
}

/* rounds of the 9-tap kernel merged into one (one pass pair for render.bloom.passes rounds):
 * the variances of convolved kernels add, so n rounds spread n times the one round's variance,
 * less what the dropped faint taps held (BLOOM_TAIL); and it takes fewer fetches than the rounds */
static double bloom_variance(int passes, int *fetches) {
    float w[WW_BLOOM_MAX_FETCHES], o[WW_BLOOM_MAX_FETCHES];
    int n = ww_bloom_kernel(passes, 0.5, w, o);
    *fetches = 2 * n - 1;
    double v = 0.0, sum = w[0];
    for (int i = 1; i < n; i++) {
        /* the fetch between taps a and a + 1 at offset o splits back into its two taps */
        int a = 2 * i - 1;
        double wb = w[i] * (o[i] - a), wa = w[i] - wb;
        v += 2.0 * (wa * a * a + wb * (a + 1) * (a + 1));
        sum += 2.0 * w[i];
    }
    ENSURE_NEAR(sum, 1.0, BLOOM_KERNEL_TOL);
    return v;
}

TEST(post_bloom_rounds_merged) {
    int f1, fn;
    double v1 = bloom_variance(1, &f1);
    for (int n = 2; n <= 16; n++) {
        double vn = bloom_variance(n, &fn);
        ENSURE_MSG(fabs(vn / (n * v1) - 1.0) < BLOOM_MERGED_VAR_TOL,
                   "%d rounds: variance %.4f, %d x %.4f", n, vn, n, v1);
        ENSURE_MSG(fn < n * f1, "%d rounds: %d fetches", n, fn);
    }
}

/* render.bloom.scale sets the blur's resolution, not the look: the glow the bloom adds (the frame
 * with it less the frame without, summed over the frame) stays within BLOOM_SCALE_ENERGY_TOL of
 * the half-size blur's at a quarter and an eighth, and the frames within BLOOM_SCALE_PSNR_MIN dB.
 * Before the kernel was matched a quarter-size blur drew a glow twice as wide (45.8 dB on the
 * demo's glitter) */
static double glow_energy(const pic *on, const pic *off) {
    double e = 0.0;
    for (int y = 0; y < on->h; y++)
        for (int x = 0; x < on->w; x++) e += ww_test_pic_luma(on, x, y) - ww_test_pic_luma(off, x, y);
    return e;
}

TEST_IMAGE(post_bloom_scale_keeps_the_glow) {
    REQUIRE_GL();
    const char *scene = "scenes/demo.yaml";
    pic off, half, quarter, eighth;
    int ok = ww_test_render_pic(scene, 240, "640x360", "--set render.bloom=false", "bl_off", &off) &&
             ww_test_render_pic(scene, 240, "640x360", "--set render.bloom.scale=0.5", "bl_half", &half) &&
             ww_test_render_pic(scene, 240, "640x360", "--set render.bloom.scale=0.25", "bl_quarter",
                                &quarter) &&
             ww_test_render_pic(scene, 240, "640x360", "--set render.bloom.scale=0.125", "bl_eighth",
                                &eighth);
    if (!ok) return;
    double e_half = glow_energy(&half, &off);
    ENSURE_MSG(e_half > 0.0, "the bloom adds no light (%.0f)", e_half);
    const pic *low[2] = {&quarter, &eighth};
    for (int i = 0; i < 2; i++) {
        int most = 0;
        double psnr = ww_test_pic_psnr(&half, low[i], &most), e = glow_energy(low[i], &off);
        fprintf(stderr, "(scale %s: %.1f dB, max %d, glow %.3f of the half's) ", i ? "1/8" : "1/4",
                psnr, most, e / e_half);
        ENSURE_MSG(psnr >= BLOOM_SCALE_PSNR_MIN, "%.1f dB against the half-size blur", psnr);
        ENSURE_MSG(fabs(e / e_half - 1.0) <= BLOOM_SCALE_ENERGY_TOL, "glow %.3f of the half's", e / e_half);
    }
}

TEST_IMAGE(post_bloom_golden) {
    REQUIRE_GL();
    golden("bloom");
}

/* bloom off: the pixels that change lie around what is bright (the sun and its glitter) */
TEST_IMAGE(post_bloom_toggle) {
    REQUIRE_GL();
    const char *scene = "scenes/features/bloom.yaml";
    char on[1024], off[1024];
    if (render_to(scene, NULL, "post_bloom_on", on, sizeof on) ||
        render_to(scene, "--set render.bloom=false", "post_bloom_off", off, sizeof off))
        return;
    pic a, b;
    if (!ww_test_pic_load(on, &a) || !ww_test_pic_load(off, &b)) goto done;
    size_t n = (size_t)a.w * (size_t)a.h;
    unsigned char *bright = calloc(n, 1), *near = calloc(n, 1);
    if (bright && near) {
        for (int y = 0; y < b.h; y++)
            for (int x = 0; x < b.w; x++)
                bright[(size_t)y * b.w + x] = ww_test_pic_luma(&b, x, y) >= BLOOM_BRIGHT_LUMA;
        dilate(bright, near, b.w, b.h, BLOOM_REACH_PX);
        masked m = count_in_mask(&a, &b, near, 0);
        fprintf(stderr, "(%ld changed, %ld near bright of %ld px) ", m.changed, m.in_mask, (long)n);
        ENSURE_MSG(m.changed >= BLOOM_MIN_CHANGED * (double)n, "bloom changed only %ld px", m.changed);
        ENSURE_MSG(m.in_mask == m.changed, "%ld px changed away from bright areas",
                   m.changed - m.in_mask);
        ENSURE(m.mask_px < (long)n); /* the region is a region, not the whole frame */
    }
    free(bright);
    free(near);
    ENSURE(plan_lists(scene, NULL, "bright pass, separable Gaussian"));
    ENSURE(!plan_lists(scene, "--set render.bloom=false", "bright pass, separable Gaussian"));
done:
    ww_image_free(&a.im);
    ww_image_free(&b.im);
}

TEST_IMAGE(post_shafts_golden) {
    REQUIRE_GL();
    golden("shafts");
}

/* shafts off under water: a large share of the frame loses light, and no pixel gains any
 * (the shafts only add) */
TEST_IMAGE(post_shafts_toggle) {
    REQUIRE_GL();
    const char *scene = "scenes/features/shafts.yaml";
    char on[1024], off[1024];
    if (render_to(scene, NULL, "post_shafts_on", on, sizeof on) ||
        render_to(scene, "--set render.god_rays=false", "post_shafts_off", off, sizeof off))
        return;
    pic a, b;
    if (!ww_test_pic_load(on, &a) || !ww_test_pic_load(off, &b)) goto done;
    long changed = 0, darker = 0, n = (long)a.w * a.h;
    for (int y = 0; y < a.h; y++)
        for (int x = 0; x < a.w; x++) {
            changed += pixel_diff(&a, &b, x, y) > 0;
            darker += ww_test_pic_luma(&a, x, y) < ww_test_pic_luma(&b, x, y);
        }
    fprintf(stderr, "(%ld of %ld px lit by shafts) ", changed, n);
    ENSURE_MSG(changed >= SHAFTS_MIN_CHANGED * (double)n, "shafts changed only %ld px", changed);
    ENSURE_MSG(darker == 0, "%ld px darker with shafts on", darker);
    ENSURE(plan_lists(scene, NULL, "radial blur toward the sun"));
    ENSURE(!plan_lists(scene, "--set render.god_rays=false", "radial blur toward the sun"));
done:
    ww_image_free(&a.im);
    ww_image_free(&b.im);
}

TEST_IMAGE(post_fxaa_golden) {
    REQUIRE_GL();
    golden("fxaa");
}

/* FXAA changes pixels on or next to luma edges of its input, and only those */
TEST_IMAGE(post_fxaa_toggle) {
    REQUIRE_GL();
    const char *scene = "scenes/features/fxaa.yaml";
    char on[1024], off[1024];
    if (render_to(scene, NULL, "post_fxaa_on", on, sizeof on) ||
        render_to(scene, "--set render.fxaa=false", "post_fxaa_off", off, sizeof off))
        return;
    pic a, b;
    if (!ww_test_pic_load(on, &a) || !ww_test_pic_load(off, &b)) goto done;
    unsigned char *edges = edge_mask(&b);
    if (edges) {
        long n = (long)a.w * a.h;
        masked m = count_in_mask(&a, &b, edges, 0);
        fprintf(stderr, "(%ld changed, %ld on edges; edge mask %ld of %ld px) ", m.changed,
                m.in_mask, m.mask_px, n);
        ENSURE_MSG(m.changed >= FXAA_MIN_CHANGED * (double)n, "FXAA changed only %ld px", m.changed);
        ENSURE_MSG(m.in_mask >= FXAA_ON_EDGES_MIN * (double)m.changed,
                   "only %ld of %ld changed px on edges", m.in_mask, m.changed);
        ENSURE(m.mask_px < n / 2);
    }
    free(edges);
    ENSURE(plan_lists(scene, NULL, "edge anti-aliasing"));
    ENSURE(!plan_lists(scene, "--set render.fxaa=false", "edge anti-aliasing"));
done:
    ww_image_free(&a.im);
    ww_image_free(&b.im);
}

TEST_IMAGE(post_hud_golden) {
    REQUIRE_GL();
    golden("hud");
}

/* the HUD changes only its text box (top left) and the chest marker; the scene's chest lies
 * under the camera, so the marker sits at the bottom edge, near the middle */
TEST_IMAGE(post_hud_toggle) {
    REQUIRE_GL();
    const char *scene = "scenes/features/hud.yaml";
    char on[1024], off[1024];
    if (render_to(scene, "--set render.hud=[clock,counters]", "post_hud_on", on, sizeof on) ||
        render_to(scene, "--set render.hud=[]", "post_hud_off", off, sizeof off))
        return;
    pic a, b;
    if (!ww_test_pic_load(on, &a) || !ww_test_pic_load(off, &b)) goto done;
    double box[4] = {0.0, 0.0, (double)HUD_BOX_RECT_PX / a.w, (double)HUD_BOX_RECT_PY / a.h};
    ww_test_region d;
    ENSURE(ww_test_region_diff(on, off, box, 0, &d) == 0);
    fprintf(stderr, "(text box: %ld px changed inside, %ld outside) ", d.inside, d.outside);
    ENSURE(d.inside > d.inside_px / 2); /* the translucent box darkens the whole corner */
    ENSURE(d.outside == 0);
    ww_image_free(&a.im);
    if (render_to(scene, "--set render.hud=[chest_marker]", "post_hud_marker", on, sizeof on))
        goto done;
    double marker[4] = {HUD_MARKER_RECT[0], HUD_MARKER_RECT[1], HUD_MARKER_RECT[2],
                        HUD_MARKER_RECT[3]};
    ENSURE(ww_test_region_diff(on, off, marker, 0, &d) == 0);
    fprintf(stderr, "(marker: %ld px changed inside, %ld outside) ", d.inside, d.outside);
    ENSURE(d.inside >= HUD_MARKER_MIN_PX);
    ENSURE(d.outside == 0);
    ENSURE(plan_lists(scene, NULL, "text and markers"));
    ENSURE(!plan_lists(scene, "--set render.hud=[]", "text and markers"));
done:
    ww_image_free(&a.im);
    ww_image_free(&b.im);
}

/* the night sky of scenes/minimal.yaml at 640x360: a gradient of about a level every 16 rows.
 * Rounded to 8 bits it lies in flat bands a level apart; dithered, it follows the gradient. The
 * banding is the RMS distance of the sky's profile from a smooth curve: the means of blocks of
 * 8 rows (the dither's period) over the middle 64 columns and the top 30% of the rows, in
 * levels of the sky's strongest channel, against the cubic fitted to them by least squares */
#define BAND_DITHERED_MAX 0.08 /* levels RMS: dithered, 0.024 */
#define BAND_ROUNDED_MIN 0.12  /* and rounded, 0.20: a band's flat top and its step */

/* the least-squares polynomial of degree 3 through (x_i, y_i), i < n, evaluated at every x_i
 * (normal equations on x scaled to [-1, 1], solved by Gaussian elimination) */
static void cubic_fit(const double *y, int n, double *fit) {
    double a[4][5] = {{0.0}};
    for (int i = 0; i < n; i++) {
        double x = n > 1 ? 2.0 * i / (n - 1) - 1.0 : 0.0, p[4] = {1.0, x, x * x, x * x * x};
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) a[r][c] += p[r] * p[c];
            a[r][4] += p[r] * y[i];
        }
    }
    for (int k = 0; k < 4; k++)
        for (int r = k + 1; r < 4; r++) {
            double m = a[r][k] / a[k][k];
            for (int c = k; c < 5; c++) a[r][c] -= m * a[k][c];
        }
    double w[4];
    for (int k = 3; k >= 0; k--) {
        w[k] = a[k][4];
        for (int c = k + 1; c < 4; c++) w[k] -= a[k][c] * w[c];
        w[k] /= a[k][k];
    }
    for (int i = 0; i < n; i++) {
        double x = n > 1 ? 2.0 * i / (n - 1) - 1.0 : 0.0;
        fit[i] = w[0] + x * (w[1] + x * (w[2] + x * w[3]));
    }
}

static double sky_banding(const pic *p) {
    enum { COLS = 64, BLOCK = 8, MAX_BLOCKS = 64 };
    int x0 = p->w / 2 - COLS / 2, n = p->h * 3 / 10 / BLOCK;
    n = n < MAX_BLOCKS ? n : MAX_BLOCKS;
    double sum[3] = {0.0, 0.0, 0.0}, prof[MAX_BLOCKS], fit[MAX_BLOCKS], e = 0.0;
    for (int y = 0; y < n * BLOCK; y++)
        for (int x = x0; x < x0 + COLS; x++)
            for (int c = 0; c < 3; c++) sum[c] += ww_test_pixel(&p->im, x, y)[c];
    int ch = sum[2] >= sum[1] ? (sum[2] >= sum[0] ? 2 : 0) : (sum[1] >= sum[0] ? 1 : 0);
    for (int b = 0; b < n; b++) {
        double m = 0.0;
        for (int y = b * BLOCK; y < (b + 1) * BLOCK; y++)
            for (int x = x0; x < x0 + COLS; x++) m += ww_test_pixel(&p->im, x, y)[ch];
        prof[b] = m / (BLOCK * COLS);
    }
    cubic_fit(prof, n, fit);
    for (int b = 0; b < n; b++) e += (prof[b] - fit[b]) * (prof[b] - fit[b]);
    return n > 0 ? sqrt(e / n) : 0.0;
}

TEST_IMAGE(post_dither_no_bands_in_the_night_sky) {
    REQUIRE_GL();
    const char *sc = "scenes/minimal.yaml";
    pic on, off;
    if (!ww_test_render_pic(sc, 0, "640x360", "--set sky.time_of_day=23", "dither_on", &on))
        return;
    if (!ww_test_render_pic(sc, 0, "640x360",
                            "--set sky.time_of_day=23 --set render.tonemap.dither=false",
                            "dither_off", &off)) {
        ww_image_free(&on.im);
        return;
    }
    double d = sky_banding(&on), r = sky_banding(&off);
    fprintf(stderr, "    the sky's banding: dithered %.3f, rounded %.3f levels RMS\n", d, r);
    ENSURE_MSG(r >= BAND_ROUNDED_MIN, "no bands to take away without the dither (%.3f)", r);
    ENSURE_MSG(d <= BAND_DITHERED_MAX, "banding %.3f > %g levels RMS", d, BAND_DITHERED_MAX);
    int most = 0;
    ww_test_pic_psnr(&on, &off, &most);
    ENSURE_MSG(most <= 1, "the dither moved a pixel by %d levels", most);
    ww_image_free(&on.im);
    ww_image_free(&off.im);
}

/* render.scale 0.5 at 320x180: the frame drawn at 160x90 (the same pixels as a 160x90 frame),
 * then scaled up bilinearly between texel centres; the HUD drawn after it, at 320x180; --alpha
 * read from the smaller depth keeps the full-size frame's coverage but for the rows at an edge */
TEST_IMAGE(post_frame_scale_draws_smaller_and_scales_up) {
    REQUIRE_GL();
    const char *scene = "scenes/lake.yaml";
    char small[1024], big[1024], hud[1024], cov[1024], cov1[1024];
    if (render_to(scene, "--size 160x90", "post_scale_small", small, sizeof small) ||
        render_to(scene, "--size 320x180 --set render.scale=0.5", "post_scale_big", big,
                  sizeof big) ||
        render_to(scene, "--size 320x180 --set render.scale=0.5 --set render.hud=[clock,counters]",
                  "post_scale_hud", hud, sizeof hud) ||
        render_to(scene, "--size 320x180 --set render.scale=0.5 --alpha", "post_scale_alpha",
                  cov, sizeof cov) ||
        render_to(scene, "--size 320x180 --alpha", "post_scale_alpha1", cov1, sizeof cov1))
        return;
    pic a = {0}, b = {0}, h = {0}, c = {0}, c1 = {0};
    if (!ww_test_pic_load(small, &a) || !ww_test_pic_load(big, &b) || !ww_test_pic_load(hud, &h) ||
        !ww_test_pic_load(cov, &c) || !ww_test_pic_load(cov1, &c1))
        goto done;
    ENSURE_EQ_INT(b.w, 320);
    ENSURE_EQ_INT(b.h, 180);
    int worst = 0;
    for (int y = 0; y < b.h; y++) {
        double fy = fmin(fmax((y + 0.5) * a.h / b.h - 0.5, 0.0), a.h - 1.0);
        int y0 = (int)fy, y1 = y0 + 1 < a.h ? y0 + 1 : y0;
        for (int x = 0; x < b.w; x++) {
            double fx = fmin(fmax((x + 0.5) * a.w / b.w - 0.5, 0.0), a.w - 1.0);
            int x0 = (int)fx, x1 = x0 + 1 < a.w ? x0 + 1 : x0;
            double tx = fx - x0, ty = fy - y0;
            for (int k = 0; k < 3; k++) {
                double v = (1 - ty) * ((1 - tx) * ww_test_pixel(&a.im, x0, y0)[k] +
                                       tx * ww_test_pixel(&a.im, x1, y0)[k]) +
                           ty * ((1 - tx) * ww_test_pixel(&a.im, x0, y1)[k] +
                                 tx * ww_test_pixel(&a.im, x1, y1)[k]);
                int e = abs((int)lround(v) - ww_test_pixel(&b.im, x, y)[k]);
                if (e > worst) worst = e;
            }
        }
    }
    ENSURE_MSG(worst <= SCALE_BLIT_TOL, "scaled frame against the small one scaled up: %d levels",
               worst);
    /* the text box lies at the top left in frame pixels: outside it nothing changes */
    double box[4] = {0.0, 0.0, (double)HUD_BOX_RECT_PX / b.w, (double)HUD_BOX_RECT_PY / b.h};
    ww_test_region d;
    ENSURE(ww_test_region_diff(hud, big, box, 0, &d) == 0);
    ENSURE_MSG(d.inside > d.inside_px / 2 && d.outside == 0, "HUD: %ld inside, %ld outside",
               d.inside, d.outside);
    long apart = 0;
    ENSURE(c.im.channels == 4 && c1.im.channels == 4);
    for (int y = 0; c.im.channels == 4 && c1.im.channels == 4 && y < c.h; y++)
        for (int x = 0; x < c.w; x++)
            apart += ww_test_pixel(&c.im, x, y)[3] != ww_test_pixel(&c1.im, x, y)[3];
    ENSURE_MSG(apart <= (long)SCALE_ALPHA_ROWS * c.w, "--alpha at scale 0.5: %ld pixels apart",
               apart);
    ENSURE(plan_lists(scene, "--set render.scale=0.5", "scaled up to the frame"));
    ENSURE(!plan_lists(scene, NULL, "scaled up to the frame"));
done:
    ww_image_free(&a.im);
    ww_image_free(&b.im);
    ww_image_free(&h.im);
    ww_image_free(&c.im);
    ww_image_free(&c1.im);
}

/* MSAA 4 against none: only pixels on or next to edges change (the resolve averages samples
 * only where a triangle's edge crosses the pixel); `plan` shows the samples and their bytes */
TEST_PROC(post_msaa_toggle) {
    REQUIRE_GL();
    const char *scene = "scenes/features/fxaa.yaml";
    char on[1024], off[1024];
    if (render_to(scene, "--set render.fxaa=false --set render.msaa=4", "post_msaa_on", on,
                  sizeof on) ||
        render_to(scene, "--set render.fxaa=false --set render.msaa=0", "post_msaa_off", off,
                  sizeof off))
        return;
    pic a, b;
    if (!ww_test_pic_load(on, &a) || !ww_test_pic_load(off, &b)) goto done;
    unsigned char *edges = edge_mask(&b);
    if (edges) {
        long n = (long)a.w * a.h;
        masked m = count_in_mask(&a, &b, edges, MSAA_LEVELS);
        fprintf(stderr, "(%ld changed, %ld on edges) ", m.changed, m.in_mask);
        ENSURE_MSG(m.changed >= MSAA_MIN_CHANGED * (double)n, "MSAA changed only %ld px", m.changed);
        ENSURE_MSG(m.in_mask >= MSAA_ON_EDGES_MIN * (double)m.changed,
                   "only %ld of %ld changed px on edges", m.in_mask, m.changed);
    }
    free(edges);
    /* 256 x 144 x 8 bytes x 4 samples */
    ENSURE(plan_lists(scene, "--set render.msaa=4", "1179648 bytes  msaa x4"));
    ENSURE(!plan_lists(scene, "--set render.msaa=0", "msaa x"));
done:
    ww_image_free(&a.im);
    ww_image_free(&b.im);
}
