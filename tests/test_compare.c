/* test_compare.c - `waterworld compare` and check/compare.h: every metric against hand-computed
 * values on tiny synthetic images, the 8/16-bit and grey/RGB twins, ImageMagick's RMSE/PSNR and
 * OpenImageIO idiff's max/mean on rendered frames, the rules and exit codes, JSON, the diff image,
 * folders, and the EXR NaN/Inf rules.
 */
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/writers.h"
#include "test.h"
#include "check/compare_impl.h"

/* the metrics are sums in double of floats of v / 255: what is left is rounding */
#define METRIC_TOL 1e-9
#define LEVEL_TOL 1e-4         /* 8-bit levels from float differences */
#define SSIM_TOL 1e-6          /* SSIM from float luma and double window sums */
/* ImageMagick prints 6 significant digits: RMSE 0.00915395, PSNR 40.7678 */
#define IM_RMSE_TOL 1e-6
#define IM_PSNR_TOL 1e-3
/* idiff prints 6 significant digits of values in [0, 1] */
#define IDIFF_TOL 1e-6
#define LEVELS_MAX 255.0       /* the largest difference of 8-bit levels */

/* a w x h PNG (3 or 4 channels) from bytes */
static void write_png(const char *path, int w, int h, int ch, const unsigned char *px) {
    ww_image im;
    ENSURE(ww_image_alloc(&im, w, h, ch, WW_PIX_U8) == 0);
    memcpy(im.u8, px, (size_t)w * (size_t)h * (size_t)ch);
    ww_error err = {0};
    ENSURE_EQ_INT(ww_write_png(path, &im, &err), WW_OK);
    ww_image_free(&im);
}

/* a 4x4 RGB image of one colour with pixel (px, py) set to another */
static void fill4(unsigned char *px, const unsigned char c[3], int x, int y, const unsigned char d[3]) {
    for (int i = 0; i < 16; i++) memcpy(px + 3 * i, c, 3);
    memcpy(px + 3 * (y * 4 + x), d, 3);
}

/* load two PNGs and compare them under o */
static ww_result cmp_files(const char *pa, const char *pb, const ww_cmp_opts *o, ww_cmp_result *res) {
    ww_cmp_image a, b;
    ww_error err = {0};
    ww_result r = ww_cmp_load_pair(pa, pb, &a, &b, &err);
    if (r == WW_OK) r = ww_cmp_images(&a, &b, o, res, &err);
    ww_cmp_image_free(&a);
    ww_cmp_image_free(&b);
    return r;
}

/* ImageMagick's command for tool ("compare" or "convert"): IM 7's `magick` (compare as its
 * subcommand) where it is installed, else IM 6's own command; NULL with neither */
static const char *imagemagick(const char *tool) {
    int compare = strcmp(tool, "compare") == 0;
    if (ww_test_have_tool("magick")) return compare ? "magick compare" : "magick";
    return ww_test_have_tool(tool) ? tool : NULL;
}

/* skip unless ImageMagick 6 or 7 is installed; im names its command for tool */
#define REQUIRE_IMAGEMAGICK(im, tool)                                                           \
    do {                                                                                        \
        if (!((im) = imagemagick(tool)))                                                        \
            SKIP("ImageMagick is not installed (neither magick nor %s)", tool);                 \
    } while (0)

/* a number after key in text (e.g. "\"rmse\":"), NAN when absent */
static double num_after(const char *text, const char *key) {
    const char *p = text ? strstr(text, key) : NULL;
    return p ? strtod(p + strlen(key), NULL) : NAN;
}

TEST(compare_hand_metrics) {
    const char *dir = ww_test_tmpdir("compare_hand");
    char pa[600], pb[600];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    unsigned char a[48], b[48];
    const unsigned char base[3] = {10, 20, 30}, other[3] = {50, 20, 10}; /* +40, 0, -20 */
    fill4(a, base, 1, 1, base);
    fill4(b, base, 1, 1, other);
    write_png(pa, 4, 4, 3, a);
    write_png(pb, 4, 4, 3, b);

    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(!r.identical);
    ENSURE_NEAR(r.max_abs, 40.0, LEVEL_TOL);
    ENSURE_NEAR(r.mean_abs, (40.0 + 20.0) / 48.0, LEVEL_TOL);           /* 16 px x 3 channels */
    double mse = (40.0 * 40.0 + 20.0 * 20.0) / (255.0 * 255.0) / 48.0;
    ENSURE_NEAR(r.rmse, sqrt(mse), METRIC_TOL);
    ENSURE_NEAR(r.psnr, 10.0 * log10(1.0 / mse), 1e-6);
    ENSURE_EQ_INT(r.diff_pixels, 1);
    ENSURE_NEAR(r.diff_percent, 100.0 / 16.0, METRIC_TOL);
    ENSURE_NEAR(r.rel_max, 40.0 / 50.0, 1e-6);
    /* no rule given: exact match required, so this fails and says why */
    ENSURE(!r.pass && strstr(r.why, "no rule given"));

    /* the rules, each on its own, at their edges */
    o.max = 40;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_MSG(r.pass, "--max 40: %s", r.why);
    o.max = 39;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(!r.pass && strstr(r.why, "--max"));
    o = ww_cmp_default_opts();
    o.threshold = 40; /* a pixel differs when over 40: none does */
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.diff_pixels, 0);
    ENSURE(r.pass);
    o.threshold = 39.5;
    o.fail_pixels = 0;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(!r.pass && r.diff_pixels == 1);
    o = ww_cmp_default_opts();
    o.fail_percent = 6.25;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(r.pass);
    o.fail_percent = 6.2;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(!r.pass);
    o = ww_cmp_default_opts();
    o.psnr_min = 10.0 * log10(1.0 / mse) - 0.01;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(r.pass);
    o.psnr_min += 0.02;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(!r.pass && strstr(r.why, "PSNR"));
}

TEST(compare_ssim_by_formula) {
    /* constant grey images x and y: sigma 0, so SSIM = (2xy + C1) / (x^2 + y^2 + C1) */
    const char *dir = ww_test_tmpdir("compare_ssim");
    char pa[600], pb[600];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    unsigned char a[16 * 16 * 3], b[16 * 16 * 3];
    memset(a, 100, sizeof a);
    memset(b, 120, sizeof b);
    write_png(pa, 16, 16, 3, a);
    write_png(pb, 16, 16, 3, b);
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    double x = 100.0 / 255, y = 120.0 / 255, c1 = 0.01 * 0.01;
    ENSURE_NEAR(r.ssim, (2 * x * y + c1) / (x * x + y * y + c1), SSIM_TOL);

    /* identical pixels through the full computation (the hash fast path defeated): exactly 1 */
    ww_cmp_image ia, ib;
    ww_error err = {0};
    unsigned char n[16 * 16 * 3];
    for (size_t i = 0; i < sizeof n; i++) n[i] = (unsigned char)(i * 37 % 251);
    write_png(pa, 16, 16, 3, n);
    ENSURE_EQ_INT(ww_cmp_load_pair(pa, pa, &ia, &ib, &err), WW_OK);
    ib.hash ^= 1;
    ENSURE_EQ_INT(ww_cmp_images(&ia, &ib, &o, &r, &err), WW_OK);
    ENSURE(!r.identical);
    ENSURE(r.ssim == 1.0 && r.max_abs == 0 && isinf(r.psnr) && r.pass);
    /* and with the fast path */
    ib.hash ^= 1;
    ENSURE_EQ_INT(ww_cmp_images(&ia, &ib, &o, &r, &err), WW_OK);
    ENSURE(r.identical && r.pass);
    ww_cmp_image_free(&ia);
    ww_cmp_image_free(&ib);
}

