/* test_picture_lantern.c - seed 003's lantern under water measured on rendered frames
 * (scenes/features/lantern.yaml and small variants): the spot's glow in the water (the lights'
 * in-scattering: the cone brighter and redder with it than without, nothing changed outside the
 * cone), a lantern under the surface lighting the surface from below and from above, and the
 * flicker: deterministic in simulated time and large enough to see on the hull it lights.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/render_impl.h"
#include "io/writers.h"
#include "scene/scene.h"
#include "test.h"

#define LANTERN_SCENE "scenes/features/lantern.yaml"

/* lantern.yaml frame 0 at 256x144: the lantern at (0.505, 0.32) of the frame, its cone running
 * down past the hull's top edge (about 0.46 down there) onto the hull's side and the seabed; a
 * patch of the cone above that edge where the ray meets only water, two patches of open water
 * well away from the cone, and the patch the cone lights on the hull's side */
static const double CONE_PATCH[4] = {0.515, 0.37, 0.54, 0.42};   /* x0 y0 x1 y1, fractions */
static const double OUTSIDE_PATCH[2][4] = {{0.03, 0.05, 0.33, 0.30}, {0.70, 0.05, 0.97, 0.30}};
static const double HULL_PATCH[4] = {0.52, 0.52, 0.56, 0.64};
#define CONE_MIN_LIFT 8.0       /* 8-bit red the glow adds to the cone's patch, at least */
#define CONE_MIN_REDDER 4.0     /* ... more than it adds to its blue (a red lantern) */
#define OUTSIDE_MAX_CHANGE 0.5  /* mean |change| of 8-bit levels outside the cone, at most */
#define SURFACE_MIN_LIFT 4.0    /* 8-bit luma a lantern 1.5 m under the surface adds to the
                                 * surface above it, seen from below and from above */
#define FLICKER_FRAMES 15       /* frames measured (half a second at 30 fps) */
#define FLICKER_MIN_VARIATION 0.08 /* (max - min) / mean of the hull's lit luma over them */

typedef ww_test_pic pic;

/* mean of channel ch (0..2; 3: luma) over a patch of image fractions */
static double mean_of(const pic *p, const double r[4], int ch) {
    double s = 0.0;
    long n = 0;
    for (int y = (int)(r[1] * p->h); y < (int)(r[3] * p->h); y++)
        for (int x = (int)(r[0] * p->w); x < (int)(r[2] * p->w); x++, n++) {
            const uint8_t *c = ww_test_pixel(&p->im, x, y);
            s += ch < 3 ? c[ch] : 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
        }
    return n ? s / (double)n : 0.0;
}

/* mean |a - b| over a patch, all three channels */
static double mean_change(const pic *a, const pic *b, const double r[4]) {
    double s = 0.0;
    long n = 0;
    for (int y = (int)(r[1] * a->h); y < (int)(r[3] * a->h); y++)
        for (int x = (int)(r[0] * a->w); x < (int)(r[2] * a->w); x++)
            for (int c = 0; c < 3; c++, n++)
                s += fabs((double)ww_test_pixel(&a->im, x, y)[c] - ww_test_pixel(&b->im, x, y)[c]);
    return n ? s / (double)n : 0.0;
}

/* the cone glows: where the view ray crosses it and meets only water, red rises (and more than
 * blue) with the in-scattering on; away from the cone nothing changes */
