/* test_picture_hull.c - picture defects around the boat and the water's optics, each measured on
 * the meshes or on a rendered frame: every procedural mesh closed and wound outward, the hull's
 * inside enclosed below its gunwale (no slit at the bow), no water drawn inside the hull in the
 * seat view, no submerged faces in the planar reflection, and no torn slivers where the
 * refraction samples what lies in front of the water.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/meshgen.h"
#include "io/writers.h"
#include "test.h"

#define WELD_QUANTUM 1e5 /* positions welded on a 1e-5 grid (mesh units) */
#define AREA_MIN 1e-12   /* a triangle of less twice-area (mesh units^2) is degenerate */

/* ---- meshes ---- */

typedef struct uedge {
    long long a[3], b[3]; /* welded end points, a < b */
    int fwd;              /* the triangle runs a -> b */
} uedge;

static int cmp_pt(const long long *a, const long long *b) {
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

static int cmp_uedge(const void *x, const void *y) {
    const uedge *a = x, *b = y;
    int c = cmp_pt(a->a, b->a);
    return c ? c : cmp_pt(a->b, b->b);
}

static void weld(const float *p, long long q[3]) {
    for (int k = 0; k < 3; k++) q[k] = llround((double)p[k] * WELD_QUANTUM);
}

/* undirected edges by welded position: how many are used by exactly one triangle (the
 * boundary), by more than two (non-manifold), and how many triangles are degenerate */
typedef struct edge_census {
    long boundary, nonmanifold, degenerate;
    long same_way; /* edges whose two triangles run it the same way (inconsistent winding) */
} edge_census;

static edge_census census(const ww_mesh_data *m) {
    edge_census c = {0, 0, 0, 0};
    uedge *e = malloc((size_t)m->nindex * sizeof *e);
    size_t n = 0;
    for (uint32_t t = 0; e && t + 2 < m->nindex; t += 3) {
        const float *v[3];
        for (int s = 0; s < 3; s++) v[s] = m->vertex + 8 * m->index[t + (uint32_t)s];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)v[1][k] - v[0][k];
            e2[k] = (double)v[2][k] - v[0][k];
        }
        double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2],
               z = e1[0] * e2[1] - e1[1] * e2[0];
        if (sqrt(x * x + y * y + z * z) < AREA_MIN) c.degenerate++;
        for (int s = 0; s < 3; s++) {
            long long p[3], q[3];
            weld(v[s], p);
            weld(v[(s + 1) % 3], q);
            int lt = cmp_pt(p, q) < 0;
            memcpy(e[n].a, lt ? p : q, sizeof p);
            memcpy(e[n].b, lt ? q : p, sizeof p);
            e[n].fwd = lt;
            n++;
        }
    }
    qsort(e, n, sizeof *e, cmp_uedge);
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && cmp_uedge(&e[i], &e[j]) == 0) j++;
        if (j - i == 1) c.boundary++;
        if (j - i > 2) c.nonmanifold++;
        if (j - i == 2 && e[i].fwd == e[i + 1].fwd) c.same_way++;
        i = j;
    }
    free(e);
    return c;
}

/* vertex normals that disagree with the winding of a triangle using them */
static long normals_against_winding(const ww_mesh_data *m) {
    long wrong = 0;
    for (uint32_t t = 0; t + 2 < m->nindex; t += 3) {
        const float *v[3];
        for (int s = 0; s < 3; s++) v[s] = m->vertex + 8 * m->index[t + (uint32_t)s];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)v[1][k] - v[0][k];
            e2[k] = (double)v[2][k] - v[0][k];
        }
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        for (int s = 0; s < 3; s++)
            if (n[0] * v[s][3] + n[1] * v[s][4] + n[2] * v[s][5] <= 0.0) wrong++;
    }
    return wrong;
}

/* every mesh kind meshgen makes; open: the surfaces that are not solids, with the number of
 * boundary edges they must have */
static const struct {
    ww_mesh_kind kind;
    const char *name;
    long open_edges; /* 0: a closed solid */
} KINDS[] = {
    {WW_MESH_BOX, "box", 0},
    {WW_MESH_SPHERE, "sphere", 0},
    {WW_MESH_STONE, "stone", 0},
    {WW_MESH_HULL, "hull", 0},
    {WW_MESH_FISH, "fish", 0},
    {WW_MESH_LURE, "lure", 0},
    {WW_MESH_CHEST, "chest", 0},
    {WW_MESHGEN_FISH_OF(WW_FISH_SLIM), "fish_slim", 0},
    {WW_MESHGEN_FISH_OF(WW_FISH_DEEP), "fish_deep", 0},
    {WW_MESHGEN_FISH_OF(WW_FISH_LONG), "fish_long", 0},
    /* a plane: its four sides */
    {WW_MESH_GRID, "grid", 4 * WW_MESHGEN_GRID},
    /* the glow column: a tube open at both ends (additive light, caps would double it) */
    {WW_MESHGEN_COLUMN, "column", 2 * WW_MESHGEN_SLICES},
    /* the hull's lid: only its rim, the inner gunwale loop */
    {WW_MESHGEN_HULL_CAP, "hull_cap", -1},
};

