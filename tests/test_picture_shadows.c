/* test_picture_shadows.c - seed 003's stencilled shadows (render.shadows projected, volumes,
 * volumes_visible; gfx/stencil_shadows.c) measured on rendered frames: where each darkens the
 * seabed and by how much against shadows off, that overlapping projected shadows darken once,
 * that the fog over a distant shadow is left alone, that shadow volumes agree with a 4096 shadow
 * map (from outside a volume and from inside one) and that showing the volumes changes the
 * picture only by their tint. Masks come from the frames: a pixel is in a technique's shadow
 * where that technique's frame is darker than the frame with shadows off.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/writers.h"
#include "scene/scene.h"
#include "sim/sky.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

#define PROJECTED "scenes/features/shadows_projected.yaml"
#define VOLUMES "scenes/features/shadow_volumes.yaml"

#define SHADOW_DROP 8.0       /* 8-bit luma a pixel must lose against shadows off to be shadow */
#define SEABED_TOP 0.3        /* rows below this fraction of the height: the seabed (both scenes
                               * look down from under water; the surface and casters lie above) */
#define MIN_SHADOW_PX 150     /* a shadow mask must hold at least this many pixels at 256x144 */
#define RATIO_MAX 0.85        /* shadowed seabed keeps at most this share of its lit luma ... */
#define RATIO_MIN 0.25        /* ... and at least this (the ambient light and the fog stay) */
#define RATIO_AGREE 0.06      /* the stencilled ratio against the map's, in the map's shadow cores */
#define CORE_ERODE 2          /* px: the map's mask eroded by this gives its shadows' cores */
#define PROJECTED_MAP_IOU 0.6 /* projected shadows against the 1024 map of the same scene */
#define VOLUME_MAP_IOU 0.7    /* volumes against a 4096 map (the volumes are hard, the map's
                               * PCF edge is soft: the masks differ along the outlines) */
#define DOUBLE_TOL 2.0        /* levels: where two projected shadows overlap, against one */
#define MIN_OVERLAP_PX 40     /* the overlap the scene is built to have, at 256x144 */
#define FOG_TOL 3.0           /* levels: a shadow deep in fog may change the frame at most this */
#define FOG_NAIVE_MIN 12.0    /* a final-colour darkening by the near ratio would move it this */
#define TINT_TOP 0.08         /* rows above this fraction: water surface, no volume reaches */
#define SLIVER_STEP 3         /* px: a sliver pixel has shadow this far below it and a much ... */
#define SLIVER_DARKER 30.0    /* ... darker pixel (the rock, the shadow) this far above it */
#define SLIVER_LIT 12.0       /* luma: within this of the shadows-off frame counts as lit */
#define SLIVER_FAIL_MIN 100   /* depth-fail draws the sliver on at least this many pixels ... */
#define SLIVER_MAX 20         /* ... and the counting used now on at most this many */
#define COUNT_TOL 8           /* levels: depth-pass against depth-fail, a channel moving more ... */
#define COUNT_MAX_SHARE 0.003 /* ... on at most this share of the pixels (depth-fail's specks on
                               * the seams where a volume's side meets its caster's surface) */

typedef ww_test_pic pic;

/* frame 0 of scene with args into tmp dir `name`, loaded into p */
static int render(const char *scene, const char *args, const char *name, pic *p) {
    char dir[768], path[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(name));
    int rc = ww_test_render(scene, args, dir);
    ENSURE_MSG(rc == 0, "%s %s: exit %d", scene, args ? args : "", rc);
    if (rc != 0) return 0;
    snprintf(path, sizeof path, "%s/frame_00000.png", dir);
    return ww_test_pic_load(path, p);
}

/* m[i] = 1 where `lit` is darker than `shadowed` by SHADOW_DROP, below SEABED_TOP */
static long shadow_mask(const pic *lit, const pic *shadowed, unsigned char *m) {
    long n = 0;
    for (int y = 0; y < lit->h; y++)
        for (int x = 0; x < lit->w; x++) {
            int in = y >= SEABED_TOP * lit->h &&
                     ww_test_pic_luma(lit, x, y) - ww_test_pic_luma(shadowed, x, y) > SHADOW_DROP;
            m[y * lit->w + x] = (unsigned char)in;
            n += in;
        }
    return n;
}

