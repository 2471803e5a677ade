/* sky.c - the sky drawn as one full-screen triangle on the far plane behind everything, one view
 * ray per pixel from the inverse view-projection (shaders/sky.frag.glsl): the gradient with the
 * sun disc and glow (shaders/common.glsl), the cubemap skybox of seed 004 (six images of the
 * scene's assets uploaded as one seamless, mipmapped sRGB cube texture, which the renderer then
 * offers the water to reflect: r->sky_cubemap) or the procedural dome (seed 003, common.glsl's
 * ww_sky_dome). Also sets common.glsl's sky uniforms for any program that includes it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"
#include "scene/assets.h"
#include "sim/sky.h"

/* the dome's clouds drift with the simulated time along a fixed wind (noise units per second);
 * the offset is wrapped to the noise's period in double, so a long run stays exact in float */
static const double DOME_WIND[2] = {0.011, 0.004};
static const double DOME_PERIOD = 256.0; /* WW_DOME_PERIOD in common.glsl */
/* Preetham's sky: the sun's lowest elevation the fit is evaluated at (rad), and the sun heights
 * (sin elevation) over which it fades into the twilight palette as the sun sets */
static const double PEREZ_MIN_ELEV = 0.0175;
static const double PEREZ_FADE0 = -0.06, PEREZ_FADE1 = 0.06;
static const double PREETHAM_SCALE = 0.022; /* WW_PREETHAM_SCALE in common.glsl */

/* one build of the sky program for each side of the surface the camera can be on
 * (WW_SKY_BELOW): llvmpipe runs both arms of a branch for every pixel, so under water the fog
 * colour paid for the clouds' noise, and above it the sky paid for the lights' glow */
typedef struct sky_prog {
    GLuint prog; /* 0: not built yet (built the first time a frame needs it) */
    ww_sky_locs sky;
    GLint inv_view_proj, intensity, below, below_density, cubemap, drift, dome_image;
} sky_prog;

struct ww_sky {
    sky_prog var[2]; /* by the camera's side: 0 above the water, 1 below */
    char defines[200];
    ww_sky_model model;
    ww_renderer *r;   /* its geometry holds this frame's lights (the glow under water) */
    int scatter;      /* WW_LIGHT_SCATTER: the lights glow in the water */
    GLuint cube_tex;  /* owned when this sky uploaded it (0 otherwise) */
    GLuint cube_draw; /* the cube texture drawn (owned or the renderer's) */
    GLuint dome_tex;  /* the dome's picture, owned when this sky uploaded it (0 otherwise) */
    GLuint dome_draw; /* the picture drawn (owned or the renderer's) */
};

void ww_sky_locs_init(const ww_gl *gl, GLuint prog, const ww_scene *sc, ww_sky_locs *l) {
    const ww_render_desc *d = &sc->render;
    l->zenith = ww_gfx_uniform(gl, prog, "u_sky_zenith");
    l->horizon = ww_gfx_uniform(gl, prog, "u_sky_horizon");
    l->sun_dir = ww_gfx_uniform(gl, prog, "u_sun_dir");
    l->sun_color = ww_gfx_uniform(gl, prog, "u_sun_color");
    l->perez = ww_gfx_uniform(gl, prog, "u_perez");
    l->zen = ww_gfx_uniform(gl, prog, "u_perez_zenith");
    l->psun = ww_gfx_uniform(gl, prog, "u_perez_sun");
    l->mode = ww_gfx_uniform(gl, prog, "u_sky_mode");
    l->clouds = ww_gfx_uniform(gl, prog, "u_sky_clouds");
    l->sky_map = ww_gfx_uniform(gl, prog, "u_sky_map");
    l->physical = d->sky == WW_SKY_PREETHAM || d->sky == WW_SKY_DOME;
    l->turbidity = d->sky_turbidity;
    /* the dome draws its own clouds over this sky */
    l->cover = d->sky == WW_SKY_PREETHAM ? d->cloud_cover : 0.0;
    l->speed = d->cloud_speed;
    /* the seed picks a start in the noise's period: a golden-ratio walk, so neighbouring seeds
     * start far apart */
    l->origin[0] = fmod(d->cloud_seed * 0.6180339887498949 * DOME_PERIOD, DOME_PERIOD);
    l->origin[1] = fmod(d->cloud_seed * 0.7548776662466927 * DOME_PERIOD, DOME_PERIOD);
}

/* Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight" (SIGGRAPH 1999): the
 * Perez distribution F(theta, gamma) = (1 + A e^(B / cos theta))(1 + C e^(D gamma) + E cos^2
 * gamma) of luminance Y and chromaticities x, y, each scaled so the zenith takes the zenith
 * value of the turbidity T and the sun's zenith angle (the paper's appendix A.2). Out: the
 * coefficients A..E for (Y, x, y) and the zenith values divided by F(0, theta_s). The fit holds
 * for the sun above the horizon: the sun is held at 1 degree at the lowest (the shader fades to
 * the twilight palette below). */
static void perez_coeffs(double T, double theta_s, float perez[15], float zen[3]) {
    const double k[5][3][2] = {/* {Y, x, y} x (slope on T, constant) for A..E */
                               {{0.1787, -1.4630}, {-0.0193, -0.2592}, {-0.0167, -0.2608}},
                               {{-0.3554, 0.4275}, {-0.0665, 0.0008}, {-0.0950, 0.0092}},
                               {{-0.0227, 5.3251}, {-0.0004, 0.2125}, {-0.0079, 0.2102}},
                               {{0.1206, -2.5771}, {-0.0641, -0.8989}, {-0.0441, -1.6537}},
                               {{-0.0670, 0.3703}, {-0.0033, 0.0452}, {-0.0109, 0.0529}}};
    double c[5][3];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 3; j++) {
            c[i][j] = k[i][j][0] * T + k[i][j][1];
            perez[i * 3 + j] = (float)c[i][j];
        }
    double t = theta_s, t2 = t * t, t3 = t2 * t, T2 = T * T;
    double chi = (4.0 / 9.0 - T / 120.0) * (WW_PI - 2.0 * t);
    double z[3];
    z[0] = (4.0453 * T - 4.9710) * tan(chi) - 0.2155 * T + 2.4192; /* kcd/m^2 */
    z[1] = T2 * (0.00166 * t3 - 0.00375 * t2 + 0.00209 * t) +
           T * (-0.02903 * t3 + 0.06377 * t2 - 0.03202 * t + 0.00394) +
           (0.11693 * t3 - 0.21196 * t2 + 0.06052 * t + 0.25886);
    z[2] = T2 * (0.00275 * t3 - 0.00610 * t2 + 0.00317 * t) +
           T * (-0.04214 * t3 + 0.08970 * t2 - 0.04153 * t + 0.00516) +
           (0.15346 * t3 - 0.26756 * t2 + 0.06670 * t + 0.26688);
    for (int j = 0; j < 3; j++) {
        /* F(0, theta_s): the zenith, where gamma is the sun's zenith angle */
        double f0 = (1.0 + c[0][j] * exp(c[1][j])) *
                    (1.0 + c[2][j] * exp(c[3][j] * t) + c[4][j] * cos(t) * cos(t));
        zen[j] = (float)(z[j] / f0);
    }
}

/* the sun the fit is evaluated for: its azimuth, at least PEREZ_MIN_ELEV high; returns the
 * elevation used */
static double perez_sun(const double s[3], double ps[3]) {
    double h = sqrt(s[0] * s[0] + s[2] * s[2]), e = asin(ww_m_clamp(s[1], -1.0, 1.0));
    if (e < PEREZ_MIN_ELEV) e = PEREZ_MIN_ELEV;
    ps[0] = h > 0.0 ? s[0] / h * cos(e) : 0.0;
    ps[1] = sin(e);
    ps[2] = h > 0.0 ? s[2] / h * cos(e) : 0.0;
    return e;
}

/* the haze along the horizon: Preetham's sky 2 degrees up averaged over the azimuths (what
 * common.glsl's ww_sky_physical gives there), blended with the clock's palette as the shader
 * blends the skies. The fog takes it, so far water and objects fade into the sky above them. */