/* closed: every edge (after welding coincident positions) shared by exactly two triangles that
 * run it opposite ways, no degenerate triangle, positive signed volume, and vertex normals that
 * agree with the winding */
TEST(hull_meshgen_every_mesh_closed_and_outward) {
    for (size_t i = 0; i < sizeof KINDS / sizeof KINDS[0]; i++) {
        ww_mesh_data m;
        ww_error err = {0};
        ENSURE(ww_meshgen(KINDS[i].kind, &m, &err) == WW_OK);
        if (!m.nindex) continue;
        edge_census c = census(&m);
        long open = KINDS[i].open_edges;
        fprintf(stderr, "%s: %ld boundary, %ld non-manifold edges, %ld degenerate; volume %.6g\n",
                KINDS[i].name, c.boundary, c.nonmanifold, c.degenerate, ww_meshgen_volume(&m));
        if (open >= 0)
            ENSURE_MSG(c.boundary == open, "%s: %ld edges used by one triangle only (want %ld)",
                       KINDS[i].name, c.boundary, open);
        else
            ENSURE_MSG(c.boundary > 0, "%s: a lid with no rim", KINDS[i].name);
        ENSURE_MSG(c.nonmanifold == 0, "%s: %ld edges used by more than two triangles",
                   KINDS[i].name, c.nonmanifold);
        ENSURE_MSG(c.same_way == 0, "%s: %ld edges run the same way by both their triangles",
                   KINDS[i].name, c.same_way);
        ENSURE_MSG(c.degenerate == 0, "%s: %ld degenerate triangles", KINDS[i].name,
                   c.degenerate);
        ENSURE_MSG(normals_against_winding(&m) == 0, "%s: %ld vertex normals against the winding",
                   KINDS[i].name, normals_against_winding(&m));
        if (open == 0)
            ENSURE_MSG(ww_meshgen_volume(&m) > 0.0, "%s: signed volume %g is not positive",
                       KINDS[i].name, ww_meshgen_volume(&m));
        ww_meshgen_free(&m);
    }
}

/* a ray from o along d hits a triangle of m (Moller-Trumbore, both faces) */
static int ray_hits(const ww_mesh_data *m, const double o[3], const double d[3]) {
    for (uint32_t t = 0; t + 2 < m->nindex; t += 3) {
        const float *a = m->vertex + 8 * m->index[t], *b = m->vertex + 8 * m->index[t + 1],
                    *c = m->vertex + 8 * m->index[t + 2];
        double e1[3], e2[3], s[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)b[k] - a[k];
            e2[k] = (double)c[k] - a[k];
            s[k] = o[k] - a[k];
        }
        double p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
                       d[0] * e2[1] - d[1] * e2[0]};
        double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
        if (fabs(det) < 1e-15) continue;
        double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
        if (u < 0.0 || u > 1.0) continue;
        double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
                       s[0] * e1[1] - s[1] * e1[0]};
        double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        if ((e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det > 0.0) return 1;
    }
    return 0;
}

#define ENCLOSED_RAYS 360 /* horizontal directions from each point inside the boat */

/* the boat's inside is walled in below the gunwale: horizontal rays from points on the
 * centreline, from stern to bow, a little above the inner keel and below the lowest gunwale
 * (HULL_SHEER, 0.05, amidships), all hit the hull; a slit at the bow or an open transom lets
 * some out */
TEST(hull_meshgen_inside_walled_in) {
    ww_mesh_data m;
    ww_error err = {0};
    ENSURE(ww_meshgen(WW_MESH_HULL, &m, &err) == WW_OK);
    if (!m.nindex) return;
    static const double xs[] = {-0.47, -0.3, 0.0, 0.3, 0.45, 0.475};
    static const double ys[] = {0.0, 0.02, 0.04};
    long escaped = 0, total = 0;
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
        for (size_t j = 0; j < sizeof ys / sizeof ys[0]; j++)
            for (int r = 0; r < ENCLOSED_RAYS; r++) {
                double th = 2.0 * 3.14159265358979323846 * r / ENCLOSED_RAYS;
                double o[3] = {xs[i], ys[j], 0.0}, d[3] = {cos(th), 0.0, sin(th)};
                if (!ray_hits(&m, o, d)) escaped++;
                total++;
            }
    fprintf(stderr, "%ld of %ld rays leave the boat below its gunwale\n", escaped, total);
    ENSURE_MSG(escaped == 0, "%ld of %ld horizontal rays from inside the boat leave it", escaped,
               total);
    ww_meshgen_free(&m);
}