static double iou(const unsigned char *a, const unsigned char *b, long n) {
    long both = 0, any = 0;
    for (long i = 0; i < n; i++) {
        both += a[i] && b[i];
        any += a[i] || b[i];
    }
    return any ? (double)both / (double)any : 0.0;
}

/* m eroded by r pixels (a pixel stays where its square of side 2 r + 1 is all in m): the
 * shadows' cores, away from the map's soft PCF edge, where both techniques are fully dark */
static unsigned char *eroded(const unsigned char *m, int w, int h, int r) {
    unsigned char *e = calloc((size_t)w * (size_t)h, 1);
    for (int y = r; e && y < h - r; y++)
        for (int x = r; x < w - r; x++) {
            int all = 1;
            for (int j = -r; j <= r && all; j++)
                for (int i = -r; i <= r && all; i++) all = m[(y + j) * w + x + i];
            e[y * w + x] = (unsigned char)all;
        }
    return e;
}

/* mean luma of `p` over `m` (and `m2` when given) divided by that of `off` */
static double ratio_on(const pic *p, const pic *off, const unsigned char *m,
                       const unsigned char *m2) {
    double a = 0.0, b = 0.0;
    for (int y = 0; y < p->h; y++)
        for (int x = 0; x < p->w; x++) {
            int i = y * p->w + x;
            if (!m[i] || (m2 && !m2[i])) continue;
            a += ww_test_pic_luma(p, x, y);
            b += ww_test_pic_luma(off, x, y);
        }
    return b > 0.0 ? a / b : 1.0;
}

static void free_pics(pic *p, int n) {
    for (int i = 0; i < n; i++) ww_image_free(&p[i].im);
}

/* the boxes' and the boat's projected shadows darken the seabed where the map's shadows fall,
 * by the share of light the sun gave it */
TEST_IMAGE(shadows_projected_darken_where_the_map_does) {
    REQUIRE_GL();
    pic f[3];
    memset(f, 0, sizeof f);
    if (!render(PROJECTED, "--set render.shadows=off", "sp_off", &f[0]) ||
        !render(PROJECTED, "--set render.shadows=map", "sp_map", &f[1]) ||
        !render(PROJECTED, NULL, "sp_projected", &f[2])) {
        free_pics(f, 3);
        return;
    }
    long n = (long)f[0].w * f[0].h;
    unsigned char *mm = calloc((size_t)n, 1), *mp = calloc((size_t)n, 1);
    long nm = shadow_mask(&f[0], &f[1], mm), np = shadow_mask(&f[0], &f[2], mp);
    ENSURE_MSG(nm >= MIN_SHADOW_PX && np >= MIN_SHADOW_PX, "shadow pixels: map %ld projected %ld",
               nm, np);
    double j = iou(mm, mp, n);
    ENSURE_MSG(j >= PROJECTED_MAP_IOU, "projected against the map: IoU %.3f < %.2f", j,
               PROJECTED_MAP_IOU);
    unsigned char *core = eroded(mm, f[0].w, f[0].h, CORE_ERODE);
    double rp = ratio_on(&f[2], &f[0], mp, NULL), rmp = ratio_on(&f[2], &f[0], mp, core),
           rm = ratio_on(&f[1], &f[0], mp, core);
    free(core);
    ENSURE_MSG(rp <= RATIO_MAX && rp >= RATIO_MIN, "projected shadow keeps %.3f of the seabed's "
               "luma, not in [%.2f, %.2f]", rp, RATIO_MIN, RATIO_MAX);
    ENSURE_MSG(fabs(rmp - rm) <= RATIO_AGREE, "on the shared mask projected keeps %.3f, the map "
               "%.3f (tolerance %.2f)", rmp, rm, RATIO_AGREE);
    free(mm);
    free(mp);
    free_pics(f, 3);
}

/* the two boxes' shadows overlap on the seabed: there the frame with both is no darker than the
 * frame with one box alone (the stencil marks a pixel once) */
