/* compare.h - image comparison: the metrics and pass/fail rules of `waterworld compare` and of
 * `render --golden`.
 *
 *   ww_cmp_image a = {0}, b = {0};
 *   ww_cmp_load("expected.png", &a, &err);          // PNG 8/16-bit grey/GA/RGB/RGBA, or EXR
 *   ww_cmp_load("actual.png", &b, &err);            // (or both at once: ww_cmp_load_pair)
 *   ww_cmp_opts o = ww_cmp_default_opts();          // then thresholds, e.g. o.max = 8
 *   ww_cmp_result res;
 *   ww_cmp_images(&a, &b, &o, &res, &err);          // WW_E_INCONSISTENT: sizes or kinds differ
 *   if (!res.pass) ww_cmp_write_diff("diff.png", &a, &b, &o, &err);
 *   ww_cmp_result_line(&res, stdout);               // or ww_cmp_result_json_fields
 *   ww_cmp_image_free(&a); ww_cmp_image_free(&b);   // the caller frees what it loaded, also
 *                                                   // after a failed load (it is then empty)
 *
 * Every image is held as float RGBA, top row first, its colour premultiplied by its alpha (as
 * ImageMagick's `compare` and OpenImageIO's `idiff` both compare: a colour under alpha 0 is no
 * difference). PNG values are normalised to [0, 1] (8- and 16-bit alike; grey spread to RGB; a
 * missing alpha is 1), so an 8-bit and a 16-bit file of the same picture, or a grey file and its
 * RGB twin, hold the same floats. EXR values are linear and unbounded (EXR alpha is already
 * premultiplied by convention).
 *
 * Metrics (compare.c), each over every pixel:
 *   max_abs, mean_abs  largest and mean |a - b| over R, G, B and (when the files have it) A; PNG
 *                      in 8-bit levels (0..255; 16-bit files give fractional levels), EXR linear.
 *                      max_abs / 255 and mean_abs / 255 are OpenImageIO idiff's "Max error" and
 *                      "Mean error" (idiff counts alpha, premultiplied, when a file has it).
 *   rmse, psnr         ImageMagick's `compare -channel RGB -metric RMSE` (the normalised figure
 *                      in brackets) and `-metric PSNR`: the mean of (a - b)^2 over R, G, B only
 *                      (alpha not counted, colour premultiplied), rmse = sqrt(mean), psnr =
 *                      10 log10(1 / mean) dB (INFINITY when equal). Measured against IM 6.9.11
 *                      and 7.1.1 (IM 6 leaves alpha out without -channel RGB, IM 7 counts it).
 *   diff_pixels        pixels with any channel difference over --threshold (PNG: levels; EXR:
 *                      relative error, below)
 *   yiq_pixels         pixelmatch (Kotsarenko & Ramos 2010 YIQ delta, both images blended on
 *   aa_pixels          white, 8-bit scale) over 35215 * yiq^2, split into not-anti-aliased and
 *                      anti-aliased (Vysniauskas 2009 detector, as pixelmatch adapts it); on 8-bit
 *                      files pixelmatch 7.2.0's counts exactly (with checkerboard: false; the
 *                      differences on purpose are in compare_impl.h)
 *   ssim               mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) of Rec. 601 luma on white
 *                      in [0, 1] (L = 1, C1 = (0.01 L)^2, C2 = (0.03 L)^2), over every 8x8 window
 *                      sliding one pixel at a time (uniform weights, population variances)
 *   rel_max, rel_mean  |a - b| / max(|a|, |b|, 1e-6) per channel (defined for PNG as well)
 *   nonfinite          EXR NaN/Inf rules, per channel: NaN against NaN matches, +Inf against +Inf
 *                      and -Inf against -Inf match (difference 0); NaN or Inf against anything
 *                      else is a failing pixel: counted here and in diff_pixels, left out of the
 *                      other sums, and it fails the comparison whatever the rules.
 *   EXR images enter pixelmatch and SSIM clamped to [0, 1] (NaN as 0): a display-referred view.
 *
 * Rules: each rule that is on must hold. With none on, the rule is "no pixel over --threshold"
 * (threshold 0 by default: exact match), the safe default for regression tests.
 */
#ifndef WW_COMPARE_H
#define WW_COMPARE_H

#include <stdint.h>
#include <stdio.h>

#include "core/error.h"

typedef struct ww_cmp_image {
    int width, height;
    int channels;        /* as stored in the file: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA */
    int bits;            /* bits per channel in the file: 8 or 16 (PNG), 16 or 32 (EXR) */
    int hdr;             /* 1: EXR, linear unbounded values */
    /* the pixels, in one of two layouts (the other pointer NULL):
     * rgb8: an 8-bit file without alpha (grey or RGB), width * height * 3 bytes as stored, grey
     *       spread to R, G, B; a fifth of the memory of floats, which a fresh process pays for
     *       page by page, and what the metrics' 8-bit path reads;
     * rgba: everything else, width * height * 4 floats, v / (2^bits - 1) for PNG, colour
     *       premultiplied by alpha. Both give the same figures to the bit for the same file. */
    unsigned char *rgb8;
    float *rgba;
    uint64_t hash;       /* hash of width, height, hdr, layout and pixels: equal hashes, equal
                          * pixels (ww_cmp_images confirms with the pixels themselves) */
} ww_cmp_image;

