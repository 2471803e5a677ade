/* backend_impl.h - what backend.c shares with the two context backends (private to src/gfx).
 *
 * backend.c allocates a zeroed ww_backend and calls one open function; on success it has made a
 * GL 3.3 core context current, set describe, impl and close, and loaded gl. close undoes all of
 * it (context, display, library) and leaves freeing the ww_backend to backend.c.
 */
#ifndef WW_BACKEND_IMPL_H
#define WW_BACKEND_IMPL_H

#include "gfx/backend.h"

struct ww_backend {
    ww_backend_kind kind;
    char describe[32];           /* "egl/surfaceless", "egl/device", "osmesa" */
    char renderer[256];          /* GL_RENDERER */
    char version[256];           /* GL_VERSION */
    ww_gl gl;
    void *impl;                  /* the backend's own record */
    void (*close)(ww_backend *b);
};

/* each returns WW_E_BACKEND with a message naming the failed call and what to install or set */
ww_result ww_backend_egl_open(ww_backend *b, ww_error *err);
ww_result ww_backend_osmesa_open(ww_backend *b, ww_error *err);
ww_result ww_backend_null_open(ww_backend *b, ww_error *err);

#endif
