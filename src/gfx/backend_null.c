/* backend_null.c - the null backend: a GL 3.3 function table whose calls do nothing, after sokol's
 * SOKOL_DUMMY_BACKEND. Every program compiles and links, every framebuffer is complete, timer
 * queries read 0 ns and glReadPixels returns zeros, so a render job runs end to end without GL and
 * writes black frames. It exists so that the CLI and the render job (writers, resume, signals,
 * stats, the sound track) can be tested where no GL opens; `--backend null` picks it, auto never.
 */
#include <string.h>

#include "gfx/backend_impl.h"

/* stubs: each has the exact type of its table entry (the compiler checks the assignment below);
 * their parameters are unused by design */
#pragma GCC diagnostic ignored "-Wunused-parameter"

static GLenum APIENTRY n_GetError(void) { return GL_NO_ERROR; }

static const GLubyte *APIENTRY n_GetString(GLenum name) {
    const char *s = name == GL_RENDERER  ? "null"
                    : name == GL_VERSION ? "3.3 (waterworld null backend: no pixels)"
                    : name == GL_VENDOR  ? "waterworld"
                    : name == GL_SHADING_LANGUAGE_VERSION ? "3.30"
                                                          : "";
    return (const GLubyte *)s;
}

/* the limits the renderer asks for, as a modest GL 3.3 implementation has them */
static void APIENTRY n_GetIntegerv(GLenum pname, GLint *data) {
    *data = pname == GL_MAX_SAMPLES              ? 8
            : pname == GL_MAX_UNIFORM_BLOCK_SIZE ? 65536
            : pname == GL_MAX_TEXTURE_SIZE       ? 16384
                                                 : 0;
}

/* object names: never 0, not unique (nothing is ever looked up by name) */
static void gen_names(GLsizei n, GLuint *ids) {
    for (GLsizei i = 0; i < n; i++) ids[i] = 1;
}
static void APIENTRY n_GenTextures(GLsizei n, GLuint *ids) { gen_names(n, ids); }
static void APIENTRY n_GenFramebuffers(GLsizei n, GLuint *ids) { gen_names(n, ids); }
static void APIENTRY n_GenRenderbuffers(GLsizei n, GLuint *ids) { gen_names(n, ids); }
static void APIENTRY n_GenVertexArrays(GLsizei n, GLuint *ids) { gen_names(n, ids); }
static void APIENTRY n_GenBuffers(GLsizei n, GLuint *ids) { gen_names(n, ids); }
static void APIENTRY n_GenQueries(GLsizei n, GLuint *ids) { gen_names(n, ids); }
static GLuint APIENTRY n_CreateShader(GLenum type) { return 1; }
static GLuint APIENTRY n_CreateProgram(void) { return 1; }

/* compile and link always succeed, with empty logs */
static void APIENTRY n_GetShaderiv(GLuint shader, GLenum pname, GLint *params) {
    *params = pname == GL_COMPILE_STATUS ? GL_TRUE : 0;
}
static void APIENTRY n_GetProgramiv(GLuint program, GLenum pname, GLint *params) {
    *params = pname == GL_LINK_STATUS ? GL_TRUE : 0;
}
static void APIENTRY n_GetShaderInfoLog(GLuint shader, GLsizei bufSize, GLsizei *length,
                                        GLchar *infoLog) {
    if (length) *length = 0;
    if (bufSize > 0) infoLog[0] = 0;
}
static void APIENTRY n_GetProgramInfoLog(GLuint program, GLsizei bufSize, GLsizei *length,
                                         GLchar *infoLog) {
    n_GetShaderInfoLog(program, bufSize, length, infoLog);
}
static GLint APIENTRY n_GetUniformLocation(GLuint program, const GLchar *name) { return 0; }
/* no program reads a uniform block: the renderer then binds none */
static GLuint APIENTRY n_GetUniformBlockIndex(GLuint program, const GLchar *name) {
    return GL_INVALID_INDEX;
}
static void APIENTRY n_GetActiveUniformBlockiv(GLuint program, GLuint index, GLenum pname,
                                               GLint *params) {
    *params = 0;
}
static GLenum APIENTRY n_CheckFramebufferStatus(GLenum target) { return GL_FRAMEBUFFER_COMPLETE; }

/* zeros, tightly packed: never more than the caller's buffer holds at any pack alignment */
static void APIENTRY n_ReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                                  GLenum type, void *pixels) {
    size_t comps = format == GL_RGBA ? 4 : format == GL_RGB ? 3 : format == GL_RG ? 2 : 1;
    size_t bytes = type == GL_FLOAT ? 4 : type == GL_HALF_FLOAT || type == GL_UNSIGNED_SHORT ? 2 : 1;
    if (width > 0 && height > 0 && pixels)
        memset(pixels, 0, (size_t)width * (size_t)height * comps * bytes);
}

