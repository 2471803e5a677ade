/* test_inflate.c - io/inflate.h and io/png_read.h: round trips through our deflate, stb_image_write's
 * entry point and gzip (dynamic Huffman codes), hand-built stored blocks and a distance of 32768,
 * truncated and bit-flipped streams, and PNGs of every supported kind decoded exactly as
 * stb_image decodes them, the fallback kinds, and broken files.
 */
#include <stdlib.h>
#include <string.h>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "core/rng.h"
#include "io/deflate.h"
#include "io/inflate.h"
#include "io/png_read.h"
#include "io/writers.h"
#include "test.h"

/* defined in io/png.c's copy of stb_image_write but declared only inside its implementation
 * section, so declared here as stb_image_write.h defines them */
unsigned char *stbi_zlib_compress(unsigned char *data, int data_len, int *out_len, int quality);
unsigned char *stbi_write_png_to_mem(const unsigned char *pixels, int stride_bytes, int x, int y,
                                     int n, int *out_len);

#define FLIP_COUNT 300
#define TEST_SEED 7

/* ---- data sets ------------------------------------------------------------------------------ */

typedef struct blob {
    unsigned char *p;
    size_t n;
} blob;

enum {
    SET_EMPTY, SET_ONE, SET_RUN, SET_OVERLAP, SET_RANDOM, SET_RAMP, SET_FAR, SET_CODES, SET_COUNT
};
static const char *SET_NAMES[SET_COUNT] = {"empty", "1 byte", "long run", "distances 1..9",
                                           "random", "ramp", "distance 32768",
                                           "every length, distances at both ends of every code"};

/* the first and last distance of each of deflate's 30 distance codes (RFC 1951 3.2.5) */
static const int CODE_ENDS[] = {1,     2,     3,     4,     5,     6,     7,     8,     9,
                                12,    13,    16,    17,    24,    25,    32,    33,    48,
                                49,    64,    65,    96,    97,    128,   129,   192,   193,
                                256,   257,   384,   385,   512,   513,   768,   769,   1024,
                                1025,  1536,  1537,  2048,  2049,  3072,  3073,  4096,  4097,
                                6144,  6145,  8192,  8193,  12288, 12289, 16384, 16385, 24576,
                                24577, 32768};

static blob make_set(int which) {
    ww_rng r;
    ww_rng_seed(&r, TEST_SEED, (uint64_t)which);
    blob b = {NULL, 0};
    size_t cap = 200000;
    b.p = malloc(cap);
    switch (which) {
    case SET_EMPTY: break;
    case SET_ONE: b.p[b.n++] = 'x'; break;
    case SET_RUN:
        memset(b.p, 'a', 100000);
        b.n = 100000;
        break;
    case SET_OVERLAP: /* a pattern of d random bytes repeated, for d = 1..9: copies that overlap */
        for (int d = 1; d <= 9; d++) {
            unsigned char pat[9];
            for (int i = 0; i < d; i++) pat[i] = (unsigned char)ww_rng_u32(&r);
            for (int k = 0; k < 700; k++) b.p[b.n++] = pat[k % d];
        }
        break;
    case SET_RANDOM:
        for (; b.n < 70000; b.n++) b.p[b.n] = (unsigned char)ww_rng_u32(&r);
        break;
    case SET_RAMP:
        for (; b.n < 150000; b.n++) b.p[b.n] = (unsigned char)(b.n * 7 / 5);
        break;
    case SET_CODES: /* 32 KiB of random bytes, then copies of every length from 3 to 258, each
                     * from a distance at one end of a distance code, each after a random byte */
        for (; b.n < 32768; b.n++) b.p[b.n] = (unsigned char)ww_rng_u32(&r);
        for (int len = 3, k = 0; len <= 258; len++, k++) {
            size_t dist = (size_t)CODE_ENDS[k % (int)(sizeof CODE_ENDS / sizeof *CODE_ENDS)];
            for (int i = 0; i < len; i++, b.n++) b.p[b.n] = b.p[b.n - dist];
            b.p[b.n++] = (unsigned char)ww_rng_u32(&r);
        }
        break;
    default: /* SET_FAR: 400 random bytes, 32368 others, the first 400 again */
        for (; b.n < 32768; b.n++) b.p[b.n] = (unsigned char)ww_rng_u32(&r);
        memcpy(b.p + b.n, b.p, 400);
        b.n += 400;
        break;
    }
    return b;
}

