/* compare.c - the metrics of compare.h and its pass/fail rules: one pass over the pixels for the
 * differences and pixelmatch, one for SSIM over a rolling band of luma rows, each half of the
 * image on its own thread; no allocation per pixel. Definitions, and what they agree with, are
 * in compare.h.
 */
#include "check/compare_impl.h"

#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#define LEVELS 255.0        /* PNG metrics are in 8-bit levels */
#define LEVEL_EPS 1e-3      /* rounding of v / 255 in float, in levels (< 1e-4): a rule on
                             * whole levels holds at the level; 16-bit steps are 0.0039 */
#define REL_FLOOR 1e-6      /* relative error: |a - b| / max(|a|, |b|, REL_FLOOR) */
#define SSIM_WINDOW 8       /* Wang et al. 2004's 8x8 window, sliding by one pixel */
#define SSIM_K1 0.01        /* C1 = (K1 L)^2, C2 = (K2 L)^2 with L = 1 (Wang et al. 2004) */
#define SSIM_K2 0.03
/* Rec. 601 luma, the Y' of SSIM's usual grey conversion */
#define LUMA_R 0.299
#define LUMA_G 0.587
#define LUMA_B 0.114

ww_cmp_opts ww_cmp_default_opts(void) {
    return (ww_cmp_opts){.threshold = 0, .yiq = 0.1, .detect_aa = 1, .max = -1, .fail_percent = -1,
                         .fail_pixels = -1, .psnr_min = -1, .yiq_pixels = -1, .ssim_min = -1,
                         .rel_max = -1};
}

static int has_alpha(const ww_cmp_image *im) { return im->channels == 2 || im->channels == 4; }

static float unit(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* NaN -> 0 */ }

/* ---- pixelmatch ------------------------------------------------------------------------------ */

/* YIQ coefficients of NTSC as Kotsarenko & Ramos 2010 use them (rows Y, I, Q) */
static const double yiq_m[3][3] = {{0.29889531, 0.58662247, 0.11448223},
                                   {0.59597799, -0.27417610, -0.32180189},
                                   {0.21147017, -0.52261711, 0.31114694}};
static const double yiq_w[3] = {0.5053, 0.299, 0.1957}; /* their weights of dY^2, dI^2, dQ^2 */

/* pixelmatch reads 8-bit RGBA. A pixel with alpha below 255 it blends on white, r a / 255 + 255 - a,
 * and it takes the difference of two pixels as one integer over 255,
 * (r1 a1 - r2 a2 - 255 (a1 - a2)) / 255, or as r1 - r2 when both are opaque (the same double).
 * We hold r / 255 * a / 255 in a float (premultiplied). The difference of two such pixels on
 * white, in 255ths of a level, is that integer off by less than 0.04 (the floats' rounding), so
 * rounding it restores the integer, and over 255 it is pixelmatch's difference to the bit.
 * 16-bit values (no pixelmatch to agree with) have their difference taken on the same grid. */
#define WHITE_STEPS (LEVELS * LEVELS) /* 255ths of an 8-bit level in the unit of [0, 1] */
/* added then subtracted, it rounds a double of magnitude below 2^51 to an integer (to nearest,
 * as the FPU rounds; a libm call per value would cost more than the rest of the delta) */
#define ROUND_TO_INT 0x1.8p52

/* v in [-1, 1] in 255ths of a level, rounded */
static inline double on_grid(double v) {
    return (v * WHITE_STEPS + ROUND_TO_INT) - ROUND_TO_INT;
}

/* pixels p and q over white, c + (1 - alpha) (premultiplied colour), to their difference in
 * levels: pixelmatch's dr, dg, db. pixelmatch divides by 255; between opaque 8-bit pixels the
 * grid's integer is 255 times whole levels, and times 1/255 gives the quotient's double (the
 * test compare_yiq_delta_bits_pixelmatch tries every one) at a fraction of a division's cost.
 * Values must be in [0, 1] (ww_cmp_yiq_delta clamps) */
static inline void white_diff(const float *p, const float *q, double d[3]) {
    static const double inv = 1.0 / LEVELS;
    double ap = p[3], aq = q[3];
    if (ap == 1.0 && aq == 1.0) {
        for (int c = 0; c < 3; c++) d[c] = on_grid((double)p[c] - (double)q[c]) * inv;
        return;
    }
    for (int c = 0; c < 3; c++)
        d[c] = on_grid(((double)p[c] + 1.0 - ap) - ((double)q[c] + 1.0 - aq)) / LEVELS;
}

/* a pixel's values clamped to [0, 1], NaN as 0 (EXR) */
static void clamp_px(const float *px, float out[4]) {
    for (int c = 0; c < 4; c++) out[c] = unit(px[c]);
}

