/* writers.h - frame files. Every write is atomic: a temporary file beside the target
 * ("NAME.tmp.PID"), fsync'd and renamed over it, so an interrupted run never leaves a partial file.
 *
 *   ww_write_png(path, &ldr, &err);     // RGB8 or RGBA8 from a U8 image, stb_image_write
 *   ww_write_exr(path, &hdr, &meta, &err); // half or float RGBA (or RGB) from an F32 image,
 *                                       // OpenEXRCore, ZIP / PIZ / no compression
 *   ww_encode_png(&ldr, &data, &len, &err), ww_encode_exr(...): the same bytes into memory
 *                                       (caller frees data), for the encoder threads of a job
 *   ww_png_complete(path), ww_exr_complete(path): a frame file on disk is whole (--resume)
 *   ww_read_exr(path, &im, &err);       // F32 image back (tests, compare)
 *   ww_read_png(path, &im, &err);       // U8 image back (tests, compare), stb_image
 *   ww_read_exr_meta(path, &frame, &t, scene, sizeof scene, gl, sizeof gl, &err);
 *
 * The readers fill an image the caller frees with ww_image_free (also after a failure: it is then
 * empty); ww_read_file returns bytes the caller frees with free().
 */
#ifndef WW_WRITERS_H
#define WW_WRITERS_H

#include <stddef.h>

#include "core/error.h"
#include "io/image.h"

/* EXR compression (zero: ZIP) */
enum { WW_EXR_COMP_ZIP = 0, WW_EXR_COMP_NONE, WW_EXR_COMP_PIZ };

/* what an EXR holds besides its pixels: the encoding (zero: half, ZIP) and our attributes */
typedef struct ww_exr_meta {
    int float32;           /* 32-bit float channels instead of half */
    int compression;       /* WW_EXR_COMP_* */
    int frame;             /* -1: not written */
    double time;           /* simulated time, s; NAN: not written */
    const char *scene;     /* scene name, or NULL */
    const char *renderer;  /* GL_RENDERER string, or NULL */
} ww_exr_meta;

/* create a folder and its parents (mkdir -p); WW_E_IO with the path on failure */
ww_result ww_make_dirs(const char *path, ww_error *err);

/* write len bytes to path atomically (temporary file + rename) */
ww_result ww_write_file_atomic(const char *path, const void *data, size_t len, ww_error *err);

ww_result ww_write_png(const char *path, const ww_image *im, ww_error *err);
ww_result ww_write_exr(const char *path, const ww_image *im, const ww_exr_meta *meta, ww_error *err);
ww_result ww_encode_png(const ww_image *im, unsigned char **data, size_t *len, ww_error *err);
ww_result ww_encode_exr(const ww_image *im, const ww_exr_meta *meta, unsigned char **data,
                        size_t *len, ww_error *err);
/* 1 when the file is a whole PNG (signature first, IEND chunk last: reads 20 bytes) / a whole EXR
 * (its header parses and its last chunk lies inside the file) */
int ww_png_complete(const char *path);
int ww_exr_complete(const char *path);
ww_result ww_read_png(const char *path, ww_image *out, ww_error *err);
ww_result ww_read_exr(const char *path, ww_image *out, ww_error *err);

/* the ww_exr_meta attributes of an EXR; absent ones read as frame -1, time NAN, "" (any output
 * may be NULL; strings are cut to their capacity) */
ww_result ww_read_exr_meta(const char *path, int *frame, double *time, char *scene,
                           size_t scene_cap, char *renderer, size_t renderer_cap, ww_error *err);

/* a whole file into malloc'd memory (NUL-terminated past len); WW_E_NOFILE when it cannot.
 * A regular file is read to its size; anything else (a pipe, /dev/zero) to WW_READ_STREAM_MAX
 * bytes, past which it is WW_E_RANGE: no read grows without bound (core/readfile.h). */
#define WW_READ_STREAM_MAX ((size_t)256 << 20)
ww_result ww_read_file(const char *path, unsigned char **data, size_t *len, ww_error *err);

#endif