/* inflate z into a buffer of exactly want_n (+ slack) bytes and compare with want */
static void check_inflates_to(const unsigned char *z, size_t zn, const blob *want, const char *what) {
    size_t cap = want->n + 1;
    unsigned char *out = malloc(cap);
    size_t n = 0;
    ww_error err = {0};
    ww_result r = ww_zlib_inflate(z, zn, out, cap, &n, &err);
    ENSURE_MSG(r == WW_OK, "%s: %s", what, err.msg);
    ENSURE_MSG(n == want->n && (n == 0 || memcmp(out, want->p, n) == 0), "%s: %zu bytes, want %zu",
               what, n, want->n);
    free(out);
}

/* ---- a tiny bit writer for hand-built streams ----------------------------------------------- */

typedef struct bitw {
    unsigned char buf[70000];
    size_t n;
    uint32_t acc;
    int count;
} bitw;

static void put_bits(bitw *w, uint32_t v, int count) {
    for (int i = 0; i < count; i++) {
        w->acc |= ((v >> i) & 1u) << w->count;
        if (++w->count == 8) {
            w->buf[w->n++] = (unsigned char)w->acc;
            w->acc = 0;
            w->count = 0;
        }
    }
}

/* Huffman codes go most significant bit first */
static void put_code(bitw *w, uint32_t code, int count) {
    for (int i = count - 1; i >= 0; i--) put_bits(w, (code >> i) & 1u, 1);
}

static void flush_byte(bitw *w) {
    if (w->count) put_bits(w, 0, 8 - w->count);
}

static void put_bytes(bitw *w, const unsigned char *p, size_t n) {
    memcpy(w->buf + w->n, p, n);
    w->n += n;
}

static void put_adler(bitw *w, const unsigned char *p, size_t n) {
    flush_byte(w);
    uint32_t a = ww_adler32(1, p, n);
    unsigned char be[4] = {(unsigned char)(a >> 24), (unsigned char)(a >> 16), (unsigned char)(a >> 8),
                           (unsigned char)a};
    put_bytes(w, be, 4);
}

/* a stored block (RFC 1951 3.2.4) of n bytes */
static void put_stored(bitw *w, int final, const unsigned char *p, size_t n) {
    put_bits(w, (uint32_t)final, 1);
    put_bits(w, 0, 2);
    flush_byte(w);
    unsigned char hdr[4] = {(unsigned char)n, (unsigned char)(n >> 8), (unsigned char)~n,
                            (unsigned char)(~n >> 8)};
    put_bytes(w, hdr, 4);
    put_bytes(w, p, n);
}

static void zlib_header(bitw *w) {
    memset(w, 0, sizeof *w);
    w->buf[w->n++] = 0x78;
    w->buf[w->n++] = 0x01;
}

/* ---- inflate -------------------------------------------------------------------------------- */

TEST(inflate_round_trip_ours) {
    for (int s = 0; s < SET_COUNT; s++) {
        blob b = make_set(s);
        size_t zn = 0;
        unsigned char *z = ww_zlib_fast(b.p, b.n, &zn);
        ENSURE(z != NULL);
        if (z) check_inflates_to(z, zn, &b, SET_NAMES[s]);
        free(z);
        free(b.p);
    }
}

/* stb_image_write's zlib entry point (in this program it hands over to ww_zlib_fast, see
 * io/png.c, whose stored-block fallback is then unused: the link is what is checked here) */
TEST(inflate_round_trip_stb) {
    for (int s = 0; s < SET_COUNT; s++) {
        blob b = make_set(s);
        int zn = 0;
        unsigned char *z = stbi_zlib_compress(b.p, (int)b.n, &zn, 8);
        ENSURE(z != NULL);
        if (z) check_inflates_to(z, (size_t)zn, &b, SET_NAMES[s]);
        free(z);
        free(b.p);
    }
}

