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

#include <stddef.h>
#include <stdint.h>

#include <cglm/cglm.h>

#include "gfx/renderer.h"
#include "scene/assets.h"

/* the framebuffer of one pass and its attachments, in the order of the pass's targets */
typedef struct ww_rt {
    GLuint fbo;
    int width, height;
    int ntex;
    GLuint tex[WW_PLAN_MAX_TARGETS];
    ww_format fmt[WW_PLAN_MAX_TARGETS];
    int unattached[WW_PLAN_MAX_TARGETS]; /* 1: not in fbo (the plan's unattached targets) */
    /* post: the multisampled targets (samples > 1) as renderbuffers of a second framebuffer,
     * which the pass draws into and resolves into fbo (MSAA); fbo_ms 0 when there are none */
    GLuint fbo_ms;
    int nrb, samples;
    GLuint rb[WW_PLAN_MAX_TARGETS];
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
    double surface_y;   /* water surface height over the camera, world m (exact query) */
    int underwater;     /* the camera is below that surface */
    int64_t frame;      /* frames rendered by this renderer before this one */
    int width, height;  /* the main pass's targets (the frame's size), px */
} ww_frame;

/* what one pass leaves for later passes of the same frame (renderer.c clears it each frame) */
typedef struct ww_shared {
    mat4 sun_view_proj;  /* shadow pass: camera-relative world -> the shadow map's clip space */
    GLuint shadow_map;   /* its depth texture (compare mode on); 0 when there is no shadow pass */
    int reflection;      /* reflection pass drew this frame (0 under water or when absent) */
    GLuint reflection_tex; /* its mipmapped colour */
    /* its nearest-depth pyramid (R32F): level k holds the least window depth, as the camera
     * sees the mirror image, of each 2^(k+1) x 2^(k+1) texels of the colour; 0 without objects */
    GLuint reflection_near;
    int reflection_near_levels;
    GLuint reflection_depth; /* its depth target (read nearest); 0 without objects */
    GLuint scene_color, scene_depth; /* prepass: solid geometry under the water; 0 when absent */
    GLuint scene_depth_full; /* its depth at the frame's size, when the prepass is smaller; or 0 */
} ww_shared;

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
extern const ww_pass_ops ww_pass_skymap_ops;  /* pass_skymap.c */
extern const ww_pass_ops ww_pass_shadow_ops;  /* pass_shadow.c */
extern const ww_pass_ops ww_pass_prepass_ops; /* pass_prepass.c */
extern const ww_pass_ops ww_pass_reflection_ops; /* pass_reflection.c */
/* post: bloom, light shafts, FXAA, HUD */
extern const ww_pass_ops ww_pass_bloom_ops;   /* pass_bloom.c */
extern const ww_pass_ops ww_pass_shafts_ops;  /* pass_shafts.c */
extern const ww_pass_ops ww_pass_fxaa_ops;    /* pass_fxaa.c */
extern const ww_pass_ops ww_pass_upscale_ops; /* pass_upscale.c */
extern const ww_pass_ops ww_pass_hud_ops;     /* pass_hud.c */

/* pass_bloom.c: the blur of `passes` (render.bloom.passes) rounds of the 9-tap binomial kernel,
 * convolved into one kernel and read as bilinear fetches: the centre weight and offset 0, then
 * (weight, offset in texels) pairs each fetched on both sides; returns how many entries (n) it
 * filled, the weights summing to weight[0] + 2 (weight[1] + ... + weight[n - 1]) = 1. One pass
 * gives Rakos's 5 fetches (n = 3). The rounds are texels of a blur at half the frame's size;
 * at another `scale` (render.bloom.scale) the kernel is the Gaussian whose glow is as wide in
 * the frame, so the scale sets the blur's resolution, not the look. */
#define WW_BLOOM_MAX_FETCHES 16
int ww_bloom_kernel(int passes, double scale, float weight[WW_BLOOM_MAX_FETCHES],
                    float offset[WW_BLOOM_MAX_FETCHES]);

typedef struct ww_pass {
    ww_pass_id id;
    const ww_pass_ops *ops;
    void *self;
    ww_rt rt;
} ww_pass;

typedef struct ww_geometry ww_geometry;