TEST(compare_yiq_pure_colours) {
    /* Kotsarenko & Ramos 2010 delta of red against black on the 8-bit scale */
    const float red[4] = {1, 0, 0, 1}, black[4] = {0, 0, 0, 1}, cyan[4] = {0, 1, 1, 1};
    double y = 0.29889531 * 255, i = 0.59597799 * 255, q = 0.21147017 * 255;
    double want = 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;
    ENSURE_NEAR(ww_cmp_yiq_delta(red, black), want, 1e-6 * want);
    /* red against cyan is the largest delta, pixelmatch's 35215 (35214.749 by the formula) */
    ENSURE_NEAR(ww_cmp_yiq_delta(red, cyan), WW_CMP_YIQ_MAX_DELTA, 1.0);

    /* a red pixel on black: over the threshold 0.5, under 0.6 (sqrt(want / 35215) = 0.544) */
    const char *dir = ww_test_tmpdir("compare_yiq");
    char pa[600], pb[600];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    unsigned char a[48], b[48];
    const unsigned char k[3] = {0, 0, 0}, r8[3] = {255, 0, 0};
    fill4(a, k, 2, 2, k);
    fill4(b, k, 2, 2, r8);
    write_png(pa, 4, 4, 3, a);
    write_png(pb, 4, 4, 3, b);
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    o.yiq = 0.5;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.yiq_pixels, 1);
    ENSURE_EQ_INT(r.aa_pixels, 0);
    o.yiq = 0.6;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.yiq_pixels, 0);
}

/* pixelmatch's colorDelta (Kotsarenko & Ramos 2010 on 8-bit RGBA, a pixel with alpha below 255
 * blended on white), written from its definition with integer samples as pixelmatch reads them:
 * the reference for the bits of ours */
static double pixelmatch_delta(const int p[4], const int q[4]) {
    double dr = p[0] - q[0], dg = p[1] - q[1], db = p[2] - q[2];
    if (p[3] < 255 || q[3] < 255) {
        double da = p[3] - q[3];
        dr = ((double)(p[0] * p[3]) - (double)(q[0] * q[3]) - 255 * da) / 255;
        dg = ((double)(p[1] * p[3]) - (double)(q[1] * q[3]) - 255 * da) / 255;
        db = ((double)(p[2] * p[3]) - (double)(q[2] * q[3]) - 255 * da) / 255;
    }
    double y = dr * 0.29889531 + dg * 0.58662247 + db * 0.11448223;
    double i = dr * 0.59597799 - dg * 0.27417610 - db * 0.32180189;
    double q2 = dr * 0.21147017 - dg * 0.52261711 + db * 0.31114694;
    return 0.5053 * y * y + 0.299 * i * i + 0.1957 * q2 * q2;
}

/* a pixel as the loader holds an 8-bit RGBA sample: v / 255 in float, colour times alpha */
static void held_pixel(const int s[4], float px[4]) {
    float a = ww_cmp_level((unsigned)s[3]);
    for (int c = 0; c < 3; c++) px[c] = ww_cmp_level((unsigned)s[c]) * a;
    px[3] = a;
}

/* our delta is pixelmatch's to the bit: every colour level under every alpha, every pair of
 * opaque levels, and seeded random pairs, opaque and not */
TEST(compare_yiq_delta_bits_pixelmatch) {
    long bad = 0;
    for (int v = 0; v < 256; v++)
        for (int a = 0; a < 256; a++) {
            int p[4] = {v, 255 - v, v / 2, a}, q[4] = {0, 0, 0, 255};
            float fp[4], fq[4];
            held_pixel(p, fp);
            held_pixel(q, fq);
            double want = pixelmatch_delta(p, q), got = ww_cmp_yiq_delta(fp, fq);
            if (got != want && bad++ < 5)
                ENSURE_MSG(0, "level %d alpha %d: %.17g, pixelmatch %.17g", v, a, got, want);
        }
    /* opaque: every pair of levels, so every difference, in each channel */
    for (int u = 0; u < 256; u++)
        for (int v = 0; v < 256; v++) {
            int p[4] = {u, v, (u + v) / 2, 255}, q[4] = {v, u, 255 - u, 255};
            float fp[4], fq[4];
            held_pixel(p, fp);
            held_pixel(q, fq);
            double want = pixelmatch_delta(p, q), got = ww_cmp_yiq_delta(fp, fq);
            if (got != want && bad++ < 5)
                ENSURE_MSG(0, "levels %d, %d: %.17g, pixelmatch %.17g", u, v, got, want);
        }
    uint32_t seed = 12345;
    for (int k = 0; k < 200000; k++) {
        int p[4], q[4];
        for (int c = 0; c < 4; c++) {
            seed = seed * 1664525u + 1013904223u;
            p[c] = (int)(seed >> 24);
            seed = seed * 1664525u + 1013904223u;
            q[c] = (int)(seed >> 24);
        }
        if (k % 2) p[3] = q[3] = 255; /* half opaque: pixelmatch's r1 - r2 branch */
        float fp[4], fq[4];
        held_pixel(p, fp);
        held_pixel(q, fq);
        double want = pixelmatch_delta(p, q), got = ww_cmp_yiq_delta(fp, fq);
        if (got != want && bad++ < 5)
            ENSURE_MSG(0, "(%d %d %d %d) against (%d %d %d %d): %.17g, pixelmatch %.17g", p[0],
                       p[1], p[2], p[3], q[0], q[1], q[2], q[3], got, want);
    }
    ENSURE_EQ_INT(bad, 0);
}

/* 8x8: black left of x = 4, white right of it, and a grey column at x = 4 (an edge's
 * anti-aliasing) whose grey differs between the two images */
static void edge_image(unsigned char *px, unsigned char grey, int spot) {
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            unsigned char v = x < 4 ? 0 : x > 4 ? 255 : grey;
            memset(px + 3 * (y * 8 + x), v, 3);
        }
    /* and, with spot, a pixel in the flat white area that is not anti-aliasing */
    if (spot) memset(px + 3 * (3 * 8 + 6), 0, 3);
}