/* gzip's deflate (dynamic Huffman blocks, stored ones for random data) inside a zlib wrapper */
static unsigned char *gzip_to_zlib(const char *dir, const blob *b, int level, size_t *zn) {
    char in[600], gz[600], cmd[1400];
    snprintf(in, sizeof in, "%s/in.bin", dir);
    snprintf(gz, sizeof gz, "%s/in.gz", dir);
    FILE *f = fopen(in, "wb");
    if (!f) return NULL;
    if (b->n) fwrite(b->p, 1, b->n, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "gzip -n -%d -c '%s'", level, in);
    if (ww_test_run(cmd, gz, NULL) != 0) return NULL;
    size_t n = 0;
    char *g = ww_test_read_file(gz, &n);
    /* RFC 1952: a 10-byte header (no name with -n from stdin), the deflate data, CRC and size */
    if (!g || n < 18 || (unsigned char)g[3] != 0) {
        free(g);
        return NULL;
    }
    unsigned char *z = malloc(n + 8);
    size_t body = n - 18;
    uint32_t a = ww_adler32(1, b->p, b->n);
    z[0] = 0x78;
    z[1] = 0x01;
    memcpy(z + 2, g + 10, body);
    for (int i = 0; i < 4; i++) z[2 + body + (size_t)i] = (unsigned char)(a >> (24 - 8 * i));
    *zn = 2 + body + 4;
    free(g);
    return z;
}

TEST_PROC(inflate_round_trip_gzip_dynamic) {
    const char *d = ww_test_tmpdir("inflate_gzip");
    ENSURE(d != NULL);
    if (!d) return;
    char dir[512];
    snprintf(dir, sizeof dir, "%s", d);
    int dynamic = 0;
    for (int level = 1; level <= 9; level += 8)
        for (int s = 0; s < SET_COUNT; s++) {
            blob b = make_set(s);
            size_t zn = 0;
            unsigned char *z = gzip_to_zlib(dir, &b, level, &zn);
            ENSURE_MSG(z != NULL, "gzip -%d of %s", level, SET_NAMES[s]);
            if (z) {
                dynamic += ((z[2] >> 1) & 3) == 2; /* the first block's BTYPE */
                check_inflates_to(z, zn, &b, SET_NAMES[s]);
            }
            free(z);
            free(b.p);
        }
    /* gzip codes tiny inputs with the fixed codes and random bytes as stored blocks */
    ENSURE_MSG(dynamic >= 4, "only %d streams start with a dynamic block", dynamic);

    /* C source, many dynamic blocks */
    size_t n = 0;
    char *text = ww_test_read_file("src/io/png_read.c", &n);
    ENSURE(text != NULL);
    if (!text) return;
    blob b = {malloc(n * 40), 0};
    for (int k = 0; k < 40; k++, b.n += n) memcpy(b.p + b.n, text, n);
    for (size_t i = 0; i < b.n; i += 97) b.p[i] = (unsigned char)(b.p[i] + i / 97); /* no long runs */
    size_t zn = 0;
    unsigned char *z = gzip_to_zlib(dir, &b, 9, &zn);
    ENSURE(z != NULL);
    if (z) {
        ENSURE(((z[2] >> 1) & 3) == 2);
        check_inflates_to(z, zn, &b, "C source");
    }
    free(z);
    free(b.p);
    free(text);
}

TEST(inflate_stored_blocks) {
    blob b = make_set(SET_RANDOM);
    bitw *w = malloc(sizeof *w);
    zlib_header(w);
    put_stored(w, 0, b.p, 0);              /* a zero-length block */
    put_stored(w, 0, b.p, 65535);          /* the longest one */
    put_stored(w, 0, b.p + 65535, 0);
    put_stored(w, 1, b.p + 65535, 1000);
    put_adler(w, b.p, 66535);
    blob want = {b.p, 66535};
    check_inflates_to(w->buf, w->n, &want, "stored blocks");

    /* an empty stream of one empty stored block */
    zlib_header(w);
    put_stored(w, 1, b.p, 0);
    put_adler(w, b.p, 0);
    blob none = {b.p, 0};
    check_inflates_to(w->buf, w->n, &none, "one empty stored block");

    /* LEN and NLEN that disagree */
    w->buf[4] ^= 1;
    size_t n = 0;
    ww_error err = {0};
    unsigned char out[16];
    ENSURE_EQ_INT(ww_zlib_inflate(w->buf, w->n, out, sizeof out, &n, &err), WW_E_TYPE);
    free(w);
    free(b.p);
}

/* RFC 1951 3.2.6: fixed codes of a length-258 match (code 285) and a distance (code 29 + 13 extra
 * bits for 24577..32768), then end-of-block */
static void put_fixed_match(bitw *w, unsigned dist) {
    put_code(w, 0xc0u + (285 - 280), 8);
    put_code(w, 29, 5);
    put_bits(w, dist - 24577u, 13);
    put_code(w, 0, 7);
}