/* per-pass timing (renderer.c, ww_renderer_time_passes; bench only): with GL timer queries, each
 * frame's queries go into one of WW_TIMER_RING slots and are read back only when that slot comes
 * round again (or when the caller asks, after glFinish), so timing never waits on the GPU;
 * without them, CPU wall time with glFinish before and after each pass */
#define WW_TIMER_RING 3
typedef struct ww_pass_timer {
    ww_timing mode;                              /* WW_TIMING_OFF, _GPU or _CPU */
    GLuint query[WW_TIMER_RING][WW_PASS_COUNT];  /* GL_TIME_ELAPSED, one per slot and pass */
    int pending[WW_TIMER_RING];                  /* the slot holds a frame not read back yet */
    double sum_ms[WW_PASS_COUNT];                /* per pass, over the frames collected */
    double frame_ms;                             /* CPU: the frames' wall time, glFinish to glFinish */
    int frames;                                  /* frames collected since the last read */
} ww_pass_timer;

struct ww_renderer {
    const ww_gl *gl;
    int npasses;
    ww_pass passes[WW_PASS_COUNT];
    GLuint empty_vao; /* full-screen triangles take their corners from gl_VertexID */
    ww_plan plan;     /* what the renderer was built from */
    ww_geometry *geometry; /* solid geometry shared by the passes that draw it; NULL: none */
    GLuint sky_dome_image; /* the dome's picture (sky.image), 2D sRGB, 0 none; as sky_cubemap */
    GLuint sky_cubemap; /* the sky's cubemap texture (sky.model cubemap), 0 otherwise; set
                         * when the pass drawing the sky is created, for the water to reflect */
    ww_shared shared; /* per frame, written by earlier passes for later ones */
    int64_t frames;   /* frames rendered so far */
    ww_pass_timer timer; /* off unless ww_renderer_time_passes */
    struct ww_stencil_shadows *stencil; /* render.shadows projected or volumes; NULL otherwise */
};

/* the reflection pass draws objects above the water (not only a seabed, which its clip plane
 * cuts away whole): it then leaves its depths for the water (ww_shared.reflection_near) */
static inline int ww_reflection_has_objects(const ww_renderer *r, const ww_scene *sc) {
    return r->geometry != NULL && ww_scene_has_objects(sc);
}

/* geometry.c: the scene's solid geometry (seabed, objects, models), its meshes uploaded once and
 * its instances once per frame, drawn by every pass that needs it in one of these modes:
 *   SHADOW      depth only, from the sun (view_proj: the shadow map's)
 *   PREPASS     lit colour + depth of what lies under the water (clip plane keeps y < level)
 *   REFLECTION  lit colour of what lies above the water, mirrored (clip plane keeps y > level)
 *   MAIN        lit colour, everything
 *   PREPASS_DEPTH  the prepass's depth alone (its cut and clip plane, no shading)
 * view_proj maps camera-relative world positions to clip space; clip is a world plane
 * (a, b, c, d) in camera-relative coordinates, kept where a x + b y + c z + d >= 0, or NULL. */
typedef enum ww_geom_mode {
    WW_GEOM_SHADOW = 0,
    WW_GEOM_PREPASS,
    WW_GEOM_REFLECTION,
    WW_GEOM_MAIN,
    WW_GEOM_PREPASS_DEPTH
} ww_geom_mode;
ww_result ww_geometry_new(ww_renderer *r, const ww_scene *sc, ww_geometry **out, ww_error *err);
void ww_geometry_draw(ww_geometry *g, ww_renderer *r, const ww_frame *f, ww_geom_mode mode,
                      mat4 view_proj, const float *clip);
/* the chest's glow column (additive), after the sky of the same pass: mode as the pass's
 * ww_geometry_draw, whose uniforms it reuses */
void ww_geometry_draw_glow(ww_geometry *g, ww_renderer *r, ww_geom_mode mode);
/* this frame's point and spot lights into prog (in use; it includes common.glsl) */
void ww_geometry_lights_set(ww_geometry *g, const ww_gl *gl, const ww_frame *f, GLuint prog);
int ww_lights_scatter_on(const ww_scene *sc);
/* the same, only some parts (the main pass draws the solids before the water and the seabed,
 * which the water mostly hides, after it; the glow is
 * ww_geometry_draw_glow's, after the sky) */
