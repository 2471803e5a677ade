/* meshgen.c - procedural meshes for the scene's objects (gfx/meshgen.h): boxes, lofted bodies
 * (sphere, pebble, fish, bobber, stem) made of rings around an axis with poles at the ends, the
 * rowing boat's hull as a shell of thickness (outer and inner skin, each closed at both ends,
 * joined by the gunwale rim) and the lid over its inside, and flat plates (tail fin). Pure CPU;
 * no GL.
 *
 * Every piece is closed, so the whole mesh is watertight by position and its signed volume is
 * the divergence-theorem sum (Zhang & Chen, "Efficient feature extraction for 2D/3D objects in
 * mesh representation", ICIP 2001). Smooth normals are the area-weighted sums of the face
 * normals around a vertex; boxes and plates keep flat faces.
 */
#include "gfx/meshgen.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* hull shape (fractions of the unit box; bow toward +x) */
#define HULL_STATIONS 18     /* sections from stern to bow */
#define HULL_SECTION 12      /* points on a section from one gunwale to the other */
#define HULL_BEAM 0.19       /* half-beam at the widest section */
#define HULL_STERN 0.72      /* transom half-beam as a fraction of the widest */
#define HULL_WIDEST 0.4      /* where the hull is widest, from the stern */
#define HULL_DEPTH 0.14      /* keel below the waterline amidships */
#define HULL_SHEER 0.05      /* gunwale above the waterline amidships */
#define HULL_SHEER_RISE 0.09 /* the gunwale rises this much more at bow and stern */
#define HULL_SKIN 0.018      /* planking thickness */
#define HULL_BOW_TIP 0.012   /* half-beam of the stem's flat face at the bow */
#define HULL_INNER_END 0.985 /* where the inner skin ends against the solid stem (0 .. 1) */
#define HULL_FULLNESS 0.7    /* |cos|^this across a section: < 1 fills out the bilge */

/* fish (head toward +x): a laterally compressed body and a forked vertical tail */
#define FISH_NOSE 0.5
#define FISH_TAIL_BASE (-0.3) /* where the body's rear pole is */
#define FISH_HEIGHT 0.16      /* half-height of the body at its deepest */
#define FISH_WIDTH 0.07       /* half-width */
#define FISH_FIN 0.012        /* half-thickness of the tail fin */
#define FISH_WIGGLE_FROM 0.15 /* the tail weight is 0 ahead of this x, 1 at x = -0.5 */

/* a growing mesh */
typedef struct mb {
    float *v;
    int nv, capv;
    uint32_t *ix;
    uint32_t ni, capi;
    int oom;
} mb;

static int mb_vert(mb *b, const double p[3], const double n[3], double u, double w) {
    if (b->nv == b->capv) {
        int cap = b->capv ? 2 * b->capv : 256;
        float *v = realloc(b->v, (size_t)cap * 8 * sizeof *v);
        if (!v) {
            b->oom = 1;
            return 0;
        }
        b->v = v;
        b->capv = cap;
    }
    float *q = b->v + 8 * b->nv;
    for (int i = 0; i < 3; i++) {
        q[i] = (float)p[i];
        q[3 + i] = n ? (float)n[i] : 0.0f;
    }
    q[6] = (float)u;
    q[7] = (float)w;
    return b->nv++;
}

static void mb_tri(mb *b, int a, int c, int d) {
    if (b->oom) return;
    if (b->ni + 3 > b->capi) {
        uint32_t cap = b->capi ? 2 * b->capi : 768;
        uint32_t *ix = realloc(b->ix, (size_t)cap * sizeof *ix);
        if (!ix) {
            b->oom = 1;
            return;
        }
        b->ix = ix;
        b->capi = cap;
    }
    b->ix[b->ni++] = (uint32_t)a;
    b->ix[b->ni++] = (uint32_t)c;
    b->ix[b->ni++] = (uint32_t)d;
}

/* normals of vertices [v0, nv) as the area-weighted sum of the faces [i0, ni) around them */
static void mb_smooth(mb *b, int v0, uint32_t i0) {
    if (b->oom) return;
    for (int i = v0; i < b->nv; i++) b->v[8 * i + 3] = b->v[8 * i + 4] = b->v[8 * i + 5] = 0.0f;
    for (uint32_t t = i0; t + 2 < b->ni; t += 3) {
        const float *p[3];
        for (int k = 0; k < 3; k++) p[k] = b->v + 8 * b->ix[t + (uint32_t)k];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)p[1][k] - p[0][k];
            e2[k] = (double)p[2][k] - p[0][k];
        }
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++) b->v[8 * b->ix[t + (uint32_t)k] + 3 + c] += (float)n[c];
    }
    for (int i = v0; i < b->nv; i++) {
        float *n = b->v + 8 * i + 3;
        float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (l > 0.0f)
            for (int c = 0; c < 3; c++) n[c] /= l;
        else
            n[1] = 1.0f;
    }
}

