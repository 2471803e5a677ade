/* test_gfx.c - graphics: the EGL and OSMesa backends, the renderer's sky and water, determinism
 * across runs and backends, far-from-origin precision, the WW_SHADER_DIR override, and the water
 * shaders' wave field against the CPU's (the GPU probe). Scenes, states and plans are built by
 * hand here; only the probe test reads sim/ (its CPU reference).
 */
#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "core/rng.h"
#include "gfx/backend.h"
#include "gfx/renderer.h"
#include "gfx/shaders.h"
#include "sim/ripples.h"
#include "sim/waves.h"
#include "test.h"

#define GFX_W 256
#define GFX_H 144
/* the sun disc has radiance 20 x sun colour; its centre pixel must be far above the sky */
#define SUN_MIN_RADIANCE 5.0
/* two renders of the same camera-relative world, once at the origin and once 1e5 m away at
 * t = 1e6 s: float rounding of the (double) centre phases may move a few LDR codes */
#define FAR_ORIGIN_LDR_TOL 2
#define FAR_ORIGIN_BAD_PIXEL_FRACTION 0.001

/* a hand-built frame: the scene, a state whose field pointers point at our arrays, the plan */
typedef struct world {
    ww_scene *sc;
    ww_state st;
    double time_of_day, sun_dir[3], sun_color[3], sky_zenith[3], sky_horizon[3], ambient[3];
    double cam_pos[3], cam_fwd[3], cam_fov;
    double wave_phase[WW_MAX_WAVES];
    double ripple[WW_RIPPLE_STRIDE * WW_MAX_RIPPLES];
    ww_plan plan;
} world;

static void add_wave(ww_scene *sc, double dir_deg, double wavelength, double amp, double q) {
    ww_wave *w = &sc->waves[sc->nwaves++];
    *w = (ww_wave){.direction = ww_m_rad(dir_deg), .wavelength = wavelength, .amplitude = amp,
                   .steepness = q};
    ww_wave_derive(w, 0.0);
}

static void set3(double *d, double x, double y, double z) {
    d[0] = x;
    d[1] = y;
    d[2] = z;
}

/* unit vector from elevation and azimuth (degrees; azimuth 0 looks along -z, 90 along +x) */
static void dir_from(double *d, double elev_deg, double azim_deg) {
    double e = ww_m_rad(elev_deg), a = ww_m_rad(azim_deg);
    set3(d, cos(e) * sin(a), sin(e), -cos(e) * cos(a));
}

/* wave phases at the origin for time t: -w t + p0, wrapped (as sim/waves.c does) */
static void world_set_time(world *w, double t) {
    w->st.t = t;
    for (int i = 0; i < w->sc->nwaves; i++)
        w->wave_phase[i] = ww_m_wrap_tau(-w->sc->waves[i].omega * t + w->sc->waves[i].phase);
}

static void world_look_at(world *w, double px, double py, double pz, double tx, double ty,
                          double tz) {
    set3(w->cam_pos, px, py, pz);
    set3(w->cam_fwd, tx - px, ty - py, tz - pz);
    ww_m_normalize3(w->cam_fwd);
}

/* late afternoon (16:30) over three Gerstner waves; camera at (0, 3, 10) looking at the origin */
static world *world_new(int width, int height) {
    world *w = calloc(1, sizeof *w);
    w->sc = malloc(sizeof *w->sc);
    ww_scene *sc = w->sc;
    ww_scene_defaults(sc);
    snprintf(sc->name, sizeof sc->name, "test_gfx");
    sc->width = width;
    sc->height = height;
    sc->tonemap = WW_TONEMAP_ACES;
    sc->render.sky = WW_SKY_GRADIENT; /* the sky from the palette set below */
    add_wave(sc, 20.0, 12.0, 0.25, 0.6);
    add_wave(sc, -35.0, 5.0, 0.08, 0.4);
    add_wave(sc, 75.0, 2.1, 0.025, 0.3);

    /* the state: the header from state.h, its arrays ours */
    ww_state *st = &w->st;
    st->bytes = sizeof *w;
    st->time_of_day = &w->time_of_day;
    st->sun_dir = w->sun_dir;
    st->sun_color = w->sun_color;
    st->sky_zenith = w->sky_zenith;
    st->sky_horizon = w->sky_horizon;
    st->ambient = w->ambient;
    st->cam_pos = w->cam_pos;
    st->cam_fwd = w->cam_fwd;
    st->cam_fov = &w->cam_fov;
    st->wave_phase = w->wave_phase;
    st->ripple = w->ripple;
    w->time_of_day = 16.5;
    dir_from(w->sun_dir, 20.0, 15.0);
    set3(w->sun_color, 1.6, 1.4, 1.1);
    set3(w->sky_zenith, 0.1, 0.25, 0.62);
    set3(w->sky_horizon, 0.55, 0.62, 0.72);
    set3(w->ambient, 0.25, 0.3, 0.4);
    w->cam_fov = ww_m_rad(60.0);
    world_look_at(w, 0.0, 3.0, 10.0, 0.0, 0.0, 0.0);
    world_set_time(w, 12.0);

    /* the plan: main HDR pass, then tone mapping */
    ww_plan *p = &w->plan;
    p->npasses = 2;
    p->passes[0] = (ww_pass_desc){.id = WW_PASS_MAIN, .name = "main", .what = "sky, water",
                                  .ntargets = 2};
    p->passes[0].targets[0] = (ww_target_desc){"hdr", WW_FMT_RGBA16F, width, height};
    p->passes[0].targets[1] = (ww_target_desc){"depth", WW_FMT_DEPTH24, width, height};
    p->passes[1] = (ww_pass_desc){.id = WW_PASS_TONEMAP, .name = "tonemap", .what = "HDR to sRGB8",
                                  .ntargets = 1};
    p->passes[1].targets[0] = (ww_target_desc){"ldr", WW_FMT_RGBA8, width, height};
    return w;
}

