/* pass_reflection.c - planar reflection (seeds 000, 002): the scene above the water seen by the
 * camera mirrored about the water's rest plane y = level, into a mipmapped RGBA16F texture that
 * the water samples by projective texture mapping (water.c, water.frag.glsl). Skipped when the
 * camera is under water (the surface seen from below reflects the water, not the sky).
 *
 * Drawing is camera-relative, so the mirror is one matrix on the camera-relative world:
 * M (x, y, z) = (x, 2 h - y, z) with h = level - camera y, and the mirror camera's view-projection
 * is proj * view * M. A point on the plane is its own image, so the mirror camera images the
 * water where the main camera does and the water reads the texture at its own window position,
 * without seed 002's flip of the texture coordinates. Geometry keeps y > water + bias by a user
 * clip plane (gl_ClipDistance) rather than an oblique near plane (Lengyel, "Oblique View Frustum
 * Depth Projection and Clipping", 2005), which would change the sky's far-plane depth. The plane
 * is the one the geometry shader shades by (the surface over the camera, u_water_y): below it a
 * face is lit and fogged as under water, teal, and a submerged face in the reflection showed as
 * teal blobs around everything that floats.
 *
 * Where there are objects to mirror, the pass also leaves its depth and a pyramid of the mirror
 * image's nearest depths (mirror_near.frag.glsl): the water reads them to leave out an image that
 * lies in front of the water point it would be seen from (water.frag.glsl, WW_REFLECT_DEPTH).
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

#define CLIP_BIAS 0.01 /* m the clip plane lies above the water plane, so no fragment the
                        * shader would shade as under water survives the clipped edge's rounding */
#define NEAR_LEVELS 6   /* levels of the nearest-depth pyramid: the colour's levels 1 to 6, past
                         * which a lookup's footprint (64 texels) is wider than what floats */

typedef struct reflection_pass {
    const ww_rt *rt;
    GLuint color;    /* the mipmapped colour target */
    GLuint prog;     /* the mirrored sky */
    ww_sky_locs sky;
    GLint inv_view_proj, cube, cube_tex, sky_intensity, dome_tex;
    /* the nearest-depth pyramid: level k the least depth of the 2^(k+1)-texel squares of the
     * depth target; 0 where the scene has no objects to mirror */
    GLuint depth, near_tex, near_fbo, near_prog;
    GLint near_src;
    int near_levels, near_w[NEAR_LEVELS], near_h[NEAR_LEVELS];
} reflection_pass;

static void reflection_destroy(void *self, const ww_gl *gl) {
    reflection_pass *p = self;
    if (!p) return;
    if (p->prog) gl->DeleteProgram(p->prog);
    if (p->near_prog) gl->DeleteProgram(p->near_prog);
    if (p->near_fbo) gl->DeleteFramebuffers(1, &p->near_fbo);
    if (p->near_tex) gl->DeleteTextures(1, &p->near_tex);
    free(p);
}

/* the nearest-depth pyramid's texture (R32F, levels half the depth target's size and down), its
 * framebuffer and program */
static ww_result near_create(reflection_pass *p, const ww_gl *gl, const ww_rt *rt,
                             ww_error *err) {
    ww_result rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "mirror_near.frag.glsl", NULL,
                                  &p->near_prog, err);
    if (rc != WW_OK) return rc;
    p->near_src = ww_gfx_uniform(gl, p->near_prog, "u_src");
    gl->GenTextures(1, &p->near_tex);
    gl->BindTexture(GL_TEXTURE_2D, p->near_tex);
    int w = rt->width, h = rt->height;
    for (int k = 0; k < NEAR_LEVELS && (w > 1 || h > 1); k++) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        p->near_w[k] = w;
        p->near_h[k] = h;
        gl->TexImage2D(GL_TEXTURE_2D, k, GL_R32F, w, h, 0, GL_RED, GL_FLOAT, NULL);
        p->near_levels = k + 1;
    }
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, p->near_levels - 1);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->GenFramebuffers(1, &p->near_fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->near_fbo);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, p->near_tex, 0);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass reflection: the nearest-depth framebuffer is incomplete "
                            "(0x%04x)", (unsigned)status);
    return WW_OK;
}

/* each level of the pyramid from the one below it (the first from the depth target), read at
 * that level alone (base and top level) so that the level drawn into is never also read */
static void near_build(const reflection_pass *p, const ww_renderer *r) {
    const ww_gl *gl = r->gl;
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->near_fbo);
    gl->Disable(GL_DEPTH_TEST);
    gl->Disable(GL_BLEND);
    gl->UseProgram(p->near_prog);
    gl->Uniform1i(p->near_src, 0);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindVertexArray(r->empty_vao);
    for (int k = 0; k < p->near_levels; k++) {
        if (k == 0) {
            gl->BindTexture(GL_TEXTURE_2D, p->depth);
        } else {
            gl->BindTexture(GL_TEXTURE_2D, p->near_tex);
            gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, k - 1);
            gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, k - 1);
        }
        gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, p->near_tex,
                                 k);
        gl->Viewport(0, 0, p->near_w[k], p->near_h[k]);
        gl->DrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl->BindVertexArray(0);
    gl->BindTexture(GL_TEXTURE_2D, p->near_tex);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, p->near_levels - 1);
    gl->BindTexture(GL_TEXTURE_2D, 0);
}