TEST(compare_aa_edge) {
    const char *dir = ww_test_tmpdir("compare_aa");
    char pa[600], pb[600];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    unsigned char a[8 * 8 * 3], b[8 * 8 * 3];
    edge_image(a, 96, 0);
    edge_image(b, 176, 1);
    write_png(pa, 8, 8, 3, a);
    write_png(pb, 8, 8, 3, b);
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.aa_pixels, 8);  /* the whole grey column */
    ENSURE_EQ_INT(r.yiq_pixels, 1); /* the black spot on white */
    o.detect_aa = 0;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.aa_pixels, 0);
    ENSURE_EQ_INT(r.yiq_pixels, 9);

    /* the diff image: AA yellow, the spot red, the rest grey */
    char pd[600];
    snprintf(pd, sizeof pd, "%s/diff.png", dir);
    ww_cmp_image ia, ib;
    ww_error err = {0};
    o = ww_cmp_default_opts();
    o.threshold = 255; /* only pixelmatch's classes paint */
    ENSURE_EQ_INT(ww_cmp_load_pair(pa, pb, &ia, &ib, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_write_diff(pd, &ia, &ib, &o, &err), WW_OK);
    ww_cmp_image_free(&ia);
    ww_cmp_image_free(&ib);
    ww_image d;
    ENSURE_EQ_INT(ww_read_png(pd, &d, &err), WW_OK);
    const unsigned char *spot = d.u8 + 3 * (3 * 8 + 6), *aa = d.u8 + 3 * (5 * 8 + 4);
    const unsigned char *flat = d.u8 + 3 * (1 * 8 + 1);
    ENSURE(spot[0] == 255 && spot[1] == 0 && spot[2] == 0);
    ENSURE(aa[0] == 255 && aa[1] == 255 && aa[2] == 0);
    /* black faded to 10% contrast: 255 - 25.5 */
    ENSURE(flat[0] == flat[1] && flat[1] == flat[2] && flat[0] >= 229 && flat[0] <= 230);
    ww_image_free(&d);
}

/* ImageMagick writes the twins: 16-bit RGB, 8-bit grey and opaque RGBA of an 8-bit RGB grey
 * picture */
TEST_PROC(compare_twins_16bit_grey) {
    const char *im;
    REQUIRE_IMAGEMAGICK(im, "convert");
    const char *dir = ww_test_tmpdir("compare_twins");
    char p8[600], p16[600], pg[600], pa[600], cmd[4096];
    snprintf(p8, sizeof p8, "%s/rgb8.png", dir);
    snprintf(p16, sizeof p16, "%s/rgb16.png", dir);
    snprintf(pg, sizeof pg, "%s/grey8.png", dir);
    snprintf(pa, sizeof pa, "%s/rgba8.png", dir);
    unsigned char px[8 * 8 * 3];
    for (int i = 0; i < 64; i++) memset(px + 3 * i, (i * 53) % 256, 3);
    write_png(p8, 8, 8, 3, px);
    snprintf(cmd, sizeof cmd, "%s %s -depth 16 PNG48:%s && %s %s -colorspace Gray "
             "-define png:color-type=0 -depth 8 %s && %s %s -alpha opaque PNG32:%s", im, p8, p16,
             im, p8, pg, im, p8, pa);
    ENSURE_MSG(ww_test_run(cmd, NULL, NULL) == 0, "ImageMagick convert failed: %s", cmd);
    ww_cmp_image a, b, g;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_cmp_load(p8, &a, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_load(p16, &b, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_load(pg, &g, &err), WW_OK);
    ENSURE(a.bits == 8 && b.bits == 16 && g.channels == 1 && a.channels == 3);
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    ENSURE_EQ_INT(ww_cmp_images(&a, &b, &o, &r, &err), WW_OK);
    ENSURE_MSG(r.identical, "16-bit twin: max %g", r.max_abs);
    ENSURE_EQ_INT(ww_cmp_images(&a, &g, &o, &r, &err), WW_OK);
    ENSURE_MSG(r.identical, "grey twin: max %g", r.max_abs);
    ww_cmp_image rgba;
    ENSURE_EQ_INT(ww_cmp_load(pa, &rgba, &err), WW_OK);
    ENSURE_EQ_INT(rgba.channels, 4);
    ENSURE_EQ_INT(ww_cmp_images(&a, &rgba, &o, &r, &err), WW_OK);
    ENSURE_MSG(r.identical && r.pass, "opaque RGBA twin: max %g", r.max_abs);
    ww_cmp_image_free(&rgba);
    ww_cmp_image_free(&a);
    ww_cmp_image_free(&b);
    ww_cmp_image_free(&g);
}

TEST_PROC(compare_cli_exit_codes) {
    const char *dir = ww_test_tmpdir("compare_exit");
    char pa[600], pb[600], pc[600], pt[600], args[4096], out[600];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    snprintf(pc, sizeof pc, "%s/c.png", dir);
    snprintf(pt, sizeof pt, "%s/t.png", dir);
    snprintf(out, sizeof out, "%s/out.txt", dir);
    unsigned char a[48], b[48], c[8 * 4 * 3] = {0};
    const unsigned char k[3] = {0, 0, 0}, g[3] = {3, 3, 3};
    fill4(a, k, 0, 0, k);
    fill4(b, k, 0, 0, g);
    write_png(pa, 4, 4, 3, a);
    write_png(pb, 4, 4, 3, b);
    write_png(pc, 8, 4, 3, c);
    ENSURE(ww_test_write_text(pt, "not an image") == 0);

    snprintf(args, sizeof args, "compare %s %s", pa, pa);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "identical"));
    snprintf(args, sizeof args, "compare %s %s", pa, pb);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 1);
    snprintf(args, sizeof args, "compare %s %s --max 3", pa, pb);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(args, sizeof args, "compare %s %s --max=2", pa, pb);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 1);
    /* bad input: sizes differ, not an image, no such file, a bad threshold */
    snprintf(args, sizeof args, "compare %s %s", pa, pc);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, out), 2);
    ENSURE(ww_test_file_contains(out, "sizes differ"));
    snprintf(args, sizeof args, "compare %s %s", pa, pt);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, out), 2);
    ENSURE(ww_test_file_contains(out, "t.png"));
    snprintf(args, sizeof args, "compare %s %s/none.png", pa, dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 2);
    snprintf(args, sizeof args, "compare %s %s --max -1", pa, pb);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 2);
    snprintf(args, sizeof args, "compare %s", pa);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 2);
}

