/* collide.c - the camera against solid objects: push out, sweep and slide, rejoin the path
 * (model, sources and departures from seed 003 in collide.h). */
#include "sim/collide.h"

#include <math.h>

#include "core/mathx.h"
#include "sim/camera.h"
#include "sim/events.h"
#include "sim/floaters.h"

#define COLLIDE_SKIN 1e-6  /* m: a stopped camera is put this far outside the grown surface, so
                            * the next sweep starts outside it */
#define COLLIDE_SLIDES 3   /* sweeps per step: the move, then up to two slides */

/* one solid grown by the margin: a sphere (radius h[0]) or a box (half extents h) turned by q */
typedef struct solid {
    int what, index;
    int sphere;
    double c[3];
    double q[4];   /* unit quaternion w x y z */
    double h[3];
    double reach2; /* a sphere about c holding it, squared, widened past rounding */
} solid;

/* the most solids a scene has: the boat, the cubes, the chest, the models */
#define MAX_SOLIDS (1 + WW_MAX_CUBES + 1 + WW_MAX_MODELS)
/* the bounding sphere's widening: far more than the rounding of a point turned into a solid's
 * frame, so a point or a move it leaves out is out of the solid for the exact tests too */
#define REACH_SLACK (1.0 + 1e-9)

/* v turned by q (or by its inverse when inv): v + 2w (u x v) + 2 u x (u x v), u = q.xyz */
static void turn(const double q[4], int inv, const double v[3], double out[3]) {
    double u[3] = {inv ? -q[1] : q[1], inv ? -q[2] : q[2], inv ? -q[3] : q[3]}, w = q[0];
    double t[3] = {2.0 * (u[1] * v[2] - u[2] * v[1]), 2.0 * (u[2] * v[0] - u[0] * v[2]),
                   2.0 * (u[0] * v[1] - u[1] * v[0])};
    out[0] = v[0] + w * t[0] + (u[1] * t[2] - u[2] * t[1]);
    out[1] = v[1] + w * t[1] + (u[2] * t[0] - u[0] * t[2]);
    out[2] = v[2] + w * t[2] + (u[0] * t[1] - u[1] * t[0]);
}

static int solid_count(const ww_scene *sc) {
    return (sc->boat.on ? 1 : 0) + (sc->cubes.on ? sc->cubes.count : 0) + (sc->chest.on ? 1 : 0) +
           sc->models.count;
}

static void box(solid *s, int what, int index, const double c[3], const double half[3], double m) {
    *s = (solid){.what = what, .index = index, .q = {1.0, 0.0, 0.0, 0.0}};
    for (int a = 0; a < 3; a++) {
        s->c[a] = c[a];
        s->h[a] = half[a] + m;
    }
    s->reach2 = REACH_SLACK * (s->h[0] * s->h[0] + s->h[1] * s->h[1] + s->h[2] * s->h[2]);
}

/* a model whose parent chain ends at the boat moves with it: its bounds are in the boat's frame,
 * and the boat's own sphere already stops the camera there */
static int rides_boat(const ww_scene *sc, int k) {
    int p = sc->models.model[k].parent;
    for (int guard = 0; p >= 0 && guard < WW_MAX_MODELS; guard++) p = sc->models.model[p].parent;
    return p == WW_PARENT_BOAT;
}

/* solid k (boat, cubes, chest, models in that order); 0 when it is absent now */
static int get_solid(const ww_scene *sc, const ww_state *st, int k, double m, solid *s) {
    if (sc->boat.on && k-- == 0) {
        *s = (solid){.what = WW_SOLID_BOAT, .sphere = 1, .h = {sc->boat.radius + m}};
        s->reach2 = REACH_SLACK * s->h[0] * s->h[0];
        for (int a = 0; a < 3; a++) s->c[a] = st->boat_pos[a];
        return 1;
    }
    int ncubes = sc->cubes.on ? sc->cubes.count : 0;
    if (k < ncubes) {
        double e = 0.5 * sc->cubes.cube[k].size, half[3] = {e, e, e};
        box(s, WW_SOLID_CUBE, k, st->cube_pos + 3 * k, half, m);
        const double *q = st->cube_rot + 4 * k;
        double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (n > 0.0)
            for (int a = 0; a < 4; a++) s->q[a] = q[a] / n;
        return 1;
    }
    k -= ncubes;
    if (sc->chest.on && k-- == 0) {
        if (st->chest_state[0] == 0.0) return 0;
        const double *z = sc->chest.size, *b = st->chest_pos;
        double c[3] = {b[0], b[1] + 0.5 * z[1], b[2]}, half[3] = {0.5 * z[0], 0.5 * z[1], 0.5 * z[2]};
        box(s, WW_SOLID_CHEST, 0, c, half, m);
        return 1;
    }
    if (rides_boat(sc, k)) return 0;
    const ww_model_desc *md = &sc->models.model[k];
    if (!md->solid) return 0; /* plants, groups: the camera passes */
    double c[3], half[3], fq[4];
    int floating = ww_floater_box(sc, st, k, c, half, fq); /* sim/floaters.h */
    if (floating < 0) return 0;
    if (floating > 0) {
        box(s, WW_SOLID_MODEL, k, c, half, m);
        for (int a = 0; a < 4; a++) s->q[a] = fq[a];
        return 1;
    }
    if (md->oriented) {
        box(s, WW_SOLID_MODEL, k, md->obb_c, md->obb_h, m);
        for (int a = 0; a < 4; a++) s->q[a] = md->obb_q[a];
        return 1;
    }
    for (int a = 0; a < 3; a++) {
        c[a] = 0.5 * (md->min[a] + md->max[a]);
        half[a] = 0.5 * (md->max[a] - md->min[a]);
    }
    box(s, WW_SOLID_MODEL, k, c, half, m);
    return 1;
}

