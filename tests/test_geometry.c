/* test_geometry.c - solid geometry: the procedural meshes (gfx/meshgen.h: watertight, outward,
 * inside the unit box, volumes against the analytic shapes), and the pictures of the geometry
 * features (shadows, caustics, lights, fog, the lake at dusk) with their toggles.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/backend.h"
#include "gfx/meshgen.h"
#include "gfx/render_impl.h"
#include "scene/plan.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* a UV sphere of S slices and T stacks is inscribed in the sphere: its volume falls short by
 * about (2 pi / S)^2 / 6 + (pi / T)^2 / 6 (the inscribed polygons' area deficits) */
#define SPHERE_TESS_VOLUME_TOL 0.03  /* relative, at 24 x 16 */
#define BOX_VOLUME_TOL 1e-6          /* m^3: exact shapes, float vertices */
#define NORMAL_UNIT_TOL 1e-5
#define UNIT_BOX_SLACK 1e-6

/* unit normals that agree with their triangles' winding, and every position in the unit box */
static void check_normals_and_bounds(const ww_mesh_data *m, const char *name) {
    long wrong = 0, not_unit = 0;
    for (int i = 0; i < m->nvert; i++) {
        const float *v = m->vertex + 8 * i;
        double l = sqrt((double)v[3] * v[3] + (double)v[4] * v[4] + (double)v[5] * v[5]);
        if (fabs(l - 1.0) > NORMAL_UNIT_TOL) not_unit++;
        for (int k = 0; k < 3; k++)
            ENSURE_MSG(fabs(v[k]) <= 0.5 + UNIT_BOX_SLACK, "%s: vertex %d coordinate %d = %g is "
                       "outside the unit box", name, i, k, (double)v[k]);
    }
    for (uint32_t t = 0; t + 2 < m->nindex; t += 3) {
        const float *a = m->vertex + 8 * m->index[t], *b = m->vertex + 8 * m->index[t + 1],
                    *c = m->vertex + 8 * m->index[t + 2];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = (double)b[k] - a[k];
            e2[k] = (double)c[k] - a[k];
        }
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (ln < 1e-12) continue;
        const float *vs[3] = {a, b, c};
        for (int s = 0; s < 3; s++)
            if (n[0] * vs[s][3] + n[1] * vs[s][4] + n[2] * vs[s][5] <= 0.0) wrong++;
    }
    ENSURE_MSG(not_unit == 0, "%s: %ld normals are not unit", name, not_unit);
    ENSURE_MSG(wrong == 0, "%s: %ld vertex normals point against their triangle's winding", name,
               wrong);
}

static const struct {
    ww_mesh_kind kind;
    const char *name;
    int closed;
} MESHES[] = {
    {WW_MESH_BOX, "box", 1},     {WW_MESH_SPHERE, "sphere", 1}, {WW_MESH_STONE, "stone", 1},
    {WW_MESH_HULL, "hull", 1},   {WW_MESH_FISH, "fish", 1},     {WW_MESH_LURE, "lure", 1},
    {WW_MESH_CHEST, "chest", 1}, {WW_MESH_GRID, "grid", 0},     {WW_MESHGEN_COLUMN, "column", 0},
    {WW_MESHGEN_FISH_OF(WW_FISH_SLIM), "fish_slim", 1},
    {WW_MESHGEN_FISH_OF(WW_FISH_DEEP), "fish_deep", 1},
    {WW_MESHGEN_FISH_OF(WW_FISH_LONG), "fish_long", 1},
    {WW_MESHGEN_DROP, "drop", 1},
};

/* the shipped OBJ models the renderer's closed test sorts: the floating marker buoy is one
 * closed shell (its inside, cut open by the reflection's plane, is shaded as the cut's face);
 * the kelp's fronds are open sheets seen from both sides */
