/* assets.c - the files a scene names (scene/assets.h): images looked at through stb_image's
 * header reader at load and decoded (core/stb_image_impl.c: PNG, TGA, JPEG) into RGBA8 only when
 * drawn, OBJ models through obj.c. Each path is kept once, whatever names it how often. Every
 * read is capped (scene/assets.h, scene/obj.h) and every error names the scene's place.
 */
#include "scene/assets.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb/stb_image.h>

#include "core/readfile.h"
#include "core/stb_guard.h"
#include "scene/files.h"
#include "scene/obj.h"

/* bytes read to find an image's size: a PNG's IHDR and a TGA's header are at the start; a JPEG's
 * frame header follows its APP segments (EXIF, ICC), which rarely pass this; when they do the
 * whole file is read (under its cap) and looked at again */
#define IMAGE_PEEK_BYTES 65536


/* err moved to the place that named the file, its message kept (the readers below io/ know the
 * file, not who named it) */
static ww_result at_place(ww_result r, const char *from, int line, int column, ww_error *err) {
    if (!err) return r;
    snprintf(err->file, sizeof err->file, "%s", from ? from : "");
    err->line = line;
    err->column = column;
    return r;
}

/* up to cap bytes from the start of path; *got how many */
static int read_prefix(const char *path, unsigned char *buf, size_t cap, size_t *got) {
    *got = 0;
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return -1;
    while (*got < cap) {
        ssize_t n = read(fd, buf + *got, cap - *got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        *got += (size_t)n;
    }
    close(fd);
    return 0;
}

/* pin stb's run-time settings (io/png.c may have set them): rows top first, as stored */
static void stb_settings(void) {
    stbi_set_flip_vertically_on_load(0);
    stbi_set_unpremultiply_on_load(0);
    stbi_convert_iphone_png_to_rgb(0);
}

/* width and height from the header, the whole file read only when the start does not hold it */
static ww_result image_size(const char *path, const char *from, int line, int column, int *w,
                            int *h, ww_error *err) {
    unsigned char *peek = malloc(IMAGE_PEEK_BYTES);
    size_t got = 0;
    if (!peek) return ww_error_set(err, WW_E_NOMEM, from, line, column, "out of memory");
    if (read_prefix(path, peek, IMAGE_PEEK_BYTES, &got) != 0) {
        free(peek);
        return ww_error_set(err, WW_E_NOFILE, from, line, column, "cannot open '%s': %s", path,
                            strerror(errno));
    }
    stb_settings();
    int ok = ww_stbi_size_from_prefix(peek, (int)got, w, h);
    free(peek);
    if (!ok && got == IMAGE_PEEK_BYTES) {
        unsigned char *file;
        size_t len;
        ww_result r = ww_file_read_max(path, WW_IMAGE_MAX_BYTES, WW_IMAGE_MAX_BYTES, &file, &len, err);
        if (r) return at_place(r, from, line, column, err);
        ok = len <= INT_MAX && ww_stbi_size_from_prefix(file, (int)len, w, h);
        free(file);
    }
    if (!ok)
        return ww_error_set(err, WW_E_SYNTAX, from, line, column,
                            "'%s' is not a PNG, TGA or JPEG image: %s", path,
                            stbi_failure_reason());
    return WW_OK;
}

static long long texels(const ww_assets *a) {
    long long n = 0;
    for (int i = 0; i < a->nimage; i++) n += (long long)a->image[i].width * a->image[i].height;
    return n;
}

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
    if (a->nimage >= WW_ASSETS_MAX)
        return ww_error_set(err, WW_E_RANGE, from, line, column, "more than %d images",
                            WW_ASSETS_MAX);
    ww_result r = ww_file_check_named(path, WW_IMAGE_MAX_BYTES, from, line, column, err);
    int w = 0, h = 0;
    if (!r) r = image_size(path, from, line, column, &w, &h, err);
    if (r) return r;
    if (w > WW_IMAGE_MAX_SIDE || h > WW_IMAGE_MAX_SIDE)
        return ww_error_set(err, WW_E_RANGE, from, line, column,
                            "'%s' is %dx%d: expected at most %d texels per side", path, w, h,
                            WW_IMAGE_MAX_SIDE);
    long long before = texels(a);
    if (before + (long long)w * h > WW_IMAGE_MAX_TEXELS)
        return ww_error_set(err, WW_E_RANGE, from, line, column,
                            "'%s' (%dx%d) makes the scene's images %lld texels: expected at most "
                            "%lld (six faces of %d^2)",
                            path, w, h, before + (long long)w * h, WW_IMAGE_MAX_TEXELS,
                            WW_IMAGE_MAX_SIDE);

    ww_image_data *grown = realloc(a->image, (size_t)(a->nimage + 1) * sizeof *grown);
    if (!grown) return ww_error_set(err, WW_E_NOMEM, from, line, column, "out of memory for '%s'", path);
    a->image = grown;
    ww_image_data *im = &a->image[a->nimage];
    *im = (ww_image_data){.width = w, .height = h, .line = line, .column = column};
    snprintf(im->path, sizeof im->path, "%s", path);
    snprintf(im->from, sizeof im->from, "%s", from ? from : "");
    *index = a->nimage++;
    return WW_OK;
}