TEST_PROC(compare_cli_folders_json_diff) {
    const char *dir = ww_test_tmpdir("compare_dirs");
    char e[600], a[600], d[600], p[700], args[4096], out[600];
    snprintf(e, sizeof e, "%s/expected", dir);
    snprintf(a, sizeof a, "%s/actual", dir);
    snprintf(d, sizeof d, "%s/diffs", dir);
    snprintf(out, sizeof out, "%s/out.txt", dir);
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "mkdir -p %s %s", e, a);
    ENSURE(ww_test_run(cmd, NULL, NULL) == 0);
    unsigned char k[48], x[48];
    const unsigned char black[3] = {0, 0, 0}, red[3] = {200, 0, 0};
    fill4(k, black, 0, 0, black);
    fill4(x, black, 2, 1, red);
    /* frame 0 equal, frame 1 differs at (2, 1), frame 2 missing from actual */
    snprintf(p, sizeof p, "%s/frame_00000.png", e), write_png(p, 4, 4, 3, k);
    snprintf(p, sizeof p, "%s/frame_00001.png", e), write_png(p, 4, 4, 3, k);
    snprintf(p, sizeof p, "%s/frame_00002.png", e), write_png(p, 4, 4, 3, k);
    snprintf(p, sizeof p, "%s/frame_00000.png", a), write_png(p, 4, 4, 3, k);
    snprintf(p, sizeof p, "%s/frame_00001.png", a), write_png(p, 4, 4, 3, x);

    snprintf(args, sizeof args, "compare %s %s --json --diff %s", e, a, d);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 1);
    char *text = ww_test_read_file(out, NULL);
    ENSURE_EQ_INT(ww_test_json_lines(text), 4); /* 3 frames and the summary */
    ENSURE(text && strstr(text, "\"name\":\"frame_00002.png\",\"missing\":true"));
    ENSURE(text && strstr(text, "\"summary\":true,\"pairs\":2,\"passed\":1,\"failed\":1,\"missing\":1"));
    free(text);

    /* the diff of the failing frame only: red at (2, 1), faded grey elsewhere */
    snprintf(p, sizeof p, "%s/frame_00000.png", d);
    ENSURE(ww_test_read_file(p, NULL) == NULL);
    snprintf(p, sizeof p, "%s/frame_00001.png", d);
    ww_image im;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_read_png(p, &im, &err), WW_OK);
    if (im.u8) {
        const unsigned char *hit = im.u8 + 3 * (1 * 4 + 2), *calm = im.u8;
        ENSURE(hit[0] == 255 && hit[1] == 0 && hit[2] == 0);
        ENSURE(calm[0] == calm[1] && calm[1] == calm[2] && calm[0] > 200);
    }
    ww_image_free(&im);

    /* the text report names the missing frame; an extra frame fails too */
    snprintf(args, sizeof args, "compare %s %s", e, a);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 1);
    ENSURE(ww_test_file_contains(out, "frame_00002.png: FAIL: missing"));
    snprintf(p, sizeof p, "%s/frame_00001.png", a), write_png(p, 4, 4, 3, k);
    snprintf(p, sizeof p, "%s/frame_00002.png", a), write_png(p, 4, 4, 3, k);
    snprintf(args, sizeof args, "compare %s %s", e, a);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 0);
    snprintf(p, sizeof p, "%s/frame_00003.png", a), write_png(p, 4, 4, 3, k);
    ENSURE_EQ_INT(ww_test_ww(args, out, NULL), 1);
    ENSURE(ww_test_file_contains(out, "frame_00003.png: FAIL: extra"));
}

/* our RMSE against ImageMagick's on an RGBA pair: premultiplied colour, alpha not counted. IM 6
 * leaves alpha out of `compare -metric RMSE` by itself, IM 7 counts it unless told
 * `-channel RGB` (0.360055 here without it), which gives IM 6's figure on both */
TEST_PROC(compare_imagemagick_alpha) {
    const char *im;
    REQUIRE_IMAGEMAGICK(im, "compare");
    const char *dir = ww_test_tmpdir("compare_im_alpha");
    char pa[600], pb[600], cmd[2048], out[600];
    snprintf(pa, sizeof pa, "%s/a.png", dir);
    snprintf(pb, sizeof pb, "%s/b.png", dir);
    snprintf(out, sizeof out, "%s/im.txt", dir);
    unsigned char a[64], b[64];
    for (int i = 0; i < 16; i++) {
        unsigned char pa4[4] = {(unsigned char)(i * 16), 200, (unsigned char)(255 - i * 9), (unsigned char)(i * 17)};
        unsigned char pb4[4] = {(unsigned char)(i * 15), 190, 40, (unsigned char)(255 - i * 5)};
        memcpy(a + 4 * i, pa4, 4);
        memcpy(b + 4 * i, pb4, 4);
    }
    write_png(pa, 4, 4, 4, a);
    write_png(pb, 4, 4, 4, b);
    snprintf(cmd, sizeof cmd, "%s -channel RGB -metric RMSE %s %s null:", im, pa, pb);
    ENSURE(ww_test_run(cmd, NULL, out) >= 0); /* IM prints the metric on stderr */
    char *said = ww_test_read_file(out, NULL);
    double im_rmse = num_after(said, "(");
    free(said);
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_NEAR(r.rmse, im_rmse, IM_RMSE_TOL);
}

/* two rendered frames against ImageMagick compare (6 or 7, over R, G, B) and OpenImageIO idiff */
TEST_PROC(compare_tools_agree_on_frames) {
    const char *im;
    REQUIRE_IMAGEMAGICK(im, "compare");
    REQUIRE_TOOL("idiff");
    REQUIRE_GL();
    const char *dir = ww_test_tmpdir("compare_frames");
    char cmd[4096], f0[600], f1[600], out[600];
    snprintf(cmd, sizeof cmd, "%s render scenes/demo.yaml --frames 0:2 --size 256x144 -o %s --quiet",
             ww_test_bin(), dir);
    ENSURE_EQ_INT(ww_test_run(cmd, NULL, NULL), 0);
    snprintf(f0, sizeof f0, "%s/frame_00000.png", dir);
    snprintf(f1, sizeof f1, "%s/frame_00001.png", dir);
    snprintf(out, sizeof out, "%s/tool.txt", dir);

    ww_cmp_opts o = ww_cmp_default_opts();
    ww_cmp_result r;
    ENSURE_EQ_INT(cmp_files(f0, f1, &o, &r), WW_OK);
    ENSURE_MSG(r.max_abs > 0, "frames 0 and 1 of the demo should differ");

    snprintf(cmd, sizeof cmd, "%s -channel RGB -metric RMSE %s %s null:", im, f0, f1);
    ww_test_run(cmd, NULL, out); /* exit 1: they differ; the metric is on stderr */
    char *t = ww_test_read_file(out, NULL);
    ENSURE_NEAR(r.rmse, num_after(t, "("), IM_RMSE_TOL);
    free(t);
    snprintf(cmd, sizeof cmd, "%s -channel RGB -metric PSNR %s %s null:", im, f0, f1);
    ww_test_run(cmd, NULL, out);
    t = ww_test_read_file(out, NULL);
    double im_psnr = t ? strtod(t, NULL) : NAN; /* IM 7 adds "(PSNR / 100)" after it */
    ENSURE_NEAR(r.psnr, im_psnr, IM_PSNR_TOL);
    free(t);

    /* idiff reports errors on [0, 1]; ours are in levels */
    snprintf(cmd, sizeof cmd, "idiff %s %s", f0, f1);
    ww_test_run(cmd, out, NULL);
    t = ww_test_read_file(out, NULL);
    ENSURE_NEAR(r.mean_abs / 255.0, num_after(t, "Mean error = "), IDIFF_TOL);
    ENSURE_NEAR(r.max_abs / 255.0, num_after(t, "Max error  = "), IDIFF_TOL);
    free(t);
}

