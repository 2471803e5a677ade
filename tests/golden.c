/* golden.c - image checks shared by the test files: a rendered frame against its golden (exact
 * on the renderer that blessed golden/ or against the renderer's own golden in DIR/KEY/, within a
 * tolerance elsewhere), rendering one frame of a scene, and where two images differ relative to a
 * rectangle (the toggle tests).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check/golden.h"
#include "core/mathx.h"
#include "gfx/backend.h"
#include "io/writers.h"
#include "scene/scene.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* On a renderer other than the one in golden/RENDERER, without goldens of its own (DIR/KEY/):
 * what llvmpipe of another Mesa release changes in the goldens of Mesa 22.3. Measured with
 * `scripts/make-golden.sh --measure` over all 19 goldens (minimal, demo 0 and 150, 16 features):
 *   Mesa 25.0.7 (Debian 13):       max 1 level, PSNR >= 88.6 dB, <= 0.027% of pixels differ
 *   Mesa 26.2.6 (Debian unstable): max 18 levels (demo frame 0), PSNR >= 57.6 dB (fxaa),
 *                                  <= 0.63% of pixels differ (demo frame 0)
 * Limits: twice the worst of each (max levels, share of pixels), and the PSNR 6 dB below its
 * worst (twice the RMS error). A GPU rasterises further off: bless its own folder (--key). */
#define GOLDEN_FOREIGN_MAX_DIFF 36            /* 8-bit levels, any channel */
#define GOLDEN_FOREIGN_PSNR_MIN 51.5          /* dB, over all channels */
#define GOLDEN_FOREIGN_DIFFER_PERCENT_MAX 1.25 /* % of pixels with any channel differing */

typedef struct {
    int max_diff;
    double psnr;
    long differing;   /* channel values */
    long pixels_diff; /* pixels with any channel differing */
} image_diff;

static int diff_images(const ww_image *a, const ww_image *b, image_diff *d) {
    if (a->width != b->width || a->height != b->height || a->channels != b->channels) return -1;
    size_t px = (size_t)a->width * (size_t)a->height, ch = (size_t)a->channels, n = px * ch;
    double se = 0;
    *d = (image_diff){0};
    for (size_t p = 0; p < px; p++) {
        int any = 0;
        for (size_t i = p * ch; i < (p + 1) * ch; i++) {
            int e = abs((int)a->u8[i] - (int)b->u8[i]);
            if (e > d->max_diff) d->max_diff = e;
            d->differing += e != 0;
            any |= e != 0;
            se += (double)e * e;
        }
        d->pixels_diff += any;
    }
    double mse = se / (double)n;
    d->psnr = mse > 0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
    return 0;
}

/* "GL_RENDERER | GL_VERSION" of the auto backend here, or "" without GL; key: its renderer key
 * (may be NULL) */
static void current_renderer(char *out, size_t cap, char *key, size_t key_cap) {
    out[0] = 0;
    if (key) key[0] = 0;
    ww_backend *b = NULL;
    ww_error err = {0};
    if (ww_backend_open(WW_BACKEND_AUTO, &b, &err) != WW_OK) return;
    snprintf(out, cap, "%s | %s", ww_backend_renderer(b), ww_backend_version(b));
    if (key) ww_golden_renderer_key(ww_backend_renderer(b), ww_backend_version(b), key, key_cap);
    ww_backend_close(b);
}

/* golden/x/NAME.png -> golden/x/KEY/NAME.png for this machine's renderer key, when that file
 * exists (the per-renderer goldens of `scripts/make-golden.sh --key`); else 0 */
static int own_golden(const char *golden, char *out, size_t cap) {
    static char key[WW_GOLDEN_KEY_SIZE];
    static int looked;
    if (!looked) {
        char r[512];
        current_renderer(r, sizeof r, key, sizeof key);
        looked = 1;
    }
    const char *slash = strrchr(golden, '/');
    if (!key[0] || !slash) return 0;
    snprintf(out, cap, "%.*s/%s%s", (int)(slash - golden), golden, key, slash);
    FILE *f = fopen(out, "rb");
    if (!f) return 0;
    fclose(f);
    return 1;
}

/* this machine renders with the renderer that blessed golden/ (same GL_RENDERER and version) */
int ww_test_renderer_is_blessed(void) {
    char here[512];
    current_renderer(here, sizeof here, NULL, 0);
    char *blessed = ww_test_read_file("golden/RENDERER", NULL);
    int same = blessed && here[0] && strncmp(blessed, here, strlen(here)) == 0;
    free(blessed);
    return same;
}

