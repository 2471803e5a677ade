/* pass_shadow.c - the sun's shadow map (seed 000's directional shadow): the casters' depth seen
 * orthographically from the sun, fitted to the part of the view frustum within
 * render.shadows.distance. The map covers the slice's bounding sphere, so its size does not
 * change as the camera turns, and its centre moves in whole texels across the sun's view, so
 * shadow edges do not shimmer as the camera moves (Valient, "Stable Rendering of Cascaded Shadow
 * Maps", ShaderX6, 2008). Depth with polygon offset; the texture compares in hardware
 * (sampler2DShadow, shaders/shadow.glsl). Publishes r->shared.sun_view_proj (camera-relative)
 * and r->shared.shadow_map.
 */
#include <math.h>
#include <stdlib.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"

#define CASTER_MARGIN 40.0   /* m: casters this far beyond the sphere toward the sun still cast */
#define OFFSET_FACTOR 2.0f   /* glPolygonOffset: slope-scaled depth bias */
#define OFFSET_UNITS 4.0f    /* and constant bias, in depth units */

typedef struct shadow_pass {
    const ww_rt *rt;
    GLuint depth;
    int size;
} shadow_pass;

static void shadow_destroy(void *self, const ww_gl *gl) {
    (void)gl;
    free(self);
}

static ww_result shadow_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                               const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    const ww_gl *gl = r->gl;
    GLuint depth = ww_gfx_rt_texture(rt, WW_FMT_DEPTH24);
    if (!depth)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "pass %s: needs a DEPTH24 target", d->name);
    shadow_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "shadow pass: out of memory");
    p->rt = rt;
    p->depth = depth;
    p->size = rt->width;
    /* hardware depth compare with bilinear weights: each tap is a 2x2 PCF */
    gl->BindTexture(GL_TEXTURE_2D, depth);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    *self = p;
    return WW_OK;
}

/* the sunlight's direction under a level surface (toward the sun, unit): Snell's refraction of
 * the sun's ray into water; (0, 0, 0) when the sun is not above the horizon */
#define WATER_IOR 1.333
void ww_sun_in_water(const double sun[3], double out[3]) {
    double a[3] = {sun[0], sun[1], sun[2]};
    ww_m_normalize3(a);
    out[0] = out[1] = out[2] = 0.0;
    if (!(a[1] > 0.0)) return;
    double eta = 1.0 / WATER_IOR, k = 1.0 - eta * eta * (1.0 - a[1] * a[1]);
    /* the transmitted ray t = eta d + (eta cos_i - sqrt(k)) n, d = -a, n = +y; out = -t */
    out[0] = eta * a[0];
    out[1] = sqrt(k);
    out[2] = eta * a[2];
}

/* the sun's view-projection for this frame, camera-relative; texel size in m */
static void fit(const ww_frame *f, int size, double shadow_distance, mat4 out) {
    const ww_scene *sc = f->sc;
    const double *sun = f->st->sun_dir;
    /* the frustum slice [near, far] and its bounding sphere: centre c along the view axis where
     * the near and far corner rings are equally far, at most at far */
    double n = sc->near_clip, fd = fmin(shadow_distance, sc->far_clip);
    double k2 = f->tan_half[0] * f->tan_half[0] + f->tan_half[1] * f->tan_half[1];
    double c = 0.5 * (fd + n) * (1.0 + k2);
    if (c > fd) c = fd;
    double R = sqrt((fd - c) * (fd - c) + fd * fd * k2);

    /* light basis: z toward the sun, x = up x z, y = z x x (glm_lookat's) */
    double z[3] = {sun[0], sun[1], sun[2]}, up[3] = {0.0, 1.0, 0.0};
    ww_m_normalize3(z);
    if (fabs(z[1]) > 0.99) {
        up[1] = 0.0;
        up[2] = 1.0;
    }
    double x[3] = {up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2],
                   up[0] * z[1] - up[1] * z[0]};
    ww_m_normalize3(x);
    double y[3] = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]};

    /* the sphere's centre in world (double), snapped to whole texels across the sun's view */
    double centre[3], texel = 2.0 * R / size;
    for (int i = 0; i < 3; i++) centre[i] = f->cam_pos[i] + f->fwd[i] * c;
    double cx = ww_m_dot3(centre, x), cy = ww_m_dot3(centre, y);
    double dx = texel * floor(cx / texel) - cx, dy = texel * floor(cy / texel) - cy;
    for (int i = 0; i < 3; i++) centre[i] += dx * x[i] + dy * y[i];

    /* eye on the sun's side of the sphere, everything camera-relative */
    vec3 eye, at, upv = {(float)y[0], (float)y[1], (float)y[2]};
    double back = R + CASTER_MARGIN;
    for (int i = 0; i < 3; i++) {
        at[i] = (float)(centre[i] - f->cam_pos[i]);
        eye[i] = (float)(centre[i] - f->cam_pos[i] + back * z[i]);
    }
    mat4 view, proj;
    glm_lookat(eye, at, upv, view);
    glm_ortho((float)-R, (float)R, (float)-R, (float)R, 0.0f, (float)(back + R), proj);
    glm_mat4_mul(proj, view, out);
}

static ww_result shadow_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    shadow_pass *p = self;
    const ww_gl *gl = r->gl;
    fit(f, p->size, f->sc->render.shadows.distance, r->shared.sun_view_proj);
    ww_gfx_begin_pass(gl, p->rt);
    gl->ClearDepth(1.0);
    gl->DepthMask(GL_TRUE);
    gl->Clear(GL_DEPTH_BUFFER_BIT);
    gl->Enable(GL_POLYGON_OFFSET_FILL);
    gl->PolygonOffset(OFFSET_FACTOR, OFFSET_UNITS);
    if (r->geometry)
        ww_geometry_draw(r->geometry, r, f, WW_GEOM_SHADOW, r->shared.sun_view_proj, NULL);
    gl->Disable(GL_POLYGON_OFFSET_FILL);
    r->shared.shadow_map = p->depth;
    return WW_OK;
}

const ww_pass_ops ww_pass_shadow_ops = {shadow_create, shadow_run, shadow_destroy};
