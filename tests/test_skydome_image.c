/* test_skydome_image.c - the dome's picture (sky.image): the mapping measured on rendered frames
 * with a test picture of flat colours (four quadrants around a centre disc: which direction sees
 * which texel), its reflection in the water, and the bad inputs (a missing file, a wrong type, a
 * picture without the dome), each an error at its file:line:column with exit 2.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/writers.h"
#include "scene/scene.h"
#include "test.h"

#define DOME_TEST_SIDE 64
#define DOME_DISC_RADIUS 0.25 /* of the side: the zenith's disc reaches 45 deg from the zenith */
#define DOME_ON 230           /* the test picture's levels (sRGB): a channel on ... */
#define DOME_OFF 10           /* ... and off */
#define DOME_TEXEL_TOL 20     /* 8-bit levels between a sky pixel and the texel it looks at, at
                               * most: intensity 1, the exp tone curve at exposure 1 and the sun's
                               * glow move a mid-bright texel by up to 10 (measured) */
#define DOME_REFLECT_MARGIN 20.0 /* levels by which the water facing the green quadrant is
                                  * greener (G - R) than the water facing the red one */

/* the test picture, 1 where a channel is on: top-left red, top-right green, bottom-left blue,
 * bottom-right yellow, the centre disc magenta */
static void test_texel(int i, int j, unsigned char rgb[3]) {
    static const unsigned char quad[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    double x = (i + 0.5) / DOME_TEST_SIDE - 0.5, y = (j + 0.5) / DOME_TEST_SIDE - 0.5;
    if (x * x + y * y < DOME_DISC_RADIUS * DOME_DISC_RADIUS) {
        rgb[0] = 1, rgb[1] = 0, rgb[2] = 1;
        return;
    }
    memcpy(rgb, quad[(y > 0.0) * 2 + (x > 0.0)], 3);
}

static int write_test_picture(const char *path) {
    ww_image im;
    if (ww_image_alloc(&im, DOME_TEST_SIDE, DOME_TEST_SIDE, 3, WW_PIX_U8) != 0) return 0;
    for (int j = 0; j < DOME_TEST_SIDE; j++)
        for (int i = 0; i < DOME_TEST_SIDE; i++) {
            unsigned char t[3];
            test_texel(i, j, t);
            for (int c = 0; c < 3; c++)
                im.u8[(j * DOME_TEST_SIDE + i) * 3 + c] = t[c] ? DOME_ON : DOME_OFF;
        }
    ww_error err = {0};
    int ok = ww_write_png(path, &im, &err) == WW_OK;
    ww_image_free(&im);
    return ok;
}

static int pixel_at(const char *png, double fx, double fy, unsigned char rgb[3]) {
    ww_image im;
    ww_error err = {0};
    if (ww_read_png(png, &im, &err) != WW_OK) return 0;
    memcpy(rgb, ww_test_pixel(&im, (int)(fx * im.width), (int)(fy * im.height)), 3);
    ww_image_free(&im);
    return 1;
}

/* render a 64x64 view of the picture's dome (its file named relative to the scene's folder) from 500 m up (the far plane at 5 m: no water),
 * or from 2 m over the water (far: 0), yawed and pitched; frame in png */
static int render_view(const char *dir, const char *picture, int k, double yaw, double pitch,
                       double height, const char *far, char *png, size_t cap) {
    char scene[700], text[2048], out[700];
    snprintf(scene, sizeof scene, "%s/view%d.yaml", dir, k);
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 1}\n"
             "render: {size: [64, 64], shadows: false, refraction: false, reflection: true,\n"
             "         bloom: false, god_rays: false, fxaa: false, msaa: 0, seabed: false}\n"
             "sky: {model: dome, image: %s, time_of_day: 15, intensity: 1}\n"
             "water:\n  look: {foam: false, caustics: false, alpha_blend: false}\n"
             "  waves: {model: flat}\n"
             "camera:\n  %s\n  path:\n    - {t: 0, position: [0, %g, 0], yaw: %g, pitch: %g}\n",
             picture, far, height, yaw, pitch);
    ENSURE(ww_test_write_text(scene, text) == 0);
    snprintf(out, sizeof out, "%s/view%d", dir, k);
    int rc = ww_test_render(scene, "", out);
    ENSURE_EQ_INT(rc, 0);
    snprintf(png, cap, "%s/frame_00000.png", out);
    return rc == 0;
}

/* the picture's centre is the zenith, its inscribed circle the horizon, its top -z, its right
 * +x: a view toward each quadrant's azimuth 20 deg up sees that quadrant's texel, a view 70 deg
 * up the centre disc's, within DOME_TEXEL_TOL after the tone curve */
TEST_IMAGE(skydome_image_mapping) {
    REQUIRE_GL();
    static const struct {
        const char *name;
        double yaw, pitch;
        unsigned char rgb[3];
    } view[5] = {{"north-west (top-left)", -45, 20, {1, 0, 0}},
                 {"north-east (top-right)", 45, 20, {0, 1, 0}},
                 {"south-west (bottom-left)", -135, 20, {0, 0, 1}},
                 {"south-east (bottom-right)", 135, 20, {1, 1, 0}},
                 {"near the zenith (centre)", 30, 70, {1, 0, 1}}};
    const char *dir = ww_test_tmpdir("skydome_image_mapping");
    char picture[700];
    ENSURE(dir != NULL);
    if (!dir) return;
    snprintf(picture, sizeof picture, "%s/quadrants.png", dir);
    ENSURE(write_test_picture(picture));
    for (int i = 0; i < 5; i++) {
        char png[800];
        unsigned char rgb[3];
        if (!render_view(dir, "quadrants.png", i, view[i].yaw, view[i].pitch, 500, "far: 5", png,
                         sizeof png))
            return;
        ENSURE(pixel_at(png, 0.5, 0.5, rgb));
        fprintf(stderr, "    %s: (%d, %d, %d)\n", view[i].name, rgb[0], rgb[1], rgb[2]);
        for (int c = 0; c < 3; c++)
            ENSURE_MSG(abs((int)rgb[c] - (view[i].rgb[c] ? DOME_ON : DOME_OFF)) <= DOME_TEXEL_TOL,
                       "view %s: centre (%d, %d, %d), expected the picture's (%d, %d, %d)",
                       view[i].name, rgb[0], rgb[1], rgb[2], view[i].rgb[0], view[i].rgb[1],
                       view[i].rgb[2]);
    }
}

