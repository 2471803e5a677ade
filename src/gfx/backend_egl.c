/* backend_egl.c - a headless GL 3.3 core context from EGL, with libEGL loaded by dlopen.
 * The device platform (EGL_EXT_platform_device) is tried first for a hardware GPU, then Mesa's
 * surfaceless platform (llvmpipe); the context is made current with no surface at all, since
 * the renderer draws into its own framebuffers.
 */
#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>

#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gfx/backend_impl.h"

#define EGL_LIB "libEGL.so.1"
#define EGL_MAX_DEVICES 16
/* OSMesa, the other backend, is only there with a Mesa older than 25.1 */
#define EGL_OTHER "try --backend osmesa (Mesa older than 25.1 only)"
#define EGL_ADVICE "install libegl1, libegl-mesa0 and libgl1-mesa-dri (Debian), or " EGL_OTHER

typedef struct egl_fns {
    PFNEGLGETPROCADDRESSPROC GetProcAddress;
    PFNEGLGETERRORPROC GetError;
    PFNEGLQUERYSTRINGPROC QueryString;
    PFNEGLINITIALIZEPROC Initialize;
    PFNEGLTERMINATEPROC Terminate;
    PFNEGLBINDAPIPROC BindAPI;
    PFNEGLCHOOSECONFIGPROC ChooseConfig;
    PFNEGLCREATECONTEXTPROC CreateContext;
    PFNEGLDESTROYCONTEXTPROC DestroyContext;
    PFNEGLMAKECURRENTPROC MakeCurrent;
    PFNEGLRELEASETHREADPROC ReleaseThread;
    /* extensions, NULL when absent */
    PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT;
    PFNEGLQUERYDEVICESEXTPROC QueryDevicesEXT;
    PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceStringEXT;
} egl_fns;

typedef struct egl_impl {
    void *lib;
    egl_fns f;
    EGLDisplay dpy;
    EGLContext ctx;
} egl_impl;

typedef enum egl_platform { PLAT_ANY = 0, PLAT_DEVICE, PLAT_SURFACELESS } egl_platform;

static const char *egl_error_name(EGLint e) {
    switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
    default: return "unknown EGL error";
    }
}

/* whole-word search in a space-separated extension string */
static int has_ext(const char *list, const char *name) {
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += n) {
        int starts = p == list || p[-1] == ' ';
        int ends = p[n] == '\0' || p[n] == ' ';
        if (starts && ends) return 1;
    }
    return 0;
}

/* "eglX failed: EGL_BAD_MATCH (0x3009)" plus the advice */
static ww_result egl_fail(egl_impl *e, ww_error *err, const char *call, const char *advice) {
    EGLint code = e->f.GetError ? e->f.GetError() : EGL_SUCCESS;
    return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0, "egl: %s failed: %s (0x%04x); %s", call,
                        egl_error_name(code), (unsigned)code, advice);
}

static ww_result load_fns(egl_impl *e, ww_error *err) {
    /* dlsym yields a void *; going through a union avoids the object-to-function pointer cast */
    union {
        void *obj;
        PFNEGLGETPROCADDRESSPROC fn;
    } gpa;
    gpa.obj = dlsym(e->lib, "eglGetProcAddress");
    if (!gpa.obj)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "egl: %s has no eglGetProcAddress; " EGL_ADVICE, EGL_LIB);
    e->f.GetProcAddress = gpa.fn;

    /* core entry points are exported by libEGL; eglGetProcAddress returns them too (EGL 1.5) */
#define EGL_CORE(type, field, name)                                                              \
    e->f.field = (type)e->f.GetProcAddress(name);                                               \
    if (!e->f.field)                                                                            \
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,                                      \
                            "egl: %s lacks %s; " EGL_ADVICE, EGL_LIB, name);
    EGL_CORE(PFNEGLGETERRORPROC, GetError, "eglGetError")
    EGL_CORE(PFNEGLQUERYSTRINGPROC, QueryString, "eglQueryString")
    EGL_CORE(PFNEGLINITIALIZEPROC, Initialize, "eglInitialize")
    EGL_CORE(PFNEGLTERMINATEPROC, Terminate, "eglTerminate")
    EGL_CORE(PFNEGLBINDAPIPROC, BindAPI, "eglBindAPI")
    EGL_CORE(PFNEGLCHOOSECONFIGPROC, ChooseConfig, "eglChooseConfig")
    EGL_CORE(PFNEGLCREATECONTEXTPROC, CreateContext, "eglCreateContext")
    EGL_CORE(PFNEGLDESTROYCONTEXTPROC, DestroyContext, "eglDestroyContext")
    EGL_CORE(PFNEGLMAKECURRENTPROC, MakeCurrent, "eglMakeCurrent")
    EGL_CORE(PFNEGLRELEASETHREADPROC, ReleaseThread, "eglReleaseThread")
