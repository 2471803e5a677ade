/* compare_out.c - what the comparison gives back: the diff image (pixelmatch's colours), the
 * JSON and text lines of a result, and the threshold options shared by `compare` and
 * `render --golden`.
 */
#include "check/compare_impl.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "io/json.h"
#include "io/writers.h"

#define FADE 0.1 /* pixelmatch's alpha: the expected image's grey keeps 10% of its contrast */
static const unsigned char diff_red[3] = {255, 0, 0};
static const unsigned char aa_yellow[3] = {255, 255, 0};

ww_result ww_cmp_write_diff(const char *path, const ww_cmp_image *a, const ww_cmp_image *b,
                            const ww_cmp_opts *o, ww_error *err) {
    WW_ASSERT(a->width == b->width && a->height == b->height);
    ww_image im;
    if (ww_image_alloc(&im, a->width, a->height, 3, WW_PIX_U8) != 0) {
        ww_image_free(&im);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot write '%s': out of memory", path);
    }
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            size_t i = (size_t)y * (size_t)a->width + (size_t)x;
            unsigned char *d = im.u8 + 3 * i;
            int kind = ww_cmp_pixel_kind(a, b, x, y, o);
            if (kind != WW_CMP_SAME) {
                memcpy(d, kind == WW_CMP_AA ? aa_yellow : diff_red, 3);
                continue;
            }
            /* the expected pixel's brightness on white, faded towards white */
            float px[4];
            ww_cmp_pixel(a, i, px);
            double g = 255.0 + (ww_cmp_luma_on_white(px) - 255.0) * FADE;
            d[0] = d[1] = d[2] = (unsigned char)lrint(g < 0 ? 0 : g > 255 ? 255 : g);
        }
    ww_result r = ww_write_png(path, &im, err);
    ww_image_free(&im);
    return r;
}

/* ---- results ---------------------------------------------------------------------------------- */

/* a JSON number; NaN and infinities (no JSON for them) as null */
static void json_num(FILE *f, const char *key, double v) {
    if (isfinite(v))
        fprintf(f, ",\"%s\":%.9g", key, v);
    else
        fprintf(f, ",\"%s\":null", key);
}

void ww_cmp_result_json_fields(const ww_cmp_result *r, const ww_cmp_opts *o, FILE *f) {
    fprintf(f, "\"width\":%d,\"height\":%d,\"units\":\"%s\",\"identical\":%s", r->width, r->height,
            r->hdr ? "linear" : "8bit", r->identical ? "true" : "false");
    json_num(f, "max_abs", r->max_abs);
    json_num(f, "mean_abs", r->mean_abs);
    json_num(f, "rmse", r->rmse);
    json_num(f, "psnr", r->psnr);
    fprintf(f, ",\"diff_pixels\":%ld", r->diff_pixels);
    json_num(f, "diff_percent", r->diff_percent);
    fprintf(f, ",\"yiq_pixels\":%ld,\"aa_pixels\":%ld", r->yiq_pixels, r->aa_pixels);
    json_num(f, "ssim", r->ssim);
    json_num(f, "rel_max", r->rel_max);
    json_num(f, "rel_mean", r->rel_mean);
    fprintf(f, ",\"nonfinite\":%ld", r->nonfinite);

    /* the settings, and the rules that were on */
    fprintf(f, ",\"rules\":{\"threshold\":%.9g,\"yiq\":%.9g,\"detect_aa\":%s", o->threshold, o->yiq,
            o->detect_aa ? "true" : "false");
    if (o->max >= 0) fprintf(f, ",\"max\":%.9g", o->max);
    if (o->fail_percent >= 0) fprintf(f, ",\"fail_percent\":%.9g", o->fail_percent);
    if (o->fail_pixels >= 0) fprintf(f, ",\"fail_pixels\":%ld", o->fail_pixels);
    if (o->psnr_min >= 0) fprintf(f, ",\"psnr_min\":%.9g", o->psnr_min);
    if (o->yiq_pixels >= 0) fprintf(f, ",\"yiq_pixels\":%.9g", o->yiq_pixels);
    if (o->ssim_min >= 0) fprintf(f, ",\"ssim_min\":%.9g", o->ssim_min);
    if (o->rel_max >= 0) fprintf(f, ",\"rel_max\":%.9g", o->rel_max);
    fprintf(f, "},\"pass\":%s,\"why\":", r->pass ? "true" : "false");
    ww_json_string(f, r->why);
}

