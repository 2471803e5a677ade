/* pass_skymap.c - the sky map: Preetham's sky and its clouds (common.glsl's ww_sky_exact and
 * ww_sky_cloud) evaluated once a frame into a small RGBA16F latitude-longitude map
 * (shaders/skymap.frag.glsl), which then stays bound to texture unit WW_TEX_SKY_MAP for the
 * frame's later passes: the programs built with WW_SKY_MAP (sky.c, water.c, geometry.c,
 * pass_reflection.c) sample it instead of evaluating the sky per pixel. Planned only for the
 * skies that cost (ww_sky_map_on); WW_SKY_EXACT=1 plans none.
 */
#include <stdlib.h>

#include "gfx/render_impl.h"

typedef struct skymap_pass {
    const ww_rt *rt;
    GLuint tex, prog;
    ww_sky_locs sky;
} skymap_pass;

static void skymap_destroy(void *self, const ww_gl *gl) {
    skymap_pass *p = self;
    if (!p) return;
    if (p->prog) gl->DeleteProgram(p->prog);
    free(p);
}

static ww_result skymap_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                               const ww_rt *rt, void **self, ww_error *err) {
    static const char *const includes[] = {"common.glsl", NULL};
    const ww_gl *gl = r->gl;
    GLuint tex = ww_gfx_rt_texture(rt, WW_FMT_RGBA16F);
    if (!tex)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "pass %s: needs an RGBA16F target",
                            d->name);
    skymap_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "skymap pass: out of memory");
    p->rt = rt;
    p->tex = tex;
    ww_result rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "skymap.frag.glsl", includes,
                                  &p->prog, err);
    if (rc != WW_OK) {
        skymap_destroy(p, gl);
        return rc;
    }
    ww_sky_locs_init(gl, p->prog, sc, &p->sky);
    /* sampled bilinearly; the azimuth wraps, the elevation ends at the poles */
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    *self = p;
    return WW_OK;
}

static ww_result skymap_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    skymap_pass *p = self;
    const ww_gl *gl = r->gl;
    /* last frame's map leaves its unit while this one is drawn into it */
    gl->ActiveTexture(GL_TEXTURE0 + WW_TEX_SKY_MAP);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    ww_gfx_begin_pass(gl, p->rt);
    gl->UseProgram(p->prog);
    ww_sky_locs_set(gl, &p->sky, f->st);
    gl->BindVertexArray(r->empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindTexture(GL_TEXTURE_2D, p->tex);
    gl->ActiveTexture(GL_TEXTURE0);
    return WW_OK;
}

const ww_pass_ops ww_pass_skymap_ops = {skymap_create, skymap_run, skymap_destroy};
