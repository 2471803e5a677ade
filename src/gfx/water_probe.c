/* water_probe.c - the wave field as the water shaders evaluate it, read back for the GPU-vs-CPU
 * accuracy test and bench (renderer.h: ww_gfx_water_probe). The probe program is built from the
 * same gerstner.glsl functions as the water pass, with the fade off; its uniform blocks are
 * packed by the same code (water.c) with the camera as the centre the phases are taken at.
 */
#include <math.h>
#include <stdlib.h>

#include "gfx/render_impl.h"

#define PROBE_ROW 1024 /* points per row of the targets (GL 3.3 guarantees 1024 texels) */

typedef struct probe {
    GLuint prog, vao, vbo, fbo, tex[2];
    ww_water_ubos ubos;
    ww_water_waves waves;
    ww_ripple_block ripples;
    float *rest, *pix; /* rest offsets (2 n), one target read back (4 w h) */
} probe;

static void probe_free(probe *p, const ww_gl *gl) {
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->UseProgram(0);
    if (p->prog) gl->DeleteProgram(p->prog);
    if (p->vao) gl->DeleteVertexArrays(1, &p->vao);
    if (p->vbo) gl->DeleteBuffers(1, &p->vbo);
    if (p->fbo) gl->DeleteFramebuffers(1, &p->fbo);
    if (p->tex[0]) gl->DeleteTextures(2, p->tex);
    ww_water_ubos_free(gl, &p->ubos);
    free(p->rest);
    free(p->pix);
    free(p);
}

/* two RGBA32F colour attachments of w x h: points, normals */
static ww_result make_targets(probe *p, const ww_gl *gl, int w, int h, ww_error *err) {
    GLenum draw[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl->GenFramebuffers(1, &p->fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->fbo);
    gl->GenTextures(2, p->tex);
    for (int i = 0; i < 2; i++) {
        gl->BindTexture(GL_TEXTURE_2D, p->tex[i]);
        gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, NULL);
        gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl->FramebufferTexture2D(GL_FRAMEBUFFER, draw[i], GL_TEXTURE_2D, p->tex[i], 0);
    }
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->DrawBuffers(2, draw);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "water probe: RGBA32F framebuffer %dx%d incomplete (0x%04x)", w, h,
                            (unsigned)status);
    return WW_OK;
}

ww_result ww_gfx_water_probe(const ww_gl *gl, const ww_scene *sc, const ww_state *st,
                             const double cam[3], int n, const double *rest_xz, float *out,
                             ww_error *err) {
    WW_ASSERT(gl && sc && st && cam && rest_xz && out && n > 0);
    int w = n < PROBE_ROW ? n : PROBE_ROW, h = (n + w - 1) / w;
    probe *p = calloc(1, sizeof *p);
    if (p) {
        p->rest = malloc((size_t)n * 2 * sizeof *p->rest);
        p->pix = malloc((size_t)w * (size_t)h * 4 * sizeof *p->pix);
    }
    if (!p || !p->rest || !p->pix) {
        if (p) probe_free(p, gl);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water probe: out of memory for %d points", n);
    }

    /* the blocks as the water pass packs them, centred on the camera instead of the mesh */
    const double centre[2] = {cam[0], cam[2]};
    ww_water_waves_init(sc, &p->waves);
    ww_water_waves_phases(sc, st, centre, &p->waves);
    ww_water_pack_ripples(sc, st, centre, &p->ripples);
    for (int i = 0; i < 2 * n; i++) p->rest[i] = (float)rest_xz[i];

    ww_result rc = ww_water_program(gl, sc, "water_probe.vert.glsl", "water_probe.frag.glsl", 0, NULL,
                                    &p->prog, err);
    if (rc == WW_OK) rc = ww_water_ubos_new(gl, sc, &p->waves, &p->ubos, err);
    if (rc == WW_OK) rc = make_targets(p, gl, w, h, err);
    if (rc != WW_OK) {
        probe_free(p, gl);
        return rc;
    }
    ww_water_ubos_upload(gl, &p->ubos, &p->waves, sc->ripples_on ? &p->ripples : NULL, 1);

    gl->GenVertexArrays(1, &p->vao);
    gl->GenBuffers(1, &p->vbo);
    gl->BindVertexArray(p->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, p->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)n * 2 * sizeof *p->rest), p->rest,
                   GL_STATIC_DRAW);
    gl->EnableVertexAttribArray(0);
    gl->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), NULL);

    /* alpha 1 marks a pixel no point reached (the probe writes 0) */
    ww_rt rt = {.fbo = p->fbo, .width = w, .height = h};
    ww_gfx_begin_pass(gl, &rt);
    gl->ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl->Clear(GL_COLOR_BUFFER_BIT);
    gl->UseProgram(p->prog);
    gl->Uniform1f(ww_gfx_uniform(gl, p->prog, "u_level"), (float)(sc->water_level - cam[1]));
    gl->Uniform2i(ww_gfx_uniform(gl, p->prog, "u_size"), w, h);
    ww_water_ubos_bind(gl, &p->ubos);
    gl->DrawArrays(GL_POINTS, 0, n);
    gl->BindVertexArray(0);

    /* read back both targets and interleave: point (x, y, z, 0), normal (x, y, z, 0) */
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, p->fbo);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 4);
    int missed = 0;
    for (int t = 0; t < 2; t++) {
        gl->ReadBuffer(GL_COLOR_ATTACHMENT0 + (GLenum)t);
        gl->ReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, p->pix);
        for (int i = 0; i < n; i++) {
            missed += p->pix[4 * i + 3] != 0.0f;
            for (int c = 0; c < 4; c++) out[8 * i + 4 * t + c] = p->pix[4 * i + c];
        }
    }
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    GLenum e = gl->GetError();
    probe_free(p, gl);
    if (e != GL_NO_ERROR)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "water probe: GL error 0x%04x", (unsigned)e);
    if (missed)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "water probe: %d of %d points were not drawn", missed / 2, n);
    return WW_OK;
}