/* Y of a difference on white (Kotsarenko & Ramos's first row), in pixelmatch's order */
static inline double yiq_y(const double d[3]) {
    return yiq_m[0][0] * d[0] + yiq_m[0][1] * d[1] + yiq_m[0][2] * d[2];
}

/* the weighted YIQ delta of a difference on white, terms in pixelmatch's order */
static inline double yiq_of(const double d[3]) {
    double delta = 0;
    for (int k = 0; k < 3; k++) {
        double e = yiq_m[k][0] * d[0] + yiq_m[k][1] * d[1] + yiq_m[k][2] * d[2];
        delta += yiq_w[k] * e * e;
    }
    return delta;
}

double ww_cmp_luma_on_white(const float *px) {
    double a = unit(px[3]), v[3];
    for (int c = 0; c < 3; c++) v[c] = LEVELS * (unit(px[c]) + 1.0 - a);
    return yiq_y(v);
}

double ww_cmp_yiq_delta(const float *p, const float *q) {
    float u[4], v[4];
    double d[3];
    clamp_px(p, u);
    clamp_px(q, v);
    white_diff(u, v, d);
    return yiq_of(d);
}

static int same_pixel(const float *p, const float *q) {
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2] && p[3] == q[3];
}

/* the 3x3 neighbourhood of (x, y) clamped to the image; edge: 1 when it is cut */
typedef struct nbhd { int x0, y0, x1, y1, edge; } nbhd;

static nbhd around(const ww_cmp_image *im, int x, int y) {
    nbhd n = {x > 0 ? x - 1 : 0, y > 0 ? y - 1 : 0, x < im->width - 1 ? x + 1 : x,
              y < im->height - 1 ? y + 1 : y, 0};
    n.edge = n.x0 == x || n.x1 == x || n.y0 == y || n.y1 == y;
    return n;
}

/* pixels i and k of an image are the same, in either layout. pixelmatch compares the stored RGBA;
 * we compare the premultiplied colour (the same for opaque pixels; under alpha 0 every colour is
 * the same to us) */
static int same_at(const ww_cmp_image *im, size_t i, size_t k) {
    if (im->rgb8) return memcmp(im->rgb8 + 3 * i, im->rgb8 + 3 * k, 3) == 0;
    return same_pixel(im->rgba + 4 * i, im->rgba + 4 * k);
}

/* the difference over white of pixels i and k of an image, in levels (white_diff): an rgb8
 * pair's is its level differences */
static void white_step(const ww_cmp_image *im, size_t i, size_t k, double d[3]) {
    if (im->rgb8) {
        const unsigned char *p = im->rgb8 + 3 * i, *q = im->rgb8 + 3 * k;
        for (int c = 0; c < 3; c++) d[c] = (double)p[c] - (double)q[c];
        return;
    }
    float p[4], q[4];
    clamp_px(im->rgba + 4 * i, p);
    clamp_px(im->rgba + 4 * k, q);
    white_diff(p, q, d);
}

/* 3+ neighbours identical to (x, y), a pixel on the image's edge counting one (pixelmatch) */
static int many_siblings(const ww_cmp_image *im, int x, int y) {
    nbhd n = around(im, x, y);
    size_t w = (size_t)im->width, c = (size_t)y * w + (size_t)x;
    int same = n.edge;
    for (int j = n.y0; j <= n.y1; j++)
        for (int i = n.x0; i <= n.x1; i++) {
            if (i == x && j == y) continue;
            if (same_at(im, c, (size_t)j * w + (size_t)i))
                if (++same > 2) return 1;
        }
    return 0;
}

int ww_cmp_antialiased(const ww_cmp_image *img, const ww_cmp_image *other, int x, int y) {
    nbhd n = around(img, x, y);
    size_t w = (size_t)img->width;
    size_t centre = (size_t)y * w + (size_t)x;
    int zeroes = n.edge;
    double lo = 0, hi = 0;
    int lox = 0, loy = 0, hix = 0, hiy = 0;

    /* brightness steps to the 8 neighbours, Y(centre - neighbour) as pixelmatch takes them:
     * equal, lowest (the brightest neighbour) and highest (the darkest). The scan goes column by
     * column, as pixelmatch's: of several equally bright neighbours the first one met is kept,
     * and which one that is decides the sibling test below */
    for (int i = n.x0; i <= n.x1; i++)
        for (int j = n.y0; j <= n.y1; j++) {
            if (i == x && j == y) continue;
            double d[3];
            white_step(img, centre, (size_t)j * w + (size_t)i, d);
            double step = yiq_y(d);
            if (step == 0) {
                if (++zeroes > 2) return 0; /* a flat area, not an edge's ramp */
            } else if (step < lo) {
                lo = step, lox = i, loy = j;
            } else if (step > hi) {
                hi = step, hix = i, hiy = j;
            }
        }
    /* a ramp needs both a brighter and a darker neighbour */
    if (lo == 0 || hi == 0) return 0;
    /* ... and one of its ends in a flat area of both images */
    return (many_siblings(img, lox, loy) && many_siblings(other, lox, loy)) ||
           (many_siblings(img, hix, hiy) && many_siblings(other, hix, hiy));
}