TEST_IMAGE(lantern_cone_glows_in_the_water) {
    REQUIRE_GL();
    pic on, off;
    if (!ww_test_render_pic(LANTERN_SCENE, 0, "256x144", NULL, "lantern_on", &on)) return;
    if (!ww_test_render_pic(LANTERN_SCENE, 0, "256x144", "--set lights[0].scatter=0",
                            "lantern_off", &off)) return;
    double red = mean_of(&on, CONE_PATCH, 0) - mean_of(&off, CONE_PATCH, 0);
    double blue = mean_of(&on, CONE_PATCH, 2) - mean_of(&off, CONE_PATCH, 2);
    double out0 = mean_change(&on, &off, OUTSIDE_PATCH[0]);
    double out1 = mean_change(&on, &off, OUTSIDE_PATCH[1]);
    fprintf(stderr, "    cone: red +%.1f, blue +%.1f levels; outside: %.2f, %.2f levels\n", red,
            blue, out0, out1);
    ENSURE_MSG(red >= CONE_MIN_LIFT, "cone red lift %.1f < %g", red, CONE_MIN_LIFT);
    ENSURE_MSG(red - blue >= CONE_MIN_REDDER, "cone redder by %.1f < %g", red - blue,
               CONE_MIN_REDDER);
    ENSURE_MSG(out0 <= OUTSIDE_MAX_CHANGE && out1 <= OUTSIDE_MAX_CHANGE,
               "outside the cone changed by %.2f, %.2f > %g", out0, out1, OUTSIDE_MAX_CHANGE);
    ww_image_free(&on.im);
    ww_image_free(&off.im);
}

/* a point lantern 1.5 m under the surface lights the surface over it: seen from 4 m below
 * (its underside: the water under it and the mirror of total internal reflection) and from
 * 3 m above (what crosses the surface into the water's glow); its own glow in the water is off
 * (scatter 0), so only the surface's light is measured */