enum {
    WW_GEOM_PART_SOLIDS = 1, /* objects and models */
    WW_GEOM_PART_SEABED = 2,
    WW_GEOM_PART_ALL = 3,    /* the opaque parts */
    WW_GEOM_PART_BUBBLES = 4, /* the air bubbles: blended, back to front, after the sky */
    WW_GEOM_PART_LINE = 8,    /* the fishing line and its rod: blended, after the bubbles */
    WW_GEOM_PART_WAKE = 16    /* the boat's wake on the water: blended, before the bubbles */
};
void ww_geometry_draw_parts(ww_geometry *g, ww_renderer *r, const ww_frame *f,
                            ww_geom_mode mode, mat4 view_proj, const float *clip, unsigned parts);
/* the lid over every hull's inside into depth only, so water drawn after it stays out of the
 * boats (main pass) */
void ww_geometry_draw_hull_mask(ww_geometry *g, ww_renderer *r, const ww_frame *f,
                                mat4 view_proj);
/* 1 when the scene has a boat or hull models (a lid to draw), so the main pass pays for the
 * mask's order only then */
int ww_geometry_has_hulls(const ww_geometry *g);
/* the scene has air bubbles to draw (WW_GEOM_PART_BUBBLES) */
int ww_geometry_has_bubbles(const ww_geometry *g);
/* the scene has a fishing line to draw (WW_GEOM_PART_LINE, gfx/line.h) */
int ww_geometry_has_line(const ww_geometry *g);
/* the scene has a boat's wake to draw (WW_GEOM_PART_WAKE, gfx/wake.h) */
int ww_geometry_has_wake(const ww_geometry *g);
/* how the next draws of the geometry test depth and light (stencilled shadows, stencil_shadows.c):
 *   NORMAL   depth LESS and written, lit (every other draw)
 *   SUNLESS  depth EQUAL, not written, no sunlight: what lies in a shadow drawn again over itself
 *   MARK     depth LEQUAL, not written: casters' outlines tested against what is drawn */
typedef enum ww_geom_stage {
    WW_GEOM_STAGE_NORMAL = 0,
    WW_GEOM_STAGE_SUNLESS,
    WW_GEOM_STAGE_MARK
} ww_geom_stage;
void ww_geometry_set_stage(ww_geometry *g, ww_geom_stage stage);
/* each caster of shadow volumes this frame (scenes with render.shadows volumes keep them): a
 * mesh id stable over the renderer's life, its data (positions in vertex[8 k..8 k+2], CCW
 * triangles), its camera-relative model matrix (column-major), and whether it is drawn as that
 * mesh under that matrix (0: the vertex shader bends it, as a fish's swimming body) */
typedef void (*ww_caster_fn)(void *user, int mesh_id, const ww_mesh_data *mesh,
                             const float model[16], int rigid);
void ww_geometry_each_caster(ww_geometry *g, ww_caster_fn fn, void *user);
void ww_geometry_free(ww_geometry *g, const ww_gl *gl);
/* instanced draws the last ww_geometry_draw made (one per mesh with instances; tests) */
int ww_geometry_draw_count(const ww_geometry *g);

/* stencil_shadows.c: seed 003's stencilled sun shadows (render.shadows projected, volumes,
 * volumes_visible). The renderer makes one when the scene asks and has casters (its main pass
 * and prepass then have a stencil); a pass calls apply after its opaque geometry, with the
 * view_proj and clip it drew them with, and draw_visible after everything opaque (the main
 * pass after its water). */
typedef struct ww_stencil_shadows ww_stencil_shadows;
ww_result ww_stencil_shadows_new(ww_renderer *r, const ww_scene *sc, ww_stencil_shadows **out,
                                 ww_error *err);
void ww_stencil_shadows_apply(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f,
                              ww_geom_mode mode, mat4 view_proj, const float *clip);
void ww_stencil_shadows_draw_visible(ww_stencil_shadows *s, ww_renderer *r, const ww_frame *f,
                                     mat4 view_proj, const float *clip);
void ww_stencil_shadows_free(ww_stencil_shadows *s, const ww_gl *gl);

