/* backend_osmesa.c - a GL 3.3 core context from Mesa's off-screen OSMesa, loaded with dlopen.
 * OSMesa needs a client buffer to be current on; a tiny private one is enough because the
 * renderer draws into its own framebuffer objects. Mesa 25.1 removed OSMesa, so EGL is the
 * default and this backend is optional: it needs no OSMesa header or library at build time.
 */
#include <dlfcn.h>
#include <stdlib.h>

#include "gfx/backend_impl.h"

/* The few parts of the OSMesa API (Mesa's GL/osmesa.h, OSMesa 11.2) this file uses, declared
 * here so that a system without OSMesa (Debian 13's successors, any Mesa from 25.1) builds it:
 * the context handle, the four entry points OSMesaCreateContextAttribs, OSMesaMakeCurrent,
 * OSMesaDestroyContext and OSMesaGetProcAddress, and the attribute names and values passed to
 * OSMesaCreateContextAttribs. */
typedef struct osmesa_context *OSMesaContext;
typedef void (*osm_proc)(void); /* OSMESAproc, without its empty parameter list */
enum {
    OSM_RGBA = 0x1908, /* OSMESA_RGBA = GL_RGBA */
    OSM_FORMAT = 0x22,
    OSM_DEPTH_BITS = 0x30,
    OSM_STENCIL_BITS = 0x31,
    OSM_ACCUM_BITS = 0x32,
    OSM_PROFILE = 0x33,
    OSM_CORE_PROFILE = 0x34,
    OSM_CONTEXT_MAJOR_VERSION = 0x36,
    OSM_CONTEXT_MINOR_VERSION = 0x37,
};

/* where the header is installed, hold our copies to it (glcorearb.h, through backend_impl.h,
 * must come before osmesa.h's GL/gl.h, or the 1.1 entry point types of the table go missing);
 * WW_OSMESA_HEADER_CHECK=0 builds as where it is absent (a test does) */
#ifndef WW_OSMESA_HEADER_CHECK
#define WW_OSMESA_HEADER_CHECK 1
#endif
#if WW_OSMESA_HEADER_CHECK && defined(__has_include)
#if __has_include(<GL/osmesa.h>)
#include <GL/osmesa.h>
_Static_assert(OSM_RGBA == OSMESA_RGBA && OSM_FORMAT == OSMESA_FORMAT &&
                   OSM_DEPTH_BITS == OSMESA_DEPTH_BITS && OSM_STENCIL_BITS == OSMESA_STENCIL_BITS &&
                   OSM_ACCUM_BITS == OSMESA_ACCUM_BITS && OSM_PROFILE == OSMESA_PROFILE &&
                   OSM_CORE_PROFILE == OSMESA_CORE_PROFILE &&
                   OSM_CONTEXT_MAJOR_VERSION == OSMESA_CONTEXT_MAJOR_VERSION &&
                   OSM_CONTEXT_MINOR_VERSION == OSMESA_CONTEXT_MINOR_VERSION,
               "OSMesa constants differ from GL/osmesa.h");
#endif
#endif

/* what to do when OSMesa does not open; backend.c's auto mode has tried EGL first */
#define OSMESA_ADVICE                                                                            \
    "OSMesa is optional (Mesa 25.1 removed it): use --backend egl, or, with a Mesa older than "  \
    "25.1, install libosmesa6 (Debian 12, 13)"
#define OSMESA_BUF_SIZE 4 /* px, square */

typedef OSMesaContext (*osm_create_fn)(const int *attribs, OSMesaContext share);
typedef GLboolean (*osm_make_current_fn)(OSMesaContext c, void *buf, GLenum type, GLsizei w,
                                         GLsizei h);
typedef void (*osm_destroy_fn)(OSMesaContext c);
typedef osm_proc (*osm_get_proc_fn)(const char *name);

typedef struct osm_impl {
    void *lib;
    const char *lib_name;
    osm_create_fn CreateContextAttribs;
    osm_make_current_fn MakeCurrent;
    osm_destroy_fn DestroyContext;
    osm_get_proc_fn GetProcAddress;
    OSMesaContext ctx;
    unsigned char buf[OSMESA_BUF_SIZE * OSMESA_BUF_SIZE * 4];
} osm_impl;