static const char UNDER_TEXT[] =
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {shadows: false, refraction: false, reflection: false, bloom: false,\n"
    "         god_rays: false, fxaa: false, msaa: 0, seabed: false}\n"
    "sky: {model: gradient, time_of_day: 19, day_length: 0}\n"
    "fog: {below: {color: [0.03, 0.14, 0.18], density: 0.06}}\n"
    "water:\n"
    "  depth: 10\n"
    "  look: {caustics: false, foam: false, alpha_blend: false}\n"
    "  waves: {model: gerstner, list: [{direction: 20, wavelength: 8, amplitude: 0.05,\n"
    "                                   steepness: 0.4}]}\n"
    "lights: [{type: point, position: [0, -1.5, -3], color: [1, 0.15, 0.05], intensity: 20,\n"
    "          range: 8, scatter: 0}]\n";

static void surface_lift(const char *name, const char *camera, double *lift) {
    char text[2048], path[1024];
    snprintf(text, sizeof text, "%scamera: {fov: 60, path: [{t: 0, %s}]}\n", UNDER_TEXT, camera);
    snprintf(path, sizeof path, "%s/%s.yaml", ww_test_tmpdir(name), name);
    ENSURE(ww_test_write_text(path, text) == 0);
    char on_dir[128], off_dir[128];
    snprintf(on_dir, sizeof on_dir, "%s_on", name);
    snprintf(off_dir, sizeof off_dir, "%s_off", name);
    pic on, off;
    *lift = 0.0;
    if (!ww_test_render_pic(path, 0, "256x144", NULL, on_dir, &on)) return;
    if (!ww_test_render_pic(path, 0, "256x144", "--set lights[0].intensity=0", off_dir,
                            &off)) return;
    static const double centre[4] = {0.4, 0.35, 0.6, 0.65};
    *lift = mean_of(&on, centre, 3) - mean_of(&off, centre, 3);
    ww_image_free(&on.im);
    ww_image_free(&off.im);
}

TEST_IMAGE(lantern_lights_the_surface_above_it) {
    REQUIRE_GL();
    double below, above;
    surface_lift("surf_below", "position: [0, -5.5, 1], look_at: [0, 0, -3]", &below);
    surface_lift("surf_above", "position: [0, 3, 1], look_at: [0, 0, -3]", &above);
    fprintf(stderr, "    the lantern adds %.1f levels to the surface seen from below, %.1f from "
                    "above\n", below, above);
    ENSURE_MSG(below >= SURFACE_MIN_LIFT, "from below: %.1f < %g", below, SURFACE_MIN_LIFT);
    ENSURE_MSG(above >= SURFACE_MIN_LIFT, "from above: %.1f < %g", above, SURFACE_MIN_LIFT);
}

/* the flicker: the lit hull's brightness varies by at least FLICKER_MIN_VARIATION of its mean over
 * half a second, and a frame rendered alone (--frames k:k+1, the simulation's prefix
 * stepped without drawing) is the same as in the run: the flicker follows simulated time */
TEST_IMAGE(lantern_flicker_visible_and_deterministic) {
    REQUIRE_GL();
    char dir[768], c[2048], path[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("flicker"));
    snprintf(c, sizeof c, "render %s --frames 0:%d --size 256x144 -o %s --quiet", LANTERN_SCENE,
             FLICKER_FRAMES, dir);
    ENSURE_EQ_INT(ww_test_ww(c, NULL, NULL), 0);
    double lo = 1e9, hi = -1e9, sum = 0.0, at7 = 0.0;
    for (int k = 0; k < FLICKER_FRAMES; k++) {
        pic p;
        snprintf(path, sizeof path, "%s/frame_%05d.png", dir, k);
        if (!ww_test_pic_load(path, &p)) return;
        double l = mean_of(&p, HULL_PATCH, 3);
        lo = l < lo ? l : lo;
        hi = l > hi ? l : hi;
        sum += l;
        if (k == 7) at7 = l;
        ww_image_free(&p.im);
    }
    double mean = sum / FLICKER_FRAMES, var = (hi - lo) / mean;
    pic again;
    if (!ww_test_render_pic(LANTERN_SCENE, 7, "256x144", NULL, "flicker_again", &again)) return;
    double l7 = mean_of(&again, HULL_PATCH, 3);
    fprintf(stderr, "    hull luma %.1f..%.1f (variation %.2f of its mean); frame 7 alone %.3f, "
                    "in the run %.3f\n", lo, hi, var, l7, at7);
    ENSURE_MSG(var >= FLICKER_MIN_VARIATION, "flicker %.3f < %g", var, FLICKER_MIN_VARIATION);
    ENSURE_MSG(l7 == at7, "frame 7 alone %.3f != in the run %.3f", l7, at7);
    ww_image_free(&again.im);
}

/* lights[].scatter is checked like every key: file:line:column, exit 2 */
static void bad_key(const char *text, int line, int column) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load_string("bad.yaml", text, strlen(text), NULL, 0, &sc, &err);
    ENSURE_MSG(r != WW_OK, "accepted: %s", text);
    ENSURE_EQ_INT(ww_result_exit_code(r), 2);
    ENSURE_EQ_INT(err.line, line);
    ENSURE_EQ_INT(err.column, column);
    ww_scene_free(sc);
}

TEST(lantern_scatter_key_validated) {
    bad_key("lights:\n  - {type: spot, position: [0, -2, 0], scatter: -1}\n", 2, 49);
    bad_key("lights:\n  - {type: spot, position: [0, -2, 0], scatter: 50}\n", 2, 49);
    bad_key("lights:\n  - {type: spot, position: [0, -2, 0], scatter: [1]}\n", 2, 49);
}

/* a scene pays only for what it uses: the shaders build the glow (WW_LIGHT_SCATTER) only when a
 * light has scatter > 0, so scenes without lights, or with scatter 0, never compile it */
static int scatter_on(const char *text) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("s.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    int on = sc ? ww_lights_scatter_on(sc) : -1;
    ww_scene_free(sc);
    return on;
}

TEST(lantern_glow_built_only_where_used) {
    ENSURE_EQ_INT(scatter_on("seed: 1\n"), 0);
    ENSURE_EQ_INT(scatter_on("lights: [{type: spot, position: [0, -2, 0], scatter: 0}]\n"), 0);
    ENSURE_EQ_INT(scatter_on("lights: [{type: point, position: [0, -2, 0]}]\n"), 1);
}