TEST(inflate_distance_32768) {
    blob b = make_set(SET_RANDOM);
    bitw *w = malloc(sizeof *w);
    zlib_header(w);
    put_stored(w, 0, b.p, 32768);
    put_bits(w, 1, 1); /* final, fixed Huffman */
    put_bits(w, 1, 2);
    put_fixed_match(w, 32768);
    unsigned char *want = malloc(32768 + 258);
    memcpy(want, b.p, 32768);
    memcpy(want + 32768, b.p, 258);
    put_adler(w, want, 32768 + 258);
    blob wb = {want, 32768 + 258};
    check_inflates_to(w->buf, w->n, &wb, "a match at distance 32768");

    /* the same match after only 32767 bytes reaches before the start */
    zlib_header(w);
    put_stored(w, 0, b.p, 32767);
    put_bits(w, 1, 1);
    put_bits(w, 1, 2);
    put_fixed_match(w, 32768);
    put_adler(w, want, 32767 + 258);
    unsigned char *out = malloc(40000);
    size_t n = 0;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_zlib_inflate(w->buf, w->n, out, 40000, &n, &err), WW_E_TYPE);
    ENSURE_MSG(strstr(err.msg, "distance 32768 before the start") != NULL, "%s", err.msg);
    free(out);
    free(want);
    free(w);
    free(b.p);
}

TEST(inflate_bad_headers) {
    unsigned char z[8] = {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01}; /* an empty stream */
    unsigned char out[4];
    size_t n = 1;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_zlib_inflate(z, sizeof z, out, sizeof out, &n, &err), WW_OK);
    ENSURE_EQ_INT(n, 0);
    unsigned char bad[8];
    memcpy(bad, z, 8);
    bad[0] = 0x79; /* CM 9 */
    ENSURE_EQ_INT(ww_zlib_inflate(bad, 8, out, sizeof out, &n, &err), WW_E_TYPE);
    memcpy(bad, z, 8);
    bad[1] = 0x9d; /* FCHECK */
    ENSURE_EQ_INT(ww_zlib_inflate(bad, 8, out, sizeof out, &n, &err), WW_E_TYPE);
    memcpy(bad, z, 8);
    bad[1] = 0xbb; /* FDICT, with a right FCHECK: 0x78bb % 31 == 0 */
    ENSURE_EQ_INT(ww_zlib_inflate(bad, 8, out, sizeof out, &n, &err), WW_E_TYPE);
    ENSURE(strstr(err.msg, "dictionary") != NULL);
    memcpy(bad, z, 8);
    bad[2] = 0x07; /* BTYPE 3 */
    ENSURE_EQ_INT(ww_zlib_inflate(bad, 8, out, sizeof out, &n, &err), WW_E_TYPE);
    memcpy(bad, z, 8);
    bad[7] = 0x02; /* Adler-32 */
    ENSURE_EQ_INT(ww_zlib_inflate(bad, 8, out, sizeof out, &n, &err), WW_E_TYPE);
    ENSURE(strstr(err.msg, "Adler-32") != NULL);
}

/* a short stream of each kind, cut at every length: never WW_OK, never out of bounds */
TEST_PROC(inflate_truncated) {
    const char *d = ww_test_tmpdir("inflate_truncated");
    char dir[512];
    snprintf(dir, sizeof dir, "%s", d ? d : ".");
    blob b = make_set(SET_OVERLAP);
    b.n = 900;
    size_t zn[2] = {0, 0};
    unsigned char *z[2] = {ww_zlib_fast(b.p, b.n, &zn[0]), gzip_to_zlib(dir, &b, 9, &zn[1])};
    unsigned char *out = malloc(b.n);
    for (int k = 0; k < 2; k++) {
        ENSURE(z[k] != NULL);
        if (!z[k]) continue;
        for (size_t len = 0; len < zn[k]; len++) {
            unsigned char *cut = malloc(len ? len : 1); /* exact size: ASan sees any overread */
            memcpy(cut, z[k], len);
            size_t n = 0;
            ww_error err = {0};
            ww_result r = ww_zlib_inflate(cut, len, out, b.n, &n, &err);
            ENSURE_MSG(r == WW_E_TYPE, "stream %d cut at %zu of %zu: %d", k, len, zn[k], (int)r);
            free(cut);
        }
        free(z[k]);
    }
    free(out);
    free(b.p);
}

