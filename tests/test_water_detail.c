/* test_water_detail.c - the water's fine detail evaluated two ways (water.look.detail): the DuDv
 * noise's gradient read from its tiled texture against the exact per-pixel noise, on rendered
 * frames of the demo (water and sky, the DuDv's ripples in the reflections and the glitter). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/writers.h"
#include "test.h"

typedef ww_test_pic pic;

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
    if (!ww_test_render_pic(sc, 0, "640x360", "--set water.look.detail=exact", "wd_exact",
                            &exact)) return;
    if (!ww_test_render_pic(sc, 0, "640x360", "--set water.look.detail=texture", "wd_tex",
                            &tex)) return;
    if (!ww_test_render_pic(sc, 0, "640x360", NULL, "wd_def", &def)) return;
    if (!ww_test_render_pic(sc, 0, "640x360", "--set water.look.distortion=0", "wd_off",
                            &off)) return;
    int m_tex, m_def, m_off;
    double p_tex = ww_test_pic_psnr(&exact, &tex, &m_tex), p_def = ww_test_pic_psnr(&exact, &def,
                                    &m_def);
    double p_off = ww_test_pic_psnr(&exact, &off, &m_off);
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