/* a box of half-sizes h around c, flat faces: each face's tangents t1 x t2 = n */
static void mb_box(mb *b, const double c[3], const double h[3]) {
    static const int face[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}, {1, 0, 2}, {2, 0, 1}, {2, 1, 0}};
    static const double sgn[6] = {1, -1, 1, -1, 1, -1}; /* normal axis face[f][0], sign */
    for (int f = 0; f < 6; f++) {
        int na = face[f][0], ta = face[f][1], tb = face[f][2];
        double n[3] = {0, 0, 0};
        n[na] = sgn[f];
        static const double cu[4] = {-1, 1, 1, -1}, cv[4] = {-1, -1, 1, 1};
        int first = b->nv;
        for (int k = 0; k < 4; k++) {
            double p[3] = {c[0], c[1], c[2]};
            p[na] += sgn[f] * h[na];
            p[ta] += cu[k] * h[ta];
            p[tb] += cv[k] * h[tb];
            mb_vert(b, p, n, 0.5 * (cu[k] + 1.0), 0.5 * (cv[k] + 1.0));
        }
        /* +x: t1 = y, t2 = z; -x: z, y; +y: z, x; -y: x, z; +z: x, y; -z: y, x  (t1 x t2 = n) */
        mb_tri(b, first, first + 1, first + 2);
        mb_tri(b, first, first + 2, first + 3);
    }
}

/* a body of revolution about axis A (basis A, B, C right-handed): stations at axial a[i] with
 * elliptic rings of semi-axes rb (along B) and rc (along C) around centre (a, cb, 0); a station
 * of zero radii at either end is a pole. Returns the first vertex. uv: (ring angle / 2 pi,
 * station fraction), or the tail weight from weight_from when it is not NAN. */
typedef struct loft {
    int n;
    const double *a, *rb, *rc, *cb;
    int axis; /* 0: x (B = y, C = z), 1: y (B = z, C = x) */
    double weight_from; /* fish: uv.x = tail weight; NAN: not a fish */
} loft;

static void loft_point(const loft *L, int i, double th, double p[3]) {
    double ax = L->a[i], vb = L->cb[i] + L->rb[i] * cos(th), vc = L->rc[i] * sin(th);
    if (L->axis == 0) {
        p[0] = ax; p[1] = vb; p[2] = vc;
    } else {
        p[1] = ax; p[2] = vb; p[0] = vc;
    }
}

static double tail_weight(double x, double from) {
    double w = (from - x) / (from + 0.5);
    w = w < 0.0 ? 0.0 : w > 1.0 ? 1.0 : w;
    return w * w;
}

static void mb_loft(mb *b, const loft *L) {
    int v0 = b->nv;
    uint32_t i0 = b->ni;
    int ns = WW_MESHGEN_SLICES;
    int first = 0, last = L->n - 1;
    int pole0 = L->rb[0] == 0.0 && L->rc[0] == 0.0, pole1 = L->rb[last] == 0.0 && L->rc[last] == 0.0;
    int ring[WW_MESHGEN_STACKS + 8];
    WW_ASSERT(L->n <= WW_MESHGEN_STACKS + 8);
    int pv0 = -1, pv1 = -1;
    for (int i = first; i <= last; i++) {
        double frac = (double)i / (double)(L->n - 1);
        if ((i == first && pole0) || (i == last && pole1)) {
            double p[3];
            loft_point(L, i, 0.0, p);
            double u = isnan(L->weight_from) ? 0.5 : tail_weight(p[0], L->weight_from);
            int v = mb_vert(b, p, NULL, u, frac);
            if (i == first) pv0 = v; else pv1 = v;
            continue;
        }
        ring[i] = b->nv;
        for (int j = 0; j < ns; j++) {
            double p[3];
            loft_point(L, i, 2.0 * PI * j / ns, p);
            double u = isnan(L->weight_from) ? (double)j / ns : tail_weight(p[0], L->weight_from);
            mb_vert(b, p, NULL, u, frac);
        }
    }
    int r0 = pole0 ? first + 1 : first, r1 = pole1 ? last - 1 : last;
    for (int i = r0; i < r1; i++) {
        for (int j = 0; j < ns; j++) {
            int a = ring[i] + j, a1 = ring[i] + (j + 1) % ns;
            int c = ring[i + 1] + j, c1 = ring[i + 1] + (j + 1) % ns;
            mb_tri(b, a, a1, c1);
            mb_tri(b, a, c1, c);
        }
    }
    for (int j = 0; j < ns; j++) {
        if (pole0) mb_tri(b, pv0, ring[r0] + (j + 1) % ns, ring[r0] + j);
        if (pole1) mb_tri(b, pv1, ring[r1] + j, ring[r1] + (j + 1) % ns);
    }
    mb_smooth(b, v0, i0);
}

