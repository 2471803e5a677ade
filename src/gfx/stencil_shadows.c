/* stencil_shadows.c - seed 003's two stencilled sun shadows (render.shadows projected | volumes |
 * volumes_visible), drawn by the prepass and the main pass after their opaque geometry:
 *
 *   projected  the casters (the scene's solids) flattened onto the seabed plane along the sun by
 *              Blinn's shadow matrix ("Me and My (Fake) Shadow", IEEE CG&A 1988) mark the stencil
 *              with REPLACE 1 where they land on the visible seabed, so two overlapping shadows
 *              mark a pixel once and never darken it twice;
 *   volumes    stencil shadow volumes (Crow, "Shadow Algorithms for Computer Graphics", SIGGRAPH
 *              1977): each caster's silhouette edges, found per frame in its model space from an
 *              edge adjacency built once per mesh, extruded away from the sun to infinity (w = 0)
 *              or to a far cap under the seabed. A volume that may hold the eye is counted
 *              depth-fail ("Carmack's reverse"; Everitt and Kilgard, "Practical and Robust
 *              Stenciled Shadow Volumes for Hardware-Accelerated Rendering", 2002), closed by a
 *              cap on the caster's faces turned from the sun and the far cap; GL_DEPTH_CLAMP keeps
 *              the near and far planes from cutting it, so the count stays right with the camera
 *              inside. A closed, rigid, opaque caster's volume that cannot hold the eye is
 *              counted depth-pass with its sides alone (the caster's own surface, drawn whole,
 *              stands where its near cap would): fewer triangles, and no light let through
 *              under a caster sunk into the seabed, which depth-fail's caps there did. Which
 *              one is decided per caster and frame from its box (counts_depth_pass).
 *
 * Both follow the sunlight as it bends at the water (Snell): under the water it comes down the
 * refracted ray, steeper than the sun's ray in air. The projected casters are flattened along
 * the refracted ray, those above the water first moved to where their bent ray lands
 * (shadow.glsl's ww_shadow_unbend); a volume's side runs down the sun's ray to the surface and
 * then down the refracted ray to infinity, and a face above the water faces the sun while one
 * below it faces the refracted light. The shadow map bends alike (shadow.glsl's ww_shadow_warp),
 * so the three techniques agree 10 m down, where the sun's ray in air put a shadow 2 m out.
 *
 * Then the marked pixels are drawn again over themselves (depth EQUAL, the same program and
 * vertices) without the sun's direct light: the ambient, the lamps, the emission and the fog
 * stay as they were, so a fogged seabed far off barely changes. volumes_visible draws the
 * volumes themselves translucent over the main pass and the prepass too (from above the water
 * they are seen through it).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/render_impl.h"

#define PLANE_LIFT 0.02f       /* m: the projected shadow lies this far above the seabed */
#define PLANE_OFFSET_FACTOR -1.0f /* and is pulled toward the eye by this polygon offset */
#define PLANE_OFFSET_UNITS -4.0f
#define SUN_MIN_Y 0.02         /* below this sun height (sin of elevation) nothing is cast */
#define MAX_MESHES 64          /* adjacencies kept (procedural slots and OBJ models) */
/* m: each volume starts this far beyond its caster, away from the sun (along the light that
 * reaches the corner). On the cap, the faces
 * turned from the sun, the count is otherwise a coin toss (the cap and the face have one depth,
 * computed twice), speckling them, and a smooth-shaded face there, whose normals still see the
 * sun near the terminator, went dark along its facets instead of fading as the map has it */
#define VOLUME_START 0.03
/* m: with a seabed, the volumes end this far under it (closed there by a far cap) instead of at
 * infinity. Every receiver lies on or above the seabed, so the count under each pixel is the
 * same; but a side no longer runs to the vanishing point of the light's direction, and llvmpipe
 * no longer fills the whole screen between each silhouette edge and that point: in the reef's
 * wreck view the volumes' fill was 140 of a 540 CPU ms main pass */
#define VOLUME_BOTTOM_MARGIN 0.5
/* m: the sphere around the eye that must lie outside a volume counted depth-pass reaches this
 * far past the near plane's corners (float rounding of the volumes' corners) */
#define EYE_MARGIN 0.05
/* volumes_visible: the volume's faces, premultiplied HDR colour and cover (seed 003's "show the
 * shadow volume": a violet glass) */
static const float VOLUME_TINT[4] = {0.05f, 0.03f, 0.12f, 0.12f};

/* one caster mesh's adjacency: positions welded, each triangle's welded corners and model-space
 * normal, each edge's two triangles (the second -1 on an open edge) */