/* p in the solid's frame (boxes), relative to its centre */
static void to_local(const solid *s, const double p[3], double l[3]) {
    double d[3];
    ww_m_sub3(p, s->c, d);
    turn(s->q, 1, d, l);
}

static int inside(const solid *s, const double p[3]) {
    double l[3];
    to_local(s, p, l);
    if (s->sphere) return ww_m_dot3(l, l) < s->h[0] * s->h[0];
    return fabs(l[0]) < s->h[0] && fabs(l[1]) < s->h[1] && fabs(l[2]) < s->h[2];
}

/* move p (inside s) to the nearest point of its surface, plus the skin */
static void push_out(const solid *s, double p[3]) {
    double l[3], n[3] = {0.0, 0.0, 0.0};
    to_local(s, p, l);
    if (s->sphere) {
        double d = ww_m_len3(l);
        if (d > 0.0)
            for (int a = 0; a < 3; a++) n[a] = l[a] / d;
        else
            n[1] = 1.0;
        for (int a = 0; a < 3; a++) p[a] = s->c[a] + n[a] * (s->h[0] + COLLIDE_SKIN);
        return;
    }
    int best = 0;
    for (int a = 1; a < 3; a++)
        if (s->h[a] - fabs(l[a]) < s->h[best] - fabs(l[best])) best = a;
    l[best] = l[best] >= 0.0 ? s->h[best] + COLLIDE_SKIN : -s->h[best] - COLLIDE_SKIN;
    double w[3];
    turn(s->q, 0, l, w);
    for (int a = 0; a < 3; a++) p[a] = s->c[a] + w[a];
}

/* first entry of p + u d (u in [0, 1]) into s from outside: u and the outward normal there */
static int sweep(const solid *s, const double p[3], const double d[3], double *u, double n[3]) {
    double o[3], v[3];
    to_local(s, p, o);
    turn(s->q, 1, d, v);
    if (s->sphere) {
        double a = ww_m_dot3(v, v), b = 2.0 * ww_m_dot3(o, v);
        double c = ww_m_dot3(o, o) - s->h[0] * s->h[0], disc = b * b - 4.0 * a * c;
        if (c < 0.0 || b >= 0.0 || a == 0.0 || disc < 0.0) return 0;
        double t = (-b - sqrt(disc)) / (2.0 * a);
        if (t < 0.0 || t > 1.0) return 0;
        for (int k = 0; k < 3; k++) n[k] = (o[k] + t * v[k]) / s->h[0];
        ww_m_normalize3(n);
        *u = t;
        return 1;
    }

    /* slabs (Ericson 5.3.3): the latest entry and the earliest exit */
    double enter = -INFINITY, leave = INFINITY;
    int axis = -1;
    for (int a = 0; a < 3; a++) {
        if (v[a] == 0.0) {
            if (o[a] <= -s->h[a] || o[a] >= s->h[a]) return 0;
            continue;
        }
        double t1 = (-s->h[a] - o[a]) / v[a], t2 = (s->h[a] - o[a]) / v[a];
        if (t1 > t2) {
            double x = t1;
            t1 = t2;
            t2 = x;
        }
        if (t1 > enter) {
            enter = t1;
            axis = a;
        }
        if (t2 < leave) leave = t2;
    }
    if (axis < 0 || enter >= leave || enter < 0.0 || enter > 1.0) return 0;
    double ln[3] = {0.0, 0.0, 0.0};
    ln[axis] = v[axis] > 0.0 ? -1.0 : 1.0;
    turn(s->q, 0, ln, n);
    *u = enter;
    return 1;
}