static void world_free(world *w) {
    free(w->sc);
    free(w);
}

/* open a backend, render one frame and read it back (hdr may be NULL) */
static ww_result render(ww_backend_kind kind, const world *w, ww_image *ldr, ww_image *hdr,
                        ww_error *err) {
    ww_backend *b = NULL;
    ww_renderer *r = NULL;
    ww_result rc = ww_backend_open(kind, &b, err);
    if (rc == WW_OK) rc = ww_renderer_new(ww_backend_gl(b), w->sc, &w->plan, &r, err);
    if (rc == WW_OK) rc = ww_render_frame(r, w->sc, &w->st, err);
    if (rc == WW_OK) rc = ww_renderer_read_ldr(r, ldr, err);
    if (rc == WW_OK && hdr) rc = ww_renderer_read_hdr(r, hdr, err);
    ww_renderer_free(r);
    ww_backend_close(b);
    if (rc != WW_OK) fprintf(stderr, "\n    render: %s\n", err->msg);
    return rc;
}

static int gl_version_at_least(const char *v, int major, int minor) {
    int ma = 0, mi = 0;
    if (!v || sscanf(v, "%d.%d", &ma, &mi) != 2) return 0;
    return ma > major || (ma == major && mi >= minor);
}

static void check_backend(ww_backend_kind kind, const char *describe_prefix) {
    ww_backend *b = NULL;
    ww_error err = {0};
    ww_result rc = ww_backend_open(kind, &b, &err);
    ENSURE_MSG(rc == WW_OK, "open: %s", err.msg);
    if (rc != WW_OK) return;
    ENSURE(ww_backend_get_kind(b) == kind);
    ENSURE(gl_version_at_least(ww_backend_version(b), 3, 3));
    ENSURE(ww_backend_renderer(b)[0] != '\0');
    ENSURE_MSG(strncmp(ww_backend_describe(b), describe_prefix, strlen(describe_prefix)) == 0,
               "describe: %s", ww_backend_describe(b));
    const ww_gl *gl = ww_backend_gl(b);
    ENSURE(gl->GetError() == GL_NO_ERROR);
    ww_backend_close(b);
}

/* the null backend: no GL, but the renderer is built from the plan, runs its passes and reads back
 * black frames of the right size, so the job's outputs can be tested anywhere */
TEST(gfx_null_backend_renders_black_frames_without_gl) {
    ww_backend *b = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_backend_open(WW_BACKEND_NULL, &b, &err), WW_OK);
    if (!b) return;
    ENSURE(ww_backend_get_kind(b) == WW_BACKEND_NULL);
    ENSURE(strcmp(ww_backend_describe(b), "null") == 0);
    ENSURE(strcmp(ww_backend_renderer(b), "null") == 0);
    ENSURE(strncmp(ww_backend_version(b), "3.3", 3) == 0);
    world *w = world_new(GFX_W, GFX_H);
    ww_renderer *r = NULL;
    ww_image ldr = {0}, hdr = {0};
    ENSURE_EQ_INT(ww_image_alloc(&ldr, GFX_W, GFX_H, 3, WW_PIX_U8), 0);
    ENSURE_EQ_INT(ww_image_alloc(&hdr, GFX_W, GFX_H, 4, WW_PIX_F32), 0);
    if (!ldr.u8 || !hdr.f32) return;
    memset(ldr.u8, 0x7f, (size_t)GFX_W * GFX_H * 3); /* so that the read is seen to write */
    ENSURE_EQ_INT(ww_renderer_new(ww_backend_gl(b), w->sc, &w->plan, &r, &err), WW_OK);
    for (int f = 0; r && f < 2; f++) ENSURE_EQ_INT(ww_render_frame(r, w->sc, &w->st, &err), WW_OK);
    if (r) ENSURE_EQ_INT(ww_renderer_read_ldr(r, &ldr, &err), WW_OK);
    if (r) ENSURE_EQ_INT(ww_renderer_read_hdr(r, &hdr, &err), WW_OK);
    size_t nonzero = 0;
    for (size_t i = 0; i < (size_t)GFX_W * GFX_H * 3; i++)
        nonzero += ldr.u8[i] != 0;
    ENSURE_EQ_INT(nonzero, 0);
    ww_image_free(&ldr);
    ww_image_free(&hdr);
    ww_renderer_free(r);
    world_free(w);
    ww_backend_close(b);
}

TEST_PROC(gfx_backend_egl_opens) {
    REQUIRE_BACKEND(WW_BACKEND_EGL);
    check_backend(WW_BACKEND_EGL, "egl/");
}

TEST_PROC(gfx_backend_osmesa_opens) {
    REQUIRE_BACKEND(WW_BACKEND_OSMESA);
    check_backend(WW_BACKEND_OSMESA, "osmesa");
}

