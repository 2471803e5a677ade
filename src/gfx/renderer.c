/* renderer.c - the frame renderer: creates exactly the planned passes (one table entry per
 * ww_pass_id), computes the camera once per frame, runs the passes in plan order and reads the
 * results back, flipped so the top row comes first.
 */
#include "gfx/renderer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"
#include "sim/water.h"

/* the passes a plan may name; a new pass is a pass_xxx.c and one line here */
static const ww_pass_ops *const pass_table[WW_PASS_COUNT] = {
    [WW_PASS_SKYMAP] = &ww_pass_skymap_ops,
    [WW_PASS_SHADOW] = &ww_pass_shadow_ops,
    [WW_PASS_PREPASS] = &ww_pass_prepass_ops,
    [WW_PASS_REFLECTION] = &ww_pass_reflection_ops,
    [WW_PASS_MAIN] = &ww_pass_main_ops,
    [WW_PASS_BLOOM] = &ww_pass_bloom_ops,
    [WW_PASS_SHAFTS] = &ww_pass_shafts_ops,
    [WW_PASS_TONEMAP] = &ww_pass_tonemap_ops,
    [WW_PASS_FXAA] = &ww_pass_fxaa_ops,
    [WW_PASS_UPSCALE] = &ww_pass_upscale_ops,
    [WW_PASS_HUD] = &ww_pass_hud_ops,
};

int ww_renderer_has_pass(ww_pass_id id) {
    return id >= 0 && id < WW_PASS_COUNT && pass_table[id] != NULL;
}

const ww_rt *ww_renderer_output(const ww_renderer *r, ww_pass_id id) {
    for (int i = 0; i < r->npasses; i++)
        if (r->passes[i].id == id) return &r->passes[i].rt;
    return NULL;
}

void ww_gfx_begin_pass(const ww_gl *gl, const ww_rt *rt) {
    gl->BindFramebuffer(GL_FRAMEBUFFER, rt->fbo);
    gl->Viewport(0, 0, rt->width, rt->height);
    /* nothing left from an earlier pass may change the pixels: every switch set explicitly */
    gl->Disable(GL_DITHER);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_CULL_FACE);
    gl->Disable(GL_DEPTH_TEST);
    gl->Disable(GL_SCISSOR_TEST);
    gl->Disable(GL_FRAMEBUFFER_SRGB);
}

void ww_gfx_blit_color(const ww_gl *gl, const ww_rt *from, const ww_rt *to, GLenum filter) {
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, from->fbo);
    gl->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, to->fbo);
    gl->BlitFramebuffer(0, 0, from->width, from->height, 0, 0, to->width, to->height,
                        GL_COLOR_BUFFER_BIT, filter);
    gl->BindFramebuffer(GL_FRAMEBUFFER, to->fbo);
}

void ww_gfx_box_row(const float model[16], int r, const float lo[3], const float hi[3],
                    float *rlo, float *rhi) {
    float a = model[12 + r], b = model[12 + r];
    for (int c = 0; c < 3; c++) {
        float e0 = model[4 * c + r] * lo[c], e1 = model[4 * c + r] * hi[c];
        a += fminf(e0, e1);
        b += fmaxf(e0, e1);
    }
    *rlo = a;
    *rhi = b;
}