/* a sphere of radius r at c (poles along x), exact normals; s scales it per axis afterwards */
static void mb_ellipsoid(mb *b, const double c[3], const double r[3]) {
    double a[WW_MESHGEN_STACKS + 1], rb[WW_MESHGEN_STACKS + 1], rc[WW_MESHGEN_STACKS + 1],
        cb[WW_MESHGEN_STACKS + 1];
    for (int i = 0; i <= WW_MESHGEN_STACKS; i++) {
        double th = PI * i / WW_MESHGEN_STACKS;
        a[i] = -cos(th);
        rb[i] = rc[i] = i == 0 || i == WW_MESHGEN_STACKS ? 0.0 : sin(th);
        cb[i] = 0.0;
    }
    loft L = {WW_MESHGEN_STACKS + 1, a, rb, rc, cb, 0, NAN};
    int v0 = b->nv;
    mb_loft(b, &L);
    /* unit sphere -> ellipsoid: positions scale by r, normals by 1 / r */
    for (int i = v0; i < b->nv && !b->oom; i++) {
        float *q = b->v + 8 * i;
        double n[3], l = 0.0;
        for (int k = 0; k < 3; k++) {
            n[k] = q[k] / r[k];
            l += n[k] * n[k];
        }
        l = sqrt(l);
        for (int k = 0; k < 3; k++) {
            q[3 + k] = (float)(n[k] / l);
            q[k] = (float)(c[k] + r[k] * q[k]);
        }
    }
}

/* a closed cylinder along y from y0 to y1, radius r, centred on x = z = 0 */
static void mb_cylinder(mb *b, double y0, double y1, double r) {
    double a[4] = {y0, y0, y1, y1}, rr[4] = {0.0, r, r, 0.0}, cb[4] = {0, 0, 0, 0};
    loft L = {4, a, rr, rr, cb, 1, NAN};
    mb_loft(b, &L);
}

/* a flat plate: polygon (x, y) counter-clockwise, star-shaped around its first point's
 * neighbour centre c, extruded to z in [-t, t], flat faces */
static void mb_plate(mb *b, const double (*poly)[2], int n, const double c[2], double t,
                     double weight_from) {
    for (int side = 0; side < 2; side++) {
        double z = side == 0 ? t : -t, nz[3] = {0.0, 0.0, side == 0 ? 1.0 : -1.0};
        double pc[3] = {c[0], c[1], z};
        int ctr = mb_vert(b, pc, nz, tail_weight(c[0], weight_from), 0.5);
        int first = b->nv;
        for (int i = 0; i < n; i++) {
            double p[3] = {poly[i][0], poly[i][1], z};
            mb_vert(b, p, nz, tail_weight(p[0], weight_from), 0.5);
        }
        for (int i = 0; i < n; i++) {
            int p = first + i, q = first + (i + 1) % n;
            if (side == 0) mb_tri(b, ctr, p, q);
            else mb_tri(b, ctr, q, p);
        }
    }
    for (int i = 0; i < n; i++) {
        const double *p = poly[i], *q = poly[(i + 1) % n];
        double dx = q[0] - p[0], dy = q[1] - p[1], l = sqrt(dx * dx + dy * dy);
        double nn[3] = {dy / l, -dx / l, 0.0};
        double pp[3] = {p[0], p[1], t}, pm[3] = {p[0], p[1], -t};
        double qp[3] = {q[0], q[1], t}, qm[3] = {q[0], q[1], -t};
        int a = mb_vert(b, pp, nn, tail_weight(p[0], weight_from), 0.0);
        int am = mb_vert(b, pm, nn, tail_weight(p[0], weight_from), 1.0);
        int cm = mb_vert(b, qm, nn, tail_weight(q[0], weight_from), 1.0);
        int cp = mb_vert(b, qp, nn, tail_weight(q[0], weight_from), 0.0);
        mb_tri(b, a, am, cm);
        mb_tri(b, a, cm, cp);
    }
}

/* ---- the shapes ---- */

static void gen_box(mb *b) {
    double c[3] = {0, 0, 0}, h[3] = {0.5, 0.5, 0.5};
    mb_box(b, c, h);
}

static void gen_sphere(mb *b) {
    double c[3] = {0, 0, 0}, r[3] = {0.5, 0.5, 0.5};
    mb_ellipsoid(b, c, r);
}

static double dist3(const double a[3], const double b[3]) {
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* a drop: an icosahedron of diameter 1 with the sphere's normals (12 vertices; a drop is a few
 * pixels across, where a 425-vertex sphere only costs vertex work). Its faces are the triples of
 * vertices a side apart, wound to face out */
