/* sky.c - the sky drawn as one full-screen triangle on the far plane behind everything, one view
 * ray per pixel from the inverse view-projection (shaders/sky.frag.glsl): the gradient with the
 * sun disc and glow (shaders/common.glsl), the cubemap skybox of seed 004 (six images of the
 * scene's assets uploaded as one seamless, mipmapped sRGB cube texture, which the renderer then
 * offers the water to reflect: r->sky_cubemap) or the procedural dome (seed 003, common.glsl's
 * ww_sky_dome). Also sets common.glsl's sky uniforms for any program that includes it.
 */
#include <math.h>
#include <stdlib.h>

#include "gfx/render_impl.h"
#include "scene/assets.h"

/* the dome's clouds drift with the simulated time along a fixed wind (noise units per second);
 * the offset is wrapped to the noise's period in double, so a long run stays exact in float */
static const double DOME_WIND[2] = {0.011, 0.004};
static const double DOME_PERIOD = 256.0; /* WW_DOME_PERIOD in common.glsl */

struct ww_sky {
    GLuint prog;
    ww_sky_model model;
    ww_sky_locs sky;
    GLint inv_view_proj, intensity, below, cubemap, drift;
    GLuint cube_tex;  /* owned when this sky uploaded it (0 otherwise) */
    GLuint cube_draw; /* the cube texture drawn (owned or the renderer's) */
};

void ww_sky_locs_init(const ww_gl *gl, GLuint prog, ww_sky_locs *l) {
    l->zenith = ww_gfx_uniform(gl, prog, "u_sky_zenith");
    l->horizon = ww_gfx_uniform(gl, prog, "u_sky_horizon");
    l->sun_dir = ww_gfx_uniform(gl, prog, "u_sun_dir");
    l->sun_color = ww_gfx_uniform(gl, prog, "u_sun_color");
}

void ww_sky_locs_set(const ww_gl *gl, const ww_sky_locs *l, const ww_state *st) {
    gl->Uniform3f(l->zenith, (float)st->sky_zenith[0], (float)st->sky_zenith[1],
                  (float)st->sky_zenith[2]);
    gl->Uniform3f(l->horizon, (float)st->sky_horizon[0], (float)st->sky_horizon[1],
                  (float)st->sky_horizon[2]);
    gl->Uniform3f(l->sun_dir, (float)st->sun_dir[0], (float)st->sun_dir[1], (float)st->sun_dir[2]);
    gl->Uniform3f(l->sun_color, (float)st->sun_color[0], (float)st->sun_color[1],
                  (float)st->sun_color[2]);
}

/* the six faces, +x -x +y -y +z -z in GL's order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), each
 * uploaded top row first as stored: GL's convention puts t = 0 at the face's top (-y up in
 * texture space for the side faces), so the images need no flip. Seamless filtering blends
 * across face edges; the mip chain keeps the sky from shimmering where it is minified. */
static ww_result upload_cubemap(const ww_gl *gl, const ww_scene *sc, GLuint *out, ww_error *err) {
    const ww_render_desc *d = &sc->render;
    if (!sc->assets)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "sky: cubemap faces were not loaded");
    GLuint tex;
    gl->GenTextures(1, &tex);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* decoded here, one face at a time, and freed once uploaded: the scene holds only the
     * faces' sizes, so commands that draw nothing never decode them */
    for (int i = 0; i < 6; i++) {
        WW_ASSERT(d->cubemap_image[i] >= 0 && d->cubemap_image[i] < sc->assets->nimage);
        const ww_image_data *im = &sc->assets->image[d->cubemap_image[i]];
        unsigned char *rgba = NULL;
        ww_result r = ww_assets_decode(im, &rgba, err);
        if (r) {
            gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
            gl->DeleteTextures(1, &tex);
            return r;
        }
        gl->TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)i, 0, GL_SRGB8_ALPHA8, im->width,
                       im->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        ww_assets_pixels_free(rgba);
    }
    gl->GenerateMipmap(GL_TEXTURE_CUBE_MAP);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
    gl->Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    *out = tex;
    return WW_OK;
}

