/* pass_tonemap.c - HDR to display: reads the main pass's RGBA16F colour, adds the bloom
 * (pass_bloom.c's `ping`, times render.bloom.strength) and the light shafts (pass_shafts.c) when
 * those passes exist, applies exposure, the scene's tone curve (exp or ACES) and gamma, and
 * writes RGBA8 with alpha 1, or the luma FXAA reads when the FXAA pass follows
 * (tonemap.frag.glsl), dithered before the 8-bit target rounds it (render.tonemap.dither).
 * The smaller inputs are upsampled bilinearly. Which inputs there are, the curve, the dither
 * and the alpha are #defines of the program (llvmpipe would run every arm per pixel).
 */
#include <stdio.h>
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct tonemap_pass {
    const ww_rt *rt;
    GLuint hdr_tex;
    GLuint bloom_tex, shafts_tex; /* 0 when the pass is not planned */
    GLuint prog;
    GLint hdr, exposure, gamma;
    GLint bloom, bloom_strength, shafts;
} tonemap_pass;

static void tonemap_destroy(void *self, const ww_gl *gl) {
    tonemap_pass *p = self;
    if (!p) return;
    if (p->prog) gl->DeleteProgram(p->prog);
    free(p);
}

static ww_result tonemap_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                                const ww_rt *rt, void **self, ww_error *err) {
    /* its input is the main pass's HDR colour, texel for texel */
    const ww_rt *in = ww_renderer_output(r, WW_PASS_MAIN);
    GLuint hdr = in ? ww_gfx_rt_texture(in, WW_FMT_RGBA16F) : 0;
    if (!hdr || !ww_gfx_rt_texture(rt, WW_FMT_RGBA8))
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs the main pass's RGBA16F colour and an RGBA8 target",
                            d->name);
    if (in->width != rt->width || in->height != rt->height)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: its %dx%d target differs from the %dx%d HDR image", d->name,
                            rt->width, rt->height, in->width, in->height);

    tonemap_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "tonemap pass: out of memory");
    p->rt = rt;
    p->hdr_tex = hdr;
    const ww_rt *bloom = ww_renderer_output(r, WW_PASS_BLOOM);
    const ww_rt *shafts = ww_renderer_output(r, WW_PASS_SHAFTS);
    p->bloom_tex = bloom ? bloom->tex[0] : 0; /* the blur ends in ping */
    p->shafts_tex = shafts ? shafts->tex[0] : 0;
    /* alpha carries the luma FXAA reads when the FXAA pass follows */
    char defs[192];
    snprintf(defs, sizeof defs,
             "#define WW_BLOOM %d\n#define WW_SHAFTS %d\n#define WW_ACES %d\n"
             "#define WW_LUMA_ALPHA %d\n#define WW_DITHER %d\n",
             p->bloom_tex != 0, p->shafts_tex != 0, sc->tonemap == WW_TONEMAP_ACES,
             sc->render.fxaa != 0, sc->dither != 0);
    ww_result rc = ww_gfx_program_defs(r->gl, "fullscreen.vert.glsl", "tonemap.frag.glsl", NULL,
                                       defs, &p->prog, err);
    if (rc != WW_OK) {
        tonemap_destroy(p, r->gl);
        return rc;
    }
    p->hdr = ww_gfx_uniform(r->gl, p->prog, "u_hdr");
    p->exposure = ww_gfx_uniform(r->gl, p->prog, "u_exposure");
    p->gamma = ww_gfx_uniform(r->gl, p->prog, "u_gamma");
    p->bloom = ww_gfx_uniform(r->gl, p->prog, "u_bloom");
    p->bloom_strength = ww_gfx_uniform(r->gl, p->prog, "u_bloom_strength");
    p->shafts = ww_gfx_uniform(r->gl, p->prog, "u_shafts");
    *self = p;
    return WW_OK;
}

static ww_result tonemap_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    tonemap_pass *p = self;
    const ww_gl *gl = r->gl;
    ww_gfx_begin_pass(gl, p->rt);
    gl->UseProgram(p->prog);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, p->hdr_tex);
    gl->Uniform1i(p->hdr, 0);
    gl->Uniform1f(p->exposure, (float)f->sc->exposure);
    gl->Uniform1f(p->gamma, (float)f->sc->gamma);
    /* every sampler on its own unit, bound or not, so none aliases u_hdr's */
    gl->ActiveTexture(GL_TEXTURE1);
    gl->BindTexture(GL_TEXTURE_2D, p->bloom_tex);
    gl->Uniform1i(p->bloom, 1);
    gl->Uniform1f(p->bloom_strength, (float)f->sc->render.bloom.strength);
    gl->ActiveTexture(GL_TEXTURE2);
    gl->BindTexture(GL_TEXTURE_2D, p->shafts_tex);
    gl->Uniform1i(p->shafts, 2);
    gl->BindVertexArray(r->empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->ActiveTexture(GL_TEXTURE1);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return WW_OK;
}

const ww_pass_ops ww_pass_tonemap_ops = {tonemap_create, tonemap_run, tonemap_destroy};