void ww_gfx_clear_scene(const ww_renderer *r, const ww_rt *rt) {
    const ww_gl *gl = r->gl;
    gl->ClearDepth(1.0);
    gl->DepthMask(GL_TRUE);
    if (ww_gfx_rt_texture(rt, WW_FMT_DEPTH24_STENCIL8)) {
        /* stencilled shadows, the water's pixels: only those targets have a stencil */
        gl->ClearStencil(0);
        gl->StencilMask(0xFF);
        gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    } else {
        gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
}

void ww_renderer_free(ww_renderer *r) {
    if (!r) return;
    const ww_gl *gl = r->gl;
    for (int i = r->npasses - 1; i >= 0; i--) {
        ww_pass *p = &r->passes[i];
        if (p->self) p->ops->destroy(p->self, gl);
        ww_gfx_rt_destroy(gl, &p->rt);
    }
    ww_renderer_time_passes(r, WW_TIMING_OFF);
    ww_stencil_shadows_free(r->stencil, gl);
    ww_geometry_free(r->geometry, gl);
    if (r->empty_vao) gl->DeleteVertexArrays(1, &r->empty_vao);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    free(r);
}

ww_result ww_renderer_for_scene(const ww_gl *gl, const ww_scene *sc, int w, int h,
                                ww_renderer **out, ww_error *err) {
    ww_plan plan;
    ww_plan_build(sc, w, h, &plan);
    return ww_renderer_new(gl, sc, &plan, out, err);
}

const ww_plan *ww_renderer_plan(const ww_renderer *r) { return &r->plan; }

ww_result ww_renderer_new(const ww_gl *gl, const ww_scene *sc, const ww_plan *plan,
                          ww_renderer **out, ww_error *err) {
    WW_ASSERT(gl && sc && plan && out);
    WW_ASSERT(plan->npasses >= 1 && plan->npasses <= WW_PASS_COUNT);
    *out = NULL;
    ww_renderer *r = calloc(1, sizeof *r);
    if (!r) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "renderer: out of memory");
    r->gl = gl;
    r->plan = *plan;
    gl->GenVertexArrays(1, &r->empty_vao);

    /* every pass's targets first, so a pass can find the outputs it reads when created */
    ww_result rc = WW_OK;
    if (plan->geometry) rc = ww_geometry_new(r, sc, &r->geometry, err);
    if (rc == WW_OK && r->geometry && sc->render.shadows.on &&
        sc->render.shadows.technique != WW_SHADOW_MAP && ww_scene_has_objects(sc))
        rc = ww_stencil_shadows_new(r, sc, &r->stencil, err);
    for (int i = 0; i < plan->npasses && rc == WW_OK; i++) {
        const ww_pass_desc *d = &plan->passes[i];
        WW_ASSERT(d->id >= 0 && d->id < WW_PASS_COUNT && pass_table[d->id] && d->name);
        WW_ASSERT(!ww_renderer_output(r, d->id)); /* each pass at most once */
        ww_pass *p = &r->passes[r->npasses++];
        p->id = d->id;
        p->ops = pass_table[d->id];
        if (d->ntargets > 0) rc = ww_gfx_rt_create(gl, d, &p->rt, err);
    }
    for (int i = 0; i < r->npasses && rc == WW_OK; i++) {
        ww_pass *p = &r->passes[i];
        rc = p->ops->create(r, sc, &plan->passes[i], &p->rt, &p->self, err);
    }
    if (rc == WW_OK) {
        GLenum e = gl->GetError();
        if (e != GL_NO_ERROR)
            rc = ww_error_set(err, WW_E_GL, NULL, 0, 0,
                              "renderer: GL error 0x%04x while creating the passes", (unsigned)e);
    }
    if (rc != WW_OK) {
        ww_renderer_free(r);
        return rc;
    }
    *out = r;
    return WW_OK;
}

/* camera rotation and projection; positions are sent camera-relative, so the view matrix has
 * no translation */
static void frame_camera(ww_frame *f, const ww_renderer *r) {
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    for (int i = 0; i < 3; i++) f->cam_pos[i] = st->cam_pos[i];

    /* orthonormal basis from forward and world up; a vertical forward takes -z as up */
    double fw[3] = {st->cam_fwd[0], st->cam_fwd[1], st->cam_fwd[2]};
    WW_ASSERT(ww_m_len3(fw) > 0.0);
    ww_m_normalize3(fw);
    double up[3] = {0.0, 1.0, 0.0};
    if (fabs(fw[1]) > 0.9999) {
        up[1] = 0.0;
        up[2] = -1.0;
    }
    double rt[3] = {fw[1] * up[2] - fw[2] * up[1], fw[2] * up[0] - fw[0] * up[2],
                    fw[0] * up[1] - fw[1] * up[0]};
    ww_m_normalize3(rt);
    double u[3] = {rt[1] * fw[2] - rt[2] * fw[1], rt[2] * fw[0] - rt[0] * fw[2],
                   rt[0] * fw[1] - rt[1] * fw[0]};

    /* cglm is column-major: m[column][row]; rows are right, up, -forward */
    glm_mat4_identity(f->view);
    for (int c = 0; c < 3; c++) {
        f->view[c][0] = (float)rt[c];
        f->view[c][1] = (float)u[c];
        f->view[c][2] = (float)-fw[c];
    }

    /* the aspect of the main pass's targets: the frame's size */
    const ww_rt *main = ww_renderer_output(r, WW_PASS_MAIN);
    if (!main) main = &r->passes[0].rt;
    double fov = st->cam_fov[0] > 0.0 ? st->cam_fov[0] : sc->fov;
    glm_perspective((float)fov, (float)main->width / (float)main->height, (float)sc->near_clip,
                    (float)sc->far_clip, f->proj);
    f->pixel_angle = (float)(2.0 * tan(0.5 * fov) / main->height);
    f->width = main->width;
    f->height = main->height;
    f->tan_half[1] = tan(0.5 * fov);
    f->tan_half[0] = f->tan_half[1] * (double)main->width / (double)main->height;
    for (int c = 0; c < 3; c++) {
        f->fwd[c] = fw[c];
        f->right[c] = rt[c];
        f->up[c] = u[c];
    }
    glm_mat4_mul(f->proj, f->view, f->view_proj);
    glm_mat4_inv(f->view_proj, f->inv_view_proj);

    /* under water: below the exact surface over the camera (waves and ripples of the state) */
    ww_water_sample ws;
    ww_water_at(sc, st, st->cam_pos[0], st->cam_pos[2], 0.0, &ws);
    f->surface_y = ws.height;
    f->underwater = st->cam_pos[1] < ws.height;
}

