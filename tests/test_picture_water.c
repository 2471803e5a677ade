/* test_picture_water.c - the water's optics measured on rendered frames, not against goldens: a
 * statistic over a region of the picture (a mask from two renders, a count, a colour mean or
 * spread) that the defect it guards against moves, with a threshold named for what it allows.
 * Each test prints its figures, so a change in the look shows as numbers.
 *   submerged      what lies under water seen through the surface is darker than its part
 *                  above it, and bluer the deeper it lies (Beer-Lambert, red absorbed first)
 *   rim            what rises above the water is not refracted into the water around it
 *   mirror image   what floats is not reflected on the water beyond it
 *   underwater     a diver sees the seabed: texture (caustics, shading) survives the fog
 *   cubemap        no dark streaks where wave backs reflect the cubemap's lower half
 *   high view      from 300 m: no hard band where the water ends, little pixel-scale noise
 *   foam           soft-edged coverage that grows with the waves' steepness
 *   open sea       colour and contrast in the water, and no shimmer far away
 *   G-buffer       the water shaded once a pixel from its G-buffer looks as the mesh shaded it,
 *                  and a frame does not depend on the frames drawn before it
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image.h"
#include "io/writers.h"
#include "test.h"

#define W 640 /* frames are rendered at 640x360, but for the moire, which shows at 1280x720 */
#define H 360

#define MASK_THRESH 6            /* 8-bit levels a pixel must move to count as the object's */
#define SUBMERGED_DARKER 0.9     /* the submerged face's luminance over the same face's above
                                  * the water at most: Fresnel and absorption take >= 10% */
#define SUBMERGED_DARKER_LOW_SUN 0.78 /* the same at 8 h and 16 h: the beam a low sun sends
                                       * down is wider below the surface than above it; lit as if
                                       * it were not, the face measured 0.82, with it 0.70 */
#define DEEPER_BLUER 1.03        /* B/R of the lower half of the submerged face over the upper
                                  * half's at least: 0.5 m deeper, red absorbed 0.45/m */
#define SEABED_TEXTURE 0.45      /* RMS 8-bit luminance difference of pixels 12 apart on the
                                  * seabed seen from 1.2 m above it, at least */
#define STREAK_ROWS 3            /* a streak is a line at most this many rows thick ... */
#define STREAK_DEPTH 0.75        /* ... darker than this times the water above and below it ... */
#define DARK_STREAK_LEVEL 0.7    /* ... and than this times the water's median luminance */
#define DARK_STREAK_FRACTION 0.003 /* the share of water pixels in streaks, at most */
#define ROW_STEP_MAX 1.2         /* largest jump of the mean 8-bit luminance between neighbouring
                                  * rows of the water seen from 300 m */
#define HIGH_FREQ_MAX 0.85       /* mean |L - mean of its 4 neighbours| of that water, 8-bit */
#define FOAM_LEVEL 4             /* 8-bit levels foam must add to a pixel to count as foam */
#define FOAM_SOFT_MIN 0.35       /* foam pixels at under half the foam's 99th percentile, at least */
#define WATER_SATURATION_MIN 0.3 /* mean (max - min) / max of the near water's pixels: the grey
                                  * water under the gradient sky measured 0.104, looking into
                                  * Preetham's low sun 0.124; the afternoon sea looking out with
                                  * the sun behind the shoulder, 0.508 */
#define WATER_CONTRAST_MIN 18.0  /* standard deviation of their 8-bit luminance: not a fog bank */
#define WATER_DETAIL_MIN 0.005   /* mean |L - mean of its 4 neighbours| there over their mean
                                  * luma: fine detail, not smooth plastic, whatever the exposure
                                  * (0.0059 at exposure 1.1 into the sun, 0.0062 at 0.7) */
#define SHIMMER_MAX 3.0          /* mean 8-bit luminance change of the far water between frames */
#define GBUF_PSNR_MIN 44.0       /* the water shaded from its G-buffer against shaded with its
                                  * mesh, dB at least: the mip levels of the reflection and the
                                  * sky differ on the pixels where a crest hides the water behind
                                  * it (46.7 dB on the cubemap scene's steep waves, 97.5 on the
                                  * open sea, the lake and the reef identical at 320x180) */
#define GBUF_LEVELS 8            /* a pixel more than this many levels apart counts ... */
#define GBUF_APART_MAX 0.01      /* ... and such pixels are at most this share (0.45% there) */
#define RIM_MAX_PIXELS 10        /* pixels around a floating cube's top half that its colour
                                  * reaches through the refraction, at most: the rim of its top
                                  * bled into the water behind it measured 139 */

typedef struct img {
    ww_image im;
    int ok;
} img;

/* frame `frame` of scene (a path) with extra arguments, rendered at w x h into a fresh folder
 * and read */
static img render_frame_at(const char *scene, int frame, const char *args, const char *tag, int w,
                           int h) {
    img r = {0};
    char dir[512], c[4096], path[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(tag));
    snprintf(c, sizeof c, "%s render %s --frames %d:%d --size %dx%d -o %s --quiet %s", ww_test_bin(),
             scene, frame, frame + 1, w, h, dir, args ? args : "");
    int rc = ww_test_run(c, NULL, NULL);
    ENSURE_MSG(rc == 0, "%s: exit %d", c, rc);
    if (rc != 0) return r;
    snprintf(path, sizeof path, "%s/frame_%05d.png", dir, frame);
    ww_error err = {0};
    r.ok = ww_read_png(path, &r.im, &err) == WW_OK && r.im.u8 && r.im.width == w && r.im.height == h &&
           r.im.channels >= 3;
    ENSURE_MSG(r.ok, "%s: %s", path, err.msg);
    return r;
}

static img render_frame(const char *scene, int frame, const char *args, const char *tag) {
    return render_frame_at(scene, frame, args, tag, W, H);
}

static void img_free(img *a) { ww_image_free(&a->im); }

static const unsigned char *px(const img *a, int x, int y) { return ww_test_pixel(&a->im, x, y); }

