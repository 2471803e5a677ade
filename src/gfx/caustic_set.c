/* caustic_set.c - water.look.caustics.method texture: seed 003's looped set of caustic textures
 * (Kilgard's OpenGL caustics sample, after Stam's periodic caustic maps), computed once on the
 * CPU from the scene's own wave field instead of read from files: frame j is the sunlight the
 * surface at time j T / N focuses onto a plane at the seabed's depth, over a periodic patch.
 *
 * Periodic in space and time: every sine of the field (the scene's waves, the water's detail
 * sines, both taken as sines of their amplitude as the analytic caustics take them) has its
 * wavevector snapped to the patch's lattice, 2 pi / P (m, n), and its frequency to the loop's,
 * 2 pi / T round(omega T / 2 pi); a sine whose snapped wavevector is 0 drops out. The water's
 * DuDv ripples become value noise with a whole number of cells per patch on axis-aligned
 * lattices (the water's are rotated), frozen in time (the water's drift a few cm/s; frozen, the
 * set loops). So the set shows the scene's field to within a few percent of each wavelength
 * and frequency, not its exact phases: good for the look of a caustic, not for a picture that
 * matches the analytic method pixel for pixel.
 *
 * The light: rays from a grid of surface points q refracted to first order in the slope land at
 * x = q - d kappa grad h(q), kappa = 1 - 1 / eta (as geometry.frag.glsl's ww_caustic), and are
 * splatted bilinearly into the frame: the irradiance is the density of landing points, the
 * Jacobian area ratio the analytic method evaluates per pixel, here summed over every ray that
 * lands (so crossing caustics add) and bounded by the ray count instead of a clamp. The mean
 * is exactly 1. Components shorter than the blur of the sun's disc over the depth fade out as
 * in the analytic method.
 */
#include "gfx/caustic_set.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"
#include "sim/state.h"
#include "sim/waves.h"

#define RAYS 2                 /* rays per texel along each axis */
#define ETA_WATER 1.333
#define SUN_RADIUS 0.00925     /* rad: common.glsl's WW_SUN_RADIUS */
#define DETAIL_SLOPE 0.06      /* water.frag.glsl's DETAIL_SLOPE: the DuDv ripples' slope */
#define MAX_COMP (WW_MAX_WAVES + WW_WATER_NDETAIL)
#define DEPTH_MIN 0.5          /* m: the shallowest plane the set is focused at ... */
#define DEPTH_MAX 20.0         /* ... and the deepest: below, the sun's blur leaves little */

static const double layer_weight[2] = {0.6, 0.4}; /* water.frag.glsl: LAYER_WEIGHT0, 1 */

/* one snapped sine h = a sin(kx x + kz z - omega t + phase) */
typedef struct comp {
    double kx, kz, a, omega, phase;
} comp;

/* a DuDv layer on the patch: c cells per side, height weight per unit of noise */
typedef struct layer {
    int c;
    double h;
} layer;

/* water.frag.glsl's ww_hash (PCG output permutation) of lattice point (i, j) */
static double lattice_hash(int i, int j) {
    uint32_t h = (uint32_t)i + (uint32_t)j * 256u;
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return (double)h * (1.0 / 4294967295.0);
}

/* the gradient (in cells) of value noise in [-1, 1] on a lattice of c x c cells that wraps,
 * septic fade (as geometry.frag.glsl's caustics) */
static void noise_grad(const layer *l, double x, double y, double g[2]) {
    double fi = floor(x), fj = floor(y), fx = x - fi, fy = y - fj;
    int i = ((int)fi % l->c + l->c) % l->c, j = ((int)fj % l->c + l->c) % l->c;
    int i1 = (i + 1) % l->c, j1 = (j + 1) % l->c;
    double gx = 1.0 - fx, gy = 1.0 - fy;
    double ux = fx * fx * fx * fx * (35.0 - fx * (84.0 - fx * (70.0 - 20.0 * fx)));
    double uy = fy * fy * fy * fy * (35.0 - fy * (84.0 - fy * (70.0 - 20.0 * fy)));
    double dx = 140.0 * fx * fx * fx * gx * gx * gx, dy = 140.0 * fy * fy * fy * gy * gy * gy;
    double a = lattice_hash(i, j), b = lattice_hash(i1, j), d = lattice_hash(i, j1);
    double e = lattice_hash(i1, j1), k = a - b - d + e;
    g[0] = 2.0 * dx * (b - a + k * uy);
    g[1] = 2.0 * dy * (d - a + k * ux);
}

