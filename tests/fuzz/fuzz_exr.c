/* fuzz_exr.c - libFuzzer entry for the EXR reader (io/exr.c on OpenEXRCore) and the compare
 * loader's EXR path (check/compare_load.c, which also reads the channel list itself): any bytes
 * in, an image, the attributes or an error out, no crash. The readers take a path, so the input
 * is handed over as a file in memory. The corpus starts from small EXRs our writer makes
 * (half and float, RGB and RGBA, ZIP, PIZ and none, with and without attributes).
 * OpenEXRCore is the system's library, not built with the fuzzer's instrumentation: the
 * sanitizers see our code and what the library does to memory we own, coverage only ours. */
#include "fuzz_file.h"

#include <math.h>
#include <stdint.h>

#include "check/compare.h"
#include "io/writers.h"

/* files whose data window is larger are not read: a size cap is the reader's business, and
 * ASan freeing a 4-megapixel float image took 1.7 s on a loaded machine and tripped libFuzzer's
 * timeout; a megapixel exercises the same code */
#define MAX_PIXELS (1 << 20)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int32_t le32(const uint8_t *p) {
    return (int32_t)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24);
}

/* the first header's dataWindow (attributes: name\0 type\0 size value), as pixels; 0 when it
 * cannot be found */
static int64_t window_pixels(const uint8_t *f, size_t len) {
    size_t p = 8;
    while (p < len && f[p]) {
        const uint8_t *nz = memchr(f + p, 0, len - p);
        const uint8_t *tz = nz ? memchr(nz + 1, 0, len - (size_t)(nz + 1 - f)) : NULL;
        if (!tz || (size_t)(tz + 5 - f) > len) return 0;
        uint32_t n = (uint32_t)le32(tz + 1);
        size_t v = (size_t)(tz + 5 - f);
        if (n > len - v) return 0;
        if (strcmp((const char *)f + p, "dataWindow") == 0 && n == 16) {
            int64_t w = (int64_t)le32(f + v + 8) - le32(f + v) + 1;
            int64_t h = (int64_t)le32(f + v + 12) - le32(f + v + 4) + 1;
            /* each side fits in 33 bits: their product may not fit in 64 */
            if (w > MAX_PIXELS || h > MAX_PIXELS) return (int64_t)MAX_PIXELS + 1;
            return w > 0 && h > 0 ? w * h : 0;
        }
        p = v + n;
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (window_pixels(data, size) > MAX_PIXELS) return 0;
    const char *path = fuzz_memfile(0, data, size);
    ww_error err;
    ww_image im;
    if (ww_read_exr(path, &im, &err) == WW_OK) {
        if (im.width < 1 || im.height < 1 || im.channels != 4 || im.type != WW_PIX_F32) abort();
        volatile float last = im.f32[(size_t)im.width * (size_t)im.height * 4 - 1];
        (void)last;
    }
    ww_image_free(&im);

    int frame;
    double t;
    char scene[64], gl[64];
    if (ww_read_exr_meta(path, &frame, &t, scene, sizeof scene, gl, sizeof gl, &err) == WW_OK &&
        (strlen(scene) >= sizeof scene || strlen(gl) >= sizeof gl))
        abort();
    (void)ww_exr_complete(path);

    ww_cmp_image c;
    ww_cmp_load(path, &c, &err);
    ww_cmp_image_free(&c);
    return 0;
}