/* renderer.c: the targets of pass `id`, or NULL when the plan has no such pass */
const ww_rt *ww_renderer_output(const ww_renderer *r, ww_pass_id id);
/* renderer.c: the state every pass starts from: its framebuffer bound, viewport, no blending,
 * culling, dithering or depth test */
void ww_gfx_begin_pass(const ww_gl *gl, const ww_rt *rt);
/* renderer.c: the bound framebuffer of a pass that draws the scene into rt cleared: colour (to
 * the clear colour set), depth to 1, and the stencil where rt has one */
void ww_gfx_clear_scene(const ww_renderer *r, const ww_rt *rt);
/* renderer.c: to's framebuffer bound, with from's first colour image copied into it (scaled by
 * `filter` where the sizes differ) */
void ww_gfx_blit_color(const ww_gl *gl, const ww_rt *from, const ww_rt *to, GLenum filter);
/* the range row r of a model matrix (column-major) takes over the box [lo, hi]: the box's
 * extent along that row of the world, where a mesh's instance reaches */
void ww_gfx_box_row(const float model[16], int r, const float lo[3], const float hi[3],
                    float *rlo, float *rhi);

/* targets.c: textures and a framebuffer for a pass description; WW_E_GL when incomplete */
ww_result ww_gfx_rt_create(const ww_gl *gl, const ww_pass_desc *d, ww_rt *rt, ww_error *err);
void ww_gfx_rt_destroy(const ww_gl *gl, ww_rt *rt);
/* a framebuffer of its own for one texture (a ping-pong side: never sampled while bound),
 * the texture switched to bilinear filtering; WW_E_GL names the pass and the side */
ww_result ww_gfx_fbo_single(const ww_gl *gl, GLuint tex, const char *pass, int side, GLuint *fbo,
                            ww_error *err);
/* the first attachment of format fmt, 0 when there is none */
GLuint ww_gfx_rt_texture(const ww_rt *rt, ww_format fmt);
/* the n-th (from 0) texture of rt in format fmt, 0 when there is none */
GLuint ww_gfx_rt_texture_nth(const ww_rt *rt, ww_format fmt, int n);
/* the depth attachment, with or without stencil; 0 when there is none */
GLuint ww_gfx_rt_depth(const ww_rt *rt);
/* the bound texture of `target` (GL_TEXTURE_2D, _2D_ARRAY) made a tile: its mip chain
 * generated, sampled trilinearly, repeating in both directions */
void ww_gfx_mipmap_tiled(const ww_gl *gl, GLenum target);

/* program.c: vertex + fragment shader files with includes (NULL-terminated list, prepended in
 * order after #version; may be NULL); WW_E_GL names the file and carries the info log */
ww_result ww_gfx_program(const ww_gl *gl, const char *vs, const char *fs,
                         const char *const *includes, GLuint *out, ww_error *err);
/* the same with the caller's #define lines (each ending in a newline) after the shared ones */
ww_result ww_gfx_program_defs(const ww_gl *gl, const char *vs, const char *fs,
                              const char *const *includes, const char *defines, GLuint *out,
                              ww_error *err);
GLint ww_gfx_uniform(const ww_gl *gl, GLuint prog, const char *name);

/* pass_shadow.c: the sunlight's direction under the water (toward the sun, unit, refracted at a
 * level surface); (0, 0, 0) with the sun at or below the horizon */
void ww_sun_in_water(const double sun[3], double out[3]);

/* sky.c: the uniforms of common.glsl (sky gradient and sun), for any program that includes it */
typedef struct ww_sky_locs {
    GLint zenith, horizon, sun_dir, sun_color;
    GLint perez, zen, psun, mode, clouds; /* Preetham's sky and the clouds (common.glsl) */
    GLint sky_map;                        /* u_sky_map (WW_SKY_MAP), -1 when not built */
    int physical;                         /* the sky is Preetham's (preetham, dome) */
    double turbidity, cover, speed;       /* the scene's sky.turbidity, sky.clouds */
    double origin[2];                     /* the clouds' start in the noise (sky.clouds.seed) */
} ww_sky_locs;
/* the texture unit the sky map (pass_skymap.c) stays bound to for the whole frame; no other
 * program uses it */
