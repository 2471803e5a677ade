/* stb_image_impl.c - the one copy of stb_image's decoder in the program (PNG, TGA, JPEG, from
 * memory only), shared by io/png.c (frames and goldens), scene/assets.c (textures, cubemap
 * faces) and check/compare_load.c, which include the header for its settings and frees and
 * decode through the guarded calls at the end of this file (core/stb_guard.h: a structural vet
 * first, core/stb_guard.c). Its compile-time settings are pinned here; callers pin the run-time
 * ones (flip, unpremultiply) before each decode. It compiles clean under our warning flags, so
 * no diagnostic is silenced around it.
 *
 * Its allocator: core/bigalloc.h, so a buffer of 1 MiB or more (a PNG's inflated rows, its
 * concatenated IDAT data, the decoded image) lies on huge pages: decoding one 1280x720 RGB frame
 * touched about 1600 4 KiB pages (21 ms of page faults on this VM, as long as the decoding).
 */
#include "core/bigalloc.h"

#define STBI_MALLOC(sz) ww_big_alloc(sz)
#define STBI_REALLOC_SIZED(p, oldsz, newsz) ww_big_realloc(p, oldsz, newsz)
#define STBI_FREE(p) free(p)

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_TGA
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 32768
#include <stb/stb_image.h>

/* ---- the guarded entry points of core/stb_guard.h ------------------------------------------ */

#include "core/stb_guard.h"

/* the vet's verdict as stb's own failure: 0, with the reason stbi_failure_reason() returns */
static int refused(const unsigned char *buf, int len) {
    const char *why = len < 0 ? "negative length" : ww_image_vet(buf, (size_t)len);
    if (why) stbi__err(why, why);
    return why != NULL;
}

int ww_stbi_info_from_memory(const unsigned char *buf, int len, int *x, int *y, int *comp) {
    return refused(buf, len) ? 0 : stbi_info_from_memory(buf, len, x, y, comp);
}

int ww_stbi_size_from_prefix(const unsigned char *buf, int len, int *x, int *y) {
    if (len < 0) return stbi__err("negative length", "negative length");
    int k = ww_image_header_size(buf, (size_t)len, x, y);
    if (k < 0) return stbi__err("bad or truncated image header", "bad or truncated image header");
    int comp;
    return k > 0 || stbi_info_from_memory(buf, len, x, y, &comp);
}

int ww_stbi_is_16_bit_from_memory(const unsigned char *buf, int len) {
    return refused(buf, len) ? 0 : stbi_is_16_bit_from_memory(buf, len);
}

unsigned char *ww_stbi_load_from_memory(const unsigned char *buf, int len, int *x, int *y,
                                        int *comp, int req_comp) {
    return refused(buf, len) ? NULL : stbi_load_from_memory(buf, len, x, y, comp, req_comp);
}

unsigned short *ww_stbi_load_16_from_memory(const unsigned char *buf, int len, int *x, int *y,
                                            int *comp, int req_comp) {
    return refused(buf, len) ? NULL : stbi_load_16_from_memory(buf, len, x, y, comp, req_comp);
}
