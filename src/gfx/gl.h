/* gl.h - the OpenGL 3.3 core function table, loaded through the backend's get-proc-address.
 * Declared once in WW_GL_FUNCS (name without the gl prefix); call as gl->Clear(...).
 * No globals: the table lives in the backend and is passed to whoever draws.
 */
#ifndef WW_GL_H
#define WW_GL_H

#define GL_GLEXT_PROTOTYPES 0
#include <GL/glcorearb.h>

#define WW_GL_FUNCS(X)                                                                            \
    X(PFNGLGETERRORPROC, GetError)                                                               \
    X(PFNGLGETSTRINGPROC, GetString)                                                             \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                         \
    X(PFNGLVIEWPORTPROC, Viewport)                                                               \
    X(PFNGLCLEARCOLORPROC, ClearColor)                                                           \
    X(PFNGLCLEARDEPTHPROC, ClearDepth)                                                           \
    X(PFNGLCLEARPROC, Clear)                                                                     \
    X(PFNGLENABLEPROC, Enable)                                                                   \
    X(PFNGLDISABLEPROC, Disable)                                                                 \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                             \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                                             \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                                                             \
    X(PFNGLCULLFACEPROC, CullFace)                                                               \
    X(PFNGLFINISHPROC, Finish)                                                                   \
    X(PFNGLFLUSHPROC, Flush)                                                                     \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                         \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                           \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                                           \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                         \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                                         \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                   \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                                         \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                     \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                           \
    X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                                           \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                     \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                 \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                           \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                 \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                       \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                   \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                               \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                                         \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                               \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                                         \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                                 \
    X(PFNGLCREATESHADERPROC, CreateShader)                                                       \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                                       \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                       \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                                     \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                         \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                               \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                     \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                     \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                                       \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                         \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                       \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                             \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                           \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                           \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                                             \
    X(PFNGLUNIFORM2IPROC, Uniform2i)                                                             \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                                             \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                                             \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                                             \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                                             \
    X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                                           \
    X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                                           \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                           \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                           \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                               \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                 \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                           \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                 \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                                           \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                     \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                           \
    X(PFNGLBUFFERDATAPROC, BufferData)                                                           \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                 \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                         \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                           \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                       \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                                     \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                                   \
    X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)                                       \
    X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding)                                         \
    X(PFNGLGETACTIVEUNIFORMBLOCKIVPROC, GetActiveUniformBlockiv)                                 \
    X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)                                         \
    X(PFNGLDRAWELEMENTSINSTANCEDPROC, DrawElementsInstanced)                                     \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)                                         \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                                                   \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                                     \
    X(PFNGLTEXPARAMETERFPROC, TexParameterf)                                                     \
    X(PFNGLTEXPARAMETERFVPROC, TexParameterfv)                                                   \
    X(PFNGLTEXIMAGE2DMULTISAMPLEPROC, TexImage2DMultisample)                                     \
    X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample)                   \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                                 \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                                             \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                                     \
    X(PFNGLCOLORMASKPROC, ColorMask)                                                             \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                                                     \
    X(PFNGLFRONTFACEPROC, FrontFace)                                                             \
    X(PFNGLDRAWBUFFERPROC, DrawBuffer)                                                           \
    X(PFNGLUNIFORM1IVPROC, Uniform1iv)                                                           \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                                               \
    X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f)                                                   \
    X(PFNGLGENQUERIESPROC, GenQueries)                                                           \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                                     \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                                           \
    X(PFNGLENDQUERYPROC, EndQuery)                                                               \
    X(PFNGLQUERYCOUNTERPROC, QueryCounter)                                                       \
    X(PFNGLGETQUERYOBJECTIVPROC, GetQueryObjectiv)                                               \
    X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)                                         \
    X(PFNGLGETQUERYIVPROC, GetQueryiv) /* rbench: the timer's counter bits */                      \
    X(PFNGLCLEARSTENCILPROC, ClearStencil) /* stencilled shadows (stencil_shadows.c) */            \
    X(PFNGLSTENCILFUNCPROC, StencilFunc)                                                         \
    X(PFNGLSTENCILOPSEPARATEPROC, StencilOpSeparate)                                             \
    X(PFNGLSTENCILMASKPROC, StencilMask)

typedef struct ww_gl {
#define WW_GL_DECL(type, name) type name;
    WW_GL_FUNCS(WW_GL_DECL)
#undef WW_GL_DECL
} ww_gl;

typedef void (*ww_gl_proc)(void);
typedef ww_gl_proc (*ww_gl_loader)(const char *name, void *user);

/* fill gl from loader("glClear", user) ...; on a missing entry point returns its name, else NULL */
const char *ww_gl_load(ww_gl *gl, ww_gl_loader loader, void *user);

#endif
