/* pass_upscale.c - render.scale below 1: every earlier pass drew at that fraction of the frame's
 * size, and this one scales the last sRGB8 image (FXAA's, else the tone mapping's) up to the
 * frame with a bilinear blit. Bilinear, bicubic and Lanczos filters measured within 0.5 dB of
 * each other against the full-size frame (docs/speed.md): what a smaller frame loses is the
 * water's fine detail, which no filter brings back. The HUD draws after it, at the frame's size.
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct upscale_pass {
    const ww_rt *rt;
    const ww_rt *in;
} upscale_pass;

static void upscale_destroy(void *self, const ww_gl *gl) {
    (void)gl;
    free(self);
}

static ww_result upscale_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                                const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    const ww_rt *in = ww_renderer_output(r, WW_PASS_FXAA);
    if (!in) in = ww_renderer_output(r, WW_PASS_TONEMAP);
    if (!in || !ww_gfx_rt_texture(in, WW_FMT_RGBA8) || !ww_gfx_rt_texture(rt, WW_FMT_RGBA8))
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs an RGBA8 image to scale and an RGBA8 target", d->name);
    upscale_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "upscale pass: out of memory");
    p->rt = rt;
    p->in = in;
    *self = p;
    return WW_OK;
}

static ww_result upscale_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)f;
    (void)err;
    upscale_pass *p = self;
    const ww_gl *gl = r->gl;
    ww_gfx_begin_pass(gl, p->rt);
    ww_gfx_blit_color(gl, p->in, p->rt, GL_LINEAR);
    return WW_OK;
}

const ww_pass_ops ww_pass_upscale_ops = {upscale_create, upscale_run, upscale_destroy};
