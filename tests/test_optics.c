/* test_optics.c - the water's optics and the reflection pass: one golden per feature
 * (scenes/features/{reflection,refraction,foam,underwater,alpha_blend}.yaml), toggle tests (a
 * feature switched off changes its region of the picture and nothing else, and leaves the plan),
 * the Fresnel term against its formula read back from the HDR image, and Snell's window from
 * below.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/mathx.h"
#include "gfx/backend.h"
#include "io/writers.h"
#include "test.h"

#define TOGGLE_THRESH 2          /* 8-bit levels a pixel must move to count as changed */
#define FRESNEL_TOL 4e-3         /* relative: two half-float HDR values and their ratio */
#define SNELL_CONTRAST 20.0      /* 8-bit luminance levels the window's centre outshines the
                                  * totally reflecting water outside it by (after tone mapping) */

/* frame 0 of a feature scene with extra arguments into a fresh folder; its PNG path in out */
static int render_feature(const char *name, const char *tag, const char *args, char *out,
                          size_t cap) {
    char dir[512], scene[256], tmp[128];
    snprintf(tmp, sizeof tmp, "optics_%s_%s", name, tag);
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(tmp));
    snprintf(scene, sizeof scene, "scenes/features/%s.yaml", name);
    snprintf(out, cap, "%s/frame_00000.%s", dir, args && strstr(args, "exr") ? "exr" : "png");
    return ww_test_render(scene, args, dir);
}

static void check_feature_golden(const char *name) {
    char actual[700], golden[256];
    ENSURE_EQ_INT(render_feature(name, "golden", NULL, actual, sizeof actual), 0);
    snprintf(golden, sizeof golden, "golden/features/%s.png", name);
    ww_test_check_golden(golden, actual);
}

/* `plan SCENE [args]` lists a pass named `pass` */
static int plan_lists(const char *name, const char *args, const char *pass) {
    char a[512], out[600], needle[64];
    snprintf(out, sizeof out, "%s/plan.txt", ww_test_tmpdir("optics_plan"));
    snprintf(a, sizeof a, "plan scenes/features/%s.yaml %s", name, args ? args : "");
    if (ww_test_ww(a, out, NULL) != 0) return -1;
    snprintf(needle, sizeof needle, " %s ", pass);
    return ww_test_file_contains(out, needle);
}

TEST_IMAGE(optics_golden_reflection) {
    REQUIRE_GL();
    check_feature_golden("reflection");
}

TEST_IMAGE(optics_golden_foam) {
    REQUIRE_GL();
    check_feature_golden("foam");
}

TEST_IMAGE(optics_golden_underwater) {
    REQUIRE_GL();
    check_feature_golden("underwater");
}

TEST_IMAGE(optics_golden_alpha_blend) {
    REQUIRE_GL();
    check_feature_golden("alpha_blend");
}

TEST_IMAGE(optics_golden_refraction) {
    REQUIRE_GL();
    check_feature_golden("refraction");
}

/* reflection off: the water below the horizon changes (the mirrored sky, distorted, instead of
 * the sky along each reflected normal), the sky above it not at all, and the pass leaves the
 * plan. The camera looks 2 deg down with a 60 deg fov: the horizon lies 47% down the image. */
