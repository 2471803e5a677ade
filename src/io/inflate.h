/* inflate.h - a fast zlib (RFC 1950) / DEFLATE (RFC 1951) decoder into a caller's buffer, for
 * PNG's IDAT data (io/png_read.h) where the size of the output is known before decoding.
 *
 *   size_t n;
 *   ww_result r = ww_zlib_inflate(z, zlen, dst, cap, &n, &err);   // no allocation
 *   // WW_OK: dst[0..n) holds the data (the Adler-32 matched); bytes in dst past n may have been
 *   //        written (match copies go 8 bytes at a time)
 *   // WW_E_TYPE: a broken stream ("zlib: truncated", "zlib: Adler-32 mismatch", "zlib: distance
 *   //        D before the start of the output", "zlib: output larger than N bytes", ...)
 *
 * Stored, fixed and dynamic Huffman blocks; no preset dictionary (FDICT is an error). Bytes after
 * the Adler-32 are ignored. Corrupt input never reads or writes outside src[0..n) and dst[0..cap).
 */
#ifndef WW_INFLATE_H
#define WW_INFLATE_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

ww_result ww_zlib_inflate(const unsigned char *src, size_t n, unsigned char *dst, size_t cap,
                          size_t *out_len, ww_error *err);

/* the Adler-32 of RFC 1950 section 8.2 (start with 1) */
uint32_t ww_adler32(uint32_t adler, const unsigned char *p, size_t n);

#endif
