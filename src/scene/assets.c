/* assets.c - the files a scene names, decoded once at load (scene/assets.h): images through
 * stb_image (core/stb_image_impl.c: PNG, TGA, JPEG) into RGBA8, OBJ models through obj.c. Each
 * path is kept once, whatever names it how often.
 */
#include "scene/assets.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include <stb/stb_image.h>

#include "core/stb_guard.h"
#include "scene/obj.h"

#define IMAGE_MAX_BYTES (64u << 20)  /* largest image file read */
#define IMAGE_MAX_SIDE 8192          /* texels per side */
#define ASSETS_MAX 1024              /* images, and meshes, per scene */

ww_result ww_assets_image(ww_assets *a, const char *path, const char *from, int line, int column,
                          int *index, ww_error *err) {
    for (int i = 0; i < a->nimage; i++)
        if (strcmp(a->image[i].path, path) == 0) {
            *index = i;
            return WW_OK;
        }
    if (strlen(path) >= WW_ASSET_PATH)
        return ww_error_set(err, WW_E_RANGE, from, line, column, "image path too long: '%.60s...'",
                            path);
    if (a->nimage >= ASSETS_MAX)
        return ww_error_set(err, WW_E_RANGE, from, line, column, "more than %d images",
                            ASSETS_MAX);
    char *file;
    size_t len;
    ww_result r = ww_assets_read_file(path, IMAGE_MAX_BYTES, from, line, column, &file, &len, err);
    if (r != WW_OK) return r;

    /* pin stb's run-time settings (io/png.c may have set them): rows top first, as stored */
    stbi_set_flip_vertically_on_load(0);
    stbi_set_unpremultiply_on_load(0);
    stbi_convert_iphone_png_to_rgb(0);
    int w, h, comp;
    unsigned char *px = NULL;
    if (!ww_stbi_info_from_memory((const unsigned char *)file, (int)len, &w, &h, &comp)) {
        free(file);
        return ww_error_set(err, WW_E_SYNTAX, from, line, column,
                            "'%s' is not a PNG, TGA or JPEG image: %s", path,
                            stbi_failure_reason());
    }
    if (w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE) {
        free(file);
        return ww_error_set(err, WW_E_RANGE, from, line, column,
                            "'%s' is %dx%d: expected at most %d texels per side", path, w, h,
                            IMAGE_MAX_SIDE);
    }
    px = ww_stbi_load_from_memory((const unsigned char *)file, (int)len, &w, &h, &comp, 4);
    free(file);
    if (!px)
        return ww_error_set(err, WW_E_SYNTAX, from, line, column, "cannot decode '%s': %s", path,
                            stbi_failure_reason());

    ww_image_data *grown = realloc(a->image, (size_t)(a->nimage + 1) * sizeof *grown);
    size_t bytes = (size_t)w * (size_t)h * 4;
    unsigned char *rgba = malloc(bytes);
    if (grown) a->image = grown;
    if (!grown || !rgba) {
        free(rgba);
        stbi_image_free(px);
        return ww_error_set(err, WW_E_NOMEM, from, line, column, "out of memory for '%s'", path);
    }
    /* our own allocation, so that ww_assets_free need not know stb's allocator */
    memcpy(rgba, px, bytes);
    stbi_image_free(px);
    ww_image_data *im = &a->image[a->nimage];
    *im = (ww_image_data){.width = w, .height = h, .rgba = rgba};
    memcpy(im->path, path, strlen(path) + 1);
    *index = a->nimage++;
    return WW_OK;
}

ww_result ww_assets_obj(ww_assets *a, const char *path, const char *from, int line, int column,
                        int *index, ww_error *err) {
    for (int i = 0; i < a->nmesh; i++)
        if (strcmp(a->mesh[i].path, path) == 0) {
            *index = i;
            return WW_OK;
        }
    if (strlen(path) >= WW_ASSET_PATH)
        return ww_error_set(err, WW_E_RANGE, from, line, column, "OBJ path too long: '%.60s...'",
                            path);
    if (a->nmesh >= ASSETS_MAX)
        return ww_error_set(err, WW_E_RANGE, from, line, column, "more than %d OBJ files",
                            ASSETS_MAX);
    char *text;
    size_t len;
    ww_result r = ww_assets_read_file(path, WW_OBJ_MAX_BYTES, from, line, column, &text, &len, err);
    if (r != WW_OK) return r;
    ww_mesh_data m;
    r = ww_obj_parse(a, path, text, len, &m, err);
    free(text);
    if (r != WW_OK) return r;
    ww_mesh_data *grown = realloc(a->mesh, (size_t)(a->nmesh + 1) * sizeof *grown);
    if (!grown) {
        free(m.vertex);
        free(m.index);
        free(m.sub);
        free(m.material);
        return ww_error_set(err, WW_E_NOMEM, from, line, column, "out of memory for '%s'", path);
    }
    a->mesh = grown;
    a->mesh[a->nmesh] = m;
    *index = a->nmesh++;
    return WW_OK;
}

void ww_assets_free(ww_assets *a) {
    if (!a) return;
    for (int i = 0; i < a->nimage; i++) free(a->image[i].rgba);
    free(a->image);
    for (int i = 0; i < a->nmesh; i++) {
        ww_mesh_data *m = &a->mesh[i];
        free(m->vertex);
        free(m->index);
        free(m->sub);
        free(m->material);
    }
    free(a->mesh);
    *a = (ww_assets){0};
}
