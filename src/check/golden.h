/* golden.h - `render --golden DIR`: every rendered frame against its golden image, under the
 * scene's thresholds (its golden: section) with the command line's over them, and an HTML report.
 *
 *   ww_golden_opts g = {.golden_dir = "golden/demo", .out_dir = "out/demo", ...};
 *   ww_golden_prepare(&g, &err);           // before rendering: DIR exists, holds no output
 *   ... render the frames into out_dir ...
 *   ww_golden_summary sum;
 *   ww_golden_check(sc, &g, &sum, &err);   // WW_E_MISMATCH when a frame fails or is missing
 *
 * Goldens per renderer. The renderer key names the GL implementation that made a frame (see
 * ww_golden_renderer_key). Frame N's golden is the first of
 *   DIR/KEY/frame_NNNNN.png, DIR/FALLBACK_1/frame_NNNNN.png, ..., DIR/frame_NNNNN.png
 * where the FALLBACKs are the scene's golden.fallback keys, in order. No golden: the frame fails.
 *
 * What lands in out_dir (every file written atomically): report.html (always), and for each
 * failing frame diff/frame_NNNNN.png (ww_cmp_write_diff) and expected/frame_NNNNN.png (a copy of
 * its golden, so that the folder is a self-contained CI artifact); stale ones of frames that now
 * pass are removed. No rule on at all (neither the scene nor the command line gives one) means
 * compare's default rule: no pixel over the per-pixel threshold (0: exact match).
 */
#ifndef WW_GOLDEN_H
#define WW_GOLDEN_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "check/compare.h"
#include "core/error.h"
#include "scene/scene.h"

typedef struct ww_golden_opts {
    const char *golden_dir;  /* DIR of --golden */
    const char *out_dir;     /* where the frames were written (PNG); the report goes here */
    int64_t first, last;     /* the frames rendered */
    const char *renderer;    /* GL_RENDERER of the run: with gl_version, picks per-renderer goldens */
    const char *gl_version;  /* GL_VERSION of the run */
    ww_cmp_opts cmp;         /* the scene's thresholds with the command line's over them */
    FILE *log;               /* a line per failing or missing frame and the key; NULL: silent */
} ww_golden_opts;

typedef struct ww_golden_summary {
    int64_t frames, passed, failed, missing;  /* failed excludes missing */
    double wall_s;                             /* time the check took (compare, diffs, report) */
    char key[WW_GOLDEN_KEY_SIZE];              /* the renderer key of the run */
    char golden_dir[600];    /* the folder(s) the goldens were taken from, with counts if several */
    char report[600];        /* path of the HTML report */
} ww_golden_summary;

/* the renderer key, e.g. "llvmpipe-mesa-22.3": lowercase letters, digits, '.', '-' only.
 *   Mesa (GL_VERSION holds "Mesa X.Y.Z"): FAMILY-mesa-X.Y, FAMILY the first word of GL_RENDERER
 *     after a leading "Mesa " (llvmpipe, softpipe, zink, intel, amd, ...)
 *   NVIDIA's driver (GL_VERSION "4.6.0 NVIDIA 535.104.05"): nvidia-535
 *   any other: FAMILY-gl-MAJOR.MINOR of GL_VERSION; nothing known: "unknown"
 * Mesa's point releases and NVIDIA's minor versions keep their rasterisation, so they share a key. */
void ww_golden_renderer_key(const char *renderer, const char *gl_version, char *out, size_t cap);

/* the scene's golden: thresholds as compare options (ww_cmp_default_opts() when it has none) */
ww_cmp_opts ww_golden_scene_opts(const ww_scene *sc);

/* before rendering: WW_E_NOFILE when golden_dir is not a folder, WW_E_USAGE when out_dir is
 * golden_dir or lies inside it (rendering would overwrite the goldens) */
ww_result ww_golden_prepare(const ww_golden_opts *o, ww_error *err);

/* after rendering: compares, writes the report; WW_E_MISMATCH (with a summary as the message)
 * when a frame fails or has no golden, WW_E_IO when a file cannot be written */
ww_result ww_golden_check(const ww_scene *sc, const ww_golden_opts *o, ww_golden_summary *s,
                          ww_error *err);

#endif