/* ---- rendered frames ---- */

#define PIC_SIZE "640x360"
#define WATER_TINT "'water.color=[1,0,1]'" /* a water colour no solid in the scenes has */
#define WATER_TINT_THRESH 6  /* 8-bit levels a pixel moves by when it is water-shaded: the
                              * water's own colour turned magenta shows in every water pixel */
#define HULL_RED_RATIO 1.5   /* a hull pixel: red this many times green and blue (the paint is
                              * (0.55, 0.16, 0.08); wood cubes are 1.5 / 2.6, the sea below 1) */
#define HULL_RED_MIN 40      /* ... and red above this, so black is not hull */
#define INSIDE_WATER_PX_MAX 2 /* water pixels allowed inside the hull's outline (a sea pixel
                               * seen past a corner of the outline where two rims cross a row) */

/* the post-processing that spreads a pixel's colour to its neighbours (FXAA, bloom, light
 * shafts), off: a pixel then changes with the water's colour only when the water shaded it */
#define POST_OFF "--set render.fxaa=false --set render.bloom=false --set render.god_rays=false"

/* render frame `frame` of scene with extra arguments into a fresh folder; the PNG's path */
static int render_at(const char *scene, int frame, const char *args, const char *tag, char *out,
                     size_t cap) {
    char dir[512], a[2048];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(tag));
    snprintf(a, sizeof a, "render %s --frames %d:%d --size " PIC_SIZE " -o %s --quiet %s %s",
             scene, frame, frame + 1, dir, POST_OFF, args ? args : "");
    snprintf(out, cap, "%s/frame_%05d.png", dir, frame);
    return ww_test_ww(a, NULL, NULL);
}

static const unsigned char *px(const ww_image *im, int x, int y) { return ww_test_pixel(im, x, y); }

static int is_hull(const unsigned char *p) {
    return p[0] > HULL_RED_MIN && p[0] > HULL_RED_RATIO * p[1] && p[0] > HULL_RED_RATIO * p[2];
}

/* water pixels inside the hull's outline in a view from the seat: the frame rendered twice, with
 * the scene's water colour and with WATER_TINT; a pixel that moves by more than
 * WATER_TINT_THRESH is water-shaded. In each row of the lower half (the boat; the horizon and the
 * cubes on it lie higher), the hull's outline spans its leftmost to its rightmost hull pixel: the
 * count is the water pixels inside those spans. -1 when a render fails. */
static long water_inside_hull(const char *scene, int frame, const char *args, const char *tag) {
    char a_png[700], b_png[700], tinted[2048], tag_b[128];
    snprintf(tinted, sizeof tinted, "%s --set " WATER_TINT, args ? args : "");
    snprintf(tag_b, sizeof tag_b, "%s_tint", tag);
    if (render_at(scene, frame, args, tag, a_png, sizeof a_png) != 0 ||
        render_at(scene, frame, tinted, tag_b, b_png, sizeof b_png) != 0)
        return -1;
    ww_image a = {0}, b = {0};
    ww_error err = {0};
    long n = -1, hull = 0;
    if (ww_read_png(a_png, &a, &err) != WW_OK || ww_read_png(b_png, &b, &err) != WW_OK) goto done;
    if (a.width != b.width || a.height != b.height || a.channels < 3) goto done;
    n = 0;
    for (int y = a.height / 2; y < a.height; y++) {
        int x0 = -1, x1 = -1;
        for (int x = 0; x < a.width; x++)
            if (is_hull(px(&a, x, y))) {
                if (x0 < 0) x0 = x;
                x1 = x;
                hull++;
            }
        for (int x = x0 + 1; x0 >= 0 && x < x1; x++) {
            const unsigned char *p = px(&a, x, y), *q = px(&b, x, y);
            int e = 0;
            for (int c = 0; c < 3; c++) e = abs(p[c] - q[c]) > e ? abs(p[c] - q[c]) : e;
            if (e > WATER_TINT_THRESH) n++;
        }
    }
    fprintf(stderr, "%s frame %d: %ld hull pixels, %ld water pixels inside the hull's outline\n",
            scene, frame, hull, n);
    if (hull == 0) n = -2; /* no boat in view: the view is not the one the test means */
done:
    ww_image_free(&a);
    ww_image_free(&b);
    return n;
}

