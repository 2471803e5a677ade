/* make_seeds.c - writes the binary seed files of tests/fuzz/corpus/ (`make fuzz-seeds`): small
 * PNGs of every kind io/png_read.c takes and some it leaves to stb_image, zlib streams of each
 * block type for inflate, WAVs of each sample format, EXRs from our own writer. A few hundred
 * bytes each; the pixels and samples are arbitrary, the structure is what the fuzzers start
 * from. The JPEG and TGA seeds of corpus/image/ come from ImageMagick (tests/fuzz/corpus/README).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "io/image.h"
#include "io/wav.h"
#include "io/writers.h"

static const char *root;

static void put(const char *dir, const char *name, const void *data, size_t len) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s/%s", root, dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, len, f) != len || fclose(f) != 0) {
        fprintf(stderr, "make_seeds: cannot write %s\n", path);
        exit(1);
    }
}

/* ---- bytes ---------------------------------------------------------------------------------- */

typedef struct buf {
    unsigned char d[1 << 16];
    size_t n;
} buf;

static void b_bytes(buf *b, const void *p, size_t n) {
    memcpy(b->d + b->n, p, n);
    b->n += n;
}
static void b_be32(buf *b, uint32_t v) {
    unsigned char p[4] = {(unsigned char)(v >> 24), (unsigned char)(v >> 16), (unsigned char)(v >> 8),
                          (unsigned char)v};
    b_bytes(b, p, 4);
}
static void b_le(buf *b, uint64_t v, int n) {
    for (int i = 0; i < n; i++) b->d[b->n++] = (unsigned char)(v >> (8 * i));
}

/* arbitrary but fixed bytes */
static unsigned char byte_at(size_t i) { return (unsigned char)((i * 2654435761u) >> 13); }

/* ---- PNG ------------------------------------------------------------------------------------ */

static void chunk(buf *b, const char *type, const void *data, uint32_t n) {
    b_be32(b, n);
    size_t at = b->n;
    b_bytes(b, type, 4);
    if (n) b_bytes(b, data, n);
    b_be32(b, (uint32_t)crc32(0, b->d + at, n + 4));
}

typedef struct png_kind {
    const char *name;
    int colour, depth, w, h;
    int idats;           /* IDAT chunks the data is split into */
    const char *extra;   /* "plte", "trns", "text" */
} png_kind;

static void png(const char *dir, const png_kind *k) {
    static const int channels[7] = {1, 0, 3, 1, 2, 0, 4};
    size_t stride = ((size_t)k->w * (size_t)channels[k->colour] * (size_t)k->depth + 7) / 8;
    unsigned char raw[4096], z[8192];
    size_t rn = 0;
    for (int y = 0; y < k->h; y++) {
        raw[rn++] = (unsigned char)(y % 5); /* every filter type */
        for (size_t i = 0; i < stride; i++, rn++)
            raw[rn] = (unsigned char)(byte_at(rn) & (k->colour == 3 && k->depth == 8 ? 15 : 255));
    }
    uLongf zn = sizeof z;
    if (compress2(z, &zn, raw, rn, 9) != Z_OK) exit(1);

    buf *b = calloc(1, sizeof *b);
    b_bytes(b, "\x89PNG\r\n\x1a\n", 8);
    unsigned char ihdr[13] = {0, 0, 0, (unsigned char)k->w, 0, 0, 0, (unsigned char)k->h,
                              (unsigned char)k->depth, (unsigned char)k->colour, 0, 0, 0};
    chunk(b, "IHDR", ihdr, 13);
    if (k->colour == 3 || (k->extra && strcmp(k->extra, "plte") == 0)) {
        unsigned char pal[48];
        for (int i = 0; i < 48; i++) pal[i] = byte_at((size_t)i + 7);
        chunk(b, "PLTE", pal, 48);
    }
    if (k->extra && strcmp(k->extra, "trns") == 0) {
        unsigned char t[6] = {0, 1, 0, 2, 0, 3};
        chunk(b, "tRNS", t, k->colour == 3 ? 4 : k->colour == 0 ? 2 : 6);
    }
    if (k->extra && strcmp(k->extra, "text") == 0) chunk(b, "tEXt", "Comment\0seed", 12);
    size_t per = (zn + (size_t)k->idats - 1) / (size_t)k->idats;
    for (size_t at = 0; at < zn; at += per)
        chunk(b, "IDAT", z + at, (uint32_t)(zn - at < per ? zn - at : per));
    chunk(b, "IEND", NULL, 0);
    char name[64];
    snprintf(name, sizeof name, "%s.png", k->name);
    put(dir, name, b->d, b->n);
    free(b);
}

