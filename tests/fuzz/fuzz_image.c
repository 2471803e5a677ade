/* fuzz_image.c - libFuzzer entry for the image files a scene and the tools name, through the
 * three places that decode them: textures and cubemap faces (scene/assets.c: stb_image to
 * RGBA8), io/png.c's reader (stb_image to RGB8 or RGBA8) and the compare loader
 * (check/compare_load.c: our PNG reader, stb_image for the rest, 8 or 16 bits). All of them reach
 * stb_image through core/stb_guard.h; any bytes in, an image or an error out, no crash. */
#include "fuzz_file.h"

#include <stdint.h>

#include "check/compare.h"
#include "core/stb_guard.h"
#include "io/writers.h"
#include "scene/assets.h"

/* images that say they are larger are not decoded: a size cap is the readers' business (their
 * own caps are tested apart), and ASan's shadow of a 32768x32768 image only slows the search */
#define MAX_PIXELS (1 << 22)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    int w, h, comp;
    if (size > INT_MAX) return 0;
    if (ww_stbi_info_from_memory(data, (int)size, &w, &h, &comp) && (int64_t)w * h > MAX_PIXELS)
        return 0;
    const char *path = fuzz_memfile(0, data, size);
    ww_error err;

    ww_assets a = {0};
    int idx;
    unsigned char *rgba = NULL;
    /* loading reads the size from the header; decoding is what the commands that draw do */
    if (ww_assets_image(&a, path, "fuzz.yaml", 1, 1, &idx, &err) == WW_OK &&
        ww_assets_decode(&a.image[idx], &rgba, &err) == WW_OK) {
        const ww_image_data *im = &a.image[idx];
        if (im->width < 1 || im->height < 1) abort();
        volatile unsigned char last = rgba[(size_t)im->width * (size_t)im->height * 4 - 1];
        (void)last;
        ww_assets_pixels_free(rgba);
    }
    ww_assets_free(&a);

    ww_image im;
    ww_read_png(path, &im, &err);
    ww_image_free(&im);

    ww_cmp_image c;
    ww_cmp_load(path, &c, &err);
    ww_cmp_image_free(&c);
    return 0;
}
