/* waveblock.c - the wave field packed for the shaders (render_impl.h: ww_water_waves and the
 * uniform blocks of shaders/gerstner.glsl), shared by everything that draws or probes the
 * surface: the water, the geometry that floats or lies under it, the GPU probe. Phases and ripple
 * ages are taken at a centre in double, so the shaders stay exact in float at t = 1e6 s and 1e5 m
 * from the origin.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"
#include "sim/ripples.h"

/* mean over a period of (e u^(e - 1) cos(phi))^2, u = (sin(phi) + 1) / 2: the mean square slope
 * of a steep sine 2 A (u^e - mean) per unit (A k)^2 (1/2 for a sine, e = 1). The rectangle rule
 * over a whole period converges spectrally for a smooth periodic integrand (exact for integer e,
 * a trigonometric polynomial of degree 2e - 1 < 256). */
static double steep_slope_factor(double e) {
    const int n = 256;
    double sum = 0.0;
    for (int j = 0; j < n; j++) {
        double phi = WW_TAU * j / n, u = 0.5 * (sin(phi) + 1.0);
        double d = e * (e > 1.0 ? pow(u, e - 1.0) : 1.0) * cos(phi);
        sum += d * d;
    }
    return sum / n;
}

int ww_water_wave_count(const ww_scene *sc) {
    if (sc->wave_model == WW_WAVES_FLAT) return 0;
    int n = 0;
    for (int i = 0; i < sc->nwaves && i < WW_MAX_WAVES; i++) n += sc->waves[i].k > 0.0;
    return n;
}

void ww_water_waves_init(const ww_scene *sc, ww_water_waves *w) {
    memset(w, 0, sizeof *w);
    ww_wave_block *b = &w->block;
    if (sc->wave_model == WW_WAVES_FLAT) return;
    int n = 0;
    for (int i = 0; i < sc->nwaves && i < WW_MAX_WAVES; i++)
        if (sc->waves[i].k > 0.0) w->order[n++] = i; /* no wave to draw, no direction to divide by */
    /* insertion sort by wavenumber ascending, stable so equal k keep the scene's order */
    for (int i = 1; i < n; i++) {
        int j = i, v = w->order[i];
        for (; j > 0 && sc->waves[w->order[j - 1]].k > sc->waves[v].k; j--) w->order[j] = w->order[j - 1];
        w->order[j] = v;
    }
    int gerstner = sc->wave_model == WW_WAVES_GERSTNER || sc->wave_model == WW_WAVES_SPECTRUM;
    int steep = sc->wave_model == WW_WAVES_STEEP_SINES;
    double total = 0.0;
    for (int i = 0; i < n; i++) {
        const ww_wave *wv = &sc->waves[w->order[i]];
        double q = gerstner ? wv->steepness : 0.0; /* sines move no water sideways */
        double c = steep ? steep_slope_factor(wv->exponent) : 0.5;
        b->wave[i][0] = (float)(wv->k * wv->dir[0]);
        b->wave[i][1] = (float)(wv->k * wv->dir[1]);
        b->wave[i][2] = (float)wv->amplitude;
        b->wave[i][3] = (float)q;
        b->wave2[i][1] = (float)wv->exponent;
        b->wave2[i][2] = (float)wv->mean;
        b->wave2[i][3] = (float)c;
        total += c * (wv->amplitude * wv->k) * (wv->amplitude * wv->k);
        w->sideways += q * wv->amplitude;
    }
    b->n = n;
    b->slope2_total = (float)total;
}

void ww_water_waves_phases(const ww_scene *sc, const ww_state *st, const double centre[2],
                           ww_water_waves *w) {
    for (int i = 0; i < w->block.n; i++) {
        int s = w->order[i];
        const ww_wave *wv = &sc->waves[s];
        double kx = wv->k * wv->dir[0], kz = wv->k * wv->dir[1];
        w->block.wave2[i][0] = (float)ww_m_wrap_tau(kx * centre[0] + kz * centre[1] + st->wave_phase[s]);
    }
}

/* a circle that holds every live ripple's front: a ripple is exactly 0 beyond v age + lambda
 * from its centre (ripples.c's causal front), so the shaders evaluate none outside it. The
 * circle about the middle of the fronts' bounding box, widened by a part in a thousand and a
 * millimetre against the float rounding of the distance the shaders compare */
