/* program.c - builds GLSL programs from shader files: each stage is its file's #version line,
 * the shared defines (array limits, then the caller's, e.g. the wave model), the include files
 * (common.glsl, ...) and then the rest of the file, with #line directives so compiler messages
 * point into the right file. Errors name the file.
 */
#include <stdlib.h>
#include <string.h>

#include "gfx/render_impl.h"
#include "gfx/shaders.h"

#define WW_MAX_INCLUDES 4
#define WW_INFO_LOG 4096

/* "source 1 = common.glsl, source 2 = gerstner.glsl": how to read "1:12(3): error" */
static void source_key(const char *const *includes, char *buf, size_t size) {
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; includes && includes[i]; i++) {
        int n = snprintf(buf + used, size - used, "%ssource %d = %s", i ? ", " : " (", i + 1,
                         includes[i]);
        if (n < 0 || (size_t)n >= size - used) return;
        used += (size_t)n;
    }
    if (used && used + 2 < size) memcpy(buf + used, ")", 2);
}

/* the stage's text with the prelude spliced in after its first line (#version) */
static ww_result assemble(const char *name, const char *const *includes, const char *defines,
                          char **out, ww_error *err) {
    char *main_src = NULL, *inc_src[WW_MAX_INCLUDES] = {0};
    int ninc = 0;
    ww_result rc = ww_shader_source(name, &main_src, err);
    for (; rc == WW_OK && includes && includes[ninc]; ninc++) {
        WW_ASSERT(ninc < WW_MAX_INCLUDES);
        rc = ww_shader_source(includes[ninc], &inc_src[ninc], err);
    }

    char *text = NULL;
    if (rc == WW_OK) {
        const char *nl = strchr(main_src, '\n');
        if (strncmp(main_src, "#version", 8) != 0 || !nl) {
            rc = ww_error_set(err, WW_E_GL, name, 1, 1, "a shader must start with a #version line");
        } else {
            size_t head = (size_t)(nl + 1 - main_src);
            size_t size = strlen(main_src) + 256 + (defines ? strlen(defines) : 0);
            for (int i = 0; i < ninc; i++) size += strlen(inc_src[i]) + 32;
            text = malloc(size);
            if (!text) rc = ww_error_set(err, WW_E_NOMEM, name, 0, 0, "out of memory");
            if (text) {
                /* #line L S: the next line is line L of source string S (0 is the file itself) */
                size_t used = (size_t)snprintf(text, size,
                                               "%.*s#define WW_MAX_WAVES %d\n"
                                               "#define WW_MAX_RIPPLES %d\n%s",
                                               (int)head, main_src, WW_MAX_WAVES, WW_MAX_RIPPLES,
                                               defines ? defines : "");
                for (int i = 0; i < ninc; i++)
                    used += (size_t)snprintf(text + used, size - used, "#line 1 %d\n%s\n", i + 1,
                                             inc_src[i]);
                snprintf(text + used, size - used, "#line 2 0\n%s", main_src + head);
            }
        }
    }
    free(main_src);
    for (int i = 0; i < ninc; i++) free(inc_src[i]);
    *out = text;
    return rc;
}

static ww_result compile(const ww_gl *gl, GLenum type, const char *name,
                         const char *const *includes, const char *defines, GLuint *out,
                         ww_error *err) {
    char *text = NULL;
    ww_result rc = assemble(name, includes, defines, &text, err);
    if (rc != WW_OK) return rc;

    GLuint sh = gl->CreateShader(type);
    const GLchar *src = text;
    gl->ShaderSource(sh, 1, &src, NULL);
    gl->CompileShader(sh);
    free(text);
    GLint ok = 0;
    gl->GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[WW_INFO_LOG], key[256];
        gl->GetShaderInfoLog(sh, sizeof log, NULL, log);
        source_key(includes, key, sizeof key);
        gl->DeleteShader(sh);
        return ww_error_set(err, WW_E_GL, name, 0, 0, "shader compile failed%s:\n%s", key, log);
    }
    *out = sh;
    return WW_OK;
}

ww_result ww_gfx_program_defs(const ww_gl *gl, const char *vs, const char *fs,
                              const char *const *includes, const char *defines, GLuint *out,
                              ww_error *err) {
    GLuint v = 0, f = 0;
    *out = 0;
    ww_result rc = compile(gl, GL_VERTEX_SHADER, vs, includes, defines, &v, err);
    if (rc == WW_OK) rc = compile(gl, GL_FRAGMENT_SHADER, fs, includes, defines, &f, err);
    if (rc != WW_OK) {
        if (v) gl->DeleteShader(v);
        return rc;
    }

    GLuint p = gl->CreateProgram();
    gl->AttachShader(p, v);
    gl->AttachShader(p, f);
    gl->LinkProgram(p);
    /* the program keeps what it linked; the shader objects go once it is built */
    gl->DeleteShader(v);
    gl->DeleteShader(f);
    GLint ok = 0;
    gl->GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[WW_INFO_LOG];
        gl->GetProgramInfoLog(p, sizeof log, NULL, log);
        gl->DeleteProgram(p);
        return ww_error_set(err, WW_E_GL, fs, 0, 0, "program link failed (%s + %s):\n%s", vs, fs,
                            log);
    }
    *out = p;
    return WW_OK;
}

ww_result ww_gfx_program(const ww_gl *gl, const char *vs, const char *fs,
                         const char *const *includes, GLuint *out, ww_error *err) {
    return ww_gfx_program_defs(gl, vs, fs, includes, NULL, out, err);
}

GLint ww_gfx_uniform(const ww_gl *gl, GLuint prog, const char *name) {
    return gl->GetUniformLocation(prog, name);
}
