/* pass_shafts.c - light shafts (seed 000, after Mitchell, GPU Gems 3 ch. 13): projects the light
 * to the screen, then one full-screen pass into the shafts target (render.god_rays.scale of the
 * frame) marches from each pixel toward it over an occlusion mask built from the main pass's
 * depth and colour (shafts.frag.glsl). The mask is drawn first, so the march reads one bilinear
 * texel per sample, and the march's jitter is smoothed last: mask into the `shafts` target, the
 * march into `march`, the smoothing back into `shafts`, which the tone mapping pass adds.
 * Above water the light is the sun and the mask the sky around it; under water it is the sun
 * refracted into the water (Snell, n = 1.333) and the mask the lit surface seen from below,
 * with exposure x render.god_rays.underwater. The shafts fade out as the light goes behind the
 * camera and, above water, as the sun leaves the screen (nothing on screen would glow).
 */
#include <math.h>
#include <stdlib.h>

#include "gfx/render_impl.h"

#define SHAFT_WATER_IOR 1.333      /* refractive index of water */
#define SHAFT_BEHIND_COS0 0.0      /* fade by the cosine between forward and the light: 0 here */
#define SHAFT_BEHIND_COS1 0.3      /*   full from here */
#define SHAFT_OFFSCREEN0 1.2       /* above water: fade by the light's NDC distance from the centre */
#define SHAFT_OFFSCREEN1 2.5
#define SHAFT_PATTERN_PERIOD 64.0  /* m: shafts.frag.glsl's caustic pattern tiles this often */
static const double SHAFT_PATTERN_RATE[3] = {0.9, -0.7, 0.5}; /* its phase speeds, rad/s */

/* the uniforms of one of the two programs (-1 where it has none) */
typedef struct shaft_locs {
    GLint mask, depth, hdr, light_uv, light_dir, light_color, ray00, ray_dx, ray_dy, samples,
        decay, density, weight, exposure, underwater, inv_size, surface_up, cam_xz, phase;
} shaft_locs;

/* the programs in the order they run; each reads what the one before drew */
enum { SHAFT_MASK = 0, SHAFT_MARCH = 1, SHAFT_SMOOTH = 2, SHAFT_NPROGS };
/* the targets: the shafts (what the tone mapping reads) and the second one */
enum { SHAFT_OUT = 0, SHAFT_TMP = 1 };
/* where each program draws: mask and smoothing into the shafts target, the march between */
static const int SHAFT_DRAWS_INTO[SHAFT_NPROGS] = {SHAFT_OUT, SHAFT_TMP, SHAFT_OUT};

typedef struct shafts_pass {
    const ww_rt *rt;
    GLuint depth_tex, hdr_tex;
    GLuint prog[SHAFT_NPROGS];
    shaft_locs loc[SHAFT_NPROGS];
    GLuint fbo[2]; /* one a target */
    GLuint tex[2];
} shafts_pass;

static void shafts_destroy(void *self, const ww_gl *gl) {
    shafts_pass *p = self;
    if (!p) return;
    for (int i = 0; i < SHAFT_NPROGS; i++)
        if (p->prog[i]) gl->DeleteProgram(p->prog[i]);
    for (int i = 0; i < 2; i++)
        if (p->fbo[i]) gl->DeleteFramebuffers(1, &p->fbo[i]);
    free(p);
}

static void shaft_locs_init(const ww_gl *gl, GLuint g, shaft_locs *l) {
    l->mask = ww_gfx_uniform(gl, g, "u_mask");
    l->depth = ww_gfx_uniform(gl, g, "u_depth");
    l->hdr = ww_gfx_uniform(gl, g, "u_hdr");
    l->light_uv = ww_gfx_uniform(gl, g, "u_light_uv");
    l->light_dir = ww_gfx_uniform(gl, g, "u_light_dir");
    l->light_color = ww_gfx_uniform(gl, g, "u_light_color");
    l->ray00 = ww_gfx_uniform(gl, g, "u_ray00");
    l->ray_dx = ww_gfx_uniform(gl, g, "u_ray_dx");
    l->ray_dy = ww_gfx_uniform(gl, g, "u_ray_dy");
    l->samples = ww_gfx_uniform(gl, g, "u_samples");
    l->decay = ww_gfx_uniform(gl, g, "u_decay");
    l->density = ww_gfx_uniform(gl, g, "u_density");
    l->weight = ww_gfx_uniform(gl, g, "u_weight");
    l->exposure = ww_gfx_uniform(gl, g, "u_exposure");
    l->underwater = ww_gfx_uniform(gl, g, "u_underwater");
    l->inv_size = ww_gfx_uniform(gl, g, "u_inv_size");
    l->surface_up = ww_gfx_uniform(gl, g, "u_surface_up");
    l->cam_xz = ww_gfx_uniform(gl, g, "u_cam_xz");
    l->phase = ww_gfx_uniform(gl, g, "u_phase");
}