/* Rec. 709 luma of the 8-bit values */
static double luma(const img *a, int x, int y) {
    const unsigned char *p = px(a, x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

static int max_diff(const img *a, const img *b, int x, int y) {
    const unsigned char *p = px(a, x, y), *q = px(b, x, y);
    int m = 0;
    for (int k = 0; k < 3; k++) {
        int d = abs((int)p[k] - (int)q[k]);
        if (d > m) m = d;
    }
    return m;
}

/* write a scene file into the test's folder; its path */
static const char *scene_file(const char *tag, const char *text) {
    static char path[600];
    snprintf(path, sizeof path, "%s/scene.yaml", ww_test_tmpdir(tag));
    ENSURE(ww_test_write_text(path, text) == 0);
    return path;
}

/* ---- submerged: darker, and bluer with depth ------------------------------------------------ */

/* a 2 m cube floating half under flat water at noon, at rest at frame 0, seen from 3 m up and
 * 6 m away on the sun's side (the sun culminates toward -z; 60 deg vertical fov, looking at the
 * cube's centre): its sunlit face spans rows 154..247 of 360, the waterline on it at row 204,
 * columns 266..374. Reflection, shadows and post effects off, so the face's pixels are its own
 * light through the surface plus the sky's Fresnel reflection. */
static const char *const CUBE_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {size: [640, 360], shadows: false, reflection: false, bloom: false, god_rays: false,\n"
    "         fxaa: false, seabed: false}\n"
    "sky: {time_of_day: 12}\n"
    "water: {waves: {model: flat}, look: {foam: false, caustics: false}}\n"
    "objects:\n"
    "  cubes: [{position: [0, 0, 0], size: 2, density: 500}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 3, -6], look_at: [0, 0, 0]}]\n";

typedef struct band {
    double luma, r, g, b;
    long n;
} band;

static band band_mean(const img *a, const img *without, int x0, int x1, int y0, int y1) {
    band s = {0};
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            if (max_diff(a, without, x, y) <= MASK_THRESH) continue;
            const unsigned char *p = px(a, x, y);
            s.luma += luma(a, x, y);
            s.r += p[0];
            s.g += p[1];
            s.b += p[2];
            s.n++;
        }
    if (s.n > 0) {
        s.luma /= (double)s.n;
        s.r /= (double)s.n;
        s.g /= (double)s.n;
        s.b /= (double)s.n;
    }
    return s;
}

TEST_IMAGE(picture_water_submerged_darker_and_bluer) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_cube", CUBE_SCENE);
    /* at noon, and with the sun low in the morning and the afternoon, where refraction bends
     * its beam steeply down: the beam below is wider than above (cos ti / cos tt), so what it
     * lights is no brighter for being bent toward it */
    static const char *const suns[] = {"12", "8", "16"};
    for (int i = 0; i < 3; i++) {
        char set[160], n_with[32], n_without[32];
        snprintf(set, sizeof set, "--set sky.time_of_day=%s", suns[i]);
        snprintf(n_with, sizeof n_with, "pw_cube_with_%s", suns[i]);
        snprintf(n_without, sizeof n_without, "pw_cube_without_%s", suns[i]);
        img with = render_frame(scene, 0, set, n_with);
        char set2[256];
        snprintf(set2, sizeof set2, "%s --set \"objects.cubes[0].position=[0,0,-4000]\"", set);
        img without = render_frame(scene, 0, set2, n_without);
        if (with.ok && without.ok) {
            printf("  sun at %s h:\n", suns[i]);
            /* the face's middle columns, 6 rows clear of its edges and of the waterline */
            band above = band_mean(&with, &without, 290, 350, 162, 198);
            band upper = band_mean(&with, &without, 290, 350, 210, 226);
            band lower = band_mean(&with, &without, 290, 350, 226, 241);
            band below = band_mean(&with, &without, 290, 350, 210, 241);
            printf("  above water: luma %.1f (%ld px); submerged: luma %.1f (%ld px); "
                   "B/R upper %.3f, lower %.3f\n", above.luma, above.n, below.luma, below.n,
                   upper.b / fmax(upper.r, 1.0), lower.b / fmax(lower.r, 1.0));
            ENSURE_MSG(above.n > 500 && upper.n > 300 && lower.n > 300,
                       "the cube's face was not found: %ld, %ld, %ld pixels", above.n, upper.n,
                       lower.n);
            double darker = i == 0 ? SUBMERGED_DARKER : SUBMERGED_DARKER_LOW_SUN;
            ENSURE_MSG(below.luma < darker * above.luma,
                       "submerged luma %.1f not below %.2f x above-water %.1f", below.luma, darker,
                       above.luma);
            double ru = upper.b / fmax(upper.r, 1.0), rl = lower.b / fmax(lower.r, 1.0);
            ENSURE_MSG(rl > DEEPER_BLUER * ru, "B/R deeper %.3f not above %.2f x shallower %.3f", rl,
                       DEEPER_BLUER, ru);
        }
        img_free(&with);
        img_free(&without);
    }
}

/* ---- no rim: what rises above the water is not refracted ----------------------------------- */

/* a 1 m cube floating on the lake's two longest waves, seen from 1.6 m up and 5 m away, with
 * reflection and post effects off. Its pixels are the ones that change when it is moved 4 km
 * away; with refraction off, only its part above the water. Whatever else changes with
 * refraction on is its colour carried into the water by the refraction: the submerged part seen
 * through the surface (below the waterline), and, if the refracted image held the cube's top, a
 * pale rim along the top and the upper sides, where nothing of it can be seen through water. */
static const char *const RIM_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {size: [640, 360], shadows: false, reflection: false, bloom: false, god_rays: false,\n"
    "         fxaa: false, seabed: {on: true, color: [0.25, 0.3, 0.3]}}\n"
    "sky: {time_of_day: 15}\n"
    "water:\n"
    "  depth: 4\n"
    "  waves: {model: gerstner, list: [{direction: 20, wavelength: 12, amplitude: 0.2, steepness: 0.6},\n"
    "                                  {direction: -35, wavelength: 5, amplitude: 0.06, steepness: 0.4}]}\n"
    "  look: {foam: false, caustics: false}\n"
    "objects:\n"
    "  cubes: [{position: [0, 0, 0], size: 1, density: 500}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 1.6, -5], look_at: [0, 0.2, 0]}]\n";

#define CUBE_AWAY "--set \"objects.cubes[0].position=[0,0,-4000]\"" /* out of sight */

/* a frame four ways, for what an object adds to the mirror image (or, with `toggle`
 * render.refraction, to the water's refraction): the image on and off, each with the object
 * where `here` puts it (extra arguments, or NULL for the scene's place) and where `away` puts
 * it, out of sight */
typedef struct mirror_frames {
    img on, on0, off, off0;
    int ok;
} mirror_frames;

static mirror_frames image_frames_render(const char *scene, int frame, const char *here,
                                         const char *away, const char *toggle, const char *tag) {
    static const char *const suffix[4] = {"on", "on_away", "off", "off_away"};
    char arg[4][300], t[4][64];
    img *out[4];
    mirror_frames m = {0};
    out[0] = &m.on, out[1] = &m.on0, out[2] = &m.off, out[3] = &m.off0;
    for (int k = 0; k < 4; k++) {
        snprintf(arg[k], sizeof arg[k], "%s%s%s%s", k % 2 ? away : here ? here : "",
                 k >= 2 ? " --set " : "", k >= 2 ? toggle : "", k >= 2 ? "=false" : "");
        snprintf(t[k], sizeof t[k], "%s_%d_%s", tag, frame, suffix[k]);
        *out[k] = render_frame(scene, frame, arg[k], t[k]);
    }
    m.ok = m.on.ok && m.on0.ok && m.off.ok && m.off0.ok;
    return m;
}

static mirror_frames mirror_frames_render(const char *scene, int frame, const char *here,
                                          const char *away, const char *tag) {
    return image_frames_render(scene, frame, here, away, "render.reflection", tag);
}

static void mirror_frames_free(mirror_frames *m) {
    img_free(&m->on);
    img_free(&m->on0);
    img_free(&m->off);
    img_free(&m->off0);
}

/* whether (x, y) is the object's mirror image (or refracted image): moved by it with the image
 * on, not off */
static int mirror_image_at(const mirror_frames *m, int x, int y) {
    return max_diff(&m->on, &m->on0, x, y) > MASK_THRESH &&
           max_diff(&m->off, &m->off0, x, y) <= MASK_THRESH;
}

/* frame 0 of a scene whose one cube is at cubes[0], with the refraction prepass on and off, and
 * each again with the cube moved 4 km away: its pixels are those that change */
static mirror_frames render_cube_frames(const char *scene, const char *tag) {
    return image_frames_render(scene, 0, NULL, CUBE_AWAY, "render.refraction", tag);
}

TEST_IMAGE(picture_water_no_rim_around_what_floats) {
    REQUIRE_GL();
    mirror_frames cf = render_cube_frames(scene_file("pw_rim", RIM_SCENE), "pw_rim");
    const img *off = &cf.off, *off0 = &cf.off0;
    if (cf.ok) {
        /* the rows of the part above the water */
        int top = H, bottom = -1;
        long above = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                if (max_diff(off, off0, x, y) > MASK_THRESH) {
                    top = y < top ? y : top;
                    bottom = y > bottom ? y : bottom;
                    above++;
                }
        ENSURE_MSG(above > 1000, "the cube was not found: %ld pixels", above);
        long rim = 0;
        for (int y = 0; y < (top + bottom) / 2; y++)
            for (int x = 0; x < W; x++) rim += mirror_image_at(&cf, x, y);
        printf("  the cube above the water: rows %d..%d, %ld px; its colour in the water around "
               "its top half: %ld px\n", top, bottom, above, rim);
        ENSURE_MSG(rim <= RIM_MAX_PIXELS, "a rim of %ld pixels around the cube (at most %d)", rim,
                   RIM_MAX_PIXELS);
    }
    mirror_frames_free(&cf);
}

/* ---- the reflection: no mirror image behind what floats ------------------------------------ */

/* what the mirror scenes share: the reflection alone, and three waves for its distortion */
#define MIRROR_RENDER                                                                             \
    "render: {size: [640, 360], shadows: false, refraction: false, bloom: false, god_rays: false,\n" \
    "         fxaa: false, seabed: false}\n"
#define MIRROR_WATER                                                                              \
    "water:\n"                                                                                    \
    "  waves: {model: gerstner, list: [{direction: 20, wavelength: 12, amplitude: 0.2, steepness: 0.6},\n" \
    "                                  {direction: -35, wavelength: 5, amplitude: 0.06, steepness: 0.4},\n" \
    "                                  {direction: 80, wavelength: 2.5, amplitude: 0.02, steepness: 0.3}]}\n" \
    "  look: {foam: false, caustics: false}\n"

/* a 0.8 m cube riding the lake's three waves at dusk, seen from 2.5 m up about 9 m away,
 * refraction and post effects off. Its pixels are those that change when it is moved 4 km away
 * with the reflection off; with the reflection on, the others that change are its mirror image
 * on the water. A water point can only show what lies beyond it along the view ray mirrored, so
 * in a column of the cube that image belongs below the cube (the water in front of it), never
 * above it (the water beyond its far side). The texture is the mirror image about the rest
 * plane, though, while the water stands up to a wave's height off it: over a trough the whole
 * image showed above the cube as a dark patch (frame 40: 576 pixels, and none below). Frame 90
 * has the image below the cube, which must stay. */
static const char *const MIRROR_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 4}\n"
    MIRROR_RENDER
    "sky: {time_of_day: 18.5}\n"
    MIRROR_WATER
    "objects:\n"
    "  cubes: [{position: [4, 0, -2], size: 0.8, density: 850}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 2.5, 6], look_at: [0, 0, -6]},\n"
    "         {t: 4, position: [4, 2.0, 4], look_at: [0, 0, -6]}]\n";
#define MIRROR_BEHIND_MAX 10  /* pixels of the cube's mirror image above it in its columns, at
                               * most (576 over a trough before the image's depth was tested) */
#define MIRROR_FRONT_MIN 300  /* pixels of it below the cube on frame 90, at least: 598, of a
                               * cube 0.12 m out of the water (1210 while the image also held its
                               * part under the water, over the reflection's plane) */

/* what a pixel of the image is tested for, with the object in place (on) and away (on0) */
typedef int (*image_test)(const mirror_frames *m, int x, int y, double level);

static int brighter_than_without(const mirror_frames *m, int x, int y, double by) {
    return luma(&m->on, x, y) > luma(&m->on0, x, y) + by;
}

static int redder_than_without(const mirror_frames *m, int x, int y, double by) {
    return px(&m->on, x, y)[0] > px(&m->on0, x, y)[0] + by;
}

static int luma_over(const mirror_frames *m, int x, int y, double level) {
    return luma(&m->on, x, y) > level;
}

/* the pixels of the object's image (mirror_image_at), and into *found those of them `test`
 * takes at `level` (none with test NULL) */
static long image_pixels(const mirror_frames *m, image_test test, double level, long *found) {
    long n = 0;
    *found = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            if (!mirror_image_at(m, x, y)) continue;
            n++;
            *found += test && test(m, x, y, level);
        }
    return n;
}

typedef struct mirror_count {
    long cube, behind, front;
} mirror_count;

/* frame `frame` of the scene with the reflection on and off, each with the cube in place and
 * 4 km away: the cube's pixels, and its mirror image's above and below it in its columns */
static mirror_count mirror_image_count(const char *scene, int frame, const char *tag) {
    mirror_count m = {0};
    mirror_frames f = mirror_frames_render(scene, frame, NULL, CUBE_AWAY, tag);
    if (f.ok) {
        for (int x = 0; x < W; x++) {
            int top = H, bottom = -1;
            for (int y = 0; y < H; y++)
                if (max_diff(&f.off, &f.off0, x, y) > MASK_THRESH) {
                    top = y < top ? y : top;
                    bottom = y;
                    m.cube++;
                }
            for (int y = 0; bottom >= 0 && y < H; y++) {
                if (y >= top && y <= bottom) continue;
                int image = mirror_image_at(&f, x, y);
                m.behind += image && y < top;
                m.front += image && y > bottom;
            }
        }
    }
    mirror_frames_free(&f);
    return m;
}

TEST_IMAGE(picture_water_no_mirror_image_behind_what_floats) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_mirror", MIRROR_SCENE);
    mirror_count trough = mirror_image_count(scene, 40, "pw_mirror");
    mirror_count calm = mirror_image_count(scene, 90, "pw_mirror");
    printf("  frame 40: cube %ld px, its mirror image %ld px above it, %ld below; frame 90: cube "
           "%ld px, image %ld above, %ld below\n", trough.cube, trough.behind, trough.front,
           calm.cube, calm.behind, calm.front);
    ENSURE_MSG(trough.cube > 300 && calm.cube > 300, "the cube was not found: %ld, %ld pixels",
               trough.cube, calm.cube);
    ENSURE_MSG(trough.behind <= MIRROR_BEHIND_MAX && calm.behind <= MIRROR_BEHIND_MAX,
               "the cube's mirror image shows beyond it: %ld and %ld pixels (at most %d)",
               trough.behind, calm.behind, MIRROR_BEHIND_MAX);
    ENSURE_MSG(calm.front >= MIRROR_FRONT_MIN,
               "the cube's mirror image in front of it is gone: %ld pixels (at least %d)",
               calm.front, MIRROR_FRONT_MIN);
}

/* ---- nothing under the water in the mirror ---------------------------------------------- */

/* one long wave (20 m, 0.3 m high) puts a crest over a static 1 m box 10 m ahead while the
 * camera stands over a trough (frame 27, t = 0.9 s). The box's top is 0.05 m over the rest
 * level, 0.25 m under the crest: under water, so it has no mirror image, and with the
 * refraction off the frame shows no trace of it. The reflection's clip plane is the surface
 * over the camera, 0.3 m under the rest level, so with the plane alone the box's upper part was
 * drawn into the mirror image, lit as if in air, and it showed on the water as a box afloat
 * (563 pixels, now 0). The same box raised 0.55 m stands 0.3 m out of the water, and its image
 * must stay (306 pixels: 903 while its part under the water, over the plane, was mirrored). */
static const char *const SUNKEN_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    MIRROR_RENDER
    "sky: {time_of_day: 15}\n"
    "water:\n"
    "  waves: {model: gerstner, list: [{direction: 90, wavelength: 20, amplitude: 0.3, steepness: 0.3}]}\n"
    "  look: {foam: false, caustics: false}\n"
    "objects:\n"
    "  models: [{name: box, mesh: box, position: [0, -0.45, -10], scale: 1.0, color: [0.8, 0.5, 0.3]}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 2.5, 0], look_at: [0, 0, -10]}]\n";
#define SUNKEN_FRAME 27       /* the crest over the box, the trough under the camera */
#define SUNKEN_IMAGE_MAX 10   /* pixels of the sunken box's mirror image, at most */
#define AFLOAT_IMAGE_MIN 200  /* pixels of the raised box's mirror image, at least */

/* pixels of the box's mirror image on frame SUNKEN_FRAME with the box at `at`: those the box
 * moves with the reflection on (against the box 4 km away) and not with it off */
static long sunken_image_count(const char *scene, const char *at, const char *tag) {
    char here[200];
    snprintf(here, sizeof here, "--set \"objects.models[0].position=%s\"", at);
    mirror_frames f = mirror_frames_render(scene, SUNKEN_FRAME, here,
                                           "--set \"objects.models[0].position=[0,-0.45,-4000]\"",
                                           tag);
    long n = -1, none;
    if (f.ok) n = image_pixels(&f, NULL, 0.0, &none);
    mirror_frames_free(&f);
    return n;
}

TEST_IMAGE(picture_water_nothing_under_the_water_in_the_mirror) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_sunken", SUNKEN_SCENE);
    long sunken = sunken_image_count(scene, "[0,-0.45,-10]", "pw_sunken");
    long afloat = sunken_image_count(scene, "[0,0.1,-10]", "pw_afloat");
    printf("  mirror image: the sunken box %ld pixels, the box afloat %ld\n", sunken, afloat);
    ENSURE_MSG(sunken >= 0 && afloat >= 0, "a frame was not rendered");
    ENSURE_MSG(sunken <= SUNKEN_IMAGE_MAX,
               "a box under the water shows in the mirror: %ld pixels (at most %d)", sunken,
               SUNKEN_IMAGE_MAX);
    ENSURE_MSG(afloat >= AFLOAT_IMAGE_MIN,
               "the mirror image of a box out of the water is gone: %ld pixels (at least %d)",
               afloat, AFLOAT_IMAGE_MIN);
}