/* timer queries are always ready and measure nothing */
static void APIENTRY n_GetQueryObjectiv(GLuint id, GLenum pname, GLint *params) { *params = 1; }
static void APIENTRY n_GetQueryObjectui64v(GLuint id, GLenum pname, GLuint64 *params) {
    *params = 0;
}
static void APIENTRY n_GetQueryiv(GLenum target, GLenum pname, GLint *params) {
    *params = pname == GL_QUERY_COUNTER_BITS ? 64 : 0;
}

/* everything else does nothing */
static void APIENTRY n_Viewport(GLint x, GLint y, GLsizei width, GLsizei height) {}
static void APIENTRY n_ClearColor(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {}
static void APIENTRY n_ClearDepth(GLdouble depth) {}
static void APIENTRY n_Clear(GLbitfield mask) {}
static void APIENTRY n_Enable(GLenum cap) {}
static void APIENTRY n_Disable(GLenum cap) {}
static void APIENTRY n_DepthFunc(GLenum func) {}
static void APIENTRY n_DepthMask(GLboolean flag) {}
static void APIENTRY n_BlendFunc(GLenum sfactor, GLenum dfactor) {}
static void APIENTRY n_CullFace(GLenum mode) {}
static void APIENTRY n_Finish(void) {}
static void APIENTRY n_Flush(void) {}
static void APIENTRY n_PixelStorei(GLenum pname, GLint param) {}
static void APIENTRY n_ReadBuffer(GLenum src) {}
static void APIENTRY n_DrawBuffers(GLsizei n, const GLenum *bufs) {}
static void APIENTRY n_DeleteTextures(GLsizei n, const GLuint *textures) {}
static void APIENTRY n_BindTexture(GLenum target, GLuint texture) {}
static void APIENTRY n_ActiveTexture(GLenum texture) {}
static void APIENTRY n_TexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                     GLsizei height, GLint border, GLenum format, GLenum type,
                     const void *pixels) {}
static void APIENTRY n_TexImage3D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                     GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                     const void *pixels) {}
static void APIENTRY n_TexParameteri(GLenum target, GLenum pname, GLint param) {}
static void APIENTRY n_DeleteFramebuffers(GLsizei n, const GLuint *framebuffers) {}
static void APIENTRY n_BindFramebuffer(GLenum target, GLuint framebuffer) {}
static void APIENTRY n_FramebufferTexture2D(GLenum target, GLenum attachment, GLenum textarget,
                     GLuint texture, GLint level) {}
static void APIENTRY n_DeleteRenderbuffers(GLsizei n, const GLuint *renderbuffers) {}
static void APIENTRY n_BindRenderbuffer(GLenum target, GLuint renderbuffer) {}
static void APIENTRY n_RenderbufferStorage(GLenum target, GLenum internalformat, GLsizei width,
                     GLsizei height) {}
static void APIENTRY n_FramebufferRenderbuffer(GLenum target, GLenum attachment,
                     GLenum renderbuffertarget, GLuint renderbuffer) {}
static void APIENTRY n_DeleteShader(GLuint shader) {}
static void APIENTRY n_ShaderSource(GLuint shader, GLsizei count, const GLchar *const *string,
                     const GLint *length) {}
static void APIENTRY n_CompileShader(GLuint shader) {}
static void APIENTRY n_DeleteProgram(GLuint program) {}
static void APIENTRY n_AttachShader(GLuint program, GLuint shader) {}
static void APIENTRY n_LinkProgram(GLuint program) {}
static void APIENTRY n_UseProgram(GLuint program) {}
static void APIENTRY n_Uniform1i(GLint location, GLint v0) {}
static void APIENTRY n_Uniform2i(GLint location, GLint v0, GLint v1) {}
static void APIENTRY n_Uniform1f(GLint location, GLfloat v0) {}
static void APIENTRY n_Uniform2f(GLint location, GLfloat v0, GLfloat v1) {}
static void APIENTRY n_Uniform3f(GLint location, GLfloat v0, GLfloat v1, GLfloat v2) {}
static void APIENTRY n_Uniform4f(GLint location, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3) {}
static void APIENTRY n_Uniform1fv(GLint location, GLsizei count, const GLfloat *value) {}
static void APIENTRY n_Uniform2fv(GLint location, GLsizei count, const GLfloat *value) {}
static void APIENTRY n_Uniform3fv(GLint location, GLsizei count, const GLfloat *value) {}
static void APIENTRY n_Uniform4fv(GLint location, GLsizei count, const GLfloat *value) {}
static void APIENTRY n_UniformMatrix4fv(GLint location, GLsizei count, GLboolean transpose,
                     const GLfloat *value) {}
