/* image.h - a CPU image: top row first, interleaved channels, either 8-bit or float.
 *
 *   ww_image im; ww_image_alloc(&im, w, h, 4, WW_PIX_F32);   // one malloc
 *   ... fill im.f32 or im.u8 ...
 *   ww_image_free(&im);
 */
#ifndef WW_IMAGE_H
#define WW_IMAGE_H

#include <stddef.h>
#include <stdint.h>

/* the largest side of an image the frame readers take (io/png.c, io/png_read.c, io/exr.c and the
 * compare loader): the largest frame render makes (render.size, WW_SIZE_MAX in scene/scene.h;
 * a test holds the two equal). A larger file is refused from its header, before any pixel is
 * decoded: a 1 MB PNG can declare 32768 x 32768 and ask compare for 17 GB of floats */
#define WW_FRAME_MAX_SIDE 16384

typedef enum ww_pixel { WW_PIX_U8 = 0, WW_PIX_F32 } ww_pixel;

typedef struct ww_image {
    int width, height, channels; /* channels 1..4 */
    ww_pixel type;
    uint8_t *u8;                 /* type U8: width * height * channels bytes */
    float *f32;                  /* type F32: width * height * channels floats */
} ww_image;

int ww_image_alloc(ww_image *im, int width, int height, int channels, ww_pixel type); /* 0 ok */
void ww_image_free(ww_image *im);
/* reverse the row order in place (GL reads bottom row first) */
void ww_image_flip_rows(ww_image *im);

#endif
