/* test_models.c - the underwater world's models (scenes/models/, made by scripts/make-models.py)
 * and what a scene does with them: each file loads with a sane triangle count and the bounds
 * its shape implies; in scenes/features/wreck.yaml the wreck covers a plausible part of the frame
 * and is redder than the water around it (wood), the starfish redder than the sand under it;
 * a face buried in the seabed's plane stays under the sand; kelp sways at its tips and not at its
 * base, the same frame twice byte for byte; the camera is stopped by a tilted hull's own box,
 * passes an empty corner of its axis-aligned box, and swims through kelp. Every figure is
 * measured against a named bound.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "io/writers.h"
#include "scene/assets.h"
#include "scene/scene.h"
#include "sim/collide.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* ---- the files ---------------------------------------------------------------------------- */

#define MODELS_TRIANGLES_MAX 30000 /* all of them together: a scene places dozens */
#define BASE_TOL 0.02              /* m: a plant's or rock's lowest point on y = 0 */

typedef struct model_spec {
    const char *file;
    int tri_lo, tri_hi;     /* triangles */
    double size_lo[3], size_hi[3]; /* extent along x, y, z, m */
    int base_on_zero;       /* its lowest point is y = 0 (plants, rocks, starfish, coral) */
    int textured;           /* some material of its library draws a map_Kd */
} model_spec;

static const model_spec SPECS[] = {
    {"wreck_hull.obj", 1000, 6000, {3.0, 2.2, 9.0}, {3.6, 3.0, 11.0}, 0, 1},
    {"wreck_deck.obj", 100, 2000, {2.5, 1.0, 7.0}, {3.4, 2.0, 10.0}, 0, 1},
    {"wreck_mast.obj", 20, 500, {0.2, 2.0, 0.2}, {0.8, 3.5, 0.8}, 0, 1},
    {"wreck_spar.obj", 50, 1000, {2.0, 4.0, 0.1}, {4.0, 6.0, 0.5}, 1, 1},
    {"rock_boulder.obj", 200, 3000, {1.5, 0.8, 1.5}, {2.5, 1.8, 2.5}, 1, 1},
    {"rock_slab.obj", 200, 3000, {2.5, 0.3, 1.8}, {4.0, 1.0, 3.0}, 1, 1},
    {"rock_spire.obj", 100, 2000, {0.8, 3.0, 0.8}, {1.8, 5.0, 1.8}, 1, 1},
    {"kelp.obj", 300, 3000, {0.2, 3.0, 0.2}, {1.2, 5.0, 1.2}, 1, 1},
    {"seaweed.obj", 100, 1500, {0.1, 0.3, 0.1}, {0.6, 1.0, 0.6}, 1, 1},
    {"starfish.obj", 200, 2000, {0.2, 0.02, 0.2}, {0.4, 0.06, 0.4}, 1, 1},
    {"starfish_purple.obj", 200, 2000, {0.2, 0.02, 0.2}, {0.4, 0.06, 0.4}, 1, 1},
    {"coral_branch.obj", 300, 5000, {0.3, 0.5, 0.3}, {1.2, 1.2, 1.2}, 1, 1},
    {"coral_brain.obj", 300, 5000, {0.6, 0.2, 0.6}, {1.2, 0.6, 1.2}, 1, 1},
    {"coral_fan.obj", 200, 3000, {0.5, 0.5, 0.05}, {1.2, 1.2, 0.3}, 1, 1},
};

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