/* a 1 m cube afloat on the waves at noon, seen from 2 m up and 6 m away: its top is lit, its
 * sides are not, and its mirror image on the water is its sides and underside, darker than the
 * sky's reflection the water shows without it. The reflection's plane cuts the cube open at
 * the waterline, and the mirror camera below sees inside it, where the waves' distortion reads
 * the mirror image along the waterline: the inside of its top, lit as the top, showed there as
 * a pale band brighter than the water (frame 39: 219 pixels, now 0). Counted: pixels of the
 * mirror image (moved by the cube with the reflection on, not with it off) brighter than the
 * water there without the cube. */
static const char *const INSIDE_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    MIRROR_RENDER
    "sky: {time_of_day: 12}\n"
    MIRROR_WATER
    "objects:\n"
    "  cubes: [{position: [0, 0, -6], size: 1.0, density: 600}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 2.0, 0], look_at: [0, 0, -6]}]\n";
#define INSIDE_FRAME 39
#define INSIDE_BRIGHTER 12   /* luma levels over the water without the cube that count a pixel */
#define INSIDE_BRIGHT_MAX 10 /* such pixels of the mirror image, at most */
#define INSIDE_IMAGE_MIN 500 /* pixels of the mirror image, at least: it is there */

TEST_IMAGE(picture_water_no_inside_of_what_floats_in_the_mirror) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_inside", INSIDE_SCENE);
    mirror_frames f = mirror_frames_render(scene, INSIDE_FRAME, NULL, CUBE_AWAY, "pw_inside");
    if (f.ok) {
        long bright, image = image_pixels(&f, brighter_than_without, INSIDE_BRIGHTER, &bright);
        printf("  the cube's mirror image: %ld pixels, %ld brighter than the water\n", image,
               bright);
        ENSURE_MSG(image >= INSIDE_IMAGE_MIN, "the cube's mirror image was not found: %ld pixels",
                   image);
        ENSURE_MSG(bright <= INSIDE_BRIGHT_MAX,
                   "the inside of the cube shows in its mirror image: %ld pixels brighter than "
                   "the water (at most %d)",
                   bright, INSIDE_BRIGHT_MAX);
    }
    mirror_frames_free(&f);
}

/* INSIDE_SCENE's cube with the refraction on and the reflection off, frame 39. The prepass
 * cuts the cube at the wave surface and keeps its part under the water, which the camera above
 * sees into. The inside of its bottom, lit as a top face, and of its far walls showed at the
 * waterline, where the waves' distortion reads the refracted image over the cut: a patch and a
 * line as bright as the cube's top (13 pixels, now 0). Counted: pixels of the refracted image
 * within TOP_NEAR levels of luma of the top's (the brightest tenth of the cube's pixels). */
