/* pass_prepass.c - the scene prepass: lit colour + depth of the solid geometry on the far side of
 * the water from the camera, which the water shows through its surface (it samples the colour
 * and reads the depth for the thickness). From above, what lies under the water, cleared to the
 * under-water fog colour; from below, what lies above it (the water shows it through Snell's
 * window), cleared to nothing (alpha 0). The geometry cuts its solids at the wave surface
 * (geometry.vert.glsl); the clip plane given here, at the rest level plus the largest crest (so
 * nothing is cut where the surface dips), is the cut of flat water and of the stencilled
 * shadows' volumes. Smaller than the frame (the plan's depth_full target), it also draws the
 * same geometry's depth alone at the frame's size, which the water reads to put the outlines of
 * what it refracts, or from below shows through Snell's window, where the frame's pixels lie.
 * Publishes r->shared.scene_color, scene_depth and scene_depth_full.
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct prepass {
    const ww_rt *rt;
    GLuint color, depth;
    GLuint depth_full, full_fbo; /* the depth at the frame's size and its framebuffer; 0: none */
    int full_w, full_h;          /* its size, px */
    double crest; /* m: the highest the surface can rise above its rest level */
} prepass;

static void prepass_destroy(void *self, const ww_gl *gl) {
    prepass *p = self;
    if (p && p->full_fbo) gl->DeleteFramebuffers(1, &p->full_fbo);
    free(p);
}

/* the framebuffer of the depth at the frame's size: that texture alone, no colour */
static ww_result full_fbo_new(const ww_gl *gl, prepass *p, ww_error *err) {
    gl->GenFramebuffers(1, &p->full_fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->full_fbo);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, p->depth_full, 0);
    GLenum none = GL_NONE;
    gl->DrawBuffers(1, &none);
    gl->ReadBuffer(GL_NONE);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass prepass: the full-size depth's framebuffer is incomplete (0x%04x)",
                            (unsigned)status);
    return WW_OK;
}

static ww_result prepass_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                                const ww_rt *rt, void **self, ww_error *err) {
    /* the targets by their names in the plan (the pass has no multisampled targets, so its
     * textures are in the plan's order) */
    int td = ww_plan_target(d, "depth"), tf = ww_plan_target(d, "depth_full");
    GLuint color = ww_gfx_rt_texture(rt, WW_FMT_RGBA16F);
    GLuint depth = td >= 0 ? rt->tex[td] : 0;
    if (!color || !depth)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs an RGBA16F colour and a depth target", d->name);
    prepass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "prepass: out of memory");
    p->rt = rt;
    p->color = color;
    p->depth = depth;
    /* the water samples the colour at its own pixel's place: bilinear, since the prepass may be
     * smaller than the frame (render.refraction.scale) */
    r->gl->BindTexture(GL_TEXTURE_2D, color);
    r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    /* and the depth the same way: read nearest at half size, the water's thickness, and with it
     * the absorption, stepped along every submerged outline in 2-pixel stairs while the colour
     * under it was smooth */
    r->gl->BindTexture(GL_TEXTURE_2D, depth);
    r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    r->gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    r->gl->BindTexture(GL_TEXTURE_2D, 0);
    p->crest = ww_water_crest(sc);
    if (tf >= 0) {
        p->depth_full = rt->tex[tf];
        p->full_w = d->targets[tf].width;
        p->full_h = d->targets[tf].height;
        ww_result rc = full_fbo_new(r->gl, p, err);
        if (rc != WW_OK) {
            prepass_destroy(p, r->gl);
            return rc;
        }
    }
    *self = p;
    return WW_OK;
}

static ww_result prepass_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    prepass *p = self;
    const ww_gl *gl = r->gl;
    const ww_scene *sc = f->sc;
    ww_gfx_begin_pass(gl, p->rt);
    float plane[4];
    double level = sc->water_level - f->cam_pos[1];
    if (!f->underwater) {
        double fb[3];
        ww_fog_below_color(sc, f->st, fb);
        gl->ClearColor((float)fb[0], (float)fb[1], (float)fb[2], 1.0f);
        /* keep y <= level + crest: -y + (level + crest) >= 0 */
        plane[0] = 0.0f; plane[1] = -1.0f; plane[2] = 0.0f;
        plane[3] = (float)(level + p->crest);
    } else {
        /* nothing: the water shows the sky through Snell's window where the prepass is clear,
         * and its colour premultiplied by coverage where an edge's texels are partly clear */
        gl->ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        /* keep y >= level - crest */
        plane[0] = 0.0f; plane[1] = 1.0f; plane[2] = 0.0f;
        plane[3] = (float)(-(level - p->crest));
    }
    ww_gfx_clear_scene(r, p->rt);
    int drew = 0; /* draws the clip plane left */
    if (r->geometry) {
        ww_geometry_draw(r->geometry, r, f, WW_GEOM_PREPASS, (vec4 *)f->view_proj, plane);
        drew = ww_geometry_draw_count(r->geometry);
    }
    /* the shadows seen through the surface from above. From below, the prepass holds what
     * rises above the water (a hull, a cube's top), whose sunlit faces cannot be seen through
     * the surface from under it: the volumes there would cost as much as the main pass's and
     * change nothing seen */
    if (!f->underwater) {
        ww_stencil_shadows_apply(r->stencil, r, f, WW_GEOM_PREPASS, (vec4 *)f->view_proj, plane);
        ww_stencil_shadows_draw_visible(r->stencil, r, f, (vec4 *)f->view_proj, plane);
    }
    /* where the clip plane left nothing to draw (from below, nothing rises above the water),
     * the full-size depth would be the far plane alone, which places no outline: not drawn,
     * and the water reads the prepass as it is */
    if (p->full_fbo && drew > 0) {
        /* the same cut geometry's depth alone at the frame's size: no shading, so it costs the
         * vertices again and a depth write a pixel (from below, it places what rises above the
         * water against the sky, cleared to the far plane) */
        gl->BindFramebuffer(GL_FRAMEBUFFER, p->full_fbo);
        gl->Viewport(0, 0, p->full_w, p->full_h);
        gl->DepthMask(GL_TRUE);
        gl->ClearDepth(1.0);
        gl->Clear(GL_DEPTH_BUFFER_BIT);
        ww_geometry_draw(r->geometry, r, f, WW_GEOM_PREPASS_DEPTH, (vec4 *)f->view_proj, plane);
        r->shared.scene_depth_full = p->depth_full;
    }
    r->shared.scene_color = p->color;
    r->shared.scene_depth = p->depth;
    return WW_OK;
}

const ww_pass_ops ww_pass_prepass_ops = {prepass_create, prepass_run, prepass_destroy};
