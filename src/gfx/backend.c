/* backend.c - picks and opens a context backend (EGL, OSMesa, or auto: EGL then OSMesa), checks
 * that the context really is OpenGL 3.3 or newer, and answers what it is. The backends
 * themselves live in backend_egl.c and backend_osmesa.c.
 */
#define _GNU_SOURCE /* dl_iterate_phdr's struct dl_phdr_info (sanitizer builds) */
#include "gfx/backend.h"

#include <dlfcn.h>
#include <link.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/backend_impl.h"

#if defined(__SANITIZE_ADDRESS__)
#define WW_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WW_ASAN 1
#endif
#endif

#ifdef WW_ASAN
/* Under AddressSanitizer no library loaded by the time a context is open is ever unmapped:
 * Mesa keeps caches behind its own globals, and once dlclose (ours, or the DRI driver's at
 * eglTerminate) unmaps them LeakSanitizer reports them as leaks in an unknown module, which no
 * suppression can name. Pinned, they stay reachable; tests/lsan.supp covers what Mesa really
 * leaks. dlopen with RTLD_NOLOAD | RTLD_NODELETE only marks an already loaded object. */
static int pin_object(struct dl_phdr_info *info, size_t size, void *user) {
    (void)size;
    (void)user;
    if (info->dlpi_name && info->dlpi_name[0]) {
        void *h = dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        if (h) dlclose(h);
    }
    return 0;
}

static void pin_loaded_libraries(void) { dl_iterate_phdr(pin_object, NULL); }
#else
static void pin_loaded_libraries(void) {}
#endif

int ww_backend_kind_parse(const char *s) {
    if (!s) return -1;
    if (strcmp(s, "auto") == 0) return WW_BACKEND_AUTO;
    if (strcmp(s, "egl") == 0) return WW_BACKEND_EGL;
    if (strcmp(s, "osmesa") == 0) return WW_BACKEND_OSMESA;
    if (strcmp(s, "null") == 0) return WW_BACKEND_NULL;
    return -1;
}

/* GL_VERSION starts "major.minor" (then anything, e.g. " (Core Profile) Mesa 22.3.6") */
static int parse_gl_version(const char *v, int *major, int *minor) {
    return v && sscanf(v, "%d.%d", major, minor) == 2;
}

/* record the context's strings and insist on 3.3 */
static ww_result check_context(ww_backend *b, ww_error *err) {
    const char *ren = (const char *)b->gl.GetString(GL_RENDERER);
    const char *ver = (const char *)b->gl.GetString(GL_VERSION);
    snprintf(b->renderer, sizeof b->renderer, "%s", ren ? ren : "");
    snprintf(b->version, sizeof b->version, "%s", ver ? ver : "");
    int major = 0, minor = 0;
    if (!parse_gl_version(ver, &major, &minor))
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "%s: GL_VERSION \"%s\" does not start with major.minor", b->describe,
                            b->version);
    if (major < 3 || (major == 3 && minor < 3))
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "%s: OpenGL %d.%d on \"%s\", but 3.3 core is needed; update Mesa or "
                            "try the other --backend",
                            b->describe, major, minor, b->renderer);
    return WW_OK;
}

static ww_result open_one(ww_backend_kind kind, ww_backend *b, ww_error *err) {
    memset(b, 0, sizeof *b);
    b->kind = kind;
    ww_result rc = kind == WW_BACKEND_EGL      ? ww_backend_egl_open(b, err)
                   : kind == WW_BACKEND_OSMESA ? ww_backend_osmesa_open(b, err)
                                               : ww_backend_null_open(b, err);
    if (rc != WW_OK) return rc;
    rc = check_context(b, err);
    if (rc != WW_OK) {
        b->close(b);
        return rc;
    }
    pin_loaded_libraries();
    return WW_OK;
}

ww_result ww_backend_open(ww_backend_kind kind, ww_backend **out, ww_error *err) {
    WW_ASSERT(out);
    *out = NULL;
    ww_backend *b = malloc(sizeof *b);
    if (!b) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "backend: out of memory");

    ww_result rc;
    if (kind != WW_BACKEND_AUTO) {
        rc = open_one(kind, b, err);
    } else {
        /* auto: EGL first; when both fail, say why for each */
        ww_error egl_err = {0}, osm_err = {0};
        rc = open_one(WW_BACKEND_EGL, b, &egl_err);
        if (rc != WW_OK) rc = open_one(WW_BACKEND_OSMESA, b, &osm_err);
        if (rc != WW_OK)
            ww_error_set(err, rc, NULL, 0, 0, "no OpenGL backend could be opened:\n  %s\n  %s",
                         egl_err.msg, osm_err.msg);
    }
    if (rc != WW_OK) {
        free(b);
        return rc;
    }
    *out = b;
    return WW_OK;
}

void ww_backend_close(ww_backend *b) {
    if (!b) return;
    b->close(b);
    free(b);
}

const ww_gl *ww_backend_gl(const ww_backend *b) { return &b->gl; }
ww_backend_kind ww_backend_get_kind(const ww_backend *b) { return b->kind; }
const char *ww_backend_describe(const ww_backend *b) { return b->describe; }
const char *ww_backend_renderer(const ww_backend *b) { return b->renderer; }
const char *ww_backend_version(const ww_backend *b) { return b->version; }