TEST(models_files_load_with_sane_counts_and_bounds) {
    ww_assets a = {0};
    ww_error err = {0};
    long total = 0;
    for (size_t i = 0; i < sizeof SPECS / sizeof SPECS[0]; i++) {
        const model_spec *s = &SPECS[i];
        char path[256];
        snprintf(path, sizeof path, "scenes/models/%s", s->file);
        int index = -1;
        double t0 = now_s();
        ww_result r = ww_assets_obj(&a, path, "test", 1, 1, &index, &err);
        double ms = 1e3 * (now_s() - t0);
        ENSURE_MSG(r == WW_OK, "%s: %s", path, err.msg);
        if (r != WW_OK) break;
        const ww_mesh_data *m = &a.mesh[index];
        int tris = (int)(m->nindex / 3);
        total += tris;
        double size[3];
        for (int k = 0; k < 3; k++) size[k] = m->max[k] - m->min[k];
        fprintf(stderr, "    %-20s %5d triangles, %.2f x %.2f x %.2f m, y from %.3f, %.2f ms\n",
                s->file, tris, size[0], size[1], size[2], m->min[1], ms);
        ENSURE_MSG(tris >= s->tri_lo && tris <= s->tri_hi, "%s: %d triangles, expected %d..%d",
                   s->file, tris, s->tri_lo, s->tri_hi);
        for (int k = 0; k < 3; k++)
            ENSURE_MSG(size[k] >= s->size_lo[k] && size[k] <= s->size_hi[k],
                       "%s: extent %d is %.3f m, expected %.2f..%.2f", s->file, k, size[k],
                       s->size_lo[k], s->size_hi[k]);
        if (s->base_on_zero)
            ENSURE_MSG(fabs(m->min[1]) <= BASE_TOL, "%s: lowest point y = %.3f, expected 0",
                       s->file, m->min[1]);
        int tex = 0;
        for (int k = 0; k < m->nmaterial; k++) tex |= m->material[k].texture >= 0;
        ENSURE_MSG(tex == s->textured, "%s: textured %d, expected %d", s->file, tex, s->textured);
        /* every normal unit length (the file's vn, or the reader's smooth ones) */
        for (int v = 0; v < m->nvert; v++) {
            const float *n = m->vertex + 8 * v + 3;
            double l = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
            if (fabs(l - 1.0) > 1e-3) {
                ENSURE_MSG(0, "%s: vertex %d normal length %.4f", s->file, v, l);
                break;
            }
        }
    }
    fprintf(stderr, "    all: %ld triangles\n", total);
    ENSURE(total <= MODELS_TRIANGLES_MAX);
    ww_assets_free(&a);
}

/* ---- rendered frames ---------------------------------------------------------------------- */

typedef ww_test_pic pic;

static const uint8_t *px(const pic *p, int x, int y) { return ww_test_pixel(&p->im, x, y); }

/* the pixels that change by more than `levels` on some channel between a and b */
static int changed(const pic *a, const pic *b, int x, int y, int levels) {
    const uint8_t *c = px(a, x, y), *d = px(b, x, y);
    for (int k = 0; k < 3; k++)
        if (abs((int)c[k] - (int)d[k]) > levels) return 1;
    return 0;
}

#define MASK_LEVELS 6 /* 8-bit levels a pixel must change by to belong to an object's mask */

/* share of the frame an object covers (its mask: with against without it), and the mean
 * redness R / (R + G + B) of the mask's pixels with the object and without it (what is behind) */
typedef struct cover {
    double share, red_with, red_behind;
    double rgb_with[3];
} cover;

static cover measure(const pic *with, const pic *without) {
    cover c = {0};
    double sw = 0, sb = 0;
    long n = 0;
    for (int y = 0; y < with->h; y++)
        for (int x = 0; x < with->w; x++) {
            if (!changed(with, without, x, y, MASK_LEVELS)) continue;
            const uint8_t *a = px(with, x, y), *b = px(without, x, y);
            sw += (double)a[0] / (1.0 + a[0] + a[1] + a[2]);
            sb += (double)b[0] / (1.0 + b[0] + b[1] + b[2]);
            for (int k = 0; k < 3; k++) c.rgb_with[k] += a[k];
            n++;
        }
    if (n) {
        c.red_with = sw / (double)n;
        c.red_behind = sb / (double)n;
        for (int k = 0; k < 3; k++) c.rgb_with[k] /= (double)n;
    }
    c.share = (double)n / ((double)with->w * (double)with->h);
    return c;
}