void ww_test_check_golden(const char *golden, const char *actual) {
    ww_image g = {0}, a = {0};
    ww_error err = {0};
    char own[1024];
    int exact = ww_test_renderer_is_blessed();
    if (!exact && own_golden(golden, own, sizeof own)) {
        golden = own; /* this renderer's own golden: exact */
        exact = 1;
    }
    ENSURE_MSG(ww_read_png(golden, &g, &err) == WW_OK, "%s: %s", golden, err.msg);
    ENSURE_MSG(ww_read_png(actual, &a, &err) == WW_OK, "%s: %s", actual, err.msg);
    if (!g.u8 || !a.u8) goto done;

    image_diff d = {0};
    ENSURE(diff_images(&g, &a, &d) == 0);
    if (exact) {
        ENSURE_MSG(d.differing == 0, "%s: %ld channel values differ (max %d, PSNR %.1f dB); "
                   "if the change is intended, look at %s and run make golden",
                   golden, d.differing, d.max_diff, d.psnr, actual);
    } else {
        double share = 100.0 * (double)d.pixels_diff / ((double)g.width * (double)g.height);
        fprintf(stderr, "(renderer differs from golden/RENDERER: comparing with tolerance) ");
        ENSURE_MSG(d.max_diff <= GOLDEN_FOREIGN_MAX_DIFF && d.psnr >= GOLDEN_FOREIGN_PSNR_MIN &&
                       share <= GOLDEN_FOREIGN_DIFFER_PERCENT_MAX,
                   "%s: max diff %d (allowed %d), PSNR %.1f dB (min %.1f), %.3f%% of pixels "
                   "differ (allowed %.2f%%); a new Mesa release may need its own goldens: "
                   "scripts/make-golden.sh --measure, then --key",
                   golden, d.max_diff, GOLDEN_FOREIGN_MAX_DIFF, d.psnr, GOLDEN_FOREIGN_PSNR_MIN,
                   share, GOLDEN_FOREIGN_DIFFER_PERCENT_MAX);
    }
done:
    ww_image_free(&g);
    ww_image_free(&a);
}

int ww_test_render(const char *scene, const char *args, const char *dir) {
    char c[4096];
    snprintf(c, sizeof c, "%s render %s --frames 1 -o %s --quiet %s", ww_test_bin(), scene, dir,
             args ? args : "");
    return ww_test_run(c, NULL, NULL);
}

const unsigned char *ww_test_pixel(const ww_image *im, int x, int y) {
    return im->u8 + ((size_t)y * (size_t)im->width + (size_t)x) * (size_t)im->channels;
}

int ww_test_pic_load(const char *path, ww_test_pic *p) {
    ww_error err = {0};
    *p = (ww_test_pic){0};
    ENSURE_MSG(ww_read_png(path, &p->im, &err) == WW_OK, "%s: %s", path, err.msg);
    p->w = p->im.width;
    p->h = p->im.height;
    return p->im.u8 != NULL;
}

double ww_test_pic_luma(const ww_test_pic *p, int x, int y) {
    x = x < 0 ? 0 : x >= p->w ? p->w - 1 : x;
    y = y < 0 ? 0 : y >= p->h ? p->h - 1 : y;
    const uint8_t *c = ww_test_pixel(&p->im, x, y);
    return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
}

int ww_test_render_pic(const char *scene, int frame, const char *size, const char *args,
                       const char *name, ww_test_pic *p) {
    char dir[768], c[2048], path[1024];
    *p = (ww_test_pic){0};
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(name));
    snprintf(c, sizeof c, "render %s --frames %d:%d --size %s -o %s --quiet %s", scene, frame,
             frame + 1, size, dir, args ? args : "");
    int rc = ww_test_ww(c, NULL, NULL);
    ENSURE_MSG(rc == 0, "%s: exit %d", c, rc);
    if (rc != 0) return 0;
    snprintf(path, sizeof path, "%s/frame_%05d.png", dir, frame);
    return ww_test_pic_load(path, p);
}