typedef struct edge {
    int v0, v1;   /* welded corners, in the order triangle t0 runs along the edge */
    int t0, t1;
} edge;

typedef struct adjacency {
    const ww_mesh_data *mesh; /* key */
    int nvert, ntri, nedge;
    int closed;               /* every edge has its two triangles */
    float *pos;               /* welded positions, 3 per vertex */
    int *tri;                 /* 3 welded corners per triangle */
    float *normal;            /* 3 per triangle, unnormalised (b - a) x (c - a) */
    float *centre;            /* 3 per triangle, the mean of its corners */
    edge *edges;
    float lo[3], hi[3];       /* the box of its positions, model space */
    int blended;              /* a part of it is drawn blended, without depth */
} adjacency;

/* a list of volume triangles, camera-relative, 4 floats per corner */
typedef struct vlist {
    float *v;
    size_t n, cap;
} vlist;

/* a volume is counted depth-fail, with both caps (right wherever the eye is), or depth-pass,
 * with its sides alone, where the eye lies outside it (a third of the triangles, less fill). The
 * vertex buffer holds, in this order, the depth-pass volumes' sides, their caps (volumes_visible
 * shows them; nothing counts them) and the depth-fail volumes */
enum { LIST_PASS = 0, LIST_PASS_CAPS, LIST_FAIL, LIST_COUNT };

struct ww_stencil_shadows {
    ww_shadow_technique technique;
    GLuint prog, vao, vbo;
    GLint view_proj, tint, clip;
    int nmesh;
    adjacency mesh[MAX_MESHES];
    vlist list[LIST_COUNT]; /* this frame's volumes, by how they are counted */
    size_t first[LIST_COUNT]; /* where each list starts in the vertex buffer, corners */
    vlist *cur;        /* the list put4 writes to */
    int pass_ok;       /* volumes may be counted depth-pass (WW_SHADOW_DEPTH_FAIL unset) */
    int show;          /* volumes_visible: the volumes are drawn, caps and all */
    int eye_above;     /* the camera is above the water's rest level, where the volumes bend */
    int cut;           /* the prepass draws the volumes, over solids cut at the surface */
    float eye_r;       /* m: a sphere around the eye that holds the near plane's corners */
    float crest;       /* m: the highest the surface rises above its rest level */
    int64_t built; /* frame whose volumes are in vbo; -1 none */
    double sun[3]; /* toward the sun, world, unit: the direction they were built for */
    double under[3]; /* toward the sun under the water (refracted), world, unit */
    float level;   /* the water's rest level, camera-relative y, this frame */
    int finite;    /* the volumes end at `bottom` (a seabed), else at infinity */
    float bottom;  /* camera-relative y they end at */
    int lost;      /* out of memory building a volume: casters left out */
    unsigned char *dark; /* scratch: each face of the caster being built turned from the light */
    int dark_cap;
    float *corners;      /* scratch: its welded corners' three points each (corner_points) */
    int corner_cap;
};

/* ---- adjacency, once per mesh ---- */

typedef struct weld_key {
    float p[3];
    int index;
} weld_key;

static int weld_cmp(const void *a, const void *b) {
    const weld_key *p = a, *q = b;
    for (int i = 0; i < 3; i++)
        if (p->p[i] != q->p[i]) return p->p[i] < q->p[i] ? -1 : 1;
    return p->index - q->index;
}

typedef struct half_edge {
    int lo, hi; /* welded corners, sorted */
    int tri;
    int forward; /* the triangle runs lo -> hi */
} half_edge;

static int half_cmp(const void *a, const void *b) {
    const half_edge *p = a, *q = b;
    if (p->lo != q->lo) return p->lo - q->lo;
    if (p->hi != q->hi) return p->hi - q->hi;
    return p->tri - q->tri;
}

static void adjacency_free(adjacency *a) {
    free(a->pos);
    free(a->tri);
    free(a->normal);
    free(a->centre);
    free(a->edges);
    memset(a, 0, sizeof *a);
}

/* weld by exact position (meshes split vertices for normals and uvs), then pair the half edges:
 * two triangles sharing an edge in opposite directions are neighbours; an edge with one
 * triangle, or with more than two, is left open (each triangle's side of it stands alone) */