/* ---- differences -------------------------------------------------------------------------------- */

/* NaN/Inf rules of compare.h: 1 when the pair counts as equal */
static int nonfinite_match(float x, float y) {
    if (isnan(x) || isnan(y)) return isnan(x) && isnan(y);
    return x == y; /* the same infinity */
}

typedef struct sums {
    double abs, sq, rel;     /* sums of |d|, d^2 over R, G, B, and relative error */
    double max_abs, rel_max; /* in the image's units (scaled to levels at the end) */
    size_t n, nsq;           /* channel pairs in abs/rel, in sq */
    long diff, yiq, aa, nonfinite;
} sums;

/* one pixel's channels: sums, and its largest difference in the threshold's unit (INFINITY:
 * a NaN/Inf mismatch) */
static inline double pixel_channels(const float *p, const float *q, int nch, int hdr, sums *s) {
    double worst = 0;
    for (int c = 0; c < nch; c++) {
        float x = p[c], y = q[c];
        if (hdr && !(isfinite(x) && isfinite(y))) {
            if (!nonfinite_match(x, y)) worst = INFINITY;
            continue;
        }
        double d = fabs((double)x - (double)y);
        s->n++;
        if (c < 3) s->sq += d * d, s->nsq++;
        if (d == 0) continue;
        double m = fmax(fmax(fabs((double)x), fabs((double)y)), REL_FLOOR), rel = d / m;
        s->abs += d;
        s->rel += rel;
        if (d > s->max_abs) s->max_abs = d;
        if (rel > s->rel_max) s->rel_max = rel;
        double unit_d = hdr ? rel : d * LEVELS;
        if (unit_d > worst) worst = unit_d;
    }
    return worst;
}

double ww_cmp_pixel_diff(const ww_cmp_image *a, const ww_cmp_image *b, size_t i) {
    sums s = {0};
    int nch = has_alpha(a) || has_alpha(b) ? 4 : 3;
    float p[4], q[4];
    ww_cmp_pixel(a, i, p);
    ww_cmp_pixel(b, i, q);
    return pixel_channels(p, q, nch, a->hdr, &s);
}

static double level_slack(const ww_cmp_image *a) { return a->hdr ? 0.0 : LEVEL_EPS; }

int ww_cmp_pixel_kind(const ww_cmp_image *a, const ww_cmp_image *b, int x, int y,
                      const ww_cmp_opts *o) {
    size_t i = (size_t)y * (size_t)a->width + (size_t)x;
    double worst = ww_cmp_pixel_diff(a, b, i);
    float p[4], q[4];
    ww_cmp_pixel(a, i, p);
    ww_cmp_pixel(b, i, q);
    double delta = ww_cmp_yiq_delta(p, q);
    if (delta > WW_CMP_YIQ_MAX_DELTA * o->yiq * o->yiq) {
        if (o->detect_aa && (ww_cmp_antialiased(a, b, x, y) || ww_cmp_antialiased(b, a, x, y)))
            return WW_CMP_AA;
        return WW_CMP_DIFF;
    }
    return worst > o->threshold + level_slack(a) ? WW_CMP_DIFF : WW_CMP_SAME;
}

/* an 8- or 16-bit image's values are v / (2^bits - 1) in [0, 1], colour premultiplied (never
 * above its alpha): no clamp, no NaN. pixelmatch's delta for such a pair, as ww_cmp_yiq_delta
 * computes it (the same operations in the same order, so the same bits) */
static inline double yiq_delta_ldr(const float *p, const float *q) {
    double d[3];
    white_diff(p, q, d);
    return yiq_of(d);
}

/* a pixel over the YIQ threshold: anti-aliasing (when detected) or a difference */
static void count_over_yiq(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                           int x, int y, sums *s) {
    if (o->detect_aa && (ww_cmp_antialiased(a, b, x, y) || ww_cmp_antialiased(b, a, x, y)))
        s->aa++;
    else
        s->yiq++;
}

/* the sums of an 8- or 16-bit pass, kept in registers while a band runs */
typedef struct ldr_sums { double abs, sq, rel, max_abs, rel_max; } ldr_sums;

/* one channel pair of an 8- or 16-bit image (values in [0, 1]) into the sums (its square only for
 * a colour channel); its difference in levels */
static inline double ldr_channel(double u, double v, int colour, ldr_sums *a) {
    double d = u > v ? u - v : v - u;
    if (colour) a->sq += d * d;
    if (d == 0) return 0;
    double rel = d / (u > v ? u : v);
    a->abs += d;
    a->rel += rel;
    if (d > a->max_abs) a->max_abs = d;
    if (rel > a->rel_max) a->rel_max = rel;
    return d * LEVELS;
}

