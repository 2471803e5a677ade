/* targets.c - a pass's render targets: one texture per planned target (colour attachments in
 * plan order, a depth texture when one is planned) in one framebuffer, checked for completeness.
 * Depth is a texture rather than a renderbuffer so later passes (light shafts) can read it.
 * Multisampled targets (MSAA, samples > 1 in the plan) are renderbuffers in a second framebuffer
 * (fbo_ms) that the pass draws into and then resolves into the plain textures; their sample
 * count is clamped to what the driver offers (GL_MAX_SAMPLES).
 */
#include "gfx/render_impl.h"

typedef struct tex_format {
    GLint internal;
    GLenum format, type;
    int is_depth; /* 1 depth, 2 depth and stencil */
} tex_format;

static tex_format format_of(ww_format f) {
    switch (f) {
    case WW_FMT_RGBA16F: return (tex_format){GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 0};
    case WW_FMT_DEPTH24:
        return (tex_format){GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 1};
    case WW_FMT_RGBA8: return (tex_format){GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 0};
    case WW_FMT_DEPTH24_STENCIL8:
        return (tex_format){GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 2};
    case WW_FMT_RGBA32F: return (tex_format){GL_RGBA32F, GL_RGBA, GL_FLOAT, 0};
    }
    WW_ASSERT(!"unknown ww_format");
    return (tex_format){0, 0, 0, 0};
}

static const char *status_name(GLenum s) {
    switch (s) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default: return "unknown status";
    }
}

/* the multisampled targets of d as renderbuffers in rt->fbo_ms, attachments in the same order
 * as the plain ones; the framebuffer's status (complete when there are none) */
static GLenum create_ms(const ww_gl *gl, const ww_pass_desc *d, ww_rt *rt) {
    int want = 0;
    for (int i = 0; i < d->ntargets; i++)
        if (d->samples[i] > want) want = d->samples[i];
    if (want <= 1) return GL_FRAMEBUFFER_COMPLETE;
    GLint max = 1;
    gl->GetIntegerv(GL_MAX_SAMPLES, &max);
    rt->samples = want < max ? want : max;
    gl->GenFramebuffers(1, &rt->fbo_ms);
    gl->BindFramebuffer(GL_FRAMEBUFFER, rt->fbo_ms);
    GLenum draw[WW_PLAN_MAX_TARGETS];
    int ncolor = 0;
    for (int i = 0; i < d->ntargets; i++) {
        const ww_target_desc *t = &d->targets[i];
        if (d->samples[i] <= 1) continue;
        tex_format tf = format_of(t->format);
        GLuint rb = 0;
        gl->GenRenderbuffers(1, &rb);
        gl->BindRenderbuffer(GL_RENDERBUFFER, rb);
        gl->RenderbufferStorageMultisample(GL_RENDERBUFFER, rt->samples, (GLenum)tf.internal,
                                           t->width, t->height);
        GLenum attach = tf.is_depth == 2 ? GL_DEPTH_STENCIL_ATTACHMENT
                        : tf.is_depth  ? GL_DEPTH_ATTACHMENT
                                       : GL_COLOR_ATTACHMENT0 + (GLenum)ncolor;
        if (!tf.is_depth) draw[ncolor++] = attach;
        gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, attach, GL_RENDERBUFFER, rb);
        rt->rb[rt->nrb++] = rb;
    }
    gl->BindRenderbuffer(GL_RENDERBUFFER, 0);
    gl->DrawBuffers(ncolor, draw);
    gl->ReadBuffer(ncolor ? GL_COLOR_ATTACHMENT0 : GL_NONE);
    return gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
}

