/* compare.h - image comparison: the metrics and pass/fail rules of `waterworld compare` and of
 * `render --golden`.
 *
 *   ww_cmp_image a = {0}, b = {0};
 *   ww_cmp_load("expected.png", &a, &err);          // PNG 8/16-bit grey/GA/RGB/RGBA, or EXR
 *   ww_cmp_load("actual.png", &b, &err);
 *   ww_cmp_opts o = ww_cmp_default_opts();          // then thresholds, e.g. o.max = 8
 *   ww_cmp_result res;
 *   ww_cmp_images(&a, &b, &o, &res, &err);          // WW_E_INCONSISTENT: sizes or kinds differ
 *   if (!res.pass) ww_cmp_write_diff("diff.png", &a, &b, &o, &err);
 *   ww_cmp_result_json(&res, &o, stdout);
 *   ww_cmp_image_free(&a); ww_cmp_image_free(&b);
 *
 * Every image is held as float RGBA, top row first. PNG values are normalised to [0, 1] (8- and
 * 16-bit alike; grey spread to RGB; a missing alpha is 1), so an 8-bit and a 16-bit file of the
 * same picture compare equal. EXR values are linear and unbounded. Difference thresholds are in
 * 8-bit units (0..255) for PNG; EXR uses relative error instead (see ww_cmp_result).
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
    float *rgba;         /* width * height * 4 */
    uint64_t hash;       /* hash of width, height, hdr and rgba: equal hashes, equal pixels */
} ww_cmp_image;

/* a rule that is off has the value -1 (all of them are off by default: any difference then
 * passes unless a rule says otherwise, except that default_rules() turns on exact matching) */
typedef struct ww_cmp_opts {
    double threshold;    /* per-pixel threshold, 8-bit units: a pixel "differs" when one of its
                          * channels differs by more than this (default 0) */
    double yiq;          /* pixelmatch threshold in 0..1 on the YIQ delta (default 0.1) */
    int detect_aa;       /* pixelmatch: anti-aliased pixels are not counted (default 1) */
    /* pass/fail rules, -1 = off */
    double max;          /* --max: largest channel difference allowed, 8-bit units */
    double fail_percent; /* --fail-percent: largest share of differing pixels allowed, % */
    long fail_pixels;    /* --fail-pixels: most differing pixels allowed */
    double psnr_min;     /* --psnr-min: smallest PSNR allowed, dB */
    double yiq_pixels;   /* --yiq-pixels: most pixels over the YIQ threshold (not AA) allowed */
    double ssim_min;     /* --ssim-min: smallest mean SSIM allowed */
    double rel_max;      /* --rel-max: EXR: largest relative error allowed */
} ww_cmp_opts;

typedef struct ww_cmp_result {
    int width, height;
    int identical;       /* content hashes equal (the fast path: no metric was computed) */
    double max_abs;      /* largest channel difference (8-bit units; EXR: linear) */
    double mean_abs;     /* mean channel difference over all pixels and channels, same units */
    double rmse;         /* normalised to [0, 1], as ImageMagick's `compare -metric RMSE` (x) */
    double psnr;         /* dB, as ImageMagick's `compare -metric PSNR`; INFINITY when equal */
    long diff_pixels;    /* pixels over opts.threshold */
    double diff_percent; /* the same as a share of all pixels, % */
    long yiq_pixels;     /* pixelmatch: pixels over the YIQ threshold, anti-aliasing excluded */
    long aa_pixels;      /* pixelmatch: pixels over it judged anti-aliasing */
    double ssim;         /* mean SSIM over the luma (8x8 windows) */
    /* EXR: relative error |a-b| / max(|a|, |b|, 1e-6); NaN/Inf rules in compare.c */
    double rel_max, rel_mean;
    long nonfinite;      /* EXR: pixels whose NaN/Inf pattern differs (always a failure) */
    int pass;            /* every rule that is on holds */
    char why[256];       /* the first rule that failed, in words; "" when pass */
} ww_cmp_result;

ww_cmp_opts ww_cmp_default_opts(void);

/* PNG or EXR by content; WW_E_NOFILE / WW_E_TYPE (not an image we read) naming the path */
ww_result ww_cmp_load(const char *path, ww_cmp_image *out, ww_error *err);
void ww_cmp_image_free(ww_cmp_image *im);

/* every metric, then the rules; WW_E_INCONSISTENT when sizes differ or one is EXR and the other
 * PNG (a mismatch of kind is bad input, not a 100% difference) */
ww_result ww_cmp_images(const ww_cmp_image *a, const ww_cmp_image *b, const ww_cmp_opts *o,
                        ww_cmp_result *res, ww_error *err);

/* diff image as PNG (atomic): the expected image faded, differing pixels red, anti-aliasing
 * yellow (pixelmatch's convention) */
ww_result ww_cmp_write_diff(const char *path, const ww_cmp_image *a, const ww_cmp_image *b,
                            const ww_cmp_opts *o, ww_error *err);

/* one JSON object (no newline) with every metric, the rules that were on, pass and why */
void ww_cmp_result_json(const ww_cmp_result *res, const ww_cmp_opts *o, FILE *f);

/* the threshold options shared by `compare` and `render --golden` (--threshold, --yiq, --no-aa,
 * --max, --fail-percent, --fail-pixels, --psnr-min, --yiq-pixels, --ssim-min, --rel-max); returns 1
 * when argv[*i] was one (then *i moves past its value), a bad value sets *r to WW_E_USAGE */
int ww_cmp_opt_arg(int argc, char **argv, int *i, ww_cmp_opts *o, ww_result *r, ww_error *err);

#endif
