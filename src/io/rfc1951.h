/* rfc1951.h - the constant tables of DEFLATE (RFC 1951) that the writer (deflate.c) and the
 * reader (inflate.c) share, and zlib's Adler-32 constants (RFC 1950). Header-only constants.
 */
#ifndef WW_RFC1951_H
#define WW_RFC1951_H

#include <stdint.h>

#define MAX_MATCH 258
#define ADLER_MOD 65521u
#define ADLER_BLOCK 5552  /* bytes summed before a reduction cannot overflow 32 bits (zlib's NMAX) */

/* RFC 1951 3.2.5: base length and extra bits of length codes 257..285, base distance and extra
 * bits of distance codes 0..29 */
static const uint16_t LEN_BASE[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t LEN_EXTRA[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                      2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t DIST_BASE[30] = {1,    2,    3,    4,    5,    7,     9,     13,    17,  25,
                                       33,   49,   65,   97,   129,  193,   257,   385,   513, 769,
                                       1025, 1537, 2049, 3073, 4097, 6145,  8193,  12289, 16385,
                                       24577};
static const uint8_t DIST_EXTRA[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                       6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

#endif
