/* test_assets.c - the scene's files: images through stb_image, the OBJ + MTL reader (exact
 * counts and values on the small files of tests/data/, malformed lines' file:line:column, size
 * caps), objects.models as a scene graph (world matrices and bounds by hand), and the skies:
 * cubemap face orientation, the skybox and skydome goldens, and the gradient/cubemap toggle.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/image.h"
#include "io/writers.h"
#include "scene/assets.h"
#include "scene/obj.h"
#include "scene/scene.h"
#include "test.h"

#define OBJ_VALUE_TOL 1e-6   /* float values read from text and normalised */
#define MODEL_MATRIX_TOL 1e-9 /* double transforms of whole numbers and right angles */

static const float *vertex(const ww_mesh_data *m, uint32_t i) { return m->vertex + 8 * i; }

static ww_result load_obj(ww_assets *a, const char *path, int *index, ww_error *err) {
    return ww_assets_obj(a, path, "scene.yaml", 3, 7, index, err);
}

TEST(assets_obj_quad_with_negative_indices) {
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_EQ_INT(load_obj(&a, "tests/data/quad_negative.obj", &idx, &err), WW_OK);
    if (idx < 0) return;
    const ww_mesh_data *m = &a.mesh[idx];
    ENSURE_EQ_INT(m->nvert, 4);
    ENSURE_EQ_INT(m->nindex, 6);
    ENSURE_EQ_INT(m->nsub, 1);
    ENSURE_EQ_INT(m->sub[0].material, -1);
    /* the quad fanned from its first corner: (0 1 2) (0 2 3) */
    static const uint32_t want[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) ENSURE_EQ_INT(m->index[i], want[i]);
    /* vn 0 2 0 normalised; vt (1, 1) of the third corner stored as (1, 1 - 1) */
    for (uint32_t i = 0; i < 4; i++) ENSURE_NEAR(vertex(m, i)[4], 1.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(vertex(m, 2)[0], 1.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(vertex(m, 2)[2], -1.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(vertex(m, 2)[6], 1.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(vertex(m, 2)[7], 0.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(vertex(m, 0)[7], 1.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(m->min[2], -1.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(m->max[0], 1.0, OBJ_VALUE_TOL);
    /* one copy per path */
    int again = -1;
    ENSURE_EQ_INT(load_obj(&a, "tests/data/quad_negative.obj", &again, &err), WW_OK);
    ENSURE_EQ_INT(again, idx);
    ENSURE_EQ_INT(a.nmesh, 1);
    ww_assets_free(&a);
}

TEST(assets_obj_ngon_fanned_with_computed_normals) {
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_EQ_INT(load_obj(&a, "tests/data/hexagon.obj", &idx, &err), WW_OK);
    if (idx < 0) return;
    const ww_mesh_data *m = &a.mesh[idx];
    ENSURE_EQ_INT(m->nvert, 6);
    ENSURE_EQ_INT(m->nindex, 12); /* six corners: four triangles */
    /* counter-clockwise seen from above: every computed normal is +y */
    for (int i = 0; i < m->nvert; i++) {
        ENSURE_NEAR(vertex(m, (uint32_t)i)[3], 0.0, OBJ_VALUE_TOL);
        ENSURE_NEAR(vertex(m, (uint32_t)i)[4], 1.0, OBJ_VALUE_TOL);
        ENSURE_NEAR(vertex(m, (uint32_t)i)[5], 0.0, OBJ_VALUE_TOL);
    }
    ww_assets_free(&a);
}

TEST(assets_obj_two_materials_with_a_texture) {
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_MSG(load_obj(&a, "tests/data/two_materials.obj", &idx, &err) == WW_OK, "%s", err.msg);
    if (idx < 0) return;
    const ww_mesh_data *m = &a.mesh[idx];
    /* corners 1//1 2//1 3//1 4//1 and 2/1/1 5/2/1 3/4/1: seven distinct (v, vt, vn) */
    ENSURE_EQ_INT(m->nvert, 7);
    ENSURE_EQ_INT(m->nindex, 9);
    ENSURE_EQ_INT(m->nsub, 2);
    ENSURE_EQ_INT(m->nmaterial, 2);
    if (m->nsub != 2 || m->nmaterial != 2) return;
    ENSURE(m->sub[0].first == 0 && m->sub[0].count == 6 && m->sub[0].material == 0);
    ENSURE(m->sub[1].first == 6 && m->sub[1].count == 3 && m->sub[1].material == 1);
    const ww_material *red = &m->material[0], *wood = &m->material[1];
    ENSURE(strcmp(red->name, "red") == 0);
    ENSURE(strcmp(wood->name, "painted wood") == 0);
    ENSURE_NEAR(red->diffuse[1], 0.1, OBJ_VALUE_TOL);
    ENSURE_NEAR(red->specular[2], 0.5, OBJ_VALUE_TOL);
    ENSURE_NEAR(red->shininess, 64.0, OBJ_VALUE_TOL);
    ENSURE_NEAR(red->opacity, 0.75, OBJ_VALUE_TOL);
    ENSURE_EQ_INT(red->texture, -1);
    ENSURE_NEAR(wood->opacity, 0.75, OBJ_VALUE_TOL); /* Tr 0.25 */
    ENSURE_NEAR(wood->emission[2], 0.3, OBJ_VALUE_TOL);
    ENSURE(wood->texture >= 0 && wood->texture < a.nimage);
    if (wood->texture < 0 || wood->texture >= a.nimage) return;
    /* the TGA, top row first: red, green / blue, white */
    const ww_image_data *im = &a.image[wood->texture];
    ENSURE(im->width == 2 && im->height == 2);
    static const unsigned char want[16] = {255, 0,   0,   255, 0,   255, 0,   255,
                                           0,   0,   255, 255, 255, 255, 255, 255};
    unsigned char *px = NULL;
    ENSURE_EQ_INT(ww_assets_decode(im, &px, &err), WW_OK);
    ENSURE(px && memcmp(px, want, 16) == 0);
    ww_assets_pixels_free(px);
    /* the same picture as a PNG decodes to the same texels; each path is kept once */
    int png = -1, tga = -1;
    char tga_path[WW_ASSET_PATH];
    memcpy(tga_path, im->path, sizeof tga_path); /* im moves when the table grows */
    ENSURE_EQ_INT(ww_assets_image(&a, "tests/data/checker.png", "x", 1, 1, &png, &err), WW_OK);
    px = NULL;
    ENSURE(png >= 0 && ww_assets_decode(&a.image[png], &px, &err) == WW_OK);
    ENSURE(px && memcmp(px, want, 16) == 0);
    ww_assets_pixels_free(px);
    ENSURE_EQ_INT(ww_assets_image(&a, tga_path, "x", 1, 1, &tga, &err), WW_OK);
    ENSURE_EQ_INT(tga, wood->texture);
    ENSURE_EQ_INT(a.nimage, 2);
    ww_assets_free(&a);
}

TEST(assets_missing_texture_names_the_mtl_line) {
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_EQ_INT(load_obj(&a, "tests/data/missing_texture.obj", &idx, &err), WW_E_NOFILE);
    ENSURE_MSG(strcmp(err.file, "tests/data/missing_texture.mtl") == 0, "file %s", err.file);
    ENSURE_EQ_INT(err.line, 3);
    ENSURE_EQ_INT(err.column, 8);
    ENSURE_EQ_INT(a.nmesh, 0);
    ww_assets_free(&a);
    /* a missing OBJ names the scene's place that named it */
    ENSURE_EQ_INT(load_obj(&a, "tests/data/no_such.obj", &idx, &err), WW_E_NOFILE);
    ENSURE(strcmp(err.file, "scene.yaml") == 0 && err.line == 3 && err.column == 7);
    ENSURE_EQ_INT(ww_assets_image(&a, "tests/data/corrupt.png", "s.yaml", 4, 2, &idx, &err),
                  WW_E_SYNTAX);
    ENSURE(err.line == 4 && err.column == 2);
    ww_assets_free(&a);
}

/* malformed OBJ text: the code and the OBJ's own line:column */
TEST(assets_obj_malformed_lines_name_their_place) {
    static const struct {
        const char *text;
        ww_result code;
        int line, column;
    } bad[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", WW_E_RANGE, 4, 7},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", WW_E_RANGE, 4, 7},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", WW_E_RANGE, 4, 3},
        {"v 0 0 0\nv 1 0 zero\n", WW_E_SYNTAX, 2, 7},
        {"v 0 0 0\nv 1 0 1e999\n", WW_E_SYNTAX, 2, 7},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1/1 2 3\n", WW_E_RANGE, 5, 5},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//2 2 3\n", WW_E_RANGE, 4, 6},
        {"v 0 0 0\nv 1 0 0\nf 1 2\n", WW_E_SYNTAX, 3, 1},
        {"v 0 0\n", WW_E_SYNTAX, 1, 6},
        {"  usemtl nothing\n", WW_E_MISSING, 1, 10},
        {"mtllib no_such.mtl\n", WW_E_NOFILE, 1, 8},
        {"# only a comment\nv 1 2 3\n", WW_E_EMPTY, 0, 0},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ww_assets a = {0};
        ww_mesh_data m;
        ww_error err = {0};
        ww_result r = ww_assets_obj_parse(&a, "tests/data/bad.obj", bad[i].text,
                                          strlen(bad[i].text), &m, &err);
        ENSURE_MSG(r == bad[i].code && err.line == bad[i].line && err.column == bad[i].column,
                   "case %zu: got %s %d:%d, expected %s %d:%d (%s)", i, ww_result_name(r),
                   err.line, err.column, ww_result_name(bad[i].code), bad[i].line, bad[i].column,
                   err.msg);
        ENSURE(strcmp(err.file, "tests/data/bad.obj") == 0);
        ENSURE(m.vertex == NULL && m.index == NULL);
        ww_assets_free(&a);
    }
}

/* a polygon past the corner cap is refused, not allocated */
TEST(assets_obj_caps_corners) {
    char text[4096];
    size_t n = (size_t)snprintf(text, sizeof text, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf");
    for (int i = 0; i <= WW_OBJ_MAX_CORNERS && n + 8 < sizeof text; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, " %d", 1 + i % 3);
    ww_assets a = {0};
    ww_mesh_data m;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_assets_obj_parse(&a, "cap.obj", text, n, &m, &err), WW_E_RANGE);
    ENSURE_EQ_INT(err.line, 4);
    ww_assets_free(&a);
}

static const double *origin(const ww_model_desc *m) { return m->world + 12; }

/* a child written before its rotated, scaled parent lands where the hand computation says */
TEST(assets_models_world_matrices) {
    static const char *text =
        "time: {dt: 1/120, fps: 30, duration: 1}\n"
        "objects:\n"
        "  models:\n"
        "    - {name: arm, mesh: sphere, parent: base, position: [1, 0, 0]}\n"
        "    - {name: base, mesh: box, position: [10, 0, 0], rotation: 90, scale: 2}\n"
        "    - {name: tip, mesh: lure, parent: arm, position: [0, 0, -1], rotation: [0, 90, 0]}\n"
        "    - {name: wreck, obj: tests/data/box.obj, position: [0, -5, 0], scale: 0.5}\n"
        "    - {name: rock, min: [-1, -8, -1], max: [1, -6, 1]}\n";
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("t.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return;
    const ww_model_desc *arm = &sc->models.model[0], *base = &sc->models.model[1],
                        *tip = &sc->models.model[2], *wreck = &sc->models.model[3],
                        *rock = &sc->models.model[4];
    ENSURE_EQ_INT(sc->models.count, 5);
    ENSURE_EQ_INT(arm->parent, 1);
    ENSURE_EQ_INT(base->parent, -1);
    ENSURE_EQ_INT(arm->mesh, WW_MESH_SPHERE);
    /* yaw 90 turns +x toward +z (the boat's heading): the arm's (1, 0, 0) m goes to (0, 0, 1)
     * from the base at (10, 0, 0); the base's scale 2 is its own, not its children's */
    ENSURE_NEAR(origin(arm)[0], 10.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(origin(arm)[1], 0.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(origin(arm)[2], 1.0, MODEL_MATRIX_TOL);
    /* the tip's (0, 0, -1) in the arm's frame: the -z nose turned by yaw 90 to +x */
    ENSURE_NEAR(origin(tip)[0], 11.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(origin(tip)[2], 1.0, MODEL_MATRIX_TOL);
    /* its pitch 90 lifts its own -z axis to +y, which the parents' yaw leaves alone */
    ENSURE_NEAR(tip->world[8 + 1], -1.0, MODEL_MATRIX_TOL); /* column z, row y: R (0,0,1) */
    /* bounds of the arm: its own unit box around (10, 0, 1) */
    ENSURE_NEAR(arm->min[0], 9.5, MODEL_MATRIX_TOL);
    ENSURE_NEAR(arm->max[2], 1.5, MODEL_MATRIX_TOL);
    /* the OBJ's own bounds (0..2, 0..1, -2..2) scaled by 0.5 and moved down 5 m */
    ENSURE_NEAR(wreck->min[0], 0.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(wreck->max[0], 1.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(wreck->min[1], -5.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(wreck->max[1], -4.5, MODEL_MATRIX_TOL);
    ENSURE_NEAR(wreck->min[2], -1.0, MODEL_MATRIX_TOL);
    ENSURE_EQ_INT(wreck->mesh, WW_MESH_OBJ);
    ENSURE(sc->assets && wreck->asset >= 0 && wreck->asset < sc->assets->nmesh);
    /* bounds only, as before: kept as written */
    ENSURE_EQ_INT(rock->mesh, WW_MESH_NONE);
    ENSURE_NEAR(rock->min[1], -8.0, MODEL_MATRIX_TOL);
    ENSURE_NEAR(rock->max[1], -6.0, MODEL_MATRIX_TOL);
    ww_scene_free(sc);
}

TEST(assets_models_graph_errors) {
    static const struct {
        const char *models;
        ww_result code;
        int line, column;
    } bad[] = {
        {"    - {name: a, mesh: box, parent: b}\n    - {name: b, mesh: box, parent: a}\n",
         WW_E_INCONSISTENT, 4, 36},
        {"    - {name: a, mesh: box, parent: a}\n", WW_E_INCONSISTENT, 4, 36},
        {"    - {name: a, mesh: box}\n    - {name: a, mesh: box}\n", WW_E_INCONSISTENT, 5, 14},
        {"    - {name: a, mesh: box, parent: boat}\n", WW_E_INCONSISTENT, 4, 36},
        {"    - {name: a}\n", WW_E_MISSING, 4, 7},
        {"    - {name: a, mesh: box, scale: 0}\n", WW_E_RANGE, 4, 35},
        {"    - {name: a, mesh: boxx}\n", WW_E_ENUM, 4, 23},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[512];
        snprintf(text, sizeof text,
                 "time: {dt: 1/120, fps: 30, duration: 1}\nobjects:\n  models:\n%s",
                 bad[i].models);
        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_result r = ww_scene_load_string("g.yaml", text, strlen(text), NULL, 0, &sc, &err);
        ENSURE_MSG(r == bad[i].code && err.line == bad[i].line && err.column == bad[i].column,
                   "case %zu: got %s %d:%d, expected %s %d:%d (%s)", i, ww_result_name(r),
                   err.line, err.column, ww_result_name(bad[i].code), bad[i].line, bad[i].column,
                   err.msg);
        ww_scene_free(sc);
    }
}

TEST_PROC(assets_bad_scene_exits_2) {
    ENSURE_EQ_INT(ww_test_ww("plan tests/bad/inconsistent_cubemap_face_size.yaml", NULL, NULL), 2);
    ENSURE_EQ_INT(ww_test_ww("plan tests/bad/nofile_model_obj.yaml", NULL, NULL), 2);
}

/* ---- skies (GL) ---------------------------------------------------------------------------- */

/* the centre pixel of a rendered PNG */
static int centre_pixel(const char *png, unsigned char rgb[3]) {
    ww_image im = {0};
    ww_error err = {0};
    if (ww_read_png(png, &im, &err) != WW_OK) return 0;
    const uint8_t *p = im.u8 + ((size_t)(im.height / 2) * (size_t)im.width + (size_t)im.width / 2) *
                                   (size_t)im.channels;
    memcpy(rgb, p, 3);
    ww_image_free(&im);
    return 1;
}

/* a view along each axis of the six-colour cubemap shows that face's colour at its centre:
 * the camera hangs 500 m up with a 5 m far plane, so no water covers the view down */
TEST_IMAGE(assets_skybox_face_orientation) {
    REQUIRE_GL();
    static const struct {
        const char *name;
        double yaw, pitch;
        unsigned char rgb[3]; /* 1: the channel is high, 0: low */
    } view[6] = {{"+x", 90, 0, {1, 0, 0}},  {"-x", -90, 0, {0, 1, 1}},
                 {"+y", 0, 89.9, {0, 1, 0}}, {"-y", 0, -89.9, {1, 0, 1}},
                 {"+z", 180, 0, {0, 0, 1}}, {"-z", 0, 0, {1, 1, 0}}};
    const char *dir = ww_test_tmpdir("assets_skybox_faces");
    char cwd[400];
    ENSURE(dir && getcwd(cwd, sizeof cwd));
    if (!dir) return;
    for (int i = 0; i < 6; i++) {
        char scene[600], text[4096], out[700], png[800];
        snprintf(scene, sizeof scene, "%s/face%d.yaml", dir, i);
        snprintf(text, sizeof text,
                 "time: {dt: 1/120, fps: 30, duration: 1}\n"
                 "render: {size: [64, 64], bloom: false, fxaa: false, god_rays: false}\n"
                 "sky:\n  model: cubemap\n  time_of_day: 15\n  cubemap: [%s/tests/data/cube_px.png,"
                 " %s/tests/data/cube_nx.png, %s/tests/data/cube_py.png, %s/tests/data/cube_ny.png,"
                 " %s/tests/data/cube_pz.png, %s/tests/data/cube_nz.png]\n"
                 "camera:\n  far: 5\n  path:\n"
                 "    - {t: 0, position: [0, 500, 0], yaw: %g, pitch: %g}\n",
                 cwd, cwd, cwd, cwd, cwd, cwd, view[i].yaw, view[i].pitch);
        ENSURE(ww_test_write_text(scene, text) == 0);
        snprintf(out, sizeof out, "%s/face%d", dir, i);
        ENSURE_EQ_INT(ww_test_render(scene, "", out), 0);
        snprintf(png, sizeof png, "%s/frame_00000.png", out);
        unsigned char rgb[3];
        ENSURE(centre_pixel(png, rgb));
        for (int c = 0; c < 3; c++)
            ENSURE_MSG(view[i].rgb[c] ? rgb[c] > 128 : rgb[c] < 64,
                       "view along %s: centre (%d, %d, %d), expected the %s face's colour",
                       view[i].name, rgb[0], rgb[1], rgb[2], view[i].name);
    }
}

static void golden_of(const char *name) {
    const char *dir = ww_test_tmpdir(name);
    char scene[256], golden[256], png[600];
    snprintf(scene, sizeof scene, "scenes/features/%s.yaml", name);
    snprintf(golden, sizeof golden, "golden/features/%s.png", name);
    snprintf(png, sizeof png, "%s/frame_00000.png", dir);
    ENSURE_EQ_INT(ww_test_render(scene, "", dir), 0);
    ww_test_check_golden(golden, png);
}

TEST_IMAGE(assets_golden_skybox) {
    REQUIRE_GL();
    golden_of("skybox");
}

TEST_IMAGE(assets_golden_skydome) {
    REQUIRE_GL();
    golden_of("skydome");
}

/* the sky region: above the horizon of scenes/features/skybox.yaml's camera (measured: the
 * horizon crosses rows 66-69 of 144). 80% of its pixels change (measured); the rest are where
 * the gradient's blue and the skybox's happen to agree within the threshold */
static const double SKY_RECT[4] = {0.0, 0.0, 1.0, 0.44};
/* the water below the horizon: the sky reaches it only through the water's reflection (planar
 * reflection pass and cubemap lookup), so it changes too, but on fewer pixels than the sky:
 * measured 1-2% of the water moves by more than 40 levels (bright clouds and the sun reflected) */
static const double WATER_RECT[4] = {0.0, 0.56, 1.0, 1.0};
#define SKY_DIFF_THRESH 8    /* 8-bit levels: a pixel differs */
#define REFLECTION_THRESH 40 /* 8-bit levels: a reflected cloud or sun, not a tint */

TEST_IMAGE(assets_toggle_sky_gradient_vs_cubemap) {
    REQUIRE_GL();
    const char *dir = ww_test_tmpdir("assets_toggle_sky");
    char on[600], off[600], a[700], b[700];
    snprintf(on, sizeof on, "%s/on", dir);
    snprintf(off, sizeof off, "%s/off", dir);
    ENSURE_EQ_INT(ww_test_render("scenes/features/skybox.yaml", "", on), 0);
    ENSURE_EQ_INT(ww_test_render("scenes/features/skybox.yaml", "--set sky.model=gradient", off), 0);
    snprintf(a, sizeof a, "%s/frame_00000.png", on);
    snprintf(b, sizeof b, "%s/frame_00000.png", off);
    ww_test_region d;
    ENSURE_EQ_INT(ww_test_region_diff(a, b, SKY_RECT, SKY_DIFF_THRESH, &d), 0);
    ENSURE_MSG(d.inside > 0.7 * d.inside_px, "sky: %ld of %ld pixels changed", d.inside,
               d.inside_px);
    ww_test_region w;
    ENSURE_EQ_INT(ww_test_region_diff(a, b, WATER_RECT, REFLECTION_THRESH, &w), 0);
    ENSURE_MSG(w.inside > 0 && w.inside < 0.25 * w.inside_px,
               "water: %ld of %ld pixels moved by more than %d (max %d): expected the sky's "
               "reflection, not the sky",
               w.inside, w.inside_px, REFLECTION_THRESH, w.max_inside);
    /* the sky is drawn by the main pass: the plan keeps every pass either way */
    char plan_on[700], plan_off[700];
    snprintf(plan_on, sizeof plan_on, "%s/plan_on.txt", dir);
    snprintf(plan_off, sizeof plan_off, "%s/plan_off.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("plan scenes/features/skybox.yaml", plan_on, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww("plan scenes/features/skybox.yaml --set sky.model=gradient",
                             plan_off, NULL), 0);
    ENSURE(ww_test_file_contains(plan_on, "MAIN") || ww_test_file_contains(plan_on, "main"));
}