static const png_kind PNGS[] = {
    {"grey8", 0, 8, 7, 5, 1, NULL},      {"grey16", 0, 16, 7, 5, 1, NULL},
    {"ga8", 4, 8, 7, 5, 1, NULL},        {"ga16", 4, 16, 7, 5, 1, NULL},
    {"rgb8", 2, 8, 7, 5, 1, "plte"},     {"rgb16", 2, 16, 7, 5, 1, NULL},
    {"rgba8_3idat", 6, 8, 7, 5, 3, "text"}, {"rgba16", 6, 16, 7, 5, 1, NULL},
    {"grey1", 0, 1, 13, 5, 1, NULL},     {"grey2", 0, 2, 13, 5, 1, NULL},
    {"palette4_trns", 3, 4, 9, 5, 1, "trns"}, {"palette8", 3, 8, 7, 5, 2, NULL},
    {"rgb8_trns", 2, 8, 7, 5, 1, "trns"},
};

/* ---- zlib streams for inflate: a 3-byte capacity, then the stream ----------------------------- */

static void zstream(const char *name, const unsigned char *data, size_t n, int level, int strategy) {
    z_stream z;
    memset(&z, 0, sizeof z);
    if (deflateInit2(&z, level, Z_DEFLATED, 15, 8, strategy) != Z_OK) exit(1);
    buf *b = calloc(1, sizeof *b);
    b_le(b, n, 3);
    z.next_in = (Bytef *)data;
    z.avail_in = (uInt)n;
    z.next_out = b->d + 3;
    z.avail_out = (uInt)(sizeof b->d - 3);
    if (deflate(&z, Z_FINISH) != Z_STREAM_END) exit(1);
    b->n = 3 + z.total_out;
    deflateEnd(&z);
    put("inflate", name, b->d, b->n);
    free(b);
}

static void inflate_seeds(void) {
    unsigned char data[3000];
    const char *text = "the lake lies still; a stone skips, skips, skips and sinks. ";
    for (size_t i = 0; i < sizeof data; i++)
        data[i] = i < 1500 ? (unsigned char)text[i % strlen(text)] : byte_at(i / 3);
    zstream("stored", data, 700, 0, Z_DEFAULT_STRATEGY);
    zstream("fixed", data, 1200, 9, Z_FIXED);
    zstream("dynamic", data, sizeof data, 9, Z_DEFAULT_STRATEGY);
    zstream("huffman_only", data + 1500, 1000, 6, Z_HUFFMAN_ONLY);
    zstream("rle", data, 2000, 6, Z_RLE);
    zstream("empty", data, 0, 6, Z_DEFAULT_STRATEGY);
}

/* ---- WAV ------------------------------------------------------------------------------------ */

/* tag 1 PCM, 3 float; ext: WAVE_FORMAT_EXTENSIBLE with the tag in its sub-format; list: a LIST
 * chunk of odd size before the data */