/* diff_pass for an 8- or 16-bit pair: pixel_channels without the HDR cases, the sums in
 * registers; the same figures to the bit (the relative error's floor cannot bind: two values
 * that differ are at least 1/65535 apart, so the larger is above REL_FLOOR) */
static void diff_pass_ldr(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                          int y0, int y1, sums *s) {
    int nch = has_alpha(a) || has_alpha(b) ? 4 : 3;
    double limit = o->threshold + level_slack(a);
    double max_delta = WW_CMP_YIQ_MAX_DELTA * o->yiq * o->yiq;
    ldr_sums acc = {s->abs, s->sq, s->rel, s->max_abs, s->rel_max};
    size_t npx = 0;
    long diff = 0;
    for (int y = y0; y < y1; y++) {
        size_t row = (size_t)y * (size_t)a->width;
        for (int x = 0; x < a->width; x++) {
            const float *p = a->rgba + 4 * (row + (size_t)x), *q = b->rgba + 4 * (row + (size_t)x);
            npx++;
            if (same_pixel(p, q)) continue;
            double worst = 0;
            for (int c = 0; c < nch; c++) {
                double l = ldr_channel(p[c], q[c], c < 3, &acc);
                if (l > worst) worst = l;
            }
            if (worst > limit) diff++;
            if (!(yiq_delta_ldr(p, q) > max_delta)) continue;
            count_over_yiq(a, b, o, x, y, s);
        }
    }
    s->abs = acc.abs, s->sq = acc.sq, s->rel = acc.rel, s->max_abs = acc.max_abs;
    s->rel_max = acc.rel_max;
    s->n += npx * (size_t)nch;
    s->nsq += npx * 3;
    s->diff += diff;
}

/* the pass over rows [y0, y1): differences, threshold count, pixelmatch */
static void diff_pass(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o, int y0,
                      int y1, sums *s) {
    int nch = has_alpha(a) || has_alpha(b) ? 4 : 3, hdr = a->hdr;
    double limit = o->threshold + level_slack(a);
    double max_delta = WW_CMP_YIQ_MAX_DELTA * o->yiq * o->yiq;
    for (int y = y0; y < y1; y++) {
        size_t row = (size_t)y * (size_t)a->width;
        for (int x = 0; x < a->width; x++) {
            const float *p = a->rgba + 4 * (row + (size_t)x), *q = b->rgba + 4 * (row + (size_t)x);
            if (same_pixel(p, q)) {
                s->n += (size_t)nch;
                s->nsq += 3;
                continue;
            }
            double worst = hdr ? pixel_channels(p, q, nch, 1, s) : pixel_channels(p, q, nch, 0, s);
            if (worst == INFINITY) s->nonfinite++;
            if (worst > limit) s->diff++;
            if (!(ww_cmp_yiq_delta(p, q) > max_delta)) continue;
            count_over_yiq(a, b, o, x, y, s);
        }
    }
}

/* the rgb8 layout's values per 8-bit level, each computed as the rgba layout's paths compute it
 * from the level's float (so both layouts give the same figures to the bit) */
typedef struct level_tables {
    double v[256];       /* the level as the float paths see it */
    double luma[3][256]; /* SSIM's weighted channel at alpha 1 (ssim_luma_ldr) */
} level_tables;

static void level_tables_make(level_tables *t) {
    static const double w[3] = {LUMA_R, LUMA_G, LUMA_B};
    for (unsigned k = 0; k < 256; k++) {
        double v = ww_cmp_level(k), a = 1.0;
        t->v[k] = v;
        for (int c = 0; c < 3; c++) t->luma[c][k] = w[c] * (v + 1.0 - a);
    }
}

/* diff_pass_ldr for two rgb8 images: three bytes a pixel read, the values from the tables */
static void diff_pass_rgb8(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                           const level_tables *t, int y0, int y1, sums *s) {
    double limit = o->threshold + level_slack(a);
    double max_delta = WW_CMP_YIQ_MAX_DELTA * o->yiq * o->yiq;
    ldr_sums acc = {s->abs, s->sq, s->rel, s->max_abs, s->rel_max};
    size_t npx = 0;
    long diff = 0;
    for (int y = y0; y < y1; y++) {
        size_t row = (size_t)y * (size_t)a->width;
        for (int x = 0; x < a->width; x++) {
            const unsigned char *p = a->rgb8 + 3 * (row + (size_t)x), *q = b->rgb8 + 3 * (row + (size_t)x);
            npx++;
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) continue;
            /* pixelmatch's differences on white: (255 p - 255 q) / 255, exactly p - q */
            double worst = 0, dw[3];
            for (int c = 0; c < 3; c++) {
                dw[c] = (double)p[c] - (double)q[c];
                double l = ldr_channel(t->v[p[c]], t->v[q[c]], 1, &acc);
                if (l > worst) worst = l;
            }
            if (worst > limit) diff++;
            if (!(yiq_of(dw) > max_delta)) continue;
            count_over_yiq(a, b, o, x, y, s);
        }
    }
    s->abs = acc.abs, s->sq = acc.sq, s->rel = acc.rel, s->max_abs = acc.max_abs;
    s->rel_max = acc.rel_max;
    s->n += npx * 3;
    s->nsq += npx * 3;
    s->diff += diff;
}

