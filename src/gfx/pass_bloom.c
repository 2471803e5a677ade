/* pass_bloom.c - bloom (seed 000): a bright pass that also downsamples the main pass's HDR
 * colour into the half-resolution `ping` target (bloom_bright.frag.glsl), then one horizontal and
 * one vertical Gaussian blur ping -> pong -> ping (bloom_blur.frag.glsl) whose kernel is
 * render.bloom.passes rounds of the 9-tap binomial one convolved together. The blurred light
 * ends in `ping`; the tone mapping pass adds it (pass_tonemap.c).
 * Seed 000 blurs at half resolution with a plain 9-tap kernel, once per pass; rounds of a kernel
 * are one wider kernel (a convolution of convolutions), so here the rounds are merged into one
 * pass pair and the kernel's neighbouring taps into bilinear fetches: 3 rounds took 6 passes of
 * 5 fetches, now 2 passes of 11, the same picture. ping and pong have a framebuffer each, so no
 * pass reads a texture that is attached to the framebuffer it draws into.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gfx/render_impl.h"

/* binomial row BLOOM_BINOMIAL_ROW without its two outermost coefficients on each side gives a
 * 9-tap kernel close to a Gaussian of sigma ~1.7 texels (Rakos 2010: 924 792 495 220 66) */
#define BLOOM_BINOMIAL_ROW 12
#define BLOOM_KNEE 0.5 /* soft knee half-width as a fraction of the threshold */
/* the merged kernel's outer taps are dropped while the weight they hold together (both sides)
 * stays below this share; the rest is renormalised */
#define BLOOM_TAIL 2e-3
#define BLOOM_MAX_TAPS (2 * (WW_BLOOM_MAX_FETCHES - 1)) /* taps each side the fetches can hold */

/* the 9-tap kernel's five weights, centre first, normalised */
static void bloom_taps(double c[5]) {
    double sum = 0.0;
    for (int i = 0; i < 5; i++) {
        /* C(n, n/2 + i) */
        int k = BLOOM_BINOMIAL_ROW / 2 + i;
        double b = 1.0;
        for (int j = 1; j <= BLOOM_BINOMIAL_ROW - k; j++) b = b * (double)(k + j) / (double)j;
        c[i] = b;
        sum += i == 0 ? b : 2.0 * b;
    }
    for (int i = 0; i < 5; i++) c[i] /= sum;
}

/* the glow in frame pixels is the blur's kernel between the bright pass's box (a texel w pixels
 * wide: variance w^2 / 12) and the tone mapping's bilinear upsample (a tent 2w wide: w^2 / 6), so
 * its variance is w^2 (V + 1/4) for a kernel of variance V texels^2. A blur at texels w wide has
 * the glow of the rounds' kernel (variance V2) at half size (w = 2) when
 * V = (4 V2 + 1) / w^2 - 1/4; the kernel is then sampled from the Gaussian of that variance */
#define BLOOM_MIN_VAR 0.25 /* texels^2: the least a kernel keeps (a blur narrower than its box) */

static void gaussian_kernel(double var, double *k, int rmax) {
    for (int i = -rmax; i <= rmax; i++) k[rmax + i] = exp(-0.5 * (double)(i * i) / var);
}