/* dlsym gives a void *; a union converts it to a function pointer without a pedantic cast */
typedef union sym {
    void *obj;
    osm_create_fn create;
    osm_make_current_fn make_current;
    osm_destroy_fn destroy;
    osm_get_proc_fn get_proc;
} sym;

static ww_gl_proc osm_loader(const char *name, void *user) {
    const osm_impl *o = user;
    return (ww_gl_proc)o->GetProcAddress(name);
}

static void osm_close(ww_backend *b) {
    osm_impl *o = b->impl;
    if (!o) return;
    if (o->ctx) {
        o->MakeCurrent(NULL, NULL, 0, 0, 0); /* release before destroying */
        o->DestroyContext(o->ctx);
    }
    if (o->lib) dlclose(o->lib);
    free(o);
    b->impl = NULL;
}

static ww_result load_lib(osm_impl *o, ww_error *err) {
    /* libOSMesa.so.8 is current Mesa; .6 is the older soname some distributions still ship */
    static const char *const names[] = {"libOSMesa.so.8", "libOSMesa.so.6"};
    const char *why = "";
    for (size_t i = 0; i < sizeof names / sizeof names[0] && !o->lib; i++) {
        o->lib = dlopen(names[i], RTLD_NOW | RTLD_LOCAL);
        if (o->lib)
            o->lib_name = names[i];
        else
            why = dlerror();
    }
    if (!o->lib)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "osmesa: cannot load libOSMesa.so.8 or libOSMesa.so.6 (%s); "
                            OSMESA_ADVICE, why ? why : "not found");

    sym s;
#define OSM_SYM(field, member, name)                                                             \
    s.obj = dlsym(o->lib, name);                                                                \
    if (!s.obj)                                                                                 \
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,                                      \
                            "osmesa: %s has no %s (OSMesa older than 11.2?); " OSMESA_ADVICE,  \
                            o->lib_name, name);                                                 \
    o->field = s.member;
    OSM_SYM(CreateContextAttribs, create, "OSMesaCreateContextAttribs")
    OSM_SYM(MakeCurrent, make_current, "OSMesaMakeCurrent")
    OSM_SYM(DestroyContext, destroy, "OSMesaDestroyContext")
    OSM_SYM(GetProcAddress, get_proc, "OSMesaGetProcAddress")
#undef OSM_SYM
    return WW_OK;
}

ww_result ww_backend_osmesa_open(ww_backend *b, ww_error *err) {
    osm_impl *o = calloc(1, sizeof *o);
    if (!o) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "osmesa: out of memory");
    b->impl = o;
    b->close = osm_close;
    snprintf(b->describe, sizeof b->describe, "osmesa");

    ww_result rc = load_lib(o, err);
    if (rc == WW_OK) {
        /* no depth, stencil or accumulation buffer: our framebuffers carry their own */
        const int attrs[] = {OSM_FORMAT, OSM_RGBA,
                             OSM_DEPTH_BITS, 0,
                             OSM_STENCIL_BITS, 0,
                             OSM_ACCUM_BITS, 0,
                             OSM_PROFILE, OSM_CORE_PROFILE,
                             OSM_CONTEXT_MAJOR_VERSION, 3,
                             OSM_CONTEXT_MINOR_VERSION, 3,
                             0};
        o->ctx = o->CreateContextAttribs(attrs, NULL);
        if (!o->ctx)
            rc = ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                              "osmesa: OSMesaCreateContextAttribs (OpenGL 3.3 core) failed; "
                              "%s needs a gallium (llvmpipe) build of Mesa; " OSMESA_ADVICE,
                              o->lib_name);
    }
    if (rc == WW_OK &&
        !o->MakeCurrent(o->ctx, o->buf, GL_UNSIGNED_BYTE, OSMESA_BUF_SIZE, OSMESA_BUF_SIZE))
        rc = ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                          "osmesa: OSMesaMakeCurrent failed; " OSMESA_ADVICE);
    if (rc == WW_OK) {
        const char *missing = ww_gl_load(&b->gl, osm_loader, o);
        if (missing)
            rc = ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                              "osmesa: OSMesaGetProcAddress(\"%s\") returned NULL; %s is too old "
                              "for OpenGL 3.3 core; " OSMESA_ADVICE,
                              missing, o->lib_name);
    }
    if (rc != WW_OK) osm_close(b);
    return rc;
}