static void gen_drop(mb *b) {
    const double f = 0.5 * (1.0 + sqrt(5.0)), r = 0.5 / sqrt(1.0 + f * f);
    double p[12][3];
    for (int i = 0; i < 12; i++) {
        double s1 = (i & 1) ? -1.0 : 1.0, s2 = (i & 2) ? -1.0 : 1.0, q[3] = {0, 0, 0};
        int k = i >> 2; /* (0, +-1, +-f), (+-1, +-f, 0), (+-f, 0, +-1) */
        q[(k + 1) % 3] = s1;
        q[(k + 2) % 3] = s2 * f;
        double l = sqrt(1.0 + f * f), n[3] = {q[0] / l, q[1] / l, q[2] / l};
        for (int j = 0; j < 3; j++) p[i][j] = r * q[j];
        mb_vert(b, p[i], n, 0.0, 0.0);
    }
    double side = 2.0 * r; /* the edge of the icosahedron (0, +-1, +-f) is 2 before scaling */
    for (int i = 0; i < 12; i++)
        for (int j = i + 1; j < 12; j++)
            for (int k = j + 1; k < 12; k++) {
                double e[3] = {dist3(p[i], p[j]), dist3(p[j], p[k]), dist3(p[i], p[k])};
                if (fabs(e[0] - side) > 1e-9 || fabs(e[1] - side) > 1e-9 ||
                    fabs(e[2] - side) > 1e-9)
                    continue;
                double u[3], v[3], c[3];
                for (int m = 0; m < 3; m++) u[m] = p[j][m] - p[i][m], v[m] = p[k][m] - p[i][m];
                c[0] = u[1] * v[2] - u[2] * v[1];
                c[1] = u[2] * v[0] - u[0] * v[2];
                c[2] = u[0] * v[1] - u[1] * v[0];
                int out = c[0] * p[i][0] + c[1] * p[i][1] + c[2] * p[i][2] > 0.0;
                if (out)
                    mb_tri(b, i, j, k);
                else
                    mb_tri(b, i, k, j);
            }
}

/* a flattened pebble: an ellipsoid, long in x, a little shorter in z, thin in y */
static void gen_stone(mb *b) {
    double c[3] = {0, 0, 0}, r[3] = {0.5, 0.5 * WW_STONE_THICKNESS, 0.5 * WW_STONE_DEPTH};
    mb_ellipsoid(b, c, r);
}

/* a bobber: a ball below and a thin stem up to the top of the box */
static void gen_lure(mb *b) {
    double c[3] = {0, -0.5 + WW_LURE_BALL, 0}, r[3] = {WW_LURE_BALL, WW_LURE_BALL, WW_LURE_BALL};
    mb_ellipsoid(b, c, r);
    mb_cylinder(b, c[1] + 0.8 * WW_LURE_BALL, 0.5, WW_LURE_STEM);
}

/* a chest: a body and a lid a little wider, sitting on it */
static void gen_chest(mb *b) {
    double lid = WW_CHEST_LID, body_top = 0.5 - lid;
    double cb[3] = {0, 0.5 * (-0.5 + body_top), 0}, hb[3] = {0.47, 0.5 * (body_top + 0.5), 0.47};
    double cl[3] = {0, 0.5 - 0.5 * lid, 0}, hl[3] = {0.5, 0.5 * lid, 0.5};
    mb_box(b, cb, hb);
    mb_box(b, cl, hl);
}

static void gen_grid(mb *b) {
    int n = WW_MESHGEN_GRID, first = b->nv;
    double up[3] = {0, 1, 0};
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double p[3] = {-0.5 + (double)i / n, 0.0, -0.5 + (double)j / n};
            mb_vert(b, p, up, (double)i / n, (double)j / n);
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = first + j * (n + 1) + i, c = a + n + 1;
            mb_tri(b, a, c, a + 1);
            mb_tri(b, a + 1, c, c + 1);
        }
}

static void gen_column(mb *b) {
    int ns = WW_MESHGEN_SLICES, nr = 5, first = b->nv;
    for (int i = 0; i < nr; i++)
        for (int j = 0; j < ns; j++) {
            double th = 2.0 * PI * j / ns, y = -0.5 + (double)i / (nr - 1);
            double p[3] = {0.5 * cos(th), y, 0.5 * sin(th)}, n[3] = {cos(th), 0.0, sin(th)};
            mb_vert(b, p, n, (double)j / ns, y + 0.5);
        }
    /* around y with angle from +x toward +z: tangent x around is +z, so (up, around) is CCW
     * seen from outside */
    for (int i = 0; i + 1 < nr; i++)
        for (int j = 0; j < ns; j++) {
            int a = first + i * ns + j, a1 = first + i * ns + (j + 1) % ns;
            int c = a + ns, c1 = a1 + ns;
            mb_tri(b, a, c, c1);
            mb_tri(b, a, c1, a1);
        }
}

