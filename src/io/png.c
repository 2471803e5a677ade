/* png.c - PNG frames through stb_image_write (encode into memory, then one atomic write) and
 * stb_image (decode from memory; its implementation lives in core/stb_image_impl.c, shared with
 * the scene's asset loader). stb_image_write's global settings are pinned once per process
 * (pthread_once, so encoder threads never race on them) and the bytes are the same run to run;
 * stb_image's decode settings are pinned before every decode.
 */
#include "io/writers.h"

#include "core/stb_guard.h"
#include "io/deflate.h"

#include <fcntl.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* the one copy of stb_image_write in the program: memory only. It compiles clean under our warning
 * flags (gcc 12 and clang, even outside the system include path), so no diagnostic is silenced
 * around it. stb_image's decoder is compiled once in core/stb_image_impl.c. */
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STBIW_ZLIB_COMPRESS png_zlib
static unsigned char *png_zlib(unsigned char *data, int len, int *out_len, int quality);
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

/* a fixed per-row filter, pinned so that nothing else in the process can change it. Measured on
 * a 1280x720 demo frame with stb's own deflate: the Sub filter (1) encoded in 50 ms to 371 KB,
 * against 82 ms and 414 KB for stb's adaptive filters, which try all five per row and whose
 * heuristic picks worse ones on smooth renders. (The deflate itself is png_zlib's, below.) */
#define PNG_FILTER 1

/* the deflate of every PNG we write: deflate.h's fast one instead of stb's (its level setting then
 * has no effect). Measured on the demo at 1280x720 (bench output): see the README. */
static unsigned char *png_zlib(unsigned char *data, int len, int *out_len, int quality) {
    (void)quality;
    size_t n = 0;
    unsigned char *z = ww_zlib_fast(data, (size_t)len, &n);
    if (!z || n > INT32_MAX) {
        free(z);
        return NULL;
    }
    *out_len = (int)n;
    return z;
}

typedef struct png_buf {
    unsigned char *data;
    size_t len, cap;
    int failed;
} png_buf;

static void png_buf_put(void *ctx, void *data, int size) {
    png_buf *b = ctx;
    if (b->failed || size <= 0) return;
    size_t need = b->len + (size_t)size;
    if (need > b->cap) {
        size_t cap = b->cap ? b->cap : 65536;
        while (cap < need) cap *= 2;
        unsigned char *nd = realloc(b->data, cap);
        if (!nd) {
            b->failed = 1;
            return;
        }
        b->data = nd;
        b->cap = cap;
    }
    memcpy(b->data + b->len, data, (size_t)size);
    b->len = need;
}

/* stb_image_write's settings are library globals: set once, before the first encode, and never
 * again (our rows are stored top row first, as PNG wants them) */
static pthread_once_t png_settings_once = PTHREAD_ONCE_INIT;

static void png_pin_settings(void) {
    stbi_write_force_png_filter = PNG_FILTER;
    stbi_flip_vertically_on_write(0);
}

ww_result ww_encode_png(const ww_image *im, unsigned char **data, size_t *len, ww_error *err) {
    WW_ASSERT(im->type == WW_PIX_U8 && im->u8);
    WW_ASSERT(im->channels == 3 || im->channels == 4);
    WW_ASSERT(im->width > 0 && im->height > 0 && im->width <= INT32_MAX / im->channels);
    *data = NULL;
    *len = 0;
    pthread_once(&png_settings_once, png_pin_settings);
    png_buf b = {0};
    int ok = stbi_write_png_to_func(png_buf_put, &b, im->width, im->height, im->channels, im->u8,
                                    im->width * im->channels);
    if (!ok || b.failed) {
        free(b.data);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "PNG encoding failed (out of memory)");
    }
    *data = b.data;
    *len = b.len;
    return WW_OK;
}

ww_result ww_write_png(const char *path, const ww_image *im, ww_error *err) {
    /* encode into memory, then publish with one atomic write */
    unsigned char *data;
    size_t len;
    ww_result r = ww_encode_png(im, &data, &len, err);
    if (r != WW_OK)
        return ww_error_set(err, r, NULL, 0, 0, "cannot write '%s': PNG encoding failed", path);
    r = ww_write_file_atomic(path, data, len, err);
    free(data);
    return r;
}

/* a PNG is complete when it starts with the signature and ends with the IEND chunk (length 0,
 * type, CRC AE 42 60 82: PNG spec 11.2.5); a torn or truncated file lacks one of them. Only the
 * first 8 and last 12 bytes are read. */
int ww_png_complete(const char *path) {
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return 0;
    unsigned char head[8], tail[12];
    struct stat st;
    int ok = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size >= 8 + 12 &&
             pread(fd, head, sizeof head, 0) == (ssize_t)sizeof head &&
             pread(fd, tail, sizeof tail, st.st_size - 12) == (ssize_t)sizeof tail &&
             memcmp(head, sig, sizeof sig) == 0 && memcmp(tail, iend, sizeof iend) == 0;
    close(fd);
    return ok;
}

ww_result ww_read_png(const char *path, ww_image *out, ww_error *err) {
    memset(out, 0, sizeof *out);
    unsigned char *file;
    size_t len;
    ww_result r = ww_read_file(path, &file, &len, err);
    if (r != WW_OK) return r;
    if (len > INT32_MAX) {
        free(file);
        return ww_error_set(err, WW_E_SYNTAX, NULL, 0, 0, "'%s': not a PNG: file too large", path);
    }

    /* pin stb's decode settings: rows top first, no premultiplied-alpha or iPhone conversions */
    stbi_set_flip_vertically_on_load(0);
    stbi_set_unpremultiply_on_load(0);
    stbi_convert_iphone_png_to_rgb(0);

    /* grey -> RGB, grey+alpha -> RGBA; 16-bit samples come back as their high bytes */
    int w, h, comp;
    if (!ww_stbi_info_from_memory(file, (int)len, &w, &h, &comp)) {
        free(file);
        return ww_error_set(err, WW_E_SYNTAX, NULL, 0, 0, "'%s': not a PNG: %s", path,
                            stbi_failure_reason());
    }
    if (w > WW_FRAME_MAX_SIDE || h > WW_FRAME_MAX_SIDE) {
        free(file);
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                            "'%s' is %dx%d: expected at most %d on a side (the largest frame)",
                            path, w, h, WW_FRAME_MAX_SIDE);
    }
    int want = (comp == 2 || comp == 4) ? 4 : 3;
    unsigned char *px = ww_stbi_load_from_memory(file, (int)len, &w, &h, &comp, want);
    free(file);
    if (!px)
        return ww_error_set(err, WW_E_SYNTAX, NULL, 0, 0, "'%s': not a PNG: %s", path,
                            stbi_failure_reason());

    if (ww_image_alloc(out, w, h, want, WW_PIX_U8) != 0) {
        stbi_image_free(px);
        ww_image_free(out);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot read '%s': out of memory", path);
    }
    memcpy(out->u8, px, (size_t)w * (size_t)h * (size_t)want);
    stbi_image_free(px);
    return WW_OK;
}