TEST_IMAGE(optics_toggle_reflection) {
    REQUIRE_GL();
    char on[700], off[700];
    ENSURE_EQ_INT(render_feature("reflection", "on", NULL, on, sizeof on), 0);
    ENSURE_EQ_INT(render_feature("reflection", "off", "--set render.reflection=false", off,
                                 sizeof off), 0);
    const double below[4] = {0.0, 0.45, 1.0, 1.0};
    ww_test_region d;
    ENSURE(ww_test_region_diff(on, off, below, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside > d.inside_px / 4, "%ld of %ld pixels below the horizon changed",
               d.inside, d.inside_px);
    ENSURE_MSG(d.outside == 0, "%ld pixels above the horizon changed (max %d)", d.outside,
               d.max_outside);
    ENSURE_EQ_INT(plan_lists("reflection", NULL, "reflection"), 1);
    ENSURE_EQ_INT(plan_lists("reflection", "--set render.reflection=false", "reflection"), 0);
}

/* refraction off (the seabed stays on): the water changes, the sky above the horizon (20% down
 * the image for a camera 20.6 deg down) does not, and the prepass leaves the plan */
TEST_IMAGE(optics_toggle_refraction) {
    REQUIRE_GL();
    ENSURE_EQ_INT(plan_lists("refraction", NULL, "prepass"), 1);
    ENSURE_EQ_INT(plan_lists("refraction", "--set render.refraction=false", "prepass"), 0);
    char on[700], off[700];
    ENSURE_EQ_INT(render_feature("refraction", "on", NULL, on, sizeof on), 0);
    ENSURE_EQ_INT(render_feature("refraction", "off", "--set render.refraction=false", off,
                                 sizeof off), 0);
    const double water[4] = {0.0, 0.18, 1.0, 1.0};
    ww_test_region d;
    ENSURE(ww_test_region_diff(on, off, water, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside > d.inside_px / 2, "%ld of %ld water pixels changed", d.inside,
               d.inside_px);
    ENSURE_MSG(d.outside == 0, "%ld sky pixels changed (max %d)", d.outside, d.max_outside);
}

/* foam off: only water pixels change (the camera looks 8 deg down: the horizon is 38% down),
 * and enough of them that the folds and steep crests are foamed */
TEST_IMAGE(optics_toggle_foam) {
    REQUIRE_GL();
    char on[700], off[700];
    ENSURE_EQ_INT(render_feature("foam", "on", NULL, on, sizeof on), 0);
    ENSURE_EQ_INT(render_feature("foam", "off", "--set water.look.foam=false", off, sizeof off),
                  0);
    const double water[4] = {0.0, 0.3, 1.0, 1.0};
    ww_test_region d;
    ENSURE(ww_test_region_diff(on, off, water, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside > d.inside_px / 50, "%ld of %ld water pixels foamed", d.inside,
               d.inside_px);
    ENSURE_MSG(d.outside == 0, "%ld sky pixels changed (max %d)", d.outside, d.max_outside);
}

/* the formula of water.look.fresnel for the cosine c between view and normal */
static double fresnel_formula(int schlick, double bias, double scale, double power, double c) {
    double m = 1.0 - c;
    if (schlick) return bias + (1.0 - bias) * pow(m, 5.0);
    double f = bias + scale * pow(m, power);
    return f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
}

/* the Fresnel term read back: flat water with a black body colour, no fog and no sun highlight
 * is F(v.n) times the reflected sky. A second render with F = 1 (bias 1, scale 0) gives the sky
 * alone, so the ratio of the two HDR images is F. The camera looks 45 deg down with a 90 deg fov:
 * row j's ray is atan(ndc_y) above the axis, and v.n = sin(its depression) on flat water spans
 * 0 (the horizon, top row) to 1 (straight down, bottom row). */
static void check_fresnel(int schlick, double bias, double scale, double power) {
    static const char *base =
        "--format exr --set water.waves.model=flat --set water.color=[0,0,0] "
        "--set fog.above.density=0 --set water.look.specular=0 --set render.reflection=false "
        "--set camera.fov=90 --set 'camera.path[0].position=[0,3,0]' "
        "--set 'camera.path[0].look_at=[0,0,-3]'";
    char args[1024], one[700], f[700];
    snprintf(args, sizeof args, "%s --set water.look.fresnel=bias_scale --set "
             "water.look.fresnel_bias=1 --set water.look.fresnel_scale=0", base);
    ENSURE_EQ_INT(render_feature("reflection", "fresnel_one", args, one, sizeof one), 0);
    snprintf(args, sizeof args, "%s --set water.look.fresnel=%s --set water.look.fresnel_bias=%g "
             "--set water.look.fresnel_scale=%g --set water.look.fresnel_power=%g", base,
             schlick ? "schlick" : "bias_scale", bias, scale, power);
    ENSURE_EQ_INT(render_feature("reflection", schlick ? "fresnel_s" : "fresnel_b", args, f,
                                 sizeof f), 0);
    ww_image a = {0}, b = {0};
    ww_error err = {0};
    ENSURE_MSG(ww_read_exr(one, &a, &err) == WW_OK, "%s", err.msg);
    ENSURE_MSG(ww_read_exr(f, &b, &err) == WW_OK, "%s", err.msg);
    if (!a.f32 || !b.f32) goto done;
    /* the centre column, from the bottom row (v.n = 1) up to 2 deg below the horizon */
    int checked = 0;
    double worst = 0.0;
    for (int j = a.height - 1; j >= 0; j--) {
        double ndc = 1.0 - 2.0 * (j + 0.5) / a.height;
        double dep = ww_m_rad(45.0) - atan(ndc);
        if (dep < ww_m_rad(2.0)) break;
        size_t i = ((size_t)j * (size_t)a.width + (size_t)(a.width / 2)) * (size_t)a.channels;
        double want = fresnel_formula(schlick, bias, scale, power, sin(dep));
        double got = (double)b.f32[i + 1] / (double)a.f32[i + 1]; /* green: the sky's brightest */
        double e = fabs(got - want) / want;
        if (e > worst) worst = e;
        ENSURE_NEAR(got / want, 1.0, FRESNEL_TOL);
        checked++;
        if (ww_test_failed_now()) break;
    }
    ENSURE(checked > a.height / 2);
    fprintf(stderr, "(%d rows, worst relative error %.2g) ", checked, worst);
done:
    ww_image_free(&a);
    ww_image_free(&b);
}

TEST_IMAGE(optics_fresnel_schlick_matches_formula) {
    REQUIRE_GL();
    check_fresnel(1, 0.02, 0.98, 5.0);
}

TEST_IMAGE(optics_fresnel_bias_scale_matches_formula) {
    REQUIRE_GL();
    check_fresnel(0, 0.1, 0.8, 2.5);
}

static double luminance(const ww_image *im, double fx, double fy) {
    int x = (int)(fx * (im->width - 1)), y = (int)(fy * (im->height - 1));
    const unsigned char *p = im->u8 + ((size_t)y * (size_t)im->width + (size_t)x) * (size_t)im->channels;
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/* from below, looking up: the sky shows through a bright disc around the zenith (the image's
 * centre) and the corners, 55 deg and more off the vertical, lie outside the 48.6 deg window in
 * total internal reflection; the same scene from above the water is another picture */
TEST_IMAGE(optics_underwater_snell_window) {
    REQUIRE_GL();
    char below[700], above[700];
    ENSURE_EQ_INT(render_feature("underwater", "below", NULL, below, sizeof below), 0);
    ENSURE_EQ_INT(render_feature("underwater", "above", "--set 'camera.path[0].position=[0,3,0]'",
                                 above, sizeof above), 0);
    ww_image im = {0};
    ww_error err = {0};
    ENSURE_MSG(ww_read_png(below, &im, &err) == WW_OK, "%s", err.msg);
    if (!im.u8) return;
    double centre = luminance(&im, 0.5, 0.5);
    double corners[4] = {luminance(&im, 0.02, 0.03), luminance(&im, 0.98, 0.03),
                         luminance(&im, 0.02, 0.97), luminance(&im, 0.98, 0.97)};
    for (int c = 0; c < 4; c++)
        ENSURE_MSG(centre > corners[c] + SNELL_CONTRAST, "centre %.1f, corner %d %.1f", centre, c,
                   corners[c]);
    ww_image_free(&im);
    const double all[4] = {0.0, 0.0, 1.0, 1.0};
    ww_test_region d;
    ENSURE(ww_test_region_diff(below, above, all, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside > d.inside_px / 2, "%ld of %ld pixels differ from above the water",
               d.inside, d.inside_px);
}

/* alpha blend off: the water turns opaque, so the seabed below stops showing: water pixels
 * change, the sky does not (the camera looks 12 deg down: the horizon is 31% down) */
TEST_IMAGE(optics_toggle_alpha_blend) {
    REQUIRE_GL();
    char on[700], off[700];
    ENSURE_EQ_INT(render_feature("alpha_blend", "on", NULL, on, sizeof on), 0);
    ENSURE_EQ_INT(render_feature("alpha_blend", "off", "--set water.look.alpha_blend=false", off,
                                 sizeof off), 0);
    const double water[4] = {0.0, 0.28, 1.0, 1.0};
    ww_test_region d;
    ENSURE(ww_test_region_diff(on, off, water, TOGGLE_THRESH, &d) == 0);
    ENSURE_MSG(d.inside > d.inside_px / 2, "%ld of %ld water pixels changed", d.inside,
               d.inside_px);
    ENSURE_MSG(d.outside == 0, "%ld sky pixels changed (max %d)", d.outside, d.max_outside);
}

/* render.grid scales the water mesh's rings and segments; the plan says so */
TEST_PROC(optics_grid_scales_mesh) {
    char out[600];
    snprintf(out, sizeof out, "%s/plan.txt", ww_test_tmpdir("optics_grid"));
    ENSURE_EQ_INT(ww_test_ww("plan scenes/features/reflection.yaml --set render.grid=2", out, NULL),
                  0);
    ENSURE(ww_test_file_contains(out, "320 rings x 512 segments") == 1);
    ENSURE_EQ_INT(ww_test_ww("plan scenes/features/reflection.yaml", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "160 rings x 256 segments") == 1);
}

/* EGL and OSMesa give the same bytes for the optics (the noise is integer hashes of positions) */
TEST_IMAGE(optics_backends_identical) {
    REQUIRE_BACKEND(WW_BACKEND_EGL);
    REQUIRE_BACKEND(WW_BACKEND_OSMESA);
    char egl[700], osm[700];
    if (render_feature("foam", "egl", "--backend egl --set render.reflection=true", egl,
                       sizeof egl) != 0 ||
        render_feature("foam", "osmesa", "--backend osmesa --set render.reflection=true", osm,
                       sizeof osm) != 0) {
        ENSURE_MSG(0, "a render on one of the backends failed");
        return;
    }
    const double all[4] = {0.0, 0.0, 1.0, 1.0};
    ww_test_region d;
    ENSURE(ww_test_region_diff(egl, osm, all, 0, &d) == 0);
    ENSURE_MSG(d.inside == 0, "%ld pixels differ between EGL and OSMesa", d.inside);
}