static int adjacency_build(const ww_mesh_data *m, adjacency *a) {
    memset(a, 0, sizeof *a);
    a->mesh = m;
    int nv = m->nvert, nt = (int)(m->nindex / 3);
    weld_key *keys = malloc((size_t)nv * sizeof *keys);
    int *remap = malloc((size_t)nv * sizeof *remap);
    half_edge *he = malloc((size_t)nt * 3 * sizeof *he);
    a->pos = malloc((size_t)nv * 3 * sizeof *a->pos);
    a->tri = malloc((size_t)nt * 3 * sizeof *a->tri);
    a->normal = malloc((size_t)nt * 3 * sizeof *a->normal);
    a->centre = malloc((size_t)nt * 3 * sizeof *a->centre);
    a->edges = malloc((size_t)nt * 3 * sizeof *a->edges);
    int ok = keys && remap && he && a->pos && a->tri && a->normal && a->centre && a->edges;
    if (ok) {
        for (int i = 0; i < nv; i++) {
            memcpy(keys[i].p, m->vertex + 8 * i, sizeof keys[i].p);
            keys[i].index = i;
        }
        qsort(keys, (size_t)nv, sizeof *keys, weld_cmp);
        for (int i = 0; i < nv; i++) {
            if (i == 0 || memcmp(keys[i].p, keys[i - 1].p, sizeof keys[i].p) != 0) {
                memcpy(a->pos + 3 * a->nvert, keys[i].p, sizeof keys[i].p);
                a->nvert++;
            }
            remap[keys[i].index] = a->nvert - 1;
        }
        for (int t = 0; t < nt; t++) {
            int *c = a->tri + 3 * t;
            for (int k = 0; k < 3; k++) c[k] = remap[m->index[3 * t + k]];
            const float *p0 = a->pos + 3 * c[0], *p1 = a->pos + 3 * c[1], *p2 = a->pos + 3 * c[2];
            float u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
            float v[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
            float *n = a->normal + 3 * t;
            n[0] = u[1] * v[2] - u[2] * v[1];
            n[1] = u[2] * v[0] - u[0] * v[2];
            n[2] = u[0] * v[1] - u[1] * v[0];
            float *ce = a->centre + 3 * t;
            ce[0] = ce[1] = ce[2] = 0.0f;
            for (int k = 0; k < 3; k++)
                for (int r = 0; r < 3; r++) ce[r] += a->pos[3 * c[k] + r] / 3.0f;
            for (int k = 0; k < 3; k++) {
                int x = c[k], y = c[(k + 1) % 3];
                he[3 * t + k] = (half_edge){x < y ? x : y, x < y ? y : x, t, x < y};
            }
        }
        a->ntri = nt;
        qsort(he, (size_t)nt * 3, sizeof *he, half_cmp);
        for (int i = 0; i < nt * 3;) {
            int j = i + 1;
            while (j < nt * 3 && he[j].lo == he[i].lo && he[j].hi == he[i].hi) j++;
            int paired = j - i == 2 && he[i].forward != he[i + 1].forward;
            for (int k = i; k < j; k++) {
                if (he[k].lo == he[k].hi) continue; /* degenerate triangle */
                edge e = {he[k].forward ? he[k].lo : he[k].hi, he[k].forward ? he[k].hi : he[k].lo,
                          he[k].tri, paired ? he[i + (k == i)].tri : -1};
                if (paired && k == i + 1) break; /* one record per shared edge */
                a->edges[a->nedge++] = e;
            }
            i = j;
        }
        a->closed = 1;
        for (int e = 0; e < a->nedge; e++)
            if (a->edges[e].t1 < 0) a->closed = 0;
        for (int r = 0; r < 3; r++) {
            a->lo[r] = a->nvert ? a->pos[r] : 0.0f;
            a->hi[r] = a->lo[r];
        }
        for (int v = 1; v < a->nvert; v++)
            for (int r = 0; r < 3; r++) {
                float x = a->pos[3 * v + r];
                if (x < a->lo[r]) a->lo[r] = x;
                if (x > a->hi[r]) a->hi[r] = x;
            }
        for (int k = 0; k < m->nsub; k++) {
            int mi = m->sub[k].material;
            if (mi >= 0 && mi < m->nmaterial && m->material[mi].opacity < 1.0f) a->blended = 1;
        }
    }
    free(keys);
    free(remap);
    free(he);
    if (!ok) adjacency_free(a);
    return ok;
}

static adjacency *adjacency_of(ww_stencil_shadows *s, const ww_mesh_data *m) {
    for (int i = 0; i < s->nmesh; i++)
        if (s->mesh[i].mesh == m) return &s->mesh[i];
    if (s->nmesh >= MAX_MESHES || !adjacency_build(m, &s->mesh[s->nmesh])) return NULL;
    return &s->mesh[s->nmesh++];
}

/* ---- volumes, per frame ---- */

static int reserve(vlist *l, size_t more) {
    if (l->n + more <= l->cap) return 1;
    size_t cap = l->cap ? l->cap : 4096;
    while (cap < l->n + more) cap *= 2;
    float *v = realloc(l->v, cap * 4 * sizeof *v);
    if (!v) return 0;
    l->v = v;
    l->cap = cap;
    return 1;
}

static void put4(ww_stencil_shadows *s, const float p[4]) {
    vlist *l = s->cur;
    memcpy(l->v + 4 * l->n++, p, 4 * sizeof *p);
}

/* a face turned from the sun (model space; side -1 under a mirroring matrix) */
static int is_dark(const adjacency *a, int t, const vec3 Lm, float side) {
    const float *n = a->normal + 3 * t;
    return side * (n[0] * Lm[0] + n[1] * Lm[1] + n[2] * Lm[2]) < 0.0f;
}

/* the same against the light that reaches the face: the sun's (Lm) above the water, the
 * refracted (Um) below it, by the height of its centre (camera-relative) */
static int face_dark(const ww_stencil_shadows *s, const adjacency *a, int t, const float model[16],
                     const vec3 Lm, const vec3 Um, float side) {
    const float *c = a->centre + 3 * t;
    float y = model[1] * c[0] + model[5] * c[1] + model[9] * c[2] + model[13];
    return is_dark(a, t, y < s->level ? Um : Lm, side);
}

/* welded corner v in camera-relative world, moved VOLUME_START away from the sun along the
 * light that reaches it (refracted under the water) */
static void corner(const ww_stencil_shadows *s, const adjacency *a, int v, const float model[16],
                   float w[4]) {
    const float *p = a->pos + 3 * v;
    for (int r = 0; r < 3; r++)
        w[r] = model[r] * p[0] + model[4 + r] * p[1] + model[8 + r] * p[2] + model[12 + r];
    const double *l = w[1] < s->level ? s->under : s->sun;
    for (int r = 0; r < 3; r++) w[r] -= (float)(VOLUME_START * l[r]);
    w[3] = 1.0f;
}

/* where the sun's ray through w (above the water) meets the surface; w itself under it */
static void to_surface(const ww_stencil_shadows *s, const float w[4], float out[4]) {
    memcpy(out, w, 4 * sizeof *out);
    if (w[1] <= s->level) return;
    float k = (w[1] - s->level) / (float)s->sun[1];
    for (int r = 0; r < 3; r++) out[r] = w[r] - k * (float)s->sun[r];
    out[1] = s->level;
}

/* where the refracted ray from w (at or under the surface) meets the volumes' bottom; w itself
 * when it lies under it already */
static void to_bottom(const ww_stencil_shadows *s, const float w[4], float out[4]) {
    memcpy(out, w, 4 * sizeof *out);
    if (w[1] <= s->bottom) return;
    float k = (w[1] - s->bottom) / (float)s->under[1];
    for (int r = 0; r < 3; r++) out[r] = w[r] - k * (float)s->under[r];
    out[1] = s->bottom;
}

/* room for a caster of n faces and v welded corners in the scratch arrays */
static int reserve_scratch(ww_stencil_shadows *s, int n, int v) {
    if (n > s->dark_cap) {
        unsigned char *d = realloc(s->dark, (size_t)n);
        if (!d) return 0;
        s->dark = d;
        s->dark_cap = n;
    }
    if (v > s->corner_cap) {
        float *c = realloc(s->corners, (size_t)v * 12 * sizeof *c);
        if (!c) return 0;
        s->corners = c;
        s->corner_cap = v;
    }
    return 1;
}

/* the three points every volume takes from welded corner v: the corner itself (near cap), where
 * the sun's ray from it meets the surface, and where the refracted ray from there meets the
 * bottom (far cap); 12 floats */
static void corner_points(const ww_stencil_shadows *s, const adjacency *a, int v,
                          const float model[16], float out[12]) {
    corner(s, a, v, model, out);
    to_surface(s, out, out + 4);
    to_bottom(s, out + 4, out + 8);
}

/* the side of edge p -> q (reversed when `flip`) along the sunlight: above the water down the
 * sun's ray to the surface, then (and under the water from the start) down the refracted ray to
 * the bottom, or to the point at infinity */
static void put_side(ww_stencil_shadows *s, int p, int q, int flip, const float inf[4]) {
    const float *c0 = s->corners + 12 * (flip ? q : p), *c1 = s->corners + 12 * (flip ? p : q);
    const float *w0 = c0, *w1 = c1, *s0 = c0 + 4, *s1 = c1 + 4, *b0 = c0 + 8, *b1 = c1 + 8;
    if (w0[1] > s->level || w1[1] > s->level) { /* the stretch in the air, as two triangles */
        put4(s, w0);
        put4(s, w1);
        put4(s, s1);
        put4(s, w0);
        put4(s, s1);
        put4(s, s0);
    }
    if (!s->finite) {
        put4(s, s0);
        put4(s, s1);
        put4(s, inf);
        return;
    }
    put4(s, s0);
    put4(s, s1);
    put4(s, b1);
    put4(s, s0);
    put4(s, b1);
    put4(s, b0);
}


/* does o + t d, t0 <= t <= t1, meet the box [lo, hi]? (Kay and Kajiya's slabs) */
static int segment_meets_box(const double o[3], const double d[3], double t0, double t1,
                             const float lo[3], const float hi[3]) {
    for (int r = 0; r < 3; r++) {
        if (fabs(d[r]) < 1e-12) {
            if (o[r] < lo[r] || o[r] > hi[r]) return 0;
            continue;
        }
        double a = (lo[r] - o[r]) / d[r], b = (hi[r] - o[r]) / d[r];
        if (a > b) {
            double x = a;
            a = b;
            b = x;
        }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        if (t0 > t1) return 0;
    }
    return 1;
}

/* may the eye (the camera-relative origin) lie in a volume cast by what lies in the box [lo, hi]?
 * A point is in the volume when the sunlight reaching it passed through the caster: traced back
 * from the eye toward the sun, up the refracted ray to the surface (from under the water) and
 * then up the sun's ray, the path meets the caster's box. The box is widened by the sphere
 * around the eye and the volume's start, and by half again for how a point off the path bends
 * elsewhere at the surface (at most tan 48.6 deg, the critical angle, per metre of height) */
static int eye_in_column(const ww_stencil_shadows *s, const float lo[3], const float hi[3]) {
    float grow = 1.5f * (s->eye_r + (float)VOLUME_START), wlo[3], whi[3];
    for (int r = 0; r < 3; r++) {
        wlo[r] = lo[r] - grow;
        whi[r] = hi[r] + grow;
    }
    double o[3] = {0.0, 0.0, 0.0};
    if (s->eye_above) return segment_meets_box(o, s->sun, 0.0, INFINITY, wlo, whi);
    double t = s->level / s->under[1];
    if (segment_meets_box(o, s->under, 0.0, t, wlo, whi)) return 1;
    double b[3] = {t * s->under[0], s->level, t * s->under[2]};
    return segment_meets_box(b, s->sun, 0.0, INFINITY, wlo, whi);
}

/* may this caster's volume be counted depth-pass, with its sides alone? That count is right
 * when nothing between the eye and a receiver lies inside the volume unseen: the eye outside it
 * (its near plane too: the caster is not clipped), and the caster's surface, which closes the
 * volume where the caps would, drawn whole into depth as the volume was built from it: closed,
 * not blended, not bent by the vertex shader (a swimming fish), and (from above the water) not
 * cut by the prepass, which cuts what reaches the band the surface moves in. An open mesh,
 * whose every face casts, stays depth-fail: counted depth-pass the reef's coral branches went
 * darker on their sunlit sides than depth-fail and the shadow map draw them */
static int counts_depth_pass(const ww_stencil_shadows *s, const adjacency *a,
                             const float model[16], int rigid) {
    if (!s->pass_ok || !a->closed || a->blended || !rigid) return 0;
    float lo[3], hi[3]; /* the box of a's positions through the instance's matrix */
    for (int r = 0; r < 3; r++) ww_gfx_box_row(model, r, a->lo, a->hi, &lo[r], &hi[r]);
    if (s->cut && hi[1] >= s->level - s->crest) return 0;
    return !eye_in_column(s, lo, hi);
}

/* one caster instance's volume: the faces turned from the sun (model space: n . L_m < 0, with
 * L_m = A^-1 L, since n_world . L = n . A^-1 L for n_world = A^-T n) are the near cap, wound
 * to face the sun; each edge between such a face and a face toward the sun (or none) is a
 * silhouette edge, a triangle out to the point at infinity away from the sun. A mesh with open
 * edges (a sheet, a leaf) may show the sun either side: each of its faces casts, a lit one
 * turned over, so a sheet facing the sun casts as one facing away does (the count is then the
 * number of faces above a point, never 0 in a shadow) */
static void add_caster(void *user, int mesh_id, const ww_mesh_data *m, const float model[16],
                       int rigid) {
    (void)mesh_id;
    ww_stencil_shadows *s = user;
    adjacency *a = adjacency_of(s, m);
    if (!a) {
        s->lost = 1;
        return;
    }
    mat3 A, Ai;
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++) A[c][r] = model[c * 4 + r];
    float det = glm_mat3_det(A);
    if (fabsf(det) < 1e-12f) return;
    glm_mat3_inv(A, Ai);
    /* a face above the water is lit along the sun's ray, one under it along the refracted ray */
    vec3 L = {(float)s->sun[0], (float)s->sun[1], (float)s->sun[2]}, Lm;
    vec3 U = {(float)s->under[0], (float)s->under[1], (float)s->under[2]}, Um;
    glm_mat3_mulv(Ai, L, Lm);
    glm_mat3_mulv(Ai, U, Um);
    float side = det > 0.0f ? 1.0f : -1.0f; /* a mirroring matrix turns the windings */
    int pass = counts_depth_pass(s, a, model, rigid);
    vlist *sides = &s->list[pass ? LIST_PASS : LIST_FAIL];
    vlist *caps = !pass ? sides : s->show ? &s->list[LIST_PASS_CAPS] : NULL;
    /* two cap corners per face (near and far), and per edge up to two sides of twelve corners */
    size_t ncap = (size_t)a->ntri * 6, nside = (size_t)a->nedge * 24;
    int room = caps == sides ? reserve(sides, ncap + nside)
                             : (!caps || reserve(caps, ncap)) && reserve(sides, nside);
    if (!room) {
        s->lost = 1;
        return;
    }
    if (!reserve_scratch(s, a->ntri, a->nvert)) {
        s->lost = 1;
        return;
    }
    for (int v = 0; v < a->nvert; v++) corner_points(s, a, v, model, s->corners + 12 * v);
    /* which faces are turned from the light: once each, read by the caps and by the three edges
     * each face has */
    unsigned char *dk = s->dark;
    for (int t = 0; t < a->ntri; t++) dk[t] = (unsigned char)face_dark(s, a, t, model, Lm, Um, side);
    float inf[4] = {-U[0], -U[1], -U[2], 0.0f};
    s->cur = caps;
    for (int t = 0; caps && t < a->ntri; t++) {
        int dark = dk[t];
        if (!dark && a->closed) continue;
        /* the cap faces the sun: a dark face reversed, an open mesh's lit face as it is (and a
         * mirroring matrix has reversed both already) */
        static const int order[2][3] = {{0, 2, 1}, {0, 1, 2}};
        const int *o = order[!dark != (side < 0.0f)];
        for (int k = 0; k < 3; k++) put4(s, s->corners + 12 * a->tri[3 * t + o[k]]);
        /* the far cap, turned the other way, where the sides end: the corners carried as the
         * sides carry them */
        for (int k = 2; s->finite && k >= 0; k--) put4(s, s->corners + 12 * a->tri[3 * t + o[k]] + 8);
    }
    s->cur = sides;
    for (int e = 0; e < a->nedge; e++) {
        const edge *ed = &a->edges[e];
        int dark0 = dk[ed->t0];
        if (ed->t1 < 0) {
            /* an open edge: its face's side (turned away from the sun when it is lit) */
            if (dark0 || !a->closed)
                put_side(s, ed->v0, ed->v1, !dark0 != (side < 0.0f), inf);
            continue;
        }
        int dark1 = dk[ed->t1];
        if (dark0 == dark1) continue; /* not on the silhouette */
        /* the side runs along the edge as the dark face does (v0 -> v1 in t0, v1 -> v0 in t1);
         * an open mesh's lit face, turned away from the sun, gives a side of its own too */
        if (dark0 || !a->closed)
            put_side(s, ed->v0, ed->v1, !dark0 != (side < 0.0f), inf);
        if (dark1 || !a->closed)
            put_side(s, ed->v1, ed->v0, !dark1 != (side < 0.0f), inf);
    }
}