#define TOP_NEAR 40      /* luma levels under the top's that count a pixel as lit as the top */
#define TOP_LIKE_MAX 3   /* such pixels of the refracted image, at most */

static int compare_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

TEST_IMAGE(picture_water_no_inside_of_what_floats_in_the_refraction) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_inside", INSIDE_SCENE);
    mirror_frames f = image_frames_render(
        scene, INSIDE_FRAME, "--set render.refraction=true --set render.reflection=false",
        CUBE_AWAY " --set render.refraction=true --set render.reflection=false",
        "render.refraction", "pw_refr_inside");
    if (f.ok) {
        static double cube[W * H];
        long ncube = 0, lit;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                if (max_diff(&f.off, &f.off0, x, y) > MASK_THRESH)
                    cube[ncube++] = luma(&f.off, x, y);
        qsort(cube, (size_t)ncube, sizeof cube[0], compare_double);
        double top = ncube > 0 ? cube[ncube - 1 - ncube / 10] : 0.0;
        long image = image_pixels(&f, luma_over, top - TOP_NEAR, &lit);
        printf("  the cube: %ld pixels, its top's luma %.1f; its refracted image: %ld pixels, "
               "%ld as bright as the top\n", ncube, top, image, lit);
        ENSURE_MSG(ncube > 1000 && image >= INSIDE_IMAGE_MIN,
                   "the cube or its refracted image was not found: %ld, %ld pixels", ncube, image);
        ENSURE_MSG(lit <= TOP_LIKE_MAX,
                   "the inside of the cube shows in the refraction: %ld pixels as bright as its "
                   "top (at most %d)", lit, TOP_LIKE_MAX);
    }
    mirror_frames_free(&f);
}

/* the rowing boat afloat at noon, seen from 1.6 m up and 7 m away, its bow turned 30 degrees
 * away. Its hull is a shell around a hollow, and the reflection's cut opens both: the mirror
 * camera below looked up through the cut into the hollow, where the inner skin's faces are
 * turned toward it and lit, and the waves' distortion showed them under the hull as a pink
 * band (frame 60: 28 pixels of the image redder than the water without the boat, now 0).
 * The hull's faces turned toward its box's centre are shaded as the cut's face there. */
static const char *const HOLLOW_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 3}\n"
    MIRROR_RENDER
    "sky: {time_of_day: 12}\n"
    MIRROR_WATER
    "objects:\n"
    "  boat: {position: [0, 0.25, -7], heading: 30}\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 1.6, 0], look_at: [0, 0, -7]}]\n";
#define HOLLOW_FRAME 60
#define HOLLOW_REDDER 12   /* levels of red over the water's there without the boat that
                            * count a pixel of the image as the lit inside's pink (the hull's
                            * shaded outside is darker than the water) */
#define HOLLOW_RED_MAX 5   /* such pixels, at most */

TEST_IMAGE(picture_water_no_hollow_of_the_boat_in_the_mirror) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_hollow", HOLLOW_SCENE);
    mirror_frames f = mirror_frames_render(scene, HOLLOW_FRAME, NULL,
                                           "--set \"objects.boat.position=[0,0.25,-4000]\"",
                                           "pw_hollow");
    if (f.ok) {
        long red, image = image_pixels(&f, redder_than_without, HOLLOW_REDDER, &red);
        printf("  the boat's mirror image: %ld pixels, %ld redder than the water by more than "
               "%d levels\n", image, red, HOLLOW_REDDER);
        ENSURE_MSG(image >= INSIDE_IMAGE_MIN, "the boat's mirror image was not found: %ld pixels",
                   image);
        ENSURE_MSG(red <= HOLLOW_RED_MAX,
                   "the boat's hollow shows in its mirror image: %ld pinkish pixels (at most %d)",
                   red, HOLLOW_RED_MAX);
    }
    mirror_frames_free(&f);
}

/* ---- the mirror image meets the waterline ------------------------------------------------ */

/* a static 1 m box standing 0.55 m out of a crest 0.3 m high (one 10 m wave), seen from 2.5 m
 * up and 10 m away with a crest under the camera too (frame 57, t = 1.9 s). Mirrored about the
 * rest plane, the box's image stood 0.6 m (twice the crest) below the waterline: in its columns
 * a band of water about 10 rows tall lay between the box and its image. Counted per column of
 * the box: the rows from its lowest pixel down to the first of its mirror image's. */
static const char *const MEET_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    MIRROR_RENDER
    "sky: {time_of_day: 15}\n"
    "water:\n"
    "  waves: {model: gerstner, list: [{direction: 90, wavelength: 10, amplitude: 0.3, steepness: 0.3}]}\n"
    "  look: {foam: false, caustics: false}\n"
    "objects:\n"
    "  models: [{name: box, mesh: box, position: [0, 0.35, -10], scale: 1.0, color: [0.8, 0.5, 0.3]}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 2.5, 0], look_at: [0, 0, -10]}]\n";
#define MEET_FRAME 57      /* the crests under the box and the camera */
#define MEET_GAP_MAX 1     /* rows of water between the waterline and the image in the median
                            * column, at most (the crest's curvature over the box's half width,
                            * 3 cm, is under a row) */
#define MEET_COLUMNS_MIN 30 /* columns of the box with an image under them, at least */

static int compare_int(const void *a, const void *b) {
    return *(const int *)a - *(const int *)b;
}

TEST_IMAGE(picture_water_the_mirror_image_meets_the_waterline) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_meet", MEET_SCENE);
    mirror_frames f = mirror_frames_render(scene, MEET_FRAME, NULL,
                                           "--set \"objects.models[0].position=[0,0.35,-4000]\"",
                                           "pw_meet");
    if (f.ok) {
        int gap[W], n = 0;
        for (int x = 0; x < W; x++) {
            int bottom = -1, image = -1;
            for (int y = 0; y < H; y++)
                if (max_diff(&f.off, &f.off0, x, y) > MASK_THRESH) bottom = y;
            for (int y = bottom + 1; bottom >= 0 && image < 0 && y < H; y++)
                if (mirror_image_at(&f, x, y)) image = y;
            if (image >= 0) gap[n++] = image - bottom - 1;
        }
        qsort(gap, (size_t)n, sizeof gap[0], compare_int);
        int median = n > 0 ? gap[n / 2] : -1;
        printf("  %d columns of the box with its image under them; rows of water between: "
               "median %d, least %d, most %d\n", n, median, n > 0 ? gap[0] : -1,
               n > 0 ? gap[n - 1] : -1);
        ENSURE_MSG(n >= MEET_COLUMNS_MIN, "the box's mirror image was not found: %d columns", n);
        ENSURE_MSG(median <= MEET_GAP_MAX,
                   "the box's mirror image stands off its waterline: %d rows of water between "
                   "(at most %d)", median, MEET_GAP_MAX);
    }
    mirror_frames_free(&f);
}

/* ---- submerged outlines: straight, not stairs ------------------------------------------- */

/* a 2 m cube turned 30 deg, floating 0.4 m out of flat water, seen from 3 m up and 5 m away:
 * the lower right edge of its submerged side, seen through the surface, is a straight line from
 * about (300, 258) to (385, 228) on the 640x360 frame. The refraction prepass is half the
 * frame's size; its depth read nearest, the water's thickness (and the absorption with it)
 * stepped along the outline in 2-pixel stairs; its colour and depth read bilinear, the outline
 * still wobbled along the prepass's texels. Per column the edge is where the luma crosses
 * halfway from the cube's to the water's, to a fraction of a pixel; a straight line is fitted
 * and what is left over is the stairs. */
#define OUTLINE_RMS_MAX 0.33 /* px: rms distance of the edge from its fitted line, at most: the
                             * stepped depth gave 0.53, read bilinear 0.40; upsampled by the
                             * full-size depth 0.287, as a full-size prepass (0.29): the
                             * pixels' own aliasing */
