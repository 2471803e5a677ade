/* stb_guard.c - the structural vet of core/stb_guard.h: a walk over a JPEG's markers or a PNG's
 * chunks, made the way stb_image 2.27 makes it, that refuses the inputs stb decodes unsafely
 * before stb sees them (the wrappers that call it live beside stb in core/stb_image_impl.c).
 */
#include "core/stb_guard.h"

#include <stdint.h>
#include <string.h>

#define JPEG_MAX_SIDE 32768   /* STBI_MAX_DIMENSIONS in core/stb_image_impl.c */
#define HUFF_MAX_CODES 256    /* entries of stb's stbi__huffman.values */
#define PNG_SIG_LEN 8
#define PNG_CHUNK_MAX 0x7fffffffu
#define PNG_IHDR_LEN 13

enum {
    M_SOF0 = 0xc0, M_SOF1 = 0xc1, M_SOF2 = 0xc2, M_DHT = 0xc4, M_RST0 = 0xd0, M_RST7 = 0xd7,
    M_SOI = 0xd8, M_EOI = 0xd9, M_SOS = 0xda, M_DQT = 0xdb, M_DNL = 0xdc, M_DRI = 0xdd,
    M_APP0 = 0xe0, M_APP15 = 0xef, M_COM = 0xfe,
    M_NONE = 0x100 /* no marker where one must be */
};

/* ---- JPEG (ITU T.81 annex B), in stb_image 2.27's order ------------------------------------- */

/* the reader, and which tables the segments so far defined: stb 2.27 decodes a scan with
 * whatever its Huffman and quantisation tables hold, defined or not (uninitialised memory: a
 * fast-AC entry read from it ran the bit count negative, a shift by 33 in
 * stbi__grow_buffer_unsafe); libjpeg refuses a scan whose tables were never defined, and so do we */
typedef struct rd {
    const unsigned char *p;
    size_t n, at;
    unsigned huff;       /* bit 4 * class + id: class 0 DC, 1 AC */
    unsigned quant;      /* bit id */
    int progressive;     /* SOF2 */
    int ncomp;
    unsigned comp_id[4], comp_tq[4];
} rd;

static size_t left(const rd *r) { return r->at < r->n ? r->n - r->at : 0; }
/* like stbi__get8: 0 past the end (the callers check what they need is there) */
static unsigned get8(rd *r) { return r->at < r->n ? r->p[r->at++] : (r->at++, 0u); }
static unsigned get16(rd *r) {
    unsigned hi = get8(r);
    return hi << 8 | get8(r);
}

/* stbi__get_marker: FF, any fill bytes (FF), then the code; M_NONE when the byte is not FF */
static unsigned get_marker(rd *r) {
    if (left(r) == 0) return M_NONE;
    if (get8(r) != 0xff) return M_NONE;
    unsigned x;
    do {
        if (left(r) == 0) return M_NONE;
        x = get8(r);
    } while (x == 0xff);
    return x;
}

/* a segment's length field (counting itself) and its body inside the file */
static const char *seg_len(rd *r, unsigned min, unsigned *len) {
    if (left(r) < 2) return "JPEG: truncated segment";
    *len = get16(r);
    if (*len < min) return "JPEG: segment length too short";
    if (left(r) < *len - 2) return "JPEG: segment runs past the end of the file";
    return NULL;
}

/* stbi__process_marker's segments: DRI, DQT, DHT, APPn, COM; anything else stb rejects */
static const char *segment(rd *r, unsigned m) {
    unsigned len;
    const char *why;
    switch (m) {
    case M_DRI:
        if ((why = seg_len(r, 4, &len))) return why;
        if (len != 4) return "JPEG: DRI of the wrong length";
        r->at += 2;
        return NULL;
    case M_DQT: {
        if ((why = seg_len(r, 2, &len))) return why;
        long L = (long)len - 2;
        while (L > 0) {
            unsigned q = get8(r), sixteen = q >> 4;
            if (sixteen > 1 || (q & 15) > 3) return "JPEG: bad DQT table";
            r->quant |= 1u << (q & 15);
            r->at += sixteen ? 128 : 64;
            L -= sixteen ? 129 : 65;
        }
        return L == 0 ? NULL : "JPEG: DQT tables do not fill the segment";
    }
    case M_DHT: {
        if ((why = seg_len(r, 2, &len))) return why;
        long L = (long)len - 2;
        while (L > 0) {
            if (L < 17) return "JPEG: DHT tables do not fill the segment";
            unsigned q = get8(r), n = 0;
            if ((q >> 4) > 1 || (q & 15) > 3) return "JPEG: bad DHT header";
            r->huff |= 1u << (4 * (q >> 4) + (q & 15));
            for (int i = 0; i < 16; i++) n += get8(r);
            /* stb builds the table before it checks anything: more codes overrun it */
            if (n > HUFF_MAX_CODES) return "JPEG: a Huffman table with more than 256 codes";
            r->at += n;
            L -= 17 + (long)n;
        }
        return L == 0 ? NULL : "JPEG: DHT tables do not fill the segment";
    }
    default:
        if ((m >= M_APP0 && m <= M_APP15) || m == M_COM) {
            if ((why = seg_len(r, 2, &len))) return why;
            r->at += len - 2;
            return NULL;
        }
        return "JPEG: unknown marker";
    }
}