/* this frame's volumes into the vertex buffer (once per frame, whichever pass draws first) */
static void build_volumes(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f) {
    if (s->built == f->frame) return;
    s->built = f->frame;
    for (int l = 0; l < LIST_COUNT; l++) s->list[l].n = 0;
    for (int i = 0; i < 3; i++) s->sun[i] = f->st->sun_dir[i];
    ww_m_normalize3(s->sun);
    ww_sun_in_water(s->sun, s->under);
    s->level = (float)(f->sc->water_level - f->cam_pos[1]);
    s->finite = f->sc->render.seabed;
    s->bottom = (float)(f->sc->water_level - f->sc->water_depth - VOLUME_BOTTOM_MARGIN -
                        f->cam_pos[1]);
    s->eye_above = s->level <= 0.0f;
    s->cut = !f->underwater;
    const double *t = f->tan_half;
    s->eye_r = (float)(f->sc->near_clip * sqrt(1.0 + t[0] * t[0] + t[1] * t[1]) + EYE_MARGIN);
    ww_geometry_each_caster(r->geometry, add_caster, s);
    const ww_gl *gl = r->gl;
    size_t corner = 4 * sizeof(float), total = 0;
    for (int l = 0; l < LIST_COUNT; l++) {
        s->first[l] = total;
        total += s->list[l].n;
    }
    gl->BindBuffer(GL_ARRAY_BUFFER, s->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(total * corner), NULL, GL_STREAM_DRAW);
    for (int l = 0; l < LIST_COUNT; l++)
        if (s->list[l].n)
            gl->BufferSubData(GL_ARRAY_BUFFER, (GLintptr)(s->first[l] * corner),
                              (GLsizeiptr)(s->list[l].n * corner), s->list[l].v);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
}

