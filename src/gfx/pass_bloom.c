/* pass_bloom.c - bloom (seed 000): a bright pass that also downsamples the main pass's HDR
 * colour into the half-resolution `ping` target (bloom_bright.frag.glsl), then render.bloom.passes
 * pairs of horizontal + vertical Gaussian blurs ping -> pong -> ping (bloom_blur.frag.glsl).
 * The blurred light ends in `ping`; the tone mapping pass adds it (pass_tonemap.c).
 * Seed 000 blurs at half resolution with a plain 9-tap kernel; here the kernel is merged into 5
 * bilinear fetches and ping and pong have a framebuffer each, so no pass reads a texture that is
 * attached to the framebuffer it draws into.
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

/* binomial row BLOOM_BINOMIAL_ROW without its two outermost coefficients on each side gives a
 * 9-tap kernel close to a Gaussian of sigma ~1.7 texels (Rakos 2010: 924 792 495 220 66) */
#define BLOOM_BINOMIAL_ROW 12
#define BLOOM_KNEE 0.5 /* soft knee half-width as a fraction of the threshold */

void ww_bloom_kernel(float weight[WW_BLOOM_FETCHES], float offset[WW_BLOOM_FETCHES]) {
    /* C(n, n/2 + i) for i = 0..4, normalised over the 9 taps -4..4 */
    double c[5], sum = 0.0;
    for (int i = 0; i < 5; i++) {
        int k = BLOOM_BINOMIAL_ROW / 2 + i;
        double b = 1.0;
        for (int j = 1; j <= BLOOM_BINOMIAL_ROW - k; j++) b = b * (double)(k + j) / (double)j;
        c[i] = b;
        sum += i == 0 ? b : 2.0 * b;
    }
    for (int i = 0; i < 5; i++) c[i] /= sum;
    /* taps 1 and 2, 3 and 4 each become one bilinear fetch at their weighted mean offset */
    weight[0] = (float)c[0];
    offset[0] = 0.0f;
    for (int m = 1; m < WW_BLOOM_FETCHES; m++) {
        int a = 2 * m - 1, b = 2 * m;
        double w = c[a] + c[b];
        weight[m] = (float)w;
        offset[m] = (float)((a * c[a] + b * c[b]) / w);
    }
}

typedef struct bloom_pass {
    const ww_rt *rt;
    GLuint hdr_tex;     /* main pass's HDR colour */
    int hdr_w, hdr_h;
    GLuint fbo[2];      /* ping, pong: one attachment each */
    GLuint tex[2];
    GLuint bright, blur;
    GLint b_hdr, b_ratio, b_exposure, b_threshold, b_knee;
    GLint u_src, u_dir, u_weight, u_offset;
    float weight[WW_BLOOM_FETCHES], offset[WW_BLOOM_FETCHES];
} bloom_pass;

static void bloom_destroy(void *self, const ww_gl *gl) {
    bloom_pass *p = self;
    if (!p) return;
    if (p->bright) gl->DeleteProgram(p->bright);
    if (p->blur) gl->DeleteProgram(p->blur);
    for (int i = 0; i < 2; i++)
        if (p->fbo[i]) gl->DeleteFramebuffers(1, &p->fbo[i]);
    free(p);
}