#undef EGL_CORE

    e->f.GetPlatformDisplayEXT =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)e->f.GetProcAddress("eglGetPlatformDisplayEXT");
    e->f.QueryDevicesEXT = (PFNEGLQUERYDEVICESEXTPROC)e->f.GetProcAddress("eglQueryDevicesEXT");
    e->f.QueryDeviceStringEXT =
        (PFNEGLQUERYDEVICESTRINGEXTPROC)e->f.GetProcAddress("eglQueryDeviceStringEXT");
    return WW_OK;
}

/* a display on the device platform: device `want` when >= 0, else the first hardware device
 * (devices that advertise EGL_MESA_device_software are llvmpipe, which surfaceless covers) */
static ww_result device_display(egl_impl *e, const char *client_ext, int want, int forced,
                                ww_error *err) {
    if (!has_ext(client_ext, "EGL_EXT_platform_device") || !e->f.QueryDevicesEXT ||
        !e->f.GetPlatformDisplayEXT)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "egl: the device platform is not available (no "
                            "EGL_EXT_platform_device); set WW_EGL_PLATFORM=surfaceless");

    EGLDeviceEXT devs[EGL_MAX_DEVICES];
    EGLint n = 0;
    if (!e->f.QueryDevicesEXT(EGL_MAX_DEVICES, devs, &n))
        return egl_fail(e, err, "eglQueryDevicesEXT", "set WW_EGL_PLATFORM=surfaceless");
    if (want >= n)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "egl: WW_EGL_DEVICE=%d but only %d EGL device(s) exist", want, (int)n);

    int pick = want;
    for (EGLint i = 0; pick < 0 && i < n; i++) {
        const char *ext =
            e->f.QueryDeviceStringEXT ? e->f.QueryDeviceStringEXT(devs[i], EGL_EXTENSIONS) : NULL;
        if (!has_ext(ext, "EGL_MESA_device_software")) pick = (int)i;
    }
    /* a forced device platform may use the software device: it is still the device path */
    if (pick < 0 && forced && n > 0) pick = 0;
    if (pick < 0)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "egl: no hardware EGL device among %d device(s)", (int)n);

    e->dpy = e->f.GetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devs[pick], NULL);
    if (e->dpy == EGL_NO_DISPLAY)
        return egl_fail(e, err, "eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT)",
                        "set WW_EGL_PLATFORM=surfaceless or WW_EGL_DEVICE=N");
    if (!e->f.Initialize(e->dpy, NULL, NULL)) {
        ww_result rc = egl_fail(e, err, "eglInitialize (device platform)",
                                "check the GPU driver's EGL vendor library, or set "
                                "WW_EGL_PLATFORM=surfaceless");
        e->dpy = EGL_NO_DISPLAY;
        return rc;
    }
    return WW_OK;
}

static ww_result surfaceless_display(egl_impl *e, const char *client_ext, ww_error *err) {
    if (!has_ext(client_ext, "EGL_MESA_platform_surfaceless") || !e->f.GetPlatformDisplayEXT)
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "egl: the surfaceless platform is not available (no "
                            "EGL_MESA_platform_surfaceless); " EGL_ADVICE);
    e->dpy = e->f.GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (e->dpy == EGL_NO_DISPLAY)
        return egl_fail(e, err, "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)",
                        EGL_ADVICE);
    if (!e->f.Initialize(e->dpy, NULL, NULL)) {
        ww_result rc = egl_fail(e, err, "eglInitialize (surfaceless platform)", EGL_ADVICE);
        e->dpy = EGL_NO_DISPLAY;
        return rc;
    }
    return WW_OK;
}

/* choose the platform from WW_EGL_PLATFORM / WW_EGL_DEVICE and initialise a display on it */
static ww_result open_display(egl_impl *e, ww_backend *b, ww_error *err) {
    const char *penv = getenv("WW_EGL_PLATFORM");
    const char *denv = getenv("WW_EGL_DEVICE");
    egl_platform plat = PLAT_ANY;
    if (penv && penv[0]) {
        if (strcmp(penv, "device") == 0)
            plat = PLAT_DEVICE;
        else if (strcmp(penv, "surfaceless") == 0)
            plat = PLAT_SURFACELESS;
        else
            return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                                "egl: WW_EGL_PLATFORM=%s is not one of device, surfaceless", penv);
    }
    int want = -1;
    if (denv && denv[0]) {
        char *end = NULL;
        long v = strtol(denv, &end, 10);
        if (*end != '\0' || v < 0 || v >= EGL_MAX_DEVICES)
            return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                                "egl: WW_EGL_DEVICE=%s is not a device index 0..%d", denv,
                                EGL_MAX_DEVICES - 1);
        want = (int)v;
        if (plat == PLAT_ANY) plat = PLAT_DEVICE;
    }

    /* client extensions (EGL_EXT_client_extensions): NULL when even that is missing */
    const char *client_ext = e->f.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client_ext) client_ext = "";

    if (plat != PLAT_SURFACELESS) {
        ww_error dev_err = {0};
        if (device_display(e, client_ext, want, plat == PLAT_DEVICE, &dev_err) == WW_OK) {
            snprintf(b->describe, sizeof b->describe, "egl/device");
            return WW_OK;
        }
        if (plat == PLAT_DEVICE) {
            if (err) *err = dev_err;
            return WW_E_BACKEND;
        }
    }
    ww_result rc = surfaceless_display(e, client_ext, err);
    if (rc == WW_OK) snprintf(b->describe, sizeof b->describe, "egl/surfaceless");
    return rc;
}