/* seeded single-bit flips: WW_OK only with the right bytes (the Adler-32 still matched), else an
 * error; an output buffer of exactly the right size, so ASan sees any overrun */
TEST_PROC(inflate_bit_flips) {
    const char *d = ww_test_tmpdir("inflate_flips");
    char dir[512];
    snprintf(dir, sizeof dir, "%s", d ? d : ".");
    blob b = make_set(SET_OVERLAP);
    size_t zn[2] = {0, 0};
    unsigned char *z[2] = {ww_zlib_fast(b.p, b.n, &zn[0]), gzip_to_zlib(dir, &b, 9, &zn[1])};
    unsigned char *out = malloc(b.n);
    ww_rng r;
    ww_rng_seed(&r, TEST_SEED, 99);
    for (int k = 0; k < 2; k++) {
        ENSURE(z[k] != NULL);
        if (!z[k]) continue;
        int errors = 0;
        for (int i = 0; i < FLIP_COUNT; i++) {
            size_t bit = ww_rng_u32(&r) % (zn[k] * 8);
            unsigned char *f = malloc(zn[k]);
            memcpy(f, z[k], zn[k]);
            f[bit / 8] ^= (unsigned char)(1u << (bit % 8));
            size_t n = 0;
            ww_error err = {0};
            ww_result res = ww_zlib_inflate(f, zn[k], out, b.n, &n, &err);
            if (res == WW_OK)
                ENSURE_MSG(n == b.n && memcmp(out, b.p, n) == 0, "stream %d bit %zu: OK, wrong bytes",
                           k, bit);
            else
                ENSURE_EQ_INT(res, WW_E_TYPE);
            errors += res != WW_OK;
            free(f);
        }
        ENSURE_MSG(errors > FLIP_COUNT / 2, "stream %d: only %d of %d flips caught", k, errors,
                   FLIP_COUNT);
        free(z[k]);
    }
    free(out);
    free(b.p);
}

TEST(inflate_output_cap) {
    blob b = make_set(SET_RAMP);
    size_t zn = 0;
    unsigned char *z = ww_zlib_fast(b.p, b.n, &zn);
    unsigned char *out = malloc(b.n);
    size_t n = 0;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_zlib_inflate(z, zn, out, b.n - 1, &n, &err), WW_E_TYPE);
    ENSURE_MSG(strstr(err.msg, "output larger than") != NULL, "%s", err.msg);
    ENSURE_EQ_INT(ww_zlib_inflate(z, zn, out, 0, &n, &err), WW_E_TYPE);
    ENSURE_EQ_INT(ww_zlib_inflate(z, zn, out, b.n, &n, &err), WW_OK);
    ENSURE_EQ_INT(n, b.n);
    free(out);
    free(z);
    free(b.p);
}

/* ---- PNG ------------------------------------------------------------------------------------ */

#define PNG_W 61
#define PNG_H 47

/* a gradient with noise and a flat patch: every filter type has something to do */
static unsigned char *test_pixels(int ch) {
    unsigned char *px = malloc((size_t)PNG_W * PNG_H * (size_t)ch);
    ww_rng r;
    ww_rng_seed(&r, TEST_SEED, (uint64_t)ch);
    for (int y = 0; y < PNG_H; y++)
        for (int x = 0; x < PNG_W; x++)
            for (int c = 0; c < ch; c++) {
                int v = x * 4 + y * 3 + c * 40 + (int)(ww_rng_u32(&r) % 9);
                if (x > 40 && y > 30) v = 200;
                px[((size_t)y * PNG_W + (size_t)x) * (size_t)ch + (size_t)c] = (unsigned char)v;
            }
    return px;
}

/* ours and stb_image's decodes of a PNG in memory agree sample for sample */
static void check_png_like_stb(const unsigned char *png, size_t len, int want_ch, int want_bits,
                               const char *what) {
    ww_png_pixels im;
    ww_error err = {0};
    ww_result r = ww_png_decode(png, len, &im, &err);
    ENSURE_MSG(r == WW_OK, "%s: %s", what, err.msg);
    if (r != WW_OK) return;
    ENSURE_EQ_INT(im.channels, want_ch);
    ENSURE_EQ_INT(im.bits, want_bits);
    int w = 0, h = 0, n = 0;
    stbi_set_flip_vertically_on_load(0);
    void *ref = want_bits == 16 ? (void *)stbi_load_16_from_memory(png, (int)len, &w, &h, &n, 0)
                                : (void *)stbi_load_from_memory(png, (int)len, &w, &h, &n, 0);
    ENSURE(ref != NULL);
    if (ref) {
        ENSURE_EQ_INT(im.width, w);
        ENSURE_EQ_INT(im.height, h);
        ENSURE_EQ_INT(im.channels, n);
        size_t bytes = (size_t)w * (size_t)h * (size_t)n * (size_t)(want_bits / 8);
        ENSURE_MSG(im.width == w && im.height == h && memcmp(im.px, ref, bytes) == 0,
                   "%s: pixels differ from stb_image's", what);
    }
    stbi_image_free(ref);
    free(im.px);
}

