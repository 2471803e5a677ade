/* stones.c - thrown stones (seed 000 section 3.3): flight under gravity and optional
 * quadratic drag, a swept test of each step's path against the exact surface so no crossing is
 * missed at any speed, a skip-or-sink criterion from the physics of Clanet, Hersen & Bocquet
 * (2004), and thuds against cubes and the boat. The model and its formulas are in stones.h.
 *
 * Changed from seed 000: the seed moves the stone by explicit Euler and tests only the end of a
 * step against the surface, so a fast stone tunnels through a wave crest and the skip happens a
 * part of a step late; here flight is the exact parabola and the crossing time is solved for.
 * The seed's skip rule (speed and angle thresholds tuned by hand) becomes V > V_min(beta) with
 * the paper's two measured features (least speed near 20 deg, none above 45 deg) built in, and
 * its axis-aligned cube test becomes a swept test against the cube's oriented box.
 */
#include "sim/stones.h"

#include <math.h>

#include "core/mathx.h"
#include "sim/events.h"
#include "sim/ripples.h"
#include "sim/water.h"

#define WATER_DENSITY 1000.0  /* kg/m^3 */
#define AIR_DENSITY 1.225     /* kg/m^3, sea level at 15 C */
#define SKIN 1e-6             /* m: a stone put back above the surface or out of a box */
#define SAMPLES_PER_LENGTH 8  /* path samples per shortest wave length */
#define MAX_SAMPLES 256       /* per contact search */
#define ROOT_REL_TOL 1e-13    /* crossing time, as a fraction of the time searched */
#define ROOT_MAX_ITERATIONS 200

enum { FREE = 0, FLYING = 1, SINKING = 2 };

/* ---- the criterion (pure) -------------------------------------------------------------------- */

static double lambda_of(const ww_stones_desc *d) {
    return 4.0 * WATER_DENSITY * d->lift * d->radius * d->radius * d->radius / d->mass;
}

double ww_stone_min_speed(const ww_stones_desc *d, double beta) {
    double q = 2.0 * lambda_of(d) * pow(cos(beta), 3.0) - 1.0;
    double s = sin(beta);
    if (!(beta > 0.0) || !(beta < 0.5 * WW_PI) || !(q > 0.0)) return INFINITY;
    return sqrt(4.0 * d->radius * WW_G / (s * q));
}

/* ---- flight ---------------------------------------------------------------------------------- */

/* the drag's k in a = -k |v| v, 1/m */
static double drag_k(const ww_stones_desc *d) {
    return 0.5 * AIR_DENSITY * d->drag * WW_PI * d->radius * d->radius / d->mass;
}

static void accel(double k, const double v[3], double a[3]) {
    double s = k * sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    a[0] = -s * v[0];
    a[1] = -WW_G - s * v[1];
    a[2] = -s * v[2];
}

/* (p, v) after time h: the exact parabola without drag, one classical RK4 step with it; with
 * euler (time.integrator, the seeds' baseline) semi-implicit Euler: v += a h, p += v h */