#define WW_TEX_SKY_MAP 15
/* the #define lines of the scene's sky that the programs including common.glsl add to their
 * own: WW_SKY_MAP 1 when the sky is drawn from the map, WW_CLOUDS 1 when it has clouds */
const char *ww_sky_defines(const ww_scene *sc);
/* sc: the scene whose sky (model, turbidity, clouds) the program draws */
void ww_sky_locs_init(const ww_gl *gl, GLuint prog, const ww_scene *sc, ww_sky_locs *l);
void ww_sky_locs_set(const ww_gl *gl, const ww_sky_locs *l, const ww_state *st);
/* the sky's colour along the horizon this frame (the fog's colour when the scene gives none):
 * the clock's palette, or by day Preetham's horizon averaged over the azimuths */
void ww_sky_horizon(const ww_scene *sc, const ww_state *st, double out[3]);
/* fog.below.color lit by the light entering the water now: the scene's by day, dimmer at dusk
 * and night (gfx/sky.c) */
void ww_fog_below_color(const ww_scene *sc, const ww_state *st, double out[3]);

/* sky.c: the scene's sky (gradient, cubemap or dome) and the sun disc as a full-screen triangle
 * on the far plane. A cubemap sky uploads the scene's six faces once per renderer and sets
 * r->sky_cubemap (the first sky created owns it and must outlive its readers; later skies of
 * the same renderer draw it). */
typedef struct ww_sky ww_sky;
/* 1 when the sky is the dome's picture (sky.image): the programs that draw the sky then build
 * common.glsl's WW_SKY_DOME_IMAGE and sample r->sky_dome_image */
int ww_sky_dome_image_on(const ww_scene *sc);
ww_result ww_sky_new(ww_renderer *r, const ww_scene *sc, ww_sky **out, ww_error *err);
ww_result ww_sky_draw(ww_sky *s, const ww_gl *gl, GLuint empty_vao, const ww_frame *f,
                      ww_error *err);
void ww_sky_free(ww_sky *s, const ww_gl *gl);

/* waveblock.c: the wave field as shaders/gerstner.glsl takes it, in two std140 uniform blocks
 * (the layouts below mirror WwWaves and WwRipples; creating a program checks the driver agrees).
 * Shared by the water pass, the geometry and the probe (water_probe.c):
 *
 *   ww_water_waves ww; ww_water_waves_init(sc, &ww);          // once per scene: order, columns
 *   ww_water_program(gl, sc, vs, fs, fade, NULL, &prog, &err); // the scene's family as defines
 *   ww_water_ubos u; ww_water_ubos_new(gl, sc, &ww, &u, &err);
 *   per frame: ww_water_waves_phases(sc, st, centre, &ww);      // phases at the centre, double
 *              ww_water_pack_ripples(sc, st, centre, &rb);
 *              ww_water_ubos_upload(gl, &u, &ww, &rb); ww_water_ubos_bind(gl, &u);
 *   ww_water_ubos_free(gl, &u);
 */
#define WW_UBO_WAVES 0   /* uniform buffer binding points */
#define WW_UBO_RIPPLES 1

typedef struct ww_wave_block {
    int32_t n;
    float slope2_total;           /* sum of the mean square slopes (A k)^2 c */
    int32_t pad_[2];
    float wave[WW_MAX_WAVES][4];  /* (k Dx, k Dz, A, Q) */
    float wave2[WW_MAX_WAVES][4]; /* (phase at the centre, exponent e, mean, slope factor c) */
} ww_wave_block;

typedef struct ww_ripple_block {
    int32_t n, pad_[3];
    float param[4];                  /* (alpha, beta, kr, v) */
    float shape[4];                  /* (lambda, r0, 0, 0) */
    float bound[4];                  /* (x, z, radius, 0): a circle holding every front */
    float ripple[WW_MAX_RIPPLES][4]; /* (x - centre.x, z - centre.z, age, A0) */
} ww_ripple_block;

/* the scene's components in upload order, sorted by wavenumber ascending so that the shaders
 * can stop at the first one faded out */
typedef struct ww_water_waves {
    int order[WW_MAX_WAVES]; /* scene index of upload slot i */
    double sideways;         /* sum Q A of what is drawn: the largest sideways displacement, m */
    ww_wave_block block;     /* every column but the phases is filled once */
} ww_water_waves;

