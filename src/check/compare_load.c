/* compare_load.c - the images of `compare`: PNG (io/png_read.h, else stb_image: 8/16-bit,
 * grey/GA/RGB/RGBA, palette, interlaced) and EXR (io/writers.h), told apart by their first
 * bytes, held as RGB bytes (8-bit without alpha) or float RGBA with the colour premultiplied by
 * alpha, and hashed for the exact-match fast path.
 */
#include "check/compare_impl.h"

#include <limits.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include <stb/stb_image.h>

#include "core/bigalloc.h"
#include "core/hash.h"
#include "core/stb_guard.h"
#include "io/png_read.h"
#include "io/writers.h"

static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
static const unsigned char exr_magic[4] = {0x76, 0x2f, 0x31, 0x01}; /* OpenEXR file layout */
#define MAX_16BIT 65535.0f
#define MAX_8BIT 255.0f

/* a pixel buffer freed with free(), on huge pages when big (core/bigalloc.h): `waterworld
 * compare` of a 1280x720 pair took 0.30 s without, 0.19 s with (perf stat -r 8, 10540 page
 * faults against 3354) */
static float *alloc_pixels(size_t npx) { return ww_big_alloc(npx * 4 * sizeof(float)); }

void ww_cmp_image_free(ww_cmp_image *im) {
    free(im->rgb8);
    free(im->rgba);
    memset(im, 0, sizeof *im);
}

float ww_cmp_level(unsigned v) { return (float)v / MAX_8BIT; }

void ww_cmp_pixel(const ww_cmp_image *im, size_t i, float px[4]) {
    if (im->rgb8) {
        const unsigned char *p = im->rgb8 + 3 * i;
        px[0] = ww_cmp_level(p[0]), px[1] = ww_cmp_level(p[1]), px[2] = ww_cmp_level(p[2]);
        px[3] = 1.0f;
    } else {
        memcpy(px, im->rgba + 4 * i, 4 * sizeof(float));
    }
}

/* FNV-1a over 64-bit words in four interleaved lanes, word j into lane j % 4 (the byte-wise
 * ww_hash_bytes costs 15 ms on a 1280x720 float image; one chain of word multiplies, 3 ms; four,
 * under 1 ms), the bytes after the last whole word byte-wise; only a fast filter: equal hashes
 * are confirmed pixel by pixel */
static uint64_t image_hash(const ww_cmp_image *im) {
    const uint64_t prime = 0x100000001b3ULL;
    int head[4] = {im->width, im->height, im->hdr, im->rgb8 != NULL};
    uint64_t h0 = ww_hash_bytes(WW_HASH_INIT, head, sizeof head);
    uint64_t lane[4] = {h0, h0 ^ 1, h0 ^ 2, h0 ^ 3};
    size_t npx = (size_t)im->width * (size_t)im->height;
    const unsigned char *p = im->rgb8 ? im->rgb8 : (const unsigned char *)im->rgba;
    size_t n = im->rgb8 ? 3 * npx : 4 * sizeof(float) * npx, words = n / 8;
    for (size_t j = 0; j < words; j++) {
        uint64_t w;
        memcpy(&w, p + 8 * j, sizeof w);
        lane[j & 3] = (lane[j & 3] ^ w) * prime;
    }
    uint64_t h = ww_hash_bytes(h0, lane, sizeof lane);
    return ww_hash_bytes(h, p + 8 * words, n - 8 * words);
}

ww_result ww_cmp_to_rgba(const ww_cmp_image *in, ww_cmp_image *out, ww_error *err) {
    *out = *in;
    out->rgb8 = NULL;
    size_t npx = (size_t)in->width * (size_t)in->height;
    out->rgba = alloc_pixels(npx);
    if (!out->rgba)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "compare: out of memory");
    for (size_t i = 0; i < npx; i++) ww_cmp_pixel(in, i, out->rgba + 4 * i);
    out->hash = image_hash(out);
    return WW_OK;
}

/* colour times alpha (ImageMagick and OpenImageIO compare premultiplied colour) */
static void premultiply(float *p, size_t npx) {
    for (size_t i = 0; i < npx; i++, p += 4) {
        p[0] *= p[3];
        p[1] *= p[3];
        p[2] *= p[3];
    }
}