/* stbi__process_frame_header; *ncomp the component count */
static const char *frame_header(rd *r, int *ncomp) {
    unsigned len;
    const char *why = seg_len(r, 11, &len);
    if (why) return why;
    unsigned p = get8(r), y = get16(r), x = get16(r), c = get8(r);
    if (p != 8) return "JPEG: not 8-bit";
    if (x == 0 || y == 0 || x > JPEG_MAX_SIDE || y > JPEG_MAX_SIDE) return "JPEG: bad size";
    if (c != 1 && c != 3 && c != 4) return "JPEG: bad component count";
    if (len != 8 + 3 * c) return "JPEG: SOF of the wrong length";
    for (unsigned i = 0; i < c; i++) {
        unsigned id = get8(r), hv = get8(r), tq = get8(r);
        if ((hv >> 4) < 1 || (hv >> 4) > 4 || (hv & 15) < 1 || (hv & 15) > 4 || tq > 3)
            return "JPEG: bad component sampling or table";
        r->comp_id[i] = id;
        r->comp_tq[i] = tq;
    }
    r->ncomp = (int)c;
    *ncomp = (int)c;
    return NULL;
}

/* stbi__process_scan_header, then the entropy-coded data up to the marker that ends it: stb's
 * bit reader (stbi__grow_buffer_unsafe) takes FF, fill bytes and 00 as a data byte, stops at
 * any other code and keeps it as the next marker; restart markers (D0..D7) belong to the scan */
static const char *scan(rd *r, int ncomp, unsigned *next) {
    unsigned len;
    const char *why = seg_len(r, 8, &len);
    if (why) return why;
    unsigned ns = get8(r);
    if (ns < 1 || ns > 4 || (int)ns > ncomp) return "JPEG: bad SOS component count";
    if (len != 6 + 2 * ns) return "JPEG: SOS of the wrong length";
    /* the tables this scan decodes with: a baseline scan both of each component's; a
     * progressive one the DC table in a DC scan (spectral start 0), the AC table otherwise */
    const unsigned char *sel = r->p + r->at;
    unsigned ss = sel[2 * ns];
    for (unsigned i = 0; i < ns; i++) {
        unsigned cs = sel[2 * i], td = sel[2 * i + 1] >> 4, ta = sel[2 * i + 1] & 15;
        int k = 0;
        while (k < r->ncomp && r->comp_id[k] != cs) k++;
        if (k == r->ncomp) return "JPEG: a scan names a component the frame has not";
        if (td > 3 || ta > 3) return "JPEG: bad SOS table";
        if (!(r->quant >> r->comp_tq[k] & 1))
            return "JPEG: a quantisation table used before it is defined";
        int dc = !r->progressive || ss == 0, ac = !r->progressive || ss != 0;
        if ((dc && !(r->huff >> td & 1)) || (ac && !(r->huff >> (4 + ta) & 1)))
            return "JPEG: a Huffman table used before it is defined";
    }
    r->at += len - 3;
    for (;;) {
        const unsigned char *ff = left(r) ? memchr(r->p + r->at, 0xff, left(r)) : NULL;
        if (!ff) return "JPEG: scan data without an end marker";
        r->at = (size_t)(ff - r->p) + 1;
        unsigned c;
        do {
            if (left(r) == 0) return "JPEG: scan data without an end marker";
            c = get8(r);
        } while (c == 0xff);
        if (c != 0 && (c < M_RST0 || c > M_RST7)) {
            *next = c;
            return NULL;
        }
    }
}

/* stbi__decode_jpeg_header: segments up to the frame header and the frame header itself; stb
 * scans over stray bytes between them (after the first), a byte at a time. *w, *h, *ncomp from
 * the frame header */
