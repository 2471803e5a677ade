/* render_impl.h - the renderer's insides, shared by the files of src/gfx (private).
 *
 * A pass is a small object with create / run / destroy (ww_pass_ops), listed in one table
 * indexed by ww_pass_id (renderer.c). Adding a pass is adding a pass_xxx.c with its ops and one
 * table entry. renderer.c makes each planned pass's targets (targets.c) before any pass is
 * created, so a pass can look up the outputs of the passes it reads (ww_renderer_output).
 * Each frame renderer.c computes the camera once (ww_frame) and runs the passes in plan order.
 *
 * Drawing is camera-relative: the view matrix holds the camera's rotation only and every pass
 * sends positions minus the camera position, so float stays exact 1e5 m from the origin.
 */
#ifndef WW_RENDER_IMPL_H
#define WW_RENDER_IMPL_H

#include <cglm/cglm.h>

#include "gfx/renderer.h"

/* the framebuffer of one pass and its attachments, in the order of the pass's targets */
typedef struct ww_rt {
    GLuint fbo;
    int width, height;
    int ntex;
    GLuint tex[WW_PLAN_MAX_TARGETS];
    ww_format fmt[WW_PLAN_MAX_TARGETS];
} ww_rt;

/* what every pass needs to draw one frame */
typedef struct ww_frame {
    const ww_scene *sc;
    const ww_state *st;
    double cam_pos[3];  /* world, m */
    mat4 view;          /* camera rotation only (the camera sits at the origin) */
    mat4 proj;          /* perspective: state fov, target aspect, scene near/far */
    mat4 view_proj;     /* proj * view */
    mat4 inv_view_proj; /* for per-pixel view rays */
    float pixel_angle;  /* angle one pixel spans at the image centre, rad */
    double fwd[3], right[3], up[3]; /* camera basis, world, unit */
    double tan_half[2]; /* tangent of half the horizontal and vertical field of view */
} ww_frame;

typedef struct ww_pass_ops {
    /* build programs and meshes; rt is the pass's own targets, already made, and stays valid
     * (a pass keeps the pointer) until destroy */
    ww_result (*create)(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                        const ww_rt *rt, void **self, ww_error *err);
    ww_result (*run)(void *self, ww_renderer *r, const ww_frame *f, ww_error *err);
    void (*destroy)(void *self, const ww_gl *gl);
} ww_pass_ops;

extern const ww_pass_ops ww_pass_main_ops;    /* pass_main.c */
extern const ww_pass_ops ww_pass_tonemap_ops; /* pass_tonemap.c */

typedef struct ww_pass {
    ww_pass_id id;
    const ww_pass_ops *ops;
    void *self;
    ww_rt rt;
} ww_pass;

struct ww_renderer {
    const ww_gl *gl;
    int npasses;
    ww_pass passes[WW_PASS_COUNT];
    GLuint empty_vao; /* full-screen triangles take their corners from gl_VertexID */
};

/* renderer.c: the targets of pass `id`, or NULL when the plan has no such pass */
const ww_rt *ww_renderer_output(const ww_renderer *r, ww_pass_id id);
/* renderer.c: the state every pass starts from: its framebuffer bound, viewport, no blending,
 * culling, dithering or depth test */
void ww_gfx_begin_pass(const ww_gl *gl, const ww_rt *rt);

/* targets.c: textures and a framebuffer for a pass description; WW_E_GL when incomplete */
ww_result ww_gfx_rt_create(const ww_gl *gl, const ww_pass_desc *d, ww_rt *rt, ww_error *err);
void ww_gfx_rt_destroy(const ww_gl *gl, ww_rt *rt);
/* the first attachment of format fmt, 0 when there is none */
GLuint ww_gfx_rt_texture(const ww_rt *rt, ww_format fmt);

/* program.c: vertex + fragment shader files with includes (NULL-terminated list, prepended in
 * order after #version; may be NULL); WW_E_GL names the file and carries the info log */
ww_result ww_gfx_program(const ww_gl *gl, const char *vs, const char *fs,
                         const char *const *includes, GLuint *out, ww_error *err);
GLint ww_gfx_uniform(const ww_gl *gl, GLuint prog, const char *name);

/* sky.c: the uniforms of common.glsl (sky gradient and sun), for any program that includes it */
typedef struct ww_sky_locs {
    GLint zenith, horizon, sun_dir, sun_color;
} ww_sky_locs;
void ww_sky_locs_init(const ww_gl *gl, GLuint prog, ww_sky_locs *l);
void ww_sky_locs_set(const ww_gl *gl, const ww_sky_locs *l, const ww_state *st);

/* sky.c: the gradient sky and sun disc as a full-screen triangle, depth test off */
typedef struct ww_sky ww_sky;
ww_result ww_sky_new(const ww_gl *gl, ww_sky **out, ww_error *err);
void ww_sky_draw(const ww_sky *s, const ww_gl *gl, GLuint empty_vao, const ww_frame *f);
void ww_sky_free(ww_sky *s, const ww_gl *gl);

/* water.c: the camera-centred polar Gerstner mesh, depth tested */
typedef struct ww_water ww_water;
ww_result ww_water_new(const ww_gl *gl, const ww_scene *sc, ww_water **out, ww_error *err);
void ww_water_draw(const ww_water *w, const ww_gl *gl, const ww_frame *f);
void ww_water_free(ww_water *w, const ww_gl *gl);

#endif