/* ---- against the real pixelmatch ---------------------------------------------------------------- */

#define PIXELMATCH_VERSION "7.2.0"
/* pixelmatch's default threshold and one either side of it */
static const double pm_thresholds[] = {0.05, 0.1, 0.2};
#define PM_PAIRS_MAX 48

/* the pixelmatch package that scripts/install-pixelmatch.sh unpacks into the user's cache
 * ($WW_PIXELMATCH_DIR instead, when set); 1 when its index.js is there */
static int pixelmatch_dir(char *dir, size_t n) {
    const char *env = getenv("WW_PIXELMATCH_DIR"), *xdg = getenv("XDG_CACHE_HOME");
    const char *home = getenv("HOME");
    if (env && *env)
        snprintf(dir, n, "%s", env);
    else if (xdg && *xdg)
        snprintf(dir, n, "%s/waterworld/pixelmatch-" PIXELMATCH_VERSION, xdg);
    else
        snprintf(dir, n, "%s/.cache/waterworld/pixelmatch-" PIXELMATCH_VERSION, home ? home : "");
    char index[700];
    snprintf(index, sizeof index, "%s/index.js", dir);
    FILE *f = fopen(index, "rb");
    if (f) fclose(f);
    return f != NULL;
}

/* node and pixelmatch are here, or the test is skipped naming what is missing */
#define REQUIRE_PIXELMATCH(dir)                                                                 \
    do {                                                                                        \
        REQUIRE_TOOL("node");                                                                   \
        if (!pixelmatch_dir(dir, sizeof dir))                                                   \
            SKIP("pixelmatch " PIXELMATCH_VERSION " is not in %s (scripts/install-pixelmatch.sh " \
                 "fetches it)", dir);                                                           \
    } while (0)

/* one pair as both sides see it: ours from PNG files, pixelmatch from the same pixels as raw
 * RGBA (straight alpha) */
typedef struct pm_pair {
    char png[2][600], raw[2][600], out[600];
    char name[96];
    int opaque;
} pm_pair;

/* a PNG's pixels as RGBA bytes (malloc'd), or NULL */
static unsigned char *png_rgba(const char *path, int *w, int *h) {
    ww_image im;
    ww_error err = {0};
    if (ww_read_png(path, &im, &err) != WW_OK) return NULL;
    size_t npx = (size_t)im.width * (size_t)im.height;
    unsigned char *px = malloc(4 * npx);
    for (size_t i = 0; px && i < npx; i++) {
        const unsigned char *s = im.u8 + (size_t)im.channels * i;
        int grey = im.channels < 3;
        for (int c = 0; c < 3; c++) px[4 * i + (size_t)c] = s[grey ? 0 : c];
        px[4 * i + 3] = im.channels == 2 || im.channels == 4 ? s[im.channels - 1] : 255;
    }
    *w = im.width;
    *h = im.height;
    ww_image_free(&im);
    return px;
}

static int write_bytes(const char *path, const unsigned char *p, size_t n) {
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    size_t put = fwrite(p, 1, n, f);
    return fclose(f) == 0 && put == n ? 0 : -1;
}

/* a pair of PNG files into the list: their pixels written raw for pixelmatch; with alpha_kind > 0
 * both get an alpha channel (1: the same ramp across, 2: ramps across and down), alpha at least 1
 * (under alpha 0 we differ on purpose: see README), and are written again as RGBA PNGs for us.
 * One pixelmatch run takes one size: the first pair's sets w x h, a pair of another size is left
 * out (returns 0) */
static int pm_add(pm_pair *pairs, int *n, const char *dir, const char *a, const char *b,
                  const char *name, int alpha_kind, int *w, int *h) {
    ENSURE(*n < PM_PAIRS_MAX);
    if (*n >= PM_PAIRS_MAX) return 0;
    pm_pair *p = &pairs[*n];
    snprintf(p->name, sizeof p->name, "%s%s", name,
             alpha_kind == 1 ? " (alpha ramp)" : alpha_kind == 2 ? " (alphas differ)" : "");
    p->opaque = alpha_kind == 0;
    const char *src[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        int pw = 0, ph = 0;
        unsigned char *px = png_rgba(src[k], &pw, &ph);
        ENSURE_MSG(px != NULL, "cannot read %s", src[k]);
        if (!px) return 0;
        if (*w != 0 && (pw != *w || ph != *h)) {
            free(px);
            return 0;
        }
        *w = pw, *h = ph;
        snprintf(p->png[k], sizeof p->png[k], "%s", src[k]);
        if (alpha_kind) {
            for (int y = 0; y < ph; y++)
                for (int x = 0; x < pw; x++) {
                    int t = k == 1 && alpha_kind == 2 ? y * 254 / (ph - 1) : x * 254 / (pw - 1);
                    px[4 * ((size_t)y * (size_t)pw + (size_t)x) + 3] = (unsigned char)(1 + t);
                }
            snprintf(p->png[k], sizeof p->png[k], "%s/%d_%c.png", dir, *n, "ab"[k]);
            write_png(p->png[k], pw, ph, 4, px);
        }
        snprintf(p->raw[k], sizeof p->raw[k], "%s/%d_%c.rgba", dir, *n, "ab"[k]);
        ENSURE(write_bytes(p->raw[k], px, 4 * (size_t)pw * (size_t)ph) == 0);
        free(px);
    }
    snprintf(p->out, sizeof p->out, "%s/%d_pm.rgba", dir, *n);
    (*n)++;
    return 1;
}

/* our pixelmatch figures for a loaded pair at threshold t: counts with and without anti-aliasing
 * detection, each pixel's class against pixelmatch's diff image (red a difference, yellow
 * anti-aliasing), and with image, our diff image against its (one layout is enough:
 * compare_rgb8_layout_matches_rgba finds the two layouts' diff images equal); 1 when all agree */
