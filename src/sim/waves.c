/* waves.c - the wave field of every family (formulas in waves.h, profiles in scene.h): per-wave
 * phases, one rest point with its partials, velocity and normal in double, and a batch
 * evaluation over many points (double and float) that GCC vectorises across points.
 * Sines and cosines come from ww_sincos (core/sincos.h) everywhere, so the scalar and batch paths
 * give the same bits and no result depends on the C library's version.
 */
#include "sim/waves.h"

#include <math.h>

#include "core/mathx.h"
#include "core/sincos.h"

/* points per block of the batch evaluation: the inner loops always run this many iterations over
 * local arrays (a short last block is padded), so GCC's -O2 cost model vectorises them without
 * an epilogue or alias checks */
#define BATCH 64

/* components the model evaluates (flat water has none whatever the list holds) */
static int wave_count(const ww_scene *sc) {
    return sc->wave_model == WW_WAVES_FLAT ? 0 : sc->nwaves;
}

/* Gerstner Q as the model uses it: sines and steep sines move no water sideways */
static double wave_q(const ww_scene *sc, const ww_wave *w) {
    return (sc->wave_model == WW_WAVES_GERSTNER || sc->wave_model == WW_WAVES_SPECTRUM)
               ? w->steepness
               : 0.0;
}

static int steep(const ww_scene *sc) { return sc->wave_model == WW_WAVES_STEEP_SINES; }

/* p = e - 1 as the power of the steep-sine profile's derivative: a whole number up to 64 is
 * raised by squaring (exact order of operations, vectorisable); otherwise -1 and pow is used */
static int whole_power(double e) {
    double p = e - 1.0;
    return (p >= 0.0 && p <= 64.0 && p == floor(p)) ? (int)p : -1;
}

/* u^m by binary powers; the batch code does the same multiplications lane by lane */
static double ipow(double u, int m) {
    double r = 1.0, b = u;
    while (m) {
        if (m & 1) r *= b;
        m >>= 1;
        if (m) b *= b;
    }
    return r;
}

/* height h(phi) of one component and dh/dphi, from s = sin phi and c = cos phi.
 * Steep sines (seed 001): h = 2 A (u^e - mean), u = (sin phi + 1) / 2, so
 * dh/dphi = 2 A e u^(e-1) du/dphi = A e u^(e-1) cos phi. */
static void profile(const ww_scene *sc, const ww_wave *w, double s, double c, double *h,
                    double *dh) {
    if (!steep(sc)) {
        *h = w->amplitude * s;
        *dh = w->amplitude * c;
        return;
    }
    double u = 0.5 * (s + 1.0);
    int m = whole_power(w->exponent);
    double pe1 = m >= 0 ? ipow(u, m) : pow(u, w->exponent - 1.0);
    *h = 2.0 * w->amplitude * (pe1 * u - w->mean);
    *dh = w->amplitude * w->exponent * pe1 * c;
}

void ww_waves_phases(const ww_scene *sc, double t, double *phase) {
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        /* fmod of omega t alone keeps the wrap exact to ~1 ulp of 2 pi even at t = 1e6 s */
        phase[i] = ww_m_wrap_tau(w->phase - ww_m_wrap_tau(w->omega * t));
    }
}

void ww_waves_phases_at(const ww_scene *sc, const double *phase, double rx, double rz,
                        double *phase_at) {
    for (int i = 0; i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        /* each product wrapped on its own so a far reference keeps the phase's ulps small */
        double px = ww_m_wrap_tau(w->k * w->dir[0] * rx);
        double pz = ww_m_wrap_tau(w->k * w->dir[1] * rz);
        phase_at[i] = ww_m_wrap_tau(phase[i] + px + pz);
    }
}