/* ---- SSIM ------------------------------------------------------------------------------------ */

/* the luma of an 8- or 16-bit image's pixel (values in [0, 1]): ssim_luma without the clamps,
 * the same bits */
static inline float ssim_luma_ldr(const float *px) {
    double a = px[3];
    return (float)(LUMA_R * ((double)px[0] + 1.0 - a) + LUMA_G * ((double)px[1] + 1.0 - a) +
                   LUMA_B * ((double)px[2] + 1.0 - a));
}

static float ssim_luma(const float *px) {
    double a = unit(px[3]);
    return (float)(LUMA_R * (unit(px[0]) + 1.0 - a) + LUMA_G * (unit(px[1]) + 1.0 - a) +
                   LUMA_B * (unit(px[2]) + 1.0 - a));
}

/* row y's luma, by the image's layout and kind */
static void ssim_luma_row(const ww_cmp_image *im, const level_tables *t, int y, float *out) {
    size_t nw = (size_t)im->width;
    if (im->rgb8) {
        const unsigned char *p = im->rgb8 + 3 * (size_t)y * nw;
        for (size_t x = 0; x < nw; x++, p += 3)
            out[x] = (float)(t->luma[0][p[0]] + t->luma[1][p[1]] + t->luma[2][p[2]]);
        return;
    }
    const float *p = im->rgba + 4 * (size_t)y * nw;
    if (im->hdr)
        for (size_t x = 0; x < nw; x++) out[x] = ssim_luma(p + 4 * x);
    else
        for (size_t x = 0; x < nw; x++) out[x] = ssim_luma_ldr(p + 4 * x);
}

/* SSIM (Wang et al. 2004, eq. 13) of the n windows of width wx along a row of column sums
 * (col[0..4]: sums of x, y, x^2, y^2, xy down the window's height, np pixels a window) into v.
 * The five window sums slide in registers, five independent chains, and each window's value
 * leaves the chains, so its division overlaps the next windows' additions */
