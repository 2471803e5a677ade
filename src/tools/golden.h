/* golden.h - `render --golden DIR`: every rendered frame against its golden image, under the
 * scene's thresholds (its golden: section) or the command line's, with an HTML report.
 *
 *   ww_golden_opts g = {.golden_dir = "golden/demo", .out_dir = "out/demo", ...};
 *   ww_golden_summary sum;
 *   ww_golden_check(sc, &g, &sum, &err);   // WW_E_MISMATCH when a frame fails
 */
#ifndef WW_GOLDEN_H
#define WW_GOLDEN_H

#include <stdint.h>

#include "core/error.h"
#include "scene/scene.h"
#include "tools/compare.h"

typedef struct ww_golden_opts {
    const char *golden_dir;  /* DIR of --golden */
    const char *out_dir;     /* where the frames were written (PNG); the report goes here */
    int64_t first, last;     /* the frames rendered */
    const char *renderer;    /* GL_RENDERER of the run: with gl_version, picks per-renderer goldens */
    const char *gl_version;  /* GL_VERSION of the run */
    ww_cmp_opts cmp;         /* the scene's thresholds with the command line's over them */
} ww_golden_opts;

typedef struct ww_golden_summary {
    int64_t frames, passed, failed, missing;
    char golden_dir[600];    /* the folder the goldens were taken from */
    char report[600];        /* path of the HTML report */
} ww_golden_summary;

/* the scene's golden: thresholds as compare options (ww_cmp_default_opts() when it has none) */
ww_cmp_opts ww_golden_scene_opts(const ww_scene *sc);
ww_result ww_golden_check(const ww_scene *sc, const ww_golden_opts *o, ww_golden_summary *s,
                          ww_error *err);

#endif