TEST_IMAGE(shadows_projected_overlap_darkens_once) {
    REQUIRE_GL();
    static const char high[] = "{name: high, mesh: box, position: [-1.0, -1.0, -6.2], scale: 1.2}";
    static const char low[] = "{name: low, mesh: box, position: [0.2, -2.0, -5.4], scale: 1.0}";
    char a_only[256], b_only[256], none[64];
    snprintf(a_only, sizeof a_only, "--set 'objects.models=[%s]'", high);
    snprintf(b_only, sizeof b_only, "--set 'objects.models=[%s]'", low);
    snprintf(none, sizeof none, "--set render.shadows=off");
    pic f[4];
    memset(f, 0, sizeof f);
    if (!render(PROJECTED, none, "so_off", &f[0]) || !render(PROJECTED, NULL, "so_both", &f[1]) ||
        !render(PROJECTED, a_only, "so_a", &f[2]) || !render(PROJECTED, b_only, "so_b", &f[3])) {
        free_pics(f, 4);
        return;
    }
    long n = (long)f[0].w * f[0].h, overlap = 0;
    unsigned char *ma = calloc((size_t)n, 1), *mb = calloc((size_t)n, 1);
    shadow_mask(&f[0], &f[2], ma);
    shadow_mask(&f[0], &f[3], mb);
    double worst = 0.0, naive = 0.0;
    for (int y = 0; y < f[0].h; y++)
        for (int x = 0; x < f[0].w; x++) {
            int i = y * f[0].w + x;
            if (!ma[i] || !mb[i]) continue;
            overlap++;
            double d = fabs(ww_test_pic_luma(&f[1], x, y) - ww_test_pic_luma(&f[2], x, y));
            if (d > worst) worst = d;
            /* twice darkened: the single shadow's ratio applied again */
            double one = ww_test_pic_luma(&f[2], x, y), off = ww_test_pic_luma(&f[0], x, y);
            naive += one - one * one / off;
        }
    ENSURE_MSG(overlap >= MIN_OVERLAP_PX, "the boxes' shadows overlap on %ld pixels only", overlap);
    ENSURE_MSG(worst <= DOUBLE_TOL, "overlap darker than one shadow by up to %.2f levels (> %.1f)",
               worst, DOUBLE_TOL);
    if (overlap > 0) naive /= (double)overlap;
    ENSURE_MSG(naive > 2.0 * DOUBLE_TOL, "a second darkening would be only %.2f levels", naive);
    free(ma);
    free(mb);
    free_pics(f, 4);
}

/* the shadows 5 m off and more under fog thick enough to leave 0.2% of the seabed's light at
 * that distance (exp2 fog, 0.5 per m): the frame changes there by at most FOG_TOL, where
 * darkening the final colour by the clear shadow's ratio would move it FOG_NAIVE_MIN or more
 * (the mask comes from the same view without fog) */
TEST_IMAGE(shadows_projected_leave_the_fog_alone) {
    REQUIRE_GL();
    static const char far_cam[] = "--set fog.below.density=0.5";
    char clear_off[384], clear_on[384], fog_off[384];
    snprintf(clear_off, sizeof clear_off, "--set fog.below.density=0 --set render.shadows=off");
    snprintf(clear_on, sizeof clear_on, "--set fog.below.density=0");
    snprintf(fog_off, sizeof fog_off, "%s --set render.shadows=off", far_cam);
    pic f[4];
    memset(f, 0, sizeof f);
    if (!render(PROJECTED, clear_off, "sf_clear_off", &f[0]) ||
        !render(PROJECTED, clear_on, "sf_clear_on", &f[1]) ||
        !render(PROJECTED, fog_off, "sf_fog_off", &f[2]) ||
        !render(PROJECTED, far_cam, "sf_fog_on", &f[3])) {
        free_pics(f, 4);
        return;
    }
    long n = (long)f[0].w * f[0].h, count = 0;
    unsigned char *m = calloc((size_t)n, 1);
    shadow_mask(&f[0], &f[1], m);
    double worst = 0.0, naive = 0.0, ratio = ratio_on(&f[1], &f[0], m, NULL);
    for (int y = 0; y < f[0].h; y++)
        for (int x = 0; x < f[0].w; x++) {
            if (!m[y * f[0].w + x]) continue;
            count++;
            double d = fabs(ww_test_pic_luma(&f[3], x, y) - ww_test_pic_luma(&f[2], x, y));
            if (d > worst) worst = d;
            naive += (1.0 - ratio) * ww_test_pic_luma(&f[2], x, y);
        }
    ENSURE_MSG(count >= MIN_SHADOW_PX, "the shadows cover %ld pixels", count);
    if (count > 0) naive /= (double)count;
    ENSURE_MSG(worst <= FOG_TOL, "the fogged far shadow changed the frame by %.2f levels (> %.1f)",
               worst, FOG_TOL);
    ENSURE_MSG(naive >= FOG_NAIVE_MIN, "a final-colour darkening would move it %.2f levels only",
               naive);
    free(m);
    free_pics(f, 4);
}