ww_result ww_sky_new(ww_renderer *r, const ww_scene *sc, ww_sky **out, ww_error *err) {
    static const char *const includes[] = {"common.glsl", NULL};
    static const char *const defines[] = {[WW_SKY_GRADIENT] = NULL,
                                          [WW_SKY_CUBEMAP] = "#define WW_SKY_CUBEMAP 1\n",
                                          [WW_SKY_DOME] = "#define WW_SKY_DOME 1\n"};
    const ww_gl *gl = r->gl;
    ww_sky *s = calloc(1, sizeof *s);
    if (!s) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "sky: out of memory");
    s->model = sc->render.sky;
    ww_result rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "sky.frag.glsl", includes,
                                       defines[s->model], &s->prog, err);
    /* one cube texture per renderer: a second sky (the reflection's) draws the first one's */
    if (rc == WW_OK && s->model == WW_SKY_CUBEMAP) {
        if (r->sky_cubemap) {
            s->cube_draw = r->sky_cubemap;
        } else {
            rc = upload_cubemap(gl, sc, &s->cube_tex, err);
            s->cube_draw = r->sky_cubemap = s->cube_tex;
        }
    }
    if (rc != WW_OK) {
        ww_sky_free(s, gl);
        return rc;
    }
    ww_sky_locs_init(gl, s->prog, &s->sky);
    s->inv_view_proj = ww_gfx_uniform(gl, s->prog, "u_inv_view_proj");
    s->intensity = ww_gfx_uniform(gl, s->prog, "u_intensity");
    s->below = ww_gfx_uniform(gl, s->prog, "u_below");
    s->cubemap = ww_gfx_uniform(gl, s->prog, "u_cubemap");
    s->drift = ww_gfx_uniform(gl, s->prog, "u_drift");
    *out = s;
    return WW_OK;
}

void ww_sky_draw(const ww_sky *s, const ww_gl *gl, GLuint empty_vao, const ww_frame *f) {
    /* the triangle lies on the far plane: it passes where the depth is still clear */
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LEQUAL);
    gl->DepthMask(GL_FALSE);
    gl->UseProgram(s->prog);
    ww_sky_locs_set(gl, &s->sky, f->st);
    gl->UniformMatrix4fv(s->inv_view_proj, 1, GL_FALSE, (const GLfloat *)f->inv_view_proj);
    gl->Uniform1f(s->intensity, (float)f->sc->render.sky_intensity);
    const double *fb = f->sc->render.fog_below_color;
    gl->Uniform4f(s->below, (float)fb[0], (float)fb[1], (float)fb[2], f->underwater ? 1.0f : 0.0f);
    if (s->model == WW_SKY_CUBEMAP) {
        gl->ActiveTexture(GL_TEXTURE0);
        gl->BindTexture(GL_TEXTURE_CUBE_MAP, s->cube_draw);
        gl->Uniform1i(s->cubemap, 0);
    } else if (s->model == WW_SKY_DOME) {
        double x = fmod(DOME_WIND[0] * f->st->t, DOME_PERIOD);
        double z = fmod(DOME_WIND[1] * f->st->t, DOME_PERIOD);
        gl->Uniform2f(s->drift, (float)(x < 0.0 ? x + DOME_PERIOD : x),
                      (float)(z < 0.0 ? z + DOME_PERIOD : z));
    }
    gl->BindVertexArray(empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->DepthMask(GL_TRUE);
    gl->DepthFunc(GL_LESS);
    if (s->model == WW_SKY_CUBEMAP) gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

void ww_sky_free(ww_sky *s, const ww_gl *gl) {
    if (!s) return;
    if (s->prog) gl->DeleteProgram(s->prog);
    if (s->cube_tex) gl->DeleteTextures(1, &s->cube_tex);
    free(s);
}
