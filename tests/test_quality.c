/* test_quality.c - render.quality's presets measured on rendered frames: each preset's frame
 * against final's, by PSNR, on the lake at the chest, the open sea and the cubes seen through
 * the water. The presets trade the
 * knobs whose cheaper values cost the least picture (docs/speed.md, "Quality presets"); these
 * floors hold them to that. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "test.h"

/* dB of the preset's frame against final's at 320x180 (measured: lake 40.6 / 38.1, demo
 * frame 150 39.8 / 33.3, cubes frame 75 39.7 / 35.3; at 1280x720 the same presets keep 41-45
 * and 35-40 dB, a frame drawn smaller losing less the more pixels it has) */
#define PREVIEW_PSNR_MIN 38.0 /* preview: lighter reflection, refraction, shafts; frame at 0.9 */
#define DRAFT_PSNR_MIN 32.0   /* draft: the frame at 0.75, lighter shadows, no FXAA */

static double psnr_of(const char *a_path, const char *b_path) {
    ww_test_pic a = {0}, b = {0};
    int max_diff = 0;
    double db = -1.0;
    if (ww_test_pic_load(a_path, &a) && ww_test_pic_load(b_path, &b) && a.w == b.w && a.h == b.h)
        db = ww_test_pic_psnr(&a, &b, &max_diff);
    ww_image_free(&a.im);
    ww_image_free(&b.im);
    return db;
}

static void preset_psnr(const char *scene, int frame, const char *tag) {
    static const char *const q[3] = {"final", "preview", "draft"};
    char png[3][900];
    for (int k = 0; k < 3; k++) {
        const char *dir = ww_test_tmpdir(tag);
        char args[200], out[800];
        snprintf(out, sizeof out, "%s/%s", dir, q[k]);
        snprintf(args, sizeof args, "--size 320x180 --set render.quality=%s", q[k]);
        char cmd[1400];
        snprintf(cmd, sizeof cmd, "render %s --frames %d:%d -o %s --quiet %s", scene, frame,
                 frame + 1, out, args);
        ENSURE_EQ_INT(ww_test_ww(cmd, NULL, NULL), 0);
        snprintf(png[k], sizeof png[k], "%s/frame_%05d.png", out, frame);
    }
    double prev = psnr_of(png[0], png[1]), draft = psnr_of(png[0], png[2]);
    fprintf(stderr, "    %s frame %d: preview %.1f dB, draft %.1f dB against final\n", scene,
            frame, prev, draft);
    ENSURE_MSG(prev >= PREVIEW_PSNR_MIN, "%s preview %.1f dB < %g", scene, prev, PREVIEW_PSNR_MIN);
    ENSURE_MSG(draft >= DRAFT_PSNR_MIN, "%s draft %.1f dB < %g", scene, draft, DRAFT_PSNR_MIN);
    ENSURE_MSG(prev > draft, "%s: preview %.1f dB is not closer to final than draft %.1f", scene,
               prev, draft);
}

TEST_IMAGE(quality_presets_stay_close_to_final) {
    REQUIRE_GL();
    preset_psnr("scenes/lake.yaml", 300, "quality_lake");
    preset_psnr("scenes/demo.yaml", 150, "quality_demo");
    preset_psnr("scenes/cubes.yaml", 75, "quality_cubes");
}