/* volumes (the hull's on the wreck and the seabed, the boxes' own) against a 4096 map */
static void volumes_against_map(const char *extra, const char *name, double *j_out) {
    char a[512], b[512], c[512];
    snprintf(a, sizeof a, "%s --set render.shadows=off", extra);
    snprintf(b, sizeof b, "%s --set 'render.shadows={technique: map, size: 4096}'", extra);
    snprintf(c, sizeof c, "%s --set render.shadows=volumes", extra);
    char na[64], nb[64], nc[64];
    snprintf(na, sizeof na, "%s_off", name);
    snprintf(nb, sizeof nb, "%s_map", name);
    snprintf(nc, sizeof nc, "%s_vol", name);
    pic f[3];
    memset(f, 0, sizeof f);
    *j_out = -1.0;
    if (!render(VOLUMES, a, na, &f[0]) || !render(VOLUMES, b, nb, &f[1]) ||
        !render(VOLUMES, c, nc, &f[2])) {
        free_pics(f, 3);
        return;
    }
    long n = (long)f[0].w * f[0].h;
    unsigned char *mm = calloc((size_t)n, 1), *mv = calloc((size_t)n, 1);
    long nm = shadow_mask(&f[0], &f[1], mm), nv = shadow_mask(&f[0], &f[2], mv);
    ENSURE_MSG(nm >= MIN_SHADOW_PX && nv >= MIN_SHADOW_PX, "%s: shadow pixels: map %ld volumes %ld",
               name, nm, nv);
    *j_out = iou(mm, mv, n);
    unsigned char *core = eroded(mm, f[0].w, f[0].h, CORE_ERODE);
    double rv = ratio_on(&f[2], &f[0], mv, core), rm = ratio_on(&f[1], &f[0], mv, core);
    free(core);
    ENSURE_MSG(fabs(rv - rm) <= RATIO_AGREE, "%s: on the shared mask volumes keep %.3f, the map "
               "%.3f (tolerance %.2f): only the sun's direct light goes", name, rv, rm, RATIO_AGREE);
    free(mm);
    free(mv);
    free_pics(f, 3);
}

TEST_IMAGE(shadow_volumes_agree_with_a_4096_map) {
    REQUIRE_GL();
    double j;
    volumes_against_map("", "sv_view", &j);
    ENSURE_MSG(j >= VOLUME_MAP_IOU, "volumes against a 4096 map: IoU %.3f < %.2f", j,
               VOLUME_MAP_IOU);
}

/* an open mesh (the grid: a sheet facing up, toward the sun) casts too: each of its faces
 * makes a volume, a lit one turned over */
TEST_IMAGE(shadow_volumes_from_an_open_sheet) {
    REQUIRE_GL();
    double j;
    volumes_against_map("--set 'objects.models=[{name: sheet, mesh: grid, position: [-0.5, -2, -4.5],"
                        " scale: 1.5}]'", "sv_sheet", &j);
    ENSURE_MSG(j >= VOLUME_MAP_IOU, "an open sheet's volumes against a 4096 map: IoU %.3f < %.2f",
               j, VOLUME_MAP_IOU);
}

