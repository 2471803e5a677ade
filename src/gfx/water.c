/* water.c - the water surface: a static polar mesh built once (rings whose spacing grows
 * geometrically from 0.5 m to the horizon), re-centred each frame on the camera snapped to a
 * 0.5 m grid and displaced in the vertex shader by the Gerstner waves of src/sim/waves.h.
 * Wave phases are taken at the mesh centre here in double, so the shaders stay exact in float at
 * t = 1e6 s and 1e5 m from the origin.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"

#define WATER_SEGMENTS 256 /* vertices around each ring */
#define WATER_RINGS 160    /* rings around the centre vertex */
#define WATER_S0 0.5       /* distance of the first ring from the centre, m */
#define WATER_REACH 0.9    /* outer ring radius as a fraction of the far clip */
#define WATER_SNAP 0.5     /* the mesh centre moves on this grid, m */
#define WATER_INNER_R 10.0 /* rings inside this radius are always drawn whole, m */

struct ww_water {
    GLuint prog, vao, vbo, ibo;
    GLsizei ninner;     /* indices of the inner disc (drawn whole), first in the buffer */
    GLsizei per_seg;    /* indices of one angular segment of the outer rings, after the disc */
    double inner_r;     /* radius of the inner disc's outer ring, m */
    int cull;           /* draw only the segments in view (WW_WATER_CULL=0 turns it off) */
    float grid[3]; /* (s0, q - 1, angular step) for the shaders' spacing estimate */
    ww_sky_locs sky;
    GLint view_proj, origin, nwaves, wave, wave_phase, ugrid;
    GLint water_color, ambient, fog_color, fog_density, pixel_angle;
};

/* ring growth q such that rings s0, s0 q, s0 q^2, ... apart end at radius reach after n rings:
 * s0 (q^n - 1) / (q - 1) = reach; 1 when evenly spaced rings already reach */
static double ring_growth(double s0, int n, double reach) {
    if (reach <= s0 * n) return 1.0;
    double lo = 1.0 + 1e-12, hi = 2.0;
    for (int it = 0; it < 200; it++) {
        double q = 0.5 * (lo + hi);
        double r = s0 * (pow(q, n) - 1.0) / (q - 1.0);
        if (r < reach) lo = q; else hi = q;
    }
    return 0.5 * (lo + hi);
}

/* the two triangles between rings j and j + 1 in segment i */
static size_t quad(GLuint *idx, size_t k, int nseg, int j, int i) {
    GLuint a = (GLuint)(1 + j * nseg + i), b = (GLuint)(1 + j * nseg + (i + 1) % nseg);
    GLuint c = a + (GLuint)nseg, d = b + (GLuint)nseg;
    idx[k++] = a; idx[k++] = b; idx[k++] = c;
    idx[k++] = b; idx[k++] = d; idx[k++] = c;
    return k;
}

/* centre vertex, then WATER_RINGS rings of WATER_SEGMENTS vertices; indexed triangles in two
 * blocks: the inner disc (a fan and the rings within WATER_INNER_R), then the outer rings one
 * angular segment after another, so that a wedge of segments is one contiguous range and the
 * draw can skip what lies outside the view (water_draw) */
static ww_result build_mesh(ww_water *w, const ww_gl *gl, double reach, ww_error *err) {
    const int nseg = WATER_SEGMENTS, nring = WATER_RINGS;
    double q = ring_growth(WATER_S0, nring, reach);
    double s0 = q == 1.0 ? reach / nring : WATER_S0;
    double dtheta = WW_TAU / nseg;
    w->grid[0] = (float)s0;
    w->grid[1] = (float)(q - 1.0);
    w->grid[2] = (float)dtheta;

    size_t nvert = 1 + (size_t)nring * (size_t)nseg;
    size_t nidx = (size_t)nseg * 3 + (size_t)(nring - 1) * (size_t)nseg * 6;
    float *v = malloc(nvert * 2 * sizeof *v);
    GLuint *idx = malloc(nidx * sizeof *idx);
    if (!v || !idx) {
        free(v);
        free(idx);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water: out of memory for the mesh");
    }

    /* vertices: ring j (1-based) at radius s0 (q^j - 1) / (q - 1), or j s0 when q = 1 */
    v[0] = v[1] = 0.0f;
    double r = 0.0, step = s0;
    int ninner = 1; /* rings in the inner disc */
    for (int j = 0; j < nring; j++) {
        r += step;
        step *= q;
        if (r <= WATER_INNER_R || j == 0) {
            ninner = j + 1;
            w->inner_r = r;
        }
        for (int i = 0; i < nseg; i++) {
            size_t at = 1 + (size_t)j * (size_t)nseg + (size_t)i;
            v[2 * at] = (float)(r * cos(i * dtheta));
            v[2 * at + 1] = (float)(r * sin(i * dtheta));
        }
    }

    /* triangles: a fan around the centre, then two per quad between neighbouring rings */
    size_t k = 0;
    for (int i = 0; i < nseg; i++) {
        idx[k++] = 0;
        idx[k++] = (GLuint)(1 + (i + 1) % nseg);
        idx[k++] = (GLuint)(1 + i);
    }
    for (int j = 0; j + 1 < ninner; j++)
        for (int i = 0; i < nseg; i++) k = quad(idx, k, nseg, j, i);
    w->ninner = (GLsizei)k;
    for (int i = 0; i < nseg; i++)
        for (int j = ninner - 1; j + 1 < nring; j++) k = quad(idx, k, nseg, j, i);
    w->per_seg = (GLsizei)(6 * (nring - ninner));
    WW_ASSERT(k == nidx);

    gl->GenVertexArrays(1, &w->vao);
    gl->GenBuffers(1, &w->vbo);
    gl->GenBuffers(1, &w->ibo);
    gl->BindVertexArray(w->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, w->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nvert * 2 * sizeof *v), v, GL_STATIC_DRAW);
    gl->EnableVertexAttribArray(0);
    gl->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), NULL);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, w->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(nidx * sizeof *idx), idx, GL_STATIC_DRAW);
    gl->BindVertexArray(0);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    free(v);
    free(idx);
    return WW_OK;
}