static void draw_volumes(const ww_stencil_shadows *s, const ww_gl *gl, mat4 view_proj,
                         const float *clip, size_t first, size_t count) {
    if (count == 0) return;
    gl->UseProgram(s->prog);
    gl->UniformMatrix4fv(s->view_proj, 1, GL_FALSE, (const GLfloat *)view_proj);
    if (clip) {
        gl->Enable(GL_CLIP_DISTANCE0);
        gl->Uniform4f(s->clip, clip[0], clip[1], clip[2], clip[3]);
    } else {
        gl->Uniform4f(s->clip, 0.0f, 0.0f, 0.0f, 1.0f);
    }
    gl->BindVertexArray(s->vao);
    gl->DrawArrays(GL_TRIANGLES, (GLint)first, (GLsizei)count);
    gl->BindVertexArray(0);
    gl->Disable(GL_CLIP_DISTANCE0);
}

/* ---- the passes' side ---- */

ww_result ww_stencil_shadows_new(ww_renderer *r, const ww_scene *sc, ww_stencil_shadows **out,
                                 ww_error *err) {
    const ww_gl *gl = r->gl;
    ww_stencil_shadows *s = calloc(1, sizeof *s);
    if (!s) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "stencil shadows: out of memory");
    s->technique = sc->render.shadows.technique;
    s->built = -1;
    /* WW_SHADOW_DEPTH_FAIL=1 counts every volume depth-fail, to compare */
    const char *fail = getenv("WW_SHADOW_DEPTH_FAIL");
    s->pass_ok = !(fail && strcmp(fail, "1") == 0);
    s->show = s->technique == WW_SHADOW_VOLUMES_VISIBLE;
    s->crest = (float)ww_water_crest(sc);
    if (s->technique != WW_SHADOW_PROJECTED) {
        ww_result rc = ww_gfx_program(gl, "shadow_volume.vert.glsl", "shadow_volume.frag.glsl",
                                      NULL, &s->prog, err);
        if (rc != WW_OK) {
            free(s);
            return rc;
        }
        s->view_proj = ww_gfx_uniform(gl, s->prog, "u_view_proj");
        s->tint = ww_gfx_uniform(gl, s->prog, "u_tint");
        s->clip = ww_gfx_uniform(gl, s->prog, "u_clip");
        gl->GenVertexArrays(1, &s->vao);
        gl->BindVertexArray(s->vao);
        gl->GenBuffers(1, &s->vbo);
        gl->BindBuffer(GL_ARRAY_BUFFER, s->vbo);
        gl->EnableVertexAttribArray(0);
        gl->VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), (void *)0);
        gl->BindVertexArray(0);
        gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    }
    *out = s;
    return WW_OK;
}