/* the water mirrors the picture: looking down 20 deg toward the green quadrant, the calm water
 * is greener than looking toward the red one */
TEST_IMAGE(skydome_image_reflected) {
    REQUIRE_GL();
    const char *dir = ww_test_tmpdir("skydome_image_reflected");
    char picture[700], png[2][800];
    ENSURE(dir != NULL);
    if (!dir) return;
    snprintf(picture, sizeof picture, "%s/quadrants.png", dir);
    ENSURE(write_test_picture(picture));
    double g_minus_r[2];
    for (int k = 0; k < 2; k++) {
        if (!render_view(dir, "quadrants.png", k, k == 0 ? 45 : -45, -20, 2, "far: 2000", png[k],
                         sizeof png[k]))
            return;
        unsigned char rgb[3];
        ENSURE(pixel_at(png[k], 0.5, 0.5, rgb));
        g_minus_r[k] = (double)rgb[1] - rgb[0];
    }
    fprintf(stderr, "    water toward the green quadrant G - R %.0f, toward the red one %.0f\n",
            g_minus_r[0], g_minus_r[1]);
    ENSURE_MSG(g_minus_r[0] - g_minus_r[1] >= DOME_REFLECT_MARGIN, "%.0f < %g",
               g_minus_r[0] - g_minus_r[1], DOME_REFLECT_MARGIN);
}

/* the far water fades into the picture's own horizon: the reef's first frame looks over the open
 * sea at the dome's horizon. With the procedural sky's horizon as the fog colour the farthest
 * water drew a grey line one pixel high under the picture's horizon (its row 31 levels darker
 * than the rows 2 above and below, at 640x360) */
#define HORIZON_LINE_DIP 4.0 /* 8-bit levels a row's mean luma may fall below both rows
                              * HORIZON_LINE_SPAN away, at most */
#define HORIZON_LINE_SPAN 2
TEST_IMAGE(skydome_image_no_line_at_the_horizon) {
    REQUIRE_GL();
    const char *dir = ww_test_tmpdir("skydome_image_no_line");
    ENSURE(dir != NULL);
    if (!dir) return;
    ENSURE_EQ_INT(ww_test_render("scenes/reef.yaml", "--size 640x360", dir), 0);
    char png[800];
    snprintf(png, sizeof png, "%s/frame_00000.png", dir);
    ww_image im;
    ww_error err = {0};
    ENSURE_MSG(ww_read_png(png, &im, &err) == WW_OK, "%s", err.msg);
    if (!im.u8) return;
    double *row = calloc((size_t)im.height, sizeof *row);
    ENSURE(row != NULL);
    if (row) {
        for (int y = 0; y < im.height; y++) {
            for (int x = 0; x < im.width; x++) {
                const unsigned char *p = ww_test_pixel(&im, x, y);
                row[y] += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            }
            row[y] /= im.width;
        }
        double worst = 0.0;
        int at = -1;
        for (int y = HORIZON_LINE_SPAN; y < im.height - HORIZON_LINE_SPAN; y++) {
            double up = row[y - HORIZON_LINE_SPAN], dn = row[y + HORIZON_LINE_SPAN];
            double dip = (up < dn ? up : dn) - row[y];
            if (dip > worst) worst = dip, at = y;
        }
        fprintf(stderr, "    deepest row dip %.1f levels (row %d)\n", worst, at);
        ENSURE_MSG(worst <= HORIZON_LINE_DIP, "row %d is %.1f levels darker than its neighbours",
                   at, worst);
        free(row);
    }
    ww_image_free(&im);
}

/* bad input: file:line:column, exit 2 */
static void bad_sky(const char *name, const char *sky_line, int column, const char *what) {
    const char *dir = ww_test_tmpdir(name);
    char scene[700], text[1024], cmd[1600], errp[800];
    snprintf(scene, sizeof scene, "%s/%s.yaml", dir, name);
    snprintf(text, sizeof text, "time: {dt: 1/120, fps: 30, duration: 1}\n%s\n", sky_line);
    ENSURE(ww_test_write_text(scene, text) == 0);
    snprintf(cmd, sizeof cmd, "plan %s", scene);
    snprintf(errp, sizeof errp, "%s/stderr.txt", dir);
    ENSURE_EQ_INT(ww_test_ww(cmd, NULL, errp), 2);
    size_t len = 0;
    char *msg = ww_test_read_file(errp, &len);
    char where[800];
    snprintf(where, sizeof where, "%s:2:%d", scene, column);
    ENSURE_MSG(msg && strstr(msg, where), "%s: expected '%s' in: %s", what, where, msg ? msg : "");
    free(msg);
}

TEST_PROC(skydome_image_bad_input) {
    bad_sky("dome_missing", "sky: {model: dome, image: no_such_sky.png}", 27, "a missing file");
    bad_sky("dome_type", "sky: {model: dome, image: [1, 2]}", 27, "a list");
    bad_sky("dome_model", "sky: {model: gradient, image: sky.png}", 31, "no dome");
}