static const char *const OUTLINE_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {size: [640, 360], shadows: false, reflection: false, bloom: false, god_rays: false,\n"
    "         fxaa: false, seabed: false}\n"
    "sky: {time_of_day: 12}\n"
    "water: {waves: {model: flat}, look: {foam: false, caustics: false, distortion: 0}}\n"
    "objects:\n"
    "  cubes: [{position: [0, -0.6, 0], size: 2, density: 700, rotation: [0, 30, 0]}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, 3, -5], look_at: [0, -0.8, 0]}]\n";

TEST_IMAGE(picture_water_submerged_outline_not_stepped) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_outline", OUTLINE_SCENE);
    char path[600];
    snprintf(path, sizeof path, "%s", scene);
    img a = render_frame(path, 0, NULL, "pw_outline_r");
    if (a.ok) {
        double water = 0.0;
        for (int y = 300; y < 340; y++)
            for (int x = 300; x < 380; x++) water += luma(&a, x, y);
        water /= 40.0 * 80.0;
        double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, ex[80], ey[80];
        int n = 0;
        for (int x = 305; x < 380; x++) {
            double hi = 0.0;
            for (int y = 180; y < 300; y++) hi = fmax(hi, luma(&a, x, y));
            double mid = 0.5 * (hi + water);
            int last = -1;
            for (int y = 180; y < 299; y++)
                if (luma(&a, x, y) > mid) last = y;
            if (last < 0) continue;
            double l0 = luma(&a, x, last), l1 = luma(&a, x, last + 1);
            double y = last + (l0 - mid) / fmax(l0 - l1, 1e-6);
            ex[n] = x;
            ey[n] = y;
            sx += x;
            sy += y;
            sxx += (double)x * x;
            sxy += x * y;
            n++;
        }
        ENSURE_MSG(n >= 60, "the edge was found in %d columns of 75", n);
        double k = (n * sxy - sx * sy) / (n * sxx - sx * sx), c = (sy - k * sx) / n, rms = 0.0;
        for (int i = 0; i < n; i++) rms += (ey[i] - k * ex[i] - c) * (ey[i] - k * ex[i] - c);
        rms = sqrt(rms / (n > 0 ? n : 1));
        printf("  submerged edge over %d columns: slope %.3f, rms off its line %.3f px\n", n, k, rms);
        ENSURE_MSG(k < -0.2 && k > -0.6, "the edge was not found where it lies: slope %.3f", k);
        ENSURE_MSG(rms <= OUTLINE_RMS_MAX, "stepped outline: %.3f px rms > %.3f", rms,
                   OUTLINE_RMS_MAX);
    }
    img_free(&a);
}

/* the same cube's submerged outline, at the half-size prepass the frame is drawn with and at
 * the quarter size of the preview preset, against a full-size prepass: read bilinear, the
 * smaller images' outlines stood up to 2 and 4 pixels off the full-size one's (369 and 568
 * pixels more than 32 levels apart, of 230,400); upsampled by the full-size depth, none are */
#define OUTLINE_OFF_LEVELS 32 /* levels of a pixel's channel a smaller prepass may move */
#define OUTLINE_OFF_MAX 20    /* pixels moved more than that, at most */

/* the scene's frame 0 with the prepass at half and at a quarter of the frame, each against the
 * full-size prepass's: at most `most` pixels more than OUTLINE_OFF_LEVELS apart */
static void prepass_sizes_against_full(const char *name, const char *yaml, long most) {
    char tag[40];
    snprintf(tag, sizeof tag, "%s_full", name);
    const char *scene = scene_file(tag, yaml);
    img full = render_frame(scene, 0, "--set \"render.refraction={scale: 1}\"", tag);
    static const char *const scales[2] = {"0.5", "0.25"};
    for (int k = 0; k < 2 && full.ok; k++) {
        char args[80];
        snprintf(args, sizeof args, "--set \"render.refraction={scale: %s}\"", scales[k]);
        snprintf(tag, sizeof tag, "%s_%d", name, k);
        img part = render_frame(scene, 0, args, tag);
        if (part.ok) {
            long off = 0;
            int largest = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    int d = max_diff(&part, &full, x, y);
                    off += d > OUTLINE_OFF_LEVELS;
                    largest = d > largest ? d : largest;
                }
            printf("  prepass at %s against full size: %ld px more than %d levels apart, "
                   "largest %d\n", scales[k], off, OUTLINE_OFF_LEVELS, largest);
            ENSURE_MSG(off <= most, "prepass at %s: %ld px more than %d levels from the "
                       "full-size prepass's frame (at most %ld)", scales[k], off,
                       OUTLINE_OFF_LEVELS, most);
        }
        img_free(&part);
    }
    img_free(&full);
}

TEST_IMAGE(picture_water_submerged_outline_as_a_full_size_prepass) {
    REQUIRE_GL();
    prepass_sizes_against_full("pw_outline", OUTLINE_SCENE, OUTLINE_OFF_MAX);
}

/* ---- under water: what floats is seen through Snell's window ---------------------------- */

/* a 1.5 m cube of density 250 (three quarters of it above the water) seen from 2.5 m down and
 * 2.5 m off, looking up past its underside into Snell's window. Its pixels are those that change
 * when it is moved 4 km away. Without the refraction prepass they are its submerged part alone;
 * with it, its part above the water shows through the window too, over the sky. The water once
 * read no prepass from below, and both counts were the same (25,005 px) */
#define ABOVE_SEEN_MIN 2000 /* pixels the part above the water adds through the window, at least
                             * (measured 4,933 of 230,400) */
static const char *const UP_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 30, duration: 1}\n"
    "render: {size: [640, 360], shadows: false, reflection: false, bloom: false, god_rays: false,\n"
    "         fxaa: false, seabed: false}\n"
    "sky: {time_of_day: 12}\n"
    "water:\n"
    "  depth: 6\n"
    "  waves: {model: gerstner, list: [{direction: 20, wavelength: 12, amplitude: 0.1, steepness: 0.5}]}\n"
    "  look: {foam: false, caustics: false}\n"
    "objects:\n"
    "  cubes: [{position: [0, 0, 0], size: 1.5, density: 250}]\n"
    "camera:\n"
    "  path: [{t: 0, position: [0, -2.5, -2.5], look_at: [0, 0.5, 0]}]\n";

static long pixels_apart(const img *a, const img *b) {
    long n = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) n += max_diff(a, b, x, y) > MASK_THRESH;
    return n;
}

TEST_IMAGE(picture_water_what_floats_seen_from_below_through_the_window) {
    REQUIRE_GL();
    mirror_frames cf = render_cube_frames(scene_file("pw_up", UP_SCENE), "pw_up");
    if (cf.ok) {
        long with = pixels_apart(&cf.on, &cf.on0), without = pixels_apart(&cf.off, &cf.off0);
        printf("  the cube's pixels from below: %ld with the prepass, %ld without\n", with,
               without);
        ENSURE_MSG(with - without >= ABOVE_SEEN_MIN,
                   "its part above the water adds %ld px through the window (at least %d)",
                   with - without, ABOVE_SEEN_MIN);
    }
    mirror_frames_free(&cf);
}

/* the same cube from below, at the half-size prepass the frame is drawn with and at the quarter
 * size of the preview preset, against a full-size prepass: its part above the water stands
 * against the sky in Snell's window, and read bilinear, the smaller images drew that outline in
 * their texels' stairs (393 and 601 pixels more than 32 levels from the full-size one's frame,
 * of 230,400); upsampled by the full-size depth, what is left (100 and 102) lies along the
 * waterline, where the part above meets the part below */
#define WINDOW_OFF_MAX 200 /* pixels more than OUTLINE_OFF_LEVELS from the full-size prepass's */
TEST_IMAGE(picture_water_window_outline_as_a_full_size_prepass) {
    REQUIRE_GL();
    prepass_sizes_against_full("pw_window", UP_SCENE, WINDOW_OFF_MAX);
}

/* ---- under water: the seabed is seen ----------------------------------------------------- */

/* RMS difference of luminance between pixels d apart (horizontally and vertically) over rows
 * y0..y1: texture, which a smooth fog gradient lacks */
static double texture_rms(const img *a, int y0, int y1, int d) {
    double s = 0.0;
    long n = 0;
    for (int y = y0; y + d < y1; y++)
        for (int x = 0; x + d < a->im.width; x++) {
            double l = luma(a, x, y), h = luma(a, x + d, y) - l, v = luma(a, x, y + d) - l;
            s += h * h + v * v;
            n += 2;
        }
    return n ? sqrt(s / (double)n) : 0.0;
}

/* scenes/lake.yaml at t = 12 s: the camera dives 1.2 m above the seabed, looking down at it */
TEST_IMAGE(picture_water_underwater_seabed_visible) {
    REQUIRE_GL();
    img a = render_frame("scenes/lake.yaml", 360, NULL, "pw_dive");
    if (a.ok) {
        double t = texture_rms(&a, H * 4 / 10, H, 12);
        printf("  seabed texture (RMS luma difference 12 px apart): %.2f\n", t);
        ENSURE_MSG(t >= SEABED_TEXTURE, "seabed texture %.2f < %.2f: the fog hides it", t,
                   SEABED_TEXTURE);
    }
    img_free(&a);
}

/* scenes/lake.yaml at t = 11 s, 2 m under water (17.4 h: the sun 7 deg up), and the same at
 * night: the open water beside the chest's glow (the frame's left 15%) is the below-water fog
 * alone. Lit by the night sky it must be dark; it kept its daylight teal (0.80 of the day's
 * luma) while the seabed under it went dark, now 0.10. */
#define NIGHT_WATER_MAX 0.2 /* the open water's mean luma at night over by day, at most */
TEST_IMAGE(picture_water_underwater_dark_at_night) {
    REQUIRE_GL();
    img day = render_frame("scenes/lake.yaml", 330, NULL, "pw_under_day");
    img night = render_frame("scenes/lake.yaml", 330, "--set sky.time_of_day=23", "pw_under_night");
    if (day.ok && night.ok) {
        double d = 0.0, n = 0.0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W * 15 / 100; x++) {
                d += luma(&day, x, y);
                n += luma(&night, x, y);
            }
        printf("  open water under the surface: mean luma %.1f by day, %.1f at night\n",
               d / (H * (W * 15 / 100)), n / (H * (W * 15 / 100)));
        ENSURE_MSG(d > 0.0 && n <= NIGHT_WATER_MAX * d, "the water glows at night: %.2f of the "
                   "day's light > %.2f", d > 0.0 ? n / d : 0.0, NIGHT_WATER_MAX);
    }
    img_free(&day);
    img_free(&night);
}