static void horizon_colour(int physical, double turbidity, const ww_state *st, double out[3]) {
    for (int c = 0; c < 3; c++) out[c] = st->sky_horizon[c];
    double w = ww_m_smoothstep(PEREZ_FADE0, PEREZ_FADE1, st->sun_dir[1]);
    if (!physical || w <= 0.0) return;
    double ps[3];
    float perez[15], zen[3];
    double e = perez_sun(st->sun_dir, ps);
    perez_coeffs(turbidity, 0.5 * WW_PI - e, perez, zen);
    double rgb[3] = {0.0, 0.0, 0.0}, ct = sin(0.035), st_ = cos(0.035);
    enum { NAZ = 16 };
    for (int k = 0; k < NAZ; k++) {
        double a = 2.0 * WW_PI * (k + 0.5) / NAZ;
        double d[3] = {st_ * cos(a), ct, st_ * sin(a)};
        double cg = ww_m_clamp(d[0] * ps[0] + d[1] * ps[1] + d[2] * ps[2], -1.0, 1.0), g = acos(cg);
        double yxy[3];
        for (int j = 0; j < 3; j++)
            yxy[j] = zen[j] * (1.0 + perez[j] * exp(perez[3 + j] / ct)) *
                     (1.0 + perez[6 + j] * exp(perez[9 + j] * g) + perez[12 + j] * cg * cg);
        double Y = yxy[0] * PREETHAM_SCALE;
        double X = yxy[1] / yxy[2] * Y, Z = (1.0 - yxy[1] - yxy[2]) / yxy[2] * Y;
        rgb[0] += fmax(3.2406 * X - 1.5372 * Y - 0.4986 * Z, 0.0) / NAZ;
        rgb[1] += fmax(-0.9689 * X + 1.8758 * Y + 0.0415 * Z, 0.0) / NAZ;
        rgb[2] += fmax(0.0557 * X - 0.2040 * Y + 1.0570 * Z, 0.0) / NAZ;
    }
    for (int c = 0; c < 3; c++) out[c] += w * (rgb[c] - out[c]);
}

void ww_sky_horizon(const ww_scene *sc, const ww_state *st, double out[3]) {
    const ww_render_desc *d = &sc->render;
    if (ww_sky_dome_image_on(sc)) { /* the picture's own horizon (scene/compile_render.c) */
        for (int c = 0; c < 3; c++) out[c] = d->dome_horizon[c] * d->sky_intensity;
        return;
    }
    horizon_colour(d->sky == WW_SKY_PREETHAM || d->sky == WW_SKY_DOME, d->sky_turbidity, st, out);
}

/* the below-water fog's colour: fog.below.color is what in-scattered daylight gives the water;
 * the light that scatters there falls with the light entering the water, the sky's ambient plus
 * the sun's vertical part (by luma). Against the same for the sun FOG_BELOW_REF_ELEV high, at
 * most 1: the scene's colour by day, dimming through dusk to the night sky's level, so a lake at
 * night is dark under water too instead of glowing teal around a seabed the night has darkened */
#define FOG_BELOW_REF_ELEV 5.0 /* deg: from sunset on it dims, to a fortieth an hour later */
static double light_into_water(const double sun[3], const double sun_dir[3], const double amb[3]) {
    double l_sun = 0.2126 * sun[0] + 0.7152 * sun[1] + 0.0722 * sun[2];
    double l_amb = 0.2126 * amb[0] + 0.7152 * amb[1] + 0.0722 * amb[2];
    return l_amb + l_sun * fmax(sun_dir[1], 0.0);
}

void ww_fog_below_color(const ww_scene *sc, const ww_state *st, double out[3]) {
    double e = ww_m_rad(FOG_BELOW_REF_ELEV), dir[3] = {0.0, sin(e), -cos(e)};
    double sun[3], zenith[3], horizon[3], amb[3];
    ww_sky_colors(dir, sun, zenith, horizon, amb);
    double ref = light_into_water(sun, dir, amb);
    double k = fmin(1.0, light_into_water(st->sun_color, st->sun_dir, st->ambient) / ref);
    for (int c = 0; c < 3; c++) out[c] = sc->render.fog_below_color[c] * k;
}

