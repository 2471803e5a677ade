/* cmd_backends.c - `waterworld backends`: which GL backends open here, and what they run on. */
#include <stdio.h>
#include <string.h>

#include "check/golden.h"
#include "cli/cli.h"
#include "gfx/backend.h"

static const char usage[] =
    "usage: waterworld backends [--renderer | --key]\n"
    "\n"
    "Opens each GL backend (auto, egl, osmesa) and prints what it runs on, or why it failed.\n"
    "  --renderer   print only \"GL_RENDERER | GL_VERSION\" of the auto backend (golden/RENDERER)\n"
    "  --key        print only the auto backend's renderer key, e.g. llvmpipe-mesa-22.3: the\n"
    "               folder render --golden DIR looks in first (DIR/KEY/frame_XXXXX.png)\n"
    "\n"
    "A last line, advice:, says what (if anything) to install, for this machine's Mesa.\n"
    "Exit: 0 when at least one backend opens, 3 when none does.\n";

/* OSMesa left Mesa in 25.1: from then on no release packages it */
#define MESA_WITHOUT_OSMESA_MAJOR 25
#define MESA_WITHOUT_OSMESA_MINOR 1

const char *ww_cli_backends_advice(int egl_ok, const char *egl_version, int osmesa_ok) {
    if (egl_ok && osmesa_ok) return NULL;
    if (!egl_ok && !osmesa_ok)
        return "no backend opens: install libegl1, libegl-mesa0 and libgl1-mesa-dri (Debian); "
               "EGL is the path forward";
    if (!egl_ok)
        return "rendering goes through OSMesa; EGL is the path forward (Mesa 25.1 removed "
               "OSMesa): install libegl1, libegl-mesa0 and libgl1-mesa-dri (Debian)";
    const char *m = egl_version ? strstr(egl_version, "Mesa ") : NULL;
    int major = 0, minor = 0;
    if (!m || sscanf(m + 5, "%d.%d", &major, &minor) != 2)
        return "EGL is the path; OSMesa is optional (nothing needs it)";
    if (major > MESA_WITHOUT_OSMESA_MAJOR ||
        (major == MESA_WITHOUT_OSMESA_MAJOR && minor >= MESA_WITHOUT_OSMESA_MINOR))
        return "EGL is the path: this Mesa has no OSMesa (removed in 25.1), and nothing needs it; "
               "OSMesa is optional, there is nothing to install";
    return "EGL is the path; OSMesa is optional (libosmesa6 on Debian 12 and 13 adds it, for "
           "--backend osmesa and the tests that compare the two)";
}

ww_result ww_cmd_backends(int argc, char **argv, ww_error *err) {
    int only_renderer = 0, only_key = 0;
    for (int i = 0; i < argc; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (strcmp(argv[i], "--renderer") == 0) {
            only_renderer = 1;
            continue;
        }
        if (strcmp(argv[i], "--key") == 0) {
            only_key = 1;
            continue;
        }
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "backends: unknown option '%s'", argv[i]);
    }
    static const struct { const char *name; ww_backend_kind kind; } kinds[] = {
        {"auto", WW_BACKEND_AUTO}, {"egl", WW_BACKEND_EGL}, {"osmesa", WW_BACKEND_OSMESA}};
    int opened = 0, egl_ok = 0, osmesa_ok = 0;
    char egl_version[256] = "";
    ww_error last = {0};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        ww_backend *b = NULL;
        ww_error e = {0};
        if (ww_backend_open(kinds[k].kind, &b, &e) == WW_OK) {
            opened++;
            char key[WW_GOLDEN_KEY_SIZE];
            ww_golden_renderer_key(ww_backend_renderer(b), ww_backend_version(b), key, sizeof key);
            if (only_key) {
                printf("%s\n", key);
                ww_backend_close(b);
                return WW_OK;
            }
            if (only_renderer) {
                printf("%s | %s\n", ww_backend_renderer(b), ww_backend_version(b));
                ww_backend_close(b);
                return WW_OK;
            }
            printf("%-7s %-16s %s | %s (key %s)\n", kinds[k].name, ww_backend_describe(b),
                   ww_backend_renderer(b), ww_backend_version(b), key);
            if (kinds[k].kind == WW_BACKEND_EGL) {
                egl_ok = 1;
                snprintf(egl_version, sizeof egl_version, "%s", ww_backend_version(b));
            }
            osmesa_ok |= kinds[k].kind == WW_BACKEND_OSMESA;
            ww_backend_close(b);
        } else {
            last = e;
            if (!only_renderer && !only_key) printf("%-7s unavailable: %s\n", kinds[k].name, e.msg);
        }
    }
    const char *advice = ww_cli_backends_advice(egl_ok, egl_version, osmesa_ok);
    if (advice && !only_renderer && !only_key) printf("advice: %s\n", advice);
    if (opened) return WW_OK;
    *err = last;
    return last.code ? last.code : WW_E_BACKEND;
}