static void fly(double k, int euler, const double p[3], const double v[3], double h,
                double po[3], double vo[3]) {
    if (euler) {
        double a[3];
        accel(k, v, a);
        for (int i = 0; i < 3; i++) {
            vo[i] = v[i] + a[i] * h;
            po[i] = p[i] + vo[i] * h;
        }
        return;
    }
    if (k == 0.0) {
        for (int i = 0; i < 3; i++) {
            double g = i == 1 ? -WW_G : 0.0;
            po[i] = p[i] + v[i] * h + 0.5 * g * h * h;
            vo[i] = v[i] + g * h;
        }
        return;
    }
    double k1[3], k2[3], k3[3], k4[3], v2[3], v3[3], v4[3];
    accel(k, v, k1);
    for (int i = 0; i < 3; i++) v2[i] = v[i] + 0.5 * h * k1[i];
    accel(k, v2, k2);
    for (int i = 0; i < 3; i++) v3[i] = v[i] + 0.5 * h * k2[i];
    accel(k, v3, k3);
    for (int i = 0; i < 3; i++) v4[i] = v[i] + h * k3[i];
    accel(k, v4, k4);
    for (int i = 0; i < 3; i++) {
        po[i] = p[i] + h / 6.0 * (v[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
        vo[i] = v[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}

/* the path inside a step of length h: the parabola itself without drag, else the cubic Hermite
 * through both ends (which is the parabola again when drag is 0) */
typedef struct path {
    double p0[3], v0[3], p1[3], v1[3], h;
    int exact;
} path;

static void path_at(const path *q, double s, double p[3], double v[3]) {
    if (q->exact) {
        fly(0.0, 0, q->p0, q->v0, s, p, v);
        return;
    }
    double u = s / q->h, u2 = u * u, u3 = u2 * u, h = q->h;
    double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -6 * u2 + 6 * u, d11 = 3 * u2 - 2 * u;
    for (int i = 0; i < 3; i++) {
        p[i] = h00 * q->p0[i] + h10 * h * q->v0[i] + h01 * q->p1[i] + h11 * h * q->v1[i];
        v[i] = (d00 * q->p0[i] + d01 * q->p1[i]) / h + d10 * q->v0[i] + d11 * q->v1[i];
    }
}

/* the surface a stone meets: the waves at the step's time, exact (ww_water_height), without the
 * ripple pool. A ripple is born at nearly full height around its centre, so a stone reading the
 * pool would strike the ripple of its own skip a step later and sink; ripples are centimetres
 * high and stone skipping is measured on still water, so the stone ignores them. */
static void surface(const ww_scene *sc, const ww_state *st, double x, double z,
                    ww_water_sample *w) {
    ww_field f = {.sc = sc, .phase = st->wave_phase, .t = st->t, .ripples = NULL};
    ww_query_opts o = {.tolerance = WW_QUERY_TOLERANCE,
                       .max_iterations = WW_QUERY_MAX_ITERATIONS,
                       .min_wavelength = 0.0};
    ww_water_height(&f, x, z, &o, w);
}

/* height of a point over the surface under it */
static double above(const ww_scene *sc, const ww_state *st, const double p[3]) {
    ww_water_sample w;
    surface(sc, st, p[0], p[2], &w);
    return p[1] - w.height;
}

/* the shortest wave, m (INFINITY on a flat lake): the surface turns over no shorter length */
static double feature_length(const ww_scene *sc) {
    double l = INFINITY;
    for (int i = 0; i < sc->nwaves; i++)
        if (sc->waves[i].amplitude > 0.0 && sc->waves[i].wavelength < l) l = sc->waves[i].wavelength;
    return l;
}

/* the crossing time in [a, b] with fa >= 0 > fb: Illinois regula falsi (Dowell & Jarratt 1971)
 * with a bisection every fourth step, so it shrinks the bracket on both sides */
static double crossing(const ww_scene *sc, const ww_state *st, const path *q, double a, double fa,
                       double b, double fb) {
    double tol = ROOT_REL_TOL * q->h;
    int side = 0;
    for (int it = 0; it < ROOT_MAX_ITERATIONS && b - a > tol; it++) {
        double s = (it % 4 == 3 || fa == fb) ? 0.5 * (a + b) : (a * fb - b * fa) / (fb - fa);
        if (!(s > a && s < b)) s = 0.5 * (a + b);
        double p[3], v[3];
        path_at(q, s, p, v);
        double f = above(sc, st, p);
        if (f >= 0.0) {
            a = s;
            fa = f;
            if (side == -1) fb *= 0.5;
            side = -1;
        } else {
            b = s;
            fb = f;
            if (side == 1) fa *= 0.5;
            side = 1;
        }
        if (f == 0.0) return s;
    }
    return b;
}

/* ---- solid contacts -------------------------------------------------------------------------- */

/* v rotated by the unit quaternion (w, x, y, z), or by its inverse when inv */
static void qrot(const double *q, int inv, const double v[3], double o[3]) {
    double n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (!(n > 1e-24)) { /* a pose not set yet: identity */
        o[0] = v[0], o[1] = v[1], o[2] = v[2];
        return;
    }
    double s = 1.0 / sqrt(n), w = q[0] * s, sg = inv ? -s : s;
    double u[3] = {q[1] * sg, q[2] * sg, q[3] * sg};
    double t[3] = {2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]),
                   2 * (u[0] * v[1] - u[1] * v[0])};
    o[0] = v[0] + w * t[0] + (u[1] * t[2] - u[2] * t[1]);
    o[1] = v[1] + w * t[1] + (u[2] * t[0] - u[0] * t[2]);
    o[2] = v[2] + w * t[2] + (u[0] * t[1] - u[1] * t[0]);
}

/* the chord a -> b against cube j grown by r (slabs in the cube's frame): fraction in [0, 1]
 * where it enters and the world normal there; -1 when it misses or starts inside */
static double hit_cube(const ww_scene *sc, const ww_state *st, int j, double r, const double a[3],
                       const double b[3], double n[3]) {
    const double *c = st->cube_pos + 3 * j, *q = st->cube_rot + 4 * j;
    double half = 0.5 * sc->cubes.cube[j].size + r, ra[3], rb[3], la[3], lb[3];
    ww_m_sub3(a, c, ra);
    ww_m_sub3(b, c, rb);
    qrot(q, 1, ra, la);
    qrot(q, 1, rb, lb);
    if (fabs(la[0]) < half && fabs(la[1]) < half && fabs(la[2]) < half) return -1.0;
    double enter = -INFINITY, leave = INFINITY;
    int axis = 0;
    for (int k = 0; k < 3; k++) {
        double d = lb[k] - la[k];
        if (d == 0.0) {
            if (fabs(la[k]) > half) return -1.0;
            continue;
        }
        double t1 = (-half - la[k]) / d, t2 = (half - la[k]) / d;
        if (t1 > t2) { double t = t1; t1 = t2; t2 = t; }
        if (t1 > enter) { enter = t1; axis = k; }
        if (t2 < leave) leave = t2;
    }
    if (!(enter <= leave && enter >= 0.0 && enter <= 1.0)) return -1.0;
    double ln[3] = {0, 0, 0};
    ln[axis] = lb[axis] > la[axis] ? -1.0 : 1.0;
    qrot(q, 0, ln, n);
    return enter;
}

/* the chord a -> b against the boat's sphere grown by r */
static double hit_boat(const ww_scene *sc, const ww_state *st, double r, const double a[3],
                       const double b[3], double n[3]) {
    double R = sc->boat.radius + r, m[3], d[3];
    ww_m_sub3(a, st->boat_pos, m);
    ww_m_sub3(b, a, d);
    double A = ww_m_dot3(d, d), B = 2.0 * ww_m_dot3(m, d), C = ww_m_dot3(m, m) - R * R;
    if (C < 0.0 || !(A > 0.0)) return -1.0;
    double disc = B * B - 4.0 * A * C;
    if (disc < 0.0) return -1.0;
    double u = (-B - sqrt(disc)) / (2.0 * A);
    if (!(u >= 0.0 && u <= 1.0)) return -1.0;
    for (int i = 0; i < 3; i++) n[i] = (m[i] + u * d[i]) / R;
    return u;
}

/* ---- one stone ------------------------------------------------------------------------------- */

typedef enum contact_kind { NONE = 0, WATER, CUBE, BOAT } contact_kind;

typedef struct contact {
    contact_kind kind;
    int body;           /* cube index */
    double s;           /* time into the path, s */
    double p[3];        /* where */
    double n[3];        /* solid contacts: outward normal */
} contact;

/* the earliest contact along q, searched by samples no farther apart than a surface feature */
static contact first_contact(const ww_scene *sc, const ww_state *st, const path *q, double fa) {
    const ww_stones_desc *d = &sc->stones;
    contact best = {.kind = NONE};
    double dx = q->p1[0] - q->p0[0], dz = q->p1[2] - q->p0[2];
    double spacing = feature_length(sc) / SAMPLES_PER_LENGTH;
    double ns = ceil(sqrt(dx * dx + dz * dz) / spacing);
    int n = ns >= MAX_SAMPLES ? MAX_SAMPLES : ns > 1.0 ? (int)ns : 1;
    double sa = 0.0, pa[3], va[3];
    path_at(q, 0.0, pa, va);
    for (int k = 1; k <= n && best.kind == NONE; k++) {
        double sb = k == n ? q->h : q->h * (double)k / (double)n, pb[3], vb[3], nrm[3];
        path_at(q, sb, pb, vb);
        double u_best = 2.0;
        for (int j = 0; sc->cubes.on && j < sc->cubes.count; j++) {
            double u = hit_cube(sc, st, j, d->radius, pa, pb, nrm);
            if (u >= 0.0 && u < u_best) {
                u_best = u;
                best = (contact){.kind = CUBE, .body = j, .n = {nrm[0], nrm[1], nrm[2]}};
            }
        }
        if (sc->boat.on && sc->boat.radius > 0.0) {
            double u = hit_boat(sc, st, d->radius, pa, pb, nrm);
            if (u >= 0.0 && u < u_best) {
                u_best = u;
                best = (contact){.kind = BOAT, .n = {nrm[0], nrm[1], nrm[2]}};
            }
        }
        double fb = above(sc, st, pb);
        if (fb < 0.0) {
            double sw = crossing(sc, st, q, sa, fa, sb, fb);
            if (best.kind == NONE || sw < sa + u_best * (sb - sa)) {
                best = (contact){.kind = WATER, .s = sw};
                path_at(q, sw, best.p, vb);
                continue;
            }
        }
        if (best.kind != NONE) {
            best.s = sa + u_best * (sb - sa);
            for (int i = 0; i < 3; i++) best.p[i] = pa[i] + u_best * (pb[i] - pa[i]);
        }
        sa = sb, fa = fb;
        for (int i = 0; i < 3; i++) pa[i] = pb[i];
    }
    return best;
}

static void start_sinking(const ww_scene *sc, ww_state *st, int i, double speed, int splash) {
    const ww_stones_desc *d = &sc->stones;
    const double *p = st->stone_pos + 3 * i;
    st->stone_state[i] = SINKING;
    ww_emit(sc, st, WW_SE_STONE_SINK, i, p, speed, 0.0);
    if (!splash) return;
    int full = speed >= d->splash_full;
    ww_emit(sc, st, full ? WW_SE_SPLASH_FULL : WW_SE_SPLASH_TINY, i, p, speed, 0.0);
    ww_ripples_add(sc, st, p[0], p[2], full ? d->ripple : d->ripple_tiny);
}

/* at the surface: skip or sink (stones.h) */
static void touch_water(const ww_scene *sc, ww_state *st, int i, const contact *c) {
    const ww_stones_desc *d = &sc->stones;
    double *p = st->stone_pos + 3 * i, *v = st->stone_vel + 3 * i;
    ww_water_sample w;
    surface(sc, st, c->p[0], c->p[2], &w);
    p[0] = c->p[0], p[1] = w.height, p[2] = c->p[2];
    double speed = ww_m_len3(v), vn = ww_m_dot3(v, w.normal);
    double beta = speed > 0.0 ? asin(ww_m_clamp(-vn / speed, 0.0, 1.0)) : 0.0;
    if ((int)st->stone_bounces[i] < d->max_bounces && speed > ww_stone_min_speed(d, beta)) {
        /* seed 000: v' = -e_n v_N + c_t v_T */
        for (int k = 0; k < 3; k++) {
            double vnk = vn * w.normal[k];
            v[k] = -d->e_n * vnk + d->c_t * (v[k] - vnk);
        }
        p[1] += SKIN;
        st->stone_bounces[i] += 1.0;
        st->skips[0] += 1.0;
        ww_emit(sc, st, WW_SE_STONE_SKIP, i, p, ww_m_len3(v), st->stone_bounces[i]);
        ww_ripples_add(sc, st, p[0], p[2], d->ripple);
        return;
    }
    start_sinking(sc, st, i, speed, 1);
}

/* against a cube or the boat: an impulse along the normal with the restitution */
static void thud(const ww_scene *sc, ww_state *st, int i, const contact *c) {
    const ww_stones_desc *d = &sc->stones;
    double *p = st->stone_pos + 3 * i, *v = st->stone_vel + 3 * i;
    double *bv = c->kind == CUBE ? st->cube_vel + 3 * c->body : st->boat_vel;
    double mb = sc->boat.mass;
    if (c->kind == CUBE) {
        double e = sc->cubes.cube[c->body].size;
        mb = sc->cubes.cube[c->body].density * e * e * e;
    }
    double rel[3];
    ww_m_sub3(v, bv, rel);
    double vn = ww_m_dot3(rel, c->n);
    for (int k = 0; k < 3; k++) p[k] = c->p[k] + SKIN * c->n[k];
    if (vn >= 0.0) return; /* already parting */
    double inv_b = mb > 0.0 ? 1.0 / mb : 0.0;
    double j = -(1.0 + d->restitution) * vn / (1.0 / d->mass + inv_b);
    for (int k = 0; k < 3; k++) {
        v[k] += j / d->mass * c->n[k];
        bv[k] -= j * inv_b * c->n[k];
    }
    ww_emit(sc, st, WW_SE_STONE_THUD, i, p, j, c->kind == CUBE ? 0.0 : 1.0);
    ww_ripples_add(sc, st, p[0], p[2], d->ripple_tiny);
}

/* a sinking stone for time h: v relaxes to the sinking speed (exact exponential) */
static void sink(const ww_scene *sc, ww_state *st, int i, double h) {
    double *p = st->stone_pos + 3 * i, *v = st->stone_vel + 3 * i;
    double term[3] = {0.0, -sc->stones.sink_speed, 0.0};
    double e = exp(-h / WW_STONE_SINK_TAU);
    for (int k = 0; k < 3; k++) {
        p[k] += term[k] * h + (v[k] - term[k]) * WW_STONE_SINK_TAU * (1.0 - e);
        v[k] = term[k] + (v[k] - term[k]) * e;
    }
    double bed = sc->water_level - sc->water_depth;
    if (p[1] <= bed) {
        p[1] = bed;
        for (int k = 0; k < 3; k++) v[k] = 0.0;
        st->stone_state[i] = FREE;
    }
}

static void step_stone(const ww_scene *sc, ww_state *st, int i) {
    double k = drag_k(&sc->stones), rem = sc->dt;
    double *p = st->stone_pos + 3 * i, *v = st->stone_vel + 3 * i;
    for (int n = 0; rem > 0.0 && st->stone_state[i] == FLYING; n++) {
        double fa = above(sc, st, p);
        if (fa < 0.0 || n == WW_STONE_CONTACTS_PER_STEP) { /* under water (thrown there, or
                                                             * pinned between contacts) */
            start_sinking(sc, st, i, ww_m_len3(v), 0);
            break;
        }
        int euler = sc->integrator == WW_INTEGRATE_EULER;
        path q = {.h = rem, .exact = k == 0.0 && !euler};
        for (int j = 0; j < 3; j++) q.p0[j] = p[j], q.v0[j] = v[j];
        fly(k, euler, p, v, rem, q.p1, q.v1);
        contact c = first_contact(sc, st, &q, fa);
        if (c.kind == NONE) {
            for (int j = 0; j < 3; j++) p[j] = q.p1[j], v[j] = q.v1[j];
            rem = 0.0;
            break;
        }
        double pc[3];
        path_at(&q, c.s, pc, v);
        rem -= c.s;
        if (c.kind == WATER)
            touch_water(sc, st, i, &c);
        else
            thud(sc, st, i, &c);
    }
    if (st->stone_state[i] == SINKING && rem > 0.0) sink(sc, st, i, rem);
}

/* ---- the system ------------------------------------------------------------------------------ */

void ww_stones_reset(const ww_scene *sc, ww_state *st) {
    for (int i = 0; i < WW_N_STONES(sc); i++) {
        st->stone_state[i] = FREE;
        st->stone_bounces[i] = 0.0;
        st->stone_spin[i] = 0.0;
        st->stone_t0[i] = 0.0;
        for (int k = 0; k < 3; k++) st->stone_pos[3 * i + k] = st->stone_vel[3 * i + k] = 0.0;
    }
    st->skips[0] = 0.0;
}

void ww_stones_step(const ww_scene *sc, ww_state *st) {
    for (int i = 0; i < WW_N_STONES(sc); i++) {
        if (st->stone_state[i] == FREE || st->stone_t0[i] == st->t) continue; /* thrown now */
        if (st->stone_state[i] == FLYING)
            step_stone(sc, st, i);
        else
            sink(sc, st, i, sc->dt);
    }
}

void ww_stones_event(const ww_scene *sc, ww_state *st, const ww_event *ev) {
    /* a free slot, else the oldest stone's */
    int slot = 0;
    for (int i = 0; i < WW_N_STONES(sc); i++) {
        if (st->stone_state[i] == FREE) {
            slot = i;
            break;
        }
        if (st->stone_t0[i] < st->stone_t0[slot]) slot = i;
    }
    double heading = ev->v[6], from[3] = {ev->v[3], ev->v[4], ev->v[5]};
    if (!(ev->flags & WW_THROW_FROM)) {
        for (int k = 0; k < 3; k++) from[k] = st->cam_pos[k];
        double fx = st->cam_fwd[0], fz = st->cam_fwd[2];
        heading = fx * fx + fz * fz > 1e-18 ? atan2(fz, fx) : 0.0;
    }
    /* seed 000: d = f_flat cos(a) + (0, -sin(a), 0) */
    double a = ev->v[1], s = ev->v[0];
    double *p = st->stone_pos + 3 * slot, *v = st->stone_vel + 3 * slot;
    for (int k = 0; k < 3; k++) p[k] = from[k];
    v[0] = s * cos(heading) * cos(a);
    v[1] = -s * sin(a);
    v[2] = s * sin(heading) * cos(a);
    st->stone_state[slot] = FLYING;
    st->stone_spin[slot] = ev->v[2];
    st->stone_bounces[slot] = 0.0;
    st->stone_t0[slot] = st->t;
    ww_emit(sc, st, WW_SE_STONE_THROW, slot, p, s, 0.0);
}