TEST(meshgen_obj_models_closed_or_open) {
    static const struct {
        const char *scene, *path;
        int closed;
    } OBJ[] = {{"scenes/features/floating_models.yaml", "marker_buoy.obj", 1},
               {"scenes/reef.yaml", "kelp.obj", 0},
               {"scenes/reef.yaml", "rock_boulder.obj", 1}};
    for (size_t i = 0; i < sizeof OBJ / sizeof OBJ[0]; i++) {
        ww_scene *sc = NULL;
        ww_error err = {0};
        ENSURE_MSG(ww_scene_load(OBJ[i].scene, NULL, 0, &sc, &err) == WW_OK, "%s: %s",
                   OBJ[i].scene, err.msg);
        if (!sc) continue;
        const ww_mesh_data *m = NULL;
        for (int k = 0; sc->assets && k < sc->assets->nmesh; k++) {
            const char *p = sc->assets->mesh[k].path, *tail = strrchr(p, '/');
            if (strcmp(tail ? tail + 1 : p, OBJ[i].path) == 0) m = &sc->assets->mesh[k];
        }
        ENSURE_MSG(m != NULL, "%s: no mesh %s", OBJ[i].scene, OBJ[i].path);
        if (m) {
            long open = ww_meshgen_open_edges(m);
            ENSURE_MSG(OBJ[i].closed ? open == 0 : open > 0, "%s: %ld open edges, expected %s",
                       OBJ[i].path, open, OBJ[i].closed ? "none" : "some");
        }
        ww_scene_free(sc);
    }
}

TEST(meshgen_closed_outward_in_unit_box) {
    for (size_t i = 0; i < sizeof MESHES / sizeof MESHES[0]; i++) {
        ww_mesh_data m;
        ww_error err = {0};
        ENSURE(ww_meshgen(MESHES[i].kind, &m, &err) == WW_OK);
        ENSURE_MSG(m.nvert > 0 && m.nindex % 3 == 0 && m.nindex > 0, "%s: empty", MESHES[i].name);
        for (uint32_t t = 0; t < m.nindex; t++) ENSURE(m.index[t] < (uint32_t)m.nvert);
        check_normals_and_bounds(&m, MESHES[i].name);
        if (MESHES[i].closed) {
            long bad = ww_meshgen_open_edges(&m);
            ENSURE_MSG(bad == 0, "%s: %ld edges without an opposite twin (not watertight or "
                       "inconsistently wound)", MESHES[i].name, bad);
            ENSURE_MSG(ww_meshgen_volume(&m) > 0.0, "%s: signed volume %g is not positive",
                       MESHES[i].name, ww_meshgen_volume(&m));
        } else {
            /* the renderer takes a mesh with no open edge for closed, and shades what it sees
             * of it from inside as a cut face: an open sheet must never pass */
            ENSURE_MSG(ww_meshgen_open_edges(&m) > 0, "%s: an open mesh counted as closed",
                       MESHES[i].name);
        }
        ww_meshgen_free(&m);
    }
}

static double volume_of(ww_mesh_kind k) {
    ww_mesh_data m;
    ww_error err = {0};
    if (ww_meshgen(k, &m, &err) != WW_OK) return NAN;
    double v = ww_meshgen_volume(&m);
    ww_meshgen_free(&m);
    return v;
}

TEST(meshgen_volumes_match_the_analytic_shapes) {
    double pi = 3.14159265358979323846;
    ENSURE_NEAR(volume_of(WW_MESH_BOX), 1.0, BOX_VOLUME_TOL);
    double body = 0.94 * (1.0 - WW_CHEST_LID) * 0.94, lid = WW_CHEST_LID;
    ENSURE_NEAR(volume_of(WW_MESH_CHEST), body + lid, BOX_VOLUME_TOL);

    /* inscribed: a little below the analytic volume, within the tessellation's deficit */
    double sphere = 4.0 / 3.0 * pi * 0.125, v = volume_of(WW_MESH_SPHERE);
    ENSURE(v < sphere);
    ENSURE_NEAR(v / sphere, 1.0, SPHERE_TESS_VOLUME_TOL);
    double stone = sphere * WW_STONE_THICKNESS * WW_STONE_DEPTH;
    v = volume_of(WW_MESH_STONE);
    ENSURE(v < stone);
    ENSURE_NEAR(v / stone, 1.0, SPHERE_TESS_VOLUME_TOL);
    /* the bobber: ball plus the part of the stem outside it (a cylinder from 0.8 r above the
     * ball's centre; the cap of the ball inside the stem is small and counted twice) */
    double r = WW_LURE_BALL, rs = WW_LURE_STEM, y0 = -0.5 + r + 0.8 * r;
    double lure = 4.0 / 3.0 * pi * r * r * r + pi * rs * rs * (0.5 - y0);
    ENSURE_NEAR(volume_of(WW_MESH_LURE) / lure, 1.0, SPHERE_TESS_VOLUME_TOL);
}