/* the fish: a lofted body (head +x) and a forked tail fin */
static void gen_fish(mb *b) {
    enum { N = WW_MESHGEN_STACKS + 1 };
    double a[N], rb[N], rc[N], cb[N];
    for (int i = 0; i < N; i++) {
        double s = (double)i / (N - 1); /* 0 at the tail base, 1 at the nose */
        a[i] = FISH_TAIL_BASE + (FISH_NOSE - FISH_TAIL_BASE) * s;
        /* deepest a little ahead of the middle, blunt head, slender peduncle */
        double f = i == 0 || i == N - 1 ? 0.0 : pow(sin(PI * pow(s, 0.75)), 0.7);
        rb[i] = FISH_HEIGHT * f;
        rc[i] = FISH_WIDTH * f;
        cb[i] = 0.0;
    }
    loft L = {N, a, rb, rc, cb, 0, FISH_WIGGLE_FROM};
    mb_loft(b, &L);
    static const double tail[5][2] = {
        {-0.22, 0.035}, {-0.5, 0.21}, {-0.42, 0.0}, {-0.5, -0.21}, {-0.22, -0.035}};
    double c[2] = {-0.3, 0.0};
    mb_plate(b, tail, 5, c, FISH_FIN, FISH_WIGGLE_FROM);
}

/* a species' body plan (gfx/meshgen.h): a lofted body between tail_base and nose, deepest
 * where sin(pi s^front) peaks, rounded by the power round; a tail fin and up to two more fins,
 * each a flat plate (polygon counter-clockwise in (x, y), star-shaped around its centroid) */
typedef struct fish_plan {
    double nose, tail_base, height, width, front, round, wiggle_from;
    int nfin;
    struct {
        int n;
        double p[6][2];
        double t; /* half-thickness */
    } fin[3];
} fish_plan;

static const fish_plan FISH_PLANS[3] = {
    /* slim: a mackerel, length / depth about 5.5 */
    {0.5, -0.32, 0.085, 0.06, 0.8, 0.8, FISH_WIGGLE_FROM, 2,
     {{5, {{-0.26, 0.02}, {-0.5, 0.16}, {-0.43, 0.0}, {-0.5, -0.16}, {-0.26, -0.02}}, FISH_FIN},
      {3, {{-0.08, 0.05}, {0.10, 0.05}, {0.0, 0.14}}, 0.008}}},
    /* deep: an angelfish, a disc as deep as long with high swept fins */
    {0.45, -0.26, 0.24, 0.045, 0.9, 0.55, -0.1, 3,
     {{5, {{-0.2, 0.05}, {-0.44, 0.17}, {-0.47, 0.0}, {-0.44, -0.17}, {-0.2, -0.05}}, FISH_FIN},
      {4, {{-0.24, 0.1}, {0.1, 0.19}, {-0.06, 0.3}, {-0.3, 0.48}}, 0.008},
      {4, {{-0.24, -0.1}, {-0.3, -0.46}, {-0.06, -0.28}, {0.06, -0.17}}, 0.008}}},
    /* long: a slender fish that undulates from near its head */
    {0.5, -0.42, 0.05, 0.042, 0.85, 0.45, 0.35, 2,
     {{5, {{-0.38, 0.012}, {-0.5, 0.06}, {-0.47, 0.0}, {-0.5, -0.06}, {-0.38, -0.012}}, FISH_FIN},
      {4, {{-0.34, 0.02}, {0.1, 0.03}, {-0.05, 0.08}, {-0.3, 0.07}}, 0.006}}},
};

static void gen_fish_species(mb *b, const fish_plan *f) {
    enum { N = WW_MESHGEN_STACKS + 1 };
    double a[N], rb[N], rc[N], cb[N];
    for (int i = 0; i < N; i++) {
        double s = (double)i / (N - 1);
        a[i] = f->tail_base + (f->nose - f->tail_base) * s;
        double g = i == 0 || i == N - 1 ? 0.0 : pow(sin(PI * pow(s, f->front)), f->round);
        rb[i] = f->height * g;
        rc[i] = f->width * g;
        cb[i] = 0.0;
    }
    loft L = {N, a, rb, rc, cb, 0, f->wiggle_from};
    mb_loft(b, &L);
    for (int k = 0; k < f->nfin; k++) {
        double c[2] = {0.0, 0.0};
        int n = f->fin[k].n;
        for (int i = 0; i < n; i++) {
            c[0] += f->fin[k].p[i][0] / n;
            c[1] += f->fin[k].p[i][1] / n;
        }
        mb_plate(b, f->fin[k].p, n, c, f->fin[k].t, f->wiggle_from);
    }
}