/* ---- per-pass timing -------------------------------------------------------------------- */

/* WW_PASS_CPU_TIME=1: the passes are timed by the process's CPU time (all of llvmpipe's threads)
 * with glFinish between them, not by the wall clock or GL timers: on a machine shared with other
 * work the wall time of a pass swells with whatever else runs, its CPU time much less (the
 * before/after tables of docs/speed.md were measured so) */
static int cpu_time_on(void) {
    const char *e = getenv("WW_PASS_CPU_TIME");
    return e && e[0] == '1';
}

static double now_ms(void) {
    struct timespec ts;
    clock_gettime(cpu_time_on() ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_MONOTONIC, &ts);
    return 1e3 * (double)ts.tv_sec + 1e-6 * (double)ts.tv_nsec;
}

const char *ww_timing_name(ww_timing mode) {
    switch (mode) {
    case WW_TIMING_GPU: return "gl timer queries";
    case WW_TIMING_CPU:
        return cpu_time_on() ? "process cpu time (WW_PASS_CPU_TIME), glFinish between passes"
                             : "cpu wall time, glFinish between passes";
    case WW_TIMING_AUTO: return "auto";
    case WW_TIMING_OFF: break;
    }
    return "off";
}

/* add one slot's query results to the sums (waits for them: the caller knows the frame is old
 * enough, or has finished) */
static void timer_collect(ww_renderer *r, int slot) {
    ww_pass_timer *tm = &r->timer;
    for (int i = 0; i < r->npasses; i++) {
        GLuint64 ns = 0;
        r->gl->GetQueryObjectui64v(tm->query[slot][i], GL_QUERY_RESULT, &ns);
        tm->sum_ms[i] += 1e-6 * (double)ns;
    }
    tm->pending[slot] = 0;
    tm->frames++;
}

ww_timing ww_renderer_time_passes(ww_renderer *r, ww_timing mode) {
    ww_pass_timer *tm = &r->timer;
    const ww_gl *gl = r->gl;
    if (tm->mode == WW_TIMING_GPU)
        for (int s = 0; s < WW_TIMER_RING; s++) gl->DeleteQueries(WW_PASS_COUNT, tm->query[s]);
    *tm = (ww_pass_timer){0};
    if (mode == WW_TIMING_AUTO || mode == WW_TIMING_GPU) {
        /* GL 3.3 has ARB_timer_query in core, but a driver may give its counter no bits */
        GLint bits = 0;
        gl->GetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
        mode = bits > 0 && !cpu_time_on() ? WW_TIMING_GPU : WW_TIMING_CPU;
    }
    if (mode == WW_TIMING_GPU)
        for (int s = 0; s < WW_TIMER_RING; s++) gl->GenQueries(WW_PASS_COUNT, tm->query[s]);
    tm->mode = mode;
    return mode;
}