static const char *jpeg_header(rd *r, int *w, int *h, int *ncomp) {
    if (get_marker(r) != M_SOI) return "JPEG: no SOI";
    unsigned m = get_marker(r);
    for (;;) {
        if (m == M_SOF0 || m == M_SOF1 || m == M_SOF2) {
            r->progressive = m == M_SOF2;
            break;
        }
        const char *why = segment(r, m);
        if (why) return why;
        do {
            if (left(r) == 0) return "JPEG: no SOF";
            m = get_marker(r);
        } while (m == M_NONE);
    }
    size_t at = r->at;
    const char *why = frame_header(r, ncomp);
    if (!why) {
        /* the frame header: length (2), precision (1), height (2), width (2) */
        *h = (int)(r->p[at + 3] << 8 | r->p[at + 4]);
        *w = (int)(r->p[at + 5] << 8 | r->p[at + 6]);
    }
    return why;
}

static const char *vet_jpeg(const unsigned char *f, size_t len) {
    rd r = {.p = f, .n = len};
    int ncomp = 0, w, h;
    const char *why = jpeg_header(&r, &w, &h, &ncomp);
    if (why) return why;

    /* stbi__decode_jpeg_image: scans, tables between them, up to EOI; no stray bytes */
    unsigned m = get_marker(&r);
    while (m != M_EOI) {
        if (m == M_SOS) {
            if ((why = scan(&r, ncomp, &m))) return why;
            continue;
        }
        if (m == M_NONE) return "JPEG: expected a marker";
        if (m == M_DNL) {
            unsigned dl;
            if ((why = seg_len(&r, 4, &dl))) return why;
            if (dl != 4) return "JPEG: DNL of the wrong length";
            r.at += 2;
        } else if ((why = segment(&r, m))) {
            return why;
        }
        m = get_marker(&r);
    }
    return NULL;
}

/* ---- PNG (ISO 15948 section 5), as stbi__parse_png_file walks it ---------------------------- */

static uint32_t be32(const unsigned char *p) {
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static const unsigned char PNG_SIG[PNG_SIG_LEN] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

static const char *vet_png(const unsigned char *f, size_t len) {
    size_t pos = PNG_SIG_LEN;
    int first = 1, have_data = 0;
    for (;;) {
        if (len - pos < 12) return "PNG: truncated (no IEND chunk)";
        uint32_t n = be32(f + pos);
        const unsigned char *type = f + pos + 4;
        if (n > PNG_CHUNK_MAX || n > len - pos - 12) return "PNG: a chunk runs past the end of the file";
        int ihdr = memcmp(type, "IHDR", 4) == 0;
        if (first != ihdr) return first ? "PNG: first chunk is not IHDR" : "PNG: a second IHDR";
        if (ihdr && n != PNG_IHDR_LEN) return "PNG: IHDR of the wrong length";
        first = 0;
        if (ihdr) {
            /* the header's fields are stb's to check */
        } else if (memcmp(type, "IDAT", 4) == 0) {
            /* stb appends each IDAT to a buffer it allocates at the first non-empty one */
            if (n == 0 && !have_data) return "PNG: an empty IDAT chunk before the image data";
            have_data |= n > 0;
        } else if (memcmp(type, "IEND", 4) == 0) {
            return NULL;
        } else if (!(type[0] & 0x20u) && memcmp(type, "PLTE", 4) != 0 &&
                   memcmp(type, "CgBI", 4) != 0) {
            return "PNG: unknown critical chunk";
        }
        pos += (size_t)n + 12;
    }
}

const char *ww_image_vet(const unsigned char *f, size_t len) {
    if (!f) return "no data";
    if (len >= PNG_SIG_LEN && memcmp(f, PNG_SIG, PNG_SIG_LEN) == 0) return vet_png(f, len);
    /* what stbi__jpeg_test takes for a JPEG: its first marker is SOI */
    rd r = {.p = f, .n = len};
    if (get_marker(&r) == M_SOI) return vet_jpeg(f, len);
    return NULL;
}

int ww_image_header_size(const unsigned char *f, size_t len, int *w, int *h) {
    if (!f) return -1;
    /* PNG: the signature, then IHDR (length, type, width, height) */
    if (len >= PNG_SIG_LEN && memcmp(f, PNG_SIG, PNG_SIG_LEN) == 0) {
        if (len < PNG_SIG_LEN + 16 || be32(f + PNG_SIG_LEN) != PNG_IHDR_LEN ||
            memcmp(f + PNG_SIG_LEN + 4, "IHDR", 4) != 0)
            return -1;
        uint32_t x = be32(f + PNG_SIG_LEN + 8), y = be32(f + PNG_SIG_LEN + 12);
        if (x == 0 || y == 0 || x > (uint32_t)1 << 24 || y > (uint32_t)1 << 24) return -1;
        *w = (int)x;
        *h = (int)y;
        return 1;
    }
    rd r = {.p = f, .n = len};
    if (get_marker(&r) != M_SOI) return 0;
    r.at = 0;
    int ncomp;
    return jpeg_header(&r, w, h, &ncomp) ? -1 : 1;
}