void ww_waves_point(const ww_scene *sc, const double *phase, double x, double z,
                    double min_wavelength, ww_wave_point *out) {
    double X = x, Y = sc->water_level, Z = z;
    double xx = 1.0, xy = 0.0, xz = 0.0, zx = 0.0, zy = 0.0, zz = 1.0; /* dP/dx, dP/dz */
    double vx = 0.0, vy = 0.0, vz = 0.0;
    int nw = wave_count(sc);
    for (int i = 0; i < nw; i++) {
        const ww_wave *w = &sc->waves[i];
        if (w->wavelength < min_wavelength) continue;
        double dx = w->dir[0], dz = w->dir[1];
        double ph = w->k * (dx * x + dz * z) + phase[i];
        double s, c, h, dh;
        ww_sincos(ph, &s, &c);
        profile(sc, w, s, c, &h, &dh);
        double qa = wave_q(sc, w) * w->amplitude;
        X += qa * dx * c;
        Z += qa * dz * c;
        Y += h;
        /* chain rule with dphi/dx = k Dx, dphi/dz = k Dz (seed 001's partial derivatives) */
        double qka = w->k * qa;
        xx -= qka * dx * dx * s;
        xy += w->k * dx * dh;
        xz -= qka * dx * dz * s;
        zx -= qka * dx * dz * s;
        zy += w->k * dz * dh;
        zz -= qka * dz * dz * s;
        /* the particle at a fixed rest point: dphi/dt = -omega */
        vx += qa * w->omega * dx * s;
        vy -= w->omega * dh;
        vz += qa * w->omega * dz * s;
    }
    out->p[0] = X;
    out->p[1] = Y;
    out->p[2] = Z;
    out->dpdx[0] = xx;
    out->dpdx[1] = xy;
    out->dpdx[2] = xz;
    out->dpdz[0] = zx;
    out->dpdz[1] = zy;
    out->dpdz[2] = zz;
    out->vel[0] = vx;
    out->vel[1] = vy;
    out->vel[2] = vz;
    /* n = dP/dz x dP/dx, up for a flat sea */
    out->normal[0] = zy * xz - zz * xy;
    out->normal[1] = zz * xx - zx * xz;
    out->normal[2] = zx * xy - zy * xx;
    ww_m_normalize3(out->normal);
}

void ww_waves_eval(const ww_scene *sc, const double *phase, double x, double z, double out[3],
                   double normal[3]) {
    ww_wave_point p;
    ww_waves_point(sc, phase, x, z, 0.0, &p);
    for (int c = 0; c < 3; c++) {
        out[c] = p.p[c];
        if (normal) normal[c] = p.normal[c];
    }
}

double ww_waves_total_amplitude(const ww_scene *sc) {
    /* a steep-sine component ranges over 2 A (0 - mean) .. 2 A (1 - mean); sines over +-A */
    double sum = 0.0;
    int nw = wave_count(sc);
    for (int i = 0; i < nw; i++) {
        const ww_wave *w = &sc->waves[i];
        sum += steep(sc) ? 2.0 * w->amplitude * fmax(1.0 - w->mean, w->mean) : w->amplitude;
    }
    return sum;
}

/* ---- batch evaluation: components outer, the points of a block inner ---- */

/* the accumulators of one block of points */
typedef struct block {
    double x[BATCH], z[BATCH];                        /* rest points */
    double X[BATCH], Y[BATCH], Z[BATCH];              /* displaced points */
    double xx[BATCH], xy[BATCH], xz[BATCH];           /* dP/dx */
    double zx[BATCH], zy[BATCH], zz[BATCH];           /* dP/dz */
    double s[BATCH], c[BATCH], h[BATCH], dh[BATCH];   /* one component's values */
} block;

/* steep-sine heights and dh/dphi of one component from b->s, b->c into b->h, b->dh */
static void block_steep(block *b, const ww_wave *w) {
    double A = w->amplitude, e = w->exponent, mean = w->mean;
    double *u = b->h, *r = b->dh; /* reused as u and u^(e-1) until the last loop */
    for (int j = 0; j < BATCH; j++) u[j] = 0.5 * (b->s[j] + 1.0);
    int m = whole_power(e);
    if (m >= 0) {
        /* ipow's binary powers, each step one vectorised pass over the block */
        double base[BATCH];
        for (int j = 0; j < BATCH; j++) {
            r[j] = 1.0;
            base[j] = u[j];
        }
        while (m) {
            if (m & 1)
                for (int j = 0; j < BATCH; j++) r[j] *= base[j];
            m >>= 1;
            if (m)
                for (int j = 0; j < BATCH; j++) base[j] *= base[j];
        }
    } else {
        for (int j = 0; j < BATCH; j++) r[j] = pow(u[j], e - 1.0);
    }
    for (int j = 0; j < BATCH; j++) {
        double pe1 = r[j];
        b->h[j] = 2.0 * A * (pe1 * u[j] - mean);
        b->dh[j] = A * e * pe1 * b->c[j];
    }
}