static void ripple_bound(ww_ripple_block *b, double speed) {
    double lo[2] = {1e30, 1e30}, hi[2] = {-1e30, -1e30}, radius = 0.0;
    for (int i = 0; i < b->n; i++) {
        double front = speed * b->ripple[i][2] + b->shape[0];
        for (int k = 0; k < 2; k++) {
            lo[k] = fmin(lo[k], b->ripple[i][k] - front);
            hi[k] = fmax(hi[k], b->ripple[i][k] + front);
        }
    }
    double c[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    for (int i = 0; i < b->n; i++) {
        double front = speed * b->ripple[i][2] + b->shape[0];
        radius = fmax(radius, hypot(b->ripple[i][0] - c[0], b->ripple[i][1] - c[1]) + front);
    }
    b->bound[0] = b->n ? (float)c[0] : 0.0f;
    b->bound[1] = b->n ? (float)c[1] : 0.0f;
    b->bound[2] = b->n ? (float)(radius * 1.001 + 1e-3) : -1.0f;
    b->bound[3] = 0.0f;
}

int ww_water_pack_ripples(const ww_scene *sc, const ww_state *st, const double centre[2],
                          ww_ripple_block *b) {
    const ww_ripple_desc *d = &sc->ripples;
    int n = 0;
    b->param[0] = (float)d->radial_decay;
    b->param[1] = (float)d->time_decay;
    b->param[2] = (float)d->wavenumber;
    b->param[3] = (float)d->speed;
    b->shape[0] = d->wavenumber > 0.0 ? (float)(WW_TAU / d->wavenumber) : 0.0f;
    b->shape[1] = d->wavenumber > 0.0 ? (float)(1.0 / d->wavenumber) : 0.0f;
    if (sc->ripples_on && st->ripple && d->wavenumber > 0.0) {
        for (int i = 0; i < d->max && i < WW_MAX_RIPPLES; i++) {
            const double *e = st->ripple + i * WW_RIPPLE_STRIDE;
            double age = st->t - e[2];
            if (e[3] == 0.0 || age < 0.0) continue; /* free, or not yet started (as ripples.c) */
            b->ripple[n][0] = (float)(e[0] - centre[0]);
            b->ripple[n][1] = (float)(e[1] - centre[1]);
            b->ripple[n][2] = (float)age;
            b->ripple[n][3] = (float)e[3];
            n++;
        }
    }
    b->n = n;
    ripple_bound(b, d->speed);
    return n;
}

int ww_water_shader_model(ww_wave_model m) {
    switch (m) {
    case WW_WAVES_FLAT: return 0;
    case WW_WAVES_GERSTNER:
    case WW_WAVES_SPECTRUM: return 1;
    case WW_WAVES_SINES: return 2;
    case WW_WAVES_STEEP_SINES: return 3;
    }
    return 0;
}

/* bind block `name` of prog to `binding`, checking that the driver lays it out as our struct */
static ww_result bind_block(const ww_gl *gl, GLuint prog, const char *name, GLuint binding,
                            size_t bytes, ww_error *err) {
    GLuint idx = gl->GetUniformBlockIndex(prog, name);
    if (idx == GL_INVALID_INDEX) return WW_OK; /* the program does not read it */
    GLint size = 0, max = 0;
    gl->GetActiveUniformBlockiv(prog, idx, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    gl->GetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &max);
    if ((size_t)size != bytes)
        return ww_error_set(err, WW_E_GL, "gerstner.glsl", 0, 0,
                            "uniform block %s is %d bytes here, %zu in render_impl.h (std140)",
                            name, size, bytes);
    if ((size_t)max < bytes)
        return ww_error_set(err, WW_E_GL, "gerstner.glsl", 0, 0,
                            "uniform block %s needs %zu bytes; GL_MAX_UNIFORM_BLOCK_SIZE is %d",
                            name, bytes, max);
    gl->UniformBlockBinding(prog, idx, binding);
    return WW_OK;
}

ww_result ww_water_program(const ww_gl *gl, const ww_scene *sc, const char *vs, const char *fs,
                           int fade, const char *more, GLuint *prog, ww_error *err) {
    static const char *const includes[] = {"common.glsl", "gerstner.glsl", NULL};
    char defines[1024];
    snprintf(defines, sizeof defines,
             "#define WW_WAVE_MODEL %d\n#define WW_NWAVES %d\n#define WW_RIPPLES %d\n"
             "#define WW_FADE %d\n%s",
             ww_water_shader_model(sc->wave_model), ww_water_wave_count(sc),
             sc->ripples_on ? 1 : 0, fade ? 1 : 0, more ? more : "");
    ww_result rc = ww_gfx_program_defs(gl, vs, fs, includes, defines, prog, err);
    if (rc == WW_OK)
        rc = bind_block(gl, *prog, "WwWaves", WW_UBO_WAVES, sizeof(ww_wave_block), err);
    if (rc == WW_OK && sc->ripples_on)
        rc = bind_block(gl, *prog, "WwRipples", WW_UBO_RIPPLES, sizeof(ww_ripple_block), err);
    if (rc != WW_OK && *prog) {
        gl->DeleteProgram(*prog);
        *prog = 0;
    }
    return rc;
}

ww_result ww_water_ubos_new(const ww_gl *gl, const ww_scene *sc, const ww_water_waves *w,
                            ww_water_ubos *u, ww_error *err) {
    *u = (ww_water_ubos){0};
    gl->GenBuffers(1, &u->waves);
    gl->BindBuffer(GL_UNIFORM_BUFFER, u->waves);
    gl->BufferData(GL_UNIFORM_BUFFER, sizeof w->block, &w->block, GL_DYNAMIC_DRAW);
    if (sc->ripples_on) {
        ww_ripple_block zero = {0};
        gl->GenBuffers(1, &u->ripples);
        gl->BindBuffer(GL_UNIFORM_BUFFER, u->ripples);
        gl->BufferData(GL_UNIFORM_BUFFER, sizeof zero, &zero, GL_DYNAMIC_DRAW);
    }
    gl->BindBuffer(GL_UNIFORM_BUFFER, 0);
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR) {
        ww_water_ubos_free(gl, u);
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "water: uniform buffers raised GL error 0x%04x",
                            (unsigned)e);
    }
    return WW_OK;
}

