/* y4m.c - YUV4MPEG2 frames from RGB8 images (see y4m.h): BT.709 Y'CbCr in limited range, in
 * fixed point so the bytes are the same on every machine.
 */
#include "io/y4m.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/error.h"

/* ITU-R BT.709-6 item 3.2/3.3: luma weights, and limited-range quantisation of 8-bit signals
 * (Y' = 16 + 219 E'Y, C = 128 + 224 E'C, item 4.6) */
#define BT709_KR 0.2126
#define BT709_KB 0.0722
#define Y_OFFSET 16
#define Y_RANGE 219.0
#define C_OFFSET 128
#define C_RANGE 224.0
/* fixed-point scale of the matrix coefficients (16 fraction bits: error < 0.01 level) */
#define FIX_BITS 16
/* a frame rate within this of a ratio counts as that ratio */
#define FPS_RATIO_TOL 1e-6
#define FRAME_TAG "FRAME\n"

void ww_fps_rational(double fps, long *num, long *den) {
    /* whole rates, then NTSC-style N*1000/1001, then thousandths reduced */
    static const long dens[] = {1, 1001, 1000};
    for (size_t i = 0; i < sizeof dens / sizeof dens[0]; i++) {
        double n = round(fps * (double)dens[i]);
        if (fabs(n / (double)dens[i] - fps) > FPS_RATIO_TOL) continue;
        long a = (long)n, b = dens[i];
        for (long x = a, y = b; y != 0;) { /* gcd */
            long t = x % y;
            x = y;
            y = t;
            if (y == 0) {
                a /= x;
                b /= x;
            }
        }
        *num = a;
        *den = b;
        return;
    }
    *num = (long)round(fps * 1000.0);
    *den = 1000;
}

int ww_y4m_header(char *buf, size_t cap, int width, int height, double fps, int c420) {
    long num, den;
    ww_fps_rational(fps, &num, &den);
    int n = snprintf(buf, cap, "YUV4MPEG2 W%d H%d F%ld:%ld Ip A1:1 %s XCOLORRANGE=LIMITED\n", width,
                     height, num, den, c420 ? "C420jpeg XYSCSS=420JPEG" : "C444 XYSCSS=444");
    WW_ASSERT(n > 0 && (size_t)n < cap);
    return n;
}

static size_t chroma_side(int n, int c420) { return c420 ? (size_t)(n + 1) / 2 : (size_t)n; }

size_t ww_y4m_frame_bytes(int width, int height, int c420) {
    size_t luma = (size_t)width * (size_t)height;
    size_t chroma = chroma_side(width, c420) * chroma_side(height, c420);
    return strlen(FRAME_TAG) + luma + 2 * chroma;
}

/* the BT.709 matrix scaled to limited range, in FIX_BITS fixed point */
typedef struct y4m_matrix {
    long y[3], cb[3], cr[3];
} y4m_matrix;

static long fix(double v) { return lround(v * (double)(1L << FIX_BITS)); }

static y4m_matrix bt709_limited(void) {
    const double kr = BT709_KR, kb = BT709_KB, kg = 1.0 - kr - kb;
    const double sy = Y_RANGE / 255.0, sc = C_RANGE / 255.0;
    /* E'Cb = (B' - Y') / (2 (1 - Kb)), E'Cr = (R' - Y') / (2 (1 - Kr)) */
    const double cb = sc / (2.0 * (1.0 - kb)), cr = sc / (2.0 * (1.0 - kr));
    y4m_matrix m = {
        .y = {fix(sy * kr), fix(sy * kg), fix(sy * kb)},
        .cb = {fix(-cb * kr), fix(-cb * kg), fix(cb * (1.0 - kb))},
        .cr = {fix(cr * (1.0 - kr)), fix(-cr * kg), fix(-cr * kb)},
    };
    return m;
}

static uint8_t clamp8(long v) { return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v); }

/* offset + (row . rgb) / n for sums r, g, b over n pixels, rounded to nearest (the products
 * carry FIX_BITS fraction bits; every result of the limited-range matrix is >= 16 - 0.5) */
static long apply(const long k[3], long r, long g, long b, long offset, long n) {
    long den = n << FIX_BITS;
    long s = k[0] * r + k[1] * g + k[2] * b + offset * den + den / 2;
    return s < 0 ? 0 : s / den;
}

void ww_y4m_frame(const ww_image *im, int c420, uint8_t *out) {
    WW_ASSERT(im->type == WW_PIX_U8 && im->u8 && (im->channels == 3 || im->channels == 4));
    const y4m_matrix m = bt709_limited();
    const int w = im->width, h = im->height, nc = im->channels;
    const size_t cw = chroma_side(w, c420), ch = chroma_side(h, c420);
    memcpy(out, FRAME_TAG, strlen(FRAME_TAG));
    uint8_t *py = out + strlen(FRAME_TAG), *pb = py + (size_t)w * (size_t)h, *pr = pb + cw * ch;

    for (int y = 0; y < h; y++) {
        const uint8_t *p = im->u8 + (size_t)y * (size_t)w * (size_t)nc;
        for (int x = 0; x < w; x++, p += nc)
            py[(size_t)y * (size_t)w + (size_t)x] = clamp8(apply(m.y, p[0], p[1], p[2], Y_OFFSET, 1));
    }
    /* chroma of each sample's block (1x1, or 2x2 cut at the right and bottom edges): the
     * matrix is linear, so the block's mean R'G'B' gives its mean Cb and Cr */
    const int bs = c420 ? 2 : 1;
    for (size_t cy = 0; cy < ch; cy++) {
        for (size_t cx = 0; cx < cw; cx++) {
            long r = 0, g = 0, b = 0, n = 0;
            for (int dy = 0; dy < bs; dy++) {
                size_t y = cy * (size_t)bs + (size_t)dy;
                for (int dx = 0; dx < bs && y < (size_t)h; dx++) {
                    size_t x = cx * (size_t)bs + (size_t)dx;
                    if (x >= (size_t)w) continue;
                    const uint8_t *p = im->u8 + (y * (size_t)w + x) * (size_t)nc;
                    r += p[0];
                    g += p[1];
                    b += p[2];
                    n++;
                }
            }
            pb[cy * cw + cx] = clamp8(apply(m.cb, r, g, b, C_OFFSET, n));
            pr[cy * cw + cx] = clamp8(apply(m.cr, r, g, b, C_OFFSET, n));
        }
    }
}