/* p is surely outside s: farther from its centre than its bounding sphere */
static int far_from(const solid *s, const double p[3]) {
    double e[3];
    ww_m_sub3(p, s->c, e);
    return ww_m_dot3(e, e) > s->reach2;
}

/* the move p + u d (u in [0, 1]) surely misses s: it passes its centre beyond its bounding
 * sphere (the nearest point of the segment to the centre) */
static int passes_by(const solid *s, const double p[3], const double d[3]) {
    double e[3], dd = ww_m_dot3(d, d);
    ww_m_sub3(s->c, p, e);
    double u = dd > 0.0 ? ww_m_clamp(ww_m_dot3(e, d) / dd, 0.0, 1.0) : 0.0;
    for (int a = 0; a < 3; a++) e[a] -= u * d[a];
    return ww_m_dot3(e, e) > s->reach2;
}

void ww_camera_collide(const ww_scene *sc, ww_state *st) {
    if (!WW_N_SOLIDS(sc)) return;
    double *prev = st->collide_prev, m = sc->near_clip;
    int32_t *cs = st->collide_state;
    double p1[3] = {st->cam_pos[0], st->cam_pos[1], st->cam_pos[2]};
    int what = -1, index = 0;

    /* in the boat's seat the camera rides inside the hull's sphere by design (sim/boat.h) */
    if (sc->boat.on && st->boat_camera[0] == 1.0) {
        for (int a = 0; a < 3; a++) prev[a] = p1[a];
        cs[0] = cs[1] = 0;
        return;
    }

    /* the solids present now, in order, each built once */
    solid all[MAX_SOLIDS];
    int n = 0;
    for (int k = 0, count = solid_count(sc); k < count && n < MAX_SOLIDS; k++)
        n += get_solid(sc, st, k, m, &all[n]);

    /* 1. start where the camera was, out of anything that moved into it */
    int from_prev = cs[1] != 0 && st->step > 0;
    double p[3];
    for (int a = 0; a < 3; a++) p[a] = from_prev ? prev[a] : p1[a];
    for (int k = 0; k < n; k++) {
        const solid *s = &all[k];
        if (far_from(s, p) || !inside(s, p)) continue;
        push_out(s, p);
        what = s->what;
        index = s->index;
    }

    /* 2. sweep to the target; stop at the first entry and slide what is left. Never a jump to
     * the path: a camera held at a wall whose path comes out on the far side would pass through
     * the wall; it follows the path again once the sweep reaches it */
    double target[3] = {p1[0], p1[1], p1[2]};
    for (int it = 0; it < COLLIDE_SLIDES; it++) {
        double d[3], u = 2.0, best_n[3] = {0.0, 0.0, 0.0};
        ww_m_sub3(target, p, d);
        if (ww_m_dot3(d, d) == 0.0) break;
        int hit = -1;
        for (int k = 0; k < n; k++) {
            double uk, nk[3];
            if (passes_by(&all[k], p, d) || !sweep(&all[k], p, d, &uk, nk) || uk >= u) continue;
            u = uk;
            hit = k;
            for (int a = 0; a < 3; a++) best_n[a] = nk[a];
        }
        if (hit < 0) {
            for (int a = 0; a < 3; a++) p[a] = target[a];
            break;
        }
        for (int a = 0; a < 3; a++) p[a] += u * d[a] + COLLIDE_SKIN * best_n[a];
        if (what < 0) {
            what = all[hit].what;
            index = all[hit].index;
        }
        /* slide: drop the part of the rest of the move that points into the surface */
        double r[3];
        ww_m_sub3(target, p, r);
        double rn = ww_m_dot3(r, best_n);
        if (rn < 0.0)
            for (int a = 0; a < 3; a++) r[a] -= rn * best_n[a];
        for (int a = 0; a < 3; a++) target[a] = p[a] + r[a];
    }

    /* log a contact once, when it starts */
    double cut[3];
    ww_m_sub3(p1, p, cut);
    double cut_len = ww_m_len3(cut);
    int held = cut_len > 0.0 && what >= 0;
    if (held && cs[0] == 0)
        ww_emit(sc, st, WW_SE_CAMERA_BLOCKED, index, p, cut_len, (double)what);
    cs[0] = held ? what + 1 : 0;
    cs[1] = 1;
    for (int a = 0; a < 3; a++) prev[a] = st->cam_pos[a] = p[a];
}