/* the seat view over a rough sea (lake frame 420: the boat pitched, the sea up its sides): no
 * water drawn inside the hull, with the reflection and refraction passes on and off */
TEST_IMAGE(hull_picture_no_water_inside_the_boat) {
    REQUIRE_GL();
    long n = water_inside_hull("scenes/lake.yaml", 420, NULL, "lake420");
    ENSURE_MSG(n >= 0, "render or read failed (%ld)", n);
    ENSURE_MSG(n <= INSIDE_WATER_PX_MAX, "%ld water pixels inside the hull (at most %d)", n,
               INSIDE_WATER_PX_MAX);
    n = water_inside_hull("scenes/lake.yaml", 420,
                          "--set render.reflection=false --set render.refraction=false",
                          "lake420_plain");
    ENSURE_MSG(n >= 0, "render or read failed (%ld)", n);
    ENSURE_MSG(n <= INSIDE_WATER_PX_MAX, "%ld water pixels inside the hull without reflection "
               "and refraction (at most %d)", n, INSIDE_WATER_PX_MAX);
}

/* the bow seen from a seat behind it on a flat sea: the two sides meet, so no sea shows between
 * them on the centreline */
TEST_IMAGE(hull_picture_bow_closed) {
    REQUIRE_GL();
    long n = water_inside_hull("scenes/boat.yaml", 150, "--set water.waves.model=flat "
                               "--set 'objects.boat.seat=[-0.5,1.3,0]'", "bow150");
    ENSURE_MSG(n >= 0, "render or read failed (%ld)", n);
    ENSURE_MSG(n <= INSIDE_WATER_PX_MAX, "%ld water pixels between the sides of the bow (at most "
               "%d)", n, INSIDE_WATER_PX_MAX);
}

#define TEAL_MARGIN 20  /* 8-bit levels green and blue must both exceed red by: the under-water
                         * tint (fog.below, extinction); the dusk sky and the water reflecting it
                         * are red over blue, the cubes and the boat too */
#define TEAL_PX_MAX 4   /* teal pixels the reflection may add around the cubes */

/* teal pixels in a rectangle (fractions x0, y0, x1, y1; y from the top) of a PNG, -1 unread */
static long teal_pixels(const char *path, const double r[4]) {
    ww_image im = {0};
    ww_error err = {0};
    if (ww_read_png(path, &im, &err) != WW_OK || im.channels < 3) {
        ww_image_free(&im);
        return -1;
    }
    long n = 0;
    for (int y = (int)(r[1] * im.height); y < (int)(r[3] * im.height); y++)
        for (int x = (int)(r[0] * im.width); x < (int)(r[2] * im.width); x++) {
            const unsigned char *p = px(&im, x, y);
            if (p[1] > p[0] + TEAL_MARGIN && p[2] > p[0] + TEAL_MARGIN) n++;
        }
    ww_image_free(&im);
    return n;
}

/* the lake at dusk: the water around the floating cubes (right of the middle, from 28% to 60%
 * down) shows their reflections in wood colour. Faces under the water, or the mirrored eye's
 * path through the air fogged as if under water, showed as teal blobs beside each cube; the
 * planar reflection may add no more than TEAL_PX_MAX teal pixels there over the render without
 * it */
TEST_IMAGE(hull_picture_reflection_keeps_submerged_faces_out) {
    REQUIRE_GL();
    char on[700], off[700];
    ENSURE_EQ_INT(render_at("scenes/features/lake_dusk.yaml", 0, NULL, "dusk_on", on, sizeof on),
                  0);
    ENSURE_EQ_INT(render_at("scenes/features/lake_dusk.yaml", 0, "--set render.reflection=false",
                            "dusk_off", off, sizeof off), 0);
    static const double cubes[4] = {0.45, 0.28, 1.0, 0.6};
    long n_on = teal_pixels(on, cubes), n_off = teal_pixels(off, cubes);
    fprintf(stderr, "teal pixels around the cubes: %ld with the reflection, %ld without\n", n_on,
            n_off);
    ENSURE(n_on >= 0 && n_off >= 0);
    ENSURE_MSG(n_on - n_off <= TEAL_PX_MAX, "the reflection adds %ld teal pixels around the cubes "
               "(at most %d)", n_on - n_off, TEAL_PX_MAX);
}