static ww_result make_context(egl_impl *e, ww_error *err) {
    const char *dpy_ext = e->f.QueryString(e->dpy, EGL_EXTENSIONS);
    if (!has_ext(dpy_ext, "EGL_KHR_surfaceless_context"))
        return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                            "egl: the display lacks EGL_KHR_surfaceless_context (needed to render "
                            "without a window); " EGL_OTHER);
    if (!e->f.BindAPI(EGL_OPENGL_API))
        return egl_fail(e, err, "eglBindAPI(EGL_OPENGL_API)",
                        "this EGL has no desktop OpenGL; " EGL_OTHER);

    /* any config will do: nothing is drawn to an EGL surface */
    EGLConfig cfg = EGL_NO_CONFIG_KHR;
    if (!has_ext(dpy_ext, "EGL_KHR_no_config_context")) {
        const EGLint want[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint n = 0;
        if (!e->f.ChooseConfig(e->dpy, want, &cfg, 1, &n))
            return egl_fail(e, err, "eglChooseConfig", EGL_ADVICE);
        if (n < 1)
            return ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                                "egl: eglChooseConfig found no config with EGL_OPENGL_BIT; "
                                EGL_OTHER);
    }

    const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_NONE};
    e->ctx = e->f.CreateContext(e->dpy, cfg, EGL_NO_CONTEXT, attrs);
    if (e->ctx == EGL_NO_CONTEXT)
        return egl_fail(e, err, "eglCreateContext (OpenGL 3.3 core)",
                        "the driver needs OpenGL 3.3 core (Mesa >= 10 with llvmpipe has it)");
    if (!e->f.MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx))
        return egl_fail(e, err, "eglMakeCurrent (no surface)", EGL_OTHER);
    return WW_OK;
}

static ww_gl_proc egl_loader(const char *name, void *user) {
    const egl_impl *e = user;
    return (ww_gl_proc)e->f.GetProcAddress(name);
}

static void egl_close(ww_backend *b) {
    egl_impl *e = b->impl;
    if (!e) return;
    if (e->dpy != EGL_NO_DISPLAY) {
        e->f.MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (e->ctx != EGL_NO_CONTEXT) e->f.DestroyContext(e->dpy, e->ctx);
        e->f.Terminate(e->dpy);
    }
    if (e->f.ReleaseThread) e->f.ReleaseThread();
    if (e->lib) dlclose(e->lib);
    free(e);
    b->impl = NULL;
}

ww_result ww_backend_egl_open(ww_backend *b, ww_error *err) {
    egl_impl *e = calloc(1, sizeof *e);
    if (!e) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "egl: out of memory");
    e->dpy = EGL_NO_DISPLAY;
    e->ctx = EGL_NO_CONTEXT;
    b->impl = e;
    b->close = egl_close;

    ww_result rc = WW_OK;
    e->lib = dlopen(EGL_LIB, RTLD_NOW | RTLD_LOCAL);
    if (!e->lib)
        rc = ww_error_set(err, WW_E_BACKEND, NULL, 0, 0, "egl: cannot load %s (%s); " EGL_ADVICE,
                          EGL_LIB, dlerror());
    if (rc == WW_OK) rc = load_fns(e, err);
    if (rc == WW_OK) rc = open_display(e, b, err);
    if (rc == WW_OK) rc = make_context(e, err);
    if (rc == WW_OK) {
        const char *missing = ww_gl_load(&b->gl, egl_loader, e);
        if (missing)
            rc = ww_error_set(err, WW_E_BACKEND, NULL, 0, 0,
                              "egl: eglGetProcAddress(\"%s\") returned NULL; the driver's OpenGL "
                              "is incomplete; " EGL_OTHER,
                              missing);
    }
    if (rc != WW_OK) egl_close(b);
    return rc;
}