void ww_renderer_pass_times(ww_renderer *r, ww_pass_times *t) {
    ww_pass_timer *tm = &r->timer;
    *t = (ww_pass_times){.mode = tm->mode, .npasses = r->npasses};
    /* the slots in flight, oldest first (the order does not change the sums) */
    if (tm->mode == WW_TIMING_GPU)
        for (int s = 0; s < WW_TIMER_RING; s++)
            if (tm->pending[s]) timer_collect(r, s);
    for (int i = 0; i < r->npasses; i++) {
        t->id[i] = r->passes[i].id;
        snprintf(t->name[i], sizeof t->name[i], "%s", r->plan.passes[i].name);
        t->ms[i] = tm->sum_ms[i];
        tm->sum_ms[i] = 0.0;
    }
    t->frame_ms = tm->frame_ms;
    t->frames = tm->frames;
    tm->frame_ms = 0.0;
    tm->frames = 0;
}

ww_result ww_render_frame(ww_renderer *r, const ww_scene *sc, const ww_state *st, ww_error *err) {
    WW_ASSERT(r && sc && st);
    ww_frame f;
    f.sc = sc;
    f.st = st;
    f.frame = r->frames++;
    frame_camera(&f, r);
    r->shared = (ww_shared){0};

    ww_pass_timer *tm = &r->timer;
    int slot = (int)(f.frame % WW_TIMER_RING);
    double t0 = 0.0;
    if (tm->mode == WW_TIMING_GPU && tm->pending[slot]) timer_collect(r, slot);
    if (tm->mode == WW_TIMING_CPU) {
        r->gl->Finish();
        t0 = now_ms();
    }
    for (int i = 0; i < r->npasses; i++) {
        ww_pass *p = &r->passes[i];
        if (tm->mode == WW_TIMING_GPU) r->gl->BeginQuery(GL_TIME_ELAPSED, tm->query[slot][i]);
        ww_result rc = p->ops->run(p->self, r, &f, err);
        if (tm->mode == WW_TIMING_GPU) r->gl->EndQuery(GL_TIME_ELAPSED);
        if (rc != WW_OK) return rc;
        if (tm->mode == WW_TIMING_CPU) {
            r->gl->Finish();
            double t1 = now_ms();
            tm->sum_ms[i] += t1 - t0;
            tm->frame_ms += t1 - t0;
            t0 = t1;
        }
    }
    if (tm->mode == WW_TIMING_GPU) tm->pending[slot] = 1;
    if (tm->mode == WW_TIMING_CPU) tm->frames++;
    GLenum e = r->gl->GetError();
    if (e != GL_NO_ERROR)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "renderer: GL error 0x%04x while drawing",
                            (unsigned)e);
    return WW_OK;
}

/* read colour attachment `fmt` of rt into im (sizes checked by the caller), then flip */
static ww_result read_target(ww_renderer *r, const ww_rt *rt, ww_format fmt, GLenum format,
                             GLenum type, void *pixels, ww_image *im, ww_error *err) {
    const ww_gl *gl = r->gl;
    int color = 0, found = -1;
    for (int i = 0; i < rt->ntex && found < 0; i++) {
        if (rt->fmt[i] == fmt) found = color;
        if (rt->fmt[i] != WW_FMT_DEPTH24 && rt->fmt[i] != WW_FMT_DEPTH24_STENCIL8 &&
            !rt->unattached[i])
            color++;
    }
    WW_ASSERT(found >= 0);
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, rt->fbo);
    gl->ReadBuffer(GL_COLOR_ATTACHMENT0 + (GLenum)found);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, rt->width, rt->height, format, type, pixels);
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "renderer: glReadPixels raised 0x%04x",
                            (unsigned)e);
    ww_image_flip_rows(im);
    return WW_OK;
}

ww_result ww_renderer_read_ldr(ww_renderer *r, ww_image *im, ww_error *err) {
    /* the final image: the last planned pass that writes RGBA8 */
    const ww_rt *rt = NULL;
    for (int i = 0; i < r->npasses; i++)
        if (ww_gfx_rt_texture(&r->passes[i].rt, WW_FMT_RGBA8)) rt = &r->passes[i].rt;
    WW_ASSERT(rt);
    WW_ASSERT(im->type == WW_PIX_U8 && im->u8 && (im->channels == 3 || im->channels == 4));
    WW_ASSERT(im->width == rt->width && im->height == rt->height);
    return read_target(r, rt, WW_FMT_RGBA8, im->channels == 4 ? GL_RGBA : GL_RGB,
                       GL_UNSIGNED_BYTE, im->u8, im, err);
}