/* ---- caustics: seen on the seabed ------------------------------------------------------- */

/* the seabed (the frame's lower 40%) with caustics on and off: how far the caustics move its
 * pixels, on the reef 10 m down (scenes/reef.yaml frame 420, the camera 1.3 m over the seabed by the chest) and in
 * the shallow lake of scenes/features/caustics.yaml. From the swell alone they moved the reef's
 * seabed by 2.84 levels on average and the lake's by 7.74; with the surface's fine ripples,
 * which focus most of the light under a light breeze, 7.70 and 10.40. */
#define CAUSTICS_REEF_MIN 5.0  /* mean 8-bit levels the caustics move the reef's seabed, at least */
#define CAUSTICS_LAKE_MIN 9.0  /* the same in the shallow lake */
static double caustics_move(const char *scene, int frame, const char *tag) {
    char on_tag[64], off_tag[64];
    snprintf(on_tag, sizeof on_tag, "%s_on", tag);
    snprintf(off_tag, sizeof off_tag, "%s_off", tag);
    img on = render_frame(scene, frame, NULL, on_tag);
    img off = render_frame(scene, frame, "--set water.look.caustics=false", off_tag);
    double m = 0.0;
    long n = 0;
    if (on.ok && off.ok)
        for (int y = H * 60 / 100; y < H; y++)
            for (int x = 0; x < W; x++, n++) m += fabs(luma(&on, x, y) - luma(&off, x, y));
    img_free(&on);
    img_free(&off);
    return n ? m / (double)n : 0.0;
}

TEST_IMAGE(picture_water_caustics_seen_on_the_seabed) {
    REQUIRE_GL();
    double reef = caustics_move("scenes/reef.yaml", 420, "pw_caustics_reef");
    double lake = caustics_move("scenes/features/caustics.yaml", 0, "pw_caustics_lake");
    printf("  caustics move the seabed by %.2f levels on the reef (10 m), %.2f in the shallow lake\n",
           reef, lake);
    ENSURE_MSG(reef >= CAUSTICS_REEF_MIN, "caustics on the reef: %.2f < %.2f", reef,
               CAUSTICS_REEF_MIN);
    ENSURE_MSG(lake >= CAUSTICS_LAKE_MIN, "caustics in the lake: %.2f < %.2f", lake,
               CAUSTICS_LAKE_MIN);
}

/* ---- cubemap: no dark streaks ------------------------------------------------------------ */

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* scenes/features/skybox.yaml frame 0: the camera 3 m up looking 2.8 deg up; the horizon lies
 * at 53% of the height; the water below 58% */
TEST_IMAGE(picture_water_cubemap_no_dark_streaks) {
    REQUIRE_GL();
    img a = render_frame("scenes/features/skybox.yaml", 0, NULL, "pw_skybox");
    if (a.ok) {
        int y0 = H * 58 / 100;
        long n = (long)(H - y0) * W, dark = 0, k = 0;
        double *l = malloc((size_t)n * sizeof *l);
        ENSURE(l != NULL);
        if (l) {
            for (int y = y0; y < H; y++)
                for (int x = 0; x < W; x++) l[k++] = luma(&a, x, y);
            double *s = malloc((size_t)n * sizeof *s);
            ENSURE(s != NULL);
            if (s) {
                memcpy(s, l, (size_t)n * sizeof *s);
                qsort(s, (size_t)n, sizeof *s, cmp_double);
                double median = s[n / 2];
                /* a streak: a thin line darker than the water STREAK_ROWS above and below it,
                 * and dark in itself (the gaps between sun glints are not) */
                for (int y = y0 + STREAK_ROWS; y < H - STREAK_ROWS; y++)
                    for (int x = 0; x < W; x++) {
                        double c = l[(long)(y - y0) * W + x];
                        double up = l[(long)(y - STREAK_ROWS - y0) * W + x];
                        double dn = l[(long)(y + STREAK_ROWS - y0) * W + x];
                        dark += c < STREAK_DEPTH * up && c < STREAK_DEPTH * dn &&
                                c < DARK_STREAK_LEVEL * median;
                    }
                double frac = (double)dark / (double)n;
                printf("  water median luma %.1f; %ld of %ld pixels in dark streaks (%.4f)\n",
                       median, dark, n, frac);
                ENSURE_MSG(frac <= DARK_STREAK_FRACTION, "dark streak fraction %.4f > %.4f", frac,
                           DARK_STREAK_FRACTION);
                free(s);
            }
            free(l);
        }
    }
    img_free(&a);
}

/* ---- from high up: no band, no moire ------------------------------------------------------ */

/* the largest jump of the mean luminance between neighbouring rows y0..y1, and the mean
 * |L - mean of its 4 neighbours| there */
static void row_steps(const img *a, int y0, int y1, double *step, double *hf) {
    double prev = 0.0, s = 0.0;
    long n = 0;
    int w = a->im.width, h = a->im.height;
    *step = 0.0;
    for (int y = y0; y < y1; y++) {
        double m = 0.0;
        for (int x = 0; x < w; x++) {
            double l = luma(a, x, y);
            m += l;
            if (x > 0 && x + 1 < w && y > 0 && y + 1 < h) {
                double nb = 0.25 * (luma(a, x - 1, y) + luma(a, x + 1, y) + luma(a, x, y - 1) +
                                    luma(a, x, y + 1));
                s += fabs(l - nb);
                n++;
            }
        }
        m /= w;
        if (y > y0 && fabs(m - prev) > *step) *step = fabs(m - prev);
        prev = m;
    }
    *hf = n ? s / (double)n : 0.0;
}

/* scenes/demo.yaml's sea from 300 m up looking 1 deg down at the horizon (55 deg fov: the
 * horizon 53% down), in clear air so that the fog hides nothing of the water's own edge; at
 * 1280x720, where the moire of waves shaded near 2 pixels per wavelength shows */
TEST_IMAGE(picture_water_high_view_no_band_no_moire) {
    REQUIRE_GL();
    const int w = 2 * W, h = 2 * H;
    img a = render_frame_at("scenes/demo.yaml", 0,
                            "--set \"camera.path[0].position=[0,300,0]\" "
                            "--set \"camera.path[0].look_at=[0,295,-300]\" "
                            "--set fog.above.density=0.0001 --set sky.clouds.cover=0",
                            "pw_high", w, h);
    if (a.ok) {
        double step, hf;
        row_steps(&a, h * 55 / 100, h - 1, &step, &hf);
        printf("  largest row-to-row step of the mean luma %.2f; high-frequency energy %.3f\n", step,
               hf);
        ENSURE_MSG(step <= ROW_STEP_MAX, "a band edge: rows differ by %.2f > %.2f", step,
                   ROW_STEP_MAX);
        ENSURE_MSG(hf <= HIGH_FREQ_MAX, "moire: high-frequency energy %.3f > %.3f", hf,
                   HIGH_FREQ_MAX);
    }
    img_free(&a);
}

/* ---- foam: soft, and more of it on steeper waves ------------------------------------------- */

typedef struct foam_stats {
    long foam;      /* pixels foam brightens by FOAM_LEVEL or more */
    double soft;    /* the share of them under half the 99th percentile of the added light */
} foam_stats;

static foam_stats foam_measure(const char *steepness, const char *tag) {
    foam_stats f = {0};
    char on_args[128], off_args[200], tag_on[64], tag_off[64];
    snprintf(on_args, sizeof on_args, "--set water.waves.spectrum.steepness=%s", steepness);
    snprintf(off_args, sizeof off_args, "%s --set water.look.foam=false", on_args);
    snprintf(tag_on, sizeof tag_on, "%s_on", tag);
    snprintf(tag_off, sizeof tag_off, "%s_off", tag);
    img on = render_frame("scenes/spectrum.yaml", 45, on_args, tag_on);
    img off = render_frame("scenes/spectrum.yaml", 45, off_args, tag_off);
    if (on.ok && off.ok) {
        int hist[256] = {0};
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int d = (int)lround(luma(&on, x, y) - luma(&off, x, y));
                if (d >= FOAM_LEVEL) {
                    hist[d > 255 ? 255 : d]++;
                    f.foam++;
                }
            }
        long c = 0;
        int p99 = 255;
        for (int d = 0; d < 256; d++) {
            c += hist[d];
            if (c >= f.foam * 99 / 100) {
                p99 = d;
                break;
            }
        }
        long soft = 0;
        for (int d = FOAM_LEVEL; d < p99 / 2 + 1 && d < 256; d++) soft += hist[d];
        f.soft = f.foam ? (double)soft / (double)f.foam : 0.0;
        printf("  steepness %s: %ld foam pixels, %.3f of them soft (99th percentile %d levels)\n",
               steepness, f.foam, f.soft, p99);
    }
    img_free(&on);
    img_free(&off);
    return f;
}