static ww_result shafts_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                               const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    const ww_gl *gl = r->gl;
    const ww_rt *in = ww_renderer_output(r, WW_PASS_MAIN);
    GLuint hdr = in ? ww_gfx_rt_texture(in, WW_FMT_RGBA16F) : 0;
    GLuint depth = in ? ww_gfx_rt_depth(in) : 0;
    if (!hdr || !depth || rt->ntex != 2 || rt->fmt[0] != WW_FMT_RGBA16F ||
        rt->fmt[1] != WW_FMT_RGBA16F)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "pass %s: needs the main pass's colour and depth and two RGBA16F "
                            "targets (shafts, march)", d->name);
    shafts_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "shafts pass: out of memory");
    p->rt = rt;
    p->hdr_tex = hdr;
    p->depth_tex = depth;
    /* both read bilinearly (the march, the smoothing, the tone mapping's upsample); a
     * framebuffer each */
    p->tex[SHAFT_OUT] = rt->tex[0];
    p->tex[SHAFT_TMP] = rt->tex[1];
    for (int i = 0; i < 2; i++) {
        ww_result frc = ww_gfx_fbo_single(gl, p->tex[i], d->name, i, &p->fbo[i], err);
        if (frc != WW_OK) {
            shafts_destroy(p, gl);
            return frc;
        }
    }
    ww_result rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "shafts.frag.glsl", NULL,
                                       "#define MASK 1\n", &p->prog[SHAFT_MASK], err);
    if (rc == WW_OK)
        rc = ww_gfx_program(gl, "fullscreen.vert.glsl", "shafts.frag.glsl", NULL,
                            &p->prog[SHAFT_MARCH], err);
    if (rc == WW_OK)
        rc = ww_gfx_program_defs(gl, "fullscreen.vert.glsl", "shafts.frag.glsl", NULL,
                                 "#define SMOOTH 1\n", &p->prog[SHAFT_SMOOTH], err);
    if (rc != WW_OK) {
        shafts_destroy(p, gl);
        return rc;
    }
    for (int i = 0; i < SHAFT_NPROGS; i++) shaft_locs_init(gl, p->prog[i], &p->loc[i]);
    *self = p;
    return WW_OK;
}

static double smooth01(double e0, double e1, double x) {
    double t = (x - e0) / (e1 - e0);
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return t * t * (3.0 - 2.0 * t);
}

/* the direction light arrives from under a flat surface: Snell's law on the sun's zenith angle,
 * sin(theta_w) = sin(theta_a) / n, keeping its azimuth */
static void refracted_sun(const double s[3], double out[3]) {
    double h = sqrt(s[0] * s[0] + s[2] * s[2]);
    double hw = h / SHAFT_WATER_IOR;
    out[1] = sqrt(1.0 - hw * hw);
    out[0] = h > 0.0 ? s[0] / h * hw : 0.0;
    out[2] = h > 0.0 ? s[2] / h * hw : 0.0;
}