/* --set arguments for a camera inside the hull's volume of the volumes' scene (1.5 m from the
 * hull's middle away from the sun) and 2.5 m aside, outside it, both looking at the seabed */
static int hull_volume_cameras(char *inside, char *outside, size_t size) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load(VOLUMES, NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc) return 0;
    ww_state *st = ww_state_new(sc);
    ENSURE(st != NULL);
    if (!st) {
        ww_scene_free(sc);
        return 0;
    }
    double in[3], side[3] = {-sin(st->boat_heading[0]), 0.0, cos(st->boat_heading[0])};
    for (int i = 0; i < 3; i++) in[i] = st->boat_pos[i] - 1.5 * st->sun_dir[i];
    const char *fmt = "--set 'camera.path=[{t: 0, position: [%.3f, %.3f, %.3f], "
                      "look_at: [%.3f, -4, %.3f]}]'";
    snprintf(inside, size, fmt, in[0], in[1], in[2], in[0] + 1.0, in[2] + 4.5);
    snprintf(outside, size, fmt, in[0] + 2.5 * side[0], in[1], in[2] + 2.5 * side[2],
             in[0] + 1.0, in[2] + 4.5);
    ww_state_free(st);
    ww_scene_free(sc);
    return 1;
}

/* the camera inside the hull's volume, then outside it: the shadows are the same both times
 * (an inverted count would light the shadow and shade the rest: IoU near 0) */
TEST_IMAGE(shadow_volumes_camera_inside_a_volume) {
    REQUIRE_GL();
    char inside[256], outside[256];
    if (!hull_volume_cameras(inside, outside, sizeof inside)) return;
    double ji, jo;
    volumes_against_map(inside, "sv_inside", &ji);
    volumes_against_map(outside, "sv_outside", &jo);
    ENSURE_MSG(ji >= VOLUME_MAP_IOU && jo >= VOLUME_MAP_IOU,
               "volumes against a 4096 map: IoU %.3f inside the volume, %.3f outside (>= %.2f)", ji,
               jo, VOLUME_MAP_IOU);
}

/* pixels where a channel of a and b differs by more than tol */
static long pixels_apart(const pic *a, const pic *b, int tol) {
    long n = 0;
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++) {
            const uint8_t *p = ww_test_pixel(&a->im, x, y), *q = ww_test_pixel(&b->im, x, y);
            for (int c = 0; c < 3; c++)
                if (abs(p[c] - q[c]) > tol) {
                    n++;
                    break;
                }
        }
    return n;
}

/* a volume the eye lies outside is counted depth-pass, its sides alone; one that may hold the
 * eye (or the near plane), or whose caster is blended or cut at the surface by the prepass, is
 * counted depth-fail with both caps (stencil_shadows.c). Against every volume counted
 * depth-fail, the frame keeps its shadows: from the feature's view; from inside the hull's
 * volume (counted depth-pass it would invert: most of the frame changes); and from above the
 * water, where the prepass cuts the floating hull at the surface and the volume would leak
 * through the cut-away part */
TEST_IMAGE(shadow_volumes_depth_pass_counts_as_depth_fail) {
    REQUIRE_GL();
    char inside[256], outside[256];
    if (!hull_volume_cameras(inside, outside, sizeof inside)) return;
    const char *views[][2] = {
        {"view", ""},
        {"inside", inside},
        {"above", "--set 'camera.path=[{t: 0, position: [2.5, 3, 0], look_at: [0, -3.5, -6]}]'"},
    };
    for (size_t v = 0; v < sizeof views / sizeof views[0]; v++) {
        char args[512], name[3][64];
        const char *what[3] = {"off", "fail", "pass"};
        pic f[3];
        memset(f, 0, sizeof f);
        int ok = 1;
        for (int k = 0; k < 3 && ok; k++) {
            snprintf(args, sizeof args, "%s --set render.shadows=%s", views[v][1],
                     k == 0 ? "off" : "volumes");
            snprintf(name[k], sizeof name[k], "dp_%s_%s", views[v][0], what[k]);
            if (k == 1) setenv("WW_SHADOW_DEPTH_FAIL", "1", 1);
            ok = render(VOLUMES, args, name[k], &f[k]);
            unsetenv("WW_SHADOW_DEPTH_FAIL");
        }
        if (ok) {
            long n = (long)f[0].w * f[0].h, shadow = pixels_apart(&f[0], &f[1], COUNT_TOL),
                 apart = pixels_apart(&f[1], &f[2], COUNT_TOL);
            ENSURE_MSG(shadow >= MIN_SHADOW_PX, "%s: the volumes shade %ld pixels only",
                       views[v][0], shadow);
            ENSURE_MSG(apart <= COUNT_MAX_SHARE * n,
                       "%s: depth-pass against depth-fail: %ld of %ld pixels apart by more than "
                       "%d levels (at most %.1f%%)",
                       views[v][0], apart, n, COUNT_TOL, 100.0 * COUNT_MAX_SHARE);
        }
        free_pics(f, 3);
    }
}