static int pm_check_pair(const pm_pair *p, const ww_cmp_image *a, const ww_cmp_image *b, double t,
                         long pm_diff, long pm_aa, const char *layout, int image) {
    ww_cmp_opts o = ww_cmp_default_opts();
    o.yiq = t;
    ww_cmp_result r;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_cmp_images(a, b, &o, &r, &err), WW_OK);
    ENSURE_MSG(r.yiq_pixels == pm_diff && r.aa_pixels == pm_aa,
               "%s, %s, threshold %g: ours %ld (+%ld aa), pixelmatch %ld (+%ld aa)", p->name,
               layout, t, r.yiq_pixels, r.aa_pixels, pm_diff, pm_aa);
    int ok = r.yiq_pixels == pm_diff && r.aa_pixels == pm_aa;
    o.detect_aa = 0; /* pixelmatch's includeAA */
    ENSURE_EQ_INT(ww_cmp_images(a, b, &o, &r, &err), WW_OK);
    ENSURE_MSG(r.yiq_pixels == pm_diff + pm_aa && r.aa_pixels == 0,
               "%s, %s, threshold %g, anti-aliasing counted: ours %ld, pixelmatch %ld", p->name,
               layout, t, r.yiq_pixels, pm_diff + pm_aa);
    ok = ok && r.yiq_pixels == pm_diff + pm_aa;

    size_t len = 0, npx = (size_t)a->width * (size_t)a->height;
    unsigned char *pm = (unsigned char *)ww_test_read_file(p->out, &len);
    ENSURE_MSG(pm && len == 4 * npx, "pixelmatch's diff image %s", p->out);
    if (!pm || len != 4 * npx) {
        free(pm);
        return 0;
    }
    o = ww_cmp_default_opts();
    o.yiq = t;
    o.threshold = LEVELS_MAX; /* only pixelmatch's classes: no pixel is over 255 levels */
    long wrong = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            const unsigned char *q = pm + 4 * ((size_t)y * (size_t)a->width + (size_t)x);
            int theirs = q[0] == 255 && q[1] == 0 && q[2] == 0     ? WW_CMP_DIFF
                         : q[0] == 255 && q[1] == 255 && q[2] == 0 ? WW_CMP_AA
                                                                   : WW_CMP_SAME;
            int ours = ww_cmp_pixel_kind(a, b, x, y, &o);
            if (ours != theirs && wrong++ == 0)
                ENSURE_MSG(0, "%s, %s, threshold %g: pixel (%d, %d) is %d for us, %d for pixelmatch "
                           "(0 same, 1 differs, 2 anti-aliasing)", p->name, layout, t, x, y, ours,
                           theirs);
        }
    ENSURE_MSG(wrong == 0, "%s, %s, threshold %g: %ld pixels classed otherwise", p->name, layout, t,
               wrong);

    /* and our diff image is pixelmatch's, byte for byte (RGB: ours has no alpha) */
    if (!image) {
        free(pm);
        return ok && wrong == 0;
    }
    char ours_png[700];
    snprintf(ours_png, sizeof ours_png, "%s.ours.png", p->out);
    ww_image d = {0};
    ENSURE_EQ_INT(ww_cmp_write_diff(ours_png, a, b, &o, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_png(ours_png, &d, &err), WW_OK);
    long other = 0;
    for (size_t i = 0; d.u8 && d.channels == 3 && i < npx; i++)
        if (memcmp(d.u8 + 3 * i, pm + 4 * i, 3) != 0 && other++ == 0)
            ENSURE_MSG(0, "%s, %s, threshold %g: diff image pixel %zu is %d %d %d, pixelmatch's "
                       "%d %d %d", p->name, layout, t, i, d.u8[3 * i], d.u8[3 * i + 1],
                       d.u8[3 * i + 2], pm[4 * i], pm[4 * i + 1], pm[4 * i + 2]);
    ENSURE(d.channels == 3 && other == 0);
    ww_image_free(&d);
    free(pm);
    return ok && wrong == 0 && other == 0;
}

/* pixelmatch (node tests/tools/pixelmatch.mjs) on every pair at each threshold, then ours, in
 * the layout the file loads in and, with both_layouts, an opaque pair in the float RGBA layout
 * as well */
static void pm_check(const char *pmdir, const char *dir, const pm_pair *pairs, int n, int w, int h,
                     int both_layouts) {
    char cmd[2048], out[600], list[600];
    snprintf(out, sizeof out, "%s/pixelmatch.txt", dir);
    snprintf(list, sizeof list, "%s/pairs.txt", dir);
    FILE *f = fopen(list, "w");
    ENSURE(f != NULL);
    if (!f) return;
    for (int k = 0; k < n; k++)
        fprintf(f, "%s\t%s\t%s\n", pairs[k].raw[0], pairs[k].raw[1], pairs[k].out);
    ENSURE(fclose(f) == 0);
    ww_cmp_image a[PM_PAIRS_MAX], b[PM_PAIRS_MAX];
    ww_error err = {0};
    for (int k = 0; k < n; k++) {
        ENSURE_EQ_INT(ww_cmp_load_pair(pairs[k].png[0], pairs[k].png[1], &a[k], &b[k], &err), WW_OK);
        ENSURE_MSG(!pairs[k].opaque || a[k].rgb8, "%s: an opaque 8-bit frame loads as rgb8",
                   pairs[k].name);
    }
    for (size_t ti = 0; ti < sizeof pm_thresholds / sizeof pm_thresholds[0]; ti++) {
        double t = pm_thresholds[ti];
        snprintf(cmd, sizeof cmd, "node tests/tools/pixelmatch.mjs '%s' %d %d %g '@%s'", pmdir, w,
                 h, t, list);
        ENSURE_MSG(ww_test_run(cmd, out, NULL) == 0, "%s", cmd);
        char *text = ww_test_read_file(out, NULL);
        const char *line = text;
        for (int k = 0; k < n; k++) {
            ENSURE_MSG(line && strstr(line, "\"version\":\"" PIXELMATCH_VERSION "\""),
                       "pixelmatch %s answered: %s", PIXELMATCH_VERSION, line ? line : "nothing");
            if (!line) break;
            long pm_diff = (long)num_after(line, "\"diff\":"), pm_aa = (long)num_after(line, "\"aa\":");
            line = strchr(line, '\n');
            if (line) line++;
            int ok = pm_check_pair(&pairs[k], &a[k], &b[k], t, pm_diff, pm_aa, "as loaded", 1);
            if (ok && pairs[k].opaque && both_layouts) {
                ww_cmp_image wa, wb;
                ENSURE_EQ_INT(ww_cmp_to_rgba(&a[k], &wa, &err), WW_OK);
                ENSURE_EQ_INT(ww_cmp_to_rgba(&b[k], &wb, &err), WW_OK);
                pm_check_pair(&pairs[k], &wa, &wb, t, pm_diff, pm_aa, "float RGBA", 0);
                ww_cmp_image_free(&wa);
                ww_cmp_image_free(&wb);
            }
        }
        free(text);
    }
    for (int k = 0; k < n; k++) {
        ww_cmp_image_free(&a[k]);
        ww_cmp_image_free(&b[k]);
    }
}

/* pixelmatch 7.2.0 and ours on the golden frames (no GL needed): each feature as llvmpipe draws
 * it against the same feature as an NVIDIA GPU drew it for an earlier picture
 * (tests/data/golden-nvidia-580: kept as test data, no longer a golden), and the demo's frames 0
 * and 150; a few of them given alpha. The same
 * counts, anti-aliasing apart and counted, the same class for every pixel, the same diff image */