ww_result ww_water_new(const ww_gl *gl, const ww_scene *sc, ww_water **out, ww_error *err) {
    static const char *const includes[] = {"common.glsl", "gerstner.glsl", NULL};
    ww_water *w = calloc(1, sizeof *w);
    if (!w) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water: out of memory");
    ww_result rc = ww_gfx_program(gl, "water.vert.glsl", "water.frag.glsl", includes, &w->prog,
                                  err);
    if (rc == WW_OK) rc = build_mesh(w, gl, WATER_REACH * sc->far_clip, err);
    const char *cull = getenv("WW_WATER_CULL");
    w->cull = !(cull && strcmp(cull, "0") == 0);
    if (rc != WW_OK) {
        ww_water_free(w, gl);
        return rc;
    }
    ww_sky_locs_init(gl, w->prog, &w->sky);
    w->view_proj = ww_gfx_uniform(gl, w->prog, "u_view_proj");
    w->origin = ww_gfx_uniform(gl, w->prog, "u_origin");
    w->nwaves = ww_gfx_uniform(gl, w->prog, "u_nwaves");
    w->wave = ww_gfx_uniform(gl, w->prog, "u_wave");
    w->wave_phase = ww_gfx_uniform(gl, w->prog, "u_wave_phase");
    w->ugrid = ww_gfx_uniform(gl, w->prog, "u_grid");
    w->water_color = ww_gfx_uniform(gl, w->prog, "u_water_color");
    w->ambient = ww_gfx_uniform(gl, w->prog, "u_ambient");
    w->fog_color = ww_gfx_uniform(gl, w->prog, "u_fog_color");
    w->fog_density = ww_gfx_uniform(gl, w->prog, "u_fog_density");
    w->pixel_angle = ww_gfx_uniform(gl, w->prog, "u_pixel_angle");
    *out = w;
    return WW_OK;
}

/* the waves as the shaders take them: (k Dx, k Dz, A, Q) and the phase at the mesh centre,
 * phase_c = wrap(k D.centre + phase at the origin), in double; returns how many */
static int pack_waves(const ww_scene *sc, const ww_state *st, const double centre[2],
                      float wave[WW_MAX_WAVES][4], float phase[WW_MAX_WAVES]) {
    int n = 0;
    if (sc->wave_model != WW_WAVES_GERSTNER) return 0;
    for (int i = 0; i < sc->nwaves && i < WW_MAX_WAVES; i++) {
        const ww_wave *wv = &sc->waves[i];
        if (!(wv->k > 0.0)) continue; /* no wave to draw (and no direction to divide by) */
        double kx = wv->k * wv->dir[0], kz = wv->k * wv->dir[1];
        wave[n][0] = (float)kx;
        wave[n][1] = (float)kz;
        wave[n][2] = (float)wv->amplitude;
        wave[n][3] = (float)wv->steepness;
        phase[n] = (float)ww_m_wrap_tau(kx * centre[0] + kz * centre[1] + st->wave_phase[i]);
        n++;
    }
    return n;
}

static void draw_segments(const ww_water *w, const ww_gl *gl, int first, int count) {
    if (count <= 0) return;
    size_t offset = ((size_t)w->ninner + (size_t)first * (size_t)w->per_seg) * sizeof(GLuint);
    gl->DrawElements(GL_TRIANGLES, count * w->per_seg, GL_UNSIGNED_INT, (const void *)offset);
}

/* the wedge of outer segments the view can see: [first, first + count) modulo WATER_SEGMENTS.
 * The frustum is the cone of its four corner rays; unless it holds the vertical (then every
 * azimuth is in view) its shadow on the water plane is a wedge bounded by the corners' azimuths.
 * The margin covers the mesh centre's snap offset and the waves' sideways displacement, both
 * seen from the inner disc's edge, the nearest outer vertex. */