void ww_stencil_shadows_free(ww_stencil_shadows *s, const ww_gl *gl) {
    if (!s) return;
    if (s->prog) gl->DeleteProgram(s->prog);
    if (s->vao) gl->DeleteVertexArrays(1, &s->vao);
    if (s->vbo) gl->DeleteBuffers(1, &s->vbo);
    for (int i = 0; i < s->nmesh; i++) adjacency_free(&s->mesh[i]);
    for (int l = 0; l < LIST_COUNT; l++) free(s->list[l].v);
    free(s->dark);
    free(s->corners);
    free(s);
}

/* Blinn's shadow matrix onto the plane y = y0 (camera-relative) along the sun L (w = 0):
 * S = (P . L) I - L P^T with P = (0, 1, 0, -y0); S x = x - L (y - y0) / L.y, on the plane */
static void shadow_matrix(const double L[3], float y0, mat4 S) {
    float l[4] = {(float)L[0], (float)L[1], (float)L[2], 0.0f}, P[4] = {0.0f, 1.0f, 0.0f, -y0};
    float d = l[1];
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) S[c][r] = (r == c ? d : 0.0f) - l[r] * P[c];
}

/* mark the stencil (1 in a shadow, 0 out) over what the pass has drawn */
static void mark_projected(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f,
                           mat4 view_proj) {
    (void)s;
    const ww_gl *gl = r->gl;
    mat4 S, vps;
    float y0 = (float)(f->sc->water_level - f->sc->water_depth - f->cam_pos[1]) + PLANE_LIFT;
    /* along the sunlight under the water; casters above it are first moved to where the bent
     * ray lands (shadow.glsl's ww_shadow_unbend, the geometry's mark stage) */
    double u[3];
    ww_sun_in_water(f->st->sun_dir, u);
    shadow_matrix(u, y0, S);
    glm_mat4_mul(view_proj, S, vps);
    gl->StencilFunc(GL_ALWAYS, 1, 0xFF);
    gl->StencilOpSeparate(GL_FRONT_AND_BACK, GL_KEEP, GL_KEEP, GL_REPLACE);
    gl->Enable(GL_POLYGON_OFFSET_FILL);
    gl->PolygonOffset(PLANE_OFFSET_FACTOR, PLANE_OFFSET_UNITS);
    ww_geometry_set_stage(r->geometry, WW_GEOM_STAGE_MARK);
    ww_geometry_draw_parts(r->geometry, r, f, WW_GEOM_SHADOW, vps, NULL, WW_GEOM_PART_SOLIDS);
    ww_geometry_set_stage(r->geometry, WW_GEOM_STAGE_NORMAL);
    gl->Disable(GL_POLYGON_OFFSET_FILL);
}