TEST_PROC(compare_pixelmatch_agrees_on_goldens) {
    char pmdir[600];
    REQUIRE_PIXELMATCH(pmdir);
    const char *dir = ww_test_tmpdir("compare_pm_goldens");
    static pm_pair pairs[PM_PAIRS_MAX];
    int n = 0, w = 0, h = 0;
    static const char *const sets[] = {"golden/features", "golden/demo", "golden/minimal"};
    for (size_t s = 0; s < sizeof sets / sizeof sets[0]; s++) {
        char other[300];
        snprintf(other, sizeof other, "tests/data/golden-nvidia-580/%s", sets[s] + 7);
        DIR *d = opendir(other);
        ENSURE_MSG(d != NULL, "%s", other);
        for (struct dirent *e; d && (e = readdir(d)) && n < PM_PAIRS_MAX - 4;) {
            size_t len = strlen(e->d_name);
            if (len < 5 || strcmp(e->d_name + len - 4, ".png") != 0) continue;
            char a[600], b[600];
            snprintf(a, sizeof a, "%s/%s", sets[s], e->d_name);
            snprintf(b, sizeof b, "%s/%s", other, e->d_name);
            /* (left out when its size is not the first pair's) */
            if (access(a, R_OK) == 0) pm_add(pairs, &n, dir, a, b, a, 0, &w, &h);
        }
        if (d) closedir(d);
    }
    ENSURE_MSG(n >= 10, "only %d golden pairs found", n);
    const char *f0 = "golden/demo/frame_00000.png", *f150 = "golden/demo/frame_00150.png";
    ENSURE(pm_add(pairs, &n, dir, f0, f150, "demo frames 0 and 150", 0, &w, &h));
    ENSURE(pm_add(pairs, &n, dir, f0, f150, "demo frames 0 and 150", 1, &w, &h));
    ENSURE(pm_add(pairs, &n, dir, f0, f150, "demo frames 0 and 150", 2, &w, &h));
    ENSURE(pm_add(pairs, &n, dir, "golden/features/fxaa.png",
                  "tests/data/golden-nvidia-580/features/fxaa.png", "fxaa", 2, &w, &h));
    pm_check(pmdir, dir, pairs, n, w, h, 1);
}

/* pixelmatch 7.2.0 and ours on rendered demo frames at 1280x720: frames 0 and 11, where the
 * neighbour scan's order once made 27 pixels differ (each rendered alone: a slice gives the
 * frame of a full run; the goldens above cover more pairs, layouts and alpha) */
TEST_PROC(compare_pixelmatch_agrees_on_frames) {
    char pmdir[600];
    REQUIRE_PIXELMATCH(pmdir);
    REQUIRE_GL();
    const char *d = ww_test_tmpdir("compare_pm_frames");
    char dir[600], cmd[4096];
    snprintf(dir, sizeof dir, "%s", d);
    static const int frames[1][2] = {{0, 11}};
    for (int k = 0; k < 2; k++) {
        snprintf(cmd, sizeof cmd, "%s render scenes/demo.yaml --frames %d:%d --size 1280x720 -o %s "
                 "--quiet", ww_test_bin(), frames[0][k], frames[0][k] + 1, dir);
        ENSURE_EQ_INT(ww_test_run(cmd, NULL, NULL), 0);
    }
    static pm_pair pairs[1];
    int n = 0, w = 0, h = 0;
    for (int k = 0; k < 1; k++) {
        char a[700], b[700], name[64];
        snprintf(a, sizeof a, "%s/frame_%05d.png", dir, frames[k][0]);
        snprintf(b, sizeof b, "%s/frame_%05d.png", dir, frames[k][1]);
        snprintf(name, sizeof name, "demo frames %d and %d", frames[k][0], frames[k][1]);
        ENSURE(pm_add(pairs, &n, dir, a, b, name, 0, &w, &h));
    }
    pm_check(pmdir, dir, pairs, n, w, h, 0); /* the float layout: on the goldens above */
}

/* an RGB PNG is held in the rgb8 layout, whose 8-bit paths must give the figures of the float
 * rgba layout to the bit: the same pair compared in both layouts, every field equal, the same
 * diff image; a pair of mixed layouts too */
