/* deflate.h - a fast zlib stream (RFC 1950 around RFC 1951) for PNG frames: greedy LZ77 with one
 * hash probe per position and the fixed Huffman codes, no allocation but the output.
 *
 *   size_t n; unsigned char *z = ww_zlib_fast(data, len, &n);   // malloc'd; NULL: out of memory
 *   ... free(z);
 *
 * stb_image_write's own deflate keeps a growable list per hash bucket and matches lazily; on a
 * rendered 1280x720 frame this one is several times faster for a few per cent more bytes, which
 * is what a frame writer racing the renderer for two cores wants (README, "Frames out").
 */
#ifndef WW_DEFLATE_H
#define WW_DEFLATE_H

#include <stddef.h>

unsigned char *ww_zlib_fast(const unsigned char *data, size_t len, size_t *out_len);

#endif