void ww_cmp_result_line(const ww_cmp_result *r, FILE *f) {
    if (r->identical) {
        fprintf(f, "identical  PASS");
        return;
    }
    const char *u = r->hdr ? "" : "/255";
    fprintf(f, "max %.4g%s mean %.4g%s rmse %.6f psnr %.2f dB  over-threshold %ld (%.3f%%)  "
               "yiq %ld (+%ld aa)  ssim %.6f",
            r->max_abs, u, r->mean_abs, u, r->rmse, r->psnr, r->diff_pixels, r->diff_percent,
            r->yiq_pixels, r->aa_pixels, r->ssim);
    if (r->hdr) fprintf(f, "  rel max %.4g mean %.4g nonfinite %ld", r->rel_max, r->rel_mean,
                        r->nonfinite);
    fprintf(f, "  %s%s%s", r->pass ? "PASS" : "FAIL", r->pass ? "" : ": ", r->why);
}

/* ---- options ---------------------------------------------------------------------------------- */

typedef enum { OPT_REAL, OPT_COUNT } opt_kind;

typedef struct cmp_opt {
    const char *name;
    opt_kind kind;
    double lo, hi;       /* allowed range */
    size_t offset;       /* of the double (REAL) or long (COUNT) in ww_cmp_opts */
} cmp_opt;

static const cmp_opt cmp_opts[] = {
    {"--threshold", OPT_REAL, 0, 1e30, offsetof(ww_cmp_opts, threshold)},
    {"--yiq", OPT_REAL, 0, 1, offsetof(ww_cmp_opts, yiq)},
    {"--max", OPT_REAL, 0, 1e30, offsetof(ww_cmp_opts, max)},
    {"--fail-percent", OPT_REAL, 0, 100, offsetof(ww_cmp_opts, fail_percent)},
    {"--fail-pixels", OPT_COUNT, 0, 1e15, offsetof(ww_cmp_opts, fail_pixels)},
    {"--psnr-min", OPT_REAL, 0, 1e30, offsetof(ww_cmp_opts, psnr_min)},
    {"--yiq-pixels", OPT_REAL, 0, 1e15, offsetof(ww_cmp_opts, yiq_pixels)},
    {"--ssim-min", OPT_REAL, -1, 1, offsetof(ww_cmp_opts, ssim_min)},
    {"--rel-max", OPT_REAL, 0, 1e30, offsetof(ww_cmp_opts, rel_max)},
};

/* does word name the option? then *val is its value (after '=' or the next word, NULL: none) */
static int match_opt(const char *name, int argc, char **argv, int *i, const char **val) {
    size_t n = strlen(name);
    const char *w = argv[*i];
    if (strncmp(w, name, n) != 0 || (w[n] != '\0' && w[n] != '=')) return 0;
    if (w[n] == '=')
        *val = w + n + 1;
    else
        *val = *i + 1 < argc ? argv[++*i] : NULL;
    return 1;
}

int ww_cmp_opt_arg(int argc, char **argv, int *i, ww_cmp_opts *o, ww_result *r, ww_error *err) {
    if (strcmp(argv[*i], "--no-aa") == 0) {
        o->detect_aa = 0;
        return 1;
    }
    for (size_t k = 0; k < sizeof cmp_opts / sizeof cmp_opts[0]; k++) {
        const cmp_opt *c = &cmp_opts[k];
        const char *val;
        if (!match_opt(c->name, argc, argv, i, &val)) continue;
        char *end = NULL;
        double v = val ? strtod(val, &end) : NAN;
        int whole = c->kind == OPT_REAL || v == floor(v);
        if (!val || end == val || *end || !isfinite(v) || v < c->lo || v > c->hi || !whole) {
            *r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s wants %s in %g..%g, got '%s'",
                              c->name, c->kind == OPT_COUNT ? "a whole number" : "a number", c->lo,
                              c->hi, val ? val : "nothing");
            return 1;
        }
        if (c->kind == OPT_COUNT)
            *(long *)((char *)o + c->offset) = (long)v;
        else
            *(double *)((char *)o + c->offset) = v;
        /* --yiq alone is a rule: no pixel over it (--yiq-pixels N relaxes it) */
        if (strcmp(c->name, "--yiq") == 0 && o->yiq_pixels < 0) o->yiq_pixels = 0;
        return 1;
    }
    return 0;
}