#define WRECK_SCENE "scenes/features/wreck.yaml"
#define WRECK_SHARE_LO 0.03  /* the wreck covers at least this share of the feature frame ... */
#define WRECK_SHARE_HI 0.40  /* ... and at most this: a ship seen whole, not a close-up */
#define STAR_SHARE_LO 0.0005 /* the near starfish covers at least this share of the frame */
#define STAR_REDDER 0.03     /* its redness R / (R + G + B) over the sand's under it, at least:
                              * 8 m of water leaves the sunlight 3% of its red, so an orange
                              * starfish is only a little redder than the sand beside it */

/* the ship's parts sunk out of sight under the sand (the hull carries deck and mast), the
 * orange starfish likewise */
#define NO_WRECK "--set 'objects.models[0].position=[0, -60, -9]' " \
                 "--set 'objects.models[3].position=[0, -60, 0]'"
#define NO_STAR "--set 'objects.models[12].position=[1.9, -60, -2.7]'"

TEST_IMAGE(models_wreck_covers_the_frame_and_the_starfish_is_redder_than_the_sand) {
    REQUIRE_GL();
    pic all, wreckless, starless;
    if (!ww_test_render_pic(WRECK_SCENE, 0, "320x180", NULL, "wreck_all", &all)) return;
    if (!ww_test_render_pic(WRECK_SCENE, 0, "320x180", NO_WRECK, "wreck_none", &wreckless)) return;
    if (!ww_test_render_pic(WRECK_SCENE, 0, "320x180", NO_STAR, "wreck_nostar", &starless)) return;
    cover w = measure(&all, &wreckless), s = measure(&all, &starless);
    fprintf(stderr, "    wreck: %.3f of the frame (rgb %.0f %.0f %.0f); starfish: %.4f, redness "
            "%.3f over %.3f (rgb %.0f %.0f %.0f)\n", w.share, w.rgb_with[0], w.rgb_with[1],
            w.rgb_with[2], s.share, s.red_with, s.red_behind, s.rgb_with[0], s.rgb_with[1],
            s.rgb_with[2]);
    ENSURE(w.share >= WRECK_SHARE_LO && w.share <= WRECK_SHARE_HI);
    ENSURE(s.share >= STAR_SHARE_LO);
    ENSURE(s.red_with >= s.red_behind + STAR_REDDER);
    ww_image_free(&all.im);
    ww_image_free(&wreckless.im);
    ww_image_free(&starless.im);
}

/* the materials' own colours, under the noon sun in air (the water far below): the hull's
 * pixels wood-brown, the starfish's orange-red. Hue in degrees (0 red, 60 yellow) */
