/* compare_impl.h - what the comparison's files share inside check/ (not an interface): the
 * pixelmatch pieces, used by the metrics (compare.c) and the diff image (compare_out.c).
 *
 * pixelmatch's method (Mapbox's published description): both pixels are blended on white on an
 * 8-bit scale, their difference is weighed in YIQ after Kotsarenko & Ramos 2010,
 *   delta = 0.5053 dY^2 + 0.299 dI^2 + 0.1957 dQ^2,
 * and a pixel differs when delta > 35215 t^2 (35215: the largest delta, red against cyan; t: the
 * threshold in 0..1). A differing pixel is anti-aliasing (Vysniauskas 2009, "Anti-aliased
 * pixel and intensity slope detector") when, in either image, its 3x3 neighbourhood holds at most
 * two pixels of its own brightness, both a darker and a brighter one, and the darkest or the
 * brightest of them (the first met, scanning column by column) sits in a flat area (3+ identical
 * neighbours) in both images.
 *
 * On 8-bit files this is pixelmatch 7.2.0 to the bit (checked against it under node: tests
 * compare_pixelmatch_agrees_*), blending on white as its `checkerboard: false` does. Where we
 * differ on purpose: "identical neighbours" compares premultiplied colour, so pixels under alpha 0
 * are identical whatever colour they store (pixelmatch compares the stored RGBA); 16-bit and EXR
 * values are differenced on a grid of 1/255 of an 8-bit level (pixelmatch reads bytes only).
 */
#ifndef WW_COMPARE_IMPL_H
#define WW_COMPARE_IMPL_H

#include "check/compare.h"

#define WW_CMP_YIQ_MAX_DELTA 35215.0 /* pixelmatch: the largest delta (red against cyan) */

/* pixel kinds of the diff image */
enum { WW_CMP_SAME = 0, WW_CMP_DIFF = 1, WW_CMP_AA = 2 };

/* pin stb_image's run-time settings (once per thread that starts decoders; they are globals of
 * stb's) and load one image without pinning (ww_cmp_load's body, safe on two threads at once) */
void ww_cmp_pin_stb(void);
ww_result ww_cmp_load_one(const char *path, ww_cmp_image *out, ww_error *err);

/* pixel i as float RGBA, colour premultiplied, from either layout (as the rgba layout holds it) */
void ww_cmp_pixel(const ww_cmp_image *im, size_t i, float px[4]);
/* an image in the rgba layout made from an rgb8 one, hashed as such (a pair of mixed layouts is
 * compared in rgba); free with ww_cmp_image_free */
ww_result ww_cmp_to_rgba(const ww_cmp_image *in, ww_cmp_image *out, ww_error *err);
/* the float of an 8-bit level v, v / 255 rounded to float, as the rgba layout holds it */
float ww_cmp_level(unsigned v);

/* brightness (YIQ's Y) of a pixel blended on white, 8-bit scale; values clamped to [0, 1] */
double ww_cmp_luma_on_white(const float *px);
/* pixelmatch's delta between two pixels (>= 0) */
double ww_cmp_yiq_delta(const float *p, const float *q);
/* is pixel (x, y) of img anti-aliasing, judged against the other image? */
int ww_cmp_antialiased(const ww_cmp_image *img, const ww_cmp_image *other, int x, int y);
/* the largest channel difference of pixel i in the threshold's unit (PNG: 8-bit levels,
 * EXR: relative error; a NaN/Inf mismatch is INFINITY) */
double ww_cmp_pixel_diff(const ww_cmp_image *a, const ww_cmp_image *b, size_t i);
/* WW_CMP_SAME, _DIFF or _AA for pixel (x, y), as the diff image paints it */
int ww_cmp_pixel_kind(const ww_cmp_image *a, const ww_cmp_image *b, int x, int y,
                      const ww_cmp_opts *o);

#endif