TEST_PROC(gfx_backend_egl_platform_env) {
    REQUIRE_BACKEND(WW_BACKEND_EGL);
    ww_backend *b = NULL;
    ww_error err = {0};

    /* forced surfaceless */
    setenv("WW_EGL_PLATFORM", "surfaceless", 1);
    ww_result rc = ww_backend_open(WW_BACKEND_EGL, &b, &err);
    ENSURE_MSG(rc == WW_OK, "surfaceless: %s", err.msg);
    if (rc == WW_OK) ENSURE(strcmp(ww_backend_describe(b), "egl/surfaceless") == 0);
    ww_backend_close(b);
    b = NULL;

    /* a word that is no platform is refused, naming the variable */
    setenv("WW_EGL_PLATFORM", "wayland", 1);
    rc = ww_backend_open(WW_BACKEND_EGL, &b, &err);
    ENSURE_EQ_INT(rc, WW_E_BACKEND);
    ENSURE(b == NULL);
    ENSURE(strstr(err.msg, "WW_EGL_PLATFORM") != NULL);

    /* a device index past the last device */
    unsetenv("WW_EGL_PLATFORM");
    setenv("WW_EGL_DEVICE", "15", 1);
    rc = ww_backend_open(WW_BACKEND_EGL, &b, &err);
    ENSURE_EQ_INT(rc, WW_E_BACKEND);
    ENSURE(b == NULL);
    unsetenv("WW_EGL_DEVICE");
}

TEST(gfx_backend_bad_kind_parse) {
    ENSURE_EQ_INT(ww_backend_kind_parse("auto"), WW_BACKEND_AUTO);
    ENSURE_EQ_INT(ww_backend_kind_parse("egl"), WW_BACKEND_EGL);
    ENSURE_EQ_INT(ww_backend_kind_parse("osmesa"), WW_BACKEND_OSMESA);
    ENSURE_EQ_INT(ww_backend_kind_parse("vulkan"), -1);
    ENSURE_EQ_INT(ww_backend_kind_parse("EGL"), -1);
    ENSURE_EQ_INT(ww_backend_kind_parse("egl "), -1);
    ENSURE_EQ_INT(ww_backend_kind_parse(""), -1);
    ENSURE_EQ_INT(ww_backend_kind_parse(NULL), -1);
}

/* mean of channel c over rows [y0, y1) */
static double rows_mean(const ww_image *im, int y0, int y1, int c) {
    double s = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < im->width; x++)
            s += im->u8[((size_t)y * im->width + x) * im->channels + c];
    return s / ((double)(y1 - y0) * im->width);
}

static int count_nonfinite(const ww_image *im) {
    int bad = 0;
    size_t n = (size_t)im->width * im->height * im->channels;
    for (size_t i = 0; i < n; i++) bad += !isfinite(im->f32[i]);
    return bad;
}

/* pixel (column, row from the top) where world direction d lands for the state's camera */
static int project_dir(const world *w, const double d[3], int *px, int *py) {
    double f[3] = {w->cam_fwd[0], w->cam_fwd[1], w->cam_fwd[2]};
    ww_m_normalize3(f);
    double r[3] = {-f[2], 0.0, f[0]}; /* f x (0, 1, 0) */
    ww_m_normalize3(r);
    double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    double z = ww_m_dot3(d, f);
    if (z <= 0.0) return 0;
    double t = tan(w->cam_fov * 0.5), aspect = (double)w->sc->width / w->sc->height;
    double x = ww_m_dot3(d, r) / z / (t * aspect), y = ww_m_dot3(d, u) / z / t;
    *px = (int)floor((x + 1.0) * 0.5 * w->sc->width);
    *py = (int)floor((1.0 - y) * 0.5 * w->sc->height);
    return *px >= 0 && *px < w->sc->width && *py >= 0 && *py < w->sc->height;
}