/* a rule that is off has the value -1; all are off by default (then exact match is required) */
typedef struct ww_cmp_opts {
    double threshold;    /* per-pixel threshold: a pixel "differs" when one of its channels
                          * differs by more than this; PNG: 8-bit levels, EXR: relative error
                          * (default 0) */
    double yiq;          /* pixelmatch threshold in 0..1 on the YIQ delta (default 0.1) */
    int detect_aa;       /* pixelmatch: anti-aliased pixels are not counted (default 1) */
    /* pass/fail rules, -1 = off */
    double max;          /* --max: largest channel difference allowed, 8-bit units (EXR: linear) */
    double fail_percent; /* --fail-percent: largest share of differing pixels allowed, % */
    long fail_pixels;    /* --fail-pixels: most differing pixels allowed */
    double psnr_min;     /* --psnr-min: smallest PSNR allowed, dB */
    double yiq_pixels;   /* --yiq-pixels: most pixels over the YIQ threshold (not AA) allowed
                          * (--yiq alone turns this on at 0) */
    double ssim_min;     /* --ssim-min: smallest mean SSIM allowed */
    double rel_max;      /* --rel-max: largest relative error allowed (meant for EXR) */
} ww_cmp_opts;

typedef struct ww_cmp_result {
    int width, height;
    int hdr;             /* the images are EXR: units linear, threshold relative */
    int identical;       /* same pixels, found by content hash (the fast path: the other
                          * fields are then their exact values for equal images, not computed) */
    double max_abs;      /* largest channel difference (8-bit units; EXR: linear) */
    double mean_abs;     /* mean channel difference over all pixels and channels, same units */
    double rmse;         /* normalised to [0, 1], as ImageMagick's `compare -metric RMSE` (x) */
    double psnr;         /* dB, as ImageMagick's `compare -metric PSNR`; INFINITY when equal */
    long diff_pixels;    /* pixels over opts.threshold */
    double diff_percent; /* the same as a share of all pixels, % */
    long yiq_pixels;     /* pixelmatch: pixels over the YIQ threshold, anti-aliasing excluded */
    long aa_pixels;      /* pixelmatch: pixels over it judged anti-aliasing */
    double ssim;         /* mean SSIM over the luma (8x8 windows) */
    double rel_max, rel_mean; /* relative error |a-b| / max(|a|, |b|, 1e-6), over channels */
    long nonfinite;      /* pixels whose NaN/Inf pattern differs (always a failure) */
    int pass;            /* every rule that is on holds */
    char why[256];       /* the first rule that failed, in words; "" when pass */
} ww_cmp_result;

ww_cmp_opts ww_cmp_default_opts(void);

/* PNG or EXR by content (magic bytes, not the name); WW_E_NOFILE (cannot read) / WW_E_TYPE (not
 * an image we read, or a broken one) naming the path */
ww_result ww_cmp_load(const char *path, ww_cmp_image *out, ww_error *err);
/* both images at once, decoded on two threads (the first error wins; both are left empty) */
ww_result ww_cmp_load_pair(const char *path_a, const char *path_b, ww_cmp_image *a,
                           ww_cmp_image *b, ww_error *err);
void ww_cmp_image_free(ww_cmp_image *im);

/* every metric, then the rules; WW_E_INCONSISTENT when sizes differ or one is EXR and the other
 * PNG (a mismatch of kind is bad input, not a 100% difference). RGB against RGBA compares: the
 * layouts are normalised, a missing alpha being 1, and alpha counts where either file has it */
ww_result ww_cmp_images(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                        ww_cmp_result *res, ww_error *err);

/* ww_cmp_load_pair then ww_cmp_images, one thread beside this one for both (its second image,
 * then its share of the metrics): the same figures, without a second thread start. On success
 * the images are kept (for ww_cmp_write_diff; free both); on failure both are left empty */
ww_result ww_cmp_pair(const char *path_a, const char *path_b, const ww_cmp_opts *o,
                      ww_cmp_image *a, ww_cmp_image *b, ww_cmp_result *res, ww_error *err);

/* diff image as RGB8 PNG (atomic), pixelmatch's convention: the expected image (a) as grey
 * faded towards white (10% contrast), pixels over the YIQ threshold judged anti-aliasing yellow,
 * every other differing pixel (over the YIQ threshold or over opts.threshold) red */
ww_result ww_cmp_write_diff(const char *path, const ww_cmp_image *a, const ww_cmp_image *b,
                            const ww_cmp_opts *o, ww_error *err);

/* the members of a JSON object, without the braces (the caller's object holds them): every
 * metric, the rules that were on, pass and why; PSNR of equal images is written as null (JSON
 * has no infinity) */
void ww_cmp_result_json_fields(const ww_cmp_result *res, const ww_cmp_opts *o, FILE *f);
/* one line of text: the metrics, then PASS or FAIL and why */
void ww_cmp_result_line(const ww_cmp_result *res, FILE *f);

/* the threshold options shared by `compare` and `render --golden` (--threshold, --yiq, --no-aa,
 * --max, --fail-percent, --fail-pixels, --psnr-min, --yiq-pixels, --ssim-min, --rel-max; a value
 * as the next word or after '='); returns 1 when argv[*i] was one (then *i moves past its
 * value), a bad value sets *r to WW_E_USAGE */
int ww_cmp_opt_arg(int argc, char **argv, int *i, ww_cmp_opts *o, ww_result *r, ww_error *err);

#endif
