/* png_read.c - the PNG reader of png_read.h (PNG specification, W3C 2003 / ISO 15948): a chunk
 * walk with CRC-32 checks, the IDAT data inflated by io/inflate.c straight into the pixel buffer,
 * then unfiltered (section 9) row by row in place, each row moved up over the filter bytes as it
 * is unfiltered, so no second image-sized buffer is touched.
 */
#include "io/png_read.h"

#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/bigalloc.h"
#include "io/inflate.h"

#define PNG_SIG_LEN 8
#define CHUNK_OVERHEAD 12         /* length, type, CRC */
#define CHUNK_MAX_LEN 0x7fffffffu /* section 5.3: lengths are at most 2^31 - 1 */
#define IHDR_LEN 13
/* the most output bytes one byte of deflate input can stand for: a 258-byte match in 2 bits,
 * 1032:1 (zlib's FAQ); IDAT data shorter than the rows need by this much cannot hold them */
#define DEFLATE_MAX_RATIO 1032u
#define ZLIB_OVERHEAD 6u          /* header and Adler-32 */
#define CRC_POLY 0xedb88320u      /* section 5.5, reflected */
#define CRC_SLICES 8

enum { FILTER_NONE, FILTER_SUB, FILTER_UP, FILTER_AVERAGE, FILTER_PAETH, FILTER_COUNT };
enum { CT_GREY = 0, CT_RGB = 2, CT_PALETTE = 3, CT_GREY_ALPHA = 4, CT_RGBA = 6 };

static const unsigned char PNG_SIG[PNG_SIG_LEN] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

/* ---- CRC-32, slicing by 8 (Kounavis & Berry 2005: eight table lookups per 8 bytes) ---------- */

static uint32_t crc_table[CRC_SLICES][256];
static pthread_once_t crc_once = PTHREAD_ONCE_INIT;

static void crc_build(void) {
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++) c = c & 1u ? CRC_POLY ^ (c >> 1) : c >> 1;
        crc_table[0][n] = c;
    }
    for (int s = 1; s < CRC_SLICES; s++)
        for (int n = 0; n < 256; n++)
            crc_table[s][n] = crc_table[0][crc_table[s - 1][n] & 0xffu] ^ (crc_table[s - 1][n] >> 8);
}

static uint32_t crc_update(uint32_t c, const unsigned char *p, size_t n) {
    for (; n >= 8; n -= 8, p += 8) {
        uint32_t lo = c ^ ((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                           (uint32_t)p[3] << 24);
        c = crc_table[7][lo & 0xffu] ^ crc_table[6][(lo >> 8) & 0xffu] ^
            crc_table[5][(lo >> 16) & 0xffu] ^ crc_table[4][lo >> 24] ^ crc_table[3][p[4]] ^
            crc_table[2][p[5]] ^ crc_table[1][p[6]] ^ crc_table[0][p[7]];
    }
    for (; n > 0; n--) c = crc_table[0][(c ^ *p++) & 0xffu] ^ (c >> 8);
    return c;
}

/* ---- chunks --------------------------------------------------------------------------------- */

static uint32_t be32(const unsigned char *p) {
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

typedef struct png_info {
    uint32_t width, height;
    int depth, colour, interlace;
    int channels;
    size_t idat_total;   /* bytes of IDAT data, all chunks */
    int idat_count;
    size_t first_idat;   /* offset of the first IDAT chunk */
} png_info;

static ww_result bad(ww_error *err, const char *msg) {
    return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: %s", msg);
}

/* section 11.2.2: the image header; WW_E_RANGE for what is left to stb_image */
static ww_result parse_ihdr(const unsigned char *d, png_info *pi, ww_error *err) {
    pi->width = be32(d);
    pi->height = be32(d + 4);
    pi->depth = d[8];
    pi->colour = d[9];
    pi->interlace = d[12];
    int depth_ok;
    switch (pi->colour) {
    case CT_GREY: depth_ok = pi->depth == 1 || pi->depth == 2 || pi->depth == 4 || pi->depth == 8 || pi->depth == 16; break;
    case CT_PALETTE: depth_ok = pi->depth == 1 || pi->depth == 2 || pi->depth == 4 || pi->depth == 8; break;
    case CT_RGB:
    case CT_GREY_ALPHA:
    case CT_RGBA: depth_ok = pi->depth == 8 || pi->depth == 16; break;
    default: return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: bad colour type %d", pi->colour);
    }
    if (!depth_ok)
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: bit depth %d with colour type %d",
                            pi->depth, pi->colour);
    if (d[10] != 0 || d[11] != 0 || pi->interlace > 1)
        return bad(err, "unknown compression, filter or interlace method");
    if (pi->width == 0 || pi->height == 0) return bad(err, "zero width or height");
    if (pi->width > WW_PNG_MAX_DIM || pi->height > WW_PNG_MAX_DIM)
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: %ux%u is larger than %d on a side",
                            (unsigned)pi->width, (unsigned)pi->height, WW_PNG_MAX_DIM);
    if (pi->colour == CT_PALETTE)
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0, "png: palette image, left to stb_image");
    if (pi->interlace)
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0, "png: interlaced, left to stb_image");
    if (pi->depth < 8)
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0, "png: bit depth %d, left to stb_image",
                            pi->depth);
    pi->channels = pi->colour == CT_GREY ? 1 : pi->colour == CT_GREY_ALPHA ? 2 : pi->colour == CT_RGB ? 3 : 4;
    return WW_OK;
}