static void wav(const char *name, int tag, int bits, int channels, int rate, int frames, int ext,
                int list) {
    buf *b = calloc(1, sizeof *b);
    int block = channels * bits / 8, data_len = frames * block, fmt_len = ext ? 40 : 16;
    b_bytes(b, "RIFF", 4);
    b_le(b, 0, 4); /* patched below */
    b_bytes(b, "WAVEfmt ", 8);
    b_le(b, (uint64_t)fmt_len, 4);
    b_le(b, ext ? 0xFFFE : (uint64_t)tag, 2);
    b_le(b, (uint64_t)channels, 2);
    b_le(b, (uint64_t)rate, 4);
    b_le(b, (uint64_t)(rate * block), 4);
    b_le(b, (uint64_t)block, 2);
    b_le(b, (uint64_t)bits, 2);
    if (ext) {
        static const unsigned char guid_tail[14] = {0x00, 0x00, 0x00, 0x00, 0x10, 0x00, 0x80,
                                                    0x00, 0x00, 0xAA, 0x00, 0x38, 0x9B, 0x71};
        b_le(b, 22, 2);
        b_le(b, (uint64_t)bits, 2);
        b_le(b, channels == 2 ? 3 : 4, 4);
        b_le(b, (uint64_t)tag, 2);
        b_bytes(b, guid_tail, 14);
    }
    if (list) {
        b_bytes(b, "LIST", 4);
        b_le(b, 5, 4);
        b_bytes(b, "INFO\0\0", 6); /* 5 bytes and the pad byte */
    }
    b_bytes(b, "data", 4);
    b_le(b, (uint64_t)data_len, 4);
    for (int i = 0; i < frames * channels; i++) {
        double s = 0.8 * sin(0.3 * i);
        if (tag == 3 && bits == 32) {
            float f = (float)s;
            uint32_t u;
            memcpy(&u, &f, 4);
            b_le(b, u, 4);
        } else if (tag == 3) {
            uint64_t u;
            memcpy(&u, &s, 8);
            b_le(b, u, 8);
        } else if (bits == 8) {
            b_le(b, (uint64_t)(128 + (int)(s * 127)), 1);
        } else {
            b_le(b, (uint64_t)(int64_t)(s * (double)(1ll << (bits - 1))), bits / 8);
        }
    }
    uint32_t riff = (uint32_t)(b->n - 8);
    for (int i = 0; i < 4; i++) b->d[4 + i] = (unsigned char)(riff >> (8 * i));
    put("wav", name, b->d, b->n);
    free(b);
}

static void wav_seeds(void) {
    wav("pcm8_mono_8k.wav", 1, 8, 1, 8000, 40, 0, 0);
    wav("pcm16_stereo_44k.wav", 1, 16, 2, 44100, 40, 0, 1);
    wav("pcm24_mono_96k.wav", 1, 24, 1, 96000, 40, 0, 0);
    wav("pcm32_stereo_22k.wav", 1, 32, 2, 22050, 30, 0, 0);
    wav("float32_mono_48k.wav", 3, 32, 1, 48000, 40, 0, 0);
    wav("float64_stereo_11k.wav", 3, 64, 2, 11025, 20, 0, 0);
    wav("ext_pcm16_stereo_48k.wav", 1, 16, 2, 48000, 40, 1, 1);
}

/* ---- EXR from our writer -------------------------------------------------------------------- */

static void exr(const char *name, int channels, const ww_exr_meta *meta) {
    ww_image im;
    if (ww_image_alloc(&im, 5, 3, channels, WW_PIX_F32) != 0) exit(1);
    for (int i = 0; i < 5 * 3 * channels; i++) im.f32[i] = (float)i / 7.0f - 0.5f;
    unsigned char *data;
    size_t len;
    ww_error err;
    if (ww_encode_exr(&im, meta, &data, &len, &err) != WW_OK) {
        fprintf(stderr, "make_seeds: %s\n", err.msg);
        exit(1);
    }
    put("exr", name, data, len);
    free(data);
    ww_image_free(&im);
}

static void exr_seeds(void) {
    exr("half_zip_rgba_meta.exr", 4,
        &(ww_exr_meta){.frame = 7, .time = 0.25, .scene = "lake", .renderer = "llvmpipe"});
    exr("float_none_rgb.exr", 3,
        &(ww_exr_meta){.float32 = 1, .compression = WW_EXR_COMP_NONE, .frame = -1, .time = NAN});
    exr("half_piz_rgba.exr", 4,
        &(ww_exr_meta){.compression = WW_EXR_COMP_PIZ, .frame = -1, .time = NAN});
    exr("float_zip_rgba.exr", 4, &(ww_exr_meta){.float32 = 1, .frame = 0, .time = NAN});
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: make_seeds CORPUS_DIR (tests/fuzz/corpus)\n");
        return 2;
    }
    root = argv[1];
    for (size_t i = 0; i < sizeof PNGS / sizeof PNGS[0]; i++) png("png", &PNGS[i]);
    inflate_seeds();
    wav_seeds();
    exr_seeds();
    return 0;
}