/* decoded samples (w x h x comp, 8-bit or 16-bit host order, rows top first; taken over: freed
 * here or kept) into one of the two layouts: 8-bit RGB kept as rgb8, 8-bit grey spread to it;
 * anything with alpha or 16 bits spread to float RGBA (grey to R, G, B, a missing alpha 1;
 * v / (2^bits - 1) is the same float for an 8-bit level and its 16-bit twin, v * 257) */
static ww_result from_samples(const char *path, int w, int h, int comp, int is16, void *px,
                              ww_cmp_image *out, ww_error *err) {
    size_t npx = (size_t)w * (size_t)h;
    out->width = w;
    out->height = h;
    out->channels = comp;
    out->bits = is16 ? 16 : 8;
    if (!is16 && comp == 3) {
        out->rgb8 = px;
        return WW_OK;
    }
    const unsigned char *s8 = px;
    if (!is16 && comp == 1) {
        out->rgb8 = ww_big_alloc(3 * npx);
        if (out->rgb8)
            for (size_t i = 0; i < npx; i++) memset(out->rgb8 + 3 * i, s8[i], 3);
    } else {
        out->rgba = alloc_pixels(npx);
        if (out->rgba) {
            float lut[256];
            for (int v = 0; v < 256; v++) lut[v] = (float)v / MAX_8BIT;
            const uint16_t *s16 = px;
            int grey = comp < 3, alpha = comp == 2 || comp == 4;
            for (size_t i = 0; i < npx; i++) {
                float *d = out->rgba + 4 * i;
                for (int c = 0; c < comp; c++) {
                    size_t k = i * (size_t)comp + (size_t)c;
                    d[grey && c == 1 ? 3 : c] = is16 ? (float)s16[k] / MAX_16BIT : lut[s8[k]];
                }
                if (grey) d[1] = d[2] = d[0];
                if (!alpha) d[3] = 1.0f;
            }
            if (alpha) premultiply(out->rgba, npx);
        }
    }
    free(px);
    if (!out->rgb8 && !out->rgba)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot read '%s': out of memory", path);
    return WW_OK;
}

/* a PNG: our reader (io/png_read.h) for what it reads, stb_image for the rest (palette,
 * interlaced, under 8 bits, colour keys) and for what ours rejects, so a file stb_image reads is
 * never refused; a broken file is named with stb_image's reason */
static ww_result load_png(const char *path, const unsigned char *file, size_t len,
                          ww_cmp_image *out, ww_error *err) {
    ww_png_pixels pp;
    ww_error mine = {0};
    ww_result r = ww_png_decode(file, len, &pp, &mine);
    if (r == WW_OK) return from_samples(path, pp.width, pp.height, pp.channels, pp.bits == 16, pp.px, out, err);
    if (r == WW_E_NOMEM) {
        if (err) *err = mine;
        return r;
    }
    int w, h, comp;
    if (len > INT_MAX || !ww_stbi_info_from_memory(file, (int)len, &w, &h, &comp))
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "'%s': broken PNG: %s", path,
                            len > INT_MAX ? "file too large" : stbi_failure_reason());
    if (w > WW_FRAME_MAX_SIDE || h > WW_FRAME_MAX_SIDE)
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                            "'%s' is %dx%d: expected at most %d on a side (the largest frame)",
                            path, w, h, WW_FRAME_MAX_SIDE);
    int is16 = ww_stbi_is_16_bit_from_memory(file, (int)len);
    /* decoded as stored: asking stb for RGBA would cost one more image-sized buffer */
    void *px = is16 ? (void *)ww_stbi_load_16_from_memory(file, (int)len, &w, &h, &comp, 0)
                    : (void *)ww_stbi_load_from_memory(file, (int)len, &w, &h, &comp, 0);
    if (!px || comp < 1 || comp > 4) {
        stbi_image_free(px);
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "'%s': broken PNG: %s", path,
                            px ? "unexpected channel count" : stbi_failure_reason());
    }
    return from_samples(path, w, h, comp, is16, px, out, err);
}

/* the channel list of an EXR header (OpenEXR file layout: attributes name\0 type\0 size value,
 * "chlist" entries name\0 pixel_type(i32) pLinear(u8) reserved(3) xSampling(i32)
 * ySampling(i32)): whether A is there and the widest of R, G, B, A (16 half, 32 float) */
