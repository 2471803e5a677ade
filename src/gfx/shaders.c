/* shaders.c - shader text by file name: from $WW_SHADER_DIR when it is set (edit and re-run
 * without rebuilding), else from the table that scripts/embed-shaders.sh generates at build time.
 */
#include "gfx/shaders.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static char *copy_text(const char *text, size_t len) {
    char *s = malloc(len + 1);
    if (!s) return NULL;
    memcpy(s, text, len);
    s[len] = '\0';
    return s;
}

static ww_result read_shader_file(const char *path, char **out, ww_error *err) {
    FILE *f = fopen(path, "rb");
    if (!f)
        return ww_error_set(err, WW_E_NOFILE, path, 0, 0,
                            "cannot open shader (%s); WW_SHADER_DIR names a folder with every "
                            "shader file, or unset it to use the built-in shaders",
                            strerror(errno));
    size_t cap = 8192, n = 0, got;
    char *buf = malloc(cap + 1);
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) {
            char *nb = realloc(buf, cap * 2 + 1);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf) return ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory reading shader");
    if (bad) {
        free(buf);
        return ww_error_set(err, WW_E_NOFILE, path, 0, 0, "cannot read shader");
    }
    buf[n] = '\0';
    *out = buf;
    return WW_OK;
}

ww_result ww_shader_source(const char *name, char **out, ww_error *err) {
    WW_ASSERT(name && out);
    *out = NULL;

    /* development override: the file on disk wins, and must exist */
    const char *dir = getenv("WW_SHADER_DIR");
    if (dir && dir[0]) {
        char path[1024];
        int n = snprintf(path, sizeof path, "%s/%s", dir, name);
        if (n < 0 || (size_t)n >= sizeof path)
            return ww_error_set(err, WW_E_NOFILE, name, 0, 0, "WW_SHADER_DIR path is too long");
        return read_shader_file(path, out, err);
    }

    for (const ww_shader_file *f = ww_shader_files; f->name; f++) {
        if (strcmp(f->name, name) != 0) continue;
        *out = copy_text(f->text, f->len);
        if (!*out) return ww_error_set(err, WW_E_NOMEM, name, 0, 0, "out of memory");
        return WW_OK;
    }
    /* every name the renderer asks for is embedded: a miss is a build or code error */
    return ww_error_set(err, WW_E_NOFILE, name, 0, 0,
                        "no built-in shader of that name (is shaders/%s missing from the build?)",
                        name);
}