/* stb_image_write with each filter type forced and with its adaptive choice (-1); the setting is
 * a library global that io/png.c pins for our frames, so it is put back */
TEST(png_read_8bit_stb_filters) {
    int saved = stbi_write_force_png_filter;
    for (int ch = 1; ch <= 4; ch++) {
        unsigned char *px = test_pixels(ch);
        for (int filter = -1; filter <= 4; filter++) {
            stbi_write_force_png_filter = filter;
            int len = 0;
            unsigned char *png = stbi_write_png_to_mem(px, PNG_W * ch, PNG_W, PNG_H, ch, &len);
            ENSURE(png != NULL);
            char what[64];
            snprintf(what, sizeof what, "%d channels, filter %d", ch, filter);
            if (png) check_png_like_stb(png, (size_t)len, ch, 8, what);
            free(png);
        }
        free(px);
    }
    stbi_write_force_png_filter = saved;
}

/* through io/png.c's frame writer (RGB8 and RGBA8): the pixels come back as written */
TEST(png_read_our_writer) {
    for (int ch = 3; ch <= 4; ch++) {
        ww_image im;
        ENSURE(ww_image_alloc(&im, PNG_W, PNG_H, ch, WW_PIX_U8) == 0);
        unsigned char *px = test_pixels(ch);
        memcpy(im.u8, px, (size_t)PNG_W * PNG_H * (size_t)ch);
        unsigned char *png = NULL;
        size_t len = 0;
        ww_error err = {0};
        ENSURE_EQ_INT(ww_encode_png(&im, &png, &len, &err), WW_OK);
        check_png_like_stb(png, len, ch, 8, "io/png.c");
        ww_png_pixels out;
        if (ww_png_decode(png, len, &out, &err) == WW_OK) {
            ENSURE(memcmp(out.px, px, (size_t)PNG_W * PNG_H * (size_t)ch) == 0);
            free(out.px);
        }
        free(png);
        free(px);
        ww_image_free(&im);
    }
}

/* an 8-bit RGB(A) source PNG on disk, for ImageMagick */
static int write_source_png(const char *path, int ch) {
    unsigned char *px = test_pixels(ch);
    int ok = 0, len = 0;
    unsigned char *png = stbi_write_png_to_mem(px, PNG_W * ch, PNG_W, PNG_H, ch, &len);
    FILE *f = png ? fopen(path, "wb") : NULL;
    if (f) {
        ok = fwrite(png, 1, (size_t)len, f) == (size_t)len;
        fclose(f);
    }
    free(png);
    free(px);
    return ok;
}

/* ImageMagick's 16-bit PNGs (libpng, dynamic Huffman, adaptive filters); a blur makes the samples
 * use all 16 bits. IM 7's command is `magick` (its `convert` is a deprecated alias that some
 * installs leave out), IM 6's `convert`; the options mean the same to both */
TEST_PROC(png_read_16bit_imagemagick) {
    const char *im = ww_test_have_tool("magick") ? "magick" : "convert";
    REQUIRE_TOOL(im);
    const char *d = ww_test_tmpdir("png_read_16");
    ENSURE(d != NULL);
    if (!d) return;
    char dir[512], src[600], dst[600], cmd[1600];
    snprintf(dir, sizeof dir, "%s", d);
    snprintf(src, sizeof src, "%s/src.png", dir);
    ENSURE(write_source_png(src, 4));
    static const struct {
        const char *args;
        int ch;
    } kinds[] = {
        {"-alpha off -depth 16 -blur 0x1 PNG48:", 3},
        {"-depth 16 -blur 0x1 PNG64:", 4},
        {"-alpha off -colorspace gray -depth 16 -blur 0x1 -define png:color-type=0 "
         "-define png:bit-depth=16 PNG:", 1},
        {"-colorspace gray -depth 16 -blur 0x1 -define png:color-type=4 -define png:bit-depth=16 "
         "PNG:", 2},
    };
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        snprintf(dst, sizeof dst, "%s/out%zu.png", dir, k);
        char *colon = strrchr(kinds[k].args, ' ');
        snprintf(cmd, sizeof cmd, "%s '%s' %.*s %s'%s'", im, src, (int)(colon - kinds[k].args),
                 kinds[k].args, colon + 1, dst);
        ENSURE_MSG(ww_test_run(cmd, NULL, NULL) == 0, "%s", cmd);
        size_t len = 0;
        unsigned char *png = (unsigned char *)ww_test_read_file(dst, &len);
        ENSURE(png != NULL);
        if (png) check_png_like_stb(png, len, kinds[k].ch, 16, kinds[k].args);
        free(png);
    }
}

