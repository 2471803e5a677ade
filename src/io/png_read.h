/* png_read.h - a fast PNG reader for the common cases: non-interlaced, bit depth 8 or 16, grey,
 * grey + alpha, RGB or RGBA (PNG specification, colour types 0, 4, 2, 6).
 *
 *   ww_png_pixels im;
 *   ww_result r = ww_png_decode(file, len, &im, &err);
 *   if (r == WW_E_RANGE)  -> a valid PNG of a kind this reader leaves to stb_image (palette,
 *                            interlaced, bit depth under 8, a tRNS colour key, Apple's CgBI):
 *                            the caller falls back to stb_image
 *   else if (r != WW_OK)  -> WW_E_TYPE: a broken file (bad signature or CRC, no IEND, an IDAT
 *                            too short, a zero width, ...); WW_E_NOMEM
 *   ... im.px: rows top first, channels interleaved ...
 *   free(im.px);                         // the caller frees the pixels (NULL after a failure)
 *
 * Every chunk's CRC-32 is checked; unknown ancillary chunks are skipped, an unknown critical one
 * is an error. Width and height are at most WW_PNG_MAX_DIM and the decoded rows at most
 * WW_PNG_MAX_BYTES, so a hostile header cannot ask for more memory than that.
 */
#ifndef WW_PNG_READ_H
#define WW_PNG_READ_H

#include <stddef.h>

#include "core/error.h"
#include "io/image.h"

#define WW_PNG_MAX_DIM WW_FRAME_MAX_SIDE             /* io/image.h */
#define WW_PNG_MAX_BYTES ((size_t)0x7fffffff)        /* as stb_image: sizes fit in an int */

typedef struct ww_png_pixels {
    int width, height;
    int channels; /* 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA */
    int bits;     /* 8: px holds uint8_t; 16: uint16_t in host byte order */
    void *px;     /* width * height * channels samples, rows top first; free() */
} ww_png_pixels;

ww_result ww_png_decode(const unsigned char *file, size_t len, ww_png_pixels *out, ww_error *err);

#endif
