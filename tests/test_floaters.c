/* test_floaters.c - floating models (objects.models[].float, sim/floaters.c): a `mesh: box`
 * model passes the cubes' draft and heave oracles (tests/test_cubes.c) side by side with a cube
 * of the same size and density; a long box floats at the draft of its own edges; a small light
 * raft on a long swell keeps its up axis along the surface normal; children and the camera
 * follow the floating box; bad input; the rendered feature scene: the buoy heaves between
 * frames and sits on the waterline.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "io/image.h"
#include "io/writers.h"
#include "sim/collide.h"
#include "sim/floaters.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "test.h"

/* the cubes' oracles (tests/test_cubes.c): draft within 1% of (rho / rho_w) H, heave period
 * within 5% of 2 pi sqrt(d / g), amplitude never grows beyond rounding */
#define DRAFT_REL_TOL 0.01
#define HEAVE_PERIOD_REL_TOL 0.05
#define HEAVE_AMPLITUDE_GROWTH_TOL 1e-9
/* a floating box and a cube of the same size and density: the same physics, to rounding in
 * the inertia's composition (R I^-1 R^T against a scalar), m */
#define SAME_AS_CUBE_TOL 1e-9
/* a 0.4 x 0.1 x 0.4 m raft (density 300) on a 40 m swell, 0.5 m high: the largest angle
 * between its up axis and the surface normal under its centre after the start, rad (the swell's
 * steepest slope is atan(k A) = 4.5 deg) */
#define TILT_FOLLOW_TOL ww_m_rad(1.0)
/* the rendered buoy: its mask's centroid moves at least this much between frames 36 and 84
 * (half the 16 m swell's period of 3.2 s apart), px at 256x144 */
#define HEAVE_MIN_PX 5.0
/* its mask's lowest row lies within this of the projected waterline under it, px */
#define WATERLINE_TOL_PX 3.0
/* the crate's child lamp (emissive): the brightest pixel near where the crate's simulated frame
 * puts it lies within this of it, px, and is this bright (8-bit luma) */
#define LAMP_TOL_PX 2.5
#define LAMP_MIN_LUMA 200.0
#define LAMP_UP 1.45 /* the lamp's position in the crate's frame, m (floating_models.yaml) */

static ww_scene *load(const char *text) { return ww_test_scene_text("floaters.yaml", text); }

static void run(const ww_scene *sc, ww_state *st, int steps) {
    ww_error err = {0};
    for (int n = 0; n < steps; n++) {
        ww_result r = ww_step(sc, st, &err);
        ENSURE_MSG(r == WW_OK, "step %d: %s", n, err.msg);
        if (r != WW_OK) return;
    }
}

