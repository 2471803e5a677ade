/* pass_fxaa.c - FXAA (seed 000's last post pass; Lottes, FXAA 3.11 quality): reads the tone
 * mapping pass's RGBA8 image bilinearly and writes the anti-aliased image into its own RGBA8
 * target (fxaa.frag.glsl), its luma from the image's alpha (pass_tonemap.c writes it there).
 * Only pixels on luma edges change, and only they are shaded: the tone-mapped image is copied
 * into the target first (a blit) and the shader discards every pixel without an edge, which
 * llvmpipe skips for the rest of the shader when a whole block of pixels has none (it runs both
 * arms of a branch, but not past a discard that took every lane): 42 -> 27 CPU ms on the lake
 * at 1280x720. Where no edge was found, alpha keeps the luma (readers take RGB, or replace it
 * with the coverage).
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct fxaa_pass {
    const ww_rt *rt;
    const ww_rt *in; /* the tone mapping's target */
    GLuint ldr_tex;
    GLuint prog;
    GLint ldr;
} fxaa_pass;

static void fxaa_destroy(void *self, const ww_gl *gl) {
    fxaa_pass *p = self;
    if (!p) return;
    if (p->prog) gl->DeleteProgram(p->prog);
    free(p);
}

static ww_result fxaa_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                             const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    const ww_gl *gl = r->gl;
    const ww_rt *in = ww_renderer_output(r, WW_PASS_TONEMAP);
    GLuint ldr = in ? ww_gfx_rt_texture(in, WW_FMT_RGBA8) : 0;
    if (!ldr || !ww_gfx_rt_texture(rt, WW_FMT_RGBA8) || in->width != rt->width ||
        in->height != rt->height)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs the tone mapping's RGBA8 image and a target of its size",
                            d->name);
    fxaa_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "fxaa pass: out of memory");
    p->rt = rt;
    p->in = in;
    p->ldr_tex = ldr;
    /* the edge search and the final fetch read between texels */
    gl->BindTexture(GL_TEXTURE_2D, ldr);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    ww_result rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "fxaa.frag.glsl", NULL, &p->prog,
                                  err);
    if (rc != WW_OK) {
        fxaa_destroy(p, gl);
        return rc;
    }
    p->ldr = ww_gfx_uniform(gl, p->prog, "u_ldr");
    *self = p;
    return WW_OK;
}

static ww_result fxaa_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    (void)f;
    fxaa_pass *p = self;
    const ww_gl *gl = r->gl;
    ww_gfx_begin_pass(gl, p->rt);
    ww_gfx_blit_color(gl, p->in, p->rt, GL_NEAREST);
    gl->UseProgram(p->prog);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, p->ldr_tex);
    gl->Uniform1i(p->ldr, 0);
    gl->BindVertexArray(r->empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return WW_OK;
}

const ww_pass_ops ww_pass_fxaa_ops = {fxaa_create, fxaa_run, fxaa_destroy};