TEST_PROC(gfx_render_sky_and_water) {
    REQUIRE_GL();
    world *w = world_new(GFX_W, GFX_H);
    ww_image ldr, hdr;
    ENSURE(ww_image_alloc(&ldr, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ENSURE(ww_image_alloc(&hdr, GFX_W, GFX_H, 4, WW_PIX_F32) == 0);
    ww_error err = {0};

    /* camera at (0, 3, 10) looking at the origin: sky above, water below */
    ENSURE(render(WW_BACKEND_AUTO, w, &ldr, &hdr, &err) == WW_OK);
    double top_r = rows_mean(&ldr, 0, 8, 0), top_b = rows_mean(&ldr, 0, 8, 2);
    double top = (rows_mean(&ldr, 0, 8, 0) + rows_mean(&ldr, 0, 8, 1) + top_b) / 3.0;
    double bottom = (rows_mean(&ldr, GFX_H - 8, GFX_H, 0) + rows_mean(&ldr, GFX_H - 8, GFX_H, 1) +
                     rows_mean(&ldr, GFX_H - 8, GFX_H, 2)) / 3.0;
    ENSURE_MSG(top_b > top_r, "top rows not blue: r %.1f b %.1f", top_r, top_b);
    ENSURE_MSG(bottom < top, "water (%.1f) not darker than the sky (%.1f)", bottom, top);
    ENSURE_EQ_INT(count_nonfinite(&hdr), 0);
    /* alpha is 1 everywhere in the HDR image */
    int alpha_bad = 0;
    for (size_t i = 0; i < (size_t)GFX_W * GFX_H; i++) alpha_bad += hdr.f32[4 * i + 3] != 1.0f;
    ENSURE_EQ_INT(alpha_bad, 0);

    /* a camera looking a little below the sun sees the disc where projection puts it */
    dir_from(w->sun_dir, 8.0, 30.0);
    double look[3];
    dir_from(look, 2.0, 22.0);
    world_look_at(w, 0.0, 3.0, 0.0, look[0], 3.0 + look[1], look[2]);
    ENSURE(render(WW_BACKEND_AUTO, w, &ldr, &hdr, &err) == WW_OK);
    int px = -1, py = -1;
    ENSURE(project_dir(w, w->sun_dir, &px, &py));
    if (px >= 0 && py >= 0) {
        const float *h = &hdr.f32[((size_t)py * GFX_W + px) * 4];
        const uint8_t *l = &ldr.u8[((size_t)py * GFX_W + px) * 3];
        double lum = 0.2126 * h[0] + 0.7152 * h[1] + 0.0722 * h[2];
        ENSURE_MSG(lum > SUN_MIN_RADIANCE, "sun pixel (%d, %d) radiance %.3g", px, py, lum);
        ENSURE_MSG(l[0] >= 250 && l[1] >= 250 && l[2] >= 240, "sun pixel LDR %d %d %d", l[0],
                   l[1], l[2]);
        /* and the sky a few degrees away is not */
        const float *away = &hdr.f32[((size_t)py * GFX_W + (px + 20) % GFX_W) * 4];
        ENSURE(0.2126 * away[0] + 0.7152 * away[1] + 0.0722 * away[2] < 0.5 * SUN_MIN_RADIANCE);
    }
    ww_image_free(&ldr);
    ww_image_free(&hdr);
    world_free(w);
}

static size_t count_diff(const ww_image *a, const ww_image *b, int tol) {
    size_t n = (size_t)a->width * a->height * a->channels, bad = 0;
    for (size_t i = 0; i < n; i++) bad += abs((int)a->u8[i] - (int)b->u8[i]) > tol;
    return bad;
}

TEST_IMAGE(gfx_egl_and_osmesa_identical) {
    REQUIRE_GL();
    REQUIRE_BACKEND(WW_BACKEND_EGL);
    REQUIRE_BACKEND(WW_BACKEND_OSMESA);
    world *w = world_new(GFX_W, GFX_H);
    ww_image a, b;
    ENSURE(ww_image_alloc(&a, GFX_W, GFX_H, 4, WW_PIX_U8) == 0);
    ENSURE(ww_image_alloc(&b, GFX_W, GFX_H, 4, WW_PIX_U8) == 0);
    ww_error err = {0};
    ENSURE(render(WW_BACKEND_EGL, w, &a, NULL, &err) == WW_OK);
    ENSURE(render(WW_BACKEND_OSMESA, w, &b, NULL, &err) == WW_OK);
    ENSURE_EQ_INT(count_diff(&a, &b, 0), 0);
    ww_image_free(&a);
    ww_image_free(&b);
    world_free(w);
}

TEST_IMAGE(gfx_render_repeatable) {
    REQUIRE_GL();
    world *w = world_new(GFX_W, GFX_H);
    ww_image a, b;
    ENSURE(ww_image_alloc(&a, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ENSURE(ww_image_alloc(&b, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ww_backend *be = NULL;
    ww_renderer *r = NULL;
    ww_error err = {0};
    ENSURE(ww_backend_open(WW_BACKEND_AUTO, &be, &err) == WW_OK);
    if (be) ENSURE(ww_renderer_new(ww_backend_gl(be), w->sc, &w->plan, &r, &err) == WW_OK);
    if (r) {
        /* same renderer twice, with a different frame between (no state may leak) */
        ENSURE(ww_render_frame(r, w->sc, &w->st, &err) == WW_OK);
        ENSURE(ww_renderer_read_ldr(r, &a, &err) == WW_OK);
        world_set_time(w, 13.0);
        ENSURE(ww_render_frame(r, w->sc, &w->st, &err) == WW_OK);
        ENSURE(ww_renderer_read_ldr(r, &b, &err) == WW_OK);
        ENSURE(count_diff(&a, &b, 0) > 0); /* time moves the waves */
        world_set_time(w, 12.0);
        ENSURE(ww_render_frame(r, w->sc, &w->st, &err) == WW_OK);
        ENSURE(ww_renderer_read_ldr(r, &b, &err) == WW_OK);
        ENSURE_EQ_INT(count_diff(&a, &b, 0), 0);
    }
    ww_renderer_free(r);
    ww_backend_close(be);
    /* and a fresh context gives the same bytes */
    ENSURE(render(WW_BACKEND_AUTO, w, &b, NULL, &err) == WW_OK);
    ENSURE_EQ_INT(count_diff(&a, &b, 0), 0);
    ww_image_free(&a);
    ww_image_free(&b);
    world_free(w);
}

TEST_IMAGE(gfx_render_far_from_origin) {
    REQUIRE_GL();
    /* the same camera-relative world at the origin and at (1e5, 3, -1e5) m, t = 1e6 s: the
     * origin phases are shifted by -k D.offset so the waves around the camera are the same */
    world *w = world_new(GFX_W, GFX_H);
    ww_image a, b;
    ENSURE(ww_image_alloc(&a, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ENSURE(ww_image_alloc(&b, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ww_error err = {0};
    world_set_time(w, 1e6);
    ENSURE(render(WW_BACKEND_AUTO, w, &a, NULL, &err) == WW_OK);

    const double off[2] = {1e5, -1e5};
    world_look_at(w, off[0], 3.0, 10.0 + off[1], off[0], 0.0, off[1]);
    for (int i = 0; i < w->sc->nwaves; i++) {
        const ww_wave *wv = &w->sc->waves[i];
        double kd = wv->k * (wv->dir[0] * off[0] + wv->dir[1] * off[1]);
        w->wave_phase[i] = ww_m_wrap_tau(w->wave_phase[i] - kd);
    }
    ENSURE(render(WW_BACKEND_AUTO, w, &b, NULL, &err) == WW_OK);
    size_t bad = count_diff(&a, &b, FAR_ORIGIN_LDR_TOL);
    ENSURE_MSG(bad <= FAR_ORIGIN_BAD_PIXEL_FRACTION * GFX_W * GFX_H * 3,
               "%zu of %d values differ by more than %d", bad, GFX_W * GFX_H * 3,
               FAR_ORIGIN_LDR_TOL);
    ww_image_free(&a);
    ww_image_free(&b);
    world_free(w);
}

/* drawing only the wedge of the water mesh in view must not change a pixel: poses looking
 * level, down, steeply down, up, across the snap grid, over big waves */
TEST_IMAGE(gfx_water_wedge_culling_changes_no_pixel) {
    REQUIRE_GL();
    world *w = world_new(GFX_W, GFX_H);
    add_wave(w->sc, 140.0, 30.0, 1.5, 0.9); /* 1.35 m sideways displacement on top */
    world_set_time(w, 7.0);
    static const double poses[][6] = {
        {0.3, 3.0, 10.2, 0.0, 0.0, 0.0},        {0.0, 2.0, 0.0, 40.0, -1.0, 3.0},
        {-3.2, 5.0, 1.7, -3.0, 0.0, -1.0},      {0.0, 20.0, 0.0, 0.4, 0.0, 30.0},
        {5.26, 1.2, -7.74, -100.0, 30.0, 5.0},  {0.0, 1.0, 0.0, 0.0, -5.0, 20.0},
        {0.0, 40.0, 0.0, 0.01, 0.0, 0.01},      {12.0, 0.6, 3.0, -50.0, 0.5, 100.0},
    };
    ww_image a, b;
    ENSURE(ww_image_alloc(&a, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ENSURE(ww_image_alloc(&b, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ww_error err = {0};
    for (size_t i = 0; i < sizeof poses / sizeof poses[0]; i++) {
        const double *p = poses[i];
        world_look_at(w, p[0], p[1], p[2], p[3], p[4], p[5]);
        setenv("WW_WATER_CULL", "0", 1);
        ENSURE(render(WW_BACKEND_AUTO, w, &a, NULL, &err) == WW_OK);
        unsetenv("WW_WATER_CULL");
        ENSURE(render(WW_BACKEND_AUTO, w, &b, NULL, &err) == WW_OK);
        ENSURE_MSG(count_diff(&a, &b, 0) == 0, "pose %zu: %zu values differ", i, count_diff(&a, &b, 0));
    }
    ww_image_free(&a);
    ww_image_free(&b);
    world_free(w);
}

/* the water's rings beyond the radius where the vertex shader fades every wave out are drawn as
 * one flat band: no pixel may move by more than the float rounding of interpolating across the
 * larger triangles. Poses looking level at the horizon (where the band lies), from high up,
 * steeply down and over a long swell, whose flat radius lies farther out */
#define BAND_LDR_TOL 1            /* 8-bit levels the band's rounding may move a value */
#define BAND_BAD_FRACTION 1e-4    /* of the values, at most, moved by that much */
TEST_IMAGE(gfx_water_flat_band_changes_no_pixel) {
    REQUIRE_GL();
    world *w = world_new(GFX_W, GFX_H);
    add_wave(w->sc, 20.0, 12.0, 0.2, 0.6);
    add_wave(w->sc, -35.0, 5.0, 0.06, 0.4);
    world_set_time(w, 3.0);
    static const double poses[][6] = {
        {0.0, 2.5, 6.0, 0.0, 2.3, -100.0},  {3.0, 1.2, 0.0, -100.0, 1.0, -20.0},
        {0.0, 60.0, 0.0, 0.0, 0.0, -200.0}, {0.0, 4.0, 0.0, 1.0, 0.0, -8.0},
    };
    ww_image a, b;
    ENSURE(ww_image_alloc(&a, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ENSURE(ww_image_alloc(&b, GFX_W, GFX_H, 3, WW_PIX_U8) == 0);
    ww_error err = {0};
    for (int swell = 0; swell < 2; swell++) {
        if (swell) add_wave(w->sc, 60.0, 60.0, 0.5, 0.3);
        for (size_t i = 0; i < sizeof poses / sizeof poses[0]; i++) {
            const double *p = poses[i];
            world_look_at(w, p[0], p[1], p[2], p[3], p[4], p[5]);
            setenv("WW_WATER_BAND", "0", 1);
            ENSURE(render(WW_BACKEND_AUTO, w, &a, NULL, &err) == WW_OK);
            unsetenv("WW_WATER_BAND");
            ENSURE(render(WW_BACKEND_AUTO, w, &b, NULL, &err) == WW_OK);
            size_t moved = count_diff(&a, &b, 0), far = count_diff(&a, &b, BAND_LDR_TOL);
            ENSURE_MSG(far == 0 && moved <= BAND_BAD_FRACTION * GFX_W * GFX_H * 3,
                       "swell %d, pose %zu: %zu values moved, %zu by more than %d", swell, i,
                       moved, far, BAND_LDR_TOL);
        }
    }
    ww_image_free(&a);
    ww_image_free(&b);
    world_free(w);
}

/* copy every built-in shader into dir, then break `broken` */
static int write_shader_dir(const char *dir, const char *broken) {
    for (const ww_shader_file *f = ww_shader_files; f->name; f++) {
        char path[600];
        snprintf(path, sizeof path, "%s/%s", dir, f->name);
        FILE *out = fopen(path, "wb");
        if (!out) return -1;
        if (strcmp(f->name, broken) == 0)
            fputs("#version 330 core\nout vec4 o_color;\nvoid main() { o_color = oops; }\n", out);
        else
            fwrite(f->text, 1, f->len, out);
        if (fclose(out) != 0) return -1;
    }
    return 0;
}

TEST_PROC(gfx_shader_dir_override) {
    REQUIRE_GL();
    const char *tmp = ww_test_tmpdir("gfx_shader_dir_override");
    ENSURE(tmp != NULL);
    if (!tmp) return;
    char dir[512];
    snprintf(dir, sizeof dir, "%s", tmp);
    ENSURE(write_shader_dir(dir, "water.frag.glsl") == 0);

    /* the text comes from the folder */
    setenv("WW_SHADER_DIR", dir, 1);
    char *src = NULL;
    ww_error err = {0};
    ENSURE(ww_shader_source("water.frag.glsl", &src, &err) == WW_OK);
    ENSURE(src && strstr(src, "oops") != NULL);
    free(src);
    ENSURE_EQ_INT(ww_shader_source("missing.glsl", &src, &err), WW_E_NOFILE);

    /* and a renderer built from it fails naming the file, with the compiler's log */
    world *w = world_new(64, 36);
    ww_backend *b = NULL;
    ww_renderer *r = NULL;
    ENSURE(ww_backend_open(WW_BACKEND_AUTO, &b, &err) == WW_OK);
    if (b) {
        ww_result rc = ww_renderer_new(ww_backend_gl(b), w->sc, &w->plan, &r, &err);
        ENSURE_EQ_INT(rc, WW_E_GL);
        ENSURE(r == NULL);
        ENSURE_MSG(strcmp(err.file, "water.frag.glsl") == 0, "file: %s", err.file);
        ENSURE_MSG(strstr(err.msg, "oops") != NULL, "msg: %s", err.msg);
        /* the line of the file (3), not of the assembled text: #line directives map it back
         * (Mesa writes "0:3(", NVIDIA "0(3)") */
        ENSURE_MSG(strstr(err.msg, "0:3(") || strstr(err.msg, "0(3)"), "msg: %s", err.msg);
    }
    unsetenv("WW_SHADER_DIR");

    /* without the override the built-in shaders are back */
    if (b) {
        ENSURE(ww_renderer_new(ww_backend_gl(b), w->sc, &w->plan, &r, &err) == WW_OK);
        ww_renderer_free(r);
    }
    ww_backend_close(b);
    world_free(w);
}

/* ---- one field, two consumers: the water shaders' surface against the CPU's ---- */

/* float shaders (phases wrapped in double at the camera, float sums and sin/cos) against the
 * double CPU field: the height within a thousandth of the total amplitude */
#define PROBE_HEIGHT_TOL 1e-3
/* the same for the angle between the GPU and CPU normals, degrees */
#define PROBE_NORMAL_TOL_DEG 0.5
#define PROBE_POINTS 600
#define PROBE_RADIUS 60.0 /* sample points within this distance of the camera, m */

/* a few live ripples near the camera (x, z offsets, age s, A0 m), one free slot and one that has
 * not started yet; the pool is placed relative to the camera at time t */
static void probe_ripples(world *w, const double cam[3], double t) {
    static const double live[][4] = {
        {3.0, -4.0, 2.0, 0.08}, {-10.0, 6.0, 5.0, 0.1}, {20.0, 25.0, 12.0, 0.06}, {0.5, 0.5, 0.7, 0.05},
    };
    ww_scene *sc = w->sc;
    sc->ripples_on = 1;
    sc->ripples = (ww_ripple_desc){.amplitude = 0.05, .lifetime = 60.0, .max = 6,
                                   .radial_decay = 0.08, .time_decay = 0.1,
                                   .wavenumber = WW_TAU / 1.5};
    sc->ripples.speed = sqrt(WW_G / sc->ripples.wavenumber); /* deep water, 1.5 m ripples */
    memset(w->ripple, 0, sizeof w->ripple);
    for (int i = 0; i < 4; i++) {
        double *e = w->ripple + WW_RIPPLE_STRIDE * i;
        e[0] = cam[0] + live[i][0];
        e[1] = cam[2] + live[i][1];
        e[2] = t - live[i][2];
        e[3] = live[i][3];
    }
    double *future = w->ripple + WW_RIPPLE_STRIDE * 5; /* slot 4 stays free */
    future[0] = cam[0];
    future[1] = cam[2];
    future[2] = t + 1.0;
    future[3] = 0.2;
}

/* rest points relative to the camera, exactly representable in float (what the probe draws):
 * half spread over the disc, half within 12 m of the ripple centres */
static void probe_points(double *xz, int n) {
    static const double near[][2] = {{3.0, -4.0}, {-10.0, 6.0}, {20.0, 25.0}, {0.5, 0.5}};
    ww_rng rng;
    ww_rng_seed(&rng, 20261122u, 99u);
    for (int i = 0; i < n; i++) {
        double r, a = WW_TAU * ww_rng_uniform(&rng), cx = 0.0, cz = 0.0;
        if (i % 2 == 0) {
            r = PROBE_RADIUS * sqrt(ww_rng_uniform(&rng));
        } else {
            r = 12.0 * ww_rng_uniform(&rng);
            cx = near[(i / 2) % 4][0];
            cz = near[(i / 2) % 4][1];
        }
        xz[2 * i] = (float)(cx + r * cos(a));
        xz[2 * i + 1] = (float)(cz + r * sin(a));
    }
}

typedef struct probe_err {
    double dh, dxz, angle; /* max |height|, max |horizontal| difference (m), max normal angle (deg) */
    double total;          /* total amplitude, m */
    int rippled;           /* points where the ripples move the surface by more than 1 mm */
} probe_err;

/* the probe at one time and camera against ww_waves_point + ww_ripples_height, the ripples read at
 * the displaced point (where sim/water.h reads them) and their gradient taken through it */
static ww_result probe_compare(const ww_gl *gl, world *w, const double cam[3], double t,
                               const double *xz, int n, float *gpu, probe_err *pe, ww_error *err) {
    const ww_scene *sc = w->sc;
    w->st.t = t;
    ww_waves_phases(sc, t, w->wave_phase);
    probe_ripples(w, cam, t);
    ww_result rc = ww_gfx_water_probe(gl, sc, &w->st, cam, n, xz, gpu, err);
    if (rc != WW_OK) return rc;

    double phase_at[WW_MAX_WAVES];
    ww_waves_phases_at(sc, w->wave_phase, cam[0], cam[2], phase_at);
    pe->total = ww_waves_total_amplitude(sc);
    for (int i = 0; i < 4; i++) pe->total += w->ripple[WW_RIPPLE_STRIDE * i + 3];
    for (int i = 0; i < n; i++) {
        ww_wave_point wp;
        ww_waves_point(sc, phase_at, xz[2 * i], xz[2 * i + 1], 0.0, &wp);
        double g[2];
        double h = ww_ripples_height(sc, w->ripple, t, cam[0] + wp.p[0], cam[2] + wp.p[2], g, NULL);
        pe->rippled += fabs(h) > 1e-3;
        double dx[3] = {wp.dpdx[0], wp.dpdx[1] + g[0] * wp.dpdx[0] + g[1] * wp.dpdx[2], wp.dpdx[2]};
        double dz[3] = {wp.dpdz[0], wp.dpdz[1] + g[0] * wp.dpdz[0] + g[1] * wp.dpdz[2], wp.dpdz[2]};
        double nc[3] = {dz[1] * dx[2] - dz[2] * dx[1], dz[2] * dx[0] - dz[0] * dx[2],
                        dz[0] * dx[1] - dz[1] * dx[0]};
        ww_m_normalize3(nc);

        const float *o = gpu + 8 * i;
        double dh = fabs((cam[1] + o[1]) - (wp.p[1] + h));
        double dxz = fmax(fabs(o[0] - wp.p[0]), fabs(o[2] - wp.p[2]));
        double ng[3] = {o[4], o[5], o[6]};
        double cr[3] = {ng[1] * nc[2] - ng[2] * nc[1], ng[2] * nc[0] - ng[0] * nc[2],
                        ng[0] * nc[1] - ng[1] * nc[0]};
        double angle = ww_m_deg(atan2(ww_m_len3(cr), ww_m_dot3(ng, nc)));
        if (!(dh <= pe->dh)) pe->dh = dh; /* NaN sticks */
        if (!(dxz <= pe->dxz)) pe->dxz = dxz;
        if (!(angle <= pe->angle)) pe->angle = angle;
    }
    return WW_OK;
}

/* the five waves of the probe test (sum Q k A = 0.26 for gerstner: far from folding), from 0.9 m
 * to 30 m, in scene order not sorted by wavenumber */
static void probe_waves(ww_scene *sc, ww_wave_model model, double exponent) {
    static const double waves[][4] = {
        {20.0, 12.0, 0.25, 0.6}, {-35.0, 5.0, 0.08, 0.4}, {140.0, 30.0, 0.8, 0.5},
        {250.0, 0.9, 0.01, 0.5}, {75.0, 2.1, 0.025, 0.3},
    };
    int gerstner = model == WW_WAVES_GERSTNER;
    sc->wave_model = model;
    sc->nwaves = 0;
    for (size_t i = 0; i < sizeof waves / sizeof waves[0]; i++) {
        ww_wave *w = &sc->waves[sc->nwaves++];
        *w = (ww_wave){.direction = ww_m_rad(waves[i][0]), .wavelength = waves[i][1],
                       .amplitude = waves[i][2], .steepness = gerstner ? waves[i][3] : 0.0,
                       .exponent = exponent, .phase = 0.7 * (double)i};
        ww_wave_derive(w, 0.0);
    }
}

TEST_PROC(gfx_water_probe_matches_cpu) {
    REQUIRE_GL();
    static const struct {
        const char *name;
        ww_wave_model model;
        double exponent;
    } models[] = {
        {"gerstner", WW_WAVES_GERSTNER, 1.0},
        {"sines", WW_WAVES_SINES, 1.0},
        {"steep_sines e=3", WW_WAVES_STEEP_SINES, 3.0},
    };
    static const double times[] = {0.0, 1e3, 1e6};
    static const double cams[][3] = {{0.0, 3.0, 0.0}, {1e5, 3.0, 1e5}};
    world *w = world_new(64, 36);
    double *xz = malloc(2 * PROBE_POINTS * sizeof *xz);
    float *gpu = malloc(8 * PROBE_POINTS * sizeof *gpu);
    ENSURE(xz && gpu);
    probe_points(xz, PROBE_POINTS);
    ww_backend *b = NULL;
    ww_error err = {0};
    ENSURE(ww_backend_open(WW_BACKEND_AUTO, &b, &err) == WW_OK);
    for (size_t m = 0; b && xz && gpu && m < sizeof models / sizeof models[0]; m++) {
        probe_waves(w->sc, models[m].model, models[m].exponent);
        probe_err worst = {0};
        for (size_t ti = 0; ti < sizeof times / sizeof times[0]; ti++) {
            for (size_t c = 0; c < sizeof cams / sizeof cams[0]; c++) {
                probe_err pe = {0};
                ww_result rc = probe_compare(ww_backend_gl(b), w, cams[c], times[ti], xz,
                                             PROBE_POINTS, gpu, &pe, &err);
                ENSURE_MSG(rc == WW_OK, "%s: %s", models[m].name, err.msg);
                if (rc != WW_OK) break;
                /* the ripples are in the picture at every time and place */
                ENSURE_MSG(pe.rippled > PROBE_POINTS / 10, "%s: ripples move only %d points",
                           models[m].name, pe.rippled);
                worst.total = pe.total;
                worst.dh = fmax(worst.dh, pe.dh / pe.total);
                worst.dxz = fmax(worst.dxz, pe.dxz / pe.total);
                worst.angle = fmax(worst.angle, pe.angle);
                if (!(pe.dh / pe.total <= ww_test_tol(PROBE_HEIGHT_TOL)) ||
                    !(pe.angle <= ww_test_tol(PROBE_NORMAL_TOL_DEG)))
                    fprintf(stderr, "\n    %s at t = %g, camera (%g, %g, %g): |dh| %.3g m, angle %.3g deg",
                            models[m].name, times[ti], cams[c][0], cams[c][1], cams[c][2], pe.dh,
                            pe.angle);
            }
        }
        fprintf(stderr, "\n    %-16s max |dh| %.2e of %.3g m, |dxz| %.2e, normal %.4f deg",
                models[m].name, worst.dh, worst.total, worst.dxz, worst.angle);
        ENSURE_NEAR(worst.dh, 0.0, PROBE_HEIGHT_TOL);
        ENSURE_NEAR(worst.dxz, 0.0, PROBE_HEIGHT_TOL);
        ENSURE_NEAR(worst.angle, 0.0, PROBE_NORMAL_TOL_DEG);
    }
    fprintf(stderr, "\n    ");
    ww_backend_close(b);
    free(xz);
    free(gpu);
    world_free(w);
}

/* ---- plan: where each shader fades the components out ---- */

/* the plan's distances come from closed forms; checked against the spacing they invert */
#define PLAN_DISTANCE_TOL 1e-9 /* relative: rounding of the closed forms */

TEST(gfx_plan_fade_distances) {
    world *w = world_new(GFX_W, GFX_H);
    add_wave(w->sc, 0.0, 0.7, 0.01, 0.3); /* shorter than 2 s0: the mesh never carries it */
    const double sorted[] = {0.7, 2.1, 5.0, 12.0};
    ww_plan p;
    ww_plan_build(w->sc, GFX_W, GFX_H, &p);
    const ww_plan_water *pw = &p.water;
    ENSURE_EQ_INT(pw->components, 4);
    ENSURE_EQ_INT(pw->model, WW_WAVES_GERSTNER);

    /* the mesh: WW_WATER_RINGS rings growing by q from s0 end at the reach */
    const ww_water_mesh *m = &pw->mesh;
    double r = m->s0 * (pow(m->q, WW_WATER_RINGS) - 1.0) / (m->q - 1.0);
    ENSURE_NEAR(r / m->reach, 1.0, PLAN_DISTANCE_TOL);
    ENSURE_NEAR(m->reach, WW_WATER_REACH * w->sc->far_clip, PLAN_DISTANCE_TOL * m->reach);

    /* vertex: faded out where the spacing reaches half the wavelength (one step per component
     * for so few), 0 when the centre is already that coarse */
    ENSURE_EQ_INT(pw->vertex.nsteps, 4);
    for (int i = 0; i < pw->vertex.nsteps; i++) {
        double L = sorted[pw->vertex.faded[i] - 1], d = pw->vertex.beyond[i];
        ENSURE_EQ_INT(pw->vertex.faded[i], i + 1);
        if (d > 0.0)
            ENSURE_NEAR(ww_water_mesh_spacing(m, d) / (0.5 * L), 1.0, PLAN_DISTANCE_TOL);
        else
            ENSURE(m->s0 >= 0.5 * L);
    }
    ENSURE(pw->vertex.beyond[0] == 0.0); /* the 0.7 m wave */
    ENSURE(pw->vertex.start == 0.0);
    /* flat where the last of them, the longest, is gone */
    ENSURE(pw->flat_beyond == pw->vertex.beyond[pw->vertex.nsteps - 1]);

    /* fragment: the footprint across the view, d x pixel angle, reaches half the wavelength */
    double pa = 2.0 * tan(0.5 * w->sc->fov) / GFX_H;
    ENSURE_NEAR(pw->pixel_angle / pa, 1.0, PLAN_DISTANCE_TOL);
    ENSURE_NEAR(pw->fragment.start * pa / (0.25 * sorted[0]), 1.0, PLAN_DISTANCE_TOL);
    for (int i = 0; i < pw->fragment.nsteps; i++) {
        double L = sorted[pw->fragment.faded[i] - 1];
        ENSURE_NEAR(pw->fragment.beyond[i] * pa / (0.5 * L), 1.0, PLAN_DISTANCE_TOL);
    }
    ENSURE_EQ_INT(pw->ripple_pool, 0);

    /* ripples on: the pool is reported */
    w->sc->ripples_on = 1;
    w->sc->ripples.max = 32;
    w->sc->ripples.wavenumber = WW_TAU / 0.4;
    ww_plan_build(w->sc, GFX_W, GFX_H, &p);
    ENSURE_EQ_INT(p.water.ripple_pool, 32);
    ENSURE_NEAR(p.water.ripple_fragment_out * pa / 0.2, 1.0, PLAN_DISTANCE_TOL);
    world_free(w);
}
