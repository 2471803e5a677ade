/* pass_main.c - the main HDR pass: clears its RGBA16F colour + depth targets, draws the water
 * surface (through its G-buffer where the plan gives one: gfx/water.c) and the solid geometry (in a scene with boats the solids first, then the lid over each
 * boat's inside into depth so no water is drawn inside a hull, then the water and the seabed),
 * then the sky on the far plane behind it (sky.c, water.c, geometry.c). With MSAA (render.msaa)
 * it draws into the multisampled framebuffer and resolves colour and depth into its textures at
 * the end (post).
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct main_pass {
    const ww_rt *rt;
    ww_sky *sky;
    ww_water *water;
} main_pass;

static void main_destroy(void *self, const ww_gl *gl) {
    main_pass *p = self;
    if (!p) return;
    ww_sky_free(p->sky, gl);
    ww_water_free(p->water, gl);
    free(p);
}

static ww_result main_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                             const ww_rt *rt, void **self, ww_error *err) {
    if (!ww_gfx_rt_texture(rt, WW_FMT_RGBA16F) || !ww_gfx_rt_depth(rt))
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs an RGBA16F colour and a DEPTH24 target", d->name);
    main_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "main pass: out of memory");
    p->rt = rt;
    ww_result rc = ww_sky_new(r, sc, &p->sky, err);
    /* the water upsamples the refraction by the prepass's full-size depth where the plan has it */
    int edges = ww_plan_target(ww_plan_pass(&r->plan, WW_PASS_PREPASS), "depth_full") >= 0;
    /* and leaves out mirror images that lie in front of it where the reflection has objects */
    int mirror_depth = ww_reflection_has_objects(r, sc) &&
                       ww_plan_pass(&r->plan, WW_PASS_REFLECTION) != NULL;
    if (rc == WW_OK) rc = ww_water_new(r->gl, sc, edges, mirror_depth, &p->water, err);
    if (rc != WW_OK) {
        main_destroy(p, r->gl);
        return rc;
    }
    *self = p;
    return WW_OK;
}

/* the boat's wake, the air bubbles and the fishing line last, blended over all that lies behind
 * them (the water, the sky) */
static void draw_blended(ww_renderer *r, const ww_frame *f) {
    unsigned parts = (ww_geometry_has_bubbles(r->geometry) ? WW_GEOM_PART_BUBBLES : 0u) |
                     (ww_geometry_has_line(r->geometry) ? WW_GEOM_PART_LINE : 0u) |
                     (ww_geometry_has_wake(r->geometry) ? WW_GEOM_PART_WAKE : 0u);
    if (parts)
        ww_geometry_draw_parts(r->geometry, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL,
                               parts);
}

static ww_result main_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    ww_result rc;
    main_pass *p = self;
    const ww_gl *gl = r->gl;
    ww_gfx_begin_pass(gl, p->rt);
    if (p->rt->fbo_ms) gl->BindFramebuffer(GL_FRAMEBUFFER, p->rt->fbo_ms); /* post: MSAA */
    gl->ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    ww_gfx_clear_scene(r, p->rt);
    if (f->sc->render.water.alpha_blend && !f->underwater) {
        /* seed 004: the water blends over whatever lies behind it, the sky included */
        if (r->geometry) {
            ww_geometry_draw(r->geometry, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL);
            ww_geometry_draw_hull_mask(r->geometry, r, f, (vec4 *)f->view_proj);
            ww_stencil_shadows_apply(r->stencil, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL);
        }
        if ((rc = ww_sky_draw(p->sky, gl, r->empty_vao, f, err))) return rc;
        if (r->geometry) ww_geometry_draw_glow(r->geometry, r, WW_GEOM_MAIN);
        if ((rc = ww_water_draw(p->water, r, f, err))) return rc;
        draw_blended(r, f);
    } else if (!ww_geometry_has_hulls(r->geometry)) {
        /* the opaque water first: what lies beyond it (the seabed, everything under the surface,
         * which the water shows through the prepass) then fails the depth test before it is
         * shaded; the sky last shades only what is left uncovered */
        if ((rc = ww_water_draw(p->water, r, f, err))) return rc;
        if (r->geometry)
            ww_geometry_draw(r->geometry, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL);
        ww_stencil_shadows_apply(r->stencil, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL);
        if ((rc = ww_sky_draw(p->sky, gl, r->empty_vao, f, err))) return rc;
        /* additive light last: the sky would overwrite it where nothing opaque lies behind */
        if (r->geometry) ww_geometry_draw_glow(r->geometry, r, WW_GEOM_MAIN);
        draw_blended(r, f);
    } else {
        /* with boats: the objects, then the lids over the boats' insides into depth (the insides
         * keep their colour, the water under a lid fails the depth test), then the opaque water,
         * then the seabed beyond it (which the water shows through the prepass: it fails the
         * depth test before it is shaded) and the sky. What lies under the water is shaded
         * before the water hides it: about a tenth of lake.yaml's frame on llvmpipe */
        ww_geometry_draw_parts(r->geometry, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL,
                               WW_GEOM_PART_SOLIDS);
        ww_geometry_draw_hull_mask(r->geometry, r, f, (vec4 *)f->view_proj);
        if ((rc = ww_water_draw(p->water, r, f, err))) return rc;
        ww_geometry_draw_parts(r->geometry, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL,
                               WW_GEOM_PART_SEABED);
        ww_stencil_shadows_apply(r->stencil, r, f, WW_GEOM_MAIN, (vec4 *)f->view_proj, NULL);
        if ((rc = ww_sky_draw(p->sky, gl, r->empty_vao, f, err))) return rc;
        /* additive light last: the sky would overwrite it where nothing opaque lies behind */
        if (r->geometry) ww_geometry_draw_glow(r->geometry, r, WW_GEOM_MAIN);
        draw_blended(r, f);
    }
    /* volumes_visible: the volumes themselves, over everything opaque */
    ww_stencil_shadows_draw_visible(r->stencil, r, f, (vec4 *)f->view_proj, NULL);
    if (p->rt->fbo_ms) {
        /* post: resolve the samples: colour averaged, depth one sample per pixel (NEAREST, the
         * only filter a depth blit allows) */
        int w = p->rt->width, h = p->rt->height;
        gl->BindFramebuffer(GL_READ_FRAMEBUFFER, p->rt->fbo_ms);
        gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, p->rt->fbo);
        gl->BlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                            GL_NEAREST);
        gl->BindFramebuffer(GL_FRAMEBUFFER, p->rt->fbo);
    }
    return WW_OK;
}

const ww_pass_ops ww_pass_main_ops = {main_create, main_run, main_destroy};
