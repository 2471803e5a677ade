/* test_picture_water.c - the water's optics measured on rendered frames, not against goldens: a
 * statistic over a region of the picture (a mask from two renders, a count, a colour mean or
 * spread) that the defect it guards against moves, with a threshold named for what it allows.
 * Each test prints its figures, so a change in the look shows as numbers.
 *   underwater     a diver sees the seabed: texture (caustics, shading) survives the fog
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image.h"
#include "io/writers.h"
#include "test.h"

#define W 640 /* frames are rendered at 640x360 */
#define H 360

#define SEABED_TEXTURE 0.45      /* RMS 8-bit luminance difference of pixels 12 apart on the
                                  * seabed seen from 1.2 m above it, at least */

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

static const unsigned char *px(const img *a, int x, int y) {
    return a->im.u8 + ((size_t)y * (size_t)a->im.width + (size_t)x) * (size_t)a->im.channels;
}

/* Rec. 709 luma of the 8-bit values */
static double luma(const img *a, int x, int y) {
    const unsigned char *p = px(a, x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
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
