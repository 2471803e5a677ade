/* gl.c - fills the OpenGL function table (gl.h) through a backend's get-proc-address.
 * Every entry is required: a missing one is reported by name, so a broken driver fails early
 * with a clear message rather than crashing in the first draw.
 */
#include "gfx/gl.h"

#include <stddef.h>

const char *ww_gl_load(ww_gl *gl, ww_gl_loader loader, void *user) {
    /* one lookup per X-macro entry; the table name drops the "gl" prefix */
#define WW_GL_LOAD(type, name)                                                                   \
    gl->name = (type)loader("gl" #name, user);                                                  \
    if (!gl->name) return "gl" #name;
    WW_GL_FUNCS(WW_GL_LOAD)
#undef WW_GL_LOAD
    return NULL;
}