int ww_bloom_kernel(int passes, double scale, float weight[WW_BLOOM_MAX_FETCHES],
                    float offset[WW_BLOOM_MAX_FETCHES]) {
    enum { R_MAX = 4 * 16 }; /* render.bloom.passes at most 16 (compile_render.c) */
    double c[5], k[2 * R_MAX + 1] = {0.0}, t[2 * R_MAX + 1];
    bloom_taps(c);
    if (passes < 1) passes = 1;
    if (passes > R_MAX / 4) passes = R_MAX / 4;
    /* the rounds convolved: k = c * c * ... (passes times), taps -4 passes .. 4 passes */
    k[R_MAX] = 1.0;
    for (int p = 0; p < passes; p++) {
        for (int i = 0; i <= 2 * R_MAX; i++) {
            double s = 0.0;
            for (int j = -4; j <= 4; j++) {
                int m = i - j;
                if (m >= 0 && m <= 2 * R_MAX) s += c[j < 0 ? -j : j] * k[m];
            }
            t[i] = s;
        }
        for (int i = 0; i <= 2 * R_MAX; i++) k[i] = t[i];
    }
    int r = 4 * passes;
    if (fabs(scale - 0.5) > 1e-9 && scale > 0.0) {
        double v2 = 0.0, w = 1.0 / scale;
        for (int i = -r; i <= r; i++) v2 += (double)(i * i) * k[R_MAX + i];
        double var = fmax((4.0 * v2 + 1.0) / (w * w) - 0.25, BLOOM_MIN_VAR);
        r = (int)ceil(4.0 * sqrt(var));
        if (r > R_MAX) r = R_MAX;
        for (int i = 0; i <= 2 * R_MAX; i++) k[i] = 0.0;
        gaussian_kernel(var, k + (R_MAX - r), r);
        double total = 0.0; /* weights summing to 1, as the rounds' do, for the tail's share */
        for (int i = -r; i <= r; i++) total += k[R_MAX + i];
        for (int i = -r; i <= r; i++) k[R_MAX + i] /= total;
    }
    /* drop the faint outer taps (at most what the fetches hold), renormalise */
    double tail = 0.0;
    while (r > 4 && (r > BLOOM_MAX_TAPS || tail + 2.0 * k[R_MAX + r] < BLOOM_TAIL)) {
        tail += 2.0 * k[R_MAX + r];
        r--;
    }
    double sum = 0.0;
    for (int i = -r; i <= r; i++) sum += k[R_MAX + i];
    /* taps 1 and 2, 3 and 4, ... each become one bilinear fetch at their weighted mean offset */
    weight[0] = (float)(k[R_MAX] / sum);
    offset[0] = 0.0f;
    int n = 1;
    for (int a = 1; a <= r; a += 2, n++) {
        double wa = k[R_MAX + a], wb = a + 1 <= r ? k[R_MAX + a + 1] : 0.0, w = wa + wb;
        weight[n] = (float)(w / sum);
        offset[n] = (float)((a * wa + (a + 1) * wb) / w);
    }
    return n;
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
    float weight[WW_BLOOM_MAX_FETCHES], offset[WW_BLOOM_MAX_FETCHES];
    int fetches; /* entries of weight and offset in use */
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

    /* the bright pass thresholds every source texel of its block (WW_BLOOM_BLOCK a side) */
    char bdefs[48];
    long block = lround((double)in->width / (double)rt->width);
    snprintf(bdefs, sizeof bdefs, "#define WW_BLOOM_BLOCK %ld\n", block < 1 ? 1L : block);
    ww_result rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "bloom_bright.frag.glsl", NULL,
                                       bdefs, &p->bright, err);
    /* the fetch count is built in: llvmpipe unrolls a constant loop and indexes the weights
     * directly, where a uniform count cost more than the six passes it replaces */
    p->fetches = ww_bloom_kernel(sc->render.bloom.passes, sc->render.bloom.scale, p->weight,
                                 p->offset);
    char defs[64];
    snprintf(defs, sizeof defs, "#define WW_BLOOM_FETCHES %d\n", p->fetches);
    if (rc == WW_OK)
        rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "bloom_blur.frag.glsl", NULL, defs,
                                 &p->blur, err);
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

    /* the merged rounds: horizontal into pong, vertical back into ping */
    gl->UseProgram(p->blur);
    gl->Uniform1i(p->u_src, 0);
    gl->Uniform1fv(p->u_weight, p->fetches, p->weight);
    gl->Uniform1fv(p->u_offset, p->fetches, p->offset);
    bloom_blur(p, r, 1, 1.0f / (float)p->rt->width, 0.0f);
    bloom_blur(p, r, 0, 0.0f, 1.0f / (float)p->rt->height);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return WW_OK;
}

const ww_pass_ops ww_pass_bloom_ops = {bloom_create, bloom_run, bloom_destroy};
