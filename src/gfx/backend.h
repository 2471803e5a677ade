/* backend.h - a headless OpenGL 3.3 core context from EGL or OSMesa, both loaded with dlopen at
 * run time (one binary runs where either exists; Mesa 25.1 dropped OSMesa). GL entry points come
 * from the backend's get-proc-address, never from linking libGL.
 *
 *   ww_backend *b = NULL; ww_error err = {0};
 *   ww_backend_open(WW_BACKEND_AUTO, &b, &err);   // auto: EGL (device, then surfaceless), OSMesa
 *   const ww_gl *gl = ww_backend_gl(b);           // loaded function table
 *   ... render ...
 *   ww_backend_close(b);
 *
 * Environment: WW_EGL_PLATFORM=device|surfaceless forces the EGL platform; WW_EGL_DEVICE=N picks
 * the Nth EGL device.
 */
#ifndef WW_BACKEND_H
#define WW_BACKEND_H

#include "core/error.h"
#include "gfx/gl.h"

/* NULL: no GL at all (backend_null.c): every call does nothing and frames read back black; for
 * testing the CLI and the render job where no GL opens. AUTO never picks it. */
typedef enum ww_backend_kind {
    WW_BACKEND_AUTO = 0,
    WW_BACKEND_EGL,
    WW_BACKEND_OSMESA,
    WW_BACKEND_NULL
} ww_backend_kind;

typedef struct ww_backend ww_backend;

ww_result ww_backend_open(ww_backend_kind kind, ww_backend **out, ww_error *err);
void ww_backend_close(ww_backend *b);
const ww_gl *ww_backend_gl(const ww_backend *b);
ww_backend_kind ww_backend_get_kind(const ww_backend *b);
/* e.g. "egl/surfaceless", "egl/device", "osmesa", "null" */
const char *ww_backend_describe(const ww_backend *b);
/* GL_RENDERER and GL_VERSION strings of the current context */
const char *ww_backend_renderer(const ww_backend *b);
const char *ww_backend_version(const ww_backend *b);
/* parse "auto" | "egl" | "osmesa" | "null"; -1 when it is none of them */
int ww_backend_kind_parse(const char *s);

#endif