static void APIENTRY n_DeleteVertexArrays(GLsizei n, const GLuint *arrays) {}
static void APIENTRY n_BindVertexArray(GLuint array) {}
static void APIENTRY n_DeleteBuffers(GLsizei n, const GLuint *buffers) {}
static void APIENTRY n_BindBuffer(GLenum target, GLuint buffer) {}
static void APIENTRY n_BufferData(GLenum target, GLsizeiptr size, const void *data, GLenum usage) {}
static void APIENTRY n_EnableVertexAttribArray(GLuint index) {}
static void APIENTRY n_VertexAttribPointer(GLuint index, GLint size, GLenum type,
                     GLboolean normalized, GLsizei stride, const void *pointer) {}
static void APIENTRY n_DrawArrays(GLenum mode, GLint first, GLsizei count) {}
static void APIENTRY n_DrawElements(GLenum mode, GLsizei count, GLenum type, const void *indices) {}
static void APIENTRY n_BufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                     const void *data) {}
static void APIENTRY n_BindBufferBase(GLenum target, GLuint index, GLuint buffer) {}
static void APIENTRY n_UniformBlockBinding(GLuint program, GLuint uniformBlockIndex,
                     GLuint uniformBlockBinding) {}
static void APIENTRY n_VertexAttribDivisor(GLuint index, GLuint divisor) {}
static void APIENTRY n_DrawElementsInstanced(GLenum mode, GLsizei count, GLenum type,
                     const void *indices, GLsizei instancecount) {}
static void APIENTRY n_DrawArraysInstanced(GLenum mode, GLint first, GLsizei count,
                     GLsizei instancecount) {}
static void APIENTRY n_GenerateMipmap(GLenum target) {}
static void APIENTRY n_TexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                     GLsizei width, GLsizei height, GLenum format, GLenum type,
                     const void *pixels) {}
static void APIENTRY n_TexParameterf(GLenum target, GLenum pname, GLfloat param) {}
static void APIENTRY n_TexParameterfv(GLenum target, GLenum pname, const GLfloat *params) {}
static void APIENTRY n_TexImage2DMultisample(GLenum target, GLsizei samples, GLenum internalformat,
                     GLsizei width, GLsizei height, GLboolean fixedsamplelocations) {}
static void APIENTRY n_RenderbufferStorageMultisample(GLenum target, GLsizei samples,
                     GLenum internalformat, GLsizei width, GLsizei height) {}
static void APIENTRY n_BlitFramebuffer(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1,
                     GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask,
                     GLenum filter) {}
static void APIENTRY n_BlendFuncSeparate(GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha,
                     GLenum dfactorAlpha) {}
static void APIENTRY n_BlendEquation(GLenum mode) {}
static void APIENTRY n_ColorMask(GLboolean red, GLboolean green, GLboolean blue, GLboolean alpha) {}
static void APIENTRY n_PolygonOffset(GLfloat factor, GLfloat units) {}
static void APIENTRY n_FrontFace(GLenum mode) {}
static void APIENTRY n_DrawBuffer(GLenum buf) {}
static void APIENTRY n_Uniform1iv(GLint location, GLsizei count, const GLint *value) {}
static void APIENTRY n_UniformMatrix3fv(GLint location, GLsizei count, GLboolean transpose,
                     const GLfloat *value) {}
static void APIENTRY n_VertexAttrib4f(GLuint index, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {}
static void APIENTRY n_DeleteQueries(GLsizei n, const GLuint *ids) {}
static void APIENTRY n_BeginQuery(GLenum target, GLuint id) {}
static void APIENTRY n_EndQuery(GLenum target) {}
static void APIENTRY n_QueryCounter(GLuint id, GLenum target) {}
static void APIENTRY n_ClearStencil(GLint s) {}
static void APIENTRY n_StencilFunc(GLenum func, GLint ref, GLuint mask) {}
static void APIENTRY n_StencilOpSeparate(GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass) {}
static void APIENTRY n_StencilMask(GLuint mask) {}

static void null_close(ww_backend *b) { (void)b; }

ww_result ww_backend_null_open(ww_backend *b, ww_error *err) {
    (void)err;
#define WW_NULL_FILL(type, name) b->gl.name = n_##name;
    WW_GL_FUNCS(WW_NULL_FILL)
#undef WW_NULL_FILL
    snprintf(b->describe, sizeof b->describe, "null");
    b->close = null_close;
    return WW_OK;
}