TEST_PROC(compare_rgb8_layout_matches_rgba) {
    REQUIRE_GL();
    const char *dir = ww_test_tmpdir("compare_layouts");
    char cmd[4096], f0[600], f1[600], d8[600], d32[600];
    snprintf(cmd, sizeof cmd, "%s render scenes/lake.yaml --frames 0:3 --size 256x144 -o %s --quiet",
             ww_test_bin(), dir);
    ENSURE_EQ_INT(ww_test_run(cmd, NULL, NULL), 0);
    snprintf(f0, sizeof f0, "%s/frame_00000.png", dir);
    snprintf(f1, sizeof f1, "%s/frame_00002.png", dir);
    ww_cmp_image a, b, wa, wb;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_cmp_load_pair(f0, f1, &a, &b, &err), WW_OK);
    ENSURE_MSG(a.rgb8 && !a.rgba && b.rgb8, "an RGB frame loads in the rgb8 layout");
    ENSURE_EQ_INT(ww_cmp_to_rgba(&a, &wa, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_to_rgba(&b, &wb, &err), WW_OK);
    ww_cmp_opts o = ww_cmp_default_opts();
    o.threshold = 2;
    ww_cmp_result r8, r32, rmix;
    ENSURE_EQ_INT(ww_cmp_images(&a, &b, &o, &r8, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_images(&wa, &wb, &o, &r32, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_images(&a, &wb, &o, &rmix, &err), WW_OK);
    ENSURE_MSG(r8.diff_pixels > 0 && r8.yiq_pixels + r8.aa_pixels > 0,
               "frames 0 and 2 of the lake differ, some over the YIQ threshold");
    const ww_cmp_result *rs[2] = {&r32, &rmix};
    for (int k = 0; k < 2; k++) {
        const ww_cmp_result *q = rs[k];
        ENSURE_MSG(r8.max_abs == q->max_abs && r8.mean_abs == q->mean_abs && r8.rmse == q->rmse &&
                       r8.psnr == q->psnr && r8.ssim == q->ssim && r8.rel_max == q->rel_max &&
                       r8.rel_mean == q->rel_mean,
                   "layout %d: max %.17g/%.17g mean %.17g/%.17g rmse %.17g/%.17g ssim %.17g/%.17g",
                   k, r8.max_abs, q->max_abs, r8.mean_abs, q->mean_abs, r8.rmse, q->rmse, r8.ssim,
                   q->ssim);
        ENSURE(r8.diff_pixels == q->diff_pixels && r8.yiq_pixels == q->yiq_pixels &&
               r8.aa_pixels == q->aa_pixels);
    }
    /* the pair loaded and measured on one second thread (ww_cmp_pair, what `compare` runs):
     * the same figures; a missing file or a size mismatch leaves both images empty */
    ww_cmp_image pa, pb;
    ww_cmp_result rp;
    ENSURE_EQ_INT(ww_cmp_pair(f0, f1, &o, &pa, &pb, &rp, &err), WW_OK);
    ENSURE(rp.max_abs == r8.max_abs && rp.rmse == r8.rmse && rp.ssim == r8.ssim &&
           rp.rel_mean == r8.rel_mean && rp.diff_pixels == r8.diff_pixels &&
           rp.yiq_pixels == r8.yiq_pixels && rp.aa_pixels == r8.aa_pixels);
    ENSURE(pa.rgb8 && pb.rgb8);
    ww_cmp_image_free(&pa);
    ww_cmp_image_free(&pb);
    char missing[700], small[700];
    snprintf(missing, sizeof missing, "%s/none.png", dir);
    ENSURE_EQ_INT(ww_cmp_pair(f0, missing, &o, &pa, &pb, &rp, &err), WW_E_NOFILE);
    ENSURE(!pa.rgb8 && !pa.rgba && !pb.rgb8 && !pb.rgba);
    snprintf(small, sizeof small, "%s/small.png", dir);
    static const unsigned char px4[16 * 3] = {0};
    write_png(small, 4, 4, 3, px4);
    ENSURE_EQ_INT(ww_cmp_pair(small, f1, &o, &pa, &pb, &rp, &err), WW_E_INCONSISTENT);
    ENSURE(!pa.rgb8 && !pb.rgb8);

    snprintf(d8, sizeof d8, "%s/diff8.png", dir);
    snprintf(d32, sizeof d32, "%s/diff32.png", dir);
    ENSURE_EQ_INT(ww_cmp_write_diff(d8, &a, &b, &o, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_write_diff(d32, &wa, &wb, &o, &err), WW_OK);
    ENSURE(ww_test_files_equal(d8, d32));
    ww_cmp_image_free(&a);
    ww_cmp_image_free(&b);
    ww_cmp_image_free(&wa);
    ww_cmp_image_free(&wb);
}

/* EXR: NaN/Inf rules */
static void write_exr(const char *path, const float px[8]) {
    ww_image im;
    ENSURE(ww_image_alloc(&im, 2, 1, 4, WW_PIX_F32) == 0);
    memcpy(im.f32, px, 8 * sizeof(float));
    ww_error err = {0};
    ENSURE_EQ_INT(ww_write_exr(path, &im, NULL, &err), WW_OK);
    ww_image_free(&im);
}

TEST(compare_exr_nonfinite) {
    const char *dir = ww_test_tmpdir("compare_exr");
    char pa[600], pb[600], pp[600];
    snprintf(pa, sizeof pa, "%s/a.exr", dir);
    snprintf(pb, sizeof pb, "%s/b.exr", dir);
    snprintf(pp, sizeof pp, "%s/p.png", dir);
    /* pixel 0 carries the non-finite values, pixel 1 a small relative difference (half floats:
     * 2.0 against 2.00390625, one half step, 0.195%) */
    const float base[8] = {NAN, INFINITY, -INFINITY, 1, 2.0f, 0.5f, 0.25f, 1};
    float other[8];
    memcpy(other, base, sizeof other);
    other[4] = 2.00390625f;
    write_exr(pa, base);
    write_exr(pb, other);
    ww_cmp_opts o = ww_cmp_default_opts();
    o.rel_max = 0.002;
    ww_cmp_result r;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(r.hdr && !r.identical);
    ENSURE_EQ_INT(r.nonfinite, 0); /* NaN = NaN, +Inf = +Inf, -Inf = -Inf */
    ENSURE_NEAR(r.max_abs, 0.00390625, 1e-9);
    ENSURE_NEAR(r.rel_max, 0.00390625 / 2.00390625, 1e-9);
    ENSURE_MSG(r.pass, "%s", r.why);
    o.rel_max = 0.001;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE(!r.pass && strstr(r.why, "relative"));

    /* NaN against a number, +Inf against -Inf: failing pixels, whatever the rules */
    other[4] = 2.0f;
    other[0] = 0.0f;
    write_exr(pb, other);
    o = ww_cmp_default_opts();
    o.max = 1e9;
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.nonfinite, 1);
    ENSURE_EQ_INT(r.diff_pixels, 1);
    ENSURE(!r.pass && strstr(r.why, "NaN"));
    other[0] = NAN;
    other[1] = -INFINITY;
    write_exr(pb, other);
    ENSURE_EQ_INT(cmp_files(pa, pb, &o, &r), WW_OK);
    ENSURE_EQ_INT(r.nonfinite, 1);
    ENSURE(!r.pass);

    /* EXR against PNG is bad input, not a difference */
    unsigned char px[6] = {0};
    write_png(pp, 2, 1, 3, px);
    ENSURE_EQ_INT(cmp_files(pa, pp, &o, &r), WW_E_INCONSISTENT);
}

TEST(compare_opt_arg) {
    char *argv[] = {"--yiq", "0.2", "--no-aa", "--fail-pixels=12", "--fail-pixels", "1.5", "--ssim-min", "2"};
    ww_cmp_opts o = ww_cmp_default_opts();
    ww_result r = WW_OK;
    ww_error err = {0};
    int i = 0;
    ENSURE(ww_cmp_opt_arg(8, argv, &i, &o, &r, &err) && r == WW_OK && i == 1);
    ENSURE(o.yiq == 0.2 && o.yiq_pixels == 0); /* --yiq alone is a rule */
    i = 2;
    ENSURE(ww_cmp_opt_arg(8, argv, &i, &o, &r, &err) && !o.detect_aa);
    i = 3;
    ENSURE(ww_cmp_opt_arg(8, argv, &i, &o, &r, &err) && r == WW_OK && o.fail_pixels == 12);
    i = 4;
    ENSURE(ww_cmp_opt_arg(8, argv, &i, &o, &r, &err) && r == WW_E_USAGE); /* not whole */
    r = WW_OK;
    i = 6;
    ENSURE(ww_cmp_opt_arg(8, argv, &i, &o, &r, &err) && r == WW_E_USAGE); /* out of range */
    char *other[] = {"--frames"};
    i = 0;
    ENSURE(!ww_cmp_opt_arg(1, other, &i, &o, &r, &err));
}

/* bench compare runs, and prints every figure (no time is asserted: only that each was taken) */
TEST_PROC(compare_bench_json) {
    REQUIRE_GL();
    const char *dir = ww_test_tmpdir("compare_bench");
    char out[600];
    snprintf(out, sizeof out, "%s/bench.json", dir);
    ENSURE_EQ_INT(ww_test_ww("bench compare --size 64x36 --repeats 2 --json", out, NULL), 0);
    char *t = ww_test_read_file(out, NULL);
    ENSURE(t && ww_test_json_valid(t));
    static const char *const keys[] = {"\"ours_ms\":", "\"metrics_ms\":", "\"identical_ms\":",
                                       "\"process_ms\":", "\"process_median_ms\":",
                                       "\"imagemagick_ms\":", "\"ratio_process_median\":", NULL};
    /* each was measured (a number; the identical pair at 64x36 may round to 0.000 ms) */
    for (int k = 0; t && keys[k]; k++) ENSURE_MSG(num_after(t, keys[k]) >= 0, "%s in %s", keys[k], t);
    ENSURE_MSG(num_after(t, "\"process_ms\":") > 0 && num_after(t, "\"imagemagick_ms\":") > 0,
               "two processes take time: %s", t);
    free(t);
    ENSURE_EQ_INT(ww_test_ww("bench compare --size 64", NULL, NULL), 2);
}