/* scenes/spectrum.yaml frame 45 (a JONSWAP sea, 48 components) at two steepnesses */
TEST_IMAGE(picture_water_foam_soft_and_follows_steepness) {
    REQUIRE_GL();
    foam_stats calm = foam_measure("0.3", "pw_foam_calm");
    foam_stats steep = foam_measure("0.8", "pw_foam_steep");
    ENSURE_MSG(steep.foam > W * H / 200, "too little foam on the steep sea: %ld pixels", steep.foam);
    ENSURE_MSG(steep.foam > 2 * calm.foam, "foam coverage %ld at steepness 0.8 not above twice %ld "
               "at 0.3", steep.foam, calm.foam);
    ENSURE_MSG(steep.soft >= FOAM_SOFT_MIN, "foam edges hard: %.3f soft < %.3f", steep.soft,
               FOAM_SOFT_MIN);
}

/* ---- foam's memory: it gathers, trails behind a crest and fades ---------------------------- */

/* one steep Gerstner wave (8 m, period 2.26 s, Q A k = 0.71: it folds at every crest) travelling
 * toward +x, seen from 14 m straight above, so an image column is a line of one phase of the
 * wave (x to the right) and a crest crosses the frame in about 2 s; 30 frames at 10 fps */
#define FOAM_FRAMES 30
#define FOAM_W 320
#define FOAM_H 180
#define FOAM_FRESH_COLUMN 0.2  /* a column is under a crest when this share of it has fresh foam */
#define FOAM_TRAIL_SHARE 0.25  /* foamed pixel-frames off the fresh foam, with memory, at least */
#define FOAM_BEHIND_AHEAD 3.0  /* added light 1-3 frames behind a crest over 1-3 frames ahead of
                                * the next, at least: foam trails behind, never leads */
#define FOAM_FADES 2.0         /* added light 1-3 frames behind over 8-12 behind (life 5 frames:
                                * e^-0.4 against e^-2 of the coverage), at least */
#define FOAM_GATHERS 1.15      /* under a crest, the last frame's added light over the first's,
                                * with memory over without, at least */
static const char *const FOAM_MEMORY_SCENE =
    "seed: 1\n"
    "time: {dt: 1/120, fps: 10, duration: 3}\n"
    "render: {size: [320, 180], shadows: false, refraction: false, reflection: false, bloom: false,\n"
    "         god_rays: false, fxaa: false, msaa: 0, seabed: false}\n"
    "sky: {model: gradient, time_of_day: 12}\n"
    "water:\n"
    "  waves: {model: gerstner, list: [{direction: 0, wavelength: 8, amplitude: 0.9, steepness: 1}]}\n"
    "  look: {foam: {on: true, amount: 1, life: 0.5}, caustics: false}\n"
    "camera: {fov: 60, path: [{t: 0, position: [0, 14, 0.01], look_at: [0, 0, 0]}]}\n";

/* the luma foam adds to each pixel of each frame: the run with `args` less the run without foam */
static float *foam_added(const char *scene, const char *args, const char *tag) {
    char dir_on[512], dir_off[512], c[4096], path[700], tag2[64];
    snprintf(tag2, sizeof tag2, "%s_off", tag);
    snprintf(dir_on, sizeof dir_on, "%s", ww_test_tmpdir(tag));
    snprintf(dir_off, sizeof dir_off, "%s", ww_test_tmpdir(tag2));
    snprintf(c, sizeof c, "%s render %s --frames 0:%d -o %s --quiet %s", ww_test_bin(), scene,
             FOAM_FRAMES, dir_on, args);
    ENSURE_MSG(ww_test_run(c, NULL, NULL) == 0, "%s", c);
    snprintf(c, sizeof c, "%s render %s --frames 0:%d -o %s --quiet --set water.look.foam=false",
             ww_test_bin(), scene, FOAM_FRAMES, dir_off);
    ENSURE_MSG(ww_test_run(c, NULL, NULL) == 0, "%s", c);
    float *a = calloc((size_t)FOAM_FRAMES * FOAM_W * FOAM_H, sizeof *a);
    ENSURE(a != NULL);
    for (int t = 0; a && t < FOAM_FRAMES; t++) {
        img on = {0}, off = {0};
        ww_error err = {0};
        snprintf(path, sizeof path, "%s/frame_%05d.png", dir_on, t);
        on.ok = ww_read_png(path, &on.im, &err) == WW_OK && on.im.u8 && on.im.width == FOAM_W &&
                on.im.height == FOAM_H && on.im.channels >= 3;
        snprintf(path, sizeof path, "%s/frame_%05d.png", dir_off, t);
        off.ok = ww_read_png(path, &off.im, &err) == WW_OK && off.im.u8 &&
                 off.im.width == FOAM_W && off.im.height == FOAM_H && off.im.channels >= 3;
        ENSURE_MSG(on.ok && off.ok, "frame %d: %s", t, err.msg);
        if (on.ok && off.ok)
            for (int y = 0; y < FOAM_H; y++)
                for (int x = 0; x < FOAM_W; x++)
                    a[((size_t)t * FOAM_H + y) * FOAM_W + x] =
                        (float)(luma(&on, x, y) - luma(&off, x, y));
        img_free(&on);
        img_free(&off);
    }
    return a;
}

typedef struct foam_memory_stats {
    double trail;         /* share of the foamed pixel-frames that are not fresh foam */
    double behind, ahead; /* mean added light 1-3 frames behind a crest / ahead of the next */
    double old;           /* the same 8-12 frames behind */
    double gather;        /* under a crest: mean added light of its last frame over its first */
} foam_memory_stats;

/* `a` with memory, `f` without: a pixel of `f` adding FOAM_LEVEL or more is fresh foam; a column
 * is under a crest in a frame when FOAM_FRESH_COLUMN of it is */
static foam_memory_stats foam_memory_measure(const float *a, const float *f) {
    foam_memory_stats s = {0};
    static signed char under[FOAM_FRAMES][FOAM_W];
    for (int t = 0; t < FOAM_FRAMES; t++)
        for (int x = 0; x < FOAM_W; x++) {
            int n = 0;
            for (int y = 0; y < FOAM_H; y++) n += f[((size_t)t * FOAM_H + y) * FOAM_W + x] >= FOAM_LEVEL;
            under[t][x] = n >= FOAM_FRESH_COLUMN * FOAM_H;
        }
    long foamed = 0, trail = 0, nb = 0, na = 0, no = 0, ng = 0;
    double gfirst = 0.0, glast = 0.0;
    for (int x = 0; x < FOAM_W; x++)
        for (int t = 0; t < FOAM_FRAMES; t++) {
            int since = -1, until = -1; /* frames since the column was last under a crest, to next */
            for (int u = t; u >= 0; u--)
                if (under[u][x]) { since = t - u; break; }
            for (int u = t; u < FOAM_FRAMES; u++)
                if (under[u][x]) { until = u - t; break; }
            double col = 0.0;
            for (int y = 0; y < FOAM_H; y++) {
                size_t i = ((size_t)t * FOAM_H + y) * FOAM_W + x;
                col += a[i];
                if (a[i] >= FOAM_LEVEL) {
                    foamed++;
                    trail += f[i] < FOAM_LEVEL;
                }
            }
            col /= FOAM_H;
            if (since >= 1 && since <= 3 && (until < 0 || until > 3)) { s.behind += col; nb++; }
            if (until >= 1 && until <= 3 && (since < 0 || since > 8)) { s.ahead += col; na++; }
            if (since >= 8 && since <= 12 && (until < 0 || until > 3)) { s.old += col; no++; }
            /* a whole run under a crest: its first and last frames */
            if (under[t][x] && t > 0 && !under[t - 1][x]) {
                int e = t;
                while (e + 1 < FOAM_FRAMES && under[e + 1][x]) e++;
                if (e + 1 < FOAM_FRAMES && e > t) {
                    double c0 = 0.0, c1 = 0.0;
                    for (int y = 0; y < FOAM_H; y++) {
                        c0 += a[((size_t)t * FOAM_H + y) * FOAM_W + x];
                        c1 += a[((size_t)e * FOAM_H + y) * FOAM_W + x];
                    }
                    gfirst += c0;
                    glast += c1;
                    ng++;
                }
            }
        }
    s.trail = foamed ? (double)trail / (double)foamed : 0.0;
    s.behind = nb ? s.behind / (double)nb : 0.0;
    s.ahead = na ? s.ahead / (double)na : 0.0;
    s.old = no ? s.old / (double)no : 0.0;
    s.gather = ng && gfirst > 0.0 ? glast / gfirst : 0.0;
    ENSURE_MSG(nb > 0 && na > 0 && no > 0 && ng > 0, "the crests did not cross the frame: %ld %ld "
               "%ld %ld column-frames", nb, na, no, ng);
    return s;
}