/* the hull's section at station u (0 stern .. 1 bow) */
static void hull_section(double u, double *beam, double *keel, double *gunwale) {
    double w;
    if (u <= HULL_WIDEST) {
        w = HULL_STERN + (1.0 - HULL_STERN) * sin(0.5 * PI * u / HULL_WIDEST);
    } else {
        double v = (u - HULL_WIDEST) / (1.0 - HULL_WIDEST);
        w = sqrt(fmax(1.0 - v * v, 0.0));
    }
    *beam = fmax(HULL_BEAM * w, HULL_BOW_TIP);
    /* the keel rises toward the bow (the forefoot) */
    *keel = -HULL_DEPTH * (u < 0.6 ? 1.0 : 1.0 - 0.6 * ((u - 0.6) / 0.4) * ((u - 0.6) / 0.4));
    double e = 2.0 * u - 1.0;
    *gunwale = HULL_SHEER + HULL_SHEER_RISE * e * e;
}

double ww_meshgen_hull_waterline(double u) {
    double beam, keel, gun;
    hull_section(u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u, &beam, &keel, &gun);
    /* hull_point's section crosses y = 0 where gun + (keel - gun) sin(phi) = 0 */
    double s = gun / (gun - keel), c = sqrt(fmax(1.0 - s * s, 0.0));
    return beam * pow(c, HULL_FULLNESS);
}

/* where station i of a skin lies along the hull: the outer skin spans stern to stem (0 .. 1);
 * the inner skin starts HULL_SKIN ahead of the stern (the transom's thickness) and ends at
 * HULL_INNER_END against the solid stem */
static double hull_station(int i, int inner) {
    double f = (double)i / (HULL_STATIONS - 1);
    return inner ? HULL_SKIN + (HULL_INNER_END - HULL_SKIN) * f : f;
}

/* point k of the section at station i of the outer skin (inner 0) or the inner (inner 1) */
static void hull_point(int i, int k, int inner, double p[3]) {
    double u = hull_station(i, inner), beam, keel, gun;
    hull_section(u, &beam, &keel, &gun);
    double inset = inner ? HULL_SKIN : 0.0;
    double phi = PI * k / (HULL_SECTION - 1);
    double c = cos(phi), s = sin(phi);
    double bw = beam - inset, kd = keel + inset;
    p[0] = -0.5 + u;
    p[2] = bw * (c < 0.0 ? -1.0 : 1.0) * pow(fabs(c), HULL_FULLNESS);
    p[1] = gun + (kd - gun) * s;
}

/* one grid of the hull's skins: HULL_STATIONS x HULL_SECTION vertices, smooth normals; the
 * outer skin faces out of the hull, the inner one into the boat */
static void hull_skin(mb *b, int inner) {
    int v0 = b->nv;
    uint32_t i0 = b->ni;
    for (int i = 0; i < HULL_STATIONS; i++)
        for (int k = 0; k < HULL_SECTION; k++) {
            double p[3];
            hull_point(i, k, inner, p);
            mb_vert(b, p, NULL, (double)i / (HULL_STATIONS - 1), (double)k / (HULL_SECTION - 1));
        }
    for (int i = 0; i + 1 < HULL_STATIONS; i++)
        for (int k = 0; k + 1 < HULL_SECTION; k++) {
            int a = v0 + i * HULL_SECTION + k, bb = a + HULL_SECTION, c = bb + 1, d = a + 1;
            if (!inner) {
                mb_tri(b, a, c, bb);
                mb_tri(b, a, d, c);
            } else {
                mb_tri(b, a, bb, c);
                mb_tri(b, a, c, d);
            }
        }
    mb_smooth(b, v0, i0);
}

/* a flat end of a skin at station i: the section from gunwale to gunwale, closed across the top,
 * fanned from a point on the centreline; toward -x at the stern (i = 0), +x at the bow, turned
 * the other way on the inner skin (its ends face into the boat) */
static void hull_end(mb *b, int i, int inner) {
    int v0 = b->nv;
    uint32_t i0 = b->ni;
    double p[3], top[3], bot[3];
    hull_point(i, 0, inner, top);
    hull_point(i, (HULL_SECTION - 1) / 2, inner, bot);
    p[0] = top[0];
    p[1] = 0.5 * (top[1] + bot[1]);
    p[2] = 0.0;
    int ctr = mb_vert(b, p, NULL, 0.5, 0.5);
    for (int k = 0; k < HULL_SECTION; k++) {
        hull_point(i, k, inner, p);
        mb_vert(b, p, NULL, (double)k / (HULL_SECTION - 1), 0.0);
    }
    /* the section runs from k = 0 (+z) down and up to k = last (-z): (ctr, k, k + 1) faces +x */
    int out_x = (i != 0) != (inner != 0);
    for (int k = 0; k < HULL_SECTION; k++) {
        int a = ctr + 1 + k, c = ctr + 1 + (k + 1) % HULL_SECTION;
        if (out_x) mb_tri(b, ctr, a, c);
        else mb_tri(b, ctr, c, a);
    }
    mb_smooth(b, v0, i0);
}