static void visible_segments(const ww_water *w, const ww_frame *f, const ww_scene *sc,
                             const double centre[2], int *first, int *count) {
    *first = 0;
    *count = WATER_SEGMENTS;
    if (!w->cull) return;
    double corner = atan(sqrt(f->tan_half[0] * f->tan_half[0] + f->tan_half[1] * f->tan_half[1]));
    double off = hypot(centre[0] - f->cam_pos[0], centre[1] - f->cam_pos[2]);
    for (int i = 0; i < sc->nwaves; i++) off += sc->waves[i].steepness * sc->waves[i].amplitude;
    if (off >= w->inner_r) return;
    double margin = asin(off / w->inner_r) + 2.0 * WW_TAU / WATER_SEGMENTS;
    double vert = acos(ww_m_clamp(fabs(f->fwd[1]), 0.0, 1.0)); /* angle to the nearest vertical */
    if (vert <= corner + margin) return;

    double a0 = atan2(f->fwd[2], f->fwd[0]), lo = 0.0, hi = 0.0;
    for (int c = 0; c < 4; c++) {
        double sx = (c & 1) ? 1.0 : -1.0, sy = (c & 2) ? 1.0 : -1.0, d[3];
        for (int k = 0; k < 3; k++)
            d[k] = f->fwd[k] + sx * f->tan_half[0] * f->right[k] + sy * f->tan_half[1] * f->up[k];
        double da = atan2(d[2], d[0]) - a0;
        da -= WW_TAU * floor((da + WW_PI) / WW_TAU); /* to [-pi, pi) */
        if (da < lo) lo = da;
        if (da > hi) hi = da;
    }
    double step = WW_TAU / WATER_SEGMENTS;
    double from = floor((a0 + lo - margin) / step), to = floor((a0 + hi + margin) / step);
    int n = (int)(to - from) + 1;
    if (n >= WATER_SEGMENTS) return;
    int s = (int)fmod(from, (double)WATER_SEGMENTS);
    *first = s < 0 ? s + WATER_SEGMENTS : s;
    *count = n;
}

void ww_water_draw(const ww_water *w, const ww_gl *gl, const ww_frame *f) {
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;

    /* the mesh follows the camera in whole grid steps, so its vertices do not swim */
    double centre[2] = {WATER_SNAP * floor(f->cam_pos[0] / WATER_SNAP + 0.5),
                        WATER_SNAP * floor(f->cam_pos[2] / WATER_SNAP + 0.5)};
    float wave[WW_MAX_WAVES][4], phase[WW_MAX_WAVES];
    int n = pack_waves(sc, st, centre, wave, phase);

    /* fog colour: the scene's, or the sky at the horizon so the far water meets the sky */
    const double *fog = sc->fog_color[0] < 0.0 ? st->sky_horizon : sc->fog_color;

    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    gl->UseProgram(w->prog);
    ww_sky_locs_set(gl, &w->sky, st);
    gl->UniformMatrix4fv(w->view_proj, 1, GL_FALSE, (const GLfloat *)f->view_proj);
    gl->Uniform3f(w->origin, (float)(centre[0] - f->cam_pos[0]),
                  (float)(sc->water_level - f->cam_pos[1]), (float)(centre[1] - f->cam_pos[2]));
    gl->Uniform1i(w->nwaves, n);
    if (n > 0) {
        gl->Uniform4fv(w->wave, n, &wave[0][0]);
        gl->Uniform1fv(w->wave_phase, n, phase);
    }
    gl->Uniform3fv(w->ugrid, 1, w->grid);
    gl->Uniform3f(w->water_color, (float)sc->water_color[0], (float)sc->water_color[1],
                  (float)sc->water_color[2]);
    gl->Uniform3f(w->ambient, (float)st->ambient[0], (float)st->ambient[1], (float)st->ambient[2]);
    gl->Uniform3f(w->fog_color, (float)fog[0], (float)fog[1], (float)fog[2]);
    gl->Uniform1f(w->fog_density, (float)sc->fog_density);
    gl->Uniform1f(w->pixel_angle, f->pixel_angle);

    gl->BindVertexArray(w->vao);
    gl->DrawElements(GL_TRIANGLES, w->ninner, GL_UNSIGNED_INT, NULL);
    int first, count;
    visible_segments(w, f, sc, centre, &first, &count);
    draw_segments(w, gl, first, count < WATER_SEGMENTS - first ? count : WATER_SEGMENTS - first);
    if (first + count > WATER_SEGMENTS) draw_segments(w, gl, 0, first + count - WATER_SEGMENTS);
    gl->BindVertexArray(0);
}

void ww_water_free(ww_water *w, const ww_gl *gl) {
    if (!w) return;
    if (w->prog) gl->DeleteProgram(w->prog);
    if (w->vao) gl->DeleteVertexArrays(1, &w->vao);
    if (w->vbo) gl->DeleteBuffers(1, &w->vbo);
    if (w->ibo) gl->DeleteBuffers(1, &w->ibo);
    free(w);
}