/* lit pixels of vol forming a thin line inside darkness: lit (within SLIVER_LIT of the frame with
 * shadows off), with shadow SLIVER_STEP rows below and something SLIVER_DARKER darker the same
 * distance above */
static long sliver_pixels(const pic *off, const pic *vol) {
    long n = 0;
    for (int y = SLIVER_STEP; y + SLIVER_STEP < vol->h; y++)
        for (int x = 0; x < vol->w; x++) {
            double v = ww_test_pic_luma(vol, x, y);
            int lit = v >= ww_test_pic_luma(off, x, y) - SLIVER_LIT;
            int below = ww_test_pic_luma(vol, x, y + SLIVER_STEP) <=
                        ww_test_pic_luma(off, x, y + SLIVER_STEP) - 2.0 * SHADOW_DROP;
            int above = ww_test_pic_luma(vol, x, y - SLIVER_STEP) <= v - SLIVER_DARKER;
            n += lit && below && above;
        }
    return n;
}

/* the reef's boulder seen from its shadow side, sunk into the sand (frame 382's pose): counted
 * depth-fail, its volume let the sunlight through in a bright sliver between the rock and its
 * shadow on the sand (a closed caster: it is now counted depth-pass, the sliver gone; the map
 * draws none either) */
TEST_IMAGE(shadow_volumes_no_lit_sliver_under_a_rock) {
    REQUIRE_GL();
    static const char *const scene = "scenes/reef.yaml";
    static const char *const pose = "--size 640x360 --set time.start=1528/120";
    char args[256];
    pic f[3];
    memset(f, 0, sizeof f);
    snprintf(args, sizeof args, "%s --set render.shadows=off", pose);
    int ok = render(scene, args, "sliver_off", &f[0]);
    setenv("WW_SHADOW_DEPTH_FAIL", "1", 1);
    ok = ok && render(scene, pose, "sliver_fail", &f[1]);
    unsetenv("WW_SHADOW_DEPTH_FAIL");
    ok = ok && render(scene, pose, "sliver_now", &f[2]);
    if (ok) {
        long fail = sliver_pixels(&f[0], &f[1]), now = sliver_pixels(&f[0], &f[2]);
        ENSURE_MSG(fail >= SLIVER_FAIL_MIN, "depth-fail's sliver: %ld pixels (the pose shows it "
                   "on at least %d)", fail, SLIVER_FAIL_MIN);
        ENSURE_MSG(now <= SLIVER_MAX, "a lit sliver under the rock: %ld pixels (at most %d; "
                   "depth-fail %ld)", now, SLIVER_MAX, fail);
    }
    free_pics(f, 3);
}

/* volumes_visible adds the volumes' violet tint and nothing else: every pixel it changes gains
 * more blue than green, none above the hull (the surface, where no volume reaches), and the tint
 * covers the hull's volume between the boat and the seabed */