/* the gunwale loop of a skin, point j of 2 HULL_STATIONS: starboard (k = 0) from stern to bow,
 * then port (k = last) from bow back to stern */
static void hull_loop(int j, int inner, double p[3]) {
    if (j < HULL_STATIONS) hull_point(j, 0, inner, p);
    else hull_point(2 * HULL_STATIONS - 1 - j, HULL_SECTION - 1, inner, p);
}

/* the rim: a flat band around the top from the outer gunwale loop to the inner one, over the
 * gunwales, the breasthook at the bow and the transom's top */
static void hull_rim(mb *b) {
    for (int j = 0; j < 2 * HULL_STATIONS; j++) {
        int j1 = (j + 1) % (2 * HULL_STATIONS);
        double o0[3], o1[3], n0[3], n1[3];
        hull_loop(j, 0, o0);
        hull_loop(j1, 0, o1);
        hull_loop(j, 1, n0);
        hull_loop(j1, 1, n1);
        int v0 = b->nv;
        uint32_t i0 = b->ni;
        int a = mb_vert(b, o0, NULL, 0, 0), c = mb_vert(b, o1, NULL, 1, 0);
        int d = mb_vert(b, n1, NULL, 1, 1), e = mb_vert(b, n0, NULL, 0, 1);
        /* the loop runs clockwise seen from above (+z side toward +x first, y up), so the quad
         * o0, o1, n1, n0 faces up */
        mb_tri(b, a, c, d);
        mb_tri(b, a, d, e);
        mb_smooth(b, v0, i0);
    }
}

/* a rowing boat: a planked shell with sheer, transom stern and a solid stem, two thwarts. The
 * shell is one closed surface: the outer skin and its two flat ends, the rim, and the inner skin
 * and its two ends facing into the boat, so no view sees through it at the bow or the stern */
static void gen_hull(mb *b) {
    hull_skin(b, 0);
    hull_skin(b, 1);
    hull_end(b, 0, 0);
    hull_end(b, HULL_STATIONS - 1, 0);
    hull_end(b, 0, 1);
    hull_end(b, HULL_STATIONS - 1, 1);
    hull_rim(b);
    /* thwarts: boards across the inside, clear of the inner skin */
    static const double at[2] = {0.35, 0.62};
    for (int s = 0; s < 2; s++) {
        double beam, keel, gun;
        hull_section(at[s], &beam, &keel, &gun);
        double c[3] = {-0.5 + at[s], gun - 0.045, 0.0};
        double h[3] = {0.05, 0.008, 0.72 * (beam - HULL_SKIN)};
        mb_box(b, c, h);
    }
}

/* the lid over the hull's inside: the inner gunwale loop, triangulated across the beam station
 * by station, facing up. Not a solid: the main pass draws it into depth before the water so no
 * water is drawn inside the boat (gfx/geometry.c) */
static void gen_hull_cap(mb *b) {
    int v0 = b->nv;
    double up[3] = {0.0, 1.0, 0.0};
    for (int i = 0; i < HULL_STATIONS; i++)
        for (int k = 0; k < 2; k++) {
            double p[3];
            hull_point(i, k ? HULL_SECTION - 1 : 0, 1, p);
            mb_vert(b, p, up, (double)i / (HULL_STATIONS - 1), (double)k);
        }
    for (int i = 0; i + 1 < HULL_STATIONS; i++) {
        int s0 = v0 + 2 * i, p0 = s0 + 1, s1 = s0 + 2, p1 = s0 + 3;
        /* starboard is +z, the bow +x: (s0, s1, p1) turns counter-clockwise seen from above */
        mb_tri(b, s0, s1, p1);
        mb_tri(b, s0, p1, p0);
    }
}