const char *ww_sky_defines(const ww_scene *sc) {
    static const char *const defs[2][2] = {
        {"#define WW_CLOUDS 0\n", "#define WW_CLOUDS 1\n"},
        {"#define WW_SKY_MAP 1\n#define WW_CLOUDS 0\n", "#define WW_SKY_MAP 1\n#define WW_CLOUDS 1\n"}};
    return defs[ww_sky_map_on(sc) != 0][sc->render.cloud_cover > 0.0];
}

void ww_sky_locs_set(const ww_gl *gl, const ww_sky_locs *l, const ww_state *st) {
    /* the map itself stays bound to its unit from the skymap pass on */
    if (l->sky_map >= 0) gl->Uniform1i(l->sky_map, WW_TEX_SKY_MAP);
    double hz[3];
    horizon_colour(l->physical, l->turbidity, st, hz);
    gl->Uniform3f(l->zenith, (float)st->sky_zenith[0], (float)st->sky_zenith[1],
                  (float)st->sky_zenith[2]);
    gl->Uniform3f(l->horizon, (float)hz[0], (float)hz[1], (float)hz[2]);
    gl->Uniform3f(l->sun_dir, (float)st->sun_dir[0], (float)st->sun_dir[1], (float)st->sun_dir[2]);
    gl->Uniform3f(l->sun_color, (float)st->sun_color[0], (float)st->sun_color[1],
                  (float)st->sun_color[2]);
    if (!l->physical) {
        gl->Uniform2f(l->mode, 0.0f, 0.0f);
        gl->Uniform4f(l->clouds, 0.0f, 0.0f, 0.0f, 0.0f);
        return;
    }
    const double *s = st->sun_dir;
    double ps[3];
    double e = perez_sun(s, ps);
    float perez[15], zen[3];
    perez_coeffs(l->turbidity, 0.5 * WW_PI - e, perez, zen);
    gl->Uniform3fv(l->perez, 5, perez);
    gl->Uniform3f(l->zen, zen[0], zen[1], zen[2]);
    gl->Uniform3f(l->psun, (float)ps[0], (float)ps[1], (float)ps[2]);
    /* the share of Preetham's sky: whole by day, none once the sun is a little below the
     * horizon, where the twilight and night palette takes over */
    gl->Uniform2f(l->mode, 1.0f, (float)ww_m_smoothstep(PEREZ_FADE0, PEREZ_FADE1, s[1]));
    /* clouds: the drift of the dome's wind times sky.clouds.speed, from the seed's start,
     * wrapped to the noise period in double */
    double x = fmod(l->origin[0] + l->speed * DOME_WIND[0] * st->t, DOME_PERIOD);
    double z = fmod(l->origin[1] + l->speed * DOME_WIND[1] * st->t, DOME_PERIOD);
    gl->Uniform4f(l->clouds, (float)l->cover, (float)(x < 0.0 ? x + DOME_PERIOD : x),
                  (float)(z < 0.0 ? z + DOME_PERIOD : z), 0.0f);
}

/* the six faces, +x -x +y -y +z -z in GL's order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), each
 * uploaded top row first as stored: GL's convention puts t = 0 at the face's top (-y up in
 * texture space for the side faces), so the images need no flip. Seamless filtering blends
 * across face edges; the mip chain keeps the sky from shimmering where it is minified. */
static ww_result upload_cubemap(const ww_gl *gl, const ww_scene *sc, GLuint *out, ww_error *err) {
    const ww_render_desc *d = &sc->render;
    if (!sc->assets)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "sky: cubemap faces were not loaded");
    GLuint tex;
    gl->GenTextures(1, &tex);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* decoded here, one face at a time, and freed once uploaded: the scene holds only the
     * faces' sizes, so commands that draw nothing never decode them */
    for (int i = 0; i < 6; i++) {
        WW_ASSERT(d->cubemap_image[i] >= 0 && d->cubemap_image[i] < sc->assets->nimage);
        const ww_image_data *im = &sc->assets->image[d->cubemap_image[i]];
        unsigned char *rgba = NULL;
        ww_result r = ww_assets_decode(im, &rgba, err);
        if (r) {
            gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
            gl->DeleteTextures(1, &tex);
            return r;
        }
        gl->TexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)i, 0, GL_SRGB8_ALPHA8, im->width,
                       im->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        ww_assets_pixels_free(rgba);
    }
    gl->GenerateMipmap(GL_TEXTURE_CUBE_MAP);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
    gl->Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    *out = tex;
    return WW_OK;
}