/* walk every chunk: lengths inside the file, CRCs right, IHDR first, IEND present */
static ww_result walk_chunks(const unsigned char *f, size_t len, png_info *pi, ww_error *err) {
    if (len < PNG_SIG_LEN || memcmp(f, PNG_SIG, PNG_SIG_LEN) != 0)
        return bad(err, "not a PNG file (signature)");
    pthread_once(&crc_once, crc_build);
    size_t pos = PNG_SIG_LEN;
    int have_ihdr = 0;
    for (;;) {
        if (len - pos < CHUNK_OVERHEAD) return bad(err, "truncated (no IEND chunk)");
        const unsigned char *c = f + pos;
        uint32_t n = be32(c);
        char type[5] = {(char)c[4], (char)c[5], (char)c[6], (char)c[7], 0};
        if (n > CHUNK_MAX_LEN || n > len - pos - CHUNK_OVERHEAD)
            return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: chunk %s runs past the end of the file", type);
        uint32_t crc = crc_update(0xffffffffu, c + 4, (size_t)n + 4) ^ 0xffffffffu;
        if (crc != be32(c + 8 + n))
            return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: bad CRC in chunk %s", type);
        const unsigned char *d = c + 8;

        if (!have_ihdr) {
            if (memcmp(type, "IHDR", 4) != 0) return bad(err, "first chunk is not IHDR");
            if (n != IHDR_LEN) return bad(err, "IHDR of the wrong length");
            ww_result r = parse_ihdr(d, pi, err);
            if (r != WW_OK) return r;
            have_ihdr = 1;
        } else if (memcmp(type, "IDAT", 4) == 0) {
            if (pi->idat_count++ == 0) pi->first_idat = pos;
            pi->idat_total += n;
        } else if (memcmp(type, "IEND", 4) == 0) {
            break;
        } else if (memcmp(type, "IHDR", 4) == 0) {
            return bad(err, "a second IHDR");
        } else if (memcmp(type, "PLTE", 4) == 0) {
            /* a suggested palette for a truecolour image (section 11.2.3); none for grey */
            if (pi->colour == CT_GREY || pi->colour == CT_GREY_ALPHA)
                return bad(err, "PLTE in a grey image");
        } else if (memcmp(type, "tRNS", 4) == 0 || memcmp(type, "CgBI", 4) == 0) {
            /* stb_image turns a colour key into an alpha channel and reads Apple's PNGs */
            return ww_error_set(err, WW_E_RANGE, NULL, 0, 0, "png: %s chunk, left to stb_image", type);
        } else if (!(c[4] & 0x20u)) {
            return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: unknown critical chunk %s", type); /* section 5.4: bit 5 of the first byte */
        }
        pos += (size_t)n + CHUNK_OVERHEAD;
    }
    if (pi->idat_count == 0) return bad(err, "no IDAT chunk");
    return WW_OK;
}

/* the IDAT data as one run of bytes: the file's own when there is one chunk, else a copy
 * (*copy is set, the caller frees it) */
static ww_result gather_idat(const unsigned char *f, const png_info *pi, const unsigned char **z,
                             unsigned char **copy, ww_error *err) {
    *copy = NULL;
    if (pi->idat_count == 1) {
        *z = f + pi->first_idat + 8;
        return WW_OK;
    }
    unsigned char *buf = malloc(pi->idat_total ? pi->idat_total : 1);
    if (!buf) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "png: out of memory");
    size_t at = 0, pos = pi->first_idat;
    while (at < pi->idat_total) { /* the walk checked every length up to IEND */
        uint32_t n = be32(f + pos);
        if (memcmp(f + pos + 4, "IDAT", 4) == 0) {
            memcpy(buf + at, f + pos + 8, n);
            at += n;
        }
        pos += (size_t)n + CHUNK_OVERHEAD;
    }
    *z = buf;
    *copy = buf;
    return WW_OK;
}

/* ---- unfiltering (section 9.2) ------------------------------------------------------------- */

/* section 9.4: whichever of left, above, upper left is nearest to left + above - upper left */
static unsigned paeth(unsigned a, unsigned b, unsigned c) {
    int p = (int)a + (int)b - (int)c;
    int pa = abs(p - (int)a), pb = abs(p - (int)b), pc = abs(p - (int)c);
    if (pa <= pb && pa <= pc) return a;
    return pb <= pc ? b : c;
}