static const char AIR_SCENE[] =
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {shadows: false, refraction: false, reflection: false, bloom: false,\n"
    "         god_rays: false, fxaa: false, msaa: 0, seabed: false}\n"
    "sky: {time_of_day: 12, day_length: 0}\n"
    "water: {level: -200, waves: {model: flat}}\n"
    "objects:\n"
    "  models:\n"
    "    - {name: %s, obj: %s/scenes/models/%s, position: [0, 0, 0], scale: %g}\n"
    "camera: {fov: 40, path: [{t: 0, position: [%g, %g, %g], look_at: [0, %g, 0]}]}\n";

#define WOOD_HUE_LO 10.0   /* brown: an orange hue ... */
#define WOOD_HUE_HI 45.0
#define WOOD_SAT_LO 0.25   /* ... of some saturation (max - min) / max, and dark */
#define WOOD_VAL_HI 0.75
#define STAR_HUE_HI 30.0   /* orange to red */
#define STAR_SAT_LO 0.5

/* mean hue, saturation and value of the object's pixels (where it differs from the bare sky) */
static void hsv_of(const pic *f, const pic *bare, double out[3]) {
    double r = 0, g = 0, b = 0;
    long n = 0;
    for (int y = 0; y < f->h; y++)
        for (int x = 0; x < f->w; x++)
            if (changed(f, bare, x, y, MASK_LEVELS)) {
                const uint8_t *c = px(f, x, y);
                r += c[0];
                g += c[1];
                b += c[2];
                n++;
            }
    if (n) {
        r /= (double)n;
        g /= (double)n;
        b /= (double)n;
    }
    double hi = fmax(r, fmax(g, b)), lo = fmin(r, fmin(g, b)), d = hi - lo, h = 0;
    if (d > 0 && hi == r) h = 60.0 * fmod((g - b) / d, 6.0);
    else if (d > 0 && hi == g) h = 60.0 * ((b - r) / d + 2.0);
    else if (d > 0) h = 60.0 * ((r - g) / d + 4.0);
    if (h < 0) h += 360.0;
    out[0] = h;
    out[1] = hi > 0 ? d / hi : 0;
    out[2] = hi / 255.0;
}

static int render_air(const char *file, double scale, const double eye[3], double look_y,
                      const char *name, pic *with, pic *bare) {
    char cwd[512], text[2048], scene[1024], dir[64];
    ENSURE(getcwd(cwd, sizeof cwd) != NULL);
    snprintf(text, sizeof text, AIR_SCENE, name, cwd, file, scale, eye[0], eye[1], eye[2], look_y);
    snprintf(scene, sizeof scene, "%s/%s.yaml", ww_test_tmpdir(name), name);
    ENSURE(ww_test_write_text(scene, text) == 0);
    snprintf(dir, sizeof dir, "%s_bare", name);
    return ww_test_render_pic(scene, 0, "240x160", NULL, name, with) &&
           ww_test_render_pic(scene, 0, "240x160",
                              "--set 'objects.models[0].position=[0, -500, 0]'", dir, bare);
}

TEST_IMAGE(models_wood_is_brown_and_the_starfish_orange_in_daylight) {
    REQUIRE_GL();
    pic hull, hull_bare, star, star_bare;
    const double hull_eye[3] = {9, 4, 9}, star_eye[3] = {0.2, 0.9, 0.5};
    if (!render_air("wreck_hull.obj", 1.0, hull_eye, 1.0, "air_hull", &hull, &hull_bare)) return;
    if (!render_air("starfish.obj", 1.0, star_eye, 0.0, "air_star", &star, &star_bare)) return;
    double w[3], s[3];
    hsv_of(&hull, &hull_bare, w);
    hsv_of(&star, &star_bare, s);
    fprintf(stderr, "    hull: hue %.1f deg, saturation %.2f, value %.2f; starfish: hue %.1f, "
            "saturation %.2f, value %.2f\n", w[0], w[1], w[2], s[0], s[1], s[2]);
    ENSURE(w[0] >= WOOD_HUE_LO && w[0] <= WOOD_HUE_HI && w[1] >= WOOD_SAT_LO && w[2] <= WOOD_VAL_HI);
    ENSURE((s[0] <= STAR_HUE_HI || s[0] >= 350.0) && s[1] >= STAR_SAT_LO);
    ww_image_free(&hull.im);
    ww_image_free(&hull_bare.im);
    ww_image_free(&star.im);
    ww_image_free(&star_bare.im);
}

TEST_IMAGE(models_golden_wreck) {
    REQUIRE_GL();
    char dir[512], actual[600];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("wreck_golden"));
    ENSURE(ww_test_render(WRECK_SCENE, NULL, dir) == 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden("golden/features/wreck.png", actual);
}

/* a red crate buried in the sand with its top face in the seabed's plane (the seabed lies at
 * y = -10), seen from 3 m above it: the sand must cover the face everywhere. Where two surfaces
 * share a plane, the depths' rounding decides which is in front pixel by pixel, and it decides
 * differently for each grid the seabed is drawn with and for each Mesa release; the seabed's
 * depth offset settles it for the sand. Raised 5 cm, the crate shows, and that is its footprint */
static const char BURIED_SCENE[] =
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {shadows: false, refraction: false, reflection: false, bloom: false,\n"
    "         god_rays: false, fxaa: false, msaa: 0, seabed: true}\n"
    "sky: {time_of_day: 13, day_length: 0}\n"
    "water: {level: 0, depth: 10, waves: {model: flat}, look: {caustics: false}}\n"
    "objects:\n"
    "  models:\n"
    "    - {name: crate, mesh: box, position: [0.3, -10.5, -4.2], scale: [2.4, 1, 1.6],\n"
    "       rotation: 23, color: [0.9, 0.1, 0.1]}\n"
    "camera: {fov: 60, path: [{t: 0, position: [0, -7, -1], look_at: [0, -10, -4.5]}]}\n";

#define BURIED_FOOTPRINT_MIN 0.05 /* the raised crate's share of the frame: the test sees it */
#define BURIED_SHOWING_MAX 0 /* pixels the buried face may show on (without the seabed's offset:
                              * 3 with its grid of 8 cells, 156 with 64) */

TEST_IMAGE(models_a_face_in_the_seabed_plane_stays_under_the_sand) {
    REQUIRE_GL();
    char scene[1024];
    snprintf(scene, sizeof scene, "%s/buried.yaml", ww_test_tmpdir("buried"));
    ENSURE(ww_test_write_text(scene, BURIED_SCENE) == 0);
    pic buried, raised, bare;
    if (!ww_test_render_pic(scene, 0, "320x180", NULL, "buried", &buried)) return;
    if (!ww_test_render_pic(scene, 0, "320x180",
                            "--set 'objects.models[0].position=[0.3, -10.45, -4.2]'", "raised",
                            &raised)) {
        ww_image_free(&buried.im);
        return;
    }
    if (!ww_test_render_pic(scene, 0, "320x180",
                            "--set 'objects.models[0].position=[0.3, -60, -4.2]'", "bare", &bare)) {
        ww_image_free(&buried.im);
        ww_image_free(&raised.im);
        return;
    }
    long footprint = 0, showing = 0;
    for (int y = 0; y < bare.h; y++)
        for (int x = 0; x < bare.w; x++) {
            footprint += changed(&raised, &bare, x, y, MASK_LEVELS);
            showing += changed(&buried, &bare, x, y, MASK_LEVELS);
        }
    double area = (double)bare.w * bare.h;
    printf("    raised crate: %.3f of the frame; buried: %ld pixels show (%.4f of its footprint)\n",
           (double)footprint / area, showing, footprint ? (double)showing / (double)footprint : 0.0);
    ENSURE_MSG((double)footprint / area >= BURIED_FOOTPRINT_MIN, "raised crate covers %.3f",
               (double)footprint / area);
    ENSURE_MSG(showing <= BURIED_SHOWING_MAX,
               "the buried face shows on %ld pixels of a footprint of %ld", showing, footprint);
    ww_image_free(&buried.im);
    ww_image_free(&raised.im);
    ww_image_free(&bare.im);
}

/* a kelp 7 m in front of the camera in still, flat water (no caustics: only the sway moves),
 * swaying along x by 0.5 m at its tip, one cycle in 2 s */
static const char SWAY_SCENE[] =
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    "render: {shadows: false, refraction: false, reflection: false, bloom: false,\n"
    "         god_rays: false, fxaa: false, msaa: 0, seabed: true}\n"
    "sky: {time_of_day: 13, day_length: 0}\n"
    "water: {level: 0, depth: 8, waves: {model: flat}, look: {caustics: false}}\n"
    "objects:\n"
    "  models:\n"
    "    - {name: kelp, obj: %s/scenes/models/kelp.obj, position: [0, -8, -5],\n"
    "       sway: {amplitude: 0.5, frequency: 0.5, direction: 0}}\n"
    "camera: {fov: 60, path: [{t: 0, position: [0, -6, 2], look_at: [0, -6, -5]}]}\n";

#define SWAY_TIP_PX 6.0   /* the kelp's top fifth moves sideways at least this far between
                           * some two of the frames, px (0.5 m at the tip is 15 px here) */
#define SWAY_BASE_PX 0.5  /* its bottom tenth at most this far */

/* mean column of the kelp's pixels (where f differs from the bare seabed) in rows y0..y1 */
static double band_centroid(const pic *f, const pic *bare, int y0, int y1) {
    double sx = 0.0;
    long n = 0;
    for (int y = y0; y <= y1; y++)
        for (int x = 0; x < f->w; x++)
            if (changed(f, bare, x, y, MASK_LEVELS)) {
                sx += x;
                n++;
            }
    return n ? sx / (double)n : 0.0;
}

TEST_IMAGE(models_kelp_sways_at_its_tip_not_its_base_and_repeats) {
    REQUIRE_GL();
    char cwd[512], text[2048], scene[1024];
    ENSURE(getcwd(cwd, sizeof cwd) != NULL);
    snprintf(text, sizeof text, SWAY_SCENE, cwd);
    snprintf(scene, sizeof scene, "%s/sway.yaml", ww_test_tmpdir("sway"));
    ENSURE(ww_test_write_text(scene, text) == 0);
    static const char *const bare_args = "--set 'objects.models[0].position=[0, -60, -5]'";
    pic f[3], again, bare;
    const int frames[3] = {0, 15, 30};
    const char *names[3] = {"sway0", "sway15", "sway30"};
    for (int i = 0; i < 3; i++)
        if (!ww_test_render_pic(scene, frames[i], "240x240", NULL, names[i], &f[i])) return;
    if (!ww_test_render_pic(scene, 15, "240x240", NULL, "sway15b", &again)) return;
    if (!ww_test_render_pic(scene, 0, "240x240", bare_args, "sway_bare", &bare)) return;

    /* the kelp's rows: where any frame differs from the bare seabed */
    int top = f[0].h, bottom = -1;
    for (int i = 0; i < 3; i++)
        for (int y = 0; y < f[i].h; y++)
            for (int x = 0; x < f[i].w; x++)
                if (changed(&f[i], &bare, x, y, MASK_LEVELS)) {
                    if (y < top) top = y;
                    if (y > bottom) bottom = y;
                }
    ENSURE_MSG(bottom > top + 40, "kelp rows %d..%d", top, bottom);
    int span = bottom - top;
    double tip = 0.0, base = 0.0, ct[3], cb[3];
    for (int i = 0; i < 3; i++) {
        ct[i] = band_centroid(&f[i], &bare, top, top + span / 5);
        cb[i] = band_centroid(&f[i], &bare, bottom - span / 10, bottom);
    }
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++) {
            tip = fmax(tip, fabs(ct[i] - ct[j]));
            base = fmax(base, fabs(cb[i] - cb[j]));
        }
    long same = 0;
    for (int y = 0; y < again.h; y++)
        for (int x = 0; x < again.w; x++) same += !changed(&again, &f[1], x, y, 0);
    fprintf(stderr, "    kelp rows %d..%d: its top fifth moves %.2f px, its bottom tenth %.2f px;"
            " rerun %ld of %d pixels equal\n", top, bottom, tip, base, same, again.w * again.h);
    ENSURE(tip >= SWAY_TIP_PX);
    ENSURE(base <= SWAY_BASE_PX);
    ENSURE(same == (long)again.w * again.h);
    for (int i = 0; i < 3; i++) ww_image_free(&f[i].im);
    ww_image_free(&again.im);
    ww_image_free(&bare.im);
}