/* palette, interlaced and 1-bit files are valid but left to stb_image: WW_E_RANGE */
TEST_PROC(png_read_fallback_kinds) {
    const char *d = ww_test_tmpdir("png_read_fallback");
    ENSURE(d != NULL);
    if (!d) return;
    char dir[512], src[600], dst[600], cmd[1600];
    snprintf(dir, sizeof dir, "%s", d);
    snprintf(src, sizeof src, "%s/src.png", dir);
    ENSURE(write_source_png(src, 3));
    static const char *const kinds[] = {"PNG8:", "-interlace PNG PNG24:",
                                        "-colorspace gray -threshold 50% -depth 1 PNG:"};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        snprintf(dst, sizeof dst, "%s/out%zu.png", dir, k);
        const char *colon = strrchr(kinds[k], ' ');
        const char *fmt = colon ? colon + 1 : kinds[k];
        int pre = colon ? (int)(colon - kinds[k]) : 0;
        snprintf(cmd, sizeof cmd, "convert '%s' %.*s %s'%s'", src, pre, kinds[k], fmt, dst);
        ENSURE_MSG(ww_test_run(cmd, NULL, NULL) == 0, "%s", cmd);
        size_t len = 0;
        unsigned char *png = (unsigned char *)ww_test_read_file(dst, &len);
        ENSURE(png != NULL);
        if (!png) continue;
        ww_png_pixels im;
        ww_error err = {0};
        ENSURE_MSG(ww_png_decode(png, len, &im, &err) == WW_E_RANGE, "%s: %s", kinds[k], err.msg);
        ENSURE(im.px == NULL);
        free(png);
    }
}


/* set the CRC of the chunk at pos after editing it */
static void fix_crc(unsigned char *png, size_t pos) {
    size_t n = (size_t)png[pos] << 24 | (size_t)png[pos + 1] << 16 | (size_t)png[pos + 2] << 8 | png[pos + 3];
    uint32_t c = ww_test_crc32(png + pos + 4, n + 4);
    for (int i = 0; i < 4; i++) png[pos + 8 + n + (size_t)i] = (unsigned char)(c >> (24 - 8 * i));
}

#define IHDR_POS 8 /* the first chunk, after the signature */

static ww_result decode_copy(const unsigned char *png, size_t len, ww_error *err) {
    unsigned char *c = malloc(len ? len : 1); /* exact size: ASan sees any overread */
    memcpy(c, png, len);
    ww_png_pixels im;
    ww_result r = ww_png_decode(c, len, &im, err);
    free(im.px);
    free(c);
    return r;
}