static void block_eval(const ww_scene *sc, const double *phase, block *b, int normals) {
    for (int j = 0; j < BATCH; j++) {
        b->X[j] = b->x[j];
        b->Y[j] = sc->water_level;
        b->Z[j] = b->z[j];
        b->xx[j] = 1.0;
        b->xy[j] = b->xz[j] = b->zx[j] = b->zy[j] = 0.0;
        b->zz[j] = 1.0;
    }
    int nw = wave_count(sc), st = steep(sc);
    for (int i = 0; i < nw; i++) {
        const ww_wave *w = &sc->waves[i];
        double dx = w->dir[0], dz = w->dir[1], k = w->k, p0 = phase[i], A = w->amplitude;
        double qa = wave_q(sc, w) * A, qka = k * qa;
        double qdx = qa * dx, qdz = qa * dz, kdx = k * dx, kdz = k * dz;
        double qxx = qka * dx * dx, qxz = qka * dx * dz, qzz = qka * dz * dz;
        if (!st) {
            /* Gerstner and sines: h = A sin, dh = A cos, all in one pass (two loops, so that
             * neither holds a branch) */
            if (!normals) {
                for (int j = 0; j < BATCH; j++) {
                    double s, c;
                    ww_sincos(k * (dx * b->x[j] + dz * b->z[j]) + p0, &s, &c);
                    b->X[j] += qdx * c;
                    b->Z[j] += qdz * c;
                    b->Y[j] += A * s;
                }
                continue;
            }
            for (int j = 0; j < BATCH; j++) {
                double s, c;
                ww_sincos(k * (dx * b->x[j] + dz * b->z[j]) + p0, &s, &c);
                b->X[j] += qdx * c;
                b->Z[j] += qdz * c;
                b->Y[j] += A * s;
                double dh = A * c;
                b->xx[j] -= qxx * s;
                b->xy[j] += kdx * dh;
                b->xz[j] -= qxz * s;
                b->zx[j] -= qxz * s;
                b->zy[j] += kdz * dh;
                b->zz[j] -= qzz * s;
            }
            continue;
        }
        for (int j = 0; j < BATCH; j++)
            ww_sincos(k * (dx * b->x[j] + dz * b->z[j]) + p0, &b->s[j], &b->c[j]);
        block_steep(b, w);
        for (int j = 0; j < BATCH; j++) {
            b->Y[j] += b->h[j];
            b->xy[j] += kdx * b->dh[j];
            b->zy[j] += kdz * b->dh[j];
        }
    }
}

void ww_waves_eval_batch(const ww_scene *sc, const double *phase, int n, const double *x,
                         const double *z, double *X, double *Y, double *Z, double *nx,
                         double *ny, double *nz) {
    block b;
    for (int j0 = 0; j0 < n; j0 += BATCH) {
        int m = n - j0 < BATCH ? n - j0 : BATCH;
        for (int j = 0; j < BATCH; j++) {
            b.x[j] = j < m ? x[j0 + j] : 0.0;
            b.z[j] = j < m ? z[j0 + j] : 0.0;
        }
        block_eval(sc, phase, &b, nx != NULL);
        for (int j = 0; j < m; j++) {
            X[j0 + j] = b.X[j];
            Y[j0 + j] = b.Y[j];
            Z[j0 + j] = b.Z[j];
        }
        if (!nx) continue;
        for (int j = 0; j < m; j++) {
            /* n = dP/dz x dP/dx, normalised, as in ww_waves_point */
            double n3[3] = {b.zy[j] * b.xz[j] - b.zz[j] * b.xy[j],
                            b.zz[j] * b.xx[j] - b.zx[j] * b.xz[j],
                            b.zx[j] * b.xy[j] - b.zy[j] * b.xx[j]};
            ww_m_normalize3(n3);
            nx[j0 + j] = n3[0];
            ny[j0 + j] = n3[1];
            nz[j0 + j] = n3[2];
        }
    }
}

/* ---- the same in float, as the shader computes it: phi = phase + (k D) . x ---- */

typedef struct blockf {
    float x[BATCH], z[BATCH];
    float X[BATCH], Y[BATCH], Z[BATCH];
    float xx[BATCH], xy[BATCH], xz[BATCH];
    float zx[BATCH], zy[BATCH], zz[BATCH];
    float s[BATCH], c[BATCH], u[BATCH], r[BATCH];
} blockf;

static void blockf_steep(blockf *b, const ww_wave *w, float *h, float *dh) {
    float A = (float)w->amplitude, e = (float)w->exponent, mean = (float)w->mean;
    for (int j = 0; j < BATCH; j++) b->u[j] = 0.5f * (b->s[j] + 1.0f);
    int m = whole_power(w->exponent);
    if (m >= 0) {
        float base[BATCH];
        for (int j = 0; j < BATCH; j++) {
            b->r[j] = 1.0f;
            base[j] = b->u[j];
        }
        while (m) {
            if (m & 1)
                for (int j = 0; j < BATCH; j++) b->r[j] *= base[j];
            m >>= 1;
            if (m)
                for (int j = 0; j < BATCH; j++) base[j] *= base[j];
        }
    } else {
        for (int j = 0; j < BATCH; j++) b->r[j] = powf(b->u[j], e - 1.0f);
    }
    for (int j = 0; j < BATCH; j++) {
        h[j] = 2.0f * A * (b->r[j] * b->u[j] - mean);
        dh[j] = A * e * b->r[j] * b->c[j];
    }
}