/* ---- the camera against them -------------------------------------------------------------- */

#define COLLIDE_MARGIN 0.1  /* the camera's near clip: solids grow by it */
#define CORNER_CLEAR 0.3    /* the corner path passes at least this far outside the hull's box */

/* distance from p to the box of half extents h at c turned by the unit quaternion q, written
 * out independently of collide.c: p - c rotated by the conjugate as a matrix */
static double box_distance(const double c[3], const double q[4], const double h[3],
                           const double p[3]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    double d[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]}, s = 0;
    for (int a = 0; a < 3; a++) {
        double l = R[0][a] * d[0] + R[1][a] * d[1] + R[2][a] * d[2];
        double o = fabs(l) - h[a];
        if (o > 0) s += o * o;
    }
    return sqrt(s);
}

/* the camera flies along `axis` from a - 8 to a + 8 through (x, y, z) with the hull rolled 30
 * deg and a kelp beside it; camera_blocked events counted */
static int fly(const double at[3], int axis, ww_scene **keep) {
    char cwd[512], text[2048];
    ENSURE(getcwd(cwd, sizeof cwd) != NULL);
    double p0[3] = {at[0], at[1], at[2]}, p1[3] = {at[0], at[1], at[2]};
    p0[axis] -= 8.0;
    p1[axis] += 8.0;
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 3}\n"
             "water: {waves: {model: flat}}\n"
             "objects: {models: [{name: hull, obj: %s/scenes/models/wreck_hull.obj,"
             " rotation: [0, 0, 30]},\n"
             "  {name: kelp, obj: %s/scenes/models/kelp.obj, position: [6, 0, 0],"
             " sway: {amplitude: 0.4}}]}\n"
             "camera: {collide: true, near: %g, interpolation: linear, path: [{t: 0.5, position:"
             " [%g, %g, %g], yaw: 0}, {t: 2.5, position: [%g, %g, %g], yaw: 0}]}\n",
             cwd, cwd, COLLIDE_MARGIN, p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load_string("collide.yaml", text, strlen(text), NULL, 0, &sc, &err);
    ENSURE_MSG(r == WW_OK, "load: %s", err.msg);
    if (r != WW_OK) return -1;
    ww_state *st = ww_state_new(sc);
    int blocked = 0;
    while (st->t < 3.0) {
        ENSURE(ww_step(sc, st, &err) == WW_OK);
        for (int i = 0; i < ww_events_count(sc, st); i++)
            blocked += (int)st->events[i * WW_SIM_EVENT_STRIDE] == WW_SE_CAMERA_BLOCKED;
    }
    ww_state_free(st);
    if (keep)
        *keep = sc;
    else
        ww_scene_free(sc);
    return blocked;
}

