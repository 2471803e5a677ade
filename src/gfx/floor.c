/* floor.c - the backend's fill floor: the cost of one trivial full-screen pass (constant
 * colour into an RGBA16F target of the frame's size). Rendering can never be cheaper than this,
 * so bench reports render time as a multiple of it.
 */
#include <time.h>

#include "gfx/render_impl.h"

static double now_seconds(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* GPU ms per pass: n passes back to back inside one GL_TIME_ELAPSED query; -1 without a timer */
static double timed_on_gpu(const ww_gl *gl, int n) {
    GLint bits = 0;
    gl->GetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    if (bits <= 0) return -1.0;
    GLuint q = 0;
    GLuint64 ns = 0;
    gl->GenQueries(1, &q);
    gl->BeginQuery(GL_TIME_ELAPSED, q);
    for (int i = 0; i < n; i++) {
        gl->DrawArrays(GL_TRIANGLES, 0, 3);
        gl->Flush();
    }
    gl->EndQuery(GL_TIME_ELAPSED);
    gl->GetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
    gl->DeleteQueries(1, &q);
    return 1e-6 * (double)ns / n;
}

ww_result ww_gfx_fill_floor(const ww_gl *gl, int w, int h, double *ms, double *gpu_ms,
                            ww_error *err) {
    *gpu_ms = -1.0;
    GLuint prog = 0, tex = 0, fbo = 0, vao = 0;
    ww_result r = ww_gfx_program(gl, "fullscreen.vert.glsl", "floor.frag.glsl", NULL, &prog, err);
    if (r != WW_OK) return r;

    gl->GenTextures(1, &tex);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, NULL);
    gl->GenFramebuffers(1, &fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    gl->GenVertexArrays(1, &vao);
    if (gl->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        r = ww_error_set(err, WW_E_GL, NULL, 0, 0, "fill-floor pass could not be set up");
    } else {
        gl->Viewport(0, 0, w, h);
        gl->UseProgram(prog);
        gl->BindVertexArray(vao);
        /* warm up, then time */
        gl->DrawArrays(GL_TRIANGLES, 0, 3);
        gl->Finish();
        int n = 20;
        double t0 = now_seconds();
        for (int i = 0; i < n; i++) {
            gl->DrawArrays(GL_TRIANGLES, 0, 3);
            gl->Finish();
        }
        *ms = 1e3 * (now_seconds() - t0) / n;
        *gpu_ms = timed_on_gpu(gl, n);
    }
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->DeleteVertexArrays(1, &vao);
    gl->DeleteFramebuffers(1, &fbo);
    gl->DeleteTextures(1, &tex);
    gl->DeleteProgram(prog);
    return r;
}