int ww_test_render_with_without(const char *tag, const char *text, int frame, const char *size,
                                const char *without, ww_test_pic *with, ww_test_pic *none) {
    char path[600], on[160], off[160];
    *with = *none = (ww_test_pic){0};
    snprintf(path, sizeof path, "%s/scene.yaml", ww_test_tmpdir(tag));
    snprintf(on, sizeof on, "%s_with", tag);
    snprintf(off, sizeof off, "%s_without", tag);
    ENSURE(ww_test_write_text(path, text) == 0);
    if (ww_test_render_pic(path, frame, size, NULL, on, with) &&
        ww_test_render_pic(path, frame, size, without, off, none))
        return 1;
    ww_image_free(&with->im);
    ww_image_free(&none->im);
    *with = *none = (ww_test_pic){0};
    return 0;
}

int ww_test_moved_near(const ww_test_pic *a, const ww_test_pic *b, double x, double y, int radius,
                       int levels) {
    for (int dy = -radius; dy <= radius; dy++)
        for (int dx = -radius; dx <= radius; dx++) {
            int px = (int)floor(x) + dx, py = (int)floor(y) + dy;
            if (px < 0 || py < 0 || px >= a->w || py >= a->h) continue;
            const unsigned char *p = ww_test_pixel(&a->im, px, py);
            const unsigned char *q = ww_test_pixel(&b->im, px, py);
            for (int c = 0; c < 3; c++)
                if (abs(p[c] - q[c]) > levels) return 1;
        }
    return 0;
}

double ww_test_pic_psnr(const ww_test_pic *a, const ww_test_pic *b, int *max_diff) {
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

int ww_test_region_diff(const char *a_path, const char *b_path, const double rect[4], int thresh,
                        ww_test_region *d) {
    ww_image a = {0}, b = {0};
    ww_error err = {0};
    *d = (ww_test_region){0};
    int rc = -1;
    if (ww_read_png(a_path, &a, &err) != WW_OK || ww_read_png(b_path, &b, &err) != WW_OK) goto done;
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) goto done;
    int x0 = (int)floor(rect[0] * a.width), x1 = (int)ceil(rect[2] * a.width);
    int y0 = (int)floor(rect[1] * a.height), y1 = (int)ceil(rect[3] * a.height);
    for (int y = 0; y < a.height; y++) {
        for (int x = 0; x < a.width; x++) {
            int e = 0;
            for (int c = 0; c < a.channels; c++) {
                size_t i = ((size_t)y * (size_t)a.width + (size_t)x) * (size_t)a.channels + (size_t)c;
                int dc = abs((int)a.u8[i] - (int)b.u8[i]);
                if (dc > e) e = dc;
            }
            int in = x >= x0 && x < x1 && y >= y0 && y < y1;
            if (in) {
                d->inside_px++;
                d->inside += e > thresh;
                if (e > d->max_inside) d->max_inside = e;
            } else {
                d->outside_px++;
                d->outside += e > thresh;
                if (e > d->max_outside) d->max_outside = e;
            }
        }
    }
    rc = 0;
done:
    ww_image_free(&a);
    ww_image_free(&b);
    return rc;
}

void ww_test_project(const ww_scene *sc, const ww_state *st, const double p[3], double px[2]) {
    const double *e = st->cam_pos, *f = st->cam_fwd, up[3] = {0.0, 1.0, 0.0};
    double r[3], u[3], d[3];
    ww_m_cross3(f, up, r);
    ww_m_normalize3(r);
    ww_m_cross3(r, f, u);
    ww_m_sub3(p, e, d);
    double z = ww_m_dot3(d, f), t = tan(0.5 * st->cam_fov[0]);
    px[0] = 0.5 * (1.0 + ww_m_dot3(d, r) / (z * t * sc->width / sc->height)) * sc->width;
    px[1] = 0.5 * (1.0 - ww_m_dot3(d, u) / (z * t)) * sc->height;
}

struct ww_scene *ww_test_scene_text(const char *name, const char *text) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load_string(name, text, strlen(text), NULL, 0, &sc, &err);
    ENSURE_MSG(r == WW_OK, "%s:%d:%d: %s", name, err.line, err.column, err.msg);
    return r == WW_OK ? sc : NULL;
}

int ww_test_run_to(const struct ww_scene *sc, struct ww_state *st, int64_t step) {
    ww_error err = {0};
    ww_result r = ww_sim_advance_to(sc, st, step, &err);
    ENSURE_MSG(r == WW_OK, "step %lld: %s", (long long)st->step, err.msg);
    return r == WW_OK;
}
