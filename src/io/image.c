/* image.c - allocation and the single row flip of read-back images. */
#include "io/image.h"

#include <stdlib.h>
#include <string.h>

int ww_image_alloc(ww_image *im, int width, int height, int channels, ww_pixel type) {
    memset(im, 0, sizeof *im);
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4) return -1;
    size_t n = (size_t)width * (size_t)height * (size_t)channels;
    im->width = width;
    im->height = height;
    im->channels = channels;
    im->type = type;
    if (type == WW_PIX_U8)
        im->u8 = malloc(n);
    else
        im->f32 = malloc(n * sizeof(float));
    return (im->u8 || im->f32) ? 0 : -1;
}

void ww_image_free(ww_image *im) {
    free(im->u8);
    free(im->f32);
    im->u8 = NULL;
    im->f32 = NULL;
}

void ww_image_flip_rows(ww_image *im) {
    size_t elem = im->type == WW_PIX_U8 ? 1 : sizeof(float);
    size_t row = (size_t)im->width * (size_t)im->channels * elem;
    unsigned char *p = im->type == WW_PIX_U8 ? (unsigned char *)im->u8 : (unsigned char *)im->f32;
    unsigned char tmp[4096];
    for (int y = 0; y < im->height / 2; y++) {
        unsigned char *a = p + (size_t)y * row, *b = p + (size_t)(im->height - 1 - y) * row;
        for (size_t off = 0; off < row; off += sizeof tmp) {
            size_t n = row - off < sizeof tmp ? row - off : sizeof tmp;
            memcpy(tmp, a + off, n);
            memcpy(a + off, b + off, n);
            memcpy(b + off, tmp, n);
        }
    }
}
