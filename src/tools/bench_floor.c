/* bench_floor.c - the backend's fill floor: the cost of one trivial full-screen pass (constant
 * colour into an RGBA16F target of the frame's size). Rendering can never be cheaper than this,
 * so bench reports render time as a multiple of it.
 */
#include "tools/bench.h"

#include "tools/job.h"

static const char *const vs_src =
    "#version 330 core\n"
    "void main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "              gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n";
static const char *const fs_src =
    "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.25, 0.5, 0.75, 1.0); }\n";

static GLuint compile(const ww_gl *gl, GLenum type, const char *src) {
    GLuint s = gl->CreateShader(type);
    gl->ShaderSource(s, 1, &src, NULL);
    gl->CompileShader(s);
    GLint ok = 0;
    gl->GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        gl->DeleteShader(s);
        return 0;
    }
    return s;
}

ww_result ww_bench_fill_floor(const ww_gl *gl, int w, int h, double *ms, ww_error *err) {
    GLuint vs = compile(gl, GL_VERTEX_SHADER, vs_src), fs = compile(gl, GL_FRAGMENT_SHADER, fs_src);
    GLuint prog = gl->CreateProgram(), tex = 0, fbo = 0, vao = 0;
    gl->AttachShader(prog, vs);
    gl->AttachShader(prog, fs);
    gl->LinkProgram(prog);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    GLint linked = 0;
    gl->GetProgramiv(prog, GL_LINK_STATUS, &linked);

    gl->GenTextures(1, &tex);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, NULL);
    gl->GenFramebuffers(1, &fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    gl->GenVertexArrays(1, &vao);
    ww_result r = WW_OK;
    if (!linked || gl->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        r = ww_error_set(err, WW_E_GL, NULL, 0, 0, "fill-floor pass could not be set up");
    } else {
        gl->Viewport(0, 0, w, h);
        gl->UseProgram(prog);
        gl->BindVertexArray(vao);
        /* warm up, then time */
        gl->DrawArrays(GL_TRIANGLES, 0, 3);
        gl->Finish();
        int n = 20;
        double t0 = ww_now_seconds();
        for (int i = 0; i < n; i++) {
            gl->DrawArrays(GL_TRIANGLES, 0, 3);
            gl->Finish();
        }
        *ms = 1e3 * (ww_now_seconds() - t0) / n;
    }
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->DeleteVertexArrays(1, &vao);
    gl->DeleteFramebuffers(1, &fbo);
    gl->DeleteTextures(1, &tex);
    gl->DeleteProgram(prog);
    return r;
}