void ww_water_ubos_upload(const ww_gl *gl, const ww_water_ubos *u, const ww_water_waves *w,
                          const ww_ripple_block *rb, int full) {
    const ww_wave_block *b = &w->block;
    gl->BindBuffer(GL_UNIFORM_BUFFER, u->waves);
    if (full) {
        gl->BufferSubData(GL_UNIFORM_BUFFER, 0, sizeof *b, b);
    } else if (b->n > 0) {
        /* only the phases change from frame to frame */
        GLintptr at = (GLintptr)offsetof(ww_wave_block, wave2);
        gl->BufferSubData(GL_UNIFORM_BUFFER, at, (GLsizeiptr)((size_t)b->n * sizeof b->wave2[0]), b->wave2);
    }
    if (rb && u->ripples) {
        /* the header and the live entries */
        gl->BindBuffer(GL_UNIFORM_BUFFER, u->ripples);
        size_t bytes = offsetof(ww_ripple_block, ripple) + (size_t)rb->n * sizeof rb->ripple[0];
        gl->BufferSubData(GL_UNIFORM_BUFFER, 0, (GLsizeiptr)bytes, rb);
    }
    gl->BindBuffer(GL_UNIFORM_BUFFER, 0);
}

void ww_water_ubos_bind(const ww_gl *gl, const ww_water_ubos *u) {
    gl->BindBufferBase(GL_UNIFORM_BUFFER, WW_UBO_WAVES, u->waves);
    if (u->ripples) gl->BindBufferBase(GL_UNIFORM_BUFFER, WW_UBO_RIPPLES, u->ripples);
}

void ww_water_ubos_free(const ww_gl *gl, ww_water_ubos *u) {
    if (u->waves) gl->DeleteBuffers(1, &u->waves);
    if (u->ripples) gl->DeleteBuffers(1, &u->ripples);
    *u = (ww_water_ubos){0};
}