int ww_sky_dome_image_on(const ww_scene *sc) {
    return sc->render.sky == WW_SKY_DOME && sc->render.dome_image >= 0;
}

/* the dome's picture as a mipmapped sRGB 2D texture, clamped at its edges (the horizon's ring
 * lies inside them), decoded here and freed once uploaded */
static ww_result upload_dome_image(const ww_gl *gl, const ww_scene *sc, GLuint *out,
                                   ww_error *err) {
    const ww_render_desc *d = &sc->render;
    if (!sc->assets || d->dome_image < 0 || d->dome_image >= sc->assets->nimage)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "sky: the dome's image was not loaded");
    const ww_image_data *im = &sc->assets->image[d->dome_image];
    unsigned char *rgba = NULL;
    ww_result r = ww_assets_decode(im, &rgba, err);
    if (r) return r;
    GLuint tex;
    gl->GenTextures(1, &tex);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, im->width, im->height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, rgba);
    ww_assets_pixels_free(rgba);
    gl->GenerateMipmap(GL_TEXTURE_2D);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    *out = tex;
    return WW_OK;
}

/* builds the program for the camera's side `below` and finds its uniforms */
static ww_result build_variant(ww_sky *s, const ww_gl *gl, const ww_scene *sc, int below,
                               ww_error *err) {
    static const char *const includes[] = {"common.glsl", NULL};
    sky_prog *v = &s->var[below];
    char defs[240];
    snprintf(defs, sizeof defs, "#define WW_SKY_BELOW %d\n%s", below, s->defines);
    ww_result rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "sky.frag.glsl", includes, defs,
                                       &v->prog, err);
    if (rc != WW_OK) return rc;
    v->dome_image = ww_gfx_uniform(gl, v->prog, "u_sky_dome_image");
    ww_sky_locs_init(gl, v->prog, sc, &v->sky);
    v->inv_view_proj = ww_gfx_uniform(gl, v->prog, "u_inv_view_proj");
    v->intensity = ww_gfx_uniform(gl, v->prog, "u_intensity");
    v->below = ww_gfx_uniform(gl, v->prog, "u_below");
    v->below_density = ww_gfx_uniform(gl, v->prog, "u_below_density");
    v->cubemap = ww_gfx_uniform(gl, v->prog, "u_cubemap");
    v->drift = ww_gfx_uniform(gl, v->prog, "u_drift");
    return WW_OK;
}

ww_result ww_sky_new(ww_renderer *r, const ww_scene *sc, ww_sky **out, ww_error *err) {
    static const char *const defines[] = {[WW_SKY_GRADIENT] = NULL,
                                          [WW_SKY_CUBEMAP] = "#define WW_SKY_CUBEMAP 1\n",
                                          [WW_SKY_DOME] = "#define WW_SKY_DOME 1\n",
                                          [WW_SKY_PREETHAM] = NULL};
    const ww_gl *gl = r->gl;
    ww_sky *s = calloc(1, sizeof *s);
    if (!s) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "sky: out of memory");
    s->model = sc->render.sky;
    s->r = r;
    s->scatter = ww_lights_scatter_on(sc);
    snprintf(s->defines, sizeof s->defines,
             "%s#define WW_LIGHT_SCATTER %d\n#define WW_NLIGHTS %d\n#define WW_SKY_DOME_IMAGE %d\n%s",
             defines[s->model] ? defines[s->model] : "", s->scatter, sc->render.nlights,
             ww_sky_dome_image_on(sc), ww_sky_defines(sc));
    /* the side most frames see is built now, so a broken shader fails before the first frame */
    ww_result rc = build_variant(s, gl, sc, 0, err);
    /* one cube texture per renderer: a second sky (the reflection's) draws the first one's */
    if (rc == WW_OK && s->model == WW_SKY_CUBEMAP) {
        if (r->sky_cubemap) {
            s->cube_draw = r->sky_cubemap;
        } else {
            rc = upload_cubemap(gl, sc, &s->cube_tex, err);
            s->cube_draw = r->sky_cubemap = s->cube_tex;
        }
    }
    /* one picture per renderer, as the cube texture */
    if (rc == WW_OK && ww_sky_dome_image_on(sc)) {
        if (r->sky_dome_image) {
            s->dome_draw = r->sky_dome_image;
        } else {
            rc = upload_dome_image(gl, sc, &s->dome_tex, err);
            s->dome_draw = r->sky_dome_image = s->dome_tex;
        }
    }
    if (rc != WW_OK) {
        ww_sky_free(s, gl);
        return rc;
    }
    *out = s;
    return WW_OK;
}

