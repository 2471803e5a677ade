/* test_water_detail.c - the water's fine detail evaluated two ways (water.look.detail): the DuDv
 * noise's gradient read from its tiled texture against the exact per-pixel noise, on rendered
 * frames of the demo (water and sky, the DuDv's ripples in the reflections and the glitter). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/writers.h"
#include "test.h"

typedef struct pic {
    ww_image im;
    int w, h;
} pic;

/* render frame `frame` of scene at size with extra args into tmp dir `name`; loads it into p */
static int render_frame(const char *scene, int frame, const char *size, const char *args,
                        const char *name, pic *p) {
    char dir[768], c[2048], path[1024];
    ww_error err = {0};
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(name));
    snprintf(c, sizeof c, "render %s --frames %d:%d --size %s -o %s --quiet %s", scene, frame,
             frame + 1, size, dir, args ? args : "");
    int rc = ww_test_ww(c, NULL, NULL);
    ENSURE_MSG(rc == 0, "%s: exit %d", c, rc);
    if (rc != 0) return 0;
    snprintf(path, sizeof path, "%s/frame_%05d.png", dir, frame);
    *p = (pic){0};
    ENSURE_MSG(ww_read_png(path, &p->im, &err) == WW_OK, "%s: %s", path, err.msg);
    p->w = p->im.width;
    p->h = p->im.height;
    return p->im.u8 != NULL;
}

/* PSNR of b against a over RGB (8-bit), and the largest channel difference */
static double psnr_of(const pic *a, const pic *b, int *max_diff) {
    double se = 0.0;
    *max_diff = 0;
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++)
            for (int c = 0; c < 3; c++) {
                int d = abs((int)ww_test_pixel(&a->im, x, y)[c] - (int)ww_test_pixel(&b->im, x, y)[c]);
                se += (double)d * d;
                if (d > *max_diff) *max_diff = d;
            }
    double mse = se / (3.0 * a->w * a->h);
    return mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
}

/* The texture path against the exact one, and the DuDv's own effect (DuDv off against exact) so
 * that the agreement is not that of two frames without it: the texture's error must be a small
 * part of what the DuDv does to the frame. The default picture is one of the two, so it is held
 * within the same floor of the exact path. Measured at 640x360 on the demo's frame 0: texture
 * 54.2 dB (at most 15 levels), DuDv off 34.5 dB (65 levels). */
#define DETAIL_TEXTURE_PSNR_MIN 45.0 /* dB, texture (and default) against exact */
#define DETAIL_DUDV_PSNR_MAX 42.0    /* dB: the DuDv itself must move the frame more than this */
TEST_IMAGE(water_detail_texture_matches_exact) {
    REQUIRE_GL();
    pic exact, tex, def, off;
    const char *sc = "scenes/demo.yaml";
    if (!render_frame(sc, 0, "640x360", "--set water.look.detail=exact", "wd_exact", &exact)) return;
    if (!render_frame(sc, 0, "640x360", "--set water.look.detail=texture", "wd_tex", &tex)) return;
    if (!render_frame(sc, 0, "640x360", NULL, "wd_def", &def)) return;
    if (!render_frame(sc, 0, "640x360", "--set water.look.distortion=0", "wd_off", &off)) return;
    int m_tex, m_def, m_off;
    double p_tex = psnr_of(&exact, &tex, &m_tex), p_def = psnr_of(&exact, &def, &m_def);
    double p_off = psnr_of(&exact, &off, &m_off);
    fprintf(stderr, "    against exact: texture %.2f dB (max %d), default %.2f dB (max %d), "
                    "DuDv off %.2f dB (max %d)\n",
            p_tex, m_tex, p_def, m_def, p_off, m_off);
    ENSURE_MSG(p_tex >= DETAIL_TEXTURE_PSNR_MIN, "texture %.2f dB", p_tex);
    ENSURE_MSG(p_def >= DETAIL_TEXTURE_PSNR_MIN, "default %.2f dB", p_def);
    ENSURE_MSG(p_off <= DETAIL_DUDV_PSNR_MAX, "the DuDv moves the frame only to %.2f dB", p_off);
    ww_image_free(&exact.im);
    ww_image_free(&tex.im);
    ww_image_free(&def.im);
    ww_image_free(&off.im);
}
