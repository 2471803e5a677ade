/* fuzz_png.c - libFuzzer entry for our PNG reader (io/png_read.c) and, through it, inflate: any
 * bytes in, pixels or an error out, no crash. Each chunk's CRC is made right before decoding,
 * so that mutations reach past the CRC check; and an image our reader decodes must decode to
 * the same samples through stb_image (a second opinion on every filter and bit depth). The
 * corpus starts from small PNGs of every kind the reader takes and some it leaves to stb. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "core/stb_guard.h"
#include "io/png_read.h"

#include <stb/stb_image.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static uint32_t be32(const unsigned char *p) {
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* walk the chunks as far as their lengths allow and write each one's CRC-32 */
static void fix_crcs(unsigned char *f, size_t len) {
    for (size_t pos = 8; pos + 12 <= len;) {
        uint32_t n = be32(f + pos);
        if (n > len - pos - 12) break;
        uint32_t c = (uint32_t)crc32(0, f + pos + 4, (uInt)n + 4);
        unsigned char *o = f + pos + 8 + n;
        o[0] = (unsigned char)(c >> 24);
        o[1] = (unsigned char)(c >> 16);
        o[2] = (unsigned char)(c >> 8);
        o[3] = (unsigned char)c;
        pos += (size_t)n + 12;
    }
}

/* stb_image's samples of a file our reader decoded (asked only about files the guard lets
 * through to stb) must be ours. stb refuses one thing our reader passes over on purpose, as
 * libpng does: a truecolour image's suggested palette (PLTE) of a length that is not 3 entries'
 * worth or more than 256 of them, which the decoding never reads */
static void same_as_stb(const unsigned char *f, size_t size, const ww_png_pixels *px) {
    if (ww_image_vet(f, size)) return;
    int w, h, comp;
    void *ref = px->bits == 16
                    ? (void *)ww_stbi_load_16_from_memory(f, (int)size, &w, &h, &comp, 0)
                    : (void *)ww_stbi_load_from_memory(f, (int)size, &w, &h, &comp, 0);
    if (!ref && strcmp(stbi_failure_reason(), "invalid PLTE") == 0) return;
    size_t bytes = (size_t)px->width * (size_t)px->height * (size_t)px->channels * (size_t)(px->bits / 8);
    if (!ref || w != px->width || h != px->height || comp != px->channels ||
        memcmp(ref, px->px, bytes) != 0)
        abort();
    stbi_image_free(ref);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    unsigned char *f = malloc(size ? size : 1);
    if (!f) return 0;
    memcpy(f, data, size);
    fix_crcs(f, size);
    ww_png_pixels px;
    ww_error err;
    if (ww_png_decode(f, size, &px, &err) == WW_OK) {
        same_as_stb(f, size, &px);
        free(px.px);
    }
    free(f);
    return 0;
}
