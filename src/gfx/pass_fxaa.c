/* pass_fxaa.c - FXAA (seed 000's last post pass; Lottes, FXAA 3.11 quality): reads the tone
 * mapping pass's RGBA8 image bilinearly and writes the anti-aliased image into its own RGBA8
 * target (fxaa.frag.glsl), its luma from the image's alpha (pass_tonemap.c writes it there).
 * Only pixels on luma edges change, and only they are shaded, in three steps:
 *   1. the tone-mapped image is copied into the target (a blit);
 *   2. a marking draw runs FXAA's edge test alone (five luma fetches) and writes depth only
 *      where there is an edge, into the pass's depth target cleared to 0;
 *   3. the shading draw runs the whole of FXAA under the depth test, which passes only where
 *      the marking draw wrote.
 * llvmpipe tests depth before it runs a fragment shader and skips every block of pixels that
 * failed, but a discard does not skip the rest of the shader for a block whose every pixel
 * discarded: FXAA as one draw that discarded its edge-less pixels cost 27 CPU ms on the lake at
 * 1280x720, as much as one that discarded every pixel at its top, and the two draws cost 9.
 * Where no edge was found, alpha keeps the luma (readers take RGB, or replace it with the
 * coverage).
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct fxaa_pass {
    const ww_rt *rt;
    const ww_rt *in; /* the tone mapping's target */
    GLuint ldr_tex;
    GLuint mark, prog; /* the edge test alone (WW_FXAA_MARK), and the whole of FXAA */
    GLint ldr_mark, ldr;
} fxaa_pass;

static void fxaa_destroy(void *self, const ww_gl *gl) {
    fxaa_pass *p = self;
    if (!p) return;
    if (p->prog) gl->DeleteProgram(p->prog);
    if (p->mark) gl->DeleteProgram(p->mark);
    free(p);
}

static ww_result fxaa_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                             const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    const ww_gl *gl = r->gl;
    const ww_rt *in = ww_renderer_output(r, WW_PASS_TONEMAP);
    GLuint ldr = in ? ww_gfx_rt_texture(in, WW_FMT_RGBA8) : 0;
    if (!ldr || !ww_gfx_rt_texture(rt, WW_FMT_RGBA8) || !ww_gfx_rt_depth(rt) ||
        in->width != rt->width || in->height != rt->height)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs the tone mapping's RGBA8 image, and an RGBA8 and a "
                            "depth target of its size",
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
    ww_result rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "fxaa.frag.glsl", NULL,
                                       "#define WW_FXAA_MARK 1\n", &p->mark, err);
    if (rc == WW_OK)
        rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "fxaa.frag.glsl", NULL, &p->prog, err);
    if (rc != WW_OK) {
        fxaa_destroy(p, gl);
        return rc;
    }
    p->ldr_mark = ww_gfx_uniform(gl, p->mark, "u_ldr");
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
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, p->ldr_tex);
    gl->BindVertexArray(r->empty_vao);

    /* mark the edges: the full-screen triangle lies at depth 1, written only where the edge
     * test passes, over a clear to 0; colour untouched */
    gl->ClearDepth(0.0);
    gl->Clear(GL_DEPTH_BUFFER_BIT);
    gl->ClearDepth(1.0);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_ALWAYS);
    gl->DepthMask(GL_TRUE);
    gl->ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl->UseProgram(p->mark);
    gl->Uniform1i(p->ldr_mark, 0);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);

    /* shade them: depth 1 <= 1 where marked, not <= 0 elsewhere */
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl->DepthMask(GL_FALSE);
    gl->DepthFunc(GL_LEQUAL);
    gl->UseProgram(p->prog);
    gl->Uniform1i(p->ldr, 0);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);

    gl->DepthMask(GL_TRUE);
    gl->DepthFunc(GL_LESS);
    gl->Disable(GL_DEPTH_TEST);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return WW_OK;
}

const ww_pass_ops ww_pass_fxaa_ops = {fxaa_create, fxaa_run, fxaa_destroy};