static void blockf_eval(const ww_scene *sc, const double *phase, blockf *b, int normals) {
    for (int j = 0; j < BATCH; j++) {
        b->X[j] = b->x[j];
        b->Y[j] = (float)sc->water_level;
        b->Z[j] = b->z[j];
        b->xx[j] = 1.0f;
        b->xy[j] = b->xz[j] = b->zx[j] = b->zy[j] = 0.0f;
        b->zz[j] = 1.0f;
    }
    int nw = wave_count(sc), st = steep(sc);
    for (int i = 0; i < nw; i++) {
        const ww_wave *w = &sc->waves[i];
        /* the shader's uniforms: (k Dx, k Dz, A, Q) and the wrapped phase, each rounded to float */
        float kx = (float)(w->k * w->dir[0]), kz = (float)(w->k * w->dir[1]);
        float p0 = (float)phase[i], A = (float)w->amplitude, q = (float)wave_q(sc, w);
        float dx = (float)w->dir[0], dz = (float)w->dir[1];
        float qdx = q * A * dx, qdz = q * A * dz;
        float qxx = q * A * kx * dx, qxz = q * A * kx * dz, qzz = q * A * kz * dz;
        if (!st) {
            if (!normals) {
                for (int j = 0; j < BATCH; j++) {
                    float s, c;
                    ww_sincosf(p0 + (kx * b->x[j] + kz * b->z[j]), &s, &c);
                    b->X[j] += qdx * c;
                    b->Z[j] += qdz * c;
                    b->Y[j] += A * s;
                }
                continue;
            }
            for (int j = 0; j < BATCH; j++) {
                float s, c;
                ww_sincosf(p0 + (kx * b->x[j] + kz * b->z[j]), &s, &c);
                b->X[j] += qdx * c;
                b->Z[j] += qdz * c;
                b->Y[j] += A * s;
                float dh = A * c;
                b->xx[j] -= qxx * s;
                b->xy[j] += kx * dh;
                b->xz[j] -= qxz * s;
                b->zx[j] -= qxz * s;
                b->zy[j] += kz * dh;
                b->zz[j] -= qzz * s;
            }
            continue;
        }
        float h[BATCH], dh[BATCH];
        for (int j = 0; j < BATCH; j++)
            ww_sincosf(p0 + (kx * b->x[j] + kz * b->z[j]), &b->s[j], &b->c[j]);
        blockf_steep(b, w, h, dh);
        for (int j = 0; j < BATCH; j++) {
            b->Y[j] += h[j];
            b->xy[j] += kx * dh[j];
            b->zy[j] += kz * dh[j];
        }
    }
}

void ww_waves_eval_batch_f(const ww_scene *sc, const double *phase, int n, const float *x,
                           const float *z, float *X, float *Y, float *Z, float *nx, float *ny,
                           float *nz) {
    blockf b;
    for (int j0 = 0; j0 < n; j0 += BATCH) {
        int m = n - j0 < BATCH ? n - j0 : BATCH;
        for (int j = 0; j < BATCH; j++) {
            b.x[j] = j < m ? x[j0 + j] : 0.0f;
            b.z[j] = j < m ? z[j0 + j] : 0.0f;
        }
        blockf_eval(sc, phase, &b, nx != NULL);
        for (int j = 0; j < m; j++) {
            X[j0 + j] = b.X[j];
            Y[j0 + j] = b.Y[j];
            Z[j0 + j] = b.Z[j];
        }
        if (!nx) continue;
        for (int j = 0; j < m; j++) {
            float n0 = b.zy[j] * b.xz[j] - b.zz[j] * b.xy[j];
            float n1 = b.zz[j] * b.xx[j] - b.zx[j] * b.xz[j];
            float n2 = b.zx[j] * b.xy[j] - b.zy[j] * b.xx[j];
            float l = sqrtf(n0 * n0 + n1 * n1 + n2 * n2);
            float inv = l > 0.0f ? 1.0f / l : 0.0f;
            nx[j0 + j] = n0 * inv;
            ny[j0 + j] = n1 * inv;
            nz[j0 + j] = n2 * inv;
        }
    }
}