typedef struct ww_water_ubos {
    GLuint waves, ripples; /* ripples is 0 when the scene has none */
} ww_water_ubos;

void ww_water_waves_init(const ww_scene *sc, ww_water_waves *w);
/* the components the shaders draw (k > 0, at most WW_MAX_WAVES; 0 for flat water): the block's n,
 * built into the programs as WW_NWAVES */
int ww_water_wave_count(const ww_scene *sc);
/* the WW_WAVE_MODEL gerstner.glsl is built with for a scene's family (0 flat, 1 Gerstner and
 * spectrum, 2 sines, 3 steep sines) */
int ww_water_shader_model(ww_wave_model m);
/* each component's phase at the centre (world x, z): wrap(k D.centre + phase at the origin),
 * in double */
void ww_water_waves_phases(const ww_scene *sc, const ww_state *st, const double centre[2],
                           ww_water_waves *w);
/* the pool's live ripples relative to the centre, ages t - t0 in double; returns how many */
int ww_water_pack_ripples(const ww_scene *sc, const ww_state *st, const double centre[2],
                          ww_ripple_block *b);
/* the surface's normal-only detail (waveblock.c): WW_WATER_NDETAIL short sines as the shaders
 * take them, (k Dx, k Dz 1/m, slope amplitude A k, phase at the centre rad), the phases taken at
 * centre (world x, z) in double */
#define WW_WATER_NDETAIL 6 /* water.frag.glsl: NDETAIL; geometry.frag.glsl: WW_NDETAIL */
void ww_water_detail(const ww_state *st, const double centre[2], float d[WW_WATER_NDETAIL][4]);
void ww_water_detail_define(char *buf, size_t n);
/* the water's DuDv pattern (waveblock.c): per layer the mat2 (column-major) from metres
 * relative to `centre` to lattice cells, and the offset there (water.frag.glsl, and the
 * caustics of geometry.frag.glsl, which see it as the surface's small irregular ripples) */
void ww_water_dudv(const ww_scene *sc, const ww_state *st, const double centre[2], float m[2][4],
                   float o[2][2]);
/* vs + fs with common.glsl and gerstner.glsl, built for the scene's wave family and ripples;
 * fade 0 turns the distance fade off; more: further #define lines (each ending in a newline)
 * or NULL. Binds the blocks to WW_UBO_WAVES / WW_UBO_RIPPLES and
 * checks their sizes against the driver's layout and GL_MAX_UNIFORM_BLOCK_SIZE. */
ww_result ww_water_program(const ww_gl *gl, const ww_scene *sc, const char *vs, const char *fs,
                           int fade, const char *more, GLuint *prog, ww_error *err);
ww_result ww_water_ubos_new(const ww_gl *gl, const ww_scene *sc, const ww_water_waves *w,
                            ww_water_ubos *u, ww_error *err);
/* the whole wave block when full is set, else only its header and phases; rb may be NULL */
void ww_water_ubos_upload(const ww_gl *gl, const ww_water_ubos *u, const ww_water_waves *w,
                          const ww_ripple_block *rb, int full);
void ww_water_ubos_bind(const ww_gl *gl, const ww_water_ubos *u);
void ww_water_ubos_free(const ww_gl *gl, ww_water_ubos *u);

/* water.c: the camera-centred polar mesh of the wave field, depth tested; its density is
 * render.grid (scene/plan.h: ww_water_mesh_layout) */
typedef struct ww_water ww_water;
/* edges: the plan's prepass draws its depth at the frame's size (its depth_full target);
 * mirror_depth: the reflection pass mirrors objects, whose image's depths the water reads */
ww_result ww_water_new(const ww_gl *gl, const ww_scene *sc, int edges, int mirror_depth,
                       ww_water **out, ww_error *err);
/* uploads the frame's phases and ripples, then draws, reading what earlier passes left in
 * r->shared (reflection, prepass) and r->sky_cubemap; alpha-blended over what the target holds
 * when render.water.alpha_blend */
ww_result ww_water_draw(ww_water *w, const ww_renderer *r, const ww_frame *f, ww_error *err);
void ww_water_free(ww_water *w, const ww_gl *gl);

#endif