TEST(meshgen_fish_tail_weight) {
    ww_mesh_data m;
    ww_error err = {0};
    ENSURE(ww_meshgen(WW_MESH_FISH, &m, &err) == WW_OK);
    double head = 0.0, tail = 0.0;
    for (int i = 0; i < m.nvert; i++) {
        const float *v = m.vertex + 8 * i;
        ENSURE(v[6] >= 0.0f && v[6] <= 1.0f);
        if (v[0] > 0.2f && v[6] > head) head = v[6];
        if (v[0] < -0.45f && v[6] > tail) tail = v[6];
    }
    ENSURE_MSG(head == 0.0, "the head must not wiggle (weight %g)", head);
    ENSURE_MSG(tail > 0.9, "the tail tip must swing fully (weight %g)", tail);
    ww_meshgen_free(&m);
}

/* ---- pictures ---- */

#define TOGGLE_THRESH 2 /* LDR codes: a pixel differs when a channel moves by more than this */

static void golden_of(const char *name) {
    REQUIRE_GL();
    char scene[256], gold[256], dir[512], actual[600];
    snprintf(scene, sizeof scene, "scenes/features/%s.yaml", name);
    snprintf(gold, sizeof gold, "golden/features/%s.png", name);
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(name));
    ENSURE(ww_test_render(scene, NULL, dir) == 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden(gold, actual);
}

TEST_IMAGE(geometry_golden_shadows) { golden_of("shadows"); }
TEST_IMAGE(geometry_golden_caustics) { golden_of("caustics"); }
TEST_IMAGE(geometry_golden_caustics_texture) { golden_of("caustics_texture"); }
TEST_IMAGE(geometry_golden_lights) { golden_of("lights"); }
TEST_IMAGE(geometry_golden_fog) { golden_of("fog"); }
TEST_IMAGE(geometry_golden_lake_dusk) { golden_of("lake_dusk"); }

/* scene rendered twice, with and without `set`, into a and b; diff within rect */
static int toggle(const char *name, const char *set, const double rect[4], ww_test_region *d,
                  char *a, char *b, size_t n) {
    char scene[256], da[512], db[512], args[256];
    snprintf(scene, sizeof scene, "scenes/features/%s.yaml", name);
    snprintf(da, sizeof da, "%s", ww_test_tmpdir("toggle_on"));
    snprintf(db, sizeof db, "%s", ww_test_tmpdir("toggle_off"));
    snprintf(args, sizeof args, "--set %s", set);
    if (ww_test_render(scene, NULL, da) != 0 || ww_test_render(scene, args, db) != 0) return -1;
    snprintf(a, n, "%s/frame_00000.png", da);
    snprintf(b, n, "%s/frame_00000.png", db);
    return ww_test_region_diff(a, b, rect, TOGGLE_THRESH, d);
}

/* the shadow scene looks down from under water: the seabed fills the lower 55% of the image, the
 * surface seen from below the top; shadows fall only on the seabed */
