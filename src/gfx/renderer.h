/* renderer.h - the frame renderer, built from the scene's plan (scene/plan.h): one pass object
 * per planned pass, created once, then run in order each frame into our own framebuffers
 * (HDR RGBA16F colour + depth, then tone mapping into sRGB8). Read back with glReadPixels and
 * flipped once, so images come out top row first.
 *
 *   ww_renderer *r = NULL;
 *   ww_renderer_for_scene(gl, sc, w, h, &r, &err); // plans, compiles shaders, makes targets
 *   ww_render_frame(r, sc, st);                   // draws all passes
 *   ww_renderer_read_ldr(r, &img);                // RGB8 (or RGBA8) final image, caller allocs
 *   ww_renderer_read_hdr(r, &img);                // RGBA float linear HDR image
 *   ww_renderer_free(r);
 *
 * Per-pass timing (bench): ww_renderer_time_passes(r, WW_TIMING_AUTO) once after creation, then
 * after any frames ww_renderer_pass_times(r, &t) gives ms per pass summed over the frames drawn
 * since the previous call (it waits for the GPU to finish them).
 *
 * Shaders are embedded at build time; WW_SHADER_DIR=path/to/shaders loads them from files
 * instead (development).
 */
#ifndef WW_RENDERER_H
#define WW_RENDERER_H

#include "core/error.h"
#include "gfx/gl.h"
#include "io/image.h"
#include "scene/plan.h"
#include "scene/scene.h"
#include "sim/state.h"

typedef struct ww_renderer ww_renderer;

/* the renderer of the scene's own plan (ww_plan_build at w x h): what every command uses */
ww_result ww_renderer_for_scene(const ww_gl *gl, const ww_scene *sc, int w, int h,
                                ww_renderer **out, ww_error *err);
/* the renderer of a plan built by hand (tests: a main pass and tone mapping alone, say) */
ww_result ww_renderer_new(const ww_gl *gl, const ww_scene *sc, const ww_plan *plan,
                          ww_renderer **out, ww_error *err);
/* the plan the renderer was built from */
const ww_plan *ww_renderer_plan(const ww_renderer *r);
void ww_renderer_free(ww_renderer *r);
ww_result ww_render_frame(ww_renderer *r, const ww_scene *sc, const ww_state *st, ww_error *err);
/* im must be allocated by the caller at the plan's size: U8 with 3 or 4 channels / F32 with 4 */
ww_result ww_renderer_read_ldr(ww_renderer *r, ww_image *im, ww_error *err);
ww_result ww_renderer_read_hdr(ww_renderer *r, ww_image *im, ww_error *err);
/* [frames] the alpha channel of a 4-channel image read above (U8: 0 / 255, F32: 0 / 1) from the
 * main pass's depth: 1 where water or geometry covers the pixel, 0 where only the sky (or, under
 * water, the fog drawn in its place) is seen; depth is caller scratch of width * height floats */
ww_result ww_renderer_read_coverage(ww_renderer *r, ww_image *im, float *depth, ww_error *err);
/* ms for one trivial full-screen pass (constant colour) into an RGBA16F target of w x h: the
 * backend's fill floor, which bench sets render times against. ms: wall clock with glFinish
 * after each pass (as the frames are timed); gpu_ms: the pass alone by a GL timer query over
 * passes drawn back to back, -1 where the driver's timer has no bits (on a GPU the first holds a
 * round trip to the driver, the second the fill) */
ww_result ww_gfx_fill_floor(const ww_gl *gl, int w, int h, double *ms, double *gpu_ms,
                            ww_error *err);

/* the wave field as the water shaders evaluate it (shaders/gerstner.glsl, the functions the
 * water vertex shader displaces its mesh with, fade off): for n rest points given relative to the
 * camera position cam (world, m), draws one point each into an RGBA32F target and reads back
 * out[8 i ..]: displaced point relative to cam (x, y, z), 0, unit normal (x, y, z), 0. Waves and
 * ripples of st at st->t. For the GPU-vs-CPU accuracy test and bench. */
ww_result ww_gfx_water_probe(const ww_gl *gl, const ww_scene *sc, const ww_state *st,
                             const double cam[3], int n, const double *rest_xz, float *out,
                             ww_error *err);
/* per-pass timing: GL_TIME_ELAPSED queries around each pass's run (ARB_timer_query, core in
 * GL 3.3) or, where the driver has no timer bits, CPU wall time with glFinish between passes
 * (which serialises the frame: the sum is then an upper bound of the pipelined cost) */
typedef enum ww_timing {
    WW_TIMING_OFF = 0,
    WW_TIMING_AUTO, /* GPU when the driver's GL_TIME_ELAPSED counter has bits, else CPU */
    WW_TIMING_GPU,
    WW_TIMING_CPU
} ww_timing;

typedef struct ww_pass_times {
    ww_timing mode;                      /* what measured them: WW_TIMING_GPU or _CPU */
    int npasses;                         /* the renderer's passes, in plan order */
    ww_pass_id id[WW_PASS_COUNT];
    char name[WW_PASS_COUNT][16];        /* the plan's pass names */
    double ms[WW_PASS_COUNT];            /* summed over `frames` */
    double frame_ms;                     /* CPU mode: the frames' wall time (0 in GPU mode) */
    int frames;
} ww_pass_times;

/* turn timing on (or off) for the frames that follow; returns the mode in effect (AUTO resolved;
 * GPU falls back to CPU when the counter has no bits) */
ww_timing ww_renderer_time_passes(ww_renderer *r, ww_timing mode);
/* the timings of every frame drawn since the previous call (or since timing was turned on),
 * waiting for the GPU where a frame is still in flight; the sums restart */
void ww_renderer_pass_times(ww_renderer *r, ww_pass_times *t);
/* "gl timer queries" / "cpu wall time, glFinish between passes" / "off" */
const char *ww_timing_name(ww_timing mode);
/* 1 when this build has a pass for id (bench: a knob of a pass not written yet has no effect,
 * and a plan naming it could not be rendered) */
int ww_renderer_has_pass(ww_pass_id id);

/* glFinish; used by bench to split render from read-back time */
void ww_renderer_finish(ww_renderer *r);

#endif