#define FISH_DIFF_THRESH 6 /* 8-bit levels a pixel moves by when a fish shows in it */
#define SLIVER_REACH 4     /* px: a fish pixel of the distorted refraction farther than this from
                            * every fish pixel of the undistorted one is torn away from its fish
                            * (the waves' own tilt moves a fish by 2 to 3 px at 640x360) */
#define SLIVER_FRACTION_MAX 0.15 /* share of the fish's pixels allowed that far out */
/* the school moved 200 m off, out of view in the fog (a scene needs one fish at least) */
#define NO_FISH "--set objects.fish.count=1 --set 'objects.fish.center=[0,-2,-200]'"

/* pixels where two renders of one frame differ by more than FISH_DIFF_THRESH: 1 in mask */
static long diff_mask(const char *a_png, const char *b_png, unsigned char **mask, int *w, int *h) {
    ww_image a = {0}, b = {0};
    ww_error err = {0};
    long n = -1;
    *mask = NULL;
    if (ww_read_png(a_png, &a, &err) != WW_OK || ww_read_png(b_png, &b, &err) != WW_OK) goto done;
    if (a.width != b.width || a.height != b.height || a.channels < 3) goto done;
    *w = a.width;
    *h = a.height;
    *mask = calloc((size_t)a.width * (size_t)a.height, 1);
    if (!*mask) goto done;
    n = 0;
    for (int y = 0; y < a.height; y++)
        for (int x = 0; x < a.width; x++) {
            const unsigned char *p = px(&a, x, y), *q = px(&b, x, y);
            int e = 0;
            for (int c = 0; c < 3; c++) e = abs(p[c] - q[c]) > e ? abs(p[c] - q[c]) : e;
            if (e > FISH_DIFF_THRESH) {
                (*mask)[(size_t)y * (size_t)a.width + (size_t)x] = 1;
                n++;
            }
        }
done:
    ww_image_free(&a);
    ww_image_free(&b);
    return n;
}

/* the school seen from above through the refraction at fishing frame `frame`: where the fish
 * show (the render against one with the school away) with the scene's distortion and without it; the
 * share of the distorted fish pixels farther than SLIVER_REACH from every undistorted one, or
 * -1 when a render fails */
static double fish_torn_share(int frame) {
    static const char *scene = "scenes/fishing.yaml";
    static const char *const args[4] = {
        "", NO_FISH, "--set water.look.distortion=0",
        "--set water.look.distortion=0 " NO_FISH};
    char png[4][700], tag[64];
    for (int i = 0; i < 4; i++) {
        snprintf(tag, sizeof tag, "fish%d_%d", frame, i);
        if (render_at(scene, frame, args[i], tag, png[i], sizeof png[i]) != 0) return -1.0;
    }
    unsigned char *torn = NULL, *calm = NULL;
    int w = 0, h = 0, w2 = 0, h2 = 0;
    long n = diff_mask(png[0], png[1], &torn, &w, &h);
    long n2 = diff_mask(png[2], png[3], &calm, &w2, &h2);
    double share = -1.0;
    if (n > 0 && n2 > 0 && w == w2 && h == h2) {
        long far = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                if (!torn[(size_t)y * (size_t)w + (size_t)x]) continue;
                int near = 0;
                for (int dy = -SLIVER_REACH; dy <= SLIVER_REACH && !near; dy++)
                    for (int dx = -SLIVER_REACH; dx <= SLIVER_REACH && !near; dx++) {
                        int u = x + dx, v = y + dy;
                        if (u >= 0 && u < w && v >= 0 && v < h)
                            near = calm[(size_t)v * (size_t)w + (size_t)u];
                    }
                far += !near;
            }
        share = (double)far / (double)n;
        fprintf(stderr, "fishing frame %d: %ld fish pixels distorted, %ld undistorted; %ld (%.1f%%) "
                "more than %d px from the undistorted fish\n", frame, n, n2, far, 100.0 * share,
                SLIVER_REACH);
    }
    free(torn);
    free(calm);
    return share;
}

/* fish under a rippled sea seen from the shore (fishing frames 130 and 148): the refraction's
 * distortion moves them a little but does not tear them into slivers strewn around them */
TEST_IMAGE(hull_picture_refracted_fish_not_torn) {
    REQUIRE_GL();
    static const int frames[2] = {130, 148};
    for (int i = 0; i < 2; i++) {
        double s = fish_torn_share(frames[i]);
        ENSURE_MSG(s >= 0.0, "frame %d: a render failed, or no fish in view", frames[i]);
        ENSURE_MSG(s <= SLIVER_FRACTION_MAX, "frame %d: %.1f%% of the fish pixels are torn more "
                   "than %d px from their fish (at most %.0f%%)", frames[i], 100.0 * s,
                   SLIVER_REACH, 100.0 * SLIVER_FRACTION_MAX);
    }
}