TEST(models_camera_stopped_by_a_tilted_hull_not_its_empty_corner_nor_kelp) {
    ww_scene *sc = NULL;
    /* through the hull's middle (its box's centre in the world), along x */
    double mid[3] = {0, 0, 0};
    if (fly(mid, 0, &sc) < 0 || !sc) return;
    const ww_model_desc *hull = &sc->models.model[0], *kelp = &sc->models.model[1];
    ENSURE(hull->oriented && hull->solid);
    ENSURE(!kelp->solid);
    for (int a = 0; a < 3; a++) mid[a] = hull->obb_c[a];
    /* an empty corner of the axis-aligned box: inside it, clear of the turned box */
    double corner[3] = {hull->max[0] - 0.3, hull->max[1] - 0.3, hull->obb_c[2]};
    double clear = box_distance(hull->obb_c, hull->obb_q, hull->obb_h, corner);
    fprintf(stderr, "    hull box %.2f..%.2f x %.2f..%.2f; corner (%.2f, %.2f) %.2f m clear of "
            "the turned box\n", hull->min[0], hull->max[0], hull->min[1], hull->max[1], corner[0],
            corner[1], clear);
    ENSURE(clear >= COLLIDE_MARGIN + CORNER_CLEAR);
    ww_scene_free(sc);

    ENSURE_EQ_INT(fly(mid, 0, NULL), 1);
    ENSURE_EQ_INT(fly(corner, 2, NULL), 0); /* along the ship, through the corner */
    double through_kelp[3] = {6.0, 1.5, 0.0};
    ENSURE_EQ_INT(fly(through_kelp, 2, NULL), 0);
    double into_hull[3] = {0.0, mid[1], 0.0}; /* along the ship, inside it: blocked too */
    ENSURE_EQ_INT(fly(into_hull, 2, NULL), 1);
}