ww_result ww_gfx_rt_create(const ww_gl *gl, const ww_pass_desc *d, ww_rt *rt, ww_error *err) {
    WW_ASSERT(d->ntargets >= 1 && d->ntargets <= WW_PLAN_MAX_TARGETS);
    *rt = (ww_rt){0};
    rt->width = d->targets[0].width;
    rt->height = d->targets[0].height;
    gl->GenFramebuffers(1, &rt->fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, rt->fbo);

    /* one texture per target; nearest filtering: passes read texels, never resample */
    GLenum draw[WW_PLAN_MAX_TARGETS];
    int ncolor = 0;
    for (int i = 0; i < d->ntargets; i++) {
        const ww_target_desc *t = &d->targets[i];
        if (d->samples[i] > 1) continue; /* create_ms: in their own framebuffer */
        /* one framebuffer means one size for all of a pass's attached targets */
        WW_ASSERT(d->unattached[i] || (t->width == rt->width && t->height == rt->height));
        WW_ASSERT(t->width > 0 && t->height > 0);
        tex_format tf = format_of(t->format);
        GLuint tex = 0;
        gl->GenTextures(1, &tex);
        gl->BindTexture(GL_TEXTURE_2D, tex);
        gl->TexImage2D(GL_TEXTURE_2D, 0, tf.internal, t->width, t->height, 0, tf.format, tf.type,
                       NULL);
        gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        rt->tex[rt->ntex] = tex;
        rt->fmt[rt->ntex] = t->format;
        rt->unattached[rt->ntex] = d->unattached[i];
        rt->ntex++;
        if (d->unattached[i]) continue; /* the pass attaches it to a framebuffer of its own */
        GLenum attach = tf.is_depth == 2 ? GL_DEPTH_STENCIL_ATTACHMENT
                        : tf.is_depth  ? GL_DEPTH_ATTACHMENT
                                       : GL_COLOR_ATTACHMENT0 + (GLenum)ncolor;
        if (!tf.is_depth) draw[ncolor++] = attach;
        gl->FramebufferTexture2D(GL_FRAMEBUFFER, attach, GL_TEXTURE_2D, tex, 0);
    }
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->DrawBuffers(ncolor, draw);
    gl->ReadBuffer(ncolor ? GL_COLOR_ATTACHMENT0 : GL_NONE);

    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) status = create_ms(gl, d, rt);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        ww_gfx_rt_destroy(gl, rt);
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: framebuffer incomplete: %s (0x%04x) at %dx%d", d->name,
                            status_name(status), (unsigned)status, d->targets[0].width,
                            d->targets[0].height);
    }
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) {
        ww_gfx_rt_destroy(gl, rt);
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: making its %dx%d targets raised GL error 0x%04x", d->name,
                            d->targets[0].width, d->targets[0].height, (unsigned)e);
    }
    return WW_OK;
}

void ww_gfx_rt_destroy(const ww_gl *gl, ww_rt *rt) {
    if (rt->ntex) gl->DeleteTextures(rt->ntex, rt->tex);
    if (rt->nrb) gl->DeleteRenderbuffers(rt->nrb, rt->rb);
    if (rt->fbo_ms) gl->DeleteFramebuffers(1, &rt->fbo_ms);
    if (rt->fbo) gl->DeleteFramebuffers(1, &rt->fbo);
    *rt = (ww_rt){0};
}

GLuint ww_gfx_rt_texture(const ww_rt *rt, ww_format fmt) {
    for (int i = 0; i < rt->ntex; i++)
        if (rt->fmt[i] == fmt) return rt->tex[i];
    return 0;
}

GLuint ww_gfx_rt_texture_nth(const ww_rt *rt, ww_format fmt, int n) {
    for (int i = 0; i < rt->ntex; i++)
        if (rt->fmt[i] == fmt && n-- == 0) return rt->tex[i];
    return 0;
}

GLuint ww_gfx_rt_depth(const ww_rt *rt) {
    GLuint t = ww_gfx_rt_texture(rt, WW_FMT_DEPTH24);
    return t ? t : ww_gfx_rt_texture(rt, WW_FMT_DEPTH24_STENCIL8);
}

ww_result ww_gfx_fbo_single(const ww_gl *gl, GLuint tex, const char *pass, int side, GLuint *fbo,
                            ww_error *err) {
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->GenFramebuffers(1, fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, *fbo);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    GLenum draw = GL_COLOR_ATTACHMENT0;
    gl->DrawBuffers(1, &draw);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "pass %s: framebuffer %d incomplete (0x%04x)",
                            pass, side, (unsigned)status);
    return WW_OK;
}

void ww_gfx_mipmap_tiled(const ww_gl *gl, GLenum target) {
    gl->GenerateMipmap(target);
    gl->TexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_T, GL_REPEAT);
}