TEST_IMAGE(geometry_shadows_toggle) {
    REQUIRE_GL();
    const double seabed[4] = {0.0, 0.45, 1.0, 1.0};
    ww_test_region d;
    char a[600], b[600];
    ENSURE(toggle("shadows", "render.shadows=false", seabed, &d, a, b, sizeof a) == 0);
    double frac = (double)d.inside / (double)d.inside_px;
    ENSURE_MSG(frac > 0.05, "shadows off changed only %.3f of the seabed", frac);
    /* the surface seen from below, between the cubes (top 10%) and the seabed */
    const double top[4] = {0.0, 0.10, 1.0, 0.18};
    ENSURE(ww_test_region_diff(a, b, top, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside == 0, "shadows off changed %ld pixels at the top (surface, sky)", d.inside);
    /* and the plan loses the pass */
    char on[600], off[600];
    snprintf(on, sizeof on, "%s/on.txt", ww_test_tmpdir("geometry_plan"));
    snprintf(off, sizeof off, "%s/off.txt", ww_test_tmpdir("geometry_plan"));
    ENSURE(ww_test_ww("plan scenes/features/shadows.yaml", on, NULL) == 0);
    ENSURE(ww_test_file_contains(on, " shadow "));
    ENSURE(ww_test_ww("plan scenes/features/shadows.yaml --set render.shadows=false", off, NULL) == 0);
    ENSURE(!ww_test_file_contains(off, " shadow "));
}

/* caustics light the seabed under water and nothing above it */
TEST_IMAGE(geometry_caustics_toggle) {
    REQUIRE_GL();
    const double seabed[4] = {0.0, 0.45, 1.0, 1.0};
    ww_test_region d;
    char a[600], b[600];
    ENSURE(toggle("caustics", "water.look.caustics=false", seabed, &d, a, b, sizeof a) == 0);
    double frac = (double)d.inside / (double)d.inside_px;
    ENSURE_MSG(frac > 0.2, "caustics off changed only %.3f of the seabed", frac);
    /* the surface seen from below, between the floating cubes (whose submerged faces do catch
     * caustics) and the seabed */
    const double top[4] = {0.0, 0.10, 1.0, 0.18};
    ENSURE(ww_test_region_diff(a, b, top, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside == 0, "caustics off changed %ld pixels of the surface", d.inside);
}

/* the lights light the boat and the cubes, not the sky */
TEST_IMAGE(geometry_lights_toggle) {
    REQUIRE_GL();
    const double sky[4] = {0.0, 0.0, 1.0, 0.2};
    ww_test_region d;
    char a[600], b[600];
    ENSURE(toggle("lights", "lights[0].intensity=0 --set lights[1].intensity=0", sky, &d, a, b,
                  sizeof a) == 0);
    ENSURE_MSG(d.inside == 0, "lights off changed %ld sky pixels", d.inside);
    ENSURE_MSG(d.outside > 200, "lights off changed only %ld pixels of the boat and cubes",
               d.outside);
}

/* fog: denser fog moves the geometry's pixels; the sky keeps its colour */
TEST_IMAGE(geometry_fog_toggle) {
    REQUIRE_GL();
    const double sky[4] = {0.0, 0.0, 1.0, 0.25};
    ww_test_region d;
    char a[600], b[600];
    ENSURE(toggle("fog", "fog.below.density=0 --set fog.above.density=0", sky, &d, a, b,
                  sizeof a) == 0);
    ENSURE_MSG(d.outside > 100, "fog off changed only %ld pixels", d.outside);
}

/* instancing: the lake's 12 fish, 5 cubes, boat, chest... come out as one draw per mesh type,
 * whatever the number of objects (the draw count of the main pass's geometry) */
TEST_PROC(geometry_one_draw_per_mesh_type) {
    REQUIRE_GL();
    ww_set sets[] = {{"render.size=[64, 36]"}};
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load("scenes/lake.yaml", sets, 1, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    /* 8 s in: a chest is out, a stone in flight, the lure cast */
    for (int i = 0; i < 960 && st; i++) ENSURE(ww_step(sc, st, &err) == WW_OK);
    ww_backend *b = NULL;
    ww_renderer *r = NULL;
    ww_plan plan;
    ww_plan_build(sc, sc->width, sc->height, &plan);
    ENSURE(ww_backend_open(WW_BACKEND_AUTO, &b, &err) == WW_OK);
    if (b && st && ww_renderer_new(ww_backend_gl(b), sc, &plan, &r, &err) == WW_OK) {
        ENSURE(ww_render_frame(r, sc, st, &err) == WW_OK);
        /* mesh types present: seabed, cube, boat, fish, chest, its glow column; stones and the
         * lure come and go with the script, so count what the state has */
        int types = 6 + (st->lure_state[0] > 0.0) + (sc->bubbles.on ? 1 : 0);
        int stones = 0;
        for (int i = 0; i < WW_MAX_STONES; i++) stones += st->stone_state[i] > 0.0;
        types += stones > 0;
        int n = ww_geometry_draw_count(r->geometry);
        ENSURE_MSG(n >= 5 && n <= types, "%d draws for %d mesh types (12 fish, 5 cubes)", n, types);
        ww_renderer_free(r);
    } else {
        ENSURE_MSG(0, "renderer: %s", err.msg);
    }
    ww_backend_close(b);
    ww_state_free(st);
    ww_scene_free(sc);
}