static void ssim_windows(double *const col[5], int wx, int n, double np, double *v) {
    const double c1 = (SSIM_K1) * (SSIM_K1), c2 = (SSIM_K2) * (SSIM_K2);
    const double *c0 = col[0], *cy = col[1], *cxx = col[2], *cyy = col[3], *cxy = col[4];
    const double inv = 1.0 / np; /* exact for the 8x8 window (1/64): one division per window */
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0;
    for (int x = 0; x < wx; x++) s0 += c0[x], s1 += cy[x], s2 += cxx[x], s3 += cyy[x], s4 += cxy[x];
    for (int x = 0;; x++) {
        double mx = s0 * inv, my = s1 * inv;
        double vx = s2 * inv - mx * mx, vy = s3 * inv - my * my, cov = s4 * inv - mx * my;
        v[x] = ((2 * mx * my + c1) * (2 * cov + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
        if (x + 1 >= n) break;
        s0 += c0[x + wx] - c0[x], s1 += cy[x + wx] - cy[x], s2 += cxx[x + wx] - cxx[x];
        s3 += cyy[x + wx] - cyy[x], s4 += cxy[x + wx] - cxy[x];
    }
}

/* the sum of SSIM over the windows of wx x wy (8x8, or the image's side when smaller) whose top
 * row is in [t0, t1): luma rows in a ring of wy, column sums updated as rows enter and leave,
 * window sums sliding along x (ssim_windows), then the total in x order */
static ww_result ssim_sum(const ww_cmp_image *a, const ww_cmp_image *b, const level_tables *t,
                          int t0, int t1, double *out, ww_error *err) {
    int w = a->width, h = a->height;
    int wx = w < SSIM_WINDOW ? w : SSIM_WINDOW, wy = h < SSIM_WINDOW ? h : SSIM_WINDOW;
    int nx = w - wx + 1;
    size_t nw = (size_t)w;
    *out = 0;
    if (t0 >= t1) return WW_OK;
    float *ring = malloc(2 * (size_t)wy * nw * sizeof *ring);
    /* per column: sums of x, y, x^2, y^2, xy (col[k]); per window: SSIM */
    double *mem = calloc(6 * nw, sizeof *mem);
    if (!ring || !mem) {
        free(ring);
        free(mem);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "compare: out of memory for SSIM");
    }
    double *col[5], *val = mem + 5 * nw;
    for (int k = 0; k < 5; k++) col[k] = mem + (size_t)k * nw;
    double total = 0;
    for (int y = t0; y < t1 + wy - 1 && y < h; y++) {
        float *la = ring + (size_t)((y - t0) % wy) * 2 * nw, *lb = la + nw;
        if (y - t0 >= wy) { /* the row leaving the band */
            for (size_t x = 0; x < nw; x++) {
                double ou = la[x], ov = lb[x];
                col[0][x] -= ou, col[1][x] -= ov, col[2][x] -= ou * ou, col[3][x] -= ov * ov;
                col[4][x] -= ou * ov;
            }
        }
        ssim_luma_row(a, t, y, la);
        ssim_luma_row(b, t, y, lb);
        for (size_t x = 0; x < nw; x++) {
            float u = la[x], v = lb[x];
            col[0][x] += u, col[1][x] += v, col[2][x] += (double)u * u, col[3][x] += (double)v * v;
            col[4][x] += (double)u * v;
        }
        if (y - t0 < wy - 1) continue;
        ssim_windows(col, wx, nx, (double)wx * wy, val);
        for (int x = 0; x < nx; x++) total += val[x];
    }
    free(ring);
    free(mem);
    *out = total;
    return WW_OK;
}

/* one band of the image: its rows' differences and the SSIM windows whose top row is in it */
typedef struct band_job {
    const ww_cmp_image *a, *b;
    const ww_cmp_opts *o;
    const level_tables *t; /* the rgb8 pair's tables */
    int y0, y1;
    sums s;
    double ssim_total;
    ww_error err;
    ww_result r;
} band_job;

static void *band_run(void *arg) {
    band_job *j = arg;
    int wy = j->a->height < SSIM_WINDOW ? j->a->height : SSIM_WINDOW;
    int tops = j->a->height - wy + 1, t1 = j->y1 < tops ? j->y1 : tops;
    if (j->a->rgb8)
        diff_pass_rgb8(j->a, j->b, j->o, j->t, j->y0, j->y1, &j->s);
    else if (j->a->hdr)
        diff_pass(j->a, j->b, j->o, j->y0, j->y1, &j->s);
    else
        diff_pass_ldr(j->a, j->b, j->o, j->y0, j->y1, &j->s);
    j->r = ssim_sum(j->a, j->b, j->t, j->y0, t1, &j->ssim_total, &j->err);
    return NULL;
}

static void sums_add(sums *s, const sums *t) {
    s->abs += t->abs, s->sq += t->sq, s->rel += t->rel;
    s->max_abs = fmax(s->max_abs, t->max_abs), s->rel_max = fmax(s->rel_max, t->rel_max);
    s->n += t->n, s->nsq += t->nsq;
    s->diff += t->diff, s->yiq += t->yiq, s->aa += t->aa, s->nonfinite += t->nonfinite;
}

/* the metrics in row bands taken in turn from a counter by whichever thread is free (a thread
 * that starts late, as a woken core on a VM can, 1-4 ms, does less), the bands' sums added in
 * band order: the same figures whoever ran which band. A band re-reads the SSIM window's height
 * of rows below it, so bands are not made thinner than BAND_MIN_ROWS */
#define BANDS_MAX 8
#define BAND_MIN_ROWS 48

typedef struct bands {
    band_job job[BANDS_MAX];
    int n;
    atomic_int next;
} bands;

static void bands_make(bands *w, const ww_cmp_image *a, const ww_cmp_image *b,
                       const ww_cmp_opts *o, const level_tables *t) {
    int rows = (a->height + BANDS_MAX - 1) / BANDS_MAX;
    if (rows < BAND_MIN_ROWS) rows = BAND_MIN_ROWS;
    w->n = 0;
    for (int y = 0; y < a->height; y += rows)
        w->job[w->n++] = (band_job){.a = a, .b = b, .o = o, .t = t, .y0 = y,
                                    .y1 = y + rows < a->height ? y + rows : a->height};
    atomic_init(&w->next, 0);
}

static void bands_work(bands *w) {
    for (int k; (k = atomic_fetch_add(&w->next, 1)) < w->n;) band_run(&w->job[k]);
}

static void *bands_thread(void *arg) {
    bands_work(arg);
    return NULL;
}

/* a second thread for the metrics: a pair's loader already running (cmp_pair), else NULL (one
 * is started) */
typedef struct pair_worker pair_worker;
static void pair_worker_run(pair_worker *pw, bands *w);

/* the sums and the mean SSIM */
static ww_result measure(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                         pair_worker *pw, sums *s, double *ssim, ww_error *err) {
    level_tables tables;
    if (a->rgb8) level_tables_make(&tables);
    bands w;
    bands_make(&w, a, b, o, &tables);
    if (pw) {
        pair_worker_run(pw, &w);
    } else {
        pthread_t t;
        int threaded = pthread_create(&t, NULL, bands_thread, &w) == 0;
        bands_work(&w);
        if (threaded) pthread_join(t, NULL);
    }
    *s = (sums){0};
    double total = 0;
    for (int k = 0; k < w.n; k++) {
        if (w.job[k].r != WW_OK) {
            if (err) *err = w.job[k].err;
            return w.job[k].r;
        }
        sums_add(s, &w.job[k].s);
        total += w.job[k].ssim_total;
    }
    int wx = a->width < SSIM_WINDOW ? a->width : SSIM_WINDOW;
    int wy = a->height < SSIM_WINDOW ? a->height : SSIM_WINDOW;
    *ssim = total / ((double)(a->width - wx + 1) * (double)(a->height - wy + 1));
    return WW_OK;
}

/* ---- rules ----------------------------------------------------------------------------------- */

static int rules_on(const ww_cmp_opts *o) {
    return o->max >= 0 || o->fail_percent >= 0 || o->fail_pixels >= 0 || o->psnr_min >= 0 ||
           o->yiq_pixels >= 0 || o->ssim_min >= 0 || o->rel_max >= 0;
}

/* the first rule that fails, in res->why; pass when none */
static void apply_rules(const ww_cmp_opts *o, ww_cmp_result *r) {
    char *why = r->why;
    size_t cap = sizeof r->why;
    double slack = r->hdr ? 0.0 : LEVEL_EPS;
    const char *unit = r->hdr ? "" : " levels";
    why[0] = '\0';
    if (r->nonfinite > 0)
        snprintf(why, cap, "%ld pixels have NaN or Inf where the other image has not", r->nonfinite);
    else if (!rules_on(o) && r->diff_pixels > 0)
        snprintf(why, cap, "%ld pixels (%.4g%%) differ by more than %g%s (no rule given: none may)",
                 r->diff_pixels, r->diff_percent, o->threshold, r->hdr ? " (relative)" : unit);
    else if (o->max >= 0 && r->max_abs > o->max + slack)
        snprintf(why, cap, "max difference %.4g%s > --max %g", r->max_abs, unit, o->max);
    else if (o->fail_percent >= 0 && r->diff_percent > o->fail_percent)
        snprintf(why, cap, "%.4g%% of pixels differ by more than %g > --fail-percent %g",
                 r->diff_percent, o->threshold, o->fail_percent);
    else if (o->fail_pixels >= 0 && r->diff_pixels > o->fail_pixels)
        snprintf(why, cap, "%ld pixels differ by more than %g > --fail-pixels %ld", r->diff_pixels,
                 o->threshold, o->fail_pixels);
    else if (o->psnr_min >= 0 && r->psnr < o->psnr_min)
        snprintf(why, cap, "PSNR %.4g dB < --psnr-min %g", r->psnr, o->psnr_min);
    else if (o->yiq_pixels >= 0 && (double)r->yiq_pixels > o->yiq_pixels)
        snprintf(why, cap, "%ld pixels over the YIQ threshold %g > --yiq-pixels %g", r->yiq_pixels,
                 o->yiq, o->yiq_pixels);
    else if (o->ssim_min >= 0 && r->ssim < o->ssim_min)
        snprintf(why, cap, "SSIM %.6f < --ssim-min %g", r->ssim, o->ssim_min);
    else if (o->rel_max >= 0 && r->rel_max > o->rel_max)
        snprintf(why, cap, "relative error %.4g > --rel-max %g", r->rel_max, o->rel_max);
    r->pass = why[0] == '\0';
}

static ww_result check_kinds(const ww_cmp_image *a, const ww_cmp_image *b, ww_error *err) {
    if (a->width != b->width || a->height != b->height)
        return ww_error_set(err, WW_E_INCONSISTENT, NULL, 0, 0,
                            "compare: sizes differ: %dx%d against %dx%d", a->width, a->height,
                            b->width, b->height);
    if (a->hdr != b->hdr)
        return ww_error_set(err, WW_E_INCONSISTENT, NULL, 0, 0,
                            "compare: %s against %s: an HDR image compares with HDR only",
                            a->hdr ? "EXR" : "PNG", b->hdr ? "EXR" : "PNG");
    /* RGB against RGBA is not an error: layouts are normalised (a missing alpha is 1), so an
     * opaque RGBA file (what image editors often save) equals its RGB twin */
    return WW_OK;
}

/* ww_cmp_images with the metrics' second thread pw (NULL: one is started) */
static ww_result images_with(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                             pair_worker *pw, ww_cmp_result *res, ww_error *err) {
    memset(res, 0, sizeof *res);
    ww_result r = check_kinds(a, b, err);
    if (r != WW_OK) return r;
    WW_ASSERT((a->rgba || a->rgb8) && (b->rgba || b->rgb8) && a->width > 0 && a->height > 0);
    if (!a->rgb8 != !b->rgb8) {
        /* mixed layouts (an RGB file against an RGBA one): the rgb8 one in rgba, then as usual */
        ww_cmp_image wide;
        r = ww_cmp_to_rgba(a->rgb8 ? a : b, &wide, err);
        if (r == WW_OK)
            r = a->rgb8 ? images_with(&wide, b, o, pw, res, err) : images_with(a, &wide, o, pw, res, err);
        free(wide.rgba);
        return r;
    }
    size_t npx = (size_t)a->width * (size_t)a->height;
    size_t bytes = a->rgb8 ? 3 * npx : npx * 4 * sizeof(float);
    res->width = a->width;
    res->height = a->height;
    res->hdr = a->hdr;

    /* the fast path: equal hashes, confirmed by the bytes */
    if (a->hash == b->hash &&
        memcmp(a->rgb8 ? (const void *)a->rgb8 : a->rgba, b->rgb8 ? (const void *)b->rgb8 : b->rgba, bytes) == 0) {
        res->identical = 1;
        res->psnr = INFINITY;
        res->ssim = 1.0;
        apply_rules(o, res);
        return WW_OK;
    }

    sums s;
    r = measure(a, b, o, pw, &s, &res->ssim, err);
    if (r != WW_OK) return r;
    double scale = a->hdr ? 1.0 : LEVELS;
    res->max_abs = s.max_abs * scale;
    res->mean_abs = s.n ? s.abs / (double)s.n * scale : 0;
    double mse = s.nsq ? s.sq / (double)s.nsq : 0;
    res->rmse = sqrt(mse);
    res->psnr = mse > 0 ? 10.0 * log10(1.0 / mse) : INFINITY;
    res->diff_pixels = s.diff;
    res->diff_percent = 100.0 * (double)s.diff / (double)npx;
    res->yiq_pixels = s.yiq;
    res->aa_pixels = s.aa;
    res->rel_max = s.rel_max;
    res->rel_mean = s.n ? s.rel / (double)s.n : 0;
    res->nonfinite = s.nonfinite;
    apply_rules(o, res);
    return WW_OK;
}

ww_result ww_cmp_images(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                        ww_cmp_result *res, ww_error *err) {
    return images_with(a, b, o, NULL, res, err);
}

/* ---- a pair from files, on two threads ------------------------------------------------------ */

/* The second thread loads b, then waits for the metrics' bands and takes its share. It waits by
 * spinning (sched_yield), only while the first thread loads a: a core left idle on this VM takes
 * 1-4 ms to wake, which a second pthread_create for the metrics paid every time. */
struct pair_worker {
    pthread_t thread;
    const char *path_b;
    ww_cmp_image *b;
    ww_error err;
    ww_result r;
    atomic_int loaded;     /* 1: b is loaded (r says how) */
    _Atomic(bands *) work; /* the bands to share; PAIR_STOP: none will come */
};

#define PAIR_STOP ((bands *)&pair_stop_mark)
static const char pair_stop_mark;

static void *pair_thread(void *arg) {
    pair_worker *pw = arg;
    pw->r = ww_cmp_load_one(pw->path_b, pw->b, &pw->err);
    atomic_store(&pw->loaded, 1);
    bands *w;
    while ((w = atomic_load(&pw->work)) == NULL) sched_yield();
    if (w != PAIR_STOP) bands_work(w);
    return NULL;
}

static void pair_worker_run(pair_worker *pw, bands *w) {
    atomic_store(&pw->work, w);
    bands_work(w);
    pthread_join(pw->thread, NULL);
}

ww_result ww_cmp_pair(const char *path_a, const char *path_b, const ww_cmp_opts *o,
                      ww_cmp_image *a, ww_cmp_image *b, ww_cmp_result *res, ww_error *err) {
    ww_cmp_pin_stb();
    pair_worker pw = {.path_b = path_b, .b = b};
    atomic_init(&pw.loaded, 0);
    atomic_init(&pw.work, NULL);
    int threaded = pthread_create(&pw.thread, NULL, pair_thread, &pw) == 0;
    ww_result r = ww_cmp_load_one(path_a, a, err);
    if (threaded) {
        while (!atomic_load(&pw.loaded)) sched_yield();
    } else {
        pw.r = ww_cmp_load_one(path_b, b, &pw.err);
    }
    if (r == WW_OK && pw.r != WW_OK) {
        r = pw.r;
        if (err) *err = pw.err;
    }
    if (r == WW_OK) r = images_with(a, b, o, threaded ? &pw : NULL, res, err);
    if (threaded && atomic_load(&pw.work) == NULL) { /* no bands were handed over */
        atomic_store(&pw.work, PAIR_STOP);
        pthread_join(pw.thread, NULL);
    }
    if (r != WW_OK) {
        ww_cmp_image_free(a);
        ww_cmp_image_free(b);
    }
    return r;
}