/* the angle between floater j's axis nearest the vertical and the direction d, rad */
static double axis_angle(const ww_state *st, int j, const double d[3]) {
    const double *q = st->floater_rot + 4 * j;
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double ax[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                       {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                       {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
    double best = 0.0;
    for (int k = 0; k < 3; k++) best = fmax(best, fabs(ww_m_dot3(ax[k], d)));
    return acos(fmin(1.0, best));
}

TEST(floaters_box_model_draft_matches_density_ratio_and_the_cube) {
    const double rho[] = {100, 150, 200, 800, 900, 950}, size[] = {1, 0.5, 2, 1, 0.3, 1.5};
    char text[8192];
    int n = snprintf(text, sizeof text,
                     "time: {dt: 1/120, fps: 30, duration: 30}\nwater: {depth: 50}\n"
                     "camera: {collide: false}\nobjects:\n  models:\n");
    for (int i = 0; i < 6; i++)
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "    - {mesh: box, position: [%g, 0.5, 0], scale: %g, "
                      "float: {density: %g, drag: {linear: 5}}}\n",
                      4.0 * i, size[i], rho[i]);
    n += snprintf(text + n, sizeof text - (size_t)n, "  cubes:\n");
    for (int i = 0; i < 6; i++)
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "    - {position: [%g, 0.5, 20], size: %g, density: %g, drag: {linear: 5}}\n",
                      4.0 * i, size[i], rho[i]);
    ww_scene *sc = load(text);
    if (!sc) return;
    ENSURE_EQ_INT(sc->floaters.count, 6);
    ww_state *st = ww_state_new(sc);
    run(sc, st, 120 * 30);
    const double up[3] = {0.0, 1.0, 0.0};
    for (int i = 0; i < 6; i++) {
        double draft = sc->water_level - (st->floater_pos[3 * i + 1] - 0.5 * size[i]);
        ENSURE_NEAR(draft / (rho[i] / 1000.0 * size[i]), 1.0, DRAFT_REL_TOL);
        ENSURE(axis_angle(st, i, up) < 1e-6);
        ENSURE_NEAR(st->floater_pos[3 * i + 1], st->cube_pos[3 * i + 1], SAME_AS_CUBE_TOL);
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

/* a box with unequal edges floats at the draft of its vertical edge */
TEST(floaters_long_box_draft_of_its_height) {
    ww_scene *sc = load("time: {dt: 1/120, fps: 30, duration: 30}\nwater: {depth: 50}\n"
                        "camera: {collide: false}\nobjects:\n  models:\n"
                        "    - {mesh: box, position: [0, 0, 0], scale: [2, 0.4, 0.8], "
                        "float: {density: 300, drag: {linear: 5}}}\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    run(sc, st, 120 * 30);
    double draft = -(st->floater_pos[1] - 0.2);
    ENSURE_NEAR(draft / (0.3 * 0.4), 1.0, DRAFT_REL_TOL);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* the cubes' heave oracle on a floating box and on a cube, released 0.1 m below equilibrium */
static void heave(double rho, const char *dt, double dtv, int floater, double *period,
                  double *peak, double *d_out) {
    double s = 1.0, d = rho / 1000.0 * s, y_eq = 0.5 * s - d;
    char text[2048];
    if (floater)
        snprintf(text, sizeof text,
                 "time: {dt: %s, fps: %g, duration: 12}\nwater: {depth: 50}\ncamera: {collide: "
                 "false}\nobjects:\n  models:\n    - {mesh: box, position: [0, %.17g, 0], "
                 "float: {density: %g, drag: {linear: 0, quadratic: 0, angular: 0}}}\n",
                 dt, 1.0 / dtv, y_eq - 0.1, rho);
    else
        snprintf(text, sizeof text,
                 "time: {dt: %s, fps: %g, duration: 12}\nwater: {depth: 50}\ncamera: {collide: "
                 "false}\nobjects:\n  cubes:\n    - {position: [0, %.17g, 0], size: 1, "
                 "density: %g, drag: {linear: 0, quadratic: 0, angular: 0}}\n",
                 dt, 1.0 / dtv, y_eq - 0.1, rho);
    ww_scene *sc = load(text);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    double prev = -0.1, t_first = -1, t_last = -1;
    int crossings = 0;
    *peak = 0.0;
    for (int n = 1; n * dtv <= 12.0; n++) {
        run(sc, st, 1);
        double x = (floater ? st->floater_pos[1] : st->cube_pos[1]) - y_eq;
        *peak = fmax(*peak, fabs(x));
        if (prev < 0.0 && x >= 0.0) {
            double t = (n - 1 + prev / (prev - x)) * dtv;
            if (crossings == 0) t_first = t;
            t_last = t;
            crossings++;
        }
        prev = x;
    }
    *period = (t_last - t_first) / (crossings - 1);
    *d_out = d;
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(floaters_heave_period_matches_closed_form_like_the_cube) {
    const double rho[] = {800, 200, 900};
    const char *dts[] = {"1/120", "1/30"};
    const double dtv[] = {1.0 / 120.0, 1.0 / 30.0};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 2; b++) {
            double pf, kf, pc, kc, d;
            heave(rho[a], dts[b], dtv[b], 1, &pf, &kf, &d);
            heave(rho[a], dts[b], dtv[b], 0, &pc, &kc, &d);
            double want = WW_TAU * sqrt(d / WW_G);
            ENSURE_NEAR(pf / want, 1.0, HEAVE_PERIOD_REL_TOL);
            ENSURE_MSG(kf <= 0.1 * (1.0 + HEAVE_AMPLITUDE_GROWTH_TOL),
                       "rho %g dt %g: peak excursion %.17g > 0.1", rho[a], dtv[b], kf);
            ENSURE_NEAR(pf, pc, SAME_AS_CUBE_TOL);
            ENSURE_NEAR(kf, kc, SAME_AS_CUBE_TOL);
        }
}

TEST(floaters_small_light_raft_tilts_with_the_surface_normal) {
    ww_scene *sc = load("time: {dt: 1/120, fps: 30, duration: 20}\nwater:\n  depth: 50\n"
                        "  waves: {model: gerstner, list: [{direction: 0, wavelength: 40, "
                        "amplitude: 0.5, steepness: 0.3}]}\n"
                        "camera: {collide: false}\nobjects:\n  models:\n"
                        "    - {mesh: box, position: [0, 0, 0], scale: [0.4, 0.1, 0.4], "
                        "float: {density: 300}}\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    run(sc, st, 120 * 5); /* the start's transient out */
    double worst = 0.0, steepest = 0.0;
    for (int n = 0; n < 120 * 10; n++) {
        run(sc, st, 1);
        ww_water_sample ws;
        ww_water_at(sc, st, st->floater_pos[0], st->floater_pos[2], 0.0, &ws);
        worst = fmax(worst, axis_angle(st, 0, ws.normal));
        steepest = fmax(steepest, acos(ws.normal[1]));
    }
    ENSURE(steepest > ww_m_rad(3.0)); /* the swell does tilt it */
    ENSURE_MSG(worst < ww_test_tol(TILT_FOLLOW_TOL), "worst %g deg (slope up to %g deg)",
               worst * 180 / WW_PI, steepest * 180 / WW_PI);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* ---- the rendered feature scene --------------------------------------------------------- */

#define FEATURE "scenes/features/floating_models.yaml"
#define BALL 1 /* the red buoy: objects.models[3], the second floater */

/* the red buoy's pixels: red well above green and blue */
static int is_ball(const ww_image *im, int x, int y) {
    const unsigned char *c = ww_test_pixel(im, x, y);
    return c[0] > 60 && c[0] > 2 * c[1] && c[0] > 2 * c[2];
}

typedef struct mask_stats {
    long n;
    double cy;   /* centroid row */
    int bottom;  /* lowest row */
} mask_stats;

static mask_stats ball_mask(const ww_image *im) {
    mask_stats m = {0, 0.0, -1};
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            if (is_ball(im, x, y)) {
                m.n++;
                m.cy += y;
                if (y > m.bottom) m.bottom = y;
            }
    if (m.n) m.cy /= (double)m.n;
    return m;
}

static double row_of(const ww_scene *sc, const ww_state *st, const double p[3]) {
    double px[2];
    ww_test_project(sc, st, p, px);
    return px[1];
}

/* the brightest pixel's distance from (x, y) within a window of half-size r, and its luma */
static double brightest_near(const ww_image *im, double x, double y, int r, double *luma) {
    double best = -1.0, dist = 1e9;
    for (int j = (int)y - r; j <= (int)y + r; j++)
        for (int i = (int)x - r; i <= (int)x + r; i++) {
            if (i < 0 || j < 0 || i >= im->width || j >= im->height) continue;
            const unsigned char *c = ww_test_pixel(im, i, j);
            double l = 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
            if (l > best) {
                best = l;
                dist = hypot(i + 0.5 - x, j + 0.5 - y);
            }
        }
    *luma = best;
    return dist;
}

TEST_IMAGE(floaters_rendered_buoy_heaves_and_sits_on_the_waterline) {
    REQUIRE_GL();
    char dir[512], cmd[1024], path[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("fm"));
    const int frames[2] = {36, 84};
    for (int k = 0; k < 2; k++) {
        snprintf(cmd, sizeof cmd, "render " FEATURE " --frames %d:%d -o %s --quiet", frames[k],
                 frames[k] + 1, dir);
        ENSURE_EQ_INT(ww_test_ww(cmd, NULL, NULL), 0);
    }
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load(FEATURE, NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    mask_stats m[2];
    for (int k = 0; k < 2; k++) {
        run(sc, st, (int)(frames[k] * sc->steps_per_frame) - (int)st->step);
        ww_image im = {0};
        snprintf(path, sizeof path, "%s/frame_%05d.png", dir, frames[k]);
        ENSURE_MSG(ww_read_png(path, &im, &err) == WW_OK, "%s: %s", path, err.msg);
        m[k] = ball_mask(&im);
        /* a child rides on its floating parent: the lamp on the crate's mast */
        double pose[16], lamp[3], lp[2], luma;
        ww_floater_pose(sc, st, 0, pose);
        for (int a = 0; a < 3; a++) lamp[a] = pose[12 + a] + pose[4 + a] * LAMP_UP;
        ww_test_project(sc, st, lamp, lp);
        double off = brightest_near(&im, lp[0], lp[1], 6, &luma);
        fprintf(stderr, "frame %d: lamp %.2f px from its place (luma %.0f) at (%.1f, %.1f)\n",
                frames[k], off, luma, lp[0], lp[1]);
        ENSURE_MSG(off < LAMP_TOL_PX && luma > LAMP_MIN_LUMA,
                   "frame %d: brightest pixel %.2f px from the lamp's place, luma %.0f",
                   frames[k], off, luma);
        ww_image_free(&im);
        ENSURE_MSG(m[k].n > 50, "frame %d: %ld buoy pixels", frames[k], m[k].n);
        /* the waterline in front of the buoy: where its sphere (the mesh in its box) meets the
         * surface nearest the camera */
        const double *c = st->floater_pos + 3 * BALL;
        double radius = 0.45, sag;
        ww_water_sample ws;
        ww_water_at(sc, st, c[0], c[2], 0.0, &ws);
        sag = ws.height - c[1];
        ENSURE_MSG(fabs(sag) < radius, "frame %d: buoy centre %g m from the surface", frames[k],
                   sag);
        double front = sqrt(fmax(0.0, radius * radius - sag * sag));
        ww_water_at(sc, st, c[0], c[2] + front, 0.0, &ws);
        double p[3] = {c[0], ws.height, c[2] + front};
        double want = row_of(sc, st, p);
        ENSURE_MSG(fabs(m[k].bottom - want) < WATERLINE_TOL_PX,
                   "frame %d: buoy's lowest row %d, waterline row %.2f", frames[k], m[k].bottom,
                   want);
    }
    ENSURE_MSG(fabs(m[1].cy - m[0].cy) > HEAVE_MIN_PX, "buoy centroid rows %.2f, %.2f", m[0].cy,
               m[1].cy);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST_IMAGE(floaters_golden_floating_models) {
    REQUIRE_GL();
    char dir[512], actual[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("golden"));
    ENSURE(ww_test_render(FEATURE, NULL, dir) == 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden("golden/features/floating_models.png", actual);
}

/* the camera stops at a floating box where it floats now, and at nothing where it was written */
TEST(floaters_camera_collides_with_the_floating_box) {
    ww_scene *sc = load("time: {dt: 1/120, fps: 30, duration: 4}\nwater: {depth: 50}\n"
                        "camera:\n  collide: true\n  path:\n"
                        "    - {t: 0, position: [0, 0, 0], look_at: [0, 0, -10]}\n"
                        "    - {t: 4, position: [0, 0, -10], look_at: [0, 0, -20]}\n"
                        "objects:\n  models:\n"
                        "    - {mesh: box, position: [0, 3, -5], scale: 1, "
                        "float: {density: 500, drag: {linear: 5}}}\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    run(sc, st, 120 * 4);
    /* the box fell from y = 3 to the water: it now straddles the camera's path at y = 0 */
    ENSURE_NEAR(st->floater_pos[1], 0.0, 0.05);
    ENSURE(st->cam_pos[2] > -5.0 + 0.5 - 1e-3 - 0.05);
    ENSURE_EQ_INT(st->collide_state[0], WW_SOLID_MODEL + 1);
    ww_state_free(st);
    ww_scene_free(sc);
}