/* src scaled to dst's size, bilinear between texel centres (edges clamped), RGBA floats */
static void scale_bilinear_f32(const ww_image *src, ww_image *dst) {
    double sx = (double)src->width / dst->width, sy = (double)src->height / dst->height;
    for (int y = 0; y < dst->height; y++) {
        double fy = ww_m_clamp((y + 0.5) * sy - 0.5, 0.0, src->height - 1.0);
        int y0 = (int)fy, y1 = y0 + 1 < src->height ? y0 + 1 : y0;
        double ty = fy - y0;
        for (int x = 0; x < dst->width; x++) {
            double fx = ww_m_clamp((x + 0.5) * sx - 0.5, 0.0, src->width - 1.0);
            int x0 = (int)fx, x1 = x0 + 1 < src->width ? x0 + 1 : x0;
            double tx = fx - x0;
            const float *a = src->f32 + ((size_t)y0 * src->width + x0) * 4;
            const float *b = src->f32 + ((size_t)y0 * src->width + x1) * 4;
            const float *c = src->f32 + ((size_t)y1 * src->width + x0) * 4;
            const float *d = src->f32 + ((size_t)y1 * src->width + x1) * 4;
            float *o = dst->f32 + ((size_t)y * dst->width + x) * 4;
            for (int k = 0; k < 4; k++)
                o[k] = (float)((1.0 - ty) * ((1.0 - tx) * a[k] + tx * b[k]) +
                               ty * ((1.0 - tx) * c[k] + tx * d[k]));
        }
    }
}

/* the main pass's HDR image; drawn smaller (render.scale), scaled up to im's size */
ww_result ww_renderer_read_hdr(ww_renderer *r, ww_image *im, ww_error *err) {
    const ww_rt *rt = ww_renderer_output(r, WW_PASS_MAIN);
    WW_ASSERT(rt);
    WW_ASSERT(im->type == WW_PIX_F32 && im->f32 && im->channels == 4);
    WW_ASSERT(im->width >= rt->width && im->height >= rt->height);
    if (im->width == rt->width && im->height == rt->height)
        return read_target(r, rt, WW_FMT_RGBA16F, GL_RGBA, GL_FLOAT, im->f32, im, err);
    ww_image small;
    if (ww_image_alloc(&small, rt->width, rt->height, 4, WW_PIX_F32) != 0)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "renderer: out of memory");
    ww_result rc = read_target(r, rt, WW_FMT_RGBA16F, GL_RGBA, GL_FLOAT, small.f32, &small, err);
    if (rc == WW_OK) scale_bilinear_f32(&small, im);
    ww_image_free(&small);
    return rc;
}

/* [frames] --alpha: coverage from the main pass's depth. The sky is drawn on the far plane and
 * the clear leaves depth 1 there, so a pixel whose depth is below 1 shows water or geometry.
 * depth holds im's pixels; a main pass drawn smaller (render.scale) is read nearest. */
ww_result ww_renderer_read_coverage(ww_renderer *r, ww_image *im, float *depth, ww_error *err) {
    const ww_rt *rt = ww_renderer_output(r, WW_PASS_MAIN);
    WW_ASSERT(rt && depth && im->channels == 4);
    WW_ASSERT(im->width >= rt->width && im->height >= rt->height);
    const ww_gl *gl = r->gl;
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, rt->fbo);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, rt->width, rt->height, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "renderer: depth read-back raised 0x%04x",
                            (unsigned)e);
    /* GL rows run bottom up, the image's top down */
    size_t w = (size_t)rt->width, W = (size_t)im->width, H = (size_t)im->height;
    for (size_t y = 0; y < H; y++) {
        size_t sy = (2 * y + 1) * (size_t)rt->height / (2 * H); /* the nearest row */
        const float *d = depth + ((size_t)rt->height - 1 - sy) * w;
        for (size_t x = 0; x < W; x++) {
            size_t i = (y * W + x) * 4 + 3;
            int covered = d[(2 * x + 1) * w / (2 * W)] < 1.0f;
            if (im->type == WW_PIX_U8) im->u8[i] = covered ? 255 : 0;
            else im->f32[i] = covered ? 1.0f : 0.0f;
        }
    }
    return WW_OK;
}

void ww_renderer_finish(ww_renderer *r) { r->gl->Finish(); }