static ww_result reflection_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                                   const ww_rt *rt, void **self, ww_error *err) {
    static const char *const includes[] = {"common.glsl", NULL};
    const ww_gl *gl = r->gl;
    GLuint color = ww_gfx_rt_texture(rt, WW_FMT_RGBA16F);
    GLuint depth = ww_gfx_rt_texture(rt, WW_FMT_DEPTH24);
    if (!color || !depth)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs an RGBA16F colour and a DEPTH24 target", d->name);
    reflection_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "reflection pass: out of memory");
    p->rt = rt;
    p->color = color;
    p->depth = depth;
    ww_result rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "reflection_sky.frag.glsl",
                                       includes,
                                       ww_sky_dome_image_on(sc) ? "#define WW_SKY_DOME_IMAGE 1\n"
                                                                : ww_sky_defines(sc),
                                       &p->prog, err);
    if (rc == WW_OK && ww_reflection_has_objects(r, sc)) rc = near_create(p, gl, rt, err);
    if (rc != WW_OK) {
        reflection_destroy(p, gl);
        return rc;
    }
    ww_sky_locs_init(gl, p->prog, sc, &p->sky);
    p->inv_view_proj = ww_gfx_uniform(gl, p->prog, "u_inv_view_proj");
    p->cube = ww_gfx_uniform(gl, p->prog, "u_cube");
    p->cube_tex = ww_gfx_uniform(gl, p->prog, "u_sky_cube");
    p->sky_intensity = ww_gfx_uniform(gl, p->prog, "u_sky_intensity");
    p->dome_tex = ww_gfx_uniform(gl, p->prog, "u_sky_dome_image");

    /* trilinear: grazing views squeeze the distorted lookups, and the mip chain keeps them from
     * shimmering (seed 000); the levels are allocated here and filled each frame */
    gl->BindTexture(GL_TEXTURE_2D, color);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->GenerateMipmap(GL_TEXTURE_2D);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    *self = p;
    return WW_OK;
}

static ww_result reflection_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    reflection_pass *p = self;
    const ww_gl *gl = r->gl;
    if (f->underwater) {
        r->shared.reflection = 0;
        r->shared.reflection_tex = 0;
        r->shared.reflection_near = 0;
        r->shared.reflection_depth = 0;
        return WW_OK;
    }

    /* the mirror about y = h (camera-relative), and the mirror camera's view-projection */
    float h = (float)(f->sc->water_level - f->cam_pos[1]);
    mat4 m, pv, vp;
    glm_mat4_identity(m);
    m[1][1] = -1.0f;
    m[3][1] = 2.0f * h;
    glm_mat4_mul((vec4 *)f->proj, (vec4 *)f->view, pv);
    glm_mat4_mul(pv, m, vp);

    ww_gfx_begin_pass(gl, p->rt);
    gl->ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    gl->ClearDepth(1.0);
    gl->DepthMask(GL_TRUE);
    gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (r->geometry) {
        /* keep y >= water_y + CLIP_BIAS, camera-relative, water_y as geometry.c sets it */
        double water_y = f->surface_y - f->cam_pos[1];
        float clip[4] = {0.0f, 1.0f, 0.0f, (float)(-(water_y + CLIP_BIAS))};
        ww_geometry_draw(r->geometry, r, f, WW_GEOM_REFLECTION, vp, clip);
    }

    /* the sky along the mirrored rays: the flip of y alone (the mirror's translation moves
     * nothing at infinity), on the far plane behind the geometry */
    mat4 flip, sky_vp, inv;
    glm_mat4_identity(flip);
    flip[1][1] = -1.0f;
    glm_mat4_mul(pv, flip, sky_vp);
    glm_mat4_inv(sky_vp, inv);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LEQUAL);
    gl->DepthMask(GL_FALSE);
    gl->UseProgram(p->prog);
    ww_sky_locs_set(gl, &p->sky, f->st);
    gl->UniformMatrix4fv(p->inv_view_proj, 1, GL_FALSE, (const GLfloat *)inv);
    gl->Uniform1i(p->cube, r->sky_cubemap != 0);
    gl->Uniform1i(p->cube_tex, 0);
    gl->Uniform1f(p->sky_intensity, (float)f->sc->render.sky_intensity);
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, r->sky_cubemap);
    if (r->sky_dome_image) {
        /* the dome's picture on unit 1 (the cube's sampler keeps unit 0) */
        gl->Uniform1i(p->dome_tex, 1);
        gl->ActiveTexture(GL_TEXTURE1);
        gl->BindTexture(GL_TEXTURE_2D, r->sky_dome_image);
        gl->ActiveTexture(GL_TEXTURE0);
    }
    gl->BindVertexArray(r->empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindVertexArray(0);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
    if (r->sky_dome_image) {
        gl->ActiveTexture(GL_TEXTURE1);
        gl->BindTexture(GL_TEXTURE_2D, 0);
        gl->ActiveTexture(GL_TEXTURE0);
    }
    gl->DepthMask(GL_TRUE);
    gl->DepthFunc(GL_LESS);
    /* additive light last: the sky would overwrite it where nothing opaque lies behind */
    if (r->geometry) ww_geometry_draw_glow(r->geometry, r, WW_GEOM_REFLECTION);

    gl->BindTexture(GL_TEXTURE_2D, p->color);
    gl->GenerateMipmap(GL_TEXTURE_2D);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    r->shared.reflection = 1;
    r->shared.reflection_tex = p->color;
    r->shared.reflection_near = p->near_tex;
    r->shared.reflection_near_levels = p->near_levels;
    r->shared.reflection_depth = p->near_tex ? p->depth : 0;
    if (p->near_tex) near_build(p, r);
    return WW_OK;
}

const ww_pass_ops ww_pass_reflection_ops = {reflection_create, reflection_run, reflection_destroy};