static ww_result bloom_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                              const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    const ww_gl *gl = r->gl;
    const ww_rt *in = ww_renderer_output(r, WW_PASS_MAIN);
    GLuint hdr = in ? ww_gfx_rt_texture(in, WW_FMT_RGBA16F) : 0;
    if (!hdr || rt->ntex != 2 || rt->fmt[0] != WW_FMT_RGBA16F || rt->fmt[1] != WW_FMT_RGBA16F)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs the main pass's HDR colour and two RGBA16F targets",
                            d->name);
    bloom_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "bloom pass: out of memory");
    p->rt = rt;
    p->hdr_tex = hdr;
    p->hdr_w = in->width;
    p->hdr_h = in->height;

    /* ping and pong are filtered bilinearly (the merged taps, the tone mapping's upsample) */
    for (int i = 0; i < 2; i++) {
        p->tex[i] = rt->tex[i];
        ww_result frc = ww_gfx_fbo_single(gl, p->tex[i], d->name, i, &p->fbo[i], err);
        if (frc != WW_OK) {
            bloom_destroy(p, gl);
            return frc;
        }
    }

    ww_result rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "bloom_bright.frag.glsl", NULL,
                                  &p->bright, err);
    if (rc == WW_OK)
        rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "bloom_blur.frag.glsl", NULL, &p->blur,
                            err);
    if (rc != WW_OK) {
        bloom_destroy(p, gl);
        return rc;
    }
    p->b_hdr = ww_gfx_uniform(gl, p->bright, "u_hdr");
    p->b_ratio = ww_gfx_uniform(gl, p->bright, "u_ratio");
    p->b_exposure = ww_gfx_uniform(gl, p->bright, "u_exposure");
    p->b_threshold = ww_gfx_uniform(gl, p->bright, "u_threshold");
    p->b_knee = ww_gfx_uniform(gl, p->bright, "u_knee");
    p->u_src = ww_gfx_uniform(gl, p->blur, "u_src");
    p->u_dir = ww_gfx_uniform(gl, p->blur, "u_dir");
    p->u_weight = ww_gfx_uniform(gl, p->blur, "u_weight");
    p->u_offset = ww_gfx_uniform(gl, p->blur, "u_offset");
    ww_bloom_kernel(p->weight, p->offset);
    *self = p;
    return WW_OK;
}

/* one full-screen triangle into framebuffer `to` reading texture src (blur) */
static void bloom_blur(bloom_pass *p, ww_renderer *r, int to, float dx, float dy) {
    const ww_gl *gl = r->gl;
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->fbo[to]);
    gl->BindTexture(GL_TEXTURE_2D, p->tex[1 - to]);
    gl->Uniform2f(p->u_dir, dx, dy);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
}

static ww_result bloom_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    bloom_pass *p = self;
    const ww_gl *gl = r->gl;
    const ww_bloom_desc *b = &f->sc->render.bloom;
    ww_gfx_begin_pass(gl, p->rt);
    gl->BindVertexArray(r->empty_vao);
    gl->ActiveTexture(GL_TEXTURE0);

    /* bright pass + downsample into ping */
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->fbo[0]);
    gl->UseProgram(p->bright);
    gl->BindTexture(GL_TEXTURE_2D, p->hdr_tex);
    gl->Uniform1i(p->b_hdr, 0);
    gl->Uniform2f(p->b_ratio, (float)p->hdr_w / (float)p->rt->width,
                  (float)p->hdr_h / (float)p->rt->height);
    gl->Uniform1f(p->b_exposure, (float)f->sc->exposure);
    gl->Uniform1f(p->b_threshold, (float)b->threshold);
    gl->Uniform1f(p->b_knee, (float)(BLOOM_KNEE * b->threshold));
    gl->DrawArrays(GL_TRIANGLES, 0, 3);

    /* passes x (horizontal into pong, vertical back into ping) */
    gl->UseProgram(p->blur);
    gl->Uniform1i(p->u_src, 0);
    gl->Uniform1fv(p->u_weight, WW_BLOOM_FETCHES, p->weight);
    gl->Uniform1fv(p->u_offset, WW_BLOOM_FETCHES, p->offset);
    for (int i = 0; i < b->passes; i++) {
        bloom_blur(p, r, 1, 1.0f / (float)p->rt->width, 0.0f);
        bloom_blur(p, r, 0, 0.0f, 1.0f / (float)p->rt->height);
    }
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return WW_OK;
}

const ww_pass_ops ww_pass_bloom_ops = {bloom_create, bloom_run, bloom_destroy};