static void exr_channels(const unsigned char *f, size_t len, int *channels, int *bits) {
    *channels = 3;
    *bits = 16;
    size_t p = 8;
    while (p < len && f[p]) {
        const char *name = (const char *)f + p;
        const unsigned char *nz = memchr(f + p, 0, len - p);
        if (!nz) return;
        const char *type = (const char *)nz + 1;
        const unsigned char *tz = memchr(nz + 1, 0, len - (size_t)(nz + 1 - f));
        if (!tz || (size_t)(tz + 5 - f) > len) return;
        uint32_t size = (uint32_t)tz[1] | (uint32_t)tz[2] << 8 | (uint32_t)tz[3] << 16 |
                        (uint32_t)tz[4] << 24;
        size_t v = (size_t)(tz + 5 - f);
        if (size > len - v) return;
        if (strcmp(name, "channels") == 0 && strcmp(type, "chlist") == 0) {
            size_t q = v, end = v + size;
            while (q < end && f[q]) {
                const unsigned char *cz = memchr(f + q, 0, end - q);
                if (!cz || (size_t)(cz + 17 - f) > end) return;
                const char *ch = (const char *)f + q;
                int one = strlen(ch) == 1 && strchr("RGBA", ch[0]);
                if (one && ch[0] == 'A') *channels = 4;
                if (one && cz[1] == 2) *bits = 32; /* pixel type 2: FLOAT */
                q = (size_t)(cz + 17 - f);
            }
            return;
        }
        p = v + size;
    }
}

static ww_result load_exr(const char *path, const unsigned char *file, size_t len,
                          ww_cmp_image *out, ww_error *err) {
    ww_image im;
    ww_result r = ww_read_exr(path, &im, err);
    if (r != WW_OK) {
        ww_image_free(&im);
        if (r != WW_E_SYNTAX) return r;
        if (err) err->code = WW_E_TYPE; /* a broken EXR is "not an image we read" */
        return WW_E_TYPE;
    }
    WW_ASSERT(im.type == WW_PIX_F32 && im.channels == 4);
    out->rgba = im.f32; /* ownership moves: freed with free() as ww_image_free would */
    out->width = im.width;
    out->height = im.height;
    out->hdr = 1;
    exr_channels(file, len, &out->channels, &out->bits);
    return WW_OK;
}

/* stb's run-time settings, pinned before any decode (rows top first, no conversions) */
void ww_cmp_pin_stb(void) {
    stbi_set_flip_vertically_on_load(0);
    stbi_set_unpremultiply_on_load(0);
    stbi_convert_iphone_png_to_rgb(0);
}

/* the loader proper: reads no global that it writes, so two may run at once */
ww_result ww_cmp_load_one(const char *path, ww_cmp_image *out, ww_error *err) {
    memset(out, 0, sizeof *out);
    unsigned char *file;
    size_t len;
    ww_result r = ww_read_file(path, &file, &len, err);
    if (r != WW_OK) return r;
    if (len >= sizeof png_magic && memcmp(file, png_magic, sizeof png_magic) == 0)
        r = load_png(path, file, len, out, err);
    else if (len >= sizeof exr_magic && memcmp(file, exr_magic, sizeof exr_magic) == 0)
        r = load_exr(path, file, len, out, err);
    else
        r = ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "'%s': not a PNG or EXR image", path);
    free(file);
    if (r == WW_OK) out->hash = image_hash(out);
    return r;
}

ww_result ww_cmp_load(const char *path, ww_cmp_image *out, ww_error *err) {
    ww_cmp_pin_stb();
    return ww_cmp_load_one(path, out, err);
}

/* one load on a worker thread */
typedef struct load_job {
    const char *path;
    ww_cmp_image *im;
    ww_error err;
    ww_result r;
} load_job;

static void *load_thread(void *arg) {
    load_job *j = arg;
    j->r = ww_cmp_load_one(j->path, j->im, &j->err);
    return NULL;
}

ww_result ww_cmp_load_pair(const char *path_a, const char *path_b, ww_cmp_image *a,
                           ww_cmp_image *b, ww_error *err) {
    ww_cmp_pin_stb();

    /* b on a second thread, a on this one; without a thread, one after the other */
    load_job jb = {.path = path_b, .im = b};
    pthread_t t;
    int threaded = pthread_create(&t, NULL, load_thread, &jb) == 0;
    ww_result r = ww_cmp_load_one(path_a, a, err);
    if (threaded)
        pthread_join(t, NULL);
    else
        load_thread(&jb);
    if (r == WW_OK && jb.r != WW_OK) {
        r = jb.r;
        if (err) *err = jb.err;
    }
    if (r != WW_OK) {
        ww_cmp_image_free(a);
        ww_cmp_image_free(b);
    }
    return r;
}
