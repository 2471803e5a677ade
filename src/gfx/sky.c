/* sky.c - the gradient sky with the sun disc and glow (shaders/common.glsl), drawn as one
 * full-screen triangle behind everything; one view ray per pixel from the inverse
 * view-projection. Also sets common.glsl's sky uniforms for any program that includes it.
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

struct ww_sky {
    GLuint prog;
    ww_sky_locs sky;
    GLint inv_view_proj;
};

void ww_sky_locs_init(const ww_gl *gl, GLuint prog, ww_sky_locs *l) {
    l->zenith = ww_gfx_uniform(gl, prog, "u_sky_zenith");
    l->horizon = ww_gfx_uniform(gl, prog, "u_sky_horizon");
    l->sun_dir = ww_gfx_uniform(gl, prog, "u_sun_dir");
    l->sun_color = ww_gfx_uniform(gl, prog, "u_sun_color");
}

void ww_sky_locs_set(const ww_gl *gl, const ww_sky_locs *l, const ww_state *st) {
    gl->Uniform3f(l->zenith, (float)st->sky_zenith[0], (float)st->sky_zenith[1],
                  (float)st->sky_zenith[2]);
    gl->Uniform3f(l->horizon, (float)st->sky_horizon[0], (float)st->sky_horizon[1],
                  (float)st->sky_horizon[2]);
    gl->Uniform3f(l->sun_dir, (float)st->sun_dir[0], (float)st->sun_dir[1], (float)st->sun_dir[2]);
    gl->Uniform3f(l->sun_color, (float)st->sun_color[0], (float)st->sun_color[1],
                  (float)st->sun_color[2]);
}

ww_result ww_sky_new(const ww_gl *gl, ww_sky **out, ww_error *err) {
    static const char *const includes[] = {"common.glsl", NULL};
    ww_sky *s = calloc(1, sizeof *s);
    if (!s) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "sky: out of memory");
    ww_result rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "sky.frag.glsl", includes, &s->prog,
                                  err);
    if (rc != WW_OK) {
        free(s);
        return rc;
    }
    ww_sky_locs_init(gl, s->prog, &s->sky);
    s->inv_view_proj = ww_gfx_uniform(gl, s->prog, "u_inv_view_proj");
    *out = s;
    return WW_OK;
}

void ww_sky_draw(const ww_sky *s, const ww_gl *gl, GLuint empty_vao, const ww_frame *f) {
    /* the triangle lies on the far plane: it passes where the depth is still clear */
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LEQUAL);
    gl->DepthMask(GL_FALSE);
    gl->UseProgram(s->prog);
    ww_sky_locs_set(gl, &s->sky, f->st);
    gl->UniformMatrix4fv(s->inv_view_proj, 1, GL_FALSE, (const GLfloat *)f->inv_view_proj);
    gl->BindVertexArray(empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->DepthMask(GL_TRUE);
    gl->DepthFunc(GL_LESS);
}

void ww_sky_free(ww_sky *s, const ww_gl *gl) {
    if (!s) return;
    gl->DeleteProgram(s->prog);
    free(s);
}