TEST_IMAGE(shadow_volumes_visible_only_tint_the_volumes) {
    REQUIRE_GL();
    pic f[2];
    memset(f, 0, sizeof f);
    if (!render(VOLUMES, "--set render.shadows=volumes", "vv_plain", &f[0]) ||
        !render(VOLUMES, "--set render.shadows=volumes_visible", "vv_shown", &f[1])) {
        free_pics(f, 2);
        return;
    }
    long changed = 0, wrong_hue = 0, above = 0;
    for (int y = 0; y < f[0].h; y++)
        for (int x = 0; x < f[0].w; x++) {
            const uint8_t *a = ww_test_pixel(&f[0].im, x, y), *b = ww_test_pixel(&f[1].im, x, y);
            int dg = b[1] - a[1], db = b[2] - a[2];
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) continue;
            changed++;
            if (db - dg < 0) wrong_hue++; /* the tint is bluer than anything it covers */
            if (y < TINT_TOP * f[0].h) above++;
        }
    ENSURE_MSG(changed >= MIN_SHADOW_PX, "the volumes tint %ld pixels only", changed);
    ENSURE_MSG(wrong_hue == 0, "%ld of %ld changed pixels are not the volumes' tint", wrong_hue,
               changed);
    ENSURE_MSG(above == 0, "%ld pixels changed above the hull", above);
    free_pics(f, 2);
}

/* the feature goldens (frame 0, 256x144) */
static void golden_of(const char *name) {
    REQUIRE_GL();
    char scene[256], gold[256], dir[512], actual[600];
    snprintf(scene, sizeof scene, "scenes/features/%s.yaml", name);
    snprintf(gold, sizeof gold, "golden/features/%s.png", name);
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir(name));
    ENSURE(ww_test_render(scene, NULL, dir) == 0);
    snprintf(actual, sizeof actual, "%s/frame_00000.png", dir);
    ww_test_check_golden(gold, actual);
}

TEST_IMAGE(shadows_golden_projected) { golden_of("shadows_projected"); }
TEST_IMAGE(shadows_golden_volumes) { golden_of("shadow_volumes"); }
TEST_IMAGE(shadows_golden_volumes_visible) { golden_of("shadow_volumes_visible"); }

/* ---- the sunlight bends at the water ------------------------------------------------------ */

/* a 1 m box held 1.5 m above still water over an 8 m deep seabed at 13 h: the light reaching
 * the seabed crosses the surface and bends (Snell, n 1.333), so the box's shadow lies at
 * c - a 1.5 / a.y - u 8 / u.y (a toward the sun, u the refracted ray); a box 3 m under the
 * water casts along u alone. The camera, under the box, looks straight down at that point; the
 * shadow's centroid must lie within BEND_TOL of the frame's centre for the map, the projected
 * shadows and the volumes alike. Along the sun's ray in air (before) the first fell 1.6 m
 * further out (1.59 m for the map, 1.64 m projected and volumes). */