TEST_IMAGE(picture_water_foam_gathers_trails_and_fades) {
    REQUIRE_GL();
    const char *scene = scene_file("pw_foam_memory", FOAM_MEMORY_SCENE);
    char path[600];
    snprintf(path, sizeof path, "%s", scene);
    float *mem = foam_added(path, "", "pw_foam_mem");
    float *now = foam_added(path, "--set water.look.foam.life=0", "pw_foam_now");
    if (mem && now) {
        foam_memory_stats m = foam_memory_measure(mem, now);
        foam_memory_stats z = foam_memory_measure(now, now);
        printf("  life 0.5 s: trail %.3f, added light behind %.2f ahead %.2f old %.2f, gathers "
               "%.2f\n  life 0:     trail %.3f, added light behind %.2f ahead %.2f old %.2f, "
               "gathers %.2f\n", m.trail, m.behind, m.ahead, m.old, m.gather, z.trail, z.behind,
               z.ahead, z.old, z.gather);
        ENSURE_MSG(m.trail >= FOAM_TRAIL_SHARE, "foam has no memory: %.3f of it off the fresh "
                   "foam < %.3f", m.trail, FOAM_TRAIL_SHARE);
        ENSURE_MSG(m.behind >= FOAM_BEHIND_AHEAD * m.ahead, "foam does not trail behind the crest: "
                   "%.2f behind, %.2f ahead", m.behind, m.ahead);
        ENSURE_MSG(m.behind >= FOAM_FADES * m.old, "foam does not fade: %.2f at 1-3 frames, %.2f "
                   "at 8-12", m.behind, m.old);
        ENSURE_MSG(m.gather >= FOAM_GATHERS * z.gather, "foam does not gather under the crest: "
                   "last/first %.2f with memory, %.2f without", m.gather, z.gather);
    }
    free(mem);
    free(now);
}

/* ---- the open sea: colour, contrast, no shimmer ------------------------------------------- */

/* scenes/demo.yaml frames 0 and 1: the camera 4 m up looking level at the low sun; the horizon
 * at mid-height. The near water (rows 80%..100%, within about 15 m) for colour, contrast and
 * fine detail; the far water (rows 51%..56%, hundreds of metres away) for the shimmer between
 * consecutive frames. */
TEST_IMAGE(picture_water_open_sea_colour_no_shimmer) {
    REQUIRE_GL();
    img a = render_frame("scenes/demo.yaml", 0, NULL, "pw_sea0");
    img b = render_frame("scenes/demo.yaml", 1, NULL, "pw_sea1");
    if (a.ok && b.ok) {
        double sat = 0.0, m = 0.0, m2 = 0.0, detail = 0.0;
        long n = 0;
        for (int y = H * 80 / 100; y < H - 1; y++)
            for (int x = 1; x + 1 < W; x++) {
                const unsigned char *p = px(&a, x, y);
                int hi = p[0] > p[1] ? p[0] : p[1], lo = p[0] < p[1] ? p[0] : p[1];
                hi = hi > p[2] ? hi : p[2];
                lo = lo < p[2] ? lo : p[2];
                sat += hi > 0 ? (double)(hi - lo) / hi : 0.0;
                double l = luma(&a, x, y);
                m += l;
                m2 += l * l;
                detail += fabs(l - 0.25 * (luma(&a, x - 1, y) + luma(&a, x + 1, y) +
                                           luma(&a, x, y - 1) + luma(&a, x, y + 1)));
                n++;
            }
        sat /= (double)n;
        m /= (double)n;
        detail /= (double)n;
        double sd = sqrt(fmax(m2 / (double)n - m * m, 0.0));
        double sh = 0.0;
        long k = 0;
        for (int y = H * 51 / 100; y < H * 56 / 100; y++)
            for (int x = 0; x < W; x++, k++) sh += fabs(luma(&a, x, y) - luma(&b, x, y));
        sh /= (double)k;
        printf("  near water: saturation %.3f, luma mean %.1f sd %.1f, detail %.3f; far shimmer "
               "%.2f\n", sat, m, sd, detail, sh);
        ENSURE_MSG(sat >= WATER_SATURATION_MIN, "washed out: saturation %.3f < %.3f", sat,
                   WATER_SATURATION_MIN);
        ENSURE_MSG(sd >= WATER_CONTRAST_MIN, "flat: luma sd %.1f < %.1f", sd, WATER_CONTRAST_MIN);
        ENSURE_MSG(detail >= WATER_DETAIL_MIN * m, "plastic: detail %.3f < %.4f of the mean "
                   "luma %.1f", detail, WATER_DETAIL_MIN, m);
        ENSURE_MSG(sh <= SHIMMER_MAX, "shimmer far away: %.2f > %.2f", sh, SHIMMER_MAX);
    }
    img_free(&a);
    img_free(&b);
}

/* The water drawn as the mesh's G-buffer and shaded once a pixel (gfx/water.c) against the same
 * frames shaded per fragment of the mesh (WW_WATER_FORWARD=1): the same picture but for the mip
 * levels chosen where a crest hides the water behind it */
TEST_IMAGE(picture_water_gbuffer_shades_as_the_mesh_did) {
    REQUIRE_GL();
    static const struct {
        const char *scene;
        int frame;
    } cases[] = {{"scenes/lake.yaml", 0},            /* cubes at the waterline */
                 {"scenes/demo.yaml", 240},          /* the sun's glitter */
                 {"scenes/reef.yaml", 560},          /* under water: Snell's window */
                 {"scenes/features/skybox.yaml", 0}}; /* the cubemap's mips on steep waves */
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ww_test_pic g, m;
        unsetenv("WW_WATER_FORWARD");
        int ok = ww_test_render_pic(cases[i].scene, cases[i].frame, "320x180", NULL, "gbuf_g", &g);
        setenv("WW_WATER_FORWARD", "1", 1);
        ok = ww_test_render_pic(cases[i].scene, cases[i].frame, "320x180", NULL, "gbuf_m", &m) &&
             ok;
        unsetenv("WW_WATER_FORWARD");
        if (ok) {
            int maxd = 0;
            double db = ww_test_pic_psnr(&m, &g, &maxd);
            long apart = 0;
            for (int y = 0; y < g.h; y++)
                for (int x = 0; x < g.w; x++)
                    for (int c = 0; c < 3; c++)
                        if (abs((int)ww_test_pixel(&g.im, x, y)[c] -
                                (int)ww_test_pixel(&m.im, x, y)[c]) > GBUF_LEVELS) {
                            apart++;
                            break;
                        }
            double share = (double)apart / ((double)g.w * g.h);
            printf("  %s %d: %.1f dB, largest %d levels, %.3f%% of pixels over %d\n",
                   cases[i].scene, cases[i].frame, db, maxd, 100.0 * share, GBUF_LEVELS);
            ENSURE_MSG(db >= GBUF_PSNR_MIN, "%s %d: %.1f dB < %.1f", cases[i].scene,
                       cases[i].frame, db, GBUF_PSNR_MIN);
            ENSURE_MSG(share <= GBUF_APART_MAX, "%s %d: %.3f%% of pixels over %d levels apart",
                       cases[i].scene, cases[i].frame, 100.0 * share, GBUF_LEVELS);
        }
        ww_image_free(&g.im);
        ww_image_free(&m.im);
    }
}

/* The G-buffer's pixels that are not water this frame hold an earlier frame's values; they must
 * not reach the picture: a frame rendered after others is the same, byte for byte, as the frame
 * rendered alone (a moving camera, cubes at the waterline, steep cubemap waves) */
TEST_IMAGE(picture_water_gbuffer_frame_does_not_depend_on_the_frames_before) {
    REQUIRE_GL();
    static const struct {
        const char *scene;
        int frame;
    } cases[] = {{"scenes/lake.yaml", 90}, {"scenes/features/skybox.yaml", 12}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char seq[768], one[768], args[1200], a[1024], b[1024];
        snprintf(seq, sizeof seq, "%s", ww_test_tmpdir("gbuf_seq"));
        snprintf(one, sizeof one, "%s", ww_test_tmpdir("gbuf_one"));
        int f = cases[i].frame;
        snprintf(args, sizeof args, "render %s --frames %d:%d --size 320x180 -o %s --quiet",
                 cases[i].scene, f - 6, f + 1, seq);
        int rc = ww_test_ww(args, NULL, NULL);
        snprintf(args, sizeof args, "render %s --frames %d:%d --size 320x180 -o %s --quiet",
                 cases[i].scene, f, f + 1, one);
        rc |= ww_test_ww(args, NULL, NULL);
        ENSURE_MSG(rc == 0, "%s: a render failed", cases[i].scene);
        if (rc != 0) continue;
        snprintf(a, sizeof a, "%s/frame_%05d.png", seq, f);
        snprintf(b, sizeof b, "%s/frame_%05d.png", one, f);
        ww_test_pic p = {0}, q = {0};
        if (ww_test_pic_load(a, &p) && ww_test_pic_load(b, &q)) {
            int maxd = 0;
            double db = ww_test_pic_psnr(&p, &q, &maxd);
            printf("  %s %d after %d others against alone: largest difference %d levels\n",
                   cases[i].scene, f, 6, maxd);
            ENSURE_MSG(maxd == 0, "%s %d: %.1f dB, %d levels apart", cases[i].scene, f, db, maxd);
        }
        ww_image_free(&p.im);
        ww_image_free(&q.im);
    }
}