TEST(png_read_broken_files) {
    unsigned char *px = test_pixels(3);
    int ilen = 0;
    int saved = stbi_write_force_png_filter;
    stbi_write_force_png_filter = 4;
    unsigned char *png = stbi_write_png_to_mem(px, PNG_W * 3, PNG_W, PNG_H, 3, &ilen);
    stbi_write_force_png_filter = saved;
    ENSURE(png != NULL);
    if (!png) return;
    size_t len = (size_t)ilen;
    ww_error err = {0};
    ENSURE_EQ_INT(decode_copy(png, len, &err), WW_OK);
    unsigned char *b = malloc(len);

    /* a bad CRC: one byte of pixel data changed */
    memcpy(b, png, len);
    b[len / 2] ^= 0x10;
    ENSURE_EQ_INT(decode_copy(b, len, &err), WW_E_TYPE);
    ENSURE_MSG(strstr(err.msg, "CRC") != NULL, "%s", err.msg);

    /* no IEND: the file cut before it */
    ENSURE_EQ_INT(decode_copy(png, len - 12, &err), WW_E_TYPE);

    /* an IDAT too short: the header claims more rows than the data hold */
    memcpy(b, png, len);
    b[IHDR_POS + 8 + 7] = PNG_H + 5; /* height, low byte */
    fix_crc(b, IHDR_POS);
    ENSURE_EQ_INT(decode_copy(b, len, &err), WW_E_TYPE);
    ENSURE_MSG(strstr(err.msg, "IDAT too short") != NULL, "%s", err.msg);

    /* a zero width */
    memcpy(b, png, len);
    memset(b + IHDR_POS + 8, 0, 4);
    fix_crc(b, IHDR_POS);
    ENSURE_EQ_INT(decode_copy(b, len, &err), WW_E_TYPE);

    /* a hostile size: 32768 x 32768 RGB16 */
    memcpy(b, png, len);
    b[IHDR_POS + 8 + 1] = 0x80;
    b[IHDR_POS + 8 + 2] = 0;
    b[IHDR_POS + 8 + 3] = 0;
    b[IHDR_POS + 8 + 5] = 0x80;
    b[IHDR_POS + 8 + 6] = 0;
    b[IHDR_POS + 8 + 7] = 0;
    b[IHDR_POS + 8 + 8] = 16;
    fix_crc(b, IHDR_POS);
    ENSURE_EQ_INT(decode_copy(b, len, &err), WW_E_TYPE);

    /* an unknown critical chunk in place of IEND */
    memcpy(b, png, len);
    memcpy(b + len - 8, "ZZZZ", 4);
    fix_crc(b, len - 12);
    ENSURE_EQ_INT(decode_copy(b, len, &err), WW_E_TYPE);
    /* ... an unknown ancillary one is skipped, but then IEND is missing */
    b[len - 8] = 'z';
    fix_crc(b, len - 12);
    ENSURE_EQ_INT(decode_copy(b, len, &err), WW_E_TYPE);
    ENSURE_MSG(strstr(err.msg, "IEND") != NULL, "%s", err.msg);

    /* every truncation: never WW_OK, never out of bounds */
    for (size_t n = 0; n < len; n++) ENSURE_MSG(decode_copy(png, n, &err) == WW_E_TYPE, "cut at %zu", n);
    free(b);
    free(png);
    free(px);
}

/* a PNG of 8-bit RGB rows (each with its filter byte) around one IDAT of ww_zlib_fast's */
static unsigned char *png_from_rows(const unsigned char *rows, size_t raw, size_t *len) {
    size_t zn = 0;
    unsigned char *z = ww_zlib_fast(rows, raw, &zn);
    *len = 33 + 12 + zn + 12;
    unsigned char *png = malloc(*len);
    static const unsigned char head[33] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                                           0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                           0, 0, 0, PNG_W, 0, 0, 0, PNG_H, 8, 2, 0, 0, 0};
    memcpy(png, head, 33);
    fix_crc(png, IHDR_POS);
    size_t p = 33;
    for (int i = 0; i < 4; i++) png[p + (size_t)i] = (unsigned char)(zn >> (24 - 8 * i));
    memcpy(png + p + 4, "IDAT", 4);
    memcpy(png + p + 8, z, zn);
    fix_crc(png, p);
    p += 12 + zn;
    memset(png + p, 0, 4);
    memcpy(png + p + 4, "IEND", 4);
    fix_crc(png, p);
    free(z);
    return png;
}

/* a bad filter type byte (5) in row 3, behind a right zlib stream and CRCs; with 4 (Paeth) the
 * same file decodes */
TEST(png_read_bad_filter_type) {
    size_t stride = PNG_W * 3, raw = (stride + 1) * PNG_H, len = 0;
    unsigned char *rows = calloc(raw, 1);
    rows[3 * (stride + 1)] = 5;
    unsigned char *png = png_from_rows(rows, raw, &len);
    ww_error err = {0};
    ENSURE_EQ_INT(decode_copy(png, len, &err), WW_E_TYPE);
    ENSURE_MSG(strstr(err.msg, "filter type 5 in row 3") != NULL, "%s", err.msg);
    free(png);
    rows[3 * (stride + 1)] = 4;
    png = png_from_rows(rows, raw, &len);
    ENSURE_EQ_INT(decode_copy(png, len, &err), WW_OK);
    free(png);
    free(rows);
}