static ww_result shafts_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    shafts_pass *p = self;
    const ww_gl *gl = r->gl;
    const ww_shafts_desc *sd = &f->sc->render.shafts;
    const ww_state *st = f->st;
    ww_gfx_begin_pass(gl, p->rt);
    gl->BindFramebuffer(GL_FRAMEBUFFER, p->fbo[SHAFT_OUT]);
    gl->ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl->Clear(GL_COLOR_BUFFER_BIT);

    /* the light: the sun, or under water the sun refracted through the surface */
    double L[3] = {st->sun_dir[0], st->sun_dir[1], st->sun_dir[2]};
    double exposure = sd->exposure;
    if (f->underwater) {
        refracted_sun(st->sun_dir, L);
        exposure *= sd->underwater;
    }
    if (st->sun_dir[1] <= 0.0) return WW_OK; /* below the horizon: no light to scatter */

    /* project it: a direction is a point at infinity (w = 0) in camera-relative coordinates */
    vec4 dir = {(float)L[0], (float)L[1], (float)L[2], 0.0f}, clip;
    glm_mat4_mulv((vec4 *)f->view_proj, dir, clip);
    double facing = L[0] * f->fwd[0] + L[1] * f->fwd[1] + L[2] * f->fwd[2];
    double fade = smooth01(SHAFT_BEHIND_COS0, SHAFT_BEHIND_COS1, facing);
    if (fade <= 0.0 || clip[3] <= 0.0f) return WW_OK;
    double nx = clip[0] / clip[3], ny = clip[1] / clip[3];
    if (!f->underwater) {
        double e = fmax(fabs(nx), fabs(ny));
        fade *= 1.0 - smooth01(SHAFT_OFFSCREEN0, SHAFT_OFFSCREEN1, e);
        if (fade <= 0.0) return WW_OK;
    }

    /* view rays across the screen: fwd + (2u - 1) tan_x right + (2v - 1) tan_y up */
    float r00[3], rdx[3], rdy[3];
    for (int i = 0; i < 3; i++) {
        double ax = f->tan_half[0] * f->right[i], ay = f->tan_half[1] * f->up[i];
        r00[i] = (float)(f->fwd[i] - ax - ay);
        rdx[i] = (float)(2.0 * ax);
        rdy[i] = (float)(2.0 * ay);
    }

    /* the caustic pattern in double: camera wrapped to its period, phases wrapped to 2 pi */
    double level = f->sc->water_level - f->cam_pos[1];
    double tau = 2.0 * 3.14159265358979323846;
    float phase[3];
    for (int i = 0; i < 3; i++) phase[i] = (float)fmod(SHAFT_PATTERN_RATE[i] * st->t, tau);

    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindTexture(GL_TEXTURE_2D, p->depth_tex);
    gl->ActiveTexture(GL_TEXTURE1);
    gl->BindTexture(GL_TEXTURE_2D, p->hdr_tex);
    gl->ActiveTexture(GL_TEXTURE2);
    gl->BindVertexArray(r->empty_vao);
    for (int i = 0; i < SHAFT_NPROGS; i++) {
        const shaft_locs *l = &p->loc[i];
        /* unit 2 holds what the program before drew (none for the mask), never the target
         * being drawn */
        gl->BindTexture(GL_TEXTURE_2D, i > 0 ? p->tex[SHAFT_DRAWS_INTO[i - 1]] : 0);
        gl->BindFramebuffer(GL_FRAMEBUFFER, p->fbo[SHAFT_DRAWS_INTO[i]]);
        gl->UseProgram(p->prog[i]);
        gl->Uniform1i(l->depth, 0);
        gl->Uniform1i(l->hdr, 1);
        gl->Uniform1i(l->mask, 2);
        gl->Uniform2f(l->light_uv, (float)(0.5 * nx + 0.5), (float)(0.5 * ny + 0.5));
        gl->Uniform3f(l->light_dir, (float)L[0], (float)L[1], (float)L[2]);
        gl->Uniform3f(l->light_color, (float)st->sun_color[0], (float)st->sun_color[1],
                      (float)st->sun_color[2]);
        gl->Uniform3fv(l->ray00, 1, r00);
        gl->Uniform3fv(l->ray_dx, 1, rdx);
        gl->Uniform3fv(l->ray_dy, 1, rdy);
        gl->Uniform1i(l->samples, sd->samples);
        gl->Uniform1f(l->decay, (float)sd->decay);
        gl->Uniform1f(l->density, (float)sd->density);
        gl->Uniform1f(l->weight, (float)sd->weight);
        gl->Uniform1f(l->exposure, (float)(exposure * fade));
        gl->Uniform1i(l->underwater, f->underwater);
        gl->Uniform2f(l->inv_size, 1.0f / (float)p->rt->width, 1.0f / (float)p->rt->height);
        gl->Uniform1f(l->surface_up, (float)(level > 0.0 ? level : 0.0));
        gl->Uniform2f(l->cam_xz, (float)fmod(f->cam_pos[0], SHAFT_PATTERN_PERIOD),
                      (float)fmod(f->cam_pos[2], SHAFT_PATTERN_PERIOD));
        gl->Uniform3fv(l->phase, 1, phase);
        gl->DrawArrays(GL_TRIANGLES, 0, 3);
    }
    for (int u = 2; u >= 0; u--) {
        gl->ActiveTexture(GL_TEXTURE0 + (GLenum)u);
        gl->BindTexture(GL_TEXTURE_2D, 0);
    }
    return WW_OK;
}

const ww_pass_ops ww_pass_shafts_ops = {shafts_create, shafts_run, shafts_destroy};