/* add a sine of wavevector (kx, kz), height amplitude a, frequency omega, phase at t = 0,
 * snapped to the patch and the loop and faded by the blur; returns the count */
static int add_comp(comp *c, int n, double kx, double kz, double a, double omega, double phase,
                    double patch, double period, double blur) {
    double base = WW_TAU / patch, m = round(kx / base), q = round(kz / base);
    if ((m == 0.0 && q == 0.0) || n >= MAX_COMP) return n;
    kx = m * base;
    kz = q * base;
    double len = WW_TAU / hypot(kx, kz);
    double f = ww_m_smoothstep(2.0 * blur, 6.0 * blur, len);
    if (f == 0.0) return n;
    double wt = WW_TAU / period;
    c[n] = (comp){kx, kz, f * a, round(omega / wt) * wt, phase};
    return n + 1;
}

/* the snapped components of the scene's field and the water's detail */
static int gather(const ww_scene *sc, double patch, double period, double blur, comp *c) {
    int n = 0;
    for (int i = 0; i < sc->nwaves && i < WW_MAX_WAVES; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->k <= 0.0) continue;
        n = add_comp(c, n, w->k * w->dir[0], w->k * w->dir[1], w->amplitude, w->omega, w->phase,
                     patch, period, blur);
    }
    ww_state st0;
    memset(&st0, 0, sizeof st0); /* t = 0: the detail's phases at the origin */
    const double origin[2] = {0.0, 0.0};
    float d[WW_WATER_NDETAIL][4];
    ww_water_detail(&st0, origin, d);
    for (int j = 0; j < WW_WATER_NDETAIL; j++) {
        double kx = d[j][0], kz = d[j][1], k = hypot(kx, kz);
        n = add_comp(c, n, kx, kz, d[j][2] / k, sqrt(9.81 * k), d[j][3], patch, period, blur);
    }
    return n;
}

/* the DuDv layers with a whole number of cells per patch, faded by the blur as the sines */
static void gather_layers(const ww_scene *sc, double patch, double blur, layer l[2]) {
    ww_state st0;
    memset(&st0, 0, sizeof st0);
    const double origin[2] = {0.0, 0.0};
    float m[2][4], o[2][2];
    ww_water_dudv(sc, &st0, origin, m, o);
    double scale = sc->render.water.distortion_scale;
    for (int j = 0; j < 2; j++) {
        double per_m = hypot(m[j][0], m[j][1]); /* cells per metre */
        int c = (int)fmax(1.0, round(per_m * patch));
        double f = ww_m_smoothstep(2.0 * blur, 6.0 * blur, patch / c);
        l[j].c = c;
        l[j].h = scale > 0.0 ? f * layer_weight[j] * DETAIL_SLOPE / scale : 0.0;
    }
}

/* the frozen DuDv ripples' slope at every ray's surface point, (x, z) pairs, row after row */
static void ripple_slopes(const layer l[2], double patch, int rays, double *slope) {
    double step = patch / rays;
    for (int rj = 0; rj < rays; rj++)
        for (int ri = 0; ri < rays; ri++) {
            double x = (ri + 0.5) * step, z = (rj + 0.5) * step, gx = 0.0, gz = 0.0;
            for (int j = 0; j < 2; j++) {
                if (l[j].h == 0.0) continue;
                double per = l[j].c / patch, g[2];
                noise_grad(&l[j], x * per, z * per, g);
                gx += l[j].h * per * g[0];
                gz += l[j].h * per * g[1];
            }
            slope[2 * ((size_t)rj * rays + ri)] = gx;
            slope[2 * ((size_t)rj * rays + ri) + 1] = gz;
        }
}

/* one frame at time t: every ray's landing point splatted into out (size x size). A sine's
 * phase on the grid separates, kx x + (kz z - omega t + phase): its cosine is
 * cos a cos b - sin a sin b from a row's and a column's table (cs: 4 x rays per sine) */