/* the normal-only detail of the surface: short deep-water sines (wavelength m, direction deg,
 * slope amplitude A k) that only the shading sees (the water's normals so the near water is not
 * smooth plastic, the caustics their focus), never the physics; each travels at the
 * deep-water speed. Longest first: the shaders stop at the first one faded out. */
static const double detail_wave[WW_WATER_NDETAIL][3] = {
    {1.31, 23.0, 0.03},  {0.87, 131.0, 0.03},  {0.61, -52.0, 0.025},
    {0.43, 77.0, 0.025}, {0.29, 188.0, 0.02},  {0.19, -11.0, 0.02}};

void ww_water_detail(const ww_state *st, const double centre[2], float d[WW_WATER_NDETAIL][4]) {
    for (int j = 0; j < WW_WATER_NDETAIL; j++) {
        double k = WW_TAU / detail_wave[j][0], a = detail_wave[j][1] * (WW_PI / 180.0);
        double kx = k * cos(a), kz = k * sin(a), omega = sqrt(9.81 * k);
        d[j][0] = (float)kx;
        d[j][1] = (float)kz;
        d[j][2] = (float)detail_wave[j][2];
        /* as the wave phases: the wrap of omega t alone keeps it exact at large t */
        d[j][3] = (float)ww_m_wrap_tau(kx * centre[0] + kz * centre[1] - ww_m_wrap_tau(omega * st->t));
    }
}

/* the detail's fixed part as a GLSL constant (water.frag.glsl: WW_DETAIL_WAVES): per sine its
 * unit direction, wavelength m and slope amplitude, so the shader's loop folds them in */
void ww_water_detail_define(char *buf, size_t n) {
    size_t at = (size_t)snprintf(buf, n, "#define WW_DETAIL_WAVES vec4[%d](", WW_WATER_NDETAIL);
    for (int j = 0; j < WW_WATER_NDETAIL && at < n; j++) {
        double a = detail_wave[j][1] * (WW_PI / 180.0);
        at += (size_t)snprintf(buf + at, n - at, "%svec4(%.9g, %.9g, %.9g, %.9g)", j ? ", " : "",
                               cos(a), sin(a), detail_wave[j][0], detail_wave[j][2]);
    }
    if (at < n) snprintf(buf + at, n - at, ")\n");
}

/* the DuDv pattern's two layers (water.frag.glsl): layer j maps a rest offset p (m) to lattice
 * cells M_j p + o_j, with M_j = cells per metre x a rotation and o_j = M_j (centre + drift_j t)
 * wrapped to the lattice period in double, so the pattern is fixed to the world, drifts, and
 * stays exact in float far from the origin and at large t (seed 002 scrolls its DuDv map the
 * same way, in two directions) */
#define DUDV_PERIOD 256.0           /* lattice cells before the noise repeats (NOISE_MASK + 1) */
static const double dudv_scale[2] = {1.0, 1.93};  /* cells per metre over distortion_scale */
static const double dudv_angle[2] = {0.0, 2.14};  /* rotation of each layer, rad */
static const double dudv_drift[2][2] = {{0.8, 0.6}, {-0.45, 0.89}}; /* unit drift directions */

void ww_water_dudv(const ww_scene *sc, const ww_state *st, const double centre[2],
                   float m[2][4], float o[2][2]) {
    const ww_water_look *lk = &sc->render.water;
    for (int j = 0; j < 2; j++) {
        double s = lk->distortion_scale * dudv_scale[j], c = cos(dudv_angle[j]), n = sin(dudv_angle[j]);
        double r[2][2] = {{s * c, -s * n}, {s * n, s * c}}; /* row-major */
        double x = centre[0] + dudv_drift[j][0] * lk->distortion_speed * st->t;
        double z = centre[1] + dudv_drift[j][1] * lk->distortion_speed * st->t;
        for (int k = 0; k < 2; k++) {
            double v = r[k][0] * x + r[k][1] * z;
            o[j][k] = (float)(v - DUDV_PERIOD * floor(v / DUDV_PERIOD));
        }
        /* GLSL mat2 is column-major: (m00, m10, m01, m11) */
        m[j][0] = (float)r[0][0];
        m[j][1] = (float)r[1][0];
        m[j][2] = (float)r[0][1];
        m[j][3] = (float)r[1][1];
    }
}