/* one row of n bytes from in (after its filter byte) to out, with prev the unfiltered row above
 * (zeros for the first). out may lie before in in the same buffer: every byte is read before
 * anything at or past it is written */
static inline void unfilter_row(int type, unsigned char *out, const unsigned char *in,
                         const unsigned char *prev, size_t n, size_t bpp) {
    size_t i;
    switch (type) {
    case FILTER_NONE:
        memmove(out, in, n);
        break;
    case FILTER_SUB:
        for (i = 0; i < bpp; i++) out[i] = in[i];
        for (; i < n; i++) out[i] = (unsigned char)(in[i] + out[i - bpp]);
        break;
    case FILTER_UP:
        for (i = 0; i < n; i++) out[i] = (unsigned char)(in[i] + prev[i]);
        break;
    case FILTER_AVERAGE:
        for (i = 0; i < bpp; i++) out[i] = (unsigned char)(in[i] + (prev[i] >> 1));
        for (; i < n; i++) out[i] = (unsigned char)(in[i] + ((out[i - bpp] + prev[i]) >> 1));
        break;
    default: /* FILTER_PAETH */
        for (i = 0; i < bpp; i++) out[i] = (unsigned char)(in[i] + prev[i]);
        for (; i < n; i++)
            out[i] = (unsigned char)(in[i] + paeth(out[i - bpp], prev[i], prev[i - bpp]));
        break;
    }
}

/* 16-bit samples arrive most significant byte first */
static void swap16_row(unsigned char *row, size_t n) {
    for (size_t i = 0; i + 1 < n; i += 2) {
        uint16_t v = (uint16_t)(row[i] << 8 | row[i + 1]);
        memcpy(row + i, &v, 2);
    }
}

/* rows of 1 + stride bytes at buf become rows of stride bytes at buf, top to bottom */
static ww_result unfilter_all(unsigned char *buf, size_t stride, size_t height, size_t bpp,
                              int swap16, ww_error *err) {
    unsigned char *zero = calloc(stride, 1);
    if (!zero) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "png: out of memory");
    for (size_t y = 0; y < height; y++) {
        const unsigned char *in = buf + y * (stride + 1);
        unsigned char *out = buf + y * stride;
        int type = in[0];
        if (type >= FILTER_COUNT) {
            free(zero);
            return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: bad filter type %d in row %zu",
                                type, y);
        }
        const unsigned char *prev = y ? out - stride : zero;
        /* a constant bpp for the common pixel sizes lets the compiler unroll the per-pixel chains */
        switch (bpp) {
        case 3: unfilter_row(type, out, in + 1, prev, stride, 3); break;
        case 4: unfilter_row(type, out, in + 1, prev, stride, 4); break;
        default: unfilter_row(type, out, in + 1, prev, stride, bpp); break;
        }
        /* the row above is no longer needed as the filters' input */
        if (swap16 && y > 0) swap16_row(out - stride, stride);
    }
    if (swap16) swap16_row(buf + (height - 1) * stride, stride);
    free(zero);
    return WW_OK;
}

ww_result ww_png_decode(const unsigned char *file, size_t len, ww_png_pixels *out, ww_error *err) {
    memset(out, 0, sizeof *out);
    png_info pi;
    memset(&pi, 0, sizeof pi);
    ww_result r = walk_chunks(file, len, &pi, err);
    if (r != WW_OK) return r;

    size_t bpp = (size_t)pi.channels * (size_t)(pi.depth / 8);
    size_t stride = (size_t)pi.width * bpp, raw = (stride + 1) * pi.height; /* < 2^36 */
    if (raw > WW_PNG_MAX_BYTES)
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: %ux%u needs more than %zu bytes",
                            (unsigned)pi.width, (unsigned)pi.height, WW_PNG_MAX_BYTES);
    if (raw / DEFLATE_MAX_RATIO > pi.idat_total + ZLIB_OVERHEAD)
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0,
                            "png: IDAT too short: %zu bytes cannot hold %zu", pi.idat_total, raw);

    const unsigned char *z = NULL;
    unsigned char *copy;
    r = gather_idat(file, &pi, &z, &copy, err);
    if (r != WW_OK) return r;
    unsigned char *buf = ww_big_alloc(raw);
    if (!buf) {
        free(copy);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "png: out of memory (%zu bytes)", raw);
    }
    size_t got = 0;
    r = ww_zlib_inflate(z, pi.idat_total, buf, raw, &got, err);
    free(copy);
    if (r == WW_OK && got != raw)
        r = ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "png: IDAT too short: %zu of %zu bytes", got, raw);
    if (r == WW_OK) r = unfilter_all(buf, stride, pi.height, bpp, pi.depth == 16, err);
    if (r != WW_OK) {
        free(buf);
        return r;
    }
    out->width = (int)pi.width;
    out->height = (int)pi.height;
    out->channels = pi.channels;
    out->bits = pi.depth;
    out->px = buf;
    return WW_OK;
}