static void frame(const comp *c, int n, const double *slope, double patch, double dk, double t,
                  int size, double *cs, float *out) {
    int rays = size * RAYS;
    double step = patch / rays, texel = patch / size, w = 1.0 / (RAYS * RAYS);
    for (int i = 0; i < n; i++) {
        double *tab = cs + (size_t)4 * rays * i;
        for (int r = 0; r < rays; r++) {
            double p = (r + 0.5) * step, a = c[i].kx * p, b = c[i].kz * p - c[i].omega * t + c[i].phase;
            tab[r] = cos(a);
            tab[rays + r] = sin(a);
            tab[2 * rays + r] = cos(b);
            tab[3 * rays + r] = sin(b);
        }
    }
    memset(out, 0, (size_t)size * (size_t)size * sizeof *out);
    for (int rj = 0; rj < rays; rj++) {
        for (int ri = 0; ri < rays; ri++) {
            const double *sl = slope + 2 * ((size_t)rj * rays + ri);
            double x = (ri + 0.5) * step, z = (rj + 0.5) * step, gx = sl[0], gz = sl[1];
            for (int i = 0; i < n; i++) {
                const double *tab = cs + (size_t)4 * rays * i;
                double co = tab[ri] * tab[2 * rays + rj] - tab[rays + ri] * tab[3 * rays + rj];
                double s = c[i].a * co;
                gx += s * c[i].kx;
                gz += s * c[i].kz;
            }
            /* the landing point in texels, splatted bilinearly with wrap-around */
            double u = (x - dk * gx) / texel - 0.5, v = (z - dk * gz) / texel - 0.5;
            double fu = floor(u), fv = floor(v), au = u - fu, av = v - fv;
            int i0 = ((int)fu % size + size) % size, j0 = ((int)fv % size + size) % size;
            int i1 = (i0 + 1) % size, j1 = (j0 + 1) % size;
            out[j0 * size + i0] += (float)(w * (1.0 - au) * (1.0 - av));
            out[j0 * size + i1] += (float)(w * au * (1.0 - av));
            out[j1 * size + i0] += (float)(w * (1.0 - au) * av);
            out[j1 * size + i1] += (float)(w * au * av);
        }
    }
}

ww_result ww_caustic_set_make(const ww_scene *sc, ww_caustic_set *cs, ww_error *err) {
    memset(cs, 0, sizeof *cs);
    cs->size = WW_CAUSTIC_SET_SIZE;
    cs->frames = WW_CAUSTIC_SET_FRAMES;
    cs->patch = WW_CAUSTIC_SET_PATCH;
    cs->period = WW_CAUSTIC_SET_PERIOD;
    /* focused at the seabed, where most of it is seen (deeper still, it keeps this pattern) */
    cs->depth = ww_m_clamp(sc->water_depth, DEPTH_MIN, DEPTH_MAX);
    size_t per = (size_t)cs->size * (size_t)cs->size;
    cs->texel = malloc(per * (size_t)cs->frames * sizeof *cs->texel);
    if (!cs->texel) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "caustics: out of memory");
    /* the blur of the sun's disc over the depth, as the analytic method's, and at least a texel */
    double blur = fmax(cs->depth * 2.0 * SUN_RADIUS + 0.05, 0.5 * cs->patch / cs->size);
    comp c[MAX_COMP];
    layer l[2];
    cs->ncomp = sc->wave_model == WW_WAVES_FLAT ? 0 : gather(sc, cs->patch, cs->period, blur, c);
    gather_layers(sc, cs->patch, blur, l);
    if (sc->wave_model == WW_WAVES_FLAT) l[0].h = l[1].h = 0.0;
    double dk = cs->depth * (1.0 - 1.0 / ETA_WATER);
    size_t rays = (size_t)cs->size * RAYS;
    double *slope = malloc(2 * rays * rays * sizeof *slope);
    double *tab = malloc(4 * rays * (size_t)(cs->ncomp > 0 ? cs->ncomp : 1) * sizeof *tab);
    if (!slope || !tab) {
        free(slope);
        free(tab);
        ww_caustic_set_free(cs);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "caustics: out of memory");
    }
    ripple_slopes(l, cs->patch, (int)rays, slope);
    for (int f = 0; f < cs->frames; f++)
        frame(c, cs->ncomp, slope, cs->patch, dk, cs->period * f / cs->frames, cs->size, tab,
              cs->texel + per * (size_t)f);
    free(slope);
    free(tab);
    return WW_OK;
}

void ww_caustic_set_frame(const ww_caustic_set *cs, double t, int *i0, int *i1, double *w) {
    double u = t / cs->period;
    u = (u - floor(u)) * cs->frames;
    double f = floor(u);
    *i0 = (int)f % cs->frames;
    *i1 = (*i0 + 1) % cs->frames;
    *w = u - f;
}

void ww_caustic_set_free(ww_caustic_set *cs) {
    free(cs->texel);
    memset(cs, 0, sizeof *cs);
}