static void mark_volumes(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f,
                         mat4 view_proj) {
    const ww_gl *gl = r->gl;
    build_volumes(s, r, f);
    gl->StencilFunc(GL_ALWAYS, 0, 0xFF);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_FALSE);
    gl->Disable(GL_CULL_FACE);
    gl->Enable(GL_DEPTH_CLAMP);
    /* depth-pass: a side in front of what is drawn counts +1 entering (front), -1 leaving */
    gl->StencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    gl->StencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    draw_volumes(s, gl, view_proj, NULL, s->first[LIST_PASS], s->list[LIST_PASS].n);
    /* depth-fail: a volume face behind what is drawn counts +1 leaving (back), -1 entering */
    gl->StencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    gl->StencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    draw_volumes(s, gl, view_proj, NULL, s->first[LIST_FAIL], s->list[LIST_FAIL].n);
    gl->Disable(GL_DEPTH_CLAMP);
    gl->DepthMask(GL_TRUE);
}

void ww_stencil_shadows_apply(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f,
                              ww_geom_mode mode, mat4 view_proj, const float *clip) {
    if (!s || !r->geometry || !(f->st->sun_dir[1] > SUN_MIN_Y)) return;
    const ww_gl *gl = r->gl;
    gl->Enable(GL_STENCIL_TEST);
    gl->StencilMask(0xFF);
    gl->ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    if (s->technique == WW_SHADOW_PROJECTED) mark_projected(s, r, f, view_proj);
    else mark_volumes(s, r, f, view_proj);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* what is marked, drawn again without the sun: the projected shadows fall on the seabed
     * alone, the volumes' on everything */
    gl->StencilFunc(GL_NOTEQUAL, 0, 0xFF);
    gl->StencilOpSeparate(GL_FRONT_AND_BACK, GL_KEEP, GL_KEEP, GL_KEEP);
    gl->StencilMask(0x00);
    ww_geometry_set_stage(r->geometry, WW_GEOM_STAGE_SUNLESS);
    ww_geometry_draw_parts(r->geometry, r, f, mode, view_proj, clip,
                           s->technique == WW_SHADOW_PROJECTED ? WW_GEOM_PART_SEABED
                                                               : WW_GEOM_PART_ALL);
    ww_geometry_set_stage(r->geometry, WW_GEOM_STAGE_NORMAL);
    gl->StencilMask(0xFF);
    gl->Disable(GL_STENCIL_TEST);
}

void ww_stencil_shadows_draw_visible(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f,
                                     mat4 view_proj, const float *clip) {
    if (!s || s->technique != WW_SHADOW_VOLUMES_VISIBLE || !(f->st->sun_dir[1] > SUN_MIN_Y))
        return;
    const ww_gl *gl = r->gl;
    build_volumes(s, r, f);
    gl->UseProgram(s->prog);
    gl->Uniform4f(s->tint, VOLUME_TINT[0], VOLUME_TINT[1], VOLUME_TINT[2], VOLUME_TINT[3]);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_FALSE);
    gl->Disable(GL_CULL_FACE);
    gl->Enable(GL_DEPTH_CLAMP);
    gl->Enable(GL_BLEND);
    gl->BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); /* premultiplied */
    draw_volumes(s, gl, view_proj, clip, 0, s->first[LIST_FAIL] + s->list[LIST_FAIL].n);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_DEPTH_CLAMP);
    gl->DepthMask(GL_TRUE);
}