ww_result ww_meshgen(ww_mesh_kind kind, ww_mesh_data *out, ww_error *err) {
    memset(out, 0, sizeof *out);
    mb b = {0};
    switch (kind) {
    case WW_MESH_BOX: gen_box(&b); break;
    case WW_MESH_SPHERE: gen_sphere(&b); break;
    case WW_MESH_STONE: gen_stone(&b); break;
    case WW_MESH_HULL: gen_hull(&b); break;
    case WW_MESH_FISH: gen_fish(&b); break;
    case WW_MESH_LURE: gen_lure(&b); break;
    case WW_MESH_CHEST: gen_chest(&b); break;
    case WW_MESH_GRID: gen_grid(&b); break;
    case WW_MESH_NONE:
    case WW_MESH_OBJ:
    default:
        if (kind == WW_MESHGEN_COLUMN) {
            gen_column(&b);
            break;
        }
        if (kind == WW_MESHGEN_DROP) {
            gen_drop(&b);
            break;
        }
        if ((int)kind >= WW_MESHGEN_FISH_SPECIES && (int)kind < WW_MESHGEN_FISH_SPECIES + 3) {
            gen_fish_species(&b, &FISH_PLANS[(int)kind - WW_MESHGEN_FISH_SPECIES]);
            break;
        }
        if (kind == WW_MESHGEN_HULL_CAP) {
            gen_hull_cap(&b);
            break;
        }
        WW_ASSERT(!"ww_meshgen: not a procedural mesh kind");
        return ww_error_set(err, WW_E_INCONSISTENT, NULL, 0, 0, "meshgen: mesh kind %d is not "
                            "procedural", (int)kind);
    }
    if (b.oom) {
        free(b.v);
        free(b.ix);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "meshgen: out of memory");
    }
    out->nvert = b.nv;
    out->vertex = b.v;
    out->nindex = b.ni;
    out->index = b.ix;
    for (int k = 0; k < 3; k++) {
        out->min[k] = INFINITY;
        out->max[k] = -INFINITY;
    }
    for (int i = 0; i < b.nv; i++)
        for (int k = 0; k < 3; k++) {
            double x = b.v[8 * i + k];
            if (x < out->min[k]) out->min[k] = x;
            if (x > out->max[k]) out->max[k] = x;
        }
    return WW_OK;
}

void ww_meshgen_free(ww_mesh_data *m) {
    if (!m) return;
    free(m->vertex);
    free(m->index);
    memset(m, 0, sizeof *m);
}

typedef struct weld_edge {
    long long a[3], b[3]; /* from and to, positions in units of WW_MESHGEN_WELD */
} weld_edge;

static void weld(const float *p, long long q[3]) {
    for (int k = 0; k < 3; k++) q[k] = llround((double)p[k] / WW_MESHGEN_WELD);
}

static int cmp_weld_edge(const void *x, const void *y) {
    const weld_edge *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a->a[k] != b->a[k]) return a->a[k] < b->a[k] ? -1 : 1;
    for (int k = 0; k < 3; k++)
        if (a->b[k] != b->b[k]) return a->b[k] < b->b[k] ? -1 : 1;
    return 0;
}

/* the edges and the same edges reversed, each sorted: in a closed, consistently wound mesh the
 * two lists are equal and no edge runs twice the same way */
long ww_meshgen_open_edges(const ww_mesh_data *m) {
    size_t n = m->nindex;
    weld_edge *e = malloc((n ? n : 1) * sizeof *e), *r = malloc((n ? n : 1) * sizeof *r);
    if (!e || !r) {
        free(e);
        free(r);
        return -1;
    }
    size_t k = 0;
    for (uint32_t t = 0; t + 2 < m->nindex; t += 3)
        for (uint32_t s = 0; s < 3; s++) {
            const float *p = m->vertex + 8 * m->index[t + s];
            const float *q = m->vertex + 8 * m->index[t + (s + 1) % 3];
            weld(p, e[k].a);
            weld(q, e[k].b);
            weld(q, r[k].a);
            weld(p, r[k].b);
            k++;
        }
    qsort(e, k, sizeof *e, cmp_weld_edge);
    qsort(r, k, sizeof *r, cmp_weld_edge);
    long open = 0;
    for (size_t i = 0; i < k; i++) {
        if (cmp_weld_edge(&e[i], &r[i]) != 0) open++;
        if (i + 1 < k && cmp_weld_edge(&e[i], &e[i + 1]) == 0) open++; /* twice the same way */
    }
    free(e);
    free(r);
    return open;
}

double ww_meshgen_volume(const ww_mesh_data *m) {
    double v = 0.0;
    for (uint32_t t = 0; t + 2 < m->nindex; t += 3) {
        const float *a = m->vertex + 8 * m->index[t], *b = m->vertex + 8 * m->index[t + 1],
                    *c = m->vertex + 8 * m->index[t + 2];
        double cx = (double)b[1] * c[2] - (double)b[2] * c[1];
        double cy = (double)b[2] * c[0] - (double)b[0] * c[2];
        double cz = (double)b[0] * c[1] - (double)b[1] * c[0];
        v += (double)a[0] * cx + (double)a[1] * cy + (double)a[2] * cz;
    }
    return v / 6.0;
}