#define BEND_TOL 0.25          /* m: the shadow's centroid from where the bent light puts it */
#define BEND_SIZE 160          /* px, square */
#define BEND_DROP 0.6          /* a pixel darker than this share of the frame's median: shadow */
#define BEND_MIN_PX 200        /* the 1 m shadow covers about 28 px a side */
static void bent_shadow(const char *technique, double lift) {
    static const double level = 0.0, depth = 8.0, eta = 1.0 / 1.333, fov = 60.0;
    char text[2048];
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 1}\n"
             "sky: {time_of_day: 13, day_length: 0}\n");
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load_string("bend.yaml", text, strlen(text), NULL, 0, &sc, &err) == WW_OK,
               "%s", err.msg);
    if (!sc) return;
    double a[3];
    ww_sky_sun_dir(13.0, sc->sun_max_elevation, a);
    ww_scene_free(sc);
    double n = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int i = 0; i < 3; i++) a[i] /= n;
    double u[3] = {eta * a[0], sqrt(1.0 - eta * eta * (1.0 - a[1] * a[1])), eta * a[2]};
    /* from the box's centre down the sun's ray to the surface (when above it), then down the
     * refracted ray to the seabed */
    double air = lift > 0.0 ? lift : 0.0, water = depth + (lift < 0.0 ? lift : 0.0);
    double x = -a[0] * air / a[1] - u[0] * water / u[1];
    double z = -a[2] * air / a[1] - u[2] * water / u[1];
    const double cam_y = lift > 0.0 ? -3.0 : lift - 1.0, over = cam_y - (level - depth);
    const char *dir = ww_test_tmpdir("shadow_bend");
    char scene[800], out[900], png[1000];
    snprintf(scene, sizeof scene, "%s/bend_%s_%g.yaml", dir, technique, lift);
    snprintf(text, sizeof text,
             "time: {dt: 1/120, fps: 30, duration: 1}\n"
             "render: {size: [%d, %d], shadows: {technique: %s, size: 2048, softness: 0},\n"
             "         refraction: false, reflection: false, bloom: false, god_rays: false,\n"
             "         fxaa: false, msaa: 0, seabed: true}\n"
             "sky: {time_of_day: 13, day_length: 0}\n"
             "fog: {below: {color: [0.03, 0.16, 0.2], density: 0.01}}\n"
             "water: {level: %g, depth: %g, look: {caustics: false}, waves: {model: flat}}\n"
             "objects:\n  models:\n    - {name: block, mesh: box, position: [0, %g, 0]}\n"
             "camera:\n  fov: %g\n  collide: false\n"
             "  path: [{t: 0, position: [%.6f, %g, %.6f], yaw: 0, pitch: -89.9}]\n",
             BEND_SIZE, BEND_SIZE, technique, level, depth, level + lift, fov, x, cam_y, z);
    ENSURE(ww_test_write_text(scene, text) == 0);
    snprintf(out, sizeof out, "%s/%s_%g", dir, technique, lift);
    ENSURE_EQ_INT(ww_test_render(scene, NULL, out), 0);
    snprintf(png, sizeof png, "%s/frame_00000.png", out);
    pic p;
    if (!ww_test_pic_load(png, &p)) return;
    double *l = malloc((size_t)p.w * (size_t)p.h * sizeof *l), med = 0.0;
    ENSURE(l != NULL);
    if (l) {
        for (int y = 0; y < p.h; y++)
            for (int x2 = 0; x2 < p.w; x2++) l[y * p.w + x2] = ww_test_pic_luma(&p, x2, y);
        /* the median by counting: lumas are 0..255 */
        long hist[256] = {0};
        for (int i = 0; i < p.w * p.h; i++) hist[(int)fmin(fmax(l[i], 0.0), 255.0)]++;
        long acc = 0;
        for (int v = 0; v < 256; v++)
            if ((acc += hist[v]) >= (long)p.w * p.h / 2) {
                med = v;
                break;
            }
        double sx = 0.0, sy = 0.0;
        long cnt = 0;
        for (int y = 0; y < p.h; y++)
            for (int x2 = 0; x2 < p.w; x2++)
                if (l[y * p.w + x2] < BEND_DROP * med) sx += x2 + 0.5, sy += y + 0.5, cnt++;
        /* metres per pixel on the seabed `over` below the camera */
        double m_px = 2.0 * over * tan(0.5 * fov * 3.14159265358979323846 / 180.0) / p.h;
        double dx = cnt ? (sx / cnt - 0.5 * p.w) * m_px : INFINITY;
        double dy = cnt ? (sy / cnt - 0.5 * p.h) * m_px : INFINITY;
        double off = hypot(dx, dy);
        fprintf(stderr,
                "    %s, box at %+g m: shadow %ld px, its centroid %.3f m from the bent light's "
                "point\n",
                technique, lift, cnt, off);
        ENSURE_MSG(cnt >= BEND_MIN_PX, "%s: %ld shadow pixels", technique, cnt);
        ENSURE_MSG(off <= BEND_TOL, "%s: the shadow lies %.2f m from where the bent light puts it",
                   technique, off);
        free(l);
    }
    ww_image_free(&p.im);
}

TEST_IMAGE(shadows_bend_with_the_light_at_the_water) {
    REQUIRE_GL();
    static const char *const technique[3] = {"map", "projected", "volumes"};
    for (int k = 0; k < 3; k++) {
        bent_shadow(technique[k], 1.5);
        bent_shadow(technique[k], -3.0);
    }
}