ww_result ww_sky_draw(ww_sky *s, const ww_gl *gl, GLuint empty_vao, const ww_frame *f,
                      ww_error *err) {
    int below = f->underwater != 0;
    if (!s->var[below].prog) {
        ww_result rc = build_variant(s, gl, f->sc, below, err);
        if (rc != WW_OK) return rc;
    }
    const sky_prog *v = &s->var[below];
    /* the triangle lies on the far plane: it passes where the depth is still clear */
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LEQUAL);
    gl->DepthMask(GL_FALSE);
    gl->UseProgram(v->prog);
    ww_sky_locs_set(gl, &v->sky, f->st);
    gl->UniformMatrix4fv(v->inv_view_proj, 1, GL_FALSE, (const GLfloat *)f->inv_view_proj);
    gl->Uniform1f(v->intensity, (float)f->sc->render.sky_intensity);
    double fb[3];
    ww_fog_below_color(f->sc, f->st, fb);
    gl->Uniform4f(v->below, (float)fb[0], (float)fb[1], (float)fb[2], f->underwater ? 1.0f : 0.0f);
    if (s->scatter && f->underwater) {
        /* the lights' glow along the rays that meet nothing under water */
        gl->Uniform1f(v->below_density, (float)f->sc->render.fog_below_density);
        ww_geometry_lights_set(s->r->geometry, gl, f, v->prog);
    }
    if (s->model == WW_SKY_CUBEMAP) {
        gl->ActiveTexture(GL_TEXTURE0);
        gl->BindTexture(GL_TEXTURE_CUBE_MAP, s->cube_draw);
        gl->Uniform1i(v->cubemap, 0);
    } else if (s->dome_draw) {
        gl->ActiveTexture(GL_TEXTURE0);
        gl->BindTexture(GL_TEXTURE_2D, s->dome_draw);
        gl->Uniform1i(v->dome_image, 0);
    } else if (s->model == WW_SKY_DOME) {
        double x = fmod(DOME_WIND[0] * f->st->t, DOME_PERIOD);
        double z = fmod(DOME_WIND[1] * f->st->t, DOME_PERIOD);
        gl->Uniform2f(v->drift, (float)(x < 0.0 ? x + DOME_PERIOD : x),
                      (float)(z < 0.0 ? z + DOME_PERIOD : z));
    }
    gl->BindVertexArray(empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->DepthMask(GL_TRUE);
    gl->DepthFunc(GL_LESS);
    if (s->model == WW_SKY_CUBEMAP) gl->BindTexture(GL_TEXTURE_CUBE_MAP, 0);
    if (s->dome_draw) gl->BindTexture(GL_TEXTURE_2D, 0);
    return WW_OK;
}

void ww_sky_free(ww_sky *s, const ww_gl *gl) {
    if (!s) return;
    for (int i = 0; i < 2; i++)
        if (s->var[i].prog) gl->DeleteProgram(s->var[i].prog);
    if (s->cube_tex) gl->DeleteTextures(1, &s->cube_tex);
    if (s->dome_tex) gl->DeleteTextures(1, &s->dome_tex);
    free(s);
}