ww_result ww_assets_decode(const ww_image_data *im, unsigned char **rgba, ww_error *err) {
    const char *from = im->from[0] ? im->from : NULL;
    *rgba = NULL;
    unsigned char *file;
    size_t len;
    ww_result r = ww_file_check_named(im->path, WW_IMAGE_MAX_BYTES, from, im->line, im->column, err);
    if (!r && (r = ww_file_read_max(im->path, WW_IMAGE_MAX_BYTES, WW_IMAGE_MAX_BYTES, &file, &len, err)))
        r = at_place(r, from, im->line, im->column, err);
    if (r) return r;

    /* the size was checked at load; a file replaced since must still match it */
    int w = 0, h = 0, comp;
    stb_settings();
    int same = len <= INT_MAX && ww_stbi_size_from_prefix(file, (int)len, &w, &h) &&
               w == im->width && h == im->height;
    unsigned char *px = same ? ww_stbi_load_from_memory(file, (int)len, &w, &h, &comp, 4) : NULL;
    free(file);
    if (!same)
        return ww_error_set(err, WW_E_SYNTAX, from, im->line, im->column,
                            "'%s' changed since the scene was loaded: it is %dx%d, was %dx%d",
                            im->path, w, h, im->width, im->height);
    if (!px)
        return ww_error_set(err, WW_E_SYNTAX, from, im->line, im->column,
                            "cannot decode '%s': %s", im->path, stbi_failure_reason());
    *rgba = px;
    return WW_OK;
}

void ww_assets_pixels_free(unsigned char *rgba) { stbi_image_free(rgba); }


static long long scene_triangles(const ww_assets *a) {
    long long n = 0;
    for (int i = 0; i < a->nmesh; i++) n += a->mesh[i].nindex / 3;
    return n;
}

static ww_result load_texture(void *ctx, const char *path, const char *from, int line,
                              int column, int *index, ww_error *err) {
    return ww_assets_image(ctx, path, from, line, column, index, err);
}

ww_result ww_assets_obj_parse(ww_assets *a, const char *path, const char *text, size_t len,
                              ww_mesh_data *out, ww_error *err) {
    ww_obj_textures tx = {.load = load_texture, .ctx = a};
    return ww_obj_parse(&tx, path, text, len, out, err);
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
    if (a->nmesh >= WW_ASSETS_MAX)
        return ww_error_set(err, WW_E_RANGE, from, line, column, "more than %d OBJ files",
                            WW_ASSETS_MAX);
    char *text;
    size_t len;
    ww_result r = ww_file_read_named(path, WW_OBJ_MAX_BYTES, from, line, column, &text, &len, err);
    if (r != WW_OK) return r;
    ww_mesh_data m;
    r = ww_assets_obj_parse(a, path, text, len, &m, err);
    free(text);
    /* a file without faces (a binary file, a point cloud) is wrong as a whole: the scene's place */
    if (r == WW_E_EMPTY)
        return ww_error_set(err, r, from, line, column,
                            "'%s' holds no faces: expected an OBJ model with 'f' lines", path);
    if (r != WW_OK) return ww_file_named_at(r, from, line, column, err);
    long long total = scene_triangles(a) + m.nindex / 3;
    if (total > WW_OBJ_MAX_ELEMENTS) {
        ww_mesh_data_free(&m);
        return ww_error_set(err, WW_E_RANGE, from, line, column,
                            "'%s' makes the scene's OBJ models %lld triangles: expected at most "
                            "%d in all",
                            path, total, WW_OBJ_MAX_ELEMENTS);
    }
    ww_mesh_data *grown = realloc(a->mesh, (size_t)(a->nmesh + 1) * sizeof *grown);
    if (!grown) {
        ww_mesh_data_free(&m);
        return ww_error_set(err, WW_E_NOMEM, from, line, column, "out of memory for '%s'", path);
    }
    a->mesh = grown;
    a->mesh[a->nmesh] = m;
    *index = a->nmesh++;
    return WW_OK;
}

void ww_assets_free(ww_assets *a) {
    if (!a) return;
    free(a->image);
    for (int i = 0; i < a->nmesh; i++) ww_mesh_data_free(&a->mesh[i]);
    free(a->mesh);
    *a = (ww_assets){0};
}
